#include "scalp_roots.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

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

Eigen::Vector3d ScalpSampler::corner(size_t t, int k) const {
  const float* p = positions_.data() + 3 * size_t(indices_[3 * t + size_t(k)]);
  return Eigen::Vector3d(p[0], p[1], p[2]) - center_;
}

Eigen::Vector3d ScalpSampler::normal(size_t t) const {
  const Eigen::Vector3d a = corner(t, 0), b = corner(t, 1), c = corner(t, 2);
  Eigen::Vector3d nrm = (b - a).cross(c - a);
  const double len = nrm.norm();
  nrm = len > 0 ? Eigen::Vector3d(nrm / len) : Eigen::Vector3d::Zero();
  if (nrm.dot(a + b + c) < 0) nrm = -nrm;  // away from the center
  return nrm;
}

double ScalpSampler::estimateBytes(size_t vertexCount, size_t triangleCount) {
  // positions, indices, flags; per triangle its bin range (8, temporary) and about 6 bin
  // entries (4 each); the bin starts (at most 512 x 1024 + 1).
  return 12.0 * double(vertexCount) + (12.0 + 1 + 8 + 24) * double(triangleCount) +
         4.0 * (512 * 1024 + 1);
}

Status ScalpSampler::setScalpMask(const uint8_t* scalp, size_t nt) {
  if (!built()) return Status::Error(StatusCode::NotReady, "scalp mask: no scalp mesh set");
  if (!scalp || nt != scalp_.size())
    return Status::Error(StatusCode::InvalidInput,
                         "scalp mask: " + std::to_string(nt) + " flags for a head of " +
                             std::to_string(scalp_.size()) + " triangles");
  std::copy(scalp, scalp + nt, scalp_.begin());
  return Status::Ok();
}

Status ScalpSampler::build(const float* pos, size_t nv, const uint32_t* idx, size_t nt,
                           const uint8_t* scalp, const Eigen::Vector3d& center) {
  positions_.clear();
  indices_.clear();
  scalp_.clear();
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
  positions_.assign(pos, pos + 3 * nv);
  indices_.assign(idx, idx + 3 * nt);
  radius_ = 0;
  for (size_t v = 0; v < nv; ++v)
    radius_ = std::max(
        radius_, (Eigen::Vector3d(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]) - center).norm());
  // Bins over (theta, phi): about 8 triangles' worth of area per bin, within limits (a triangle
  // goes to every bin its cap touches: on 1M triangles, 4 per bin keep 42 MB of bins, 8 keep 26
  // and 16 keep 17, and a ray tests every triangle of its bin: 214K rays took 130, 190 and 250 ms).
  const double target = std::sqrt(double(nt) / 4.0);
  nTheta_ = std::clamp(int(target / 2), 8, 512);
  nPhi_ = 2 * nTheta_;
  const double dTheta = kPi / nTheta_, dPhi = 2 * kPi / nPhi_;
  // Each triangle goes to every bin its bounding cap touches: theta rows i0..i1, and in each
  // row the phi columns j0 .. j0 + span (mod nPhi). The cap around the normalised vertex
  // directions (axis = their mean) contains the spherical triangle because caps smaller than a
  // hemisphere are geodesically convex. Triangles whose cap is not small (containing or near
  // the center) go everywhere.
  struct Range {
    uint16_t i0, i1, j0, span;
  };
  std::vector<Range> range(nt);
  const double margin = 1e-6;
  for (size_t t = 0; t < nt; ++t) {
    Eigen::Vector3d u[3];
    bool degenerate = false;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d v = corner(t, k);
      const double l = v.norm();
      if (!(l > 1e-12 * (radius_ + 1e-300))) degenerate = true;
      u[k] = degenerate ? Eigen::Vector3d::Zero() : Eigen::Vector3d(v / l);
    }
    Eigen::Vector3d axis = u[0] + u[1] + u[2];
    double alpha = kPi;
    if (!degenerate && axis.norm() > 1e-9) {
      axis.normalize();
      double minCos = 1;
      for (int k = 0; k < 3; ++k) minCos = std::min(minCos, axis.dot(u[k]));
      alpha = std::acos(std::clamp(minCos, -1.0, 1.0)) + margin;
    }
    Range r{0, uint16_t(nTheta_ - 1), 0, uint16_t(nPhi_ - 1)};  // everywhere
    if (alpha < 0.45 * kPi) {
      const double thetaC = std::acos(std::clamp(axis.y(), -1.0, 1.0));
      const double phiC = std::atan2(axis.x(), axis.z());
      const double lo = thetaC - alpha, hi = thetaC + alpha;
      r.i0 = uint16_t(std::max(0, int(std::floor(lo / dTheta))));
      r.i1 = uint16_t(std::min(nTheta_ - 1, int(std::floor(hi / dTheta))));
      if (lo > 0 && hi < kPi) {
        const double halfPhi =
            std::asin(std::min(1.0, std::sin(alpha) / std::sin(thetaC))) + margin;
        if (halfPhi < kPi) {
          double p0 = phiC - halfPhi;
          p0 -= 2 * kPi * std::floor(p0 / (2 * kPi));  // [0, 2 pi)
          const int j0 = std::min(nPhi_ - 1, int(std::floor(p0 / dPhi)));
          const int j1 = int(std::floor((p0 + 2 * halfPhi) / dPhi));  // may pass 2 pi: wraps
          r.j0 = uint16_t(j0);
          r.span = uint16_t(std::clamp(j1 - j0, 0, nPhi_ - 1));
        }
      }
    }
    range[t] = r;
  }
  // Counted, then filled in triangle order (each bin lists its triangles in mesh order).
  const size_t nb = size_t(nTheta_) * nPhi_;
  binStart_.assign(nb + 1, 0);
  for (const Range& r : range)
    for (int i = r.i0; i <= r.i1; ++i)
      for (int s = 0; s <= r.span; ++s) ++binStart_[size_t(i) * nPhi_ + (r.j0 + s) % nPhi_ + 1];
  for (size_t b = 0; b < nb; ++b) binStart_[b + 1] += binStart_[b];
  binTris_.resize(binStart_[nb]);
  std::vector<uint32_t> fill(binStart_.begin(), binStart_.end() - 1);
  for (size_t t = 0; t < nt; ++t) {
    const Range& r = range[t];
    for (int i = r.i0; i <= r.i1; ++i)
      for (int s = 0; s <= r.span; ++s)
        binTris_[fill[size_t(i) * nPhi_ + (r.j0 + s) % nPhi_]++] = uint32_t(t);
  }
  scalp_.assign(scalp, scalp + nt);
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
    const size_t t = binTris_[k];
    const Eigen::Vector3d a = corner(t, 0), e1 = corner(t, 1) - a, e2 = corner(t, 2) - a;
    // Moller-Trumbore with the ray origin at the center (local origin 0).
    const Eigen::Vector3d pv = dir.cross(e2);
    const double det = e1.dot(pv);
    if (std::abs(det) < 1e-300) continue;
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = -a;
    const double u = s.dot(pv) * inv;
    if (u < 0 || u > 1) continue;
    const Eigen::Vector3d qv = s.cross(e1);
    const double v = dir.dot(qv) * inv;
    if (v < 0 || u + v > 1) continue;
    const double tHit = e2.dot(qv) * inv;
    if (tHit > 0 && tHit > tBest) {
      tBest = tHit;
      triBest = int(t);
    }
  }
  return triBest >= 0;
}

