#include "multigrid_transfer.hpp"

#include <algorithm>

namespace hairsketch {

int coarsenedSize(int n) { return n <= 2 ? n : n / 2 + 1; }

Interp1D makeInterp1D(int n) {
  Interp1D t;
  t.n = n;
  t.nc = coarsenedSize(n);
  t.i0.resize(n);
  t.i1.resize(n);
  t.w0.resize(n);
  t.w1.resize(n);
  auto node = [&](int I) { return t.nc == n ? I : std::min(2 * I, n - 1); };
  int I = 0;
  for (int i = 0; i < n; ++i) {
    while (I + 1 < t.nc && node(I + 1) <= i) ++I;
    if (node(I) == i) {
      t.i0[i] = t.i1[i] = I;
      t.w0[i] = 1.0;
      t.w1[i] = 0.0;
    } else {  // node(I) < i < node(I + 1)
      const double h = node(I + 1) - node(I);
      t.i0[i] = I;
      t.i1[i] = I + 1;
      t.w1[i] = (i - node(I)) / h;
      t.w0[i] = 1.0 - t.w1[i];
    }
  }
  return t;
}

Transfer3D makeTransfer(int nx, int ny, int nz) {
  return {makeInterp1D(nx), makeInterp1D(ny), makeInterp1D(nz)};
}

// Both operators are applied one axis at a time (x, y, z), through two scratch boxes:
//   T1: nc_x x n_y x n_z,  T2: nc_x x nc_y x n_z  (rows of 3).
// Each pass touches every input row once with 2 weights, ~4x fewer flops than the 8-point
// tensor stencil, and the y/z passes work on whole contiguous rows. Every pass runs in parallel
// over fine z planes, except restriction's z pass, which gathers each coarse plane from its fine
// planes in ascending order (the order a serial scatter adds them in).
namespace {

// out += w * in (rows of `len` doubles); nothing when w = 0.
inline void axpyRow(double* out, const double* in, double w, int64_t len) {
  if (w == 0.0) return;
  for (int64_t e = 0; e < len; ++e) out[e] += w * in[e];
}

// out = wa * a + wb * b (wb = 0: out = wa * a).
inline void combineRow(double* out, const double* a, double wa, const double* b, double wb,
                       int64_t len) {
  if (wb == 0.0) {
    for (int64_t e = 0; e < len; ++e) out[e] = wa * a[e];
  } else {
    for (int64_t e = 0; e < len; ++e) out[e] = wa * a[e] + wb * b[e];
  }
}

}  // namespace

void prolongAdd(const Transfer3D& t, const double* coarse, double* fine, const BoxLayout& L,
                TransferWork& work) {
  const int cx = t.x.nc, cy = t.y.nc, ny = L.ny, nz = L.nz;
  const int64_t rowC = 3 * int64_t(cx);  // one x-row of coarse values
  work.t2.resize(size_t(rowC) * cy * nz);
  work.t1.resize(size_t(rowC) * ny * nz);
  const int64_t planeC = rowC * cy;
  const int* i0 = t.x.i0.data();
  const int* i1 = t.x.i1.data();
  const double* w0 = t.x.w0.data();
  const double* w1 = t.x.w1.data();
  forPlanes(nz, 3 * int64_t(L.nx) * ny, [&](int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1; ++k) {
      // z: T2[k] = w0 C[i0(k)] + w1 C[i1(k)], planes of cx * cy rows.
      double* t2 = work.t2.data() + planeC * k;
      combineRow(t2, coarse + planeC * t.z.i0[k], t.z.w0[k], coarse + planeC * t.z.i1[k], t.z.w1[k],
                 planeC);
      // y: T1[j, k] from T2 rows.
      for (int j = 0; j < ny; ++j)
        combineRow(work.t1.data() + rowC * (j + int64_t(ny) * k), t2 + rowC * t.y.i0[j], t.y.w0[j],
                   t2 + rowC * t.y.i1[j], t.y.w1[j], rowC);
      // x: into the fine layout.
      for (int j = 0; j < ny; ++j) {
        const double* in = work.t1.data() + rowC * (j + int64_t(ny) * k);
        double* f = fine + 3 * (L.offset + L.sy * j + L.sz * k);
        for (int i = 0; i < L.nx; ++i) {
          const double* a = in + 3 * i0[i];
          const double* b = in + 3 * i1[i];
          f[3 * i] += w0[i] * a[0] + w1[i] * b[0];
          f[3 * i + 1] += w0[i] * a[1] + w1[i] * b[1];
          f[3 * i + 2] += w0[i] * a[2] + w1[i] * b[2];
        }
      }
    }
  });
}

