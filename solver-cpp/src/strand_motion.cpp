// The whole groom in motion: GuideFollowers (each strand bound to a guide, riding its displacement)
// and StrandMotion (a grown groom: guides picked and resampled, ties bound to their tail, the
// followers placed each frame and kept outside head and body), over HairSim (hair_sim.cpp).
#include "strand_motion.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "hair_sim.hpp"
#include "head_distance.hpp"
#include "parallel.hpp"

namespace hairsketch {

void GuideFollowers::bind(const float* points, int strandCount, int pointsPerStrand,
                          const HairSim& guides) {
  strands_ = strandCount;
  n_ = pointsPerStrand;
  rest_.assign(points, points + size_t(strandCount) * pointsPerStrand * 3);
  guide_.assign(size_t(strandCount), -1);
  const int gn = guides.pointsPerStrand();
  const std::vector<float>& g = guides.rest();
  parallel::forRange(0, size_t(strandCount), 256, [&](size_t b, size_t e) {
    for (size_t s = b; s < e; ++s) {
      const float* r = rest_.data() + s * n_ * 3;
      float best = INFINITY;
      for (int k = 0; k < guides.strandCount(); ++k) {
        const float* q = g.data() + size_t(k) * gn * 3;
        const float d = (q[0] - r[0]) * (q[0] - r[0]) + (q[1] - r[1]) * (q[1] - r[1]) +
                        (q[2] - r[2]) * (q[2] - r[2]);
        if (d < best) {
          best = d;
          guide_[s] = k;
        }
      }
    }
  });
}

void GuideFollowers::update(const HairSim& guides, float* out) const {
  const HeadPose& pose = guides.pose();
  const int gn = guides.pointsPerStrand();
  const std::vector<float>& gr = guides.rest();
  const std::vector<float>& gx = guides.positions();
  parallel::forRange(0, size_t(strands_), 256, [&](size_t b, size_t e) {
    for (size_t s = b; s < e; ++s) {
      const int k = guide_[s];
      for (int i = 0; i < n_; ++i) {
        const size_t a = (s * n_ + i) * 3;
        Eigen::Vector3f p = pose.apply(Eigen::Map<const Eigen::Vector3f>(rest_.data() + a));
        if (k >= 0 && gn > 0) {
          const int j = n_ > 1 ? int(std::lround(double(i) * (gn - 1) / (n_ - 1))) : 0;
          const size_t c = (size_t(k) * gn + j) * 3;
          p += Eigen::Map<const Eigen::Vector3f>(gx.data() + c) -
               pose.apply(Eigen::Map<const Eigen::Vector3f>(gr.data() + c));
        }
        Eigen::Map<Eigen::Vector3f>(out + a) = p;
      }
    }
  });
}

namespace {

// Arc length at each point of the polyline p[0 .. count - 1] (acc[0] = 0).
void followerArcLengths(const float* p, int count, std::vector<float>& acc) {
  acc.assign(size_t(std::max(count, 1)), 0.0f);
  for (int i = 1; i < count; ++i) {
    const float* a = p + 3 * (i - 1);
    const float* b = p + 3 * i;
    acc[i] = acc[i - 1] + std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                                    (b[2] - a[2]) * (b[2] - a[2]));
  }
}

}  // namespace

