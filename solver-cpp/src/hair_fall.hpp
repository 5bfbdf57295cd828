// Natural fall: what a session with the fall setting adds to the paper's method.
//
// 1. A prior direction field G over the grid (fallDirections), the target of a weak term
//    beta^2 sum_i ||t_i - g_i||^2 in the field energy (FieldSolver::setPrior): hair that no
//    curve governs hangs from the scalp as combed-down hair does. Near the head g is straight
//    down combed along the scalp, with a slight spread away from the head's vertical axis (so
//    the crown parts outward rather than standing up, and the front parts to the sides of the
//    face) and a slight lift off the surface;
//    kFallBlend away from the head, below its widest part, it is straight down.
// 2. The reach of the curves that end hair (stream curves and ponytail spines without
//    "extend"): per grid point, the curves' remaining length there, blended between curves, and
//    how far the point is from every such curve (buildCurveReach). Growth stops a strand where
//    the remaining length reaches zero, so the hair a curve governs ends where the curve ends, and
//    lets a strand governed by a curve slide over the face where ungoverned hair stops at the
//    hairline.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "field_system.hpp"
#include "grid.hpp"
#include "head_distance.hpp"

namespace hairsketch {

// The prior's weight beta^2 (relative to the bi-Laplacian's unit weight; omega^2 = 1e4) sets how
// far a curve's pull reaches before the hair hangs: D^T D has the symbol ~ |k|^4 / 36 for a
// wave of k radians per grid step, so beta^2 = (d / l)^4 / 36 makes a curve's influence fade
// over about l world units whatever the grid step d. kFallReach = l: 5 cm.
constexpr double kFallReach = 0.5;
// With the shape rules (ShapeRules below) a stroke's pull fades over 2.5 cm: beyond 3-4 cm from
// every stroke natural fall decides, whatever the stroke's direction.
constexpr double kShapeReach = 0.25;
inline double fallWeight(double step, double reach = kFallReach) {
  const double k = step / reach;
  return k * k * k * k / 36;
}
// World units (1 unit = 10 cm) over which g turns from combed along the scalp to straight down.
constexpr double kFallBlend = 0.6;
// Horizontal spread away from the head's vertical axis, and lift off the scalp, mixed into the
// combed direction.
constexpr double kFallSpread = 0.5, kFallLift = 0.15;
// In front of the vertical axis (+z, the face's side) the spread's forward part is scaled by
// this: the front hair parts sideways.
constexpr double kFallFrontSpread = 0.2;

// g at every grid point (n x 3, unit length): head = the head's distance grid, centre = the
// head's centre (its vertical axis passes through it).
// With openFace (finished edges), off the head in front of the face (below the front hairline's
// height, within kFaceHalfAngle of straight ahead about the vertical axis) g turns aside to the
// nearer side: hair no curve governs falls round the face, not in front of it.
// With shape (the shape rules), g turns to straight down within kShapeBlend of the head below its
// widest part, so hair that leaves the head there hangs instead of following the head in, and
// the face is left to growth (strand_growth.cpp parts hair round it), not turned aside here.
Field fallDirections(const Grid& grid, const HeadDistance& head, const Eigen::Vector3d& centre,
                     bool openFace = false, bool shape = false);
constexpr double kShapeBlend = 0.15;
// The face's column (relative to the centre, world units and radians): its top (the front
// hairline's height), bottom (below the chin), half angle, and how far aside g turns there
// (the sideways part against down's 1).
constexpr double kFaceTop = 0.5, kFaceBottom = -1.6, kFaceHalfAngle = 0.75, kFaceAside = 1.5;

// Reach of the curves that govern hair (stream curves and ponytail spines), on a lattice of its
// own (reachGrid: the solver grid's box in cells of at least kReachCell; the reach is smooth, so
// it need not follow the solver's resolution). A point within kReachNear of such a curve takes
// the curves' blended remaining length; past kReachFar from every curve it is far (the hair there
// grows to the maximum length); between, the far fraction rises smoothly, so hair between the
// strokes of a style takes their length.
constexpr double kReachNear = 0.8, kReachFar = 1.5, kReachCell = 0.15;
// Width (world units) of the Gaussian weights that blend nearby curves' remaining lengths.
constexpr double kReachSigma = 0.25;
// A fringe's stroke (one that leaves the scalp over the face, ReachCurve::fringe) sets the length
// of its own hair only, the hair within kOwnReach of it (as far as a stroke's pull reaches),
// fading out by kOwnReachFar: the hair beside it that hangs on past its end takes its length from
// the other strokes. (A bang drawn to the cheekbone cut all the hair in front of the ear there.)
constexpr double kOwnReach = 0.25, kOwnReachFar = 0.4;
// Hair within kFaceNear of a curve's stretch off the scalp, and heading along it (within about
// 60 degrees), may slide over the face; past kFaceFar it stops at the hairline as ungoverned hair
// does.
constexpr double kFaceNear = 0.2, kFaceFar = 0.35;
constexpr float kFaceAlign = 0.5f;

struct ReachCurve {
  const double* points = nullptr;  // points[3 * k + axis]
  size_t count = 0;
  // "Extend past the end": the curve does not end the hair near it.
  bool growsOn = false;
  // Per point (count entries, or null for none): the curve runs there off the scalp (over the
  // face, an ear, the neck, or in the air). Hair near such a stretch may follow it over the face.
  const uint8_t* offScalp = nullptr;
  // Its hair's length sets the length of the hair around it (LengthAround): stream curves, not
  // ties (which lay their own hair).
  bool setsLength = false;
  // Per point (count entries, or null: on the head): how far the point is from the head (world
  // units), for the shape rules (governed hair stands off no farther than its stroke).
  const float* lift = nullptr;
  // The curve's own Volume (world units; below 0: none, the session's applies), for the shape
  // rules: the hair around it stands off the head by this much instead (OwnVolume).
  float volume = -1;
  // (shape rules) It leaves the scalp over the face (a fringe): its length is its own hair's
  // only (kOwnReach); it does not set the length or the hem of the hair around it.
  bool fringe = false;
};

// The reach lattice for a solver grid: the same box, cells of max(step, kReachCell).
Grid reachGrid(const Grid& solverGrid);

// What a stroke's hair is: where it starts, how long it is, and whether it grows on (for the
// length of the hair between strokes, LengthAround).
struct StrokeLength {
  float x = 0, y = 0, z = 0;  // the curve's first point (on the scalp)
  float length = 0;           // the curve's arc length (world units)
  bool growsOn = false;
  // It ends on the scalp and combs on: it counts (with its own length) only where no stroke
  // that ends hair (one that leaves the head) is in the session (LengthAround).
  bool combs = false;
  float endX = 0, endY = 0, endZ = 0;  // the curve's last point (the hem, HemAround)
};

// (ties on) A stroke that grows on and ends within this distance (world units: 3 cm, as the app
// extends a stroke that ends there into a tie) of a tie's curve is combed into the tie: it does
// not set the length of the hair around it.
constexpr double kIntoTie = 0.3;

// Within kGovernNear of a curve the hair is the stroke's (it may stand off the head as the
// stroke does); past kGovernFar from every curve the shape rules lay it on the head.
constexpr double kGovernNear = 0.1, kGovernFar = 0.25;
// A curve's own Volume holds within kOwnVolumeNear of it and fades out by kOwnVolumeFar, where the
// session's Volume takes over (a stroke's reach of a few centimetres, as its pull has).
constexpr double kOwnVolumeNear = 0.3, kOwnVolumeFar = 0.6;

struct CurveReach {
  Grid grid;                     // the reach lattice
  std::vector<float> remaining;  // per lattice point: blended remaining length (world units)
  // per lattice point: the fringes' share of that blend's weight, and their remaining length
  // blended alone (ReachCurve::fringe)
  std::vector<float> fringeShare, fringeRemaining;
  std::vector<float> far;          // per lattice point: 0 near a curve .. 1 far from all
  std::vector<float> overFace;     // per lattice point: 1 near a curve's stretch off the scalp .. 0
  std::vector<float> faceTangent;  // 3 per lattice point: that stretch's unit direction
  std::vector<float> governed;     // per lattice point: 1 within kGovernNear of a curve .. 0
  std::vector<float> lift;         // per lattice point: the nearest curve's distance off the head
  std::vector<float> strokeLift;   // per lattice point: the nearest curve's largest such distance
  std::vector<float> nearest;      // per lattice point: the distance to the nearest curve
  std::vector<float> tangent;      // 3 per lattice point: the nearest curve's direction there
  std::vector<float> toCurve;      // 3 per lattice point: from it to the nearest curve point
  // Per lattice point, only when a curve has its own Volume: how far that Volume holds there
  // (1 within kOwnVolumeNear .. 0 past kOwnVolumeFar of every such curve) and its value (the
  // curves' values blended by those weights).
  std::vector<float> ownVolumeWeight, ownVolume;
  std::vector<StrokeLength> strokes;  // the curves' lengths, in curve order
  bool empty() const { return remaining.empty(); }
  void clear() {
    remaining.clear();
    fringeShare.clear();
    fringeRemaining.clear();
    far.clear();
    overFace.clear();
    faceTangent.clear();
    governed.clear();
    lift.clear();
    strokeLift.clear();
    nearest.clear();
    tangent.clear();
    toCurve.clear();
    ownVolumeWeight.clear();
    ownVolume.clear();
    strokes.clear();
  }
};

// The shape rules (a session's `shape` setting, off in sessions made before them, which keep
// their hair), so that the hair takes the shape a stylist draws rather than a box round the head:
//  - the prior's reach is kShapeReach;
//  - hair no stroke governs (CurveReach::governed) lies on the head at its standoff (the growth
//    margin, `volume` and kLayerSlope) while the skull above its widest part holds it, then hangs;
//    hair a stroke governs stands off no farther than its stroke (kLiftSlack);
//  - hair no stroke governs is combed along strokes near it (kCombNear..kCombFar) and parts round
//    the face's column (inFaceColumn);
//  - length from the strokes around (lengthAround), capped by the maximum length.
// docs/natural-fall.md section 5 gives the weights and the checks.
struct ShapeRules {
  bool on = false;
  float volume = 0;  // world units: how far the hair stands off the head at its roots (0..0.3)
  float centre[3] = {0, 0, 0};  // the head's centre (the prior's vertical axis)
  // the lower hairline where short hair fades out (nape_line.hpp napeLine), or null: no fade
  const std::vector<float>* napeLine = nullptr;
  // how far hair that ends at its strokes' line grows past it (world units; half the end
  // spread detail cuts back with finished edges, at most half its share of the length), so
  // its ends are spread round the line, not above it
  float lineOvershoot = 0;
  // Face clear (a session's faceClear): hair a stroke governs parts round the face too, unless
  // it follows a stroke over the face (reachOverFace), so hair between strokes drawn beside the
  // face does not hang across the eyes in the air in front of it. Off: as sessions made before.
  bool faceClear = false;
};
// Whether p lies in the face's column (kFaceTop, kFaceBottom, kFaceHalfAngle about the vertical
// axis through centre, in front of it), where hair no stroke governs does not go: it parts to
// the nearer side, as hair parted at the centre does.
constexpr float kFaceHalfAngleTan = 0.9315965f;  // tan(kFaceHalfAngle)
// Hair parted round the face heads back by this much (against its step's length) as it goes aside:
// as much back as aside, round the temple towards the ear.
constexpr float kFaceBack = 1.0f;
inline bool inFaceColumn(const float centre[3], float x, float y, float z) {
  const float fz = z - centre[2], dx = x - centre[0], yc = y - centre[1];
  return fz > 0 && yc < float(kFaceTop) && yc > float(kFaceBottom) &&
         std::abs(dx) < kFaceHalfAngleTan * fz;
}
// The head's outward normal must have an upward part above this for the head to hold the hair
// on it (a little under horizontal: the cranium's sides above its widest part).
constexpr float kSupportNormalY = -0.15f;
// How far from the head (world units, beyond the standoff) a strand may be and still be laid on
// it: farther, a stroke or the field has taken it away, and it is left alone.
constexpr float kLayReach = 0.4f;
// Over what length the hair rises to its standoff (volume / kVolumeRise).
constexpr float kVolumeRise = 0.5f;
// Short hair (kHugLength) keeps its Volume on top of the head and loses what it has past the
// default's (kHugVolumeKept, the Hair panel's 5 mm) down the sides and the nape, as a cut's
// close sides and nape do: that part is scaled by a smoothstep of the surface normal's height,
// 0 at kHugVolumeLow (the skull's widest part) to 1 at kHugVolumeHigh (60 degrees from the
// crown), so a pixie is lifted at the crown and tapers in to the head over the ears and down the
// nape instead of ending off it as a shelf (hair at the default volume grows as before).
constexpr float kHugVolumeLow = 0.0f, kHugVolumeHigh = 0.5f, kHugVolumeKept = 0.05f;
// Short hair at the nape loses the rest of its standoff (Volume and layering) where the skull
// turns in under its widest part, all of it where the surface faces down by this much (the
// normal's height) and past the hairline: it closes in to the neck as a tapered nape does.
constexpr float kNapeCloseNormal = 0.4f;
// Hair laid on the head lies on top of the hair rooted under it: its standoff grows by this
// much per unit of length it has come over the head (3 mm per 10 cm), up to kLayerMax (1 cm),
// so hair from the crown covers the sides in layers instead of all at one distance.
constexpr float kLayerSlope = 0.03f, kLayerMax = 0.1f;
// Hair shorter than this (world units) hugs the head (ShapeGrowth::layOnHead's `hugs`): it does
// not hang from under the skull's widest part but lies on down the nape, as short hair is too
// stiff to fall away from the head. Each strand's threshold is scaled by a factor in
// [1 - kHugJitter, 1 + kHugJitter] seeded by where its root is (mirror-symmetrically), so where
// lengths cross it the hair mixes.
constexpr float kHugLength = 1.2f, kHugJitter = 0.2f;
// Short hair lies on past the scalp's edge for about this (world units; scaled per strand by
// 1 +- kTaperJitter, strand_growth.cpp): 3 cm past the nape's hairline, 1.5 cm over an ear, so the
// nape tapers to the hairline instead of hanging down the neck, and the sides cover the top of the
// ear instead of hanging over it to a blunt line. Hair a stroke combs over an ear goes with the
// stroke instead (it is not cut).
constexpr float kTaperPastNape = 0.3f, kTaperPastEar = 0.15f;
// Short hair (hugs) that a stroke's hair ends (the remaining length) ends anywhere from
// kLayeredPast past that end to kLayeredBand before it (by noise seeded where its root is; never
// before it has used kLayeredShare of the length it had left at its root), as a layered cut's
// ends are spread round the line where the strokes end: not all on it, a bowl's shelf.
constexpr float kLayeredBand = 0.35f, kLayeredShare = 0.5f, kLayeredPast = 0.15f;
// A crown's whorl, not a seam: where the field sends the hair apart across a line that runs
// across the head (strokes drawn forward from the crown and others down the back from the same
// place), hair rooted within about kSeamProbe of the line first lies along it, outward from the
// head's mid-plane (down on the sides), fading out over kSeamCoverLength; by how sharply the
// field parts there (the turn of its direction across the probe, from kSeamLow to kSeamHigh) and
// how far the line runs across the head rather than front to back (kSeamAcrossLow to
// kSeamAcrossHigh of 1 - |t.z|, t the line's direction): the line is covered as a whorl is, not
// bare scalp as a parting. Lines that run front to back (the partings strokes make) stay partings.
constexpr float kSeamProbe = 0.12f, kSeamLow = 0.4f, kSeamHigh = 0.8f, kSeamCoverLength = 0.35f,
                kSeamAcrossLow = 0.4f, kSeamAcrossHigh = 0.8f;
// Short hair a stroke governs lies on the head as hair no stroke governs does when that stroke
// never goes farther than this off the head (world units, 3 cm): a stroke drawn down past the nape
// in a back view keeps its depth (the depth rule) and so leaves the neck as it curves in, and the
// short hair it governed stood off the nape as a curtain; a spike drawn up and away goes farther.
constexpr float kDrawnLift = 0.3f;
// Hair a stroke governs stands off the head no farther than the stroke does, plus this (world
// units): it may lie closer, never flare out past its stroke.
constexpr float kLiftSlack = 0.05f;
// Hair no stroke governs within kCombNear of a stroke that falls (its direction at least
// kCombFalls downward) or lies on the head there (within kCombOnHead of it) is combed along it,
// fading out by kCombFar (kCombFarOverEar over an ear): hair beside a stroke drawn down behind an
// ear goes behind the ear with it, hair beside a sweep across the forehead sweeps with it (and is
// not parted round the face); over an ear it also heads for the stroke, so it goes round the ear
// where the stroke does.
// Hair that hangs falls down, spread this much (against down's 1) away from the head's axis.
constexpr float kHangSpread = 0.12f;
constexpr float kCombNear = 0.3f, kCombFar = 0.5f, kCombFarOverEar = 0.8f, kCombFalls = 0.3f,
                kCombOnHead = 0.15f;
// Over an ear, hair heads for a stroke behind it (tucking it behind the ear; never for one in
// front of it, as a stroke drawn down over the shoulder: the side's hair would gather onto it as
// a rope), at full strength from kCombNear out and not at all within kCombBeside of it: it goes
// round the ear beside the stroke, not onto its line.
constexpr float kCombBeside = 0.15f;
// The length of hair no stroke ends, rooted at p: Shepard's inverse-square-distance blend of the
// strokes' lengths (a stroke that grows on counts as maxLength, unless it ends on the scalp: a
// stroke that combs counts its own length, and only when every stroke combs: one sweep drawn on
// the head over long hair says where the hair goes, not how long it is), capped by maxLength;
// maxLength when there is no stroke.
float lengthAround(const std::vector<StrokeLength>& strokes, const float p[3], float maxLength);

// The hem: hair no stroke ends that hangs beside strokes that end their hair well below where
// they start (kHemDrop: long hair drawn down the back, a bob drawn to the chin) stops at the
// height where those strokes end, blended over the scalp with lengthAround's weights, not at
// their length: hair rooted low at the sides would otherwise hang lower than a stroke drawn down
// the middle of the back (an upside-down U). A stroke's end sets the hem of the hair hanging
// beside it: its weight fades out as the root lies farther across (in x and z) from that end,
// from kHemNear to kHemFar (hair at the back is not cut to the height of a sweep drawn down the
// front). Where such strokes hold less than kHemShareFrom of the weight (a fringe, a spike,
// strokes extended to the maximum, ends far across) there is no hem; up to kHemShareTo it sinks
// by up to kHemFade, so it comes in smoothly over the scalp. Returns the hem's height,
// -infinity where there is none.
constexpr float kHemDrop = 1.5f, kHemNear = 0.8f, kHemFar = 1.4f, kHemShareFrom = 0.4f,
                kHemShareTo = 0.8f, kHemFade = 3.f;
float hemAround(const std::vector<StrokeLength>& strokes, const float p[3]);
// A stroke that sets a hem: it ends its hair off the head, kHemDrop or more below its start.
inline bool setsHem(const StrokeLength& c) {
  return !c.growsOn && !c.combs && c.endY < c.y - kHemDrop;
}

// One curve's part of the reach: the lattice points within kReachFar of it, with the distance to
// it, its remaining length there (L - s, s the arc length of the closest point on the polyline,
// less how far the point lies past the curve's end along its last segment), and the distance to
// its nearest stretch off the scalp (infinite: none) with that stretch's direction. A curve's
// footprint depends on it and the lattice alone, so the engine keeps it while the curve is
// unchanged (a stroke's previews redo only the stroke's).
struct CurveFootprint {
  std::vector<int> index;
  std::vector<float> distance, remaining, faceDistance, faceTangent;  // faceTangent: 3 each
  std::vector<float> lift;     // the curve's distance off the head at the closest point
  std::vector<float> tangent;  // 3 each: the curve's direction at the closest point
  std::vector<float> toCurve;  // 3 each: from the lattice point to the closest point
  bool growsOn = false;
  float volume = -1;    // the curve's own Volume (ReachCurve::volume)
  float maxLift = 0;    // the curve's largest distance off the head (ReachCurve::lift)
  bool fringe = false;  // ReachCurve::fringe
  StrokeLength stroke;
};
void curveFootprint(const Grid& lattice, const ReachCurve& curve, CurveFootprint& out);

// The reach of curves from their footprints: remaining lengths blended by Gaussian weights of
// the distances (kReachSigma), the far fraction from the nearest curve, the over-face weight and
// direction from the nearest stretch off the scalp. faceCentre (the head's centre; null: none):
// a fringe's length holds at any distance in front of the face (faceColumnWeight).
void combineReach(const Grid& lattice, const std::vector<const CurveFootprint*>& curves,
                  CurveReach& out, const Eigen::Vector3d* faceCentre = nullptr);

// How far x is in front of the face (0..1): within the face's half angle (kFaceHalfAngle, fading
// from 0.6 of it) in front of the head's centre, from kFaceBottom (fading in over 3 cm) up to
// kFaceTop (fading out over 2 cm).
double faceColumnWeight(const Eigen::Vector3d& centre, const Eigen::Vector3d& x);

// curveFootprint of each curve, then combineReach, on reachGrid(solverGrid).
void buildCurveReach(const Grid& solverGrid, const std::vector<ReachCurve>& curves, CurveReach& out,
                     const Eigen::Vector3d* faceCentre = nullptr);

// Trilinear interpolation of a per-grid-point scalar at x (clamped to the volume); stride and
// offset pick one component of interleaved values.
float interpolateScalar(const Grid& grid, const float* values, float x, float y, float z,
                        int stride = 1, int offset = 0);

// interpolateScalar of `count` per-grid-point scalars at once (the weights found once): out[k]
// from arrays[k].
void interpolateScalars(const Grid& grid, const float* const* arrays, int count, float x, float y,
                        float z, float* out);

// The remaining length at x for hair of at most maxLength: the curves' blend near them, the
// maximum length far from them.
inline float reachRemaining(const CurveReach& reach, float x, float y, float z, float maxLength) {
  const float f = interpolateScalar(reach.grid, reach.far.data(), x, y, z);
  const float r = interpolateScalar(reach.grid, reach.remaining.data(), x, y, z);
  return (1.f - f) * r + f * maxLength;
}

// Whether hair at x heading along dir (unit) follows a curve over the face.
inline bool reachOverFace(const CurveReach& reach, float x, float y, float z, const float dir[3]) {
  if (interpolateScalar(reach.grid, reach.overFace.data(), x, y, z) < 0.5f) return false;
  float t[3], n2 = 0;
  for (int e = 0; e < 3; ++e) {
    t[e] = interpolateScalar(reach.grid, reach.faceTangent.data(), x, y, z, 3, e);
    n2 += t[e] * t[e];
  }
  const float along = dir[0] * t[0] + dir[1] * t[1] + dir[2] * t[2];
  return n2 > 0 && along >= kFaceAlign * std::sqrt(n2);
}

}  // namespace hairsketch
