#include "strand_growth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "field_samplers.hpp"
#include "hair_fall.hpp"
#include "nape_line.hpp"
#include "parallel.hpp"
#include "rng.hpp"
#include "seam_cover.hpp"
#include "shape_growth.hpp"
#include "strand_detail.hpp"
#include "strand_noise.hpp"

namespace hairsketch {

using field_samplers::F4;
using field_samplers::makeSampler;
using field_samplers::PaddedSampler;

std::vector<float> toFloatField(const Field& T) {
  std::vector<float> v(size_t(T.rows()) * 3);
  const double* src = T.data();  // row-major n x 3: already interleaved
  for (size_t i = 0; i < v.size(); ++i) v[i] = float(src[i]);
  return v;
}

Eigen::Vector3f interpolateField(const Grid& g, const float* field, const Eigen::Vector3f& x) {
  float v[3];
  makeSampler(g, field).at(x.x(), x.y(), x.z(), v);
  return {v[0], v[1], v[2]};
}

namespace {

using PointBuffer = decltype(Strands::points);

// Each short strand lies on past the scalp's edge for kTaperPast* scaled by a factor in
// [1 - kTaperJitter, 1 + kTaperJitter], from rootNoise read kTaperNoiseShift away (other values
// than its hug threshold's).
constexpr float kTaperJitter = 0.5f, kTaperNoiseShift = 7.3f;
// Hair that stops at the hem (HemAround) stops up to kHemBand above it, from rootNoise read
// kHemNoiseShift away, so the hem is a band of cut ends, not one line; never before it has
// kHemKeeps of its length.
// Hair within kGovernNear of a stroke (governed above kHemGoverned) is the stroke's: no hem.
// Layered ends (kLayeredBand) read rootNoise kLayeredNoiseShift away.
constexpr float kLayeredNoiseShift = 19.7f;
// Hair a stroke's hair ends may grow this share past the strokes' length around it: it ends
// where the remaining length runs out (its path beside the stroke is a little longer).
constexpr double kAroundSlack = 0.1;
// The fade round the lower hairline (nape_line.hpp) reads rootNoise at kFadeNoiseScale times the
// root's coordinates (1 mm cells: neighbouring strands differ, mirror twins agree), shifted.
constexpr float kFadeNoiseScale = 5.f, kFadeNoiseShift = 29.3f;
constexpr float kHemBand = 0.12f, kHemNoiseShift = 13.1f, kHemKeeps = 0.5f, kHemGoverned = 0.5f;

// Between the body's distance, read at one point, and the distance read later that lower bound
// stands in for (trilinear interpolation is not exactly 1-Lipschitz): world units (1 mm).
constexpr float kBodySlack = 0.01f;
// A slide pushes the step's end this share of the margin past it (HeadDistance::pushOut's
// overshoot), so one or two moves get it out.
constexpr float kBodyOvershoot = 0.1f;

// Grows the strands of roots [b, e) into buf from offset `used` on (buf grown ahead of each
// strand, never zero-filled), writing each strand's end (in points of buf) to ends[r - b].
// False when buf passes maxPoints points.
struct GrowRange {
  const PaddedSampler& s;
  const HeadDistance* head;
  float margin, minSlide, l, minMag2;
  double maxLen;
  int maxSegments;
  const std::vector<Eigen::Vector3f>& roots;
  const CurveReach* reach;   // null: the paper's stopping rules only
  const HeadDistance* body;  // the body's own mesh (bust on), or null
  bool headBelow;            // bust on: the head mesh is the body below kHeadBodyBelowY
  bool shape;                // the shape rules (hair_fall.hpp ShapeRules): their steps below
  ShapeGrowth shaped;
  const float* lengthCap;  // per root (null: none)
  bool hems;               // with the shape rules, a stroke sets a hem (setsHem)
  uint8_t* flags;          // per root (Strands::flags), or null
  bool faceClear;          // with the shape rules, ShapeRules::faceClear

