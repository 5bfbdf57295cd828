#include "hair_fall.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hairsketch {

namespace {

double smoothstep(double a, double b, double x) {
  const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

// Distance of every grid point to the head, approximately: the head's distance where it is
// exact (within its band; 0 inside the head), carried outward by a two-pass 26-neighbour chamfer
// transform (overestimates a straight-line distance by at most ~8 %).
std::vector<float> headDistanceOnGrid(const Grid& g, const HeadDistance& head) {
  const size_t n = size_t(g.size());
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> d(n, inf);
  constexpr float kExactBand = 0.08f;  // inside the head distance grid's exact band (0.09)
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const Eigen::Vector3d p = g.position(i, j, k);
        const float h = head.distance(float(p.x()), float(p.y()), float(p.z()));
        if (h < kExactBand) d[size_t(g.index(i, j, k))] = std::max(h, 0.f);
      }
  const float s = float(g.step);
  const float w[4] = {0, s, s * std::sqrt(2.f), s * std::sqrt(3.f)};
  auto pass = [&](int dir) {
    const int k0 = dir > 0 ? 0 : g.nz - 1, k1 = dir > 0 ? g.nz : -1;
    const int j0 = dir > 0 ? 0 : g.ny - 1, j1 = dir > 0 ? g.ny : -1;
    const int i0 = dir > 0 ? 0 : g.nx - 1, i1 = dir > 0 ? g.nx : -1;
    for (int k = k0; k != k1; k += dir)
      for (int j = j0; j != j1; j += dir)
        for (int i = i0; i != i1; i += dir) {
          float& c = d[size_t(g.index(i, j, k))];
          // the 13 neighbours already visited in this pass's order
          for (int dk = -1; dk <= 0; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
              for (int di = -1; di <= 1; ++di) {
                if (dk == 0 && (dj > 0 || (dj == 0 && di >= 0))) continue;
                const int a = i + dir * di, b = j + dir * dj, e = k + dir * dk;
                if (!g.contains(a, b, e)) continue;
                const float v = d[size_t(g.index(a, b, e))] + w[std::abs(di) + std::abs(dj) - dk];
                if (v < c) c = v;
              }
        }
  };
  pass(1);
  pass(-1);
  return d;
}

// The remaining length near a curve whose hair grows on: past any maximum length.
constexpr double kGrowsOnRemaining = 100.0;

}  // namespace

double faceColumnWeight(const Eigen::Vector3d& centre, const Eigen::Vector3d& x) {
  const double fz = x.z() - centre.z(), yc = x.y() - centre.y();
  if (!(fz > 0)) return 0;
  const double azimuth = std::abs(std::atan2(x.x() - centre.x(), fz));
  return (1 - smoothstep(0.6 * kFaceHalfAngle, kFaceHalfAngle, azimuth)) *
         smoothstep(kFaceBottom, kFaceBottom + 0.3, yc) *
         (1 - smoothstep(kFaceTop - 0.2, kFaceTop, yc));
}

Field fallDirections(const Grid& g, const HeadDistance& head, const Eigen::Vector3d& centre,
                     bool openFace, bool shape) {
  const double blend = shape ? kShapeBlend : kFallBlend;
  Field G(g.size(), 3);
  const Eigen::Vector3d down(0, -1, 0);
  const std::vector<float> dist = headDistanceOnGrid(g, head);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int p = g.index(i, j, k);
        const Eigen::Vector3d x = g.position(i, j, k);
        const float xf[3] = {float(x.x()), float(x.y()), float(x.z())};
        float o[3];
        head.outward(xf, o);
        const Eigen::Vector3d nrm(o[0], o[1], o[2]);
        // away from the vertical axis; in front (the face's side) mostly sideways, so the hair
        // of the front parts to the sides of the face rather than falling in front of it
        const double fz = x.z() - centre.z();
        Eigen::Vector3d h(x.x() - centre.x(), 0, fz > 0 ? kFallFrontSpread * fz : fz);
        const double hn = std::hypot(x.x() - centre.x(), fz);
        h = hn > 1e-9 ? Eigen::Vector3d(h / hn) : Eigen::Vector3d::Zero();
        const Eigen::Vector3d c = down + kFallSpread * h;
        const Eigen::Vector3d t = c - c.dot(nrm) * nrm;
        Eigen::Vector3d combed =
            t.norm() > 1e-3 ? Eigen::Vector3d(t.normalized() + kFallLift * nrm) : nrm;
        combed.normalize();
        // straight down away from the head, but only where down does not lead back into it
        // (below its widest part; above, combed hair runs over the head)
        const double away =
            std::isfinite(dist[size_t(p)]) ? smoothstep(0, blend, dist[size_t(p)]) : 1.0;
        const double a = away * smoothstep(-0.3, 0.3, -nrm.y());
        Eigen::Vector3d v = (1 - a) * combed + a * down;
        const double off = std::isfinite(dist[size_t(p)]) ? double(dist[size_t(p)]) : 1e9;
        if (openFace && !shape && fz > 0 && off > 0) {
          const double dx = x.x() - centre.x();
          const double inFront = faceColumnWeight(centre, x) * smoothstep(0, 0.15, off);
          const Eigen::Vector3d aside =
              Eigen::Vector3d(dx >= 0 ? kFaceAside : -kFaceAside, -1, 0).normalized();
          v = (1 - inFront) * v.normalized() + inFront * aside;
        }
        const double vn = v.norm();
        v = vn > 1e-9 ? Eigen::Vector3d(v / vn) : down;
        G.row(p) = v.transpose();
      }
  return G;
}

