// Gathered tails in the growth step: the hair a gathered ponytail (gather = 1,
// ponytail_constraints.hpp) draws in is laid out as a round bunch along the ponytail's spine.
//
// Why a growth step: the field is smooth, so the hair of a 2D patch of scalp reaches the tail's
// first circle C1 as a thin sheet (neighbouring strands stay neighbours along the flow), and a
// field alone keeps that sheet flat all the way down (ratio of principal widths about 0.3). A
// band round a real ponytail re-seats each hair: hair from the far hairline ends on the outside
// of the bunch, hair from beside the band in its core, all round. That is a reordering of
// strands across the tail, which no direction field can express, so it happens here, after the
// strands have grown through the field up to C1, seeded and deterministic like detail.
//
// For a tail with circles C_1..C_m (centre c_k, unit axis a_k, radius r_k) on a spine polyline:
//   Capture: a strand is captured by the first tail it reaches along its path: where it crosses
//     C1's plane going along a_1 (w = (p - c_1) . a_1 goes from < 0 to >= 0 between two points)
//     at a distance from the axis rho <= kTailCapture r_1, or at its first point past C1 that lies
//     within kTailCapture r(s) of the spine (hair hanging beside the tail joins it, so the bunch
//     stands clear of the loose hair around it). That point q splits the strand: the path up to q
//     is kept; s_q is q's arc length along the spine (0 at C1's plane).
//   Seat: the captured strands' roots, projected on C1's plane around c_1, are ranked by angle
//     (starting after the widest empty gap of angles, so roots from one side of the head spread
//     round the whole bunch) and, independently, by distance from c_1. The strand of angle rank
//     i and distance rank j of N gets the seat
//       theta = 2 pi (i + 0.5 + jitter) / N,  rho' = r sqrt((j + 0.5) / N)  (a uniform disc),
//     jitter in [-0.5, 0.5) from the strand's key (Pcg32), so the bunch has no visible spiral.
//   Lay: from q on, the strand follows the spine S(s) (arc length s from c_1, from s_q on; past
//     the spine's end, straight on along its last direction) at the offset
//       o(s) = o_q + (seat(s) - o_q) smoothstep((s - s_q) / kTailBlend),
//     seat(s) = rho' r(s) / r_1 (cos theta E1(s) + sin theta E2(s)) with (E1, E2) a frame
//     transported along the spine without twist (double reflection) and r(s) the circles' radius
//     interpolated along the spine (r_m past C_m), o_q the crossing's own offset in that frame.
//     It keeps the length it had after q (so hair still ends where its curve ends), sampled at
//     the growth step, within the strand's point budget.
//
// Whole sections (a tie with `section` set, scalp_sections.hpp): the tie takes every strand the
// caller assigns it, whatever path the field gave it. Such a strand is laid anew from its root:
//   Combed: from the root over the scalp to the foot of its seat (the head's point nearest
//     P = c_1 + rho' r_1 (cos theta E1 + sin theta E2), its seat on C1's plane): directions from
//     the head's centre slerped from the root's to the foot's, each point put at
//     margin + kCombLift lambda smoothstep(t) off the head (lambda the root's distance rank:
//     hair from farther away lies on top), then straight up to P.
//   Tail: from P along the spine as above, the circles' radii scaled so the tail holds its hair
//     (at least sectionTailRadius at the tie, its 1 2/3 below it, spreading by up to 30 % over
//     the last 30 % of the spine), its length what the hair has left (maxLength less the combed
//     path), ending at the spine's end (less a seeded 0-8 % so the ends are not cut straight)
//     unless the curve lets it grow on. A bun's radius is at least sectionBunRadius and its
//     height 0.6 of it; its strands wind as many turns (up to K) as their length allows.
//   That is the ties-off layout; with the session's ties on, see "Ties from any hand" below.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "braid_bun.hpp"
#include "strand_growth.hpp"

