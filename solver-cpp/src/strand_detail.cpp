#include "strand_detail.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <tuple>

#include "rng.hpp"

namespace hairsketch {

namespace {

using V3 = Eigen::Vector3d;
constexpr double kTwoPi = 6.283185307179586476925;

// Pcg32 streams, one per use of a strand's randomness (digits of pi, as in Blowfish).
constexpr uint64_t kStreamJitter = 0x243f6a8885a308d3ULL;
constexpr uint64_t kStreamOrder = 0x13198a2e03707344ULL;
constexpr uint64_t kStreamSpread = 0xa4093822299f31d0ULL;
constexpr uint64_t kStreamCurl = 0x082efa98ec4e6c89ULL;
constexpr uint64_t kStreamFrizz = 0x452821e638d01377ULL;
constexpr uint64_t kStreamEndSpread = 0xbe5466cf34e90c6cULL;
constexpr uint64_t kStreamRinglet = 0x3f84d5b5b5470917ULL;

// Ringlets vary as real ones do: each clump's curl radius and frequency are scaled by a seeded
// factor within 1 ± kRingletVary (independently), and half the clumps (seeded) wind the other
// way, so neighbouring ringlets do not line up in rows of parallel stripes.
constexpr double kRingletVary = 0.25;

Pcg32 strandRng(uint32_t seed, uint32_t key, uint64_t stream) {
  return Pcg32((uint64_t(seed) << 32) | key, stream);
}

double unitFromBits(uint32_t v) { return v * (1.0 / 4294967296.0); }

// A point uniform in the unit ball (rejection from the cube).
V3 inBall(Pcg32& rng) {
  for (;;) {
    const V3 v(2 * unitFromBits(rng.nextU32()) - 1, 2 * unitFromBits(rng.nextU32()) - 1,
               2 * unitFromBits(rng.nextU32()) - 1);
    if (v.squaredNorm() <= 1) return v;
  }
}

// S(x; s) with its exponent worked out once.
struct Falloff {
  bool constant = true, tipward = true, low = true;
  double k = 0;
  explicit Falloff(double s) {
    if (s == 0) return;
    constant = false;
    const double a = std::min(std::abs(s), 1.0);
    tipward = s > 0;
    low = a <= 0.5;
    k = low ? -std::log2(1 - a) : -std::log2(a);
  }
  double operator()(double x) const {
    if (constant) return 1;
    x = std::min(1.0, std::max(0.0, x));
    const double xp = tipward ? x : 1 - x;
    if (k == 1) return xp;  // s = +-0.5, the default
    return low ? std::pow(xp, k) : 1 - std::pow(1 - xp, k);
  }
};

V3 lerp(const V3& a, const V3& b, double u) { return (1 - u) * a + u * b; }

struct Work {
  std::vector<V3> p, q, t, n, b;
  std::vector<double> s;
};

void load(const float* f, size_t count, std::vector<V3>& p) {
  p.resize(count);
  for (size_t i = 0; i < count; ++i) p[i] = V3(f[3 * i], f[3 * i + 1], f[3 * i + 2]);
}

void store(const std::vector<V3>& p, float* f) {
  for (size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 3; ++a) f[3 * i + a] = float(p[i][a]);
}

double arcLengths(const std::vector<V3>& p, std::vector<double>& s) {
  s.resize(p.size());
  s[0] = 0;
  for (size_t i = 1; i < p.size(); ++i) s[i] = s[i - 1] + (p[i] - p[i - 1]).norm();
  return s.back();
}

// For ascending targets: advances j to the segment with s[j] <= target <= s[j + 1] (count >= 2)
// and returns the fraction along it.
double locate(const double* s, size_t count, double target, size_t& j) {
  const size_t last = count - 1;
  target = std::min(std::max(target, 0.0), s[last]);
  while (j + 1 < last && s[j + 1] < target) ++j;
  const double len = s[j + 1] - s[j];
  return len > 0 ? std::min(1.0, std::max(0.0, (target - s[j]) / len)) : 0.0;
}

// m >= 2 points evenly spaced by arc length along (p, s), first and last kept exactly.
void resampleEven(const std::vector<V3>& p, const std::vector<double>& s, size_t m,
                  std::vector<V3>& out) {
  out.resize(m);
  const double L = s.back();
  size_t j = 0;
  for (size_t k = 1; k + 1 < m; ++k) {
    const double u = locate(s.data(), s.size(), L * double(k) / double(m - 1), j);
    out[k] = lerp(p[j], p[j + 1], u);
  }
  out[0] = p.front();
  out[m - 1] = p.back();
}

// Cuts the strand at arc length len (0 < len), interpolating its new last point.
void cutAt(std::vector<V3>& p, std::vector<double>& s, double len) {
  if (!(len < s.back())) return;
  size_t i = 1;
  while (s[i] < len) ++i;
  const double seg = s[i] - s[i - 1];
  const double u = seg > 0 ? (len - s[i - 1]) / seg : 1.0;
  p[i] = lerp(p[i - 1], p[i], u);
  p.resize(i + 1);
  s.resize(i + 1);
  s[i] = len;
}

// Rotation-minimising frame along p (double reflection, Wang et al. 2008): vertex tangents T (the
// mean of the adjacent segment directions), N_0 = the part of +y normal to T_0 (+x if T_0 is along
// y), B = T x N.
void frames(const std::vector<V3>& p, std::vector<V3>& T, std::vector<V3>& N, std::vector<V3>& B) {
  const size_t n = p.size();  // >= 2
  T.resize(n);
  N.resize(n);
  B.resize(n);
  // Unit segment directions (a zero segment repeats the previous direction), in B for now.
  V3 prev(0, 0, 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    const V3 d = p[i + 1] - p[i];
    const double l2 = d.squaredNorm();
    B[i] = l2 > 0 ? V3(d * (1 / std::sqrt(l2))) : prev;
    prev = B[i];
  }
  T[0] = B[0];
  for (size_t i = 1; i + 1 < n; ++i) {
    const V3 t = B[i - 1] + B[i];
    const double l2 = t.squaredNorm();
    T[i] = l2 > 1e-12 ? V3(t * (1 / std::sqrt(l2))) : B[i];
  }
  T[n - 1] = B[n - 2];
  auto normalTo = [](const V3& t) {
    V3 r = V3(0, 1, 0) - t.y() * t;
    if (r.squaredNorm() < 1e-12) r = V3(1, 0, 0) - t.x() * t;
    return V3(r.normalized());
  };
  N[0] = normalTo(T[0]);
  for (size_t i = 0; i + 1 < n; ++i) {
    // Reflect (N, T) in the plane normal to the segment, then in the one taking T onto T_{i+1}.
    const V3& d = B[i];
    const V3 rL = N[i] - 2 * d.dot(N[i]) * d, tL = T[i] - 2 * d.dot(T[i]) * d;
    const V3 v2 = T[i + 1] - tL;
    const double c2 = v2.squaredNorm();
    V3 r = c2 > 1e-30 ? V3(rL - (2 / c2) * v2.dot(rL) * v2) : rL;
    // Reflections keep lengths and angles; only rounding (or a repeated direction) is corrected.
    r -= r.dot(T[i + 1]) * T[i + 1];
    const double l2 = r.squaredNorm();
    N[i + 1] = std::abs(l2 - 1) < 1e-9 ? r
               : l2 > 1e-12            ? V3(r / std::sqrt(l2))
                                       : normalTo(T[i + 1]);
  }
  for (size_t i = 0; i < n; ++i) B[i] = T[i].cross(N[i]);
}

double smoothstep(double x) {
  x = std::min(1.0, std::max(0.0, x));
  return x * x * (3 - 2 * x);
}

// Points a strand of n points and length L has after curl: at least 12 a turn, at most cap.
size_t curlPointCount(const DetailParams& d, size_t n, double L, size_t cap) {
  if (!(d.curl.radius > 0) || !(L > 0)) return n;
  const double want = std::ceil(L * 12 * d.curl.frequency) + 1;
  return size_t(std::min(double(cap), std::max(double(n), want)));
}

// How a ringlet strand curls: `d` with its curl radius and frequency scaled by its clump's
// seeded factors (kRingletVary), and which way it winds (+1 or -1); the guide's key seeds them,
// so a clump stays one ringlet.
struct Ringlet {
  DetailParams detail;
  double hand = 1;
};
Ringlet ringletOf(const DetailParams& d, uint32_t seed, uint32_t phaseKey) {
  Pcg32 rng = strandRng(seed, phaseKey, kStreamRinglet);
  Ringlet r{d, 1};
  r.detail.curl.radius *= 1 + kRingletVary * (2 * unitFromBits(rng.nextU32()) - 1);
  r.detail.curl.frequency *= 1 + kRingletVary * (2 * unitFromBits(rng.nextU32()) - 1);
  r.hand = rng.nextU32() & 1 ? -1 : 1;
  return r;
}

// Curl then frizz on one strand (w.p), in place; with curl, the strand is first resampled evenly
// to m points (curlPointCount) and s_k = L k / (m - 1) is the arc length along the path.
// phaseKey seeds the curl's phase (the strand's own key, or its clump guide's for ringlets);
// hand = -1 winds the curl the other way round the strand.
void curlAndFrizz(const DetailParams& d, uint32_t seed, uint32_t key, uint32_t phaseKey, size_t m,
                  Work& w, double hand = 1) {
  const double L = arcLengths(w.p, w.s);
  if (!(L > 0)) return;
  const bool curl = d.curl.radius > 0, frizz = d.frizz.distance > 0;
  if (curl) {
    resampleEven(w.p, w.s, m, w.q);
    std::swap(w.p, w.q);
    w.s.resize(m);
    for (size_t k = 0; k < m; ++k) w.s[k] = L * double(k) / double(m - 1);
  }
  frames(w.p, w.t, w.n, w.b);
  const size_t n = w.p.size();
  const double invL = 1 / L;
  if (curl) {
    // theta_k = theta_0 + k dTheta (even spacing), by rotating (cos, sin) one step at a time.
    const double r = d.curl.radius, a = d.curl.start;
    const double phase = d.curl.randomOffset * strandRng(seed, phaseKey, kStreamCurl).uniform();
    const double step = kTwoPi * d.curl.frequency * L / double(n - 1);
    const double cs = std::cos(step), sn = std::sin(step);
    double c = std::cos(kTwoPi * phase), s = std::sin(kTwoPi * phase);
    for (size_t i = 1; i < n; ++i) {
      const double c1 = c * cs - s * sn;
      s = s * cs + c * sn;
      c = c1;
      const double ramp = a > 0 ? smoothstep(w.s[i] * invL / a) : 1.0;
      w.p[i] += r * ramp * (c * w.n[i] + hand * s * w.b[i]);
    }
  }
  if (frizz) {
    const Falloff S(d.frizz.shape);
    Pcg32 rng = strandRng(seed, key, kStreamFrizz);
    V3 c = V3::Zero();
    for (size_t i = 1; i < n; ++i) {
      const V3 v = inBall(rng);
      c += v.x() * w.t[i] + v.y() * w.n[i] + v.z() * w.b[i];
      w.p[i] += d.frizz.distance * S(w.s[i] * invL) * c;
    }
  }
}

// Open-addressing table from a grid cell to the first guide in it (guides in a cell are linked
// through `next`).
class CellTable {
 public:
  explicit CellTable(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n) cap <<= 1;
    keys_.assign(cap, 0);
    heads_.assign(cap, -1);
    mask_ = cap - 1;
  }
  int32_t head(uint64_t key) const { return heads_[slot(key)]; }
  int32_t& headRef(uint64_t key) {
    const size_t i = slot(key);
    keys_[i] = key;
    return heads_[i];
  }