Grid reachGrid(const Grid& g) {
  Grid r;
  r.step = std::max(g.step, kReachCell);
  r.origin = g.origin;
  const Eigen::Vector3d ext = g.maxCorner() - g.origin;
  r.nx = std::max(2, int(std::ceil(ext.x() / r.step - 1e-9)) + 1);
  r.ny = std::max(2, int(std::ceil(ext.y() / r.step - 1e-9)) + 1);
  r.nz = std::max(2, int(std::ceil(ext.z() / r.step - 1e-9)) + 1);
  return r;
}

void curveFootprint(const Grid& g, const ReachCurve& c, CurveFootprint& out) {
  out = CurveFootprint();
  out.growsOn = c.growsOn;
  out.fringe = c.fringe;
  if (c.count < 2 || !c.points) return;
  const double* q = c.points;
  std::vector<double> s(c.count, 0);
  for (size_t k = 1; k < c.count; ++k)
    s[k] = s[k - 1] + std::hypot(q[3 * k] - q[3 * k - 3], q[3 * k + 1] - q[3 * k - 2],
                                 q[3 * k + 2] - q[3 * k - 1]);
  const double L = s.back();
  if (!(L > 0)) return;
  // a stroke that ends on the scalp combs on, but its length is what it says for the hair
  // around it (a short slicked back stays short); one extended off the head grows to the maximum
  const bool combs = c.growsOn && c.offScalp && !c.offScalp[c.count - 1];
  out.volume = c.volume;
  if (c.lift)
    for (size_t k = 0; k < c.count; ++k) out.maxLift = std::max(out.maxLift, c.lift[k]);
  if (c.setsLength && !c.fringe)
    out.stroke = {float(q[0]),
                  float(q[1]),
                  float(q[2]),
                  float(L),
                  c.growsOn && !combs,
                  combs,
                  float(q[3 * c.count - 3]),
                  float(q[3 * c.count - 2]),
                  float(q[3 * c.count - 1])};
  size_t lastSeg = c.count - 2;
  while (lastSeg > 0 && !(s[lastSeg + 1] > s[lastSeg])) --lastSeg;
  const double inf = std::numeric_limits<double>::infinity();
  // per lattice point of the curve's neighbourhood: its slot in the footprint (-1: none yet)
  std::vector<int> slot(size_t(g.size()), -1);
  std::vector<double> d2s, face2;
  const double R2 = kReachFar * kReachFar;
  for (size_t k = 0; k + 1 < c.count; ++k) {
    const double ax = q[3 * k], ay = q[3 * k + 1], az = q[3 * k + 2];
    const double ex = q[3 * k + 3] - ax, ey = q[3 * k + 4] - ay, ez = q[3 * k + 5] - az;
    const double len2 = ex * ex + ey * ey + ez * ez;
    if (!(len2 > 0)) continue;
    const double len = std::sqrt(len2);
    auto lo = [&](double a, double b, double o) {
      return std::max(0, int(std::ceil((std::min(a, b) - kReachFar - o) / g.step)));
    };
    auto hi = [&](double a, double b, double o, int n) {
      return std::min(n - 1, int(std::floor((std::max(a, b) + kReachFar - o) / g.step)));
    };
    const int i0 = lo(ax, ax + ex, g.origin.x()), i1 = hi(ax, ax + ex, g.origin.x(), g.nx);
    const int j0 = lo(ay, ay + ey, g.origin.y()), j1 = hi(ay, ay + ey, g.origin.y(), g.ny);
    const int k0 = lo(az, az + ez, g.origin.z()), k1 = hi(az, az + ez, g.origin.z(), g.nz);
    const bool last = k == lastSeg;
    const bool offScalp = c.offScalp && (c.offScalp[k] || c.offScalp[k + 1]);
    for (int kk = k0; kk <= k1; ++kk) {
      const double rz = g.origin.z() + g.step * kk - az;
      for (int jj = j0; jj <= j1; ++jj) {
        const double ry = g.origin.y() + g.step * jj - ay;
        for (int ii = i0; ii <= i1; ++ii) {
          const double rx = g.origin.x() + g.step * ii - ax;
          const double u = (rx * ex + ry * ey + rz * ez) / len2;
          const double uc = std::clamp(u, 0.0, 1.0);
          const double dx = rx - uc * ex, dy = ry - uc * ey, dz = rz - uc * ez;
          const double d2 = dx * dx + dy * dy + dz * dz;
          if (d2 > R2) continue;
          const size_t p = size_t(g.index(ii, jj, kk));
          int& at = slot[p];
          if (at < 0) {
            at = int(out.index.size());
            out.index.push_back(int(p));
            out.remaining.push_back(0.f);
            out.lift.push_back(0.f);
            out.tangent.insert(out.tangent.end(), {0.f, 0.f, 0.f});
            out.toCurve.insert(out.toCurve.end(), {0.f, 0.f, 0.f});
            out.faceTangent.insert(out.faceTangent.end(), {0.f, 0.f, 0.f});
            d2s.push_back(inf);
            face2.push_back(inf);
          }
          const size_t e = size_t(at);
          if (offScalp && d2 < face2[e]) {
            face2[e] = d2;
            out.faceTangent[3 * e] = float(ex / len);
            out.faceTangent[3 * e + 1] = float(ey / len);
            out.faceTangent[3 * e + 2] = float(ez / len);
          }
          if (!(d2 < d2s[e])) continue;
          d2s[e] = d2;
          double r = L - (s[k] + uc * len);
          if (last && u > 1) r -= (u - 1) * len;  // past the end
          out.remaining[e] = float(r);
          if (c.lift) out.lift[e] = float((1 - uc) * c.lift[k] + uc * c.lift[k + 1]);
          out.tangent[3 * e] = float(ex / len);
          out.tangent[3 * e + 1] = float(ey / len);
          out.tangent[3 * e + 2] = float(ez / len);
          out.toCurve[3 * e] = float(-dx);
          out.toCurve[3 * e + 1] = float(-dy);
          out.toCurve[3 * e + 2] = float(-dz);
        }
      }
    }
  }
  out.distance.resize(d2s.size());
  out.faceDistance.resize(d2s.size());
  for (size_t e = 0; e < d2s.size(); ++e) {
    out.distance[e] = float(std::sqrt(d2s[e]));
    out.faceDistance[e] = float(std::sqrt(face2[e]));
  }
}

