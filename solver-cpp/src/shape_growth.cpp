// The shape rules' steps in growth (shape_growth.hpp).
#include "shape_growth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hairsketch {

float ShapeGrowth::distanceOff(const float p[3], float nrm[3], float hint) const {
  const float band = head->band(), walk = 0.5f * band;
  // hint (the last step's distance) past the band: jump most of the way in at once; a jump
  // that lands deeper than the band inside the head walks again from p
  for (int attempt = hint > band ? 0 : 1; attempt < 2; ++attempt) {
    float q[3] = {p[0], p[1], p[2]};
    float walked = 0;
    if (attempt == 0) {
      float dir[3];
      head->outward(q, dir);
      walked = hint - walk;
      for (int k = 0; k < 3; ++k) q[k] -= walked * dir[k];
    }
    for (; walked <= kLayReach + 0.3f; walked += walk) {
      float g[3];
      const float d = head->distance(q[0], q[1], q[2], g);
      const float gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      if (d < 0.9f * band && gn > 0.5f) {
        for (int k = 0; k < 3; ++k) nrm[k] = g[k] / gn;
        return walked + d;
      }
      if (d < 0) break;  // deep inside: the jump went too far
      float dir[3];
      head->outward(q, dir);
      for (int k = 0; k < 3; ++k) q[k] -= walk * dir[k];
    }
  }
  return std::numeric_limits<float>::quiet_NaN();
}

ShapeGrowth::Lay ShapeGrowth::layOnHead(const float x[3], float n[3], double& segLen, double arc,
                                        float gov, float lift, float& dist, float nrm[3],
                                        float ownWeight, float ownVolume, bool hugs,
                                        bool liesOn) const {
  if (liesOn) gov = 0;  // laid as hair no stroke governs is
  const float keep = 1.f - gov;
  bool held = true, past = false;
  const float dx = distanceOff(x, nrm, dist);
  if (std::isnan(dx)) return Lay::Free;
  {
    dist = dx;
    // short hair lies on under the skull's widest part and down the nape (behind the head's
    // axis more than beside it), and on past the scalp's edge (PastEdge)
    const bool onScalp =
        head->scalpNear(x[0] - dx * nrm[0], x[1] - dx * nrm[1], x[2] - dx * nrm[2]);
    if (nrm[1] < kSupportNormalY && !hugs) {
      if (keep > 0.5f) return Lay::Hangs;
      held = false;
    } else if (!hugs && !onScalp && !inFaceColumn(centre, x[0], x[1], x[2])) {
      if (keep > 0.5f) return Lay::Over;
      held = false;
    }
    // short hair lies on past the scalp's edge, at the nape and over an ear (growth ends it
    // kTaperPastNape or kTaperPastEar on)
    past = hugs && !onScalp && keep > 0.5f && !inFaceColumn(centre, x[0], x[1], x[2]);
  }
  // the standoff: the volume reached over the first length, and hair that has come farther
  // over the head lying on top of the hair rooted where it passes (kLayerSlope)
  float vol = volume + ownWeight * (ownVolume - volume);
  // short hair at the nape closes in to the head where the skull turns in under its widest part
  // (the surface facing down by kNapeCloseNormal: all of its Volume and layering gone) and past
  // the hairline: a tapered nape, not a shelf
  const float closes = hugs && atNape(x[0], x[2])
                           ? (past ? 1.f : std::clamp(-nrm[1] / kNapeCloseNormal, 0.f, 1.f))
                           : 0.f;
  if (hugs) {  // short hair: lifted on top, close at the sides and the nape (kHugVolumeLow)
    const float t =
        std::clamp((nrm[1] - kHugVolumeLow) / (kHugVolumeHigh - kHugVolumeLow), 0.f, 1.f);
    const float kept = std::min(vol, kHugVolumeKept);
    vol = kept + (vol - kept) * t * t * (3 - 2 * t);
  }
  const float layer = std::min(kLayerMax, kLayerSlope * float(arc));
  const float want = margin + (1 - closes) * (std::min(vol, kVolumeRise * float(arc)) + layer);
  const float cap = margin + kLiftSlack + std::max(lift, ownWeight * (want - margin));
  float st[3] = {n[0] - x[0], n[1] - x[1], n[2] - x[2]};
  const float dn = dist + st[0] * nrm[0] + st[1] * nrm[1] + st[2] * nrm[2];
  if (dn > std::max(want, cap) + kLayReach) return Lay::Free;
  const float step = float(segLen);
  // no stroke: towards the standoff while the head holds the hair; a stroke: no farther off
  // than the stroke
  const float toWant = held ? std::clamp(want - dn, -step, step) : 0.f;
  const float toCap = std::clamp(cap - dn, -step, 0.f);
  // a curve's own Volume lifts the hair it governs too (up to its standoff)
  const float toOwn = held ? ownWeight * std::clamp(want - dn, 0.f, step) : 0.f;
  const float delta = keep * toWant + gov * (toCap + toOwn);
  for (int k = 0; k < 3; ++k) st[k] += delta * nrm[k];
  const float len = std::sqrt(st[0] * st[0] + st[1] * st[1] + st[2] * st[2]);
  const Lay laid = past ? Lay::PastEdge : Lay::Laid;
  if (!(len > 1e-3f * step)) return laid;
  for (int k = 0; k < 3; ++k) {
    st[k] *= step / len;
    n[k] = x[k] + st[k];
  }
  dist += st[0] * nrm[0] + st[1] * nrm[1] + st[2] * nrm[2];
  return laid;
}

