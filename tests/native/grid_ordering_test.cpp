#include "grid_ordering.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "field_system.hpp"
#include "supernodal_symbolic.hpp"

namespace grid_ordering_test {
using namespace hairsketch;
namespace {

Grid box(int nx, int ny, int nz) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  return g;
}

// True when a is s or a descendant of s in the tree.
bool inSubtree(const DissectionTree& t, int a, int s) {
  for (; a >= 0; a = t.parent[size_t(a)])
    if (a == s) return true;
  return false;
}

class OrderingTest
    : public ::testing::TestWithParam<std::tuple<std::array<int, 4>, DissectionOptions::Method>> {};

TEST_P(OrderingTest, PermutationTreeAndSeparators) {
  const auto [nx, ny, nz, leaf] = std::get<0>(GetParam());
  const Grid g = box(nx, ny, nz);
  DissectionOptions o;
  o.leafMax = leaf;
  o.method = std::get<1>(GetParam());
  const DissectionTree t = boxNestedDissection(g, o);
  const int n = int(g.size());

  // perm is a permutation and iperm its inverse.
  ASSERT_EQ(int(t.perm.size()), n);
  std::vector<int> sorted = t.perm;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < n; ++i) ASSERT_EQ(sorted[size_t(i)], i);
  for (int k = 0; k < n; ++k) ASSERT_EQ(t.iperm[size_t(t.perm[size_t(k)])], k);

  // Postorder tree, nodes own contiguous non-empty ranges covering 0..n.
  ASSERT_EQ(t.nodeStart.front(), 0);
  ASSERT_EQ(t.nodeStart.back(), n);
  int roots = 0;
  for (int s = 0; s < t.nodes(); ++s) {
    EXPECT_LT(t.nodeStart[size_t(s)], t.nodeStart[size_t(s) + 1]);
    if (t.parent[size_t(s)] < 0)
      ++roots;
    else
      EXPECT_GT(t.parent[size_t(s)], s);
  }
  EXPECT_EQ(roots, 1);

  // Separator property in the graph of D^T D: every coupled pair lies on one root path.
  std::vector<int> node(static_cast<size_t>(n));
  for (int s = 0; s < t.nodes(); ++s)
    for (int k = t.nodeStart[size_t(s)]; k < t.nodeStart[size_t(s) + 1]; ++k)
      node[size_t(t.perm[size_t(k)])] = s;
  const SparseMatrix M = assembleBiLaplacian(g);
  for (int c = 0; c < n; ++c)
    for (SparseMatrix::InnerIterator it(M, c); it; ++it) {
      const int a = node[size_t(it.row())], b = node[size_t(c)];
      ASSERT_TRUE(inSubtree(t, a, b) || inSubtree(t, b, a))
          << "points " << it.row() << " and " << c << " coupled across a separator";
    }

  // Symbolic: every entry of M (lower, permuted) is in its column's supernode rows, and each
  // supernode's boundary rows are rows of its parent.
  const SupernodalSymbolic S = analyseSupernodal(M, t);
  for (int c = 0; c < n; ++c) {
    const int pc = t.iperm[size_t(c)], s = S.colSuper[size_t(pc)];
    for (SparseMatrix::InnerIterator it(M, c); it; ++it) {
      const int pr = t.iperm[size_t(it.row())];
      if (pr < pc) continue;
      ASSERT_TRUE(std::binary_search(S.rows(s), S.rows(s) + S.nrows(s), pr));
    }
  }
  for (int s = 0; s < S.supernodes(); ++s) {
    const int p = S.parent[size_t(s)];
    EXPECT_TRUE(std::is_sorted(S.rows(s), S.rows(s) + S.nrows(s)));
    if (p < 0) {
      EXPECT_EQ(S.nrows(s), S.width(s));
      continue;
    }
    for (int i = S.width(s); i < S.nrows(s); ++i)
      ASSERT_TRUE(std::binary_search(S.rows(p), S.rows(p) + S.nrows(p), S.rows(s)[i]));
  }
}

const std::vector<std::array<int, 4>> kBoxes = {{2, 2, 2, 64},   {5, 4, 3, 4},     {9, 9, 9, 8},
                                                {13, 7, 20, 27}, {16, 16, 16, 64}, {3, 30, 4, 1}};
INSTANTIATE_TEST_SUITE_P(Boxes, OrderingTest,
                         ::testing::Combine(::testing::ValuesIn(kBoxes),
                                            ::testing::Values(DissectionOptions::Method::Planes,
                                                              DissectionOptions::Method::Boxes)));

// The diagonal slabs must pay off: less fill than axis-aligned boxes on a cube.
TEST(Ordering, PlanesFillLessThanBoxes) {
  const Grid g = box(21, 21, 21);
  const SparseMatrix M = assembleBiLaplacian(g);
  DissectionOptions planes, boxes;
  boxes.method = DissectionOptions::Method::Boxes;
  const SupernodalSymbolic a = analyseSupernodal(M, boxNestedDissection(g, planes));
  const SupernodalSymbolic b = analyseSupernodal(M, boxNestedDissection(g, boxes));
  EXPECT_LT(a.nnzL, 0.85 * b.nnzL);
  EXPECT_LT(a.factorFlops, 0.7 * b.factorFlops);
}

}  // namespace
}  // namespace grid_ordering_test