void combineReach(const Grid& g, const std::vector<const CurveFootprint*>& curves, CurveReach& out,
                  const Eigen::Vector3d* faceCentre) {
  const size_t n = size_t(g.size());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> sumW(n, 0), sumWR(n, 0), sumWF(n, 0), sumWFR(n, 0), dmin(n, inf),
      dface(n, inf);
  out.grid = g;
  out.lift.assign(n, 0.f);
  out.strokeLift.assign(n, 0.f);
  out.tangent.assign(3 * n, 0.f);
  out.toCurve.assign(3 * n, 0.f);
  out.faceTangent.assign(3 * n, 0.f);
  const double twoSigma2 = 2 * kReachSigma * kReachSigma;
  // in front of the face a fringe's length holds at any distance (faceColumnWeight): the hair
  // there beside it ends with it instead of hanging over the eyes
  std::vector<float> face;
  if (faceCentre && std::any_of(curves.begin(), curves.end(),
                                [](const CurveFootprint* c) { return c->fringe; })) {
    face.resize(n);
    for (int k = 0; k < g.nz; ++k)
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
          face[size_t(g.index(i, j, k))] =
              float(faceColumnWeight(*faceCentre, g.position(i, j, k)));
  }
  for (const CurveFootprint* c : curves)
    for (size_t e = 0; e < c->index.size(); ++e) {
      const size_t p = size_t(c->index[e]);
      const double d = c->distance[e];
      // a fringe's length holds for its own hair only
      const double w = std::exp(-d * d / twoSigma2) *
                       (c->fringe ? std::max(1 - smoothstep(kOwnReach, kOwnReachFar, d),
                                             face.empty() ? 0.0 : double(face[p]))
                                  : 1.0);
      sumW[p] += w;
      const double r = c->growsOn ? kGrowsOnRemaining : double(c->remaining[e]);
      sumWR[p] += w * r;
      if (c->fringe) {
        sumWF[p] += w;
        sumWFR[p] += w * r;
      }
      if (d < dmin[p]) {
        dmin[p] = d;
        out.lift[p] = c->lift.empty() ? 0.f : c->lift[e];
        out.strokeLift[p] = c->maxLift;
        std::copy(&c->tangent[3 * e], &c->tangent[3 * e] + 3, &out.tangent[3 * p]);
        std::copy(&c->toCurve[3 * e], &c->toCurve[3 * e] + 3, &out.toCurve[3 * p]);
      }
      if (c->faceDistance[e] < dface[p]) {
        dface[p] = c->faceDistance[e];
        std::copy(&c->faceTangent[3 * e], &c->faceTangent[3 * e] + 3, &out.faceTangent[3 * p]);
      }
    }
  out.remaining.assign(n, 0.f);
  out.fringeShare.assign(n, 0.f);
  out.fringeRemaining.assign(n, 0.f);
  out.far.assign(n, 1.f);
  out.overFace.assign(n, 0.f);
  out.governed.assign(n, 0.f);
  out.nearest.assign(n, float(kReachFar));
  for (size_t p = 0; p < n; ++p) {
    if (!(sumW[p] > 0)) continue;
    out.overFace[p] = float(1 - smoothstep(kFaceNear, kFaceFar, dface[p]));
    out.remaining[p] = float(sumWR[p] / sumW[p]);
    out.fringeShare[p] = float(sumWF[p] / sumW[p]);
    if (sumWF[p] > 0) out.fringeRemaining[p] = float(sumWFR[p] / sumWF[p]);
    out.far[p] = float(smoothstep(kReachNear, kReachFar, dmin[p]));
    out.governed[p] = float(1 - smoothstep(kGovernNear, kGovernFar, dmin[p]));
    out.nearest[p] = float(dmin[p]);
  }
  out.strokes.clear();
  for (const CurveFootprint* c : curves)
    if (c->stroke.length > 0) out.strokes.push_back(c->stroke);
  // curves' own Volumes: each holds near its curve, blended where several reach
  out.ownVolumeWeight.clear();
  out.ownVolume.clear();
  bool anyOwn = false;
  for (const CurveFootprint* c : curves) anyOwn |= c->volume >= 0;
  if (!anyOwn) return;
  std::vector<double> sumV(n, 0), sumVW(n, 0);
  out.ownVolumeWeight.assign(n, 0.f);
  out.ownVolume.assign(n, 0.f);
  for (const CurveFootprint* c : curves) {
    if (!(c->volume >= 0)) continue;
    for (size_t e = 0; e < c->index.size(); ++e) {
      const size_t p = size_t(c->index[e]);
      const double w = 1 - smoothstep(kOwnVolumeNear, kOwnVolumeFar, c->distance[e]);
      if (!(w > 0)) continue;
      sumV[p] += w * c->volume;
      sumVW[p] += w;
      out.ownVolumeWeight[p] = std::max(out.ownVolumeWeight[p], float(w));
    }
  }
  for (size_t p = 0; p < n; ++p)
    if (sumVW[p] > 0) out.ownVolume[p] = float(sumV[p] / sumVW[p]);
}