 private:
  size_t slot(uint64_t key) const {
    uint64_t h = key + 0x9e3779b97f4a7c15ULL;  // splitmix64 finaliser
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
    size_t i = size_t(h) & mask_;
    while (heads_[i] != -1 && keys_[i] != key) i = (i + 1) & mask_;
    return i;
  }
  std::vector<uint64_t> keys_;
  std::vector<int32_t> heads_;
  size_t mask_ = 0;
};

constexpr int64_t kCellHalf = int64_t(1) << 20;  // cell coordinates kept in [-2^20, 2^20)

int64_t cellCoord(double v, double inv) {
  const double c = std::floor(v * inv);
  return int64_t(std::min(double(kCellHalf - 1), std::max(double(-kCellHalf), c)));
}

uint64_t packCell(int64_t x, int64_t y, int64_t z) {
  return (uint64_t(x + kCellHalf) << 42) | (uint64_t(y + kCellHalf) << 21) |
         uint64_t(z + kCellHalf);
}

// Calls f(member) for every guide in the 27 cells around the cell of p.
template <class F>
void forNearGuides(const CellTable& table, const std::vector<int32_t>& next, const V3& p,
                   double inv, F f) {
  const int64_t cx = cellCoord(p.x(), inv), cy = cellCoord(p.y(), inv), cz = cellCoord(p.z(), inv);
  for (int64_t x = std::max(cx - 1, -kCellHalf); x <= std::min(cx + 1, kCellHalf - 1); ++x)
    for (int64_t y = std::max(cy - 1, -kCellHalf); y <= std::min(cy + 1, kCellHalf - 1); ++y)
      for (int64_t z = std::max(cz - 1, -kCellHalf); z <= std::min(cz + 1, kCellHalf - 1); ++z)
        for (int32_t k = table.head(packCell(x, y, z)); k >= 0; k = next[size_t(k)])
          if (!f(k)) return;
}

// cos 60°: a guide whose heading is further from a follower's than this does not take it.
constexpr double kSameWay = 0.5;
// How far (world units, 10 cm; at least 4 guide distances) a follower's path may part from its
// guide's and still be clumped to it: round different sides of the head they part by more.
constexpr double kMaxApart = 1.0;

// Clump of one group's strands (members, each with >= 2 points), in place.
// phaseKey (optional): a clumped strand's entry becomes its guide's key.
void clumpGroup(const ClumpParams& c, const std::vector<uint32_t>& members,
                const std::vector<uint32_t>& key, uint32_t seed, Strands& strands, Work& w,
                std::vector<uint32_t>* phaseKey) {
  const size_t M = members.size();
  const uint32_t* start = strands.strandStart.data();
  float* P = strands.points.data();
  std::vector<V3> roots(M), heading(M);
  for (size_t m = 0; m < M; ++m) {
    const size_t a = start[members[m]], n = start[members[m] + 1] - a;
    const float* r = P + 3 * a;
    roots[m] = V3(r[0], r[1], r[2]);
    // where the strand sets off to: root to its point a few steps on (unit, or zero)
    const float* q = P + 3 * (a + std::min<size_t>(n - 1, 4));
    const V3 d = V3(q[0], q[1], q[2]) - roots[m];
    heading[m] = d.norm() > 0 ? V3(d / d.norm()) : V3(V3::Zero());
  }
  // Seeded visiting order: by a hash of (seed, key), then key, then position.
  std::vector<std::tuple<uint32_t, uint32_t, uint32_t>> order(M);
  for (size_t m = 0; m < M; ++m) {
    const uint32_t k = key[members[m]];
    order[m] = {strandRng(seed, k, kStreamOrder).nextU32(), k, uint32_t(m)};
  }
  std::sort(order.begin(), order.end());

  const double g = c.guideDistance, g2 = g * g, inv = 1 / g;
  CellTable table(M);
  std::vector<int32_t> next(M, -1);
  std::vector<char> isGuide(M, 0);
  for (const auto& o : order) {
    const uint32_t m = std::get<2>(o);
    bool near = false;
    forNearGuides(table, next, roots[m], inv, [&](int32_t k) {
      near = (roots[size_t(k)] - roots[m]).squaredNorm() < g2;
      return !near;
    });
    if (near) continue;
    isGuide[m] = 1;
    int32_t& head = table.headRef(packCell(
        cellCoord(roots[m].x(), inv), cellCoord(roots[m].y(), inv), cellCoord(roots[m].z(), inv)));
    next[m] = head;
    head = int32_t(m);
  }

  // The guides' un-clumped shapes: arc lengths and (for the tip spread) frames, flat.
  const bool spread = c.tipSpread > 0;
  std::vector<size_t> guideAt(M, 0);
  std::vector<double> gs;
  std::vector<V3> gt, gn;
  for (size_t m = 0; m < M; ++m) {
    if (!isGuide[m]) continue;
    const uint32_t s = members[m];
    load(P + 3 * size_t(start[s]), start[s + 1] - start[s], w.p);
    arcLengths(w.p, w.s);
    guideAt[m] = gs.size();
    gs.insert(gs.end(), w.s.begin(), w.s.end());
    if (spread) {
      frames(w.p, w.t, w.n, w.b);
      gt.insert(gt.end(), w.t.begin(), w.t.end());
      gn.insert(gn.end(), w.n.begin(), w.n.end());
    }
  }

  const Falloff S(c.shape);
  for (size_t m = 0; m < M; ++m) {
    if (isGuide[m]) continue;
    int32_t best = -1;
    double bestD2 = std::numeric_limits<double>::infinity();
    forNearGuides(table, next, roots[m], inv, [&](int32_t k) {
      // a guide that sets off the other way (across a parting) does not take this strand
      if (heading[size_t(k)].dot(heading[m]) < kSameWay) return true;
      const double d2 = (roots[size_t(k)] - roots[m]).squaredNorm();
      if (d2 < bestD2) {
        bestD2 = d2;
        best = k;
      }
      return true;
    });
    if (best < 0) continue;  // no guide near that sets off the same way: not clumped
    const uint32_t s = members[m], G = members[size_t(best)];
    const size_t count = start[s + 1] - start[s], gCount = start[G + 1] - start[G];
    const float* gp = P + 3 * size_t(start[G]);
    const double* gArc = gs.data() + guideAt[size_t(best)];
    const double LG = gArc[gCount - 1];
    load(P + 3 * size_t(start[s]), count, w.p);
    const double L = arcLengths(w.p, w.s);
    if (!(L > 0) || !(LG > 0)) continue;
    // Along the guide by arc length, stretched to its tip only for a strand longer than it: a
    // shorter strand (stubble at a hairline) joins the clump near its root, not at its far tip.
    const double along = LG / std::max(L, LG);
    const double phi = spread ? kTwoPi * strandRng(seed, key[s], kStreamSpread).uniform() : 0;
    const double cPhi = std::cos(phi), sPhi = std::sin(phi);
    // A strand whose path parts from its guide's by more than kMaxApart (the two go round
    // different sides of the head, or either side of a parting further on) is not clumped: a
    // blend of the two paths would cut through the head.
    const double maxApart = std::max(kMaxApart, 4 * c.guideDistance);
    bool apart = false;
    size_t j = 0;
    for (size_t i = 1; i < count && !apart; ++i) {
      const double u = locate(gArc, gCount, w.s[i] * along, j);
      const V3 a(gp[3 * j], gp[3 * j + 1], gp[3 * j + 2]);
      const V3 b(gp[3 * j + 3], gp[3 * j + 4], gp[3 * j + 5]);
      apart = (lerp(a, b, u) - w.p[i]).norm() > maxApart;
    }
    if (apart) continue;
    if (phaseKey) (*phaseKey)[s] = key[G];
    j = 0;
    for (size_t i = 1; i < count; ++i) {
      const double x = w.s[i] / L;
      const double u = locate(gArc, gCount, w.s[i] * along, j);
      const V3 a(gp[3 * j], gp[3 * j + 1], gp[3 * j + 2]);
      const V3 b(gp[3 * j + 3], gp[3 * j + 4], gp[3 * j + 5]);
      const double wgt = c.factor * S(x);
      w.p[i] = (1 - wgt) * w.p[i] + wgt * lerp(a, b, u);
      if (spread) {
        const size_t o = guideAt[size_t(best)] + j;
        const V3 t = lerp(gt[o], gt[o + 1], u).normalized();
        V3 nrm = lerp(gn[o], gn[o + 1], u);
        nrm = (nrm - nrm.dot(t) * t).normalized();
        w.p[i] += c.tipSpread * x * (cPhi * nrm + sPhi * t.cross(nrm));
      }
    }
    store(w.p, P + 3 * size_t(start[s]));
  }
}

Status rangeError(const std::string& field, const char* rule) {
  return Status::Error(StatusCode::InvalidInput, "detail: " + field + " must be " + rule);
}

}  // namespace

