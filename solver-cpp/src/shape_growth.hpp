// The shape rules' steps in growth (hair_fall.hpp ShapeRules), for strand_growth.cpp's
// growStrands: laying hair on the head, letting it hang, combing it along strokes near it and
// parting it round the face. Each moves the end (nx, ny, nz) of a step from (x, y, z) that the
// field proposed.
#pragma once

#include <limits>

#include "hair_fall.hpp"
#include "head_distance.hpp"

namespace hairsketch {

struct ShapeGrowth {
  const HeadDistance* head = nullptr;            // set whenever the rules are on
  const CurveReach* reach = nullptr;             // the curves' reach, or null (no curve ends hair)
  float margin = 0;                              // the growth margin off the head (world units)
  float volume = 0;                              // the lift at the roots (world units, 0..0.3)
  float centre[3] = {0, 0, 0};                   // the head's centre (the prior's vertical axis)
  const std::vector<float>* napeLine = nullptr;  // the lower hairline (nape_line.hpp), or null
  // no fade above this height (the line's highest point plus kFadeAbove): growth reads the line
  // only below it
  float napeTop = -std::numeric_limits<float>::infinity();
  float lineOvershoot = 0;  // ShapeRules::lineOvershoot

  // The head's distance at p (world units) and its outward normal there (nrm, unit): read where
  // the distance grid is exact (HeadDistance::band), farther out by walking towards the head
  // (outward's direction) until it is, starting with a jump by hint (the last step's distance);
  // NaN past kLayReach plus the largest volume.
  float distanceOff(const float p[3], float nrm[3], float hint) const;

  // "Hair lies on the head": moves the step's end n (from x, of length segLen) along the head's
  // normal towards the strand's standoff (margin, the volume reached over the first length, and
  // kLayerSlope), no farther off than its stroke (lift + kLiftSlack) as far as a stroke governs it
  // (gov), then back to the step's length; dist and nrm return the distance read at x. A curve's
  // own Volume (ownVolume, holding by ownWeight at the strand's root) replaces the session's, and
  // lifts the hair that curve governs to its standoff too (a lifted bob, a pixie's crown). Anything
  // but Laid when the strand leaves the head's support: it is not laid again. Below the cranium's
  // widest part (the surface under it facing down past kSupportNormalY) it hangs from there
  // (Hangs), and off the scalp (an ear; not in the face's column, where it parts round the face)
  // too (Over); taken farther than kLayReach off by the field it follows the field (Free).
  // Short hair (hugs) is held at its standoff under the skull's widest part and down the nape
  // (behind the head's axis more than beside it), as a pixie's or a crop's hair is. At the nape
  // and over an ear it lies on past the scalp's edge (PastEdge: laid, its foot off the scalp),
  // where growth ends it (kTaperPastNape, kTaperPastEar; over an ear, hair a stroke combs goes on
  // with the stroke instead): a tapered nape and sides, not a blunt line.
  enum class Lay { Laid, PastEdge, Hangs, Over, Free };
  // Behind the head's axis more than beside it.
  bool atNape(float x, float z) const { return z - centre[2] < -std::abs(x - centre[0]); }
  // liesOn (short hair whose stroke stays within kDrawnLift of the head): it is laid at its
  // standoff as hair no stroke governs is, wherever a stroke governs it.
  Lay layOnHead(const float x[3], float n[3], double& segLen, double arc, float gov, float lift,
                float& dist, float nrm[3], float ownWeight = 0, float ownVolume = 0,
                bool hugs = false, bool liesOn = false) const;

  // "The face stays open": a step of hair no stroke governs or combs (gov below 0.5) that ends in
  // the face's column, its top raised by the Volume, turns to the nearer side (its horizontal part
  // sideways, at least as much as it falls), so the hair parts round the face.
  void partRoundFace(float x, float y, float z, float gov, float& nx, float& ny, float& nz) const;

  // "Hair no stroke governs hangs" and "is combed along a stroke beside it": the step of a strand
  // no stroke governs turns towards a direction: within kCombFar of a stroke that falls or lies
  // on the head, that stroke's direction there (fully within kCombNear; over an ear also towards
  // the stroke); farther, down spread by kHangSpread for a strand that hangs and its own direction
  // for one still laid on the head. here: (governed, nearest stroke's distance, its lift) at x.
  // Returns how far the strand is combed (0..1).
  float fallOrComb(bool hangs, bool overEar, float x, float y, float z, const float here[3],
                   float& nx, float& ny, float& nz) const;
};

}  // namespace hairsketch
