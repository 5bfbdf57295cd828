#include "strand_detail.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "strand_detail_internal.hpp"

namespace hairsketch {

namespace {

Status rangeError(const std::string& field, const char* rule) {
  return Status::Error(StatusCode::InvalidInput, "detail: " + field + " must be " + rule);
}

}  // namespace

double shapeFalloff(double x, double s) { return strand_detail::Falloff(s)(x); }

Status validateDetail(const DetailParams& d) {
  auto nonNegative = [](double v) { return std::isfinite(v) && v >= 0; };
  auto unit = [](double v) { return std::isfinite(v) && v >= 0 && v <= 1; };
  auto shape = [](double v) { return std::isfinite(v) && v >= -1 && v <= 1; };
  const char* kNonNeg = "finite and >= 0";
  const char* kUnit = "in [0, 1]";
  const char* kShape = "in [-1, 1]";
  if (!nonNegative(d.curl.radius)) return rangeError("curl.radius", kNonNeg);
  if (!nonNegative(d.curl.frequency)) return rangeError("curl.frequency", kNonNeg);
  if (!unit(d.curl.start)) return rangeError("curl.start", kUnit);
  if (!unit(d.curl.randomOffset)) return rangeError("curl.randomOffset", kUnit);
  if (!nonNegative(d.curl.spread)) return rangeError("curl.spread", kNonNeg);
  if (!unit(d.clump.factor)) return rangeError("clump.factor", kUnit);
  if (!shape(d.clump.shape)) return rangeError("clump.shape", kShape);
  if (!nonNegative(d.clump.tipSpread)) return rangeError("clump.tipSpread", kNonNeg);
  if (!nonNegative(d.clump.guideDistance)) return rangeError("clump.guideDistance", kNonNeg);
  if (!nonNegative(d.frizz.distance)) return rangeError("frizz.distance", kNonNeg);
  if (!shape(d.frizz.shape)) return rangeError("frizz.shape", kShape);
  if (!unit(d.flyaway.share)) return rangeError("flyaway.share", kUnit);
  if (!nonNegative(d.flyaway.distance)) return rangeError("flyaway.distance", kNonNeg);
  if (!unit(d.flyaway.start)) return rangeError("flyaway.start", kUnit);
  if (!unit(d.lengthJitter)) return rangeError("lengthJitter", kUnit);
  return Status::Ok();
}

Status applyDetail(const std::vector<DetailParams>& groups, const std::vector<uint32_t>& groupOf,
                   const std::vector<uint32_t>& key, uint32_t seed, Strands& strands, int maxPoints,
                   const std::vector<float>* endSpread, bool ringlets,
                   const Eigen::Vector3d* headCentre, const std::vector<uint8_t>* flags,
                   bool clumpAll, bool locks) {
  using namespace strand_detail;
  auto invalid = [](std::string m) {
    return Status::Error(StatusCode::InvalidInput, std::move(m));
  };
  if (maxPoints < 2) return invalid("detail: maxPoints must be at least 2");
  std::vector<uint32_t>& start = strands.strandStart;
  const size_t nS = start.empty() ? 0 : start.size() - 1;
  if (groupOf.size() != nS)
    return invalid("detail: groupOf has " + std::to_string(groupOf.size()) + " entries for " +
                   std::to_string(nS) + " strands");
  if (key.size() != nS)
    return invalid("detail: key has " + std::to_string(key.size()) + " entries for " +
                   std::to_string(nS) + " strands");
  if (endSpread && endSpread->size() != nS)
    return invalid("detail: endSpread has " + std::to_string(endSpread->size()) + " entries for " +
                   std::to_string(nS) + " strands");
  if (flags && flags->size() != nS)
    return invalid("detail: flags has " + std::to_string(flags->size()) + " entries for " +
                   std::to_string(nS) + " strands");
  auto flagged = [&](size_t s, uint8_t bit) { return flags && ((*flags)[s] & bit) != 0; };
  if (nS == 0) return Status::Ok();
  if (start[0] != 0 || size_t(start[nS]) * 3 != strands.points.size())
    return invalid("detail: strandStart does not match the points");
  for (size_t s = 0; s < nS; ++s)
    if (start[s + 1] < start[s]) return invalid("detail: strandStart is not ascending");
  for (size_t k = 0; k < groups.size(); ++k) {
    Status st = validateDetail(groups[k]);
    if (!st.ok()) {
      st.message += " (group " + std::to_string(k) + ")";
      return st;
    }
  }
  for (size_t s = 0; s < nS; ++s)
    if (groupOf[s] >= groups.size())
      return invalid("detail: strand " + std::to_string(s) + " uses group " +
                     std::to_string(groupOf[s]) + " of " + std::to_string(groups.size()));

  const size_t cap = size_t(maxPoints);
  auto spreadOf = [&](size_t s) -> double {
    const float v = endSpread ? (*endSpread)[s] : 0.f;
    return std::isfinite(v) && v > 0 ? double(v) : 0.0;
  };
  bool work = false, anyCurl = false, anyClump = false, anyCurlOrFrizz = false, anyFly = false;
  for (size_t s = 0; s < nS; ++s) {
    const size_t count = start[s + 1] - start[s];
    const DetailParams& d = groups[groupOf[s]];
    const bool active = count >= 2 && d.any();
    work |= active || count > cap || (count >= 2 && spreadOf(s) > 0);
    anyCurl |= active && d.curl.radius > 0;
    anyClump |= active && d.clump.factor > 0 && d.clump.guideDistance > 0;
    anyCurlOrFrizz |= active && (d.curl.radius > 0 || d.frizz.distance > 0);
    anyFly |= active && d.flyaway.share > 0 && d.flyaway.distance > 0;
  }
  if (!work) return Status::Ok();
  Work w;

  // 1. Length jitter, end spread, and the cap for strands that came in too long (compacting in
  // place).
  {
    float* P = strands.points.data();
    size_t out = 0;
    for (size_t s = 0; s < nS; ++s) {
      const size_t b = start[s], count = start[s + 1] - b;
      start[s] = uint32_t(out);
      const DetailParams& d = groups[groupOf[s]];
      const bool jitter = count >= 2 && d.any() && d.lengthJitter > 0 && !flagged(s, kCutAtLine);
      const double spread = count >= 2 ? spreadOf(s) : 0.0;
      if (!jitter && spread == 0 && count <= cap) {
        if (out != b) std::memmove(P + 3 * out, P + 3 * b, 3 * count * sizeof(float));
        out += count;
        continue;
      }
      load(P + 3 * b, count, w.p);
      const double L = arcLengths(w.p, w.s);
      double keep = L;
      if (jitter) keep *= 1 - d.lengthJitter * strandRng(seed, key[s], kStreamJitter).uniform();
      if (spread > 0)
        keep -= std::min(spread, kEndSpreadShare * L) *
                strandRng(seed, key[s], kStreamEndSpread).uniform();
      if (keep < L && L > 0) cutAt(w.p, w.s, keep);
      if (w.p.size() > cap) {
        resampleEven(w.p, w.s, cap, w.q);
        std::swap(w.p, w.q);
      }
      store(w.p, P + 3 * out);
      out += w.p.size();
    }
    start[nS] = uint32_t(out);
    strands.points.resize(3 * out);
  }

  // a strand's curl phase: its own, or with ringlets its clump guide's (set while clumping)
  std::vector<uint32_t> phaseKey = key;

  // 2. Clump, group by group (guides keep their shape, so each group reads its guides as grown).
  if (anyClump) {
    std::vector<std::vector<uint32_t>> members(groups.size());
    for (size_t s = 0; s < nS; ++s)
      if (start[s + 1] - start[s] >= 2) members[groupOf[s]].push_back(uint32_t(s));
    for (size_t g = 0; g < groups.size(); ++g) {
      const ClumpParams& c = groups[g].clump;
      if (c.factor > 0 && c.guideDistance > 0 && members[g].size() >= 2)
        clumpGroup(c, members[g], key, seed, strands, w, ringlets ? &phaseKey : nullptr, clumpAll,
                   locks, locks && !(groups[g].curl.radius > 0) ? kLockLength : 0.0);
    }
  }

  // 3. Flyaways, strand by strand (in place: the point count stays).
  if (anyFly) {
    const V3 centre = headCentre ? *headCentre : V3::Zero();
    float* P = strands.points.data();
    for (size_t s = 0; s < nS; ++s) {
      const size_t count = start[s + 1] - start[s];
      const FlyawayParams& f = groups[groupOf[s]].flyaway;
      if (count < 2 || flagged(s, kLiesOnHead) || !flyawayPicked(f, seed, key[s])) continue;
      load(P + 3 * size_t(start[s]), count, w.p);
      flyaway(f, seed, key[s], centre, w, locks);
      store(w.p, P + 3 * size_t(start[s]));
    }
  }

  // 4. Curl and frizz, strand by strand (curl may add points: then into a new buffer).
  if (anyCurlOrFrizz) {
    const V3 centre = headCentre ? *headCentre : V3::Zero();
    // with ringlets a strand curls as its clump's ringlet (ringletOf)
    auto curlOf = [&](size_t s) {
      return ringlets ? ringletOf(groups[groupOf[s]], seed, phaseKey[s])
                      : Ringlet{groups[groupOf[s]], 1};
    };
    auto detailed = [&](size_t s) {
      const DetailParams& d = groups[groupOf[s]];
      return start[s + 1] - start[s] >= 2 && (d.curl.radius > 0 || d.frizz.distance > 0);
    };
    if (!anyCurl) {
      float* P = strands.points.data();
      for (size_t s = 0; s < nS; ++s) {
        if (!detailed(s)) continue;
        const size_t count = start[s + 1] - start[s];
        load(P + 3 * size_t(start[s]), count, w.p);
        const Ringlet r = curlOf(s);
        curlAndFrizz(r.detail, seed, key[s], phaseKey[s], count, w, r.hand, centre);
        store(w.p, P + 3 * size_t(start[s]));
      }
    } else {
      // Each strand's point count after curl first, so the new buffer is allocated once.
      std::vector<uint32_t> outStart(nS + 1, 0);
      const float* P = strands.points.data();
      for (size_t s = 0; s < nS; ++s) {
        size_t count = start[s + 1] - start[s];
        if (detailed(s) && groups[groupOf[s]].curl.radius > 0) {
          load(P + 3 * size_t(start[s]), count, w.p);
          count = curlPointCount(curlOf(s).detail, count, arcLengths(w.p, w.s), cap);
        }
        outStart[s + 1] = uint32_t(outStart[s] + count);
      }
      decltype(strands.points) out(3 * size_t(outStart[nS]));
      for (size_t s = 0; s < nS; ++s) {
        const float* src = P + 3 * size_t(start[s]);
        const size_t count = start[s + 1] - start[s], m = outStart[s + 1] - outStart[s];
        float* dst = out.data() + 3 * size_t(outStart[s]);
        if (!detailed(s)) {
          std::memcpy(dst, src, 3 * count * sizeof(float));
          continue;
        }
        load(src, count, w.p);
        const Ringlet r = curlOf(s);
        curlAndFrizz(r.detail, seed, key[s], phaseKey[s], m, w, r.hand, centre);
        store(w.p, dst);  // m points: resampled to m with curl, count = m without
      }
      strands.points.swap(out);
      start.swap(outStart);
    }
  }
  return Status::Ok();
}

}  // namespace hairsketch