void ShapeGrowth::partRoundFace(float x, float y, float z, float gov, float& nx, float& ny,
                                float& nz) const {
  // the column reaches up by the Volume: hair lifted that far off the front hairline parts
  // before it comes down over the forehead (else it ended on the forehead's skin as a short
  // blunt fringe nobody drew: fresh eyes' tucked behind the ears at Volume 1.2 cm)
  if (gov >= 0.5f || !inFaceColumn(centre, nx, ny - volume, nz)) return;  // gov: governed or combed
  const float d[3] = {nx - x, ny - y, nz - z};
  const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const float side = nx >= centre[0] ? 1.f : -1.f;
  const float fall = std::min(d[1], 0.f);
  // aside, falling, and back towards the ear (kFaceBack): the hair combs aside round the temple
  // instead of falling across the eye's outer corner
  float t[3] = {side * std::max(len, std::abs(fall)), fall, std::min(d[2], 0.f) - kFaceBack * len};
  const float m = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  nx = x + t[0] * len / m;
  ny = y + t[1] * len / m;
  nz = z + t[2] * len / m;
}

float ShapeGrowth::fallOrComb(bool hangs, bool overEar, float x, float y, float z,
                              const float here[3], float& nx, float& ny, float& nz) const {
  const float w = 1.f - here[0], near = here[1], lift = here[2];
  float c = 0.f, t[3] = {0, -1, 0};
  if (reach) {
    const float far = overEar ? kCombFarOverEar : kCombFar;
    if (near < far) {
      for (int e = 0; e < 3; ++e)
        t[e] = interpolateScalar(reach->grid, reach->tangent.data(), x, y, z, 3, e);
      const float tn = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
      const bool onHead = lift < kCombOnHead;
      if (tn > 1e-3f && (t[1] < -kCombFalls * tn || onHead)) {
        c = std::clamp((far - near) / (far - kCombNear), 0.f, 1.f);
        for (float& e : t) e /= tn;
        // over an ear: head for a stroke behind it (the face is +z) as well as along it, until
        // the hair is beside it (kCombBeside): hair that kept heading for the stroke would gather
        // on its line as a rope
        const float toward =
            overEar ? 2 * std::clamp((near - kCombBeside) / (kCombNear - kCombBeside), 0.f, 1.f)
                    : 0.f;
        float to[3] = {0, 0, 0};
        if (toward > 0)  // read only where it is used: this runs every step of combed hair
          for (int e = 0; e < 3; ++e)
            to[e] = interpolateScalar(reach->grid, reach->toCurve.data(), x, y, z, 3, e);
        if (toward > 0 && to[2] < 0) {
          for (int e = 0; e < 3; ++e) t[e] += toward * to[e] / near;
          const float m = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
          for (float& e : t) e /= m > 1e-6f ? m : 1.f;
        }
      }
    }
  }
  // hanging: down, spread a little away from the head's vertical axis (hair falling from the
  // skull's widest part fans out rather than falling in lines)
  float h[2] = {x - centre[0], z - centre[2]};
  const float hn = std::sqrt(h[0] * h[0] + h[1] * h[1]);
  const float sp = hn > 1e-6f ? kHangSpread / hn : 0.f;
  const float to[3] = {c * t[0] + (1 - c) * sp * h[0], (1 - c) * -1.f + c * t[1],
                       c * t[2] + (1 - c) * sp * h[1]};
  const float k = hangs ? w : w * c;  // how far the step turns to `to`
  if (!(k > 0)) return c;
  float d[3] = {nx - x, ny - y, nz - z};
  const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const float tl = std::sqrt(to[0] * to[0] + to[1] * to[1] + to[2] * to[2]);
  if (!(tl > 1e-6f)) return c;
  for (int e = 0; e < 3; ++e) d[e] = (1 - k) * d[e] + k * len * to[e] / tl;
  const float m = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(m > 1e-6f)) return c;
  nx = x + d[0] * len / m;
  ny = y + d[1] * len / m;
  nz = z + d[2] * len / m;
  return c;
}

}  // namespace hairsketch
