#include "braid_bun.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

namespace hairsketch {

namespace {

Status inRange(const char* what, double v, double lo, double hi, bool openLo) {
  if (!std::isfinite(v))
    return Status::Error(StatusCode::NonFinite, std::string(what) + " is not finite");
  if ((openLo ? !(v > lo) : !(v >= lo)) || !(v <= hi))
    return Status::Error(StatusCode::InvalidInput, std::string(what) + " must be in " +
                                                       (openLo ? "(" : "[") + std::to_string(lo) +
                                                       ", " + std::to_string(hi) + "], is " +
                                                       std::to_string(v));
  return Status::Ok();
}

}  // namespace

Status parseBraidParams(const double* p, size_t count, BraidParams& out) {
  if (count != kBraidParamCount && count != kBraidSection)
    return Status::Error(StatusCode::InvalidInput, "a braid has " +
                                                       std::to_string(kBraidParamCount) +
                                                       " parameters, not " + std::to_string(count));
  Status s;
  if (!(s = inRange("width", p[kBraidWidth], 0, 3, true)).ok()) return s;
  if (!(s = inRange("crossings", p[kBraidCrossings], 0, 40, true)).ok()) return s;
  if (!(s = inRange("tightness", p[kBraidTightness], 0, 1, false)).ok()) return s;
  if (!(s = inRange("tail length", p[kBraidTailLength], 0, 20, false)).ok()) return s;
  const double section = count > kBraidSection ? p[kBraidSection] : 0;
  if (section != 0 && section != 1)
    return Status::Error(StatusCode::InvalidInput, "braid section must be 0 or 1");
  out = {p[kBraidWidth], p[kBraidCrossings], p[kBraidTightness], p[kBraidTailLength], section != 0};
  return Status::Ok();
}

Status parseBunParams(const double* p, size_t count, BunParams& out) {
  if (count != kBunParamCount && count != kBunSection)
    return Status::Error(StatusCode::InvalidInput, "a bun has " + std::to_string(kBunParamCount) +
                                                       " parameters, not " + std::to_string(count));
  Status s;
  if (!(s = inRange("radius", p[kBunRadius], 0, 2, false)).ok()) return s;
  if (!(s = inRange("height", p[kBunHeight], 0, 2, true)).ok()) return s;
  if (!(s = inRange("turns", p[kBunTurns], 0, 10, true)).ok()) return s;
  const double section = count > kBunSection ? p[kBunSection] : 0;
  if (section != 0 && section != 1)
    return Status::Error(StatusCode::InvalidInput, "bun section must be 0 or 1");
  out = {p[kBunRadius], p[kBunHeight], p[kBunTurns], section != 0};
  return Status::Ok();
}

size_t braidGatherIndex(const uint8_t* offScalp, size_t n) {
  if (!offScalp) return 0;
  for (size_t k = 0; k < n; ++k)
    if (offScalp[k]) return k;
  return 0;
}

PonytailParams braidAsPonytail(const double* spine, size_t n, size_t gather, const BraidParams& prm,
                               double* braidLength) {
  PonytailParams pp;
  pp.gather = 1;
  if (n == 0) return pp;
  gather = std::min(gather, n - 1);
  auto at = [&](size_t i) {
    return Eigen::Vector3d(spine[3 * i], spine[3 * i + 1], spine[3 * i + 2]);
  };
  std::vector<double> s(n, 0.0);
  for (size_t i = gather + 1; i < n; ++i) s[i] = s[i - 1] + (at(i) - at(i - 1)).norm();
  const double total = s[n - 1];
  const double end = std::max(0.0, total - prm.tailLength);
  if (braidLength) *braidLength = end;
  for (size_t i = gather; i < n; ++i) {
    if (i > gather && s[i] > end) break;
    const Eigen::Vector3d d = at(std::min(i + 1, n - 1)) - at(i > gather ? i - 1 : i);
    const Eigen::Vector3d axis = d.norm() > 1e-12 ? d.normalized() : Eigen::Vector3d(0, -1, 0);
    const double f = end > 0 ? std::min(s[i] / end, 1.0) : 0.0;
    pp.circles.push_back({at(i), axis, 0.5 * prm.width * (1 - 0.4 * f)});
  }
  return pp;
}

BunFrame bunFrame(const double* loop, size_t n, const BunParams& prm,
                  const Eigen::Vector3d* headCentre) {
  BunFrame f;
  if (n == 0) return f;
  for (size_t i = 0; i < n; ++i)
    f.centre += Eigen::Vector3d(loop[3 * i], loop[3 * i + 1], loop[3 * i + 2]);
  f.centre /= double(n);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  double size = 0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d =
        Eigen::Vector3d(loop[3 * i], loop[3 * i + 1], loop[3 * i + 2]) - f.centre;
    C += d * d.transpose();
    size += d.norm();
  }
  size /= double(n);
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();
  if (n >= 3) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
    axis = es.eigenvectors().col(0);  // the least variance
  }
  const Eigen::Vector3d out =
      headCentre ? Eigen::Vector3d(f.centre - *headCentre) : Eigen::Vector3d::UnitY();
  if (axis.dot(out) < 0) axis = -axis;
  if (n < 3 && headCentre && out.norm() > 0) axis = out.normalized();
  f.axis = axis.normalized();
  f.radius = prm.radius > 0 ? prm.radius : std::max(size, 0.1);
  return f;
}

PonytailParams bunAsPonytail(const BunFrame& f, const BunParams& prm, std::vector<double>& spine) {
  const Eigen::Vector3d a = f.centre - 1.5 * f.radius * f.axis, b = f.centre + prm.height * f.axis;
  spine = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z()};
  PonytailParams pp;
  pp.gather = 1;
  pp.circles.push_back({f.centre + 0.05 * f.axis, f.axis, 0.6 * f.radius});
  pp.circles.push_back({b, f.axis, 0.6 * f.radius});
  return pp;
}

}  // namespace hairsketch