double shapeFalloff(double x, double s) { return Falloff(s)(x); }

Status validateDetail(const DetailParams& d) {
  auto nonNegative = [](double v) { return std::isfinite(v) && v >= 0; };
  auto unit = [](double v) { return std::isfinite(v) && v >= 0 && v <= 1; };
  auto shape = [](double v) { return std::isfinite(v) && v >= -1 && v <= 1; };
  const char* kNonNeg = "finite and >= 0";
  const char* kUnit = "in [0, 1]";
  const char* kShape = "in [-1, 1]";
  if (!nonNegative(d.curl.radius)) return rangeError("curl.radius", kNonNeg);
  if (!nonNegative(d.curl.frequency)) return rangeError("curl.frequency", kNonNeg);
  if (!unit(d.curl.start)) return rangeError("curl.start", kUnit);
  if (!unit(d.curl.randomOffset)) return rangeError("curl.randomOffset", kUnit);
  if (!unit(d.clump.factor)) return rangeError("clump.factor", kUnit);
  if (!shape(d.clump.shape)) return rangeError("clump.shape", kShape);
  if (!nonNegative(d.clump.tipSpread)) return rangeError("clump.tipSpread", kNonNeg);
  if (!nonNegative(d.clump.guideDistance)) return rangeError("clump.guideDistance", kNonNeg);
  if (!nonNegative(d.frizz.distance)) return rangeError("frizz.distance", kNonNeg);
  if (!shape(d.frizz.shape)) return rangeError("frizz.shape", kShape);
  if (!unit(d.lengthJitter)) return rangeError("lengthJitter", kUnit);
  return Status::Ok();
}