  // Slides the step from x to n (which ends within the margin of `mesh`) over the body
  // (BodyCollider): n and segLen become the slid step's end and length. prev: the strand's last
  // direction (unit; the step's own on the first step). False only when no direction along the
  // surface is left (nothing to go on with).
  bool slideOverBody(const HeadDistance& mesh, const float x[3], const float prev[3], float n[3],
                     double& segLen) const {
    float nrm[3];
    mesh.outward(n, nrm);  // unit: the distance gradient, or away from the mesh centre
    float st[3] = {n[0] - x[0], n[1] - x[1], n[2] - x[2]};
    const float sn = st[0] * nrm[0] + st[1] * nrm[1] + st[2] * nrm[2];
    if (sn < 0)
      for (int k = 0; k < 3; ++k) st[k] -= sn * nrm[k];
    float len = std::sqrt(st[0] * st[0] + st[1] * st[1] + st[2] * st[2]);
    if (!(len >= minSlide * segLen)) {
      // too short to move on (hair falling onto the top of a shoulder): the tangential part of
      // gravity plus the strand's previous direction
      float t[3] = {prev[0], prev[1] - 1.0f, prev[2]};
      float tn = t[0] * nrm[0] + t[1] * nrm[1] + t[2] * nrm[2];
      for (int k = 0; k < 3; ++k) st[k] = t[k] - tn * nrm[k];
      len = std::sqrt(st[0] * st[0] + st[1] * st[1] + st[2] * st[2]);
      if (!(len > 1e-2f)) {
        // straight down onto a flat top: horizontally away from the body's centre
        const Eigen::Vector3f& c = mesh.centre();
        t[0] = n[0] - c.x();
        t[1] = 0;
        t[2] = n[2] - c.z();
        tn = t[0] * nrm[0] + t[1] * nrm[1] + t[2] * nrm[2];
        for (int k = 0; k < 3; ++k) st[k] = t[k] - tn * nrm[k];
        len = std::sqrt(st[0] * st[0] + st[1] * st[1] + st[2] * st[2]);
        if (!(len > 1e-6f)) return false;
      }
    }
    // the length the field asked for, then out to the margin
    const float scale = float(segLen) / len;
    for (int k = 0; k < 3; ++k) n[k] = x[k] + scale * st[k];
    mesh.pushOut(n, margin, kBodyOvershoot * margin);
    segLen = std::sqrt(double(n[0] - x[0]) * (n[0] - x[0]) + double(n[1] - x[1]) * (n[1] - x[1]) +
                       double(n[2] - x[2]) * (n[2] - x[2]));
    return true;
  }

  // Whether a step from (x, y, z) to (nx, ny, nz) follows a curve over the face.
  bool followsOverFace(float x, float y, float z, float nx, float ny, float nz) const {
    if (!reach) return false;
    float d[3] = {nx - x, ny - y, nz - z};
    const float n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(n > 0)) return false;
    for (float& e : d) e /= n;
    return reachOverFace(*reach, nx, ny, nz, d);
  }

