// Hair detail on grown strands: length jitter, clump, flyaway, curl, frizz (parameters as Blender
// names them, but flyaway, which Blender has not; docs/user-guide.md "Detail"), applied in that
// order. World units (1 = 10 cm). For a strand
// with points p_0 (root) .. p_{n-1}, arc length s_i along its current path, length L = s_{n-1} and
// normalised arc length x_i = s_i / L (0 root .. 1 tip):
//
// Shape falloff S(x; s): s = 0 -> 1; else a = min(|s|, 1), x' = x if s > 0 else 1 - x, and
//   S = x'^(-log2(1 - a))            for a <= 0.5,
//   S = 1 - (1 - x')^(-log2 a)       for a > 0.5      (s = 0.5 -> x, s = -0.5 -> 1 - x).
//
// Length jitter j: L' = L (1 - j u), u uniform in [0, 1) from the strand's key; the strand is cut
// at
//   arc length L' (its last point interpolated on the segment that contains L').
// Clump (factor f, shape s, tipSpread t, guideDistance g), per group: guides are picked by a greedy
//   Poisson-disc pass over the roots in a seeded random order (sorted by a hash of seed and key):
//   a strand becomes a guide when no guide root lies closer than g to its root (g = 0: every strand
//   is its own guide, nothing moves). Every other strand follows its nearest guide G (lookup in a
//   uniform hash grid of cell size g) among those that set off the same way (headings, root to
//   the 4th point, within 60°: no clump across a parting; none such: not clumped), unless their
//   paths part by more than max(1, 4 g) somewhere (round different sides of the head: a blend
//   would cut through it; then not clumped): for every point but the root,
//     p_i <- (1 - w) p_i + w G(s_i) + t x_i (cos phi N_G(s_i) + sin phi B_G(s_i)),
//     w = f S(x_i; s), x_i = s_i / L,
//   G(s) being the guide's point at arc length s L_G / max(L, L_G) (interpolated): a strand longer
//   than its guide follows it stretched to its tip, a shorter one (stubble at a hairline) joins
//   the clump by arc length near its root and is not stretched towards a far tip; N_G, B_G the
//   guide's rotation-minimising frame there and phi a seeded per-strand angle. Guides keep their
//   shape and strands follow the guides' un-clumped shape. f = 1, s = 0, t = 0: every point lands
//   on the guide, the tip on its tip when the strand is at least as long.
// Flyaway (share h, distance D, start a), with the head's centre c (the origin when none is given):
//   a strand is a flyaway when u_0 < h, u_0 the first draw of its own stream (seeded by its key);
//   two more draws give its side angle phi = 0.5 (2 u_1 - 1) rad and bend beta = 0.25 D (2 u_2 -
//   1). With v_i = (x_i - a) / (1 - a) for x_i > a (the path after clump; nothing moves up to a):
//     p_i <- p_i + D v_i^2 (cos phi R_i + sin phi B_i) + beta sin^2(pi v_i) B_i,
//   T_i the path's tangent (p_{i+1} - p_{i-1}, one-sided at the ends), R_i the unit part of
//   p_i - c normal to T_i (away from the head, across the strand; any unit normal of T_i when
//   the strand points straight out, within 1e-3 rad), B_i = T_i x R_i. The tip moves by exactly D;
//   as (p_i - c) . B_i = 0 and (p_i - c) . R_i >= 0, no point comes closer to c than it was: a
//   stray hair that leaves its clump, smoothly (v^2, sin^2: no kink at a), not frizz.
// Curl (radius r, frequency q turns per unit of arc length, start a, randomOffset o): the strand is
//   first resampled evenly by arc length to m = min(maxPoints, max(n, ceil(12 q L) + 1)) points
//   (at least 12 a turn unless the cap binds), s_k = L k / (m - 1); then around that path
//     p_k <- p_k + r ramp(x_k) (cos theta_k N_k + sin theta_k B_k),
//     theta_k = 2 pi (q s_k + o u),  ramp(x) = smoothstep(x / a) (1 for a = 0; 0 at the root),
//   u uniform in [0, 1) from the key, (T, N, B) the path's rotation-minimising frame (double
//   reflection, Wang et al. 2008; N_0 = the component of +y normal to T_0, +x if T_0 is along y).
// Curl volume (spread v > 0, curl on): before the helix, the path it winds round moves out from the
//   head as curly hair stands out from the hair under it, widening towards the ends: with the
//   curl's shrinkage k = 1 - 1 / sqrt(1 + (2 pi q r)^2) (the share of its length a helix of radius
//   r and q turns a unit takes up: about 0.5 for curly and coily types, 0.02 for loose waves),
//     p_k <- p_k + v k L g t_k^1.3 D_k,   t_k = max(0, (x_k - a) / (1 - a)),
//   g = 1 + kCurlSpreadVary (2 u - 1) per lock (u seeded by the phase key: a ringlet's guide's),
//   D_k the unit of (p_k - c) with its y part dropped and its forward (+z) part clamped at 0, c the
//   head's centre (so hair spreads sideways and back, never over the face; a point straight in
//   front of c does not move), turned by the lock's lean; the move's back (-z) part is then
//   scaled by kCurlSpreadBack (curls widen more than they stand off the back: at the full amount
//   a new user saw long curls lean back off the body).
// Coil volume (coil w = 1, with curl volume): coily hair (4A-4C) stands out from the head as a
//   spring does, rather than hanging as a curtain: with its coiliness
//     C = w smoothstep((q - kCoilFrom) / (kCoilFull - kCoilFrom))   (0 for 3C and looser, 1 from
//   the middle of 4A), the curl volume's tip move is (1 + kCoilGain C) times as far, its profile
//   t^(1.3 + (kCoilPower - 1.3) C) (it leaves the head sooner), and D_k keeps C times the upward
//   (+y) part of p_k - c (hair on the top of the head stands up, never pushed down). C = 0: the
//   curl volume above, bit for bit.
// Frizz (distance d, shape s): v_i uniform in the unit ball (seeded by the key, one per point),
//   c_0 = 0, c_i = c_{i-1} + v_i.x T_i + v_i.y N_i + v_i.z B_i (the frame of the path before curl),
//   p_i <- p_i + d S(x_i; s) c_i. The root is pinned.
//
// Every detail leaves the root where it is. Strands with fewer than 2 points and strands whose
// group has nothing on are left bit-identical, unless they have more than maxPoints points: every
// strand ends with at most maxPoints points (a longer one is resampled evenly by arc length to
// maxPoints, root and tip kept). Randomness comes from Pcg32 seeded with (seed, key[s]) and a
// stream per use, so a strand's jitter, curl phase, frizz, tip spread and whether (and how) it
// flies away do not depend on which other strands are grown; clump guides do (they are chosen
// among the strands present).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "status.hpp"
#include "strand_growth.hpp"