void StrandMotion::init(const MotionInput& in) {
  head_ = in.head && in.head->built() ? in.head : nullptr;
  body_ = in.body && in.body->built() ? in.body : nullptr;
  margin_ = in.settings.collisionMargin;
  const int count = std::max(0, in.strandCount);
  start_.assign(in.strandStart, in.strandStart + count + 1);
  const size_t points = count > 0 ? start_[count] : 0;
  rest_.assign(in.points, in.points + 3 * points);
  out_ = rest_;
  auto pointsOf = [&](int s) { return int(start_[s + 1] - start_[s]); };
  auto tailOf = [&](int s) { return in.tailCurves ? in.tailCurves[s] : -1; };
  // Guides: every k-th strand that has a segment; each tail gets at least one.
  int visible = 0;
  for (int s = 0; s < count; ++s) visible += pointsOf(s) >= 2;
  const int k = std::max(1, (visible + std::max(1, in.maxGuides) - 1) / std::max(1, in.maxGuides));
  std::vector<int> guides;
  std::vector<int32_t> guideIndex(size_t(count), -1);
  std::vector<int32_t> tailGuide;  // per tail curve: its guide (index into guides), or -1
  int seen = 0;
  for (int s = 0; s < count; ++s) {
    if (pointsOf(s) < 2) continue;
    const int t = tailOf(s);
    bool take = seen++ % k == 0;
    if (t >= 0) {
      if (size_t(t) >= tailGuide.size()) tailGuide.resize(size_t(t) + 1, -1);
      take = tailGuide[t] < 0;  // one guide per tail: the whole bunch follows it
      if (take) tailGuide[t] = int32_t(guides.size());
    }
    if (take) {
      guideIndex[s] = int32_t(guides.size());
      guides.push_back(s);
    }
  }
  // Resample each guide to G points by arc length.
  const int G = std::max(3, in.guidePoints);
  std::vector<float> gp(guides.size() * G * 3);
  std::vector<float> gLength(guides.size());
  parallel::forRange(0, guides.size(), 64, [&](size_t b, size_t e) {
    std::vector<float> acc;
    for (size_t g = b; g < e; ++g) {
      const int s = guides[g];
      const float* p = rest_.data() + 3 * size_t(start_[s]);
      const int n = pointsOf(s);
      followerArcLengths(p, n, acc);
      gLength[g] = acc[n - 1];
      int j = 0;
      for (int i = 0; i < G; ++i) {
        const float a = acc[n - 1] * float(i) / float(G - 1);
        while (j + 2 < n && acc[j + 1] < a) ++j;
        const float seg = acc[j + 1] - acc[j];
        const float w = seg > 0 ? std::clamp((a - acc[j]) / seg, 0.0f, 1.0f) : 0.0f;
        for (int c = 0; c < 3; ++c)
          gp[(g * G + i) * 3 + c] = p[3 * j + c] + w * (p[3 * (j + 1) + c] - p[3 * j + c]);
      }
    }
  });
  guides_ = guides;
  sim_.init(gp.data(), int(guides.size()), G, head_, in.pivot, in.motion, in.seed, in.settings,
            body_);
  // Followers: the guide with the nearest root, by a uniform grid over the guides' roots.
  guideOf_.assign(size_t(count), -1);
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(INFINITY), hi = -lo;
  for (int s : guides) {
    const Eigen::Vector3f r = Eigen::Map<const Eigen::Vector3f>(rest_.data() + 3 * start_[s]);
    lo = lo.cwiseMin(r);
    hi = hi.cwiseMax(r);
  }
  const int cells = std::max(1, int(std::cbrt(double(guides.size()) / 2.0)));
  const Eigen::Vector3f ext = (hi - lo).cwiseMax(1e-6f);
  const Eigen::Vector3f inv = Eigen::Vector3f::Constant(float(cells)).cwiseQuotient(ext);
  auto cellOf = [&](const float* r, int c) {
    return std::clamp(int(std::floor((r[c] - lo[c]) * inv[c])), 0, cells - 1);
  };
  std::vector<uint32_t> cellStart(size_t(cells) * cells * cells + 1, 0), cellItems(guides.size());
  auto cellIndex = [&](int x, int y, int z) { return size_t(x + cells * (y + cells * z)); };
  for (size_t g = 0; g < guides.size(); ++g) {
    const float* r = rest_.data() + 3 * start_[guides[g]];
    ++cellStart[cellIndex(cellOf(r, 0), cellOf(r, 1), cellOf(r, 2)) + 1];
  }
  for (size_t c = 1; c < cellStart.size(); ++c) cellStart[c] += cellStart[c - 1];
  {
    std::vector<uint32_t> fill(cellStart.begin(), cellStart.end() - 1);
    for (size_t g = 0; g < guides.size(); ++g) {
      const float* r = rest_.data() + 3 * start_[guides[g]];
      cellItems[fill[cellIndex(cellOf(r, 0), cellOf(r, 1), cellOf(r, 2))]++] = uint32_t(g);
    }
  }
  const float cellMin = std::min({ext.x(), ext.y(), ext.z()}) / float(cells);
  along_.assign(points, 0.0f);
  near_.assign(points, 0);
  parallel::forRange(0, size_t(count), 256, [&](size_t b, size_t e) {
    std::vector<float> acc;
    for (size_t s = b; s < e; ++s) {
      const int n = pointsOf(int(s));
      if (n < 2 || guides.empty()) continue;
      const float* r = rest_.data() + 3 * size_t(start_[s]);
      int32_t best = guideIndex[s];
      const int t = tailOf(int(s));
      if (best < 0 && t >= 0 && size_t(t) < tailGuide.size()) best = tailGuide[t];
      if (best < 0) {
        // rings of cells around the root's, until the nearest found is nearer than the ring
        const int cx = cellOf(r, 0), cy = cellOf(r, 1), cz = cellOf(r, 2);
        float bestD = INFINITY;
        for (int ring = 0; ring < cells; ++ring) {
          for (int z = std::max(0, cz - ring); z <= std::min(cells - 1, cz + ring); ++z)
            for (int y = std::max(0, cy - ring); y <= std::min(cells - 1, cy + ring); ++y)
              for (int x = std::max(0, cx - ring); x <= std::min(cells - 1, cx + ring); ++x) {
                if (std::max({std::abs(x - cx), std::abs(y - cy), std::abs(z - cz)}) != ring)
                  continue;
                const size_t c = cellIndex(x, y, z);
                for (uint32_t q = cellStart[c]; q < cellStart[c + 1]; ++q) {
                  const uint32_t g = cellItems[q];
                  const float* o = rest_.data() + 3 * start_[guides[g]];
                  const float d = (o[0] - r[0]) * (o[0] - r[0]) + (o[1] - r[1]) * (o[1] - r[1]) +
                                  (o[2] - r[2]) * (o[2] - r[2]);
                  if (d < bestD || (d == bestD && int32_t(g) < best)) {
                    bestD = d;
                    best = int32_t(g);
                  }
                }
              }
          // every point outside the searched block is farther than ring * cellMin
          if (best >= 0 && std::sqrt(bestD) <= float(ring) * cellMin) break;
        }
      }
      guideOf_[s] = best;
      followerArcLengths(r, n, acc);
      const float total = acc[n - 1] > 0 ? acc[n - 1] : 1.0f;
      for (int i = 0; i < n; ++i) {
        const size_t p = start_[s] + i;
        along_[p] = acc[i] / total * float(G - 1);
        const float* q = rest_.data() + 3 * p;
        float d = INFINITY;
        for (const HeadDistance* c : {head_, body_})
          if (c) d = std::min(d, c->distanceAtLeast(q[0], q[1], q[2]));
        near_[p] = i >= 1 && d < in.nearHead;
      }
    }
  });
}