namespace {

// Calls f(stroke, weight) for each stroke that counts for the length of the hair rooted at p
// (strokes that comb only when every stroke combs), with Shepard's inverse-square weight.
template <class F>
void eachLengthStroke(const std::vector<StrokeLength>& strokes, const float p[3], F&& f) {
  const bool anyEnds =
      std::any_of(strokes.begin(), strokes.end(), [](const StrokeLength& c) { return !c.combs; });
  for (const StrokeLength& c : strokes) {
    if (anyEnds && c.combs) continue;
    const double d2 = double(c.x - p[0]) * (c.x - p[0]) + double(c.y - p[1]) * (c.y - p[1]) +
                      double(c.z - p[2]) * (c.z - p[2]);
    f(c, 1 / (d2 + 1e-4));
  }
}

}  // namespace

float lengthAround(const std::vector<StrokeLength>& strokes, const float p[3], float maxLength) {
  double sw = 0, swl = 0;
  eachLengthStroke(strokes, p, [&](const StrokeLength& c, double w) {
    sw += w;
    swl += w * (c.growsOn ? double(maxLength) : std::min(double(c.length), double(maxLength)));
  });
  return sw > 0 ? float(std::min(swl / sw, double(maxLength))) : maxLength;
}

float hemAround(const std::vector<StrokeLength>& strokes, const float p[3]) {
  double sw = 0, swHem = 0, swy = 0;
  eachLengthStroke(strokes, p, [&](const StrokeLength& c, double w) {
    sw += w;
    if (setsHem(c)) {
      const double across = std::hypot(double(c.endX - p[0]), double(c.endZ - p[2]));
      const double h = w * (1 - smoothstep(kHemNear, kHemFar, across));
      swHem += h;
      swy += h * c.endY;
    }
  });
  const double share = swHem > 0 ? swHem / sw : 0;
  if (!(share > kHemShareFrom)) return -std::numeric_limits<float>::infinity();
  return float(swy / swHem - (1 - smoothstep(kHemShareFrom, kHemShareTo, share)) * kHemFade);
}