Status ScalpSampler::sample(const RootParams& p, std::vector<Eigen::Vector3f>& roots,
                            std::vector<uint32_t>* sampleIds) const {
  roots.clear();
  if (sampleIds) sampleIds->clear();
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
  std::vector<uint32_t> ids;
  for (int i = 0; i < nT; ++i)
    for (int j = 0; j < nP; ++j) {
      // Always two draws per sample, so the sequence does not depend on the jitter.
      const double ut = rng.uniform(), up = rng.uniform();
      const double theta = std::clamp((i + 0.5 + p.jitter * (ut - 0.5)) * dT, 0.0, kPi);
      const double phi = (j + 0.5 + p.jitter * (up - 0.5)) * dP;
      const Eigen::Vector3d dir = sphericalDirection(theta, phi);
      double t;
      int tri;
      if (!castOutermost(dir, t, tri) || !scalp_[size_t(tri)]) continue;
      const Eigen::Vector3d hit = center_ + t * dir + pushOut * normal(size_t(tri));
      all.push_back(hit.cast<float>());
      ids.push_back(uint32_t(i) * uint32_t(nP) + uint32_t(j));
    }
  if (p.maxStrands > 0 && all.size() > size_t(p.maxStrands)) {
    const size_t m = size_t(p.maxStrands), total = all.size();
    roots.resize(m);
    for (size_t k = 0; k < m; ++k) roots[k] = all[k * total / m];
    if (sampleIds) {
      sampleIds->resize(m);
      for (size_t k = 0; k < m; ++k) (*sampleIds)[k] = ids[k * total / m];
    }
  } else {
    roots.swap(all);
    if (sampleIds) sampleIds->swap(ids);
  }
  return Status::Ok();
}

void dropLoneRoots(const std::vector<Eigen::Vector3f>& all, std::vector<uint32_t>& pick,
                   float reach) {
  size_t n = pick.size();
  if (n == 0 || !(reach > 0) || !std::isfinite(reach)) return;
  Eigen::AlignedBox3f box;
  for (uint32_t i : pick) box.extend(all[i]);
  // a hash grid of the picked roots, cells of the reach: neighbours lie in the 27 round a cell
  auto neighbours = [&](float cell, auto&& visit) {
    std::unordered_map<int64_t, std::vector<uint32_t>> grid;
    auto key = [&](const Eigen::Vector3f& p, int dx, int dy, int dz) {
      const Eigen::Vector3f q = (p - box.min()) / cell;
      return (int64_t(std::floor(q.x())) + dx) * 73856093LL ^
             (int64_t(std::floor(q.y())) + dy) * 19349663LL ^
             (int64_t(std::floor(q.z())) + dz) * 83492791LL;
    };
    for (size_t k = 0; k < n; ++k) grid[key(all[pick[k]], 0, 0, 0)].push_back(uint32_t(k));
    for (size_t k = 0; k < n; ++k)
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            auto it = grid.find(key(all[pick[k]], dx, dy, dz));
            if (it == grid.end()) continue;
            for (uint32_t j : it->second)
              if (j != k) visit(k, j, (all[pick[k]] - all[pick[j]]).norm());
          }
  };
  // dropping a root can leave its one neighbour alone: again until none goes (a few rounds)
  for (int round = 0; round < 8; ++round) {
    std::vector<int> count(n, 0);
    neighbours(reach, [&](size_t k, uint32_t, float d) { count[k] += d <= reach ? 1 : 0; });
    size_t out = 0;
    for (size_t k = 0; k < n; ++k)
      if (count[k] >= kLoneNeighbours) pick[out++] = pick[k];
    if (out == n) break;
    pick.resize(out);
    n = out;
  }
}

}  // namespace hairsketch