Eigen::Vector3f placeFollowerPoint(Eigen::Vector3f q, const Eigen::Vector3f* prev, float length,
                                   const HeadPose& pose, const HeadDistance* head,
                                   const HeadDistance* body, float margin) {
  // the groomed segment length, from the root outward (follow-the-leader): a follower longer or
  // shorter than its guide keeps its own lengths
  auto relength = [&] {
    if (!prev) return;
    const Eigen::Vector3f step = q - *prev;
    const float l = step.norm();
    if (l > 1e-12f) q = *prev + step * (length / l);
  };
  relength();
  if (!head && !body) return q;
  auto toLocal = [&](const Eigen::Vector3f& w) {
    return Eigen::Vector3f(pose.rotation.transpose() * (w - pose.translation));
  };
  auto inside = [&](const Eigen::Vector3f& local) {
    for (const HeadDistance* c : {head, body})
      if (c && c->distanceAtLeast(local.x(), local.y(), local.z()) < margin) return true;
    return false;
  };
  Eigen::Vector3f local = toLocal(q);
  if (!inside(local)) return q;
  const Eigen::Vector3f before = local;
  keepOutside(head, body, local.data(), margin);
  const Eigen::Vector3f pushed = pose.apply(local);
  q = pushed;
  if (!prev) return q;
  // Back to the groomed length along the step from prev. Where prev stands off the surface and
  // the step points into it, that takes the point in again: the step turns toward the push's
  // direction (out of the surface) until its end is outside, at the groomed length.
  const Eigen::Vector3f out = pose.rotation * (local - before);
  const float outLen = out.norm();
  Eigen::Vector3f d = pushed - *prev;
  if (d.norm() <= 1e-12f) d = out;
  if (d.norm() <= 1e-12f) return q;
  d.normalize();
  const Eigen::Vector3f n = outLen > 1e-12f ? Eigen::Vector3f(out / outLen) : d;
  for (float t : {0.0f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f, 16.0f}) {
    const Eigen::Vector3f dir = (d + t * n).normalized();
    const Eigen::Vector3f c = *prev + length * dir;
    if (!inside(toLocal(c))) return c;
  }
  return pushed;  // outside, off its length where the head is in the way
}