  bool operator()(size_t b, size_t e, PointBuffer& buf, size_t& used, uint32_t* ends,
                  size_t maxPoints) const {
    const size_t perStrand = 3 * (size_t(maxSegments) + 1);
    const auto field = [this](const float q[3], float out[3]) {  // seamCover's sample
      if (!s.inside(q[0], q[1], q[2])) return false;
      const F4 v = s.at(q[0], q[1], q[2]);
      for (int k = 0; k < 3; ++k) out[k] = v[k];
      return true;
    };
    for (size_t r = b; r < e; ++r) {
      if (buf.size() < used + perStrand)  // doubling, never past every strand at its max
        buf.resize(std::max(std::min(buf.size() * 2, (e - b) * perStrand), used + perStrand) +
                   3 * 4096);
      float* dst = buf.data() + used;
      float x = roots[r].x(), y = roots[r].y(), z = roots[r].z();
      *dst++ = x;
      *dst++ = y;
      *dst++ = z;
      double length = 0;
      double arc = 0;  // the path's length (length is the field's steps')
      // With the curves' reach: a strand rooted where a curve's hair still has length ends
      // where the remaining length runs out; one rooted past a curve's end (on the scalp beyond
      // a stroke that ends there) is short near it and longer away from it.
      double strandMax = maxLen;
      bool endsWithCurve = false;
      // the length of hair no stroke ends: the maximum, or with the shape rules the length of
      // the strokes around (capped by the maximum)
      float around = float(maxLen);
      if (reach && shape) {
        const float at[3] = {x, y, z};
        around = lengthAround(reach->strokes, at, float(maxLen));
      }
      float remainingAtRoot = 0;
      if (reach && s.inside(x, y, z)) {
        const float r0 = reachRemaining(*reach, x, y, z, around);
        remainingAtRoot = r0;
        if (r0 > 0) {
          endsWithCurve = true;
          // (shape) the strokes around bound its length; a fringe's hair, its stroke (the
          // strokes around do not count a fringe, kOwnReach)
          if (shape) {
            const float* const arrays[2] = {reach->fringeShare.data(),
                                            reach->fringeRemaining.data()};
            float fringe[2];
            interpolateScalars(reach->grid, arrays, 2, x, y, z, fringe);
            strandMax = around + fringe[0] * (std::min(fringe[1], float(maxLen)) - around);
          }
        } else {
          const float f = interpolateScalar(reach->grid, reach->far.data(), x, y, z);
          const double farLength = shape ? double(around) : maxLen;
          strandMax = std::min(maxLen, double(f) * farLength + double(1 - f) * kPastEndLength);
        }
      }
      if (lengthCap) strandMax = std::min(strandMax, double(lengthCap[r]));
      // hair that hangs beside strokes drawn down to a hem, and that no stroke governs (its
      // hair ends where the stroke does), stops there
      float hem = -std::numeric_limits<float>::infinity();
      if (hems && s.inside(x, y, z) &&
          interpolateScalar(reach->grid, reach->governed.data(), x, y, z) < kHemGoverned) {
        const float at[3] = {x, y, z};
        hem = hemAround(reach->strokes, at);
        if (std::isfinite(hem))  // the band's noise only where there is a hem
          hem += kHemBand * rootNoise(std::abs(x - shaped.centre[0]) + kHemNoiseShift, y, z);
      }
      bool laying = shape && head, hanging = false, overEar = false;
      // short hair hugs the head (kHugLength, each strand's threshold seeded by where its root
      // is, mirror-symmetrically and smoothly: rootNoise, so Mirror's hair is the same on both
      // sides though mirrored roots are a fraction of a millimetre apart)
      bool hugs = false;
      if (laying) {
        const double expected =
            endsWithCurve ? std::min(strandMax, double(remainingAtRoot)) : strandMax;
        hugs = expected <
               kHugLength *
                   (1 + kHugJitter * (2 * rootNoise(std::abs(x - shaped.centre[0]), y, z) - 1));
      }
      if (flags) flags[r] = hugs ? kLiesOnHead : 0;
      // with finished edges, hair that ends at its strokes' line (their length, the remaining
      // length, a hem) grows on past it by half the end spread detail cuts back
      // (ShapeRules::lineOvershoot), so its ends spread round the line instead of above it
      const double overshoot =
          shape && !hugs ? std::min(double(shaped.lineOvershoot), 0.5 * kEndSpreadShare * strandMax)
                         : 0.0;
      // short hair whose nearest stroke never leaves the head by kDrawnLift lies on the head
      // wherever that stroke governs it (ShapeGrowth::layOnHead's liesOn)
      const bool liesOn =
          hugs && reach && s.inside(x, y, z) && !reach->strokeLift.empty() &&
          interpolateScalar(reach->grid, reach->strokeLift.data(), x, y, z) < kDrawnLift;
      // how far past the scalp's edge this strand lies on (kTaperPast* scaled, seeded by
      // where its root is as the hug threshold is, from other noise): a nape and sides that end
      // in uneven tufts, not on one line
      const float taper =
          hugs
              ? 1 + kTaperJitter *
                        (2 * rootNoise(std::abs(x - shaped.centre[0]) + kTaperNoiseShift, y, z) - 1)
              : 1.f;
      // short hair's share of the band round the lower hairline where it ends (kFadeAbove ..
      // kFadeBelow; -1: no fade), from rootNoise read finer and kFadeNoiseShift away, so
      // neighbouring strands end at different heights: the nape thins out to the skin
      const float fade =
          hugs && shaped.napeLine && !shaped.napeLine->empty()
              ? rootNoise(kFadeNoiseScale * std::abs(x - shaped.centre[0]) + kFadeNoiseShift,
                          kFadeNoiseScale * y, kFadeNoiseScale * z)
              : -1.f;
      // short hair a stroke's hair ends stops from kLayeredPast past that end to kLayeredBand
      // before it (the remaining length it stops at): a layered cut's ends, spread round the
      // line where the strokes end
      const float layeredEnd =
          hugs && endsWithCurve
              ? std::min(kLayeredBand, kLayeredShare * remainingAtRoot) *
                        rootNoise(std::abs(x - shaped.centre[0]) + kLayeredNoiseShift, y, z) -
                    kLayeredPast
              : 0.f;
      // and is never shorter than the hair rooted just past that end (kPastEndLength): no
      // stubs on the scalp just above the strokes' ends
      const double shortest = hugs && endsWithCurve ? std::min(kPastEndLength, strandMax) : 0.0;
      float layDist = 0, layNormal[3] = {0, 1, 0};
      double pastEdge = 0;  // the length laid past the scalp's edge (Lay::PastEdge)
      // a curve's own Volume at the root (weight, value): the strand's lift is that curve's
      float own[2] = {0.f, 0.f};
      if (shape && reach && !reach->ownVolume.empty() && s.inside(x, y, z)) {
        const float* const arrays[2] = {reach->ownVolumeWeight.data(), reach->ownVolume.data()};
        interpolateScalars(reach->grid, arrays, 2, x, y, z, own);
      }
      // the point before (x, y, z), for the strand's direction when it slides over the body
      float px = x, py = y, pz = z;
      // a lower bound of the body's distance at (x, y, z) (the distance is 1-Lipschitz): the
      // body is read only where a step could end within the margin (and kBodySlack)
      float bodyClear = -1;
      // at a seam across the head, the hair first lies along it (kSeam*: a whorl, not a parting)
      float coverDir[3] = {0, 0, 0};
      const float cover = laying ? seamCover(*head, field, shaped.centre, x, y, z, coverDir) : 0.f;
      if (s.inside(x, y, z)) {
        for (int seg = 0; seg < maxSegments; ++seg) {
          F4 v = s.at(x, y, z);
          if (cover > 0 && length < kSeamCoverLength) {
            const float f = float(length) / kSeamCoverLength;
            const float w = cover * (1 - f * f);
            const float m = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            const float keep = m > 0 ? (1 - w) / m : 0.f;
            F4 d{keep * v[0] + w * coverDir[0], keep * v[1] + w * coverDir[1],
                 keep * v[2] + w * coverDir[2], 0.f};
            const float dl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            // the field's strength (at least the growth's least), along the blend
            const float k = dl > 0 ? std::max(m, 1.01f * std::sqrt(minMag2)) / dl : 0.f;
            v = d * k;
          }
          const float m2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
          if (!(m2 >= minMag2)) break;  // weak field (or NaN)
          float nx = x + l * v[0], ny = y + l * v[1], nz = z + l * v[2];
          double segLen = double(l) * std::sqrt(double(m2));
          // with the shape rules: how far a stroke governs the hair here (1: its own), how far
          // the nearest stroke is, and how far that stroke is off the head
          float here[3] = {0.f, float(kReachFar), 0.f};
          if (shape && reach) {
            const float* const arrays[3] = {reach->governed.data(), reach->nearest.data(),
                                            reach->lift.data()};
            interpolateScalars(reach->grid, arrays, 3, x, y, z, here);
          }
          const float gov = here[0];
          const float combed = hanging || laying
                                   ? shaped.fallOrComb(hanging, overEar, x, y, z, here, nx, ny, nz)
                                   : 0.f;
          if (shape) {
            // with face clear, hair a stroke governs parts round the face too unless it follows
            // a stroke over the face (reachOverFace: near its stretch off the scalp, along it)
            float g = std::max(gov, combed);
            if (faceClear && g >= 0.5f && inFaceColumn(shaped.centre, nx, ny, nz) &&
                !followsOverFace(x, y, z, nx, ny, nz))
              g = 0.f;
            shaped.partRoundFace(x, y, z, g, nx, ny, nz);
          }
          // The body: the strand slides over it (never stops there).
          auto slide = [&](const HeadDistance& mesh) {
            const float at[3] = {x, y, z};
            float prev[3] = {x - px, y - py, z - pz};
            if (seg == 0)
              for (int k = 0; k < 3; ++k) prev[k] = v[k];
            const float pl = std::sqrt(prev[0] * prev[0] + prev[1] * prev[1] + prev[2] * prev[2]);
            for (float& e : prev) e = pl > 0 ? e / pl : 0.f;
            float q[3] = {nx, ny, nz};
            if (!slideOverBody(mesh, at, prev, q, segLen)) return false;
            nx = q[0];
            ny = q[1];
            nz = q[2];
            return true;
          };
          if (head) {
            float grad[3];
            if (head->distance(nx, ny, nz, grad) < margin) {
              if (headBelow && ny < kHeadBodyBelowY) {
                if (!slide(*head)) break;
              } else {
                // not over the face, unless a curve takes the hair there; with the shape rules
                // hair that hangs slides down the neck and over the ears as it does over the
                // scalp (only the face's column stops it)
                const bool slidesOn = shape && hanging && !inFaceColumn(shaped.centre, nx, ny, nz);
                if (seg > 0 && !head->scalpNear(nx, ny, nz) && !slidesOn &&
                    !followsOverFace(x, y, z, nx, ny, nz))
                  break;
                // Slide: drop the inward part of the step, then stand off at the margin.
                float st[3] = {nx - x, ny - y, nz - z};
                const float g2 = grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2];
                const float sn = (st[0] * grad[0] + st[1] * grad[1] + st[2] * grad[2]);
                if (g2 > 1e-6f && sn < 0)
                  for (int k = 0; k < 3; ++k) st[k] -= sn / g2 * grad[k];
                float q[3] = {x + st[0], y + st[1], z + st[2]};
                head->pushOut(q, margin);
                const double moved =
                    std::sqrt(double(q[0] - x) * (q[0] - x) + double(q[1] - y) * (q[1] - y) +
                              double(q[2] - z) * (q[2] - z));
                if (!(moved >= minSlide * segLen)) break;  // the field points into the head
                nx = q[0];
                ny = q[1];
                nz = q[2];
                segLen = moved;
              }
            }
          }
          if (laying) {
            const float at[3] = {x, y, z};
            float q[3] = {nx, ny, nz};
            const ShapeGrowth::Lay lay =
                shaped.layOnHead(at, q, segLen, length + segLen, gov, here[2], layDist, layNormal,
                                 own[0], own[1], hugs, liesOn);
            // hair no stroke governs or combs ends where it would lie on the forehead's skin (in
            // the face's column, its foot off the scalp): no strays lying across the forehead
            // along the hairline (fresh eyes round 16)
            if (seg > 0 && std::max(gov, combed) < 0.5f && inFaceColumn(shaped.centre, x, y, z) &&
                !head->scalpNear(x - layDist * layNormal[0], y - layDist * layNormal[1],
                                 z - layDist * layNormal[2]))
              break;
            // short hair laid on past the scalp's edge ends kTaperPast* on; over an ear, hair a
            // stroke combs goes round the ear with it instead
            ShapeGrowth::Lay now = lay;
            if (now == ShapeGrowth::Lay::PastEdge) {
              const bool nape = shaped.atNape(x, z);
              if (!nape && combed > 0) {
                now = ShapeGrowth::Lay::Over;
              } else {
                pastEdge += segLen;
                if (pastEdge > taper * (nape ? kTaperPastNape : kTaperPastEar)) break;
              }
            }
            laying = now == ShapeGrowth::Lay::Laid || now == ShapeGrowth::Lay::PastEdge;
            hanging = now == ShapeGrowth::Lay::Hangs || now == ShapeGrowth::Lay::Over;
            overEar = now == ShapeGrowth::Lay::Over;
            nx = q[0];
            ny = q[1];
            nz = q[2];
          }
          if (shape) {
            if (head && head->distance(nx, ny, nz) < margin) {
              float q[3] = {nx, ny, nz};
              head->pushOut(q, margin);
              nx = q[0];
              ny = q[1];
              nz = q[2];
            }
          }
          if (body) {
            const float step = float(segLen);
            if (bodyClear - step < margin + kBodySlack) {
              bodyClear = body->distanceAtLeast(nx, ny, nz);
              if (bodyClear < margin) {
                if (!slide(*body)) break;
                bodyClear = 0;  // read again at the next step
              }
            } else {
              bodyClear -= step;
            }
          }
          if (!s.inside(nx, ny, nz)) break;  // leaving the bounding volume
          // Max length bounds the path as drawn: the rules above bend the step (combing,
          // parting round the face, standing off the head), so it can be longer than segLen
          const double pathStep = std::sqrt(double(nx - x) * (nx - x) + double(ny - y) * (ny - y) +
                                            double(nz - z) * (nz - z));
          if (arc + pathStep > maxLen) break;
          // hair a stroke's hair ends: the remaining length ends it; the strokes' length, with
          // kAroundSlack for a path a little longer than the stroke's (laid on the head), only
          // bounds it
          if (length + segLen > (endsWithCurve && shape
                                     ? std::min(maxLen, strandMax * (1 + kAroundSlack) + overshoot)
                                     : strandMax)) {
            // hair whose length is its strokes' ends at their line: no length jitter
            if (flags && endsWithCurve && shape) flags[r] |= kCutAtLine;
            break;
          }
          // short hair ends in a band round the lower hairline (nape_line.hpp): a faded nape
          if (fade >= 0 && length + segLen > kFadeShortest && ny - y < -kFadeDown * segLen &&
              ny < shaped.napeTop &&
              ny < napeLineAt(*shaped.napeLine, shaped.centre, nx, nz) + kFadeAbove -
                       fade * (kFadeAbove + kFadeBelow)) {
            if (flags) flags[r] |= kCutAtLine;
            break;
          }
          if ((ny < hem - float(overshoot) && ny < y && length + segLen > kHemKeeps * strandMax) ||
              (endsWithCurve && length + segLen > shortest &&
               reachRemaining(*reach, nx, ny, nz, around) < layeredEnd - float(overshoot))) {
            if (flags) flags[r] |= kCutAtLine;
            break;
          }
          length += segLen;
          arc += pathStep;
          px = x;
          py = y;
          pz = z;
          x = nx;
          y = ny;
          z = nz;
          *dst++ = x;
          *dst++ = y;
          *dst++ = z;
        }
      }
      used = size_t(dst - buf.data());
      if (used / 3 > maxPoints) return false;
      ends[r - b] = uint32_t(used / 3);
    }
    return true;
  }
};

}  // namespace

