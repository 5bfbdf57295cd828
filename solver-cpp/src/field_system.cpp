#include "field_system.hpp"

#include <cmath>
#include <vector>

namespace hairsketch {
namespace {

constexpr int kOffsets[6][3] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};

int neighbourCount(const Grid& g, int i, int j, int k) {
  int c = 0;
  for (const auto& o : kOffsets) c += g.contains(i + o[0], j + o[1], k + o[2]);
  return c;
}

}  // namespace

SparseMatrix assembleLaplacian(const Grid& g) {
  const int n = int(g.size());
  std::vector<Eigen::Triplet<double>> trips;
  trips.reserve(size_t(n) * 7);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int p = g.index(i, j, k);
        const double w = 1.0 / neighbourCount(g, i, j, k);
        trips.emplace_back(p, p, -1.0);
        for (const auto& o : kOffsets)
          if (g.contains(i + o[0], j + o[1], k + o[2]))
            trips.emplace_back(p, g.index(i + o[0], j + o[1], k + o[2]), w);
      }
  SparseMatrix D(n, n);
  D.setFromTriplets(trips.begin(), trips.end());
  return D;
}

SparseMatrix assembleBiLaplacian(const Grid& g) {
  const SparseMatrix D = assembleLaplacian(g);
  SparseMatrix M = SparseMatrix(D.transpose()) * D;
  M.makeCompressed();
  return M;
}

Field assembleRhs(const Grid& g, const ConstraintSet& set, double omega) {
  Field B = Field::Zero(g.size(), 3);
  for (const Constraint& c : set) B.row(c.index) = omega * omega * c.target.transpose();
  return B;
}

Field assembleRhs(const Grid& g, const ConstraintSet& set, double omega, double beta2,
                  const Field& G) {
  Field B = assembleRhs(g, set, omega);
  if (beta2 != 0 && G.rows() > 0) B += beta2 * G;
  return B;
}

Status validatePrior(const Grid& g, double beta2, const Field& G) {
  if (!std::isfinite(beta2) || beta2 < 0)
    return Status::Error(StatusCode::InvalidInput, "prior weight beta^2 must be finite and >= 0");
  if (G.rows() != 0 && G.rows() != g.size())
    return Status::Error(StatusCode::InvalidInput,
                         "prior field must be empty or have one row per grid point");
  if (!G.allFinite()) return Status::Error(StatusCode::InvalidInput, "prior field must be finite");
  return Status::Ok();
}

Eigen::VectorXd penaltyDiagonal(const Grid& g, const ConstraintSet& set, double omega) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(g.size());
  for (const Constraint& c : set) w[c.index] = omega * omega;
  return w;
}

double fieldEnergy(const Grid& g, const ConstraintSet& set, double omega, const Field& T) {
  const SparseMatrix D = assembleLaplacian(g);
  const Field DT = D * T;
  double e = DT.squaredNorm();
  for (const Constraint& c : set)
    e += omega * omega * (T.row(c.index).transpose() - c.target).squaredNorm();
  return e;
}

double fieldEnergy(const Grid& g, const ConstraintSet& set, double omega, const Field& T,
                   double beta2, const Field& G) {
  double e = fieldEnergy(g, set, omega, T);
  if (beta2 != 0) e += beta2 * (G.rows() > 0 ? Field(T - G).squaredNorm() : T.squaredNorm());
  return e;
}

void applyBiLaplacian(const Grid& g, const Field& X, Field& Y) {
  // Two passes: L = D X, then Y = D^T L. D^T has entries D[q, p] = 1 / |N(q)| for neighbours.
  const int n = int(g.size());
  Field L(n, 3);
  Eigen::VectorXd inv(n);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int p = g.index(i, j, k);
        inv[p] = 1.0 / neighbourCount(g, i, j, k);
        Eigen::RowVector3d s = Eigen::RowVector3d::Zero();
        for (const auto& o : kOffsets)
          if (g.contains(i + o[0], j + o[1], k + o[2]))
            s += X.row(g.index(i + o[0], j + o[1], k + o[2]));
        L.row(p) = inv[p] * s - X.row(p);
      }
  Y.resize(n, 3);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int p = g.index(i, j, k);
        Eigen::RowVector3d s = -L.row(p);
        for (const auto& o : kOffsets)
          if (g.contains(i + o[0], j + o[1], k + o[2])) {
            const int q = g.index(i + o[0], j + o[1], k + o[2]);
            s += inv[q] * L.row(q);
          }
        Y.row(p) = s;
      }
}

}  // namespace hairsketch