void restrictTranspose(const Transfer3D& t, const double* fine, const BoxLayout& L, double* coarse,
                       TransferWork& work) {
  const int cx = t.x.nc, cy = t.y.nc, cz = t.z.nc, ny = L.ny, nz = L.nz;
  const int64_t rowC = 3 * int64_t(cx);
  work.t1.resize(size_t(rowC) * ny * nz);
  work.t2.resize(size_t(rowC) * cy * nz);
  const int* i0 = t.x.i0.data();
  const int* i1 = t.x.i1.data();
  const double* w0 = t.x.w0.data();
  const double* w1 = t.x.w1.data();
  const int64_t planeC = rowC * cy;
  forPlanes(nz, 3 * int64_t(L.nx) * ny, [&](int64_t k0, int64_t k1) {
    for (int64_t k = k0; k < k1; ++k) {
      // x: T1 rows of plane k.
      for (int j = 0; j < ny; ++j) {
        double* out = work.t1.data() + rowC * (j + int64_t(ny) * k);
        std::fill(out, out + rowC, 0.0);
        const double* f = fine + 3 * (L.offset + L.sy * j + L.sz * k);
        for (int i = 0; i < L.nx; ++i) {
          double* a = out + 3 * i0[i];
          double* b = out + 3 * i1[i];
          for (int c = 0; c < 3; ++c) {
            a[c] += w0[i] * f[3 * i + c];
            b[c] += w1[i] * f[3 * i + c];
          }
        }
      }
      // y: T2 plane k from the T1 rows of plane k.
      double* out = work.t2.data() + planeC * k;
      std::fill(out, out + planeC, 0.0);
      for (int j = 0; j < ny; ++j) {
        const double* in = work.t1.data() + rowC * (j + int64_t(ny) * k);
        axpyRow(out + rowC * t.y.i0[j], in, t.y.w0[j], rowC);
        axpyRow(out + rowC * t.y.i1[j], in, t.y.w1[j], rowC);
      }
    }
  });
  // z: coarse plane K = sum over the fine planes k next to it, in ascending k. Only the span of
  // fine planes that name K is visited: scanning every fine plane for every coarse one costs
  // nz^2/2 steps, which dominates on long thin grids (2 x 2 x 100000).
  work.zFirst.assign(size_t(cz), nz);
  work.zLast.assign(size_t(cz), -1);
  for (int k = 0; k < nz; ++k)
    for (const int K : {t.z.i0[k], t.z.i1[k]}) {
      work.zFirst[size_t(K)] = std::min(work.zFirst[size_t(K)], k);
      work.zLast[size_t(K)] = std::max(work.zLast[size_t(K)], k);
    }
  forPlanes(cz, 2 * planeC * nz / std::max(cz, 1), [&](int64_t K0, int64_t K1) {
    for (int64_t K = K0; K < K1; ++K) {
      double* out = coarse + planeC * K;
      std::fill(out, out + planeC, 0.0);
      for (int k = work.zFirst[size_t(K)]; k <= work.zLast[size_t(K)]; ++k) {
        const double* in = work.t2.data() + planeC * k;
        if (t.z.i0[k] == K) axpyRow(out, in, t.z.w0[k], planeC);
        if (t.z.i1[k] == K) axpyRow(out, in, t.z.w1[k], planeC);
      }
    }
  });
}

Csr interpolationMatrix(const Transfer3D& t) {
  Csr p;
  p.rows = t.x.n * t.y.n * t.z.n;
  p.cols = t.coarseSize();
  p.ptr.assign(size_t(p.rows) + 1, 0);
  // At most 2 weights per coarsened axis: reserve that bound (no push_back doubling slack).
  const size_t perRow =
      size_t(t.x.nc < t.x.n ? 2 : 1) * (t.y.nc < t.y.n ? 2 : 1) * (t.z.nc < t.z.n ? 2 : 1);
  p.col.reserve(size_t(p.rows) * perRow);
  p.val.reserve(size_t(p.rows) * perRow);
  int row = 0;
  for (int k = 0; k < t.z.n; ++k)
    for (int j = 0; j < t.y.n; ++j)
      for (int i = 0; i < t.x.n; ++i, ++row) {
        std::vector<std::pair<int, double>> e;
        const int ks[2] = {t.z.i0[k], t.z.i1[k]}, js[2] = {t.y.i0[j], t.y.i1[j]},
                  is[2] = {t.x.i0[i], t.x.i1[i]};
        const double kw[2] = {t.z.w0[k], t.z.w1[k]}, jw[2] = {t.y.w0[j], t.y.w1[j]},
                     iw[2] = {t.x.w0[i], t.x.w1[i]};
        for (int c = 0; c < 2; ++c)
          for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
              const double w = kw[c] * jw[b] * iw[a];
              if (w != 0.0) e.emplace_back(is[a] + t.x.nc * (js[b] + t.y.nc * ks[c]), w);
            }
        std::sort(e.begin(), e.end());
        for (const auto& [c, w] : e) {
          p.col.push_back(c);
          p.val.push_back(w);
        }
        p.ptr[row + 1] = int64_t(p.col.size());
      }
  return p;
}

}  // namespace hairsketch
