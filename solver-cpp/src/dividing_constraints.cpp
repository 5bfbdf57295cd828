#include "dividing_constraints.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace hairsketch {

namespace {

Eigen::Vector3d pointAt(const double* pts, size_t i) {
  return Eigen::Vector3d(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]);
}

}  // namespace

Status parseDividingParams(const double* params, size_t paramCount, size_t pointCount,
                           DividingParams& out) {
  const size_t expected = kDividingParamCount + 3 * pointCount;
  if (paramCount != expected)
    return Status::Error(StatusCode::InvalidInput,
                         "dividing parameter block has " + std::to_string(paramCount) +
                             " numbers, expected " + std::to_string(kDividingParamCount) +
                             " + 3 * " + std::to_string(pointCount) + " = " +
                             std::to_string(expected));
  for (size_t i = 0; i < paramCount; ++i)
    if (!std::isfinite(params[i]))
      return Status::Error(StatusCode::NonFinite,
                           "dividing parameter " + std::to_string(i) + " is not finite");
  if (!(params[kDividingSigma] > 0))
    return Status::Error(StatusCode::InvalidInput, "dividing sigma must be > 0");
  const double* normals = params + kDividingParamCount;
  for (size_t i = 0; i < pointCount; ++i) {
    const double* n = normals + 3 * i;
    if (n[0] == 0 && n[1] == 0 && n[2] == 0)
      return Status::Error(StatusCode::InvalidInput,
                           "dividing scalp normal at point " + std::to_string(i) + " is zero");
  }
  out.sigma = params[kDividingSigma];
  out.h = params[kDividingH];
  out.alpha0 = params[kDividingAlpha0];
  out.alpha1 = params[kDividingAlpha1];
  out.normals = normals;
  return Status::Ok();
}

std::vector<DividingFrame> dividingFrames(const double* pts, size_t n, const DividingParams& prm) {
  std::vector<DividingFrame> frames(n);
  if (n < 2) return frames;  // a single point has no tangent
  for (size_t i = 0; i < n; ++i) {
    DividingFrame& f = frames[i];
    f.origin = pointAt(pts, i);
    const Eigen::Vector3d y = pointAt(prm.normals, i).normalized();
    const size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? n - 1 : i + 1;
    Eigen::Vector3d t = pointAt(pts, b) - pointAt(pts, a);
    t -= t.dot(y) * y;
    const double tl = t.norm();
    const double scale = (pointAt(pts, b) - pointAt(pts, a)).norm();
    if (!(tl > 1e-9 * std::max(scale, 1e-300))) continue;
    t /= tl;
    f.alpha = prm.alpha0 + (prm.alpha1 - prm.alpha0) * double(i) / double(n - 1);
    f.y = y;
    f.z = std::cos(f.alpha) * t + std::sin(f.alpha) * y.cross(t);
    f.x = y.cross(f.z);
    f.valid = true;
  }
  return frames;
}

double dividingProfile(double s, double sigma, double h) {
  const double q = (s + sigma) / sigma;
  return h * (std::exp(-0.5 * q * q) - std::exp(-0.5));
}

double dividingProfileSlope(double s, double sigma, double h) {
  const double q = (s + sigma) / sigma;
  return -h * q / sigma * std::exp(-0.5 * q * q);
}

void appendDividingConstraints(const Grid& g, const double* pts, size_t n,
                               const DividingParams& prm, std::vector<Constraint>& out,
                               std::vector<ConstraintColour>* colours) {
  const std::vector<DividingFrame> frames = dividingFrames(pts, n, prm);
  const double reach = std::max(3.0 * prm.sigma, 1.0);  // blue |u| limit, grid steps
  // Lowest v any claimed point can have: the profile's minimum minus the blue band.
  const double vLow = std::min(0.0, dividingProfile(reach, prm.sigma, prm.h)) - kDividingBlueBand;
  const double vHigh = std::max(kDividingRedTop, std::max(0.0, prm.h) + kDividingBlueBand);
  const double radius = std::sqrt(reach * reach + std::max(vHigh, -vLow) * std::max(vHigh, -vLow) +
                                  kDividingSlab * kDividingSlab) +
                        1.0;  // grid steps, covers every claimable (u, v, w)
  const int R = int(std::ceil(radius));
  for (const DividingFrame& f : frames) {
    if (!f.valid) continue;
    const Eigen::Vector3d c = (f.origin - g.origin) / g.step;
    const int ci = int(std::floor(c.x())), cj = int(std::floor(c.y())), ck = int(std::floor(c.z()));
    for (int k = ck - R; k <= ck + R + 1; ++k)
      for (int j = cj - R; j <= cj + R + 1; ++j)
        for (int i = ci - R; i <= ci + R + 1; ++i) {
          if (!g.contains(i, j, k)) continue;
          const Eigen::Vector3d r = (g.position(i, j, k) - f.origin) / g.step;
          const double u = r.dot(f.x), v = r.dot(f.y), w = r.dot(f.z);
          if (std::abs(w) > kDividingSlab || std::abs(u) < 1e-9) continue;
          const double side = u > 0 ? 1.0 : -1.0;
          const double s = std::abs(u);
          const double G = dividingProfile(s, prm.sigma, prm.h);
          if (s <= reach && std::abs(v - G) <= kDividingBlueBand) {
            const Eigen::Vector3d dir =
                (side * f.x + dividingProfileSlope(s, prm.sigma, prm.h) * f.y).normalized();
            out.push_back({g.index(i, j, k), dir});
            if (colours) colours->push_back(ConstraintColour::Blue);
          } else if (s <= kDividingRedColumn && v > G + kDividingBlueBand && v <= kDividingRedTop) {
            out.push_back({g.index(i, j, k), kDividingRedMagnitude * side * f.x});
            if (colours) colours->push_back(ConstraintColour::Red);
          }
        }
  }
}

}  // namespace hairsketch
