#include "scalp_roots.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rng.hpp"

namespace hairsketch {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr size_t kMaxTriangles = size_t(1) << 24;
constexpr int64_t kMaxRays = int64_t(1) << 24;
}  // namespace

Eigen::Vector3d sphericalDirection(double theta, double phi) {
  const double st = std::sin(theta);
  return {st * std::sin(phi), std::cos(theta), st * std::cos(phi)};
}

int ScalpSampler::binOf(double theta, double phi) const {
  int i = int(theta / kPi * nTheta_);
  int j = int(phi / (2 * kPi) * nPhi_);
  i = std::clamp(i, 0, nTheta_ - 1);
  j = ((j % nPhi_) + nPhi_) % nPhi_;
  return i * nPhi_ + j;
}

Status ScalpSampler::build(const float* pos, size_t nv, const uint32_t* idx, size_t nt,
                           const uint8_t* scalp, const Eigen::Vector3d& center) {
  tris_.clear();
  binStart_.clear();
  binTris_.clear();
  if (!center.allFinite()) return Status::Error(StatusCode::NonFinite, "scalp: center");
  if (nt == 0 || nv == 0 || !pos || !idx || !scalp)
    return Status::Error(StatusCode::InvalidInput, "scalp: empty mesh");
  if (nt > kMaxTriangles) return Status::Error(StatusCode::InvalidInput, "scalp: too large");
  for (size_t i = 0; i < 3 * nv; ++i)
    if (!std::isfinite(pos[i]))
      return Status::Error(StatusCode::NonFinite, "scalp: non-finite vertex position");
  for (size_t i = 0; i < 3 * nt; ++i)
    if (idx[i] >= nv)
      return Status::Error(StatusCode::InvalidInput,
                           "scalp: triangle index " + std::to_string(idx[i]) + " out of range");
  center_ = center;
  radius_ = 0;
  tris_.resize(nt);
  auto vert = [&](uint32_t v) -> Eigen::Vector3d {
    return Eigen::Vector3d(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]) - center;
  };
  for (size_t t = 0; t < nt; ++t) {
    const Eigen::Vector3d a = vert(idx[3 * t]), b = vert(idx[3 * t + 1]), c = vert(idx[3 * t + 2]);
    Tri& tr = tris_[t];
    tr.a = a;
    tr.e1 = b - a;
    tr.e2 = c - a;
    Eigen::Vector3d nrm = tr.e1.cross(tr.e2);
    const double len = nrm.norm();
    nrm = len > 0 ? Eigen::Vector3d(nrm / len) : Eigen::Vector3d::Zero();
    if (nrm.dot(a + b + c) < 0) nrm = -nrm;  // away from the center
    tr.normal = nrm;
    tr.scalp = scalp[t] != 0;
    radius_ = std::max({radius_, a.norm(), b.norm(), c.norm()});
  }
  // Bins over (theta, phi): about 4 triangles' worth of area per bin, within limits.
  const double target = std::sqrt(double(nt) / 2.0);
  nTheta_ = std::clamp(int(target / 2), 8, 512);
  nPhi_ = 2 * nTheta_;
  const double dTheta = kPi / nTheta_, dPhi = 2 * kPi / nPhi_;
  // Each triangle goes to every bin its bounding cap touches. The cap around the normalised
  // vertex directions (axis = their mean) contains the spherical triangle because caps smaller
  // than a hemisphere are geodesically convex. Triangles whose cap is not small (containing or
  // near the center) go everywhere.
  std::vector<std::pair<uint32_t, uint32_t>> claims;  // (bin, triangle)
  claims.reserve(nt * 4);
  const double margin = 1e-6;
  for (size_t t = 0; t < nt; ++t) {
    const Tri& tr = tris_[t];
    const Eigen::Vector3d v[3] = {tr.a, tr.a + tr.e1, tr.a + tr.e2};
    Eigen::Vector3d u[3];
    bool degenerate = false;
    for (int k = 0; k < 3; ++k) {
      const double l = v[k].norm();
      if (!(l > 1e-12 * (radius_ + 1e-300))) degenerate = true;
      u[k] = degenerate ? Eigen::Vector3d::Zero() : Eigen::Vector3d(v[k] / l);
    }
    Eigen::Vector3d axis = u[0] + u[1] + u[2];
    double alpha = kPi;
    if (!degenerate && axis.norm() > 1e-9) {
      axis.normalize();
      double minCos = 1;
      for (int k = 0; k < 3; ++k) minCos = std::min(minCos, axis.dot(u[k]));
      alpha = std::acos(std::clamp(minCos, -1.0, 1.0)) + margin;
    }
    int i0 = 0, i1 = nTheta_ - 1;
    bool allPhi = true;
    double phiC = 0, halfPhi = kPi;
    if (alpha < 0.45 * kPi) {
      const double thetaC = std::acos(std::clamp(axis.y(), -1.0, 1.0));
      phiC = std::atan2(axis.x(), axis.z());
      const double lo = thetaC - alpha, hi = thetaC + alpha;
      i0 = std::max(0, int(std::floor(lo / dTheta)));
      i1 = std::min(nTheta_ - 1, int(std::floor(hi / dTheta)));
      if (lo > 0 && hi < kPi) {
        halfPhi = std::asin(std::min(1.0, std::sin(alpha) / std::sin(thetaC))) + margin;
        allPhi = halfPhi >= kPi;
      }
    }
    for (int i = i0; i <= i1; ++i) {
      if (allPhi) {
        for (int j = 0; j < nPhi_; ++j) claims.emplace_back(uint32_t(i * nPhi_ + j), uint32_t(t));
      } else {
        double p0 = phiC - halfPhi;
        p0 -= 2 * kPi * std::floor(p0 / (2 * kPi));  // [0, 2 pi)
        const int j0 = int(std::floor(p0 / dPhi));
        const int span = std::min(nPhi_ - 1, int(std::ceil(2 * halfPhi / dPhi)) + 1);
        for (int s = 0; s <= span; ++s)
          claims.emplace_back(uint32_t(i * nPhi_ + (j0 + s) % nPhi_), uint32_t(t));
      }
    }
  }
  const size_t nb = size_t(nTheta_) * nPhi_;
  binStart_.assign(nb + 1, 0);
  for (const auto& c : claims) ++binStart_[c.first + 1];
  for (size_t b = 0; b < nb; ++b) binStart_[b + 1] += binStart_[b];
  binTris_.resize(claims.size());
  std::vector<uint32_t> fill(binStart_.begin(), binStart_.end() - 1);
  for (const auto& c : claims) binTris_[fill[c.first]++] = c.second;
  return Status::Ok();
}