namespace hairsketch {

struct CurlParams {
  double radius = 0;           // world units; 0 = off
  double frequency = 1;        // turns per world unit of arc length
  double start = 0.1;          // fraction of the length over which the curl ramps in
  double randomOffset = 0.25;  // per-strand phase, fraction of a turn
  // Curl volume (0 = off, as in sessions before it; the engine sets kCurlSpread with the
  // session's `curlVolume`): the share of a curl's shrinkage that spreads the hair out at its tip
  // (above, "Curl volume").
  double spread = 0;
  // Coil volume (0 = off, as in sessions before it; 1 with the session's `coilVolume`): above,
  // "Coil volume".
  double coil = 0;
};

struct ClumpParams {
  double factor = 0;  // 0 = off, 1 = onto the guide
  double shape = 0.5;
  double tipSpread = 0;        // world units at the tip
  double guideDistance = 0.1;  // world units between guide roots
};

struct FrizzParams {
  double distance = 0;  // world units per point; 0 = off
  double shape = 0.5;
};

struct FlyawayParams {
  double share = 0;        // 0..1: fraction of strands that fly away; 0 = off
  double distance = 0.12;  // world units at the tip
  double start = 0.55;     // fraction of the length where a flyaway leaves the groom
};

struct DetailParams {
  CurlParams curl;
  ClumpParams clump;
  FrizzParams frizz;
  FlyawayParams flyaway;
  double lengthJitter = 0;  // 0..1
  bool any() const {
    return curl.radius > 0 || clump.factor > 0 || frizz.distance > 0 || lengthJitter > 0 ||
           (flyaway.share > 0 && flyaway.distance > 0);
  }
};

// Blender's shape falloff S(x; s) (above); x is clamped to [0, 1].
double shapeFalloff(double x, double s);

// InvalidInput naming the field ("detail: curl.radius must be finite and >= 0") if a parameter is
// out of range: radius, frequency, tipSpread, guideDistance, distances finite and >= 0; factor,
// starts, randomOffset, share, lengthJitter in [0, 1]; shapes in [-1, 1].
Status validateDetail(const DetailParams& d);

// groups: the detail parameter sets; groupOf[s]: which set strand s uses (size = strand count);
// key[s]: a stable per-strand key (the root's index in the full root set) that seeds that strand's
// randomness; seed: the session's seed. No strand ends with more than maxPoints (>= 2) points.
// InvalidInput (strands untouched) on a bad parameter, size mismatch, group out of range or
// malformed strands. endSpread (optional, one per strand, world units): strand s is cut back by
// u · min(endSpread[s], kEndSpreadShare · its length), u uniform in [0, 1) seeded by its key, so
// hair that ends at one line (a bob, a fringe, a length cap) ends over a little band instead.
// ringlets: a clumped strand curls in phase with its clump's guide, so a clump's strands wind
// round together (ringlets) instead of each at its own phase (a crimped texture); each hair but
// the guide at its own radius (the ringlet's × (1 ± 0.35)) and up to 0.05 of a turn off the
// guide's phase, so that a ringlet has a thickness (strand_detail_curl_frizz.cpp).
// headCentre (optional): the head's centre flyaways move away from (the origin when absent).
// flags (optional, one per strand, growth's StrandFlag bits: Strands::flags): exceptions to a
// strand's group without moving it to another group (clumps stay whole). A kCutAtLine strand
// takes no length jitter (hair cut at a line keeps its length); a kLiesOnHead strand is never a
// flyaway (a stray hair 1.2 cm off at the tip of 10 cm hair stands up as a spike on a slicked
// crown).
// clumpAll: a strand whose path parts from its nearest clump guide's (by more than 4 guide
// distances, at least 10 cm: round the other side of the head or of a parting) is clumped to the
// next nearest guide whose path stays with it, instead of not at all (each such strand curled on
// its own: with curls, 3.5 % of long curly hair stood round it as a wiry halo of lone loops).
// locks (the rules locks 2.5 cm apart need): in a group without curl, a strand shorter than
// kLockLength is drawn onto its lock the less by its length over it (short hair lies as a sheet
// with soft pieces, long hair parts into locks; curls keep their ringlets); a strand clumping or
// a flyaway made longer than it
// grew is cut back to that length and resampled to its point count, so the maximum length stays
// a maximum (locks 2.5 cm apart lengthened hair grown to 60 cm to 61.5 cm); curl, which winds a
// strand, is not held to it.
Status applyDetail(const std::vector<DetailParams>& groups, const std::vector<uint32_t>& groupOf,
                   const std::vector<uint32_t>& key, uint32_t seed, Strands& strands,
                   int maxPoints = 255, const std::vector<float>* endSpread = nullptr,
                   bool ringlets = false, const Eigen::Vector3d* headCentre = nullptr,
                   const std::vector<uint8_t>* flags = nullptr, bool clumpAll = false,
                   bool locks = false);

// With locks, the length (world units, 30 cm) a strand needs to be drawn onto its lock in full:
// locks 2.5 cm apart drew a bob's back as "wedge panels with hard seams" and its hem as "a
// saw-tooth" (two judges).
constexpr double kLockLength = 3.0;

// The end spread of sessions with finished edges (world units: 1.2 cm), and the most of a
// strand's length it may take.
constexpr float kEndSpread = 0.12f;
constexpr double kEndSpreadShare = 0.15;

// The curl volume sessions with `curlVolume` get (CurlParams::spread), and how much it varies
// lock by lock (a seeded factor within 1 +- kCurlSpreadVary).
constexpr double kCurlSpread = 0.4;
constexpr double kCurlSpreadVary = 0.35;
constexpr double kCurlSpreadTurn = 0.5;  // radians
constexpr double kCurlSpreadBack = 0.5;  // of the move's back (-z) part
// Coil volume: the coiliness ramps in between these curl frequencies (turns a world unit: 3C's
// fastest and 4A's middle), and at full coiliness the curl volume's move is 1 + kCoilGain as far
// with the profile t^kCoilPower.
constexpr double kCoilFrom = 5.4;
constexpr double kCoilFull = 7.0;
constexpr double kCoilGain = 1.0;
constexpr double kCoilPower = 0.8;

}  // namespace hairsketch
