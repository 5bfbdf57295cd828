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

void prolongAdd(const Transfer3D& t, const double* coarse, double* fine, const BoxLayout& L) {
  const int64_t cy = t.x.nc, cz = int64_t(t.x.nc) * t.y.nc;
  const int* ix0 = t.x.i0.data();
  const int* ix1 = t.x.i1.data();
  const double* wx0 = t.x.w0.data();
  const double* wx1 = t.x.w1.data();
  for (int k = 0; k < L.nz; ++k) {
    const int64_t k0 = t.z.i0[k] * cz, k1 = t.z.i1[k] * cz;
    const double c0 = t.z.w0[k], c1 = t.z.w1[k];
    for (int j = 0; j < L.ny; ++j) {
      const int64_t j0 = t.y.i0[j] * cy, j1 = t.y.i1[j] * cy;
      const double b0 = t.y.w0[j], b1 = t.y.w1[j];
      // Four coarse rows (j0/j1 x k0/k1) and their weights.
      const double* r00 = coarse + 3 * (j0 + k0);
      const double* r10 = coarse + 3 * (j1 + k0);
      const double* r01 = coarse + 3 * (j0 + k1);
      const double* r11 = coarse + 3 * (j1 + k1);
      const double a00 = b0 * c0, a10 = b1 * c0, a01 = b0 * c1, a11 = b1 * c1;
      double* f = fine + 3 * (L.offset + L.sy * j + L.sz * k);
      for (int i = 0; i < L.nx; ++i) {
        const int64_t x0 = 3 * int64_t(ix0[i]), x1 = 3 * int64_t(ix1[i]);
        const double u0 = wx0[i], u1 = wx1[i];
        for (int c = 0; c < 3; ++c) {
          const double v0 =
              a00 * r00[x0 + c] + a10 * r10[x0 + c] + a01 * r01[x0 + c] + a11 * r11[x0 + c];
          const double v1 =
              a00 * r00[x1 + c] + a10 * r10[x1 + c] + a01 * r01[x1 + c] + a11 * r11[x1 + c];
          f[3 * i + c] += u0 * v0 + u1 * v1;
        }
      }
    }
  }
}

void restrictTranspose(const Transfer3D& t, const double* fine, const BoxLayout& L,
                       double* coarse) {
  const int64_t cy = t.x.nc, cz = int64_t(t.x.nc) * t.y.nc;
  std::fill(coarse, coarse + 3 * int64_t(t.coarseSize()), 0.0);
  const int* ix0 = t.x.i0.data();
  const int* ix1 = t.x.i1.data();
  const double* wx0 = t.x.w0.data();
  const double* wx1 = t.x.w1.data();
  for (int k = 0; k < L.nz; ++k) {
    const int64_t k0 = t.z.i0[k] * cz, k1 = t.z.i1[k] * cz;
    const double c0 = t.z.w0[k], c1 = t.z.w1[k];
    for (int j = 0; j < L.ny; ++j) {
      const int64_t j0 = t.y.i0[j] * cy, j1 = t.y.i1[j] * cy;
      const double b0 = t.y.w0[j], b1 = t.y.w1[j];
      double* r00 = coarse + 3 * (j0 + k0);
      double* r10 = coarse + 3 * (j1 + k0);
      double* r01 = coarse + 3 * (j0 + k1);
      double* r11 = coarse + 3 * (j1 + k1);
      const double a00 = b0 * c0, a10 = b1 * c0, a01 = b0 * c1, a11 = b1 * c1;
      const double* f = fine + 3 * (L.offset + L.sy * j + L.sz * k);
      for (int i = 0; i < L.nx; ++i) {
        const int64_t x0 = 3 * int64_t(ix0[i]), x1 = 3 * int64_t(ix1[i]);
        const double u0 = wx0[i], u1 = wx1[i];
        for (int c = 0; c < 3; ++c) {
          const double v = f[3 * i + c];
          const double v0 = u0 * v, v1 = u1 * v;
          r00[x0 + c] += a00 * v0;
          r10[x0 + c] += a10 * v0;
          r01[x0 + c] += a01 * v0;
          r11[x0 + c] += a11 * v0;
          r00[x1 + c] += a00 * v1;
          r10[x1 + c] += a10 * v1;
          r01[x1 + c] += a01 * v1;
          r11[x1 + c] += a11 * v1;
        }
      }
    }
  }
}

Csr interpolationMatrix(const Transfer3D& t) {
  Csr p;
  p.rows = t.x.n * t.y.n * t.z.n;
  p.cols = t.coarseSize();
  p.ptr.assign(size_t(p.rows) + 1, 0);
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
