// Grid transfer operators of the multigrid hierarchy: trilinear interpolation P (coarse -> fine)
// and its transpose R = P^T (fine -> coarse), for any box size n >= 2 per axis.
//
// Coarsening per axis: n -> nc = n/2 + 1 when n >= 3 (kept as is when n <= 2). Coarse node I sits
// at fine index X_I = min(2I, n - 1): for odd n that is every other point, for even n the last
// interval is one fine step instead of two. Every fine index lies between two consecutive coarse
// nodes and gets the 1D linear weights; the 3D operator is the tensor product. Nodes are nested
// from level to level, so the composite P of several levels also has at most 2 weights per axis.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "multigrid_sparse.hpp"
#include "parallel.hpp"

namespace hairsketch {

int coarsenedSize(int n);

// Values (doubles read or written) a parallel chunk should at least handle: below that a loop
// runs serially, as waking a thread costs more than the work (tens of microseconds in wasm).
constexpr int64_t kMinParallelValues = 32768;

// fn(k0, k1) over planes [0, planes) (or any items) each costing about `perPlane` values, in
// parallel chunks of at least kMinParallelValues values. Every item is handled exactly as in a
// serial loop, so a caller whose items are independent gets the same bits with any thread count.
template <class F>
void forPlanes(int64_t planes, int64_t perPlane, F&& fn) {
  const int64_t grain = std::max<int64_t>(1, kMinParallelValues / std::max<int64_t>(perPlane, 1));
  parallel::forRange(0, size_t(std::max<int64_t>(planes, 0)), size_t(grain),
                     [&](size_t b, size_t e) { fn(int64_t(b), int64_t(e)); });
}

// 1D weights: fine index i -> w0[i] * coarse[i0[i]] + w1[i] * coarse[i1[i]] (w1 = 0, i1 = i0
// when i coincides with a coarse node).
struct Interp1D {
  int n = 0, nc = 0;
  std::vector<int> i0, i1;
  std::vector<double> w0, w1;
};
Interp1D makeInterp1D(int n);

// Where point (i, j, k) of an nx x ny x nz box lives in a row-major (points x 3) array:
// row = offset + i + sy * j + sz * k. Lets the padded fine level and the dense coarse levels
// share the transfer code.
struct BoxLayout {
  int nx = 0, ny = 0, nz = 0;
  int64_t offset = 0, sy = 0, sz = 0;
  static BoxLayout dense(int nx, int ny, int nz) {
    return {nx, ny, nz, 0, int64_t(nx), int64_t(nx) * ny};
  }
};

struct Transfer3D {
  Interp1D x, y, z;
  int coarseSize() const { return x.nc * y.nc * z.nc; }
};
Transfer3D makeTransfer(int nx, int ny, int nz);

// Scratch space of the axis-by-axis transfers (reused between calls).
struct TransferWork {
  std::vector<double> t1, t2;
  std::vector<int> zFirst, zLast;  // restrictTranspose: the fine planes each coarse plane reads
};

// Both run in parallel over z planes (each output value is computed by one thread, in the same
// order as serially).
// fine += P coarse; coarse is dense (x.nc * y.nc * z.nc rows of 3), fine in `layout`.
void prolongAdd(const Transfer3D& t, const double* coarse, double* fine, const BoxLayout& layout,
                TransferWork& work);
// coarse = P^T fine (overwritten).
void restrictTranspose(const Transfer3D& t, const double* fine, const BoxLayout& layout,
                       double* coarse, TransferWork& work);
// P as a sparse matrix (fine dense index x coarse dense index), zero weights left out.
Csr interpolationMatrix(const Transfer3D& t);

}  // namespace hairsketch
