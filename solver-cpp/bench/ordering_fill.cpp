// Exact nnz(L) (symbolic count, Eigen SimplicialLDLT analysis of the permuted matrix) of three
// dissections of the box: axis planes 1 thick (not separators for D^T D: the halves stay coupled
// through (i-1) <-> (i+1)), axis slabs 2 thick, and the default 2-layer diagonal planes.
// Run: build/native/ordering_fill
#include <Eigen/SparseCholesky>
#include <cstdio>

#include "field_system.hpp"
#include "grid_ordering.hpp"
using namespace hairsketch;
struct Counter : Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> {
  long long nnz() const {
    long long s = 0;
    for (int i = 0; i < m_nonZerosPerCol.size(); ++i) s += m_nonZerosPerCol[i] + 1;
    return s;
  }
};
int main() {
  for (int N : {29, 37}) {
    Grid g;
    g.nx = g.ny = g.nz = N;
    SparseMatrix M = assembleBiLaplacian(g);
    for (int variant = 0; variant < 3; ++variant) {
      DissectionOptions o;
      o.method =
          variant == 2 ? DissectionOptions::Method::Planes : DissectionOptions::Method::Boxes;
      o.thickness = variant == 0 ? 1 : 2;
      DissectionTree t = boxNestedDissection(g, o);
      Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(int(t.iperm.size()));
      for (size_t i = 0; i < t.iperm.size(); ++i) P.indices()[i] = t.iperm[i];
      SparseMatrix A;
      A = M.twistedBy(P);
      Counter c;
      c.analyzePattern(A);
      printf("N=%d %s nnz(L)=%.1fM\n", N,
             variant == 0   ? "boxes, 1-thick planes"
             : variant == 1 ? "boxes, 2-thick planes"
                            : "diagonal planes, 2 layers",
             c.nnz() * 1e-6);
    }
  }
}