namespace hairsketch {

constexpr float kTailCapture = 2.5f;      // x r_1: how far from the axis a crossing is taken in
constexpr float kBunCapture = 5.0f;       // the same for a bun (x its circles' 0.6 R: 3 R)
constexpr float kBraidBundle = 1 / 4.5f;  // a braid bundle's radius, x the braid's width
constexpr float kPlaitStretchMax = 2.5f;  // round plaits: the most a bundle's slice is widened
constexpr float kBraidLoose = 0.7f;       // the loose tail's radius, x the width at the tie
constexpr float kTailBlend = 0.3f;        // world units (3 cm): from the crossing to the seat
constexpr float kBraidTie = 0.1f;         // world units: the bundles meet into the loose tail
constexpr float kBunTuckAt = 0.85f;       // of a bun strand's coil: from there its tip turns under
constexpr float kBraidOpenAt = 0.35f;     // ties on: a braid's bundles' spread at the gather
constexpr float kBraidEndCut = 0.7f;      // ties on: the outer loose hair ends this much short

// Round: a ponytail's bunch. Braid, Bun: braid_bun.hpp, laid as described there.
enum class TailShape : uint8_t { Round, Braid, Bun };

struct GatheredTail {
  std::vector<Eigen::Vector3f> spine;               // from c_1 to the spine's tip
  std::vector<float> radius;                        // r(s) at each spine point
  Eigen::Vector3f axis = Eigen::Vector3f::UnitY();  // a_1 (unit): C1's plane is normal to it
  // Away from the head at C1 (zero: unknown): the frame's E2 points that way, E1 across.
  Eigen::Vector3f out = Eigen::Vector3f::Zero();
  TailShape shape = TailShape::Round;
  BraidParams braid;
  float braidLength = 0;  // from C1 to where the loose tail starts
  BunParams bun;
  Eigen::Vector3f bunCentre = Eigen::Vector3f::Zero();  // on the scalp
  float bunRadius = 0;
  // A round tail's or braid's hair ends at the spine's end unless its curve lets hair grow on.
  bool growsOn = false;
  // Gathers its whole scalp section (see "Whole sections" above); anchor: where it meets the
  // head (the scalp point nearest C1's centre).
  bool section = false;
  Eigen::Vector3f anchor = Eigen::Vector3f::Zero();
  // Where its stroke was pressed (the head point under the curve's first point): with `ties` on,
  // a ponytail's or braid's section is the one pressed in, not the one its band lies over (fresh
  // eyes pressed just in front of a half-up parting; the band, 1.2 cm along the stroke, lay
  // behind it and the tie gathered the hair behind).
  Eigen::Vector3f pressed = Eigen::Vector3f::Zero();
  // The session's `ties` (HairEngine::ties): lay the tie as "Ties from any hand" below
  // (gathered_tail_ties.cpp). Off: laid exactly as before (saved sessions keep their hair).
  bool ties = false;
  // The session's `roundPlaits` (HairEngine::roundPlaits): a braid's sections are round across
  // their own path (gathered_tail_shapes.cpp plaitStretch). Off: as before.
  bool roundPlaits = false;
  // The session's `tieVolume` (HairEngine::tieVolume): sizeTie makes a round tail's body and a
  // bun's rope kTieVolume times as wide. Off: as before.
  bool tieVolume = false;
  // The session's `compactBun` (HairEngine::compactBun): a bun's rope wraps its own base tightly,
  // each wrap a little lower and further out (knotShape), instead of spiralling out over a wide
  // flat dome. Off: as before.
  bool compactBun = false;
};

// The tail of a gathered ponytail: spine = the curve's points from the one nearest C1's centre
// (replaced by that centre) to the tip; radii interpolated between the circles by arc length.
struct PonytailParams;
GatheredTail gatheredTail(const double* spine, size_t pointCount, const PonytailParams& params);

// A braid's tail (braid_bun.hpp): the gathered ponytail of braidAsPonytail, laid as a plait.
// out: away from the head at the gather (zero: unknown).
GatheredTail braidTail(const double* spine, size_t pointCount, size_t gather,
                       const BraidParams& params, const Eigen::Vector3f& out);
// A bun's tail: its two circles as the spine, laid as a coil.
GatheredTail bunTail(const BunFrame& frame, const BunParams& params);

class HeadDistance;

// Whole sections: which tie each strand belongs to (assigned[s]: an index in `tails` of a tail
// with section set, or -1), and the head the combed hair lies on.
struct SectionGather {
  std::vector<int32_t> assigned;
  const HeadDistance* head = nullptr;  // null: the hair is combed over the sphere about centre
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  float margin = 0.02f;  // kept off the head, world units
};

// The radius of a round tail at its tie and in its body, and a bun's, for a tie holding `share`
// of the whole head's hair (a full head: kTieRadius, kTailRadius), world units. A bun's radius
// also grows with the length of hair it coils (lengthAfterTie, world units).
constexpr float kTieRadius = 0.12f;  // 1.2 cm: the whole head's hair held by a band
// The widest a ponytail's drawn circles make its band (ties on): a one-stroke ponytail's width
// (web/model/ponytailFromSpine.ts ONE_STROKE_RADIUS), 8 mm.
constexpr float kBandDrawnRadius = 0.08f;
constexpr float kTailRadius = 0.2f;  // 2 cm: the same hair hanging below it
constexpr float kCombLift = 0.07f;   // 7 mm: the top layer of combed hair over the scalp
// ties on: combed hair rises to its seat over kCombRise times the seat's height off the head
// (at most 1.5 / kCombRise of a slope: about 37 degrees)
constexpr float kCombRise = 2.f;
float sectionTailRadius(float share);
// Tie volume (the session's tieVolume, with ties from any hand): a whole section's round tail
// hangs kTieVolume times as wide as sectionTailRadius (3 cm for a whole head), and its bun's rope
// is as much thicker (a braid keeps its width). Judges of the style library found tails, buns and
// braids too small for the hair they gather (a whole head of long hair in a ponytail hangs 5-7 cm
// wide).
constexpr float kTieVolume = 1.5f;
float sectionBunRadius(float share, float lengthAfterTie);

// Ties from any hand (the session's `ties` on; gathered_tail_ties.cpp, docs/braids-buns.md):
//   A tie's hair is as long as its tail needs (combed path + the spine to its end) whatever the
//   session's Max length, unless its curve lets the hair grow on.
//   Round tail: its radius r(s) times tieTaper(s / L) (L the spine's length), and each strand
//   ends tieEndCut(rho, u1, u2) L short of the spine's end (rho its seat radius in the unit
//   disc, u1, u2 seeded per strand): the outer hair ends earlier, so the tail tapers to uneven
//   ends instead of a square cut.
//   Bun: the gathered hair goes up the axis from the band, over the top's centre, then as one
//   twisted rope of radius rr K turns outward and down the dome to the base and a quarter turn
//   in under the outer wrap: R = rr (kBunRopePitch K + 2). A whole-section bun's rope holds its
//   hair (rr = kBunRopeFill x sectionTailRadius(share)) and K is what its length allows.
constexpr float kTieTaper = 0.3f;      // the radius lost by a round tail's end (x r)
constexpr float kTieEndOuter = 0.15f;  // the outermost hair ends up to this much short (x L)
constexpr float kTieEndAll = 0.05f;    // every strand ends up to this much short (x L)
constexpr float kBunRopePitch = 1.7f;  // a bun's wraps' spacing, x the rope's radius
constexpr float kBunRopeFill = 0.7f;   // a rope's radius, x the hair's round-tail radius
constexpr float kBunRopeTwist = 6.f;   // the rope's strands turn once per this many rope radii
constexpr float kBunHeadRadius = 1.f;  // world units: the scalp's curvature under a bun
float tieTaper(float f);
float tieEndCut(float rho, float u1, float u2);
// A bun's rope radius for its radius R and turns K; H (its height) raised to hold the dome.
void bunRopeShape(float R, float K, float& rr, float& H);
// Compact bun (the session's compactBun): the rope climbs the axis from the band and wraps round
// its own stub from the top down, K turns, each kKnotPitch rr lower and kKnotSpread rr further
// out than the last, the first kKnotWrap rr from the axis, then a quarter turn in under the
// lowest wrap (its end tucked). No hole at the top (the stub and the first wrap overlap), none at
// the sides (wraps kKnotPitch < 2 rope radii apart) and no loose end: a round knot R = rr
// (kKnotWrap + kKnotSpread K + 1) wide and H = rr (kKnotPitch K + 2) high. A whole-section bun's
// rope is a twisted rope's, tighter than a hanging tail: rr = kKnotRope x sectionTailRadius.
constexpr float kKnotWrap = 1.6f;
constexpr float kKnotSpread = 0.6f;
constexpr float kKnotPitch = 1.3f;
constexpr float kKnotRope = 0.75f;
// A whole-section compact bun wraps at least this many turns (fewer read as a loop, a C of rope
// round a hole): its hair is as long as the rope (kWholeRope), as a ponytail's is its tail's.
constexpr float kKnotMinTurns = 1.5f;
// A compact bun's rope radius and height for its radius R, turns K and the height asked for.
void knotShape(float R, float K, float height, float& rr, float& H);
// A whole-section tie's size for `share` of the hair, `after` long past the tie (world units).
void sizeTie(GatheredTail& t, float share, float after);

struct TailStats {
  size_t captured = 0;            // strands laid into a tail
  std::vector<uint32_t> strands;  // which, in increasing order
  std::vector<uint32_t> tail;     // tail[i]: the index in `tails` of the one that laid strands[i]
  // Per tail (in `tails` order): the radius of its hair at its first circle as laid (a round
  // tail's r(0) once sized to the hair it holds), 0 where that is not one circle (a braid's
  // bundles, a bun): where a band round it goes.
  std::vector<float> bandRadius;
};

// Re-lays the captured strands of every tail (see above). key[s] is strand s's seed key (its root
// index in the full root set), roots[s] its root; step is the growth step (world units);
// maxPoints caps a strand's points. maxLength (world units; 0: unknown) is the hair's length
// budget: a bun's strand coils up to it (the field walk ends at the bun's top). Strands that no
// tail captures are left bit-identical.
// sections (may be null) names the strands whole-section ties take; no other tail captures
// them, and a whole-section tie captures no other strand.
TailStats gatherTails(const std::vector<GatheredTail>& tails,
                      const std::vector<Eigen::Vector3f>& roots, const std::vector<uint32_t>& key,
                      uint64_t seed, float step, size_t maxPoints, Strands& strands,
                      float maxLength = 0, const SectionGather* sections = nullptr);

}  // namespace hairsketch
