// Curl and frizz of hair detail (strand_detail.hpp "Curl", "Frizz"), strand by strand, and the
// ringlets' clump-by-clump variation.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>

#include "strand_detail_internal.hpp"

namespace hairsketch::strand_detail {

namespace {

// Ringlets vary as real ones do: each clump's curl radius and frequency are scaled by seeded
// factors within 1 ± kRingletRadiusVary and 1 ± kRingletTurnsVary, half the clumps (seeded) wind
// the other way, and each ringlet's curl ramps in over its own share of the hair, the curl's
// start × (1 ± kRingletStartVary), so neighbouring ringlets do not line up in rows of beads of
// one size. (±0.25 of radius and turns alone still read as identical ringlets to a stylist.)
constexpr double kRingletRadiusVary = 0.4;
constexpr double kRingletTurnsVary = 0.3;
constexpr double kRingletStartVary = 0.5;
// Within a ringlet each hair but its guide winds at its own radius, within 1 ±
// kRingletStrandRadiusVary of the ringlet's, and a little off its phase (± kRingletStrandPhaseVary
// of a turn): a ringlet is a bundle of hairs with a thickness, not a tube whose every turn is lit
// as one bead (a stylist: "curly reads as scales").
constexpr double kRingletStrandRadiusVary = 0.35;
constexpr double kRingletStrandPhaseVary = 0.05;

// A point uniform in the unit ball (rejection from the cube).
V3 inBall(Pcg32& rng) {
  for (;;) {
    const V3 v(2 * unitFromBits(rng.nextU32()) - 1, 2 * unitFromBits(rng.nextU32()) - 1,
               2 * unitFromBits(rng.nextU32()) - 1);
    if (v.squaredNorm() <= 1) return v;
  }
}

double smoothstep(double x) {
  x = std::min(1.0, std::max(0.0, x));
  return x * x * (3 - 2 * x);
}

// Curl volume and coil volume (strand_detail.hpp "Curl volume", "Coil volume") on the evenly
// resampled path, before the helix.
void spreadCurl(const CurlParams& c, double L, uint32_t seed, uint32_t phaseKey, const V3& centre,
                Work& w) {
  const double steep = kTwoPi * c.frequency * c.radius;
  const double shrink = 1 - 1 / std::sqrt(1 + steep * steep);
  const double coily = c.coil * smoothstep((c.frequency - kCoilFrom) / (kCoilFull - kCoilFrom));
  const double vary =
      1 + kCurlSpreadVary * (2 * strandRng(seed, phaseKey, kStreamCurlSpread).uniform() - 1);
  const double tip = c.spread * shrink * L * vary * (1 + kCoilGain * coily);
  if (!(tip > 0)) return;
  // each lock leans its own way, within +-kCurlSpreadTurn of straight out (about the vertical)
  const double turn =
      kCurlSpreadTurn * (2 * strandRng(seed, phaseKey, kStreamCurlSpread + 1).uniform() - 1);
  const double ct = std::cos(turn), st = std::sin(turn);
  const double a = std::min(c.start, 0.99);
  const size_t n = w.p.size();
  for (size_t k = 1; k < n; ++k) {
    const double t = (w.s[k] / L - a) / (1 - a);
    if (!(t > 0)) continue;
    V3 out = w.p[k] - centre;
    out.y() = coily * std::max(out.y(), 0.0);
    out.z() = std::min(out.z(), 0.0);
    out = V3(ct * out.x() + st * out.z(), out.y(), -st * out.x() + ct * out.z());
    out.z() = std::min(out.z(), 0.0);
    const double len = out.norm();
    if (!(len > 1e-9)) continue;
    // coils leave the head at once and then hang: a rounded mass, not a flare to the tips
    const double curl = std::pow(t, 1.3);
    const double profile = coily > 0 ? curl + (1 - (1 - t) * (1 - t) - curl) * coily : curl;
    V3 move = (tip * profile / len) * out;
    move.z() *= kCurlSpreadBack;  // less back than sideways: curls widen, the mass does not lean
    w.p[k] += move;
  }
}

}  // namespace

size_t curlPointCount(const DetailParams& d, size_t n, double L, size_t cap) {
  if (!(d.curl.radius > 0) || !(L > 0)) return n;
  const double want = std::ceil(L * 12 * d.curl.frequency) + 1;
  return size_t(std::min(double(cap), std::max(double(n), want)));
}

Ringlet ringletOf(const DetailParams& d, uint32_t seed, uint32_t phaseKey) {
  Pcg32 rng = strandRng(seed, phaseKey, kStreamRinglet);
  Ringlet r{d, 1};
  r.detail.curl.radius *= 1 + kRingletRadiusVary * (2 * unitFromBits(rng.nextU32()) - 1);
  r.detail.curl.frequency *= 1 + kRingletTurnsVary * (2 * unitFromBits(rng.nextU32()) - 1);
  r.hand = rng.nextU32() & 1 ? -1 : 1;
  const double start =
      r.detail.curl.start * (1 + kRingletStartVary * (2 * unitFromBits(rng.nextU32()) - 1));
  r.detail.curl.start = std::min(start, 0.9);
  return r;
}

void curlAndFrizz(const DetailParams& d, uint32_t seed, uint32_t key, uint32_t phaseKey, size_t m,
                  Work& w, double hand, const V3& centre) {
  const double L = arcLengths(w.p, w.s);
  if (!(L > 0)) return;
  const bool curl = d.curl.radius > 0, frizz = d.frizz.distance > 0;
  if (curl) {
    resampleEven(w.p, w.s, m, w.q);
    std::swap(w.p, w.q);
    w.s.resize(m);
    for (size_t k = 0; k < m; ++k) w.s[k] = L * double(k) / double(m - 1);
    if (d.curl.spread > 0) spreadCurl(d.curl, L, seed, phaseKey, centre, w);
  }
  frames(w.p, w.t, w.n, w.b);
  const size_t n = w.p.size();
  const double invL = 1 / L;
  if (curl) {
    // theta_k = theta_0 + k dTheta (even spacing), by rotating (cos, sin) one step at a time.
    const double a = d.curl.start;
    double r = d.curl.radius;
    double phase = d.curl.randomOffset * strandRng(seed, phaseKey, kStreamCurl).uniform();
    if (key != phaseKey) {  // a hair of a ringlet, not its guide
      Pcg32 rng = strandRng(seed, key, kStreamRingletStrand);
      r *= 1 + kRingletStrandRadiusVary * (2 * unitFromBits(rng.nextU32()) - 1);
      phase += kRingletStrandPhaseVary * (2 * unitFromBits(rng.nextU32()) - 1);
    }
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

}  // namespace hairsketch::strand_detail