bool ScalpSampler::castOutermost(const Eigen::Vector3d& dir, double& tBest, int& triBest) const {
  const double theta = std::acos(std::clamp(dir.y() / dir.norm(), -1.0, 1.0));
  double phi = std::atan2(dir.x(), dir.z());
  if (phi < 0) phi += 2 * kPi;
  const int b = binOf(theta, phi);
  tBest = -1;
  triBest = -1;
  for (uint32_t k = binStart_[b]; k < binStart_[b + 1]; ++k) {
    const Tri& tr = tris_[binTris_[k]];
    // Moller-Trumbore with the ray origin at the center (local origin 0).
    const Eigen::Vector3d pv = dir.cross(tr.e2);
    const double det = tr.e1.dot(pv);
    if (std::abs(det) < 1e-300) continue;
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = -tr.a;
    const double u = s.dot(pv) * inv;
    if (u < 0 || u > 1) continue;
    const Eigen::Vector3d qv = s.cross(tr.e1);
    const double v = dir.dot(qv) * inv;
    if (v < 0 || u + v > 1) continue;
    const double t = tr.e2.dot(qv) * inv;
    if (t > 0 && t > tBest) {
      tBest = t;
      triBest = int(binTris_[k]);
    }
  }
  return triBest >= 0;
}

Status ScalpSampler::sample(const RootParams& p, std::vector<Eigen::Vector3f>& roots) const {
  roots.clear();
  if (!built()) return Status::Error(StatusCode::NotReady, "no scalp mesh set");
  if (!(p.thetaStepDeg > 0) || !(p.phiStepDeg > 0) || !std::isfinite(p.thetaStepDeg) ||
      !std::isfinite(p.phiStepDeg))
    return Status::Error(StatusCode::InvalidInput, "root sampling steps must be > 0");
  if (!(p.jitter >= 0 && p.jitter <= 1))
    return Status::Error(StatusCode::InvalidInput, "jitter must be in [0, 1]");
  if (p.maxStrands < 0) return Status::Error(StatusCode::InvalidInput, "maxStrands < 0");
  const int nT = std::max(1, int(std::ceil(180.0 / p.thetaStepDeg - 1e-9)));
  const int nP = std::max(1, int(std::ceil(360.0 / p.phiStepDeg - 1e-9)));
  if (int64_t(nT) * nP > kMaxRays)
    return Status::Error(StatusCode::InvalidInput, "too many root samples (steps too small)");
  const double dT = p.thetaStepDeg * kPi / 180, dP = p.phiStepDeg * kPi / 180;
  const double pushOut = 1e-5 * radius_;
  Pcg32 rng(p.seed);
  std::vector<Eigen::Vector3f> all;
  for (int i = 0; i < nT; ++i)
    for (int j = 0; j < nP; ++j) {
      // Always two draws per sample, so the sequence does not depend on the jitter.
      const double ut = rng.uniform(), up = rng.uniform();
      const double theta = std::clamp((i + 0.5 + p.jitter * (ut - 0.5)) * dT, 0.0, kPi);
      const double phi = (j + 0.5 + p.jitter * (up - 0.5)) * dP;
      const Eigen::Vector3d dir = sphericalDirection(theta, phi);
      double t;
      int tri;
      if (!castOutermost(dir, t, tri) || !tris_[tri].scalp) continue;
      const Eigen::Vector3d hit = center_ + t * dir + pushOut * tris_[tri].normal;
      all.push_back(hit.cast<float>());
    }
  if (p.maxStrands > 0 && all.size() > size_t(p.maxStrands)) {
    const size_t m = size_t(p.maxStrands), total = all.size();
    roots.resize(m);
    for (size_t k = 0; k < m; ++k) roots[k] = all[k * total / m];
  } else {
    roots.swap(all);
  }
  return Status::Ok();
}

}  // namespace hairsketch