Status growStrands(const Grid& g, const std::vector<float>& field,
                   const std::vector<Eigen::Vector3f>& roots, const GrowthParams& prm, Strands& out,
                   size_t maxPoints, const HeadDistance* head, const CurveReach* reach,
                   const BodyCollider& body, const ShapeRules* shape, const float* lengthCap) {
  // The point buffer keeps its capacity from the last call and is not zero-filled (see
  // UninitAllocator), so a repeated growth neither reallocates nor refills it.
  out.points.clear();
  out.strandStart.assign(1, 0);
  out.flags.clear();
  if (!g.valid()) return Status::Error(StatusCode::NotReady, "grow: no grid");
  if (field.size() != size_t(g.size()) * 3)
    return Status::Error(StatusCode::NotReady, "grow: no field for this grid (solve first)");
  if (!(prm.stepFraction > 0) || !std::isfinite(prm.stepFraction))
    return Status::Error(StatusCode::InvalidInput, "grow: stepFraction must be > 0");
  if (!(prm.minMagnitude >= 0) || !std::isfinite(prm.minMagnitude))
    return Status::Error(StatusCode::InvalidInput, "grow: minMagnitude must be >= 0");
  if (!(prm.maxLength >= 0) || std::isnan(prm.maxLength))
    return Status::Error(StatusCode::InvalidInput, "grow: maxLength must be >= 0");
  if (prm.maxSegments < 0)
    return Status::Error(StatusCode::InvalidInput, "grow: maxSegments must be >= 0");
  if (!(prm.margin >= 0) || !std::isfinite(prm.margin) || !(prm.minSlide >= 0) ||
      !std::isfinite(prm.minSlide))
    return Status::Error(StatusCode::InvalidInput, "grow: margin and minSlide must be >= 0");
  if (head && !head->built()) head = nullptr;
  const float margin = float(prm.margin), minSlide = float(prm.minSlide);
  const PaddedSampler s(g, field);
  GrowRange grow{s,
                 head,
                 margin,
                 minSlide,
                 float(prm.stepFraction * g.step),
                 float(prm.minMagnitude * prm.minMagnitude),
                 prm.maxLength,
                 prm.maxSegments,
                 roots,
                 reach && !reach->empty() ? reach : nullptr,
                 body.body && body.body->built() ? body.body : nullptr,
                 body.headBelow,
                 shape && shape->on,
                 ShapeGrowth{head,
                             reach && !reach->empty() ? reach : nullptr,
                             margin,
                             shape ? std::clamp(shape->volume, 0.f, 0.3f) : 0.f,
                             {shape ? shape->centre[0] : 0.f, shape ? shape->centre[1] : 0.f,
                              shape ? shape->centre[2] : 0.f}},
                 lengthCap,
                 shape && shape->on && reach && !reach->empty() &&
                     std::any_of(reach->strokes.begin(), reach->strokes.end(), setsHem),
                 nullptr,
                 shape && shape->on && shape->faceClear};
  grow.shaped.napeLine = shape ? shape->napeLine : nullptr;
  if (grow.shaped.napeLine) grow.shaped.napeTop = napeLineTop(*grow.shaped.napeLine) + kFadeAbove;
  grow.shaped.lineOvershoot = shape ? std::max(shape->lineOvershoot, 0.f) : 0.f;
  if (shape && shape->on) {
    out.flags.assign(roots.size(), 0);
    grow.flags = out.flags.data();
  }
  out.strandStart.resize(roots.size() + 1);
  const size_t n = roots.size();
  const int threads = parallel::threadCount();
  // Fewer than ~256 strands a chunk is not worth a thread.
  const int chunks = threads > 1 ? int(std::min<size_t>(size_t(threads) * 4, n / 256)) : 1;
  if (chunks <= 1) {
    out.points.resize(out.points.capacity());
    size_t used = 0;
    if (!grow(0, n, out.points, used, out.strandStart.data() + 1, maxPoints)) {
      out.points.clear();
      out.strandStart.assign(1, 0);
      out.flags.clear();
      return Status::Error(StatusCode::OverMemoryCap, "grow: too many strand points");
    }
    out.points.resize(used);
    return Status::Ok();
  }
  // Threads: each chunk of roots grows into its own buffer (strand ends relative to it), then
  // the chunks are joined in root order: the same bytes as one thread.
  std::vector<PointBuffer> bufs;
  bufs.resize(size_t(chunks));
  std::vector<size_t> usedBy(size_t(chunks), 0);
  std::vector<char> fits(size_t(chunks), 1);
  parallel::forChunks(n, chunks, [&](int c, size_t b, size_t e) {
    fits[size_t(c)] =
        grow(b, e, bufs[size_t(c)], usedBy[size_t(c)], out.strandStart.data() + 1 + b, maxPoints);
  });
  size_t total = 0;
  bool ok = true;
  for (int c = 0; c < chunks; ++c) {
    ok = ok && fits[size_t(c)];
    total += usedBy[size_t(c)];
  }
  if (!ok || total / 3 > maxPoints) {
    out.points.clear();
    out.strandStart.assign(1, 0);
    out.flags.clear();
    return Status::Error(StatusCode::OverMemoryCap, "grow: too many strand points");
  }
  out.points.resize(total);
  size_t at = 0;
  for (int c = 0; c < chunks; ++c) {
    const size_t b = n * size_t(c) / size_t(chunks), e = n * size_t(c + 1) / size_t(chunks);
    for (size_t r = b; r < e; ++r) out.strandStart[r + 1] += uint32_t(at / 3);
    std::copy(bufs[size_t(c)].begin(), bufs[size_t(c)].begin() + std::ptrdiff_t(usedBy[size_t(c)]),
              out.points.begin() + std::ptrdiff_t(at));
    at += usedBy[size_t(c)];
    bufs[size_t(c)] = PointBuffer();  // free as we go
  }
  return Status::Ok();
}

}  // namespace hairsketch
