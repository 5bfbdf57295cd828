// Flyaways of hair detail (strand_detail.hpp "Flyaway"): a few stray hairs that leave the groom
// past a share of their length, away from the head and a little sideways, with one gentle bend.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "strand_detail_internal.hpp"

namespace hairsketch::strand_detail {

namespace {

// How far a flyaway turns sideways of straight out (radians, each way) and the amplitude of its
// bend, a share of the distance.
constexpr double kFlyawaySide = 0.5;
constexpr double kFlyawayBend = 0.25;
// A strand whose path is within this (the sine of the angle) of straight out from the centre has
// no direction across it that is "out": it takes anyNormal.
constexpr double kStraightOut = 1e-3;

// A unit vector normal to the unit t (for a strand pointing straight out from the centre).
V3 anyNormal(const V3& t) {
  const V3 a = std::abs(t.y()) < 0.9 ? V3(0, 1, 0) : V3(1, 0, 0);
  return t.cross(a).normalized();
}

}  // namespace

bool flyawayPicked(const FlyawayParams& f, uint32_t seed, uint32_t key) {
  if (!(f.share > 0) || !(f.distance > 0)) return false;
  return strandRng(seed, key, kStreamFlyaway).uniform() < f.share;
}

void flyaway(const FlyawayParams& f, uint32_t seed, uint32_t key, const V3& centre, Work& w,
             bool locks) {
  std::vector<V3>& p = w.p;
  const size_t n = p.size();
  if (n < 2) return;
  const double L = arcLengths(p, w.s);
  if (!(L > 0) || f.start >= 1) return;
  Pcg32 rng(strandRng(seed, key, kStreamFlyaway));
  rng.uniform();  // the pick (flyawayPicked)
  const double phi = kFlyawaySide * (2 * rng.uniform() - 1);
  const double bend = kFlyawayBend * f.distance * (2 * rng.uniform() - 1);
  const double c = std::cos(phi), sn = std::sin(phi);
  // the offsets from the un-moved path (its tangents and directions from the centre)
  w.q.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double x = w.s[i] / L;
    if (x <= f.start) {
      w.q[i].setZero();
      continue;
    }
    const double u = (x - f.start) / (1 - f.start);
    const double bump = std::sin(kTwoPi * 0.5 * u);  // sin^2: no kink where it leaves
    const V3 t = (p[std::min(i + 1, n - 1)] - p[i > 0 ? i - 1 : 0]);
    const double tl = t.norm();
    const V3 T = tl > 0 ? V3(t / tl) : V3(0, 1, 0);
    const V3 d = p[i] - centre;
    V3 r = d - T * d.dot(T);
    const double rl = r.norm();
    r = rl > kStraightOut * d.norm() ? V3(r / rl) : anyNormal(T);
    const V3 b = T.cross(r);
    w.q[i] = f.distance * u * u * (c * r + sn * b) + bend * bump * bump * b;
  }
  for (size_t i = 0; i < n; ++i) p[i] += w.q[i];
  if (locks) keepLength(p, w.s, L, w.q);
}

}  // namespace hairsketch::strand_detail
