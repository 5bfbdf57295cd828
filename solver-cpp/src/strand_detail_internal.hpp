// Internal to hair detail (strand_detail.hpp): what its translation units share. applyDetail
// (strand_detail.cpp) runs the steps in order; the polyline helpers are in
// strand_detail_polyline.cpp, curl and frizz in strand_detail_curl_frizz.cpp, clump in
// strand_detail_clump.cpp, flyaways in strand_detail_flyaway.cpp. Not part of the solver's API:
// only those files include it.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rng.hpp"
#include "strand_detail.hpp"

namespace hairsketch::strand_detail {

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
constexpr uint64_t kStreamFlyaway = 0x9216d5d98979fb1bULL;
constexpr uint64_t kStreamCurlSpread = 0xd1310ba698dfb5acULL;
constexpr uint64_t kStreamRingletStrand = 0x98dfb5ac2ffd72dbULL;

inline Pcg32 strandRng(uint32_t seed, uint32_t key, uint64_t stream) {
  return Pcg32((uint64_t(seed) << 32) | key, stream);
}

inline double unitFromBits(uint32_t v) { return v * (1.0 / 4294967296.0); }

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

// Polyline helpers (strand_detail_polyline.cpp). A strand's points as doubles, its arc lengths
// and its frame, reused from strand to strand.

inline V3 lerp(const V3& a, const V3& b, double u) { return (1 - u) * a + u * b; }

struct Work {
  std::vector<V3> p, q, t, n, b;
  std::vector<double> s;
};

void load(const float* f, size_t count, std::vector<V3>& p);
void store(const std::vector<V3>& p, float* f);
double arcLengths(const std::vector<V3>& p, std::vector<double>& s);

// For ascending targets: advances j to the segment with s[j] <= target <= s[j + 1] (count >= 2)
// and returns the fraction along it.
inline double locate(const double* s, size_t count, double target, size_t& j) {
  const size_t last = count - 1;
  target = std::min(std::max(target, 0.0), s[last]);
  while (j + 1 < last && s[j + 1] < target) ++j;
  const double len = s[j + 1] - s[j];
  return len > 0 ? std::min(1.0, std::max(0.0, (target - s[j]) / len)) : 0.0;
}

// m >= 2 points evenly spaced by arc length along (p, s), first and last kept exactly.
void resampleEven(const std::vector<V3>& p, const std::vector<double>& s, size_t m,
                  std::vector<V3>& out);

// Cuts the strand at arc length len (0 < len), interpolating its new last point.
void cutAt(std::vector<V3>& p, std::vector<double>& s, double len);

// Keeps a strand that detail moved (clump, flyaway: detail that bends, not curls) within its
// length before, len: longer, it is cut there and resampled to its point count (q: scratch), so
// the maximum length stays a maximum (s: arc lengths, recomputed). applyDetail's locks.
void keepLength(std::vector<V3>& p, std::vector<double>& s, double len, std::vector<V3>& q);

// Rotation-minimising frame along p (double reflection, Wang et al. 2008): vertex tangents T (the
// mean of the adjacent segment directions), N_0 = the part of +y normal to T_0 (+x if T_0 is along
// y), B = T x N.
void frames(const std::vector<V3>& p, std::vector<V3>& T, std::vector<V3>& N, std::vector<V3>& B);

// Curl and frizz (strand_detail_curl_frizz.cpp).

// Points a strand of n points and length L has after curl: at least 12 a turn, at most cap.
size_t curlPointCount(const DetailParams& d, size_t n, double L, size_t cap);

// How a ringlet strand curls: `d` with its curl radius and frequency scaled by its clump's
// seeded factors (kRingletVary), and which way it winds (+1 or -1); the guide's key seeds them,
// so a clump stays one ringlet.
struct Ringlet {
  DetailParams detail;
  double hand = 1;
};
Ringlet ringletOf(const DetailParams& d, uint32_t seed, uint32_t phaseKey);

// Curl then frizz on one strand (w.p), in place; with curl, the strand is first resampled evenly
// to m points (curlPointCount) and s_k = L k / (m - 1) is the arc length along the path.
// phaseKey seeds the curl's phase (the strand's own key, or its clump guide's for ringlets);
// hand = -1 winds the curl the other way round the strand; centre: the head's, the curl volume
// spreads hair away from.
void curlAndFrizz(const DetailParams& d, uint32_t seed, uint32_t key, uint32_t phaseKey, size_t m,
                  Work& w, double hand = 1, const V3& centre = V3::Zero());

// Clump (strand_detail_clump.cpp).

// Clump of one group's strands (members, each with >= 2 points), in place.
// phaseKey (optional): a clumped strand's entry becomes its guide's key. nextGuide: a strand
// whose path parts from its nearest guide's is clumped to the next nearest whose path stays with
// it (applyDetail's clumpAll); off, it is not clumped. locks (applyDetail's): a strand clumping
// made longer is cut back to its length (keepLength). lockLength (> 0): a strand shorter is drawn
// onto its guide the less by its length over it.
void clumpGroup(const ClumpParams& c, const std::vector<uint32_t>& members,
                const std::vector<uint32_t>& key, uint32_t seed, Strands& strands, Work& w,
                std::vector<uint32_t>* phaseKey, bool nextGuide = false, bool locks = false,
                double lockLength = 0);

// Flyaway (strand_detail_flyaway.cpp).

// Whether the strand of `key` is a flyaway (its seeded pick; false when share or distance is 0).
bool flyawayPicked(const FlyawayParams& f, uint32_t seed, uint32_t key);

// Moves a picked strand (w.p, in place) away from `centre` past f.start of its length (within
// its length with locks: keepLength).
void flyaway(const FlyawayParams& f, uint32_t seed, uint32_t key, const V3& centre, Work& w,
             bool locks = false);

}  // namespace hairsketch::strand_detail