void buildCurveReach(const Grid& solverGrid, const std::vector<ReachCurve>& curves, CurveReach& out,
                     const Eigen::Vector3d* faceCentre) {
  const Grid g = reachGrid(solverGrid);
  std::vector<CurveFootprint> fp(curves.size());
  std::vector<const CurveFootprint*> ptr;
  for (size_t c = 0; c < curves.size(); ++c) {
    curveFootprint(g, curves[c], fp[c]);
    ptr.push_back(&fp[c]);
  }
  combineReach(g, ptr, out, faceCentre);
}

namespace {

// The lattice cell holding (x, y, z) (clamped to the volume) and the weights within it.
struct TrilinearCell {
  size_t at;      // the cell's lowest corner, in points
  float a, b, c;  // the weights along x, y, z
};

TrilinearCell trilinearCell(const Grid& g, float x, float y, float z) {
  const float inv = float(1.0 / g.step);
  float u = (x - float(g.origin.x())) * inv, v = (y - float(g.origin.y())) * inv,
        w = (z - float(g.origin.z())) * inv;
  u = std::clamp(u, 0.f, float(g.nx - 1));
  v = std::clamp(v, 0.f, float(g.ny - 1));
  w = std::clamp(w, 0.f, float(g.nz - 1));
  const int i = std::min(int(u), g.nx - 2), j = std::min(int(v), g.ny - 2),
            k = std::min(int(w), g.nz - 2);
  return {size_t(i) + size_t(j) * size_t(g.nx) + size_t(k) * size_t(g.nx) * size_t(g.ny),
          u - float(i), v - float(j), w - float(k)};
}

// The trilinear blend of the cell's eight values at p (steps sx, sy, sz between them).
float blendCell(const float* p, size_t sx, size_t sy, size_t sz, const TrilinearCell& t) {
  const float c00 = p[0] + t.a * (p[sx] - p[0]);
  const float c10 = p[sy] + t.a * (p[sy + sx] - p[sy]);
  const float c01 = p[sz] + t.a * (p[sz + sx] - p[sz]);
  const float c11 = p[sz + sy] + t.a * (p[sz + sy + sx] - p[sz + sy]);
  const float c0 = c00 + t.b * (c10 - c00), c1 = c01 + t.b * (c11 - c01);
  return c0 + t.c * (c1 - c0);
}

}  // namespace

float interpolateScalar(const Grid& g, const float* f, float x, float y, float z, int stride,
                        int offset) {
  const TrilinearCell t = trilinearCell(g, x, y, z);
  const size_t sx = size_t(stride), sy = sx * size_t(g.nx), sz = sy * size_t(g.ny);
  return blendCell(f + offset + sx * t.at, sx, sy, sz, t);
}

void interpolateScalars(const Grid& g, const float* const* arrays, int count, float x, float y,
                        float z, float* out) {
  const TrilinearCell t = trilinearCell(g, x, y, z);
  const size_t sy = size_t(g.nx), sz = sy * size_t(g.ny);
  for (int n = 0; n < count; ++n) out[n] = blendCell(arrays[n] + t.at, 1, sy, sz, t);
}

}  // namespace hairsketch