void StrandMotion::step() {
  sim_.step();
  update();
}

void StrandMotion::update() {
  const HeadPose& pose = sim_.pose();
  const int G = sim_.pointsPerStrand();
  const std::vector<float>& gr = sim_.rest();
  const std::vector<float>& gx = sim_.positions();
  // each guide point's displacement from its groomed place carried by the head, once per frame
  disp_.resize(gx.size());
  parallel::forRange(0, gx.size() / 3, 4096, [&](size_t b, size_t e) {
    for (size_t c = b; c < e; ++c)
      Eigen::Map<Eigen::Vector3f>(disp_.data() + 3 * c) =
          Eigen::Map<const Eigen::Vector3f>(gx.data() + 3 * c) -
          pose.apply(Eigen::Map<const Eigen::Vector3f>(gr.data() + 3 * c));
  });
  const int count = int(guideOf_.size());
  parallel::forRange(0, size_t(count), 256, [&](size_t b, size_t e) {
    for (size_t s = b; s < e; ++s) {
      const int32_t g = guideOf_[s];
      Eigen::Vector3f prevOut = Eigen::Vector3f::Zero(), prevRest = prevOut;
      for (uint32_t p = start_[s]; p < start_[s + 1]; ++p) {
        const Eigen::Map<const Eigen::Vector3f> r(rest_.data() + 3 * p);
        Eigen::Vector3f q = pose.apply(r);
        if (g >= 0) {
          const float a = along_[p];
          const int j = std::min(G - 2, int(a));
          const float w = a - float(j);
          const float* d = disp_.data() + (size_t(g) * G + j) * 3;
          q += (1 - w) * Eigen::Map<const Eigen::Vector3f>(d) +
               w * Eigen::Map<const Eigen::Vector3f>(d + 3);
          const bool first = p == start_[s];
          q = placeFollowerPoint(q, first ? nullptr : &prevOut, (r - prevRest).norm(), pose,
                                 near_[p] ? head_ : nullptr, near_[p] ? body_ : nullptr, margin_);
        }
        Eigen::Map<Eigen::Vector3f>(out_.data() + 3 * p) = q;
        prevOut = q;
        prevRest = r;
      }
    }
  });
}

}  // namespace hairsketch
