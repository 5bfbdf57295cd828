#include "stream_constraints.hpp"

#include <algorithm>
#include <cmath>

namespace hairsketch {

namespace {

// Claims the 8 corners of the cell containing world point m, if m is inside the volume.
void claimCell(const Grid& g, const Eigen::Vector3d& m, const Eigen::Vector3d& target,
               std::vector<Constraint>& out) {
  if (!g.insideVolume(m)) return;
  const Eigen::Vector3d u = (m - g.origin) / g.step;
  const int dims[3] = {g.nx, g.ny, g.nz};
  int c[3];
  for (int a = 0; a < 3; ++a) {
    // A point on the upper face belongs to the last cell.
    c[a] = std::min(int(std::floor(u[a])), dims[a] - 2);
    c[a] = std::max(c[a], 0);
  }
  for (int dk = 0; dk < 2; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di)
        out.push_back({g.index(c[0] + di, c[1] + dj, c[2] + dk), target});
}

}  // namespace

void appendStreamConstraints(const Grid& g, const double* pts, size_t count, bool extend,
                             std::vector<Constraint>& out, std::vector<ConstraintColour>* colours,
                             const double* params) {
  (void)params;  // none shapes the constraints (Volume is read by the shape rules)
  Eigen::Vector3d lastTangent = Eigen::Vector3d::Zero();
  double lastLength = 0;
  for (size_t s = 0; s + 1 < count; ++s) {
    const Eigen::Vector3d a(pts[3 * s], pts[3 * s + 1], pts[3 * s + 2]);
    const Eigen::Vector3d b(pts[3 * s + 3], pts[3 * s + 4], pts[3 * s + 5]);
    const double len = (b - a).norm();
    if (!(len > 0)) continue;
    const Eigen::Vector3d t = (b - a) / len;
    claimCell(g, 0.5 * (a + b), t, out);
    if (colours) colours->resize(out.size(), ConstraintColour::Blue);
    lastTangent = t;
    lastLength = len;
  }
  if (!extend || lastLength == 0) return;
  const Eigen::Vector3d end(pts[3 * (count - 1)], pts[3 * (count - 1) + 1],
                            pts[3 * (count - 1) + 2]);
  const int K = kStreamExtensionSegments;
  for (int k = 1; k <= K; ++k) {
    const double m = 1.0 - double(k) / K;
    const Eigen::Vector3d mid = end + (k - 0.5) * lastLength * lastTangent;
    claimCell(g, mid, m * lastTangent, out);
    if (colours) colours->resize(out.size(), ConstraintColour::Red);
  }
}

}  // namespace hairsketch
