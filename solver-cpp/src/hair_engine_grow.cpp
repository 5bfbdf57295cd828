// HairEngine::grow: the roots sampled (and cached), strands grown along the solved field, the
// tails laid, the strands kept outside head and body.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "curve_kinds.hpp"
#include "elapsed.hpp"
#include "hair_engine.hpp"
#include "memory_budget.hpp"
#include "nape_line.hpp"
#include "soft_hairline.hpp"

namespace hairsketch {

Status HairEngine::grow(const RootParams& rp, const GrowthParams& gp) {
  if (!hasGrid_) return Status::Error(StatusCode::NotReady, "grow before setGrid");
  if (!fieldValid_) return Status::Error(StatusCode::NotReady, "grow: curves changed, solve first");
  if (rp.maxStrands < 0) return Status::Error(StatusCode::InvalidInput, "maxStrands < 0");
  const auto t0 = Clock::now();
  // The full root set is cached (sampling casts a ray per root); a cap takes an even stride of
  // it, so previews (capped) and full growth share one sampling.
  const bool same = rootsValid_ && rootKey_.thetaStepDeg == rp.thetaStepDeg &&
                    rootKey_.phiStepDeg == rp.phiStepDeg && rootKey_.jitter == rp.jitter &&
                    rootKey_.seed == rp.seed;
  if (!same) {
    rootsValid_ = false;
    RootParams all = rp;
    all.maxStrands = 0;
    Status s = scalp_.sample(all, roots_, &rootIds_);
    if (!s.ok()) return s;
    rootKey_ = all;
    rootsValid_ = true;
  }
  // the roots grown: all, less lone ones (finished edges: judged on the full set, so a cap
  // keeps its count), then an even stride of those under a cap
  const size_t total = roots_.size();
  if (!same || keptFinish_ != finish_ || keptHairline_ != hairline_ ||
      kept_.empty() != (total == 0)) {
    kept_.resize(total);
    for (size_t k = 0; k < total; ++k) kept_[k] = uint32_t(k);
    if (finish_ && total > 0) {
      // the sampling's spacing: a θ step at the roots' mean distance from the centre
      double r = 0;
      for (const Eigen::Vector3f& p : roots_) r += (p.cast<double>() - centre_).norm();
      const double spacing = r / double(total) * rootKey_.thetaStepDeg * 3.14159265358979 / 180;
      dropLoneRoots(roots_, kept_, float(kLoneReach * spacing));
    }
    rootCap_.clear();
    if (hairline_ && total > 0) {
      // a soft hairline: the roots' distances to the scalp's edge, then which grow what
      const std::vector<float> edge = distanceToEdges(
          roots_, scalpEdges(scalp_.positions(), scalp_.indices(), scalp_.scalpMask()),
          kHairlineWidth);
      std::vector<float> cap;
      softHairline(edge, rootIds_, rootKey_.seed, kept_, cap);
      rootCap_.assign(total, std::numeric_limits<float>::infinity());
      for (size_t k = 0; k < kept_.size(); ++k) rootCap_[kept_[k]] = cap[k];
    }
    keptFinish_ = finish_;
    keptHairline_ = hairline_;
  }
  const std::vector<uint32_t>& kept = kept_;
  const bool capped = rp.maxStrands > 0 && kept.size() > size_t(rp.maxStrands);
  const size_t m = capped ? size_t(rp.maxStrands) : kept.size();
  subsetIndex_.resize(m);
  for (size_t k = 0; k < m; ++k) subsetIndex_[k] = kept[k * kept.size() / m];
  subset_ = m != total;
  if (subset_) {
    subsetRoots_.resize(subsetIndex_.size());
    subsetRootIds_.resize(subsetIndex_.size());
    for (size_t k = 0; k < subsetIndex_.size(); ++k) {
      subsetRoots_[k] = roots_[subsetIndex_[k]];
      subsetRootIds_[k] = rootIds_[subsetIndex_[k]];
    }
  }
  // The strand buffers for every root at maxSegments must fit: the point buffer (12 bytes a
  // point) is grown by doubling up to that bound, so it and its previous copy may both be live.
  const double worstPoints =
      double(roots().size()) * (double(std::max(gp.maxSegments, 0)) + 1) + 3 * 4096;
  const double needs = 2 * 12 * worstPoints + 4 * double(roots().size() + 1);
  const int64_t cap = availableMemoryBytes() + int64_t(strands_.points.capacity() * sizeof(float));
  Status fits = checkMemory("growth (" + std::to_string(roots().size()) + " strands of up to " +
                                std::to_string(gp.maxSegments) + " segments)",
                            needs, cap);
  if (!fits.ok()) {
    strands_ = Strands{};
    strands_.strandStart.assign(1, 0);
    return fits;
  }
  const HeadDistance* head = headDistance_.built() ? &headDistance_ : nullptr;
  const CurveReach* reach = fall_ && !reach_.empty() ? &reach_ : nullptr;
  ShapeRules shape = shape_;
  for (int e = 0; e < 3; ++e) shape.centre[e] = float(centre_[e]);
  if (fall_ && shape.on) {
    if (!napeValid_) {  // the lower hairline, for the fade of short hair there
      napeLine_ = napeLine(scalpEdges(scalp_.positions(), scalp_.indices(), scalp_.scalpMask()),
                           shape.centre);
      napeValid_ = true;
    }
    shape.napeLine = &napeLine_;
    shape.lineOvershoot = finish_ ? 0.5f * kEndSpread : 0.f;
    shape.faceClear = faceClear_;
  }
  growCap_.clear();
  if (!rootCap_.empty()) {
    growCap_.resize(roots().size());
    for (size_t k = 0; k < growCap_.size(); ++k)
      growCap_[k] = rootCap_[subset_ ? subsetIndex_[k] : k];
  }
  Status s = growStrands(grid_, fieldF_, roots(), gp, strands_, size_t(24) << 20, head, reach,
                         head ? bodyCollider() : BodyCollider(), fall_ ? &shape : nullptr,
                         growCap_.empty() ? nullptr : growCap_.data());
  const std::vector<Eigen::Vector3f>& R = roots();
  const size_t n = R.size();
  // a strand's seed key: its index in the full root set (previews take a stride of it)
  std::vector<uint32_t> key(n);
  for (size_t k = 0; k < n; ++k) key[k] = subset_ ? subsetIndex_[k] : uint32_t(k);
  strandTailCurve_.assign(n, -1);
  std::vector<uint8_t> inBun(n, 0);  // laid in a bun's coil
  tieFrames_.clear();
  strandSection_.clear();
  ScalpSections sections;
  if (sections_) {
    sections.build(roots_, centre_.cast<float>(), partings_, ties_);
    strandSection_.resize(n);
    for (size_t st = 0; st < n; ++st) {
      // with finished edges, hair at a parting belongs to the side it is combed to
      const int at =
          finish_ && s.ok()
              ? sections.combedSection(
                    strands_.points.data() + 3 * size_t(strands_.strandStart[st]),
                    strands_.strandStart[st + 1] - strands_.strandStart[st], kCombedReach)
              : sections.section(R[st]);
      strandSection_[st] = uint8_t(std::min(at, 255));
    }
  }
  if (s.ok() && !tails_.empty()) {
    // laid strands keep to the 255 points engines take (detail's cap too)
    // whole-section ties (with sections on): each strand goes to the nearest such tie in its
    // root's section; without sections every tie takes the hair that reaches it
    std::vector<GatheredTail> tails = tails_;
    SectionGather sg;
    bool bySection = false;
    for (GatheredTail& t : tails) {
      t.section = t.section && sections_;
      t.ties = ties_;
      t.roundPlaits = roundPlaits_;
      t.tieVolume = tieVolume_;
      t.compactBun = compactBun_;
      bySection |= t.section;
    }
    if (bySection) {
      std::vector<int> tieSection(tails.size(), -1);
      for (size_t k = 0; k < tails.size(); ++k)
        if (tails[k].section)
          tieSection[k] = sections.section(ties_ ? tails[k].pressed : tails[k].anchor);
      sg.assigned.assign(n, -1);
      for (size_t st = 0; st < n; ++st) {
        const int here = strandSection_[st];
        float best = std::numeric_limits<float>::infinity();
        for (size_t k = 0; k < tails.size(); ++k) {
          if (tieSection[k] != here) continue;
          const float d = (R[st] - tails[k].anchor).squaredNorm();
          if (d < best) {
            best = d;
            sg.assigned[st] = int32_t(k);
          }
        }
      }
      sg.head = head;
      sg.centre = centre_.cast<float>();
      sg.margin = float(gp.margin);
    }
    const TailStats ts =
        gatherTails(tails, R, key, rp.seed, float(gp.stepFraction * grid_.step),
                    std::min<size_t>(size_t(std::max(gp.maxSegments, 1)) + 1, 255), strands_,
                    float(std::min(gp.maxLength, 1e6)), bySection ? &sg : nullptr);
    for (size_t i = 0; i < ts.strands.size(); ++i) {
      strandTailCurve_[ts.strands[i]] = tailCurves_[ts.tail[i]];
      inBun[ts.strands[i]] = tails[ts.tail[i]].shape == TailShape::Bun;
    }
    // where each tie gathers its hair, and how wide that hair is there (its band)
    for (size_t k = 0; k < tails.size() && k < tailCurves_.size(); ++k) {
      const GatheredTail& t = tails[k];
      if (t.spine.empty()) continue;
      tieFrames_.insert(tieFrames_.end(), {float(tailCurves_[k]), t.spine[0].x(), t.spine[0].y(),
                                           t.spine[0].z(), t.axis.x(), t.axis.y(), t.axis.z(),
                                           k < ts.bandRadius.size() ? ts.bandRadius[k] : 0.f});
    }
    // growth kept the rest outside already
    if (head && ts.captured > 0) {
      keepOutsideHead(*head, float(gp.margin), strands_, &ts.strands);
      keepOutsideBody(float(gp.margin), &ts.strands);
    }
  }
  bool anyDetail = false;
  for (const DetailParams& d : detail_) anyDetail |= d.any();
  std::vector<float> endSpread;
  if (finish_) {
    endSpread.assign(n, kEndSpread);
    for (size_t st = 0; st < n; ++st)
      if (strandTailCurve_[st] >= 0) endSpread[st] = 0;
  }
  if (s.ok() && (anyDetail || finish_)) {
    std::vector<uint32_t> groupOf(n, 0);
    bool perCurve = false;
    for (int32_t g : curveGroup_) perCurve |= g != 0;
    if (anyDetail && perCurve && !curvePoints_.empty())
      for (size_t k = 0; k < n; ++k) {
        float best = std::numeric_limits<float>::infinity();
        int32_t curve = -1;
        for (size_t q = 0; q < curvePoints_.size(); ++q) {
          const float d2 = (curvePoints_[q] - R[k]).squaredNorm();
          if (d2 < best) {
            best = d2;
            curve = curvePointCurve_[q];
          }
        }
        if (curve >= 0 && size_t(curve) < curveGroup_.size())
          groupOf[k] = uint32_t(curveGroup_[curve]);
      }
    std::vector<DetailParams> groups =
        detail_.empty() ? std::vector<DetailParams>{DetailParams{}} : detail_;
    if (curlVolume_)
      for (DetailParams& d : groups) {
        d.curl.spread = kCurlSpread;
        if (coilVolume_) d.curl.coil = 1;
      }
    // (ties on) hair a tie lays keeps its length: a tail ends where its stroke ends, with the
    // tie's own uneven ends (gathered_tail.hpp), so its strands take their group's detail without
    // the length jitter (which cut tails up to a tenth short of their strokes' ends) and, with
    // locks, the clumps' tip spread (4 mm of it drew strands out across the band); hair
    // wound into a bun's coil, without flyaways and frizz too (a bun is wound tight and its ends
    // tucked: a new session's 1 % of flyaways stood round it as a wiry grey halo). (curl volume on)
    // hair a tie lays keeps the shape the tie gives it: it curls but does not spread.
    if ((ties_ || curlVolume_) && anyDetail) {
      const size_t own = groups.size();
      std::vector<int64_t> tiedGroup(2 * own, -1);  // [g]: a tail's, [own + g]: a bun's
      for (size_t st = 0; st < n; ++st) {
        if (strandTailCurve_[st] < 0) continue;
        const uint32_t g = groupOf[st];
        if (g >= own) continue;
        const DetailParams& d = groups[g];
        const bool keep = ties_ && (d.lengthJitter > 0 || (locks_ && d.clump.tipSpread > 0));
        const bool bun = ties_ && inBun[st] && (d.flyaway.share > 0 || d.frizz.distance > 0);
        const bool spread = d.curl.spread > 0 && d.curl.radius > 0;
        if (!keep && !bun && !spread) continue;
        const size_t slot = bun ? own + g : g;
        if (tiedGroup[slot] < 0) {
          DetailParams tied = groups[g];
          if (ties_) tied.lengthJitter = 0;
          if (ties_ && locks_) tied.clump.tipSpread = 0;
          tied.curl.spread = 0;
          if (bun) {
            tied.flyaway.share = 0;
            tied.frizz.distance = 0;
          }
          tiedGroup[slot] = int64_t(groups.size());
          groups.push_back(tied);
        }
        groupOf[st] = uint32_t(tiedGroup[slot]);
      }
    }
    // With the shape rules, what growth found of each strand (Strands::flags) excepts it from
    // its group's detail, in its group (its clumps stay whole): hair ended at a line keeps its
    // length, ending over the end spread's band at that line as a cut does (the jitter, up to a
    // tenth of the length, 2.5 cm on a bob, lifted a bob's hem above its strokes' ends); short
    // hair lying on the head has no flyaways (they stood up as spikes on a slicked crown)
    s = applyDetail(groups, groupOf, key, rp.seed, strands_, 255, finish_ ? &endSpread : nullptr,
                    finish_, &centre_, strands_.flags.size() == n ? &strands_.flags : nullptr,
                    clumpAll_, locks_);
    // cutting ends back moves no point: only detail needs keeping outside again
    if (head && anyDetail) {
      keepOutsideHead(*head, float(gp.margin), strands_);
      keepOutsideBody(float(gp.margin), nullptr);
    }
  }
  growMs_ = msSince(t0);
  return s;
}

}  // namespace hairsketch