Status applyDetail(const std::vector<DetailParams>& groups, const std::vector<uint32_t>& groupOf,
                   const std::vector<uint32_t>& key, uint32_t seed, Strands& strands, int maxPoints,
                   const std::vector<float>* endSpread, bool ringlets) {
  auto invalid = [](std::string m) {
    return Status::Error(StatusCode::InvalidInput, std::move(m));
  };
  if (maxPoints < 2) return invalid("detail: maxPoints must be at least 2");
  std::vector<uint32_t>& start = strands.strandStart;
  const size_t nS = start.empty() ? 0 : start.size() - 1;
  if (groupOf.size() != nS)
    return invalid("detail: groupOf has " + std::to_string(groupOf.size()) + " entries for " +
                   std::to_string(nS) + " strands");
  if (key.size() != nS)
    return invalid("detail: key has " + std::to_string(key.size()) + " entries for " +
                   std::to_string(nS) + " strands");
  if (endSpread && endSpread->size() != nS)
    return invalid("detail: endSpread has " + std::to_string(endSpread->size()) + " entries for " +
                   std::to_string(nS) + " strands");
  if (nS == 0) return Status::Ok();
  if (start[0] != 0 || size_t(start[nS]) * 3 != strands.points.size())
    return invalid("detail: strandStart does not match the points");
  for (size_t s = 0; s < nS; ++s)
    if (start[s + 1] < start[s]) return invalid("detail: strandStart is not ascending");
  for (size_t k = 0; k < groups.size(); ++k) {
    Status st = validateDetail(groups[k]);
    if (!st.ok()) {
      st.message += " (group " + std::to_string(k) + ")";
      return st;
    }
  }
  for (size_t s = 0; s < nS; ++s)
    if (groupOf[s] >= groups.size())
      return invalid("detail: strand " + std::to_string(s) + " uses group " +
                     std::to_string(groupOf[s]) + " of " + std::to_string(groups.size()));

  const size_t cap = size_t(maxPoints);
  auto spreadOf = [&](size_t s) -> double {
    const float v = endSpread ? (*endSpread)[s] : 0.f;
    return std::isfinite(v) && v > 0 ? double(v) : 0.0;
  };
  bool work = false, anyCurl = false, anyClump = false, anyCurlOrFrizz = false;
  for (size_t s = 0; s < nS; ++s) {
    const size_t count = start[s + 1] - start[s];
    const DetailParams& d = groups[groupOf[s]];
    const bool active = count >= 2 && d.any();
    work |= active || count > cap || (count >= 2 && spreadOf(s) > 0);
    anyCurl |= active && d.curl.radius > 0;
    anyClump |= active && d.clump.factor > 0 && d.clump.guideDistance > 0;
    anyCurlOrFrizz |= active && (d.curl.radius > 0 || d.frizz.distance > 0);
  }
  if (!work) return Status::Ok();
  Work w;

  // 1. Length jitter, end spread, and the cap for strands that came in too long (compacting in
  // place).
  {
    float* P = strands.points.data();
    size_t out = 0;
    for (size_t s = 0; s < nS; ++s) {
      const size_t b = start[s], count = start[s + 1] - b;
      start[s] = uint32_t(out);
      const DetailParams& d = groups[groupOf[s]];
      const bool jitter = count >= 2 && d.any() && d.lengthJitter > 0;
      const double spread = count >= 2 ? spreadOf(s) : 0.0;
      if (!jitter && spread == 0 && count <= cap) {
        if (out != b) std::memmove(P + 3 * out, P + 3 * b, 3 * count * sizeof(float));
        out += count;
        continue;
      }
      load(P + 3 * b, count, w.p);
      const double L = arcLengths(w.p, w.s);
      double keep = L;
      if (jitter) keep *= 1 - d.lengthJitter * strandRng(seed, key[s], kStreamJitter).uniform();
      if (spread > 0)
        keep -= std::min(spread, kEndSpreadShare * L) *
                strandRng(seed, key[s], kStreamEndSpread).uniform();
      if (keep < L && L > 0) cutAt(w.p, w.s, keep);
      if (w.p.size() > cap) {
        resampleEven(w.p, w.s, cap, w.q);
        std::swap(w.p, w.q);
      }
      store(w.p, P + 3 * out);
      out += w.p.size();
    }
    start[nS] = uint32_t(out);
    strands.points.resize(3 * out);
  }

  // a strand's curl phase: its own, or with ringlets its clump guide's (set while clumping)
  std::vector<uint32_t> phaseKey = key;

  // 2. Clump, group by group (guides keep their shape, so each group reads its guides as grown).
  if (anyClump) {
    std::vector<std::vector<uint32_t>> members(groups.size());
    for (size_t s = 0; s < nS; ++s)
      if (start[s + 1] - start[s] >= 2) members[groupOf[s]].push_back(uint32_t(s));
    for (size_t g = 0; g < groups.size(); ++g) {
      const ClumpParams& c = groups[g].clump;
      if (c.factor > 0 && c.guideDistance > 0 && members[g].size() >= 2)
        clumpGroup(c, members[g], key, seed, strands, w, ringlets ? &phaseKey : nullptr);
    }
  }

  // 3. Curl and frizz, strand by strand (curl may add points: then into a new buffer).
  if (anyCurlOrFrizz) {
    // with ringlets a strand curls as its clump's ringlet (ringletOf)
    auto curlOf = [&](size_t s) {
      return ringlets ? ringletOf(groups[groupOf[s]], seed, phaseKey[s])
                      : Ringlet{groups[groupOf[s]], 1};
    };
    auto detailed = [&](size_t s) {
      const DetailParams& d = groups[groupOf[s]];
      return start[s + 1] - start[s] >= 2 && (d.curl.radius > 0 || d.frizz.distance > 0);
    };
    if (!anyCurl) {
      float* P = strands.points.data();
      for (size_t s = 0; s < nS; ++s) {
        if (!detailed(s)) continue;
        const size_t count = start[s + 1] - start[s];
        load(P + 3 * size_t(start[s]), count, w.p);
        const Ringlet r = curlOf(s);
        curlAndFrizz(r.detail, seed, key[s], phaseKey[s], count, w, r.hand);
        store(w.p, P + 3 * size_t(start[s]));
      }
    } else {
      // Each strand's point count after curl first, so the new buffer is allocated once.
      std::vector<uint32_t> outStart(nS + 1, 0);
      const float* P = strands.points.data();
      for (size_t s = 0; s < nS; ++s) {
        size_t count = start[s + 1] - start[s];
        if (detailed(s) && groups[groupOf[s]].curl.radius > 0) {
          load(P + 3 * size_t(start[s]), count, w.p);
          count = curlPointCount(curlOf(s).detail, count, arcLengths(w.p, w.s), cap);
        }
        outStart[s + 1] = uint32_t(outStart[s] + count);
      }
      decltype(strands.points) out(3 * size_t(outStart[nS]));
      for (size_t s = 0; s < nS; ++s) {
        const float* src = P + 3 * size_t(start[s]);
        const size_t count = start[s + 1] - start[s], m = outStart[s + 1] - outStart[s];
        float* dst = out.data() + 3 * size_t(outStart[s]);
        if (!detailed(s)) {
          std::memcpy(dst, src, 3 * count * sizeof(float));
          continue;
        }
        load(src, count, w.p);
        const Ringlet r = curlOf(s);
        curlAndFrizz(r.detail, seed, key[s], phaseKey[s], m, w, r.hand);
        store(w.p, dst);  // m points: resampled to m with curl, count = m without
      }
      strands.points.swap(out);
      start.swap(outStart);
    }
  }
  return Status::Ok();
}

}  // namespace hairsketch
