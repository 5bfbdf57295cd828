#include "hair_sim.hpp"

#include <algorithm>
#include <cmath>

#include "head_distance.hpp"
#include "parallel.hpp"

namespace hairsketch {

namespace {

constexpr double kPi = 3.14159265358979323846;

// 0 at t = 0 with zero slope, then a smooth oscillation of period 2 s.
double swing(double t) {
  const double ramp = t < 0.5 ? std::sin(kPi * t) * std::sin(kPi * t) : 1.0;  // eases in
  return ramp * std::sin(kPi * t);
}

uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

double unit(uint32_t seed, uint32_t k) { return hash32(seed * 0x9e3779b9U + k) / 4294967295.0; }

}  // namespace

HeadPose headPose(SimMotion motion, double t, const Eigen::Vector3f& pivot) {
  HeadPose pose;
  double angle = 0;
  Eigen::Vector3f axis = Eigen::Vector3f::UnitY();
  if (motion == SimMotion::HeadTurn) {
    angle = 60.0 * kPi / 180.0 * swing(t);
  } else if (motion == SimMotion::Nod) {
    angle = 25.0 * kPi / 180.0 * swing(t);
    axis = Eigen::Vector3f::UnitX();
  }
  pose.rotation = Eigen::AngleAxisf(float(angle), axis).toRotationMatrix();
  pose.translation = pivot - pose.rotation * pivot;
  return pose;
}

Eigen::Vector3f windVelocity(SimMotion motion, double t, uint32_t seed) {
  if (motion != SimMotion::Wind) return Eigen::Vector3f::Zero();
  // Gusts: a few seeded sinusoids, ramped in over the first second.
  const double ramp = std::min(1.0, t);
  double speed = 3.0;
  for (uint32_t k = 0; k < 3; ++k) {
    const double f = 0.3 + 0.7 * unit(seed, 2 * k), ph = 2 * kPi * unit(seed, 2 * k + 1);
    speed += 1.5 * std::sin(2 * kPi * f * t + ph);
  }
  const double dir = 2 * kPi * unit(seed, 99) * 0.25 - kPi / 8;  // mostly from the front (+z)
  return float(ramp * speed) * Eigen::Vector3f(float(std::sin(dir)), 0.0f, float(-std::cos(dir)));
}

void HairSim::init(const float* points, int strandCount, int pointsPerStrand,
                   const HeadDistance* head, const Eigen::Vector3f& pivot, SimMotion motion,
                   uint32_t seed, const SimSettings& settings, const HeadDistance* body) {
  settings_ = settings;
  motion_ = motion;
  seed_ = seed;
  head_ = head && head->built() ? head : nullptr;
  body_ = body && body->built() ? body : nullptr;
  pivot_ = pivot;
  strands_ = strandCount;
  n_ = pointsPerStrand;
  frame_ = 0;
  pose_ = HeadPose();
  const size_t count = size_t(strandCount) * size_t(pointsPerStrand);
  rest_.assign(points, points + 3 * count);
  x_ = rest_;
  prev_ = rest_;
  len_.assign(count, 0.0f);
  bendLen_.assign(count, 0.0f);
  for (int s = 0; s < strands_; ++s) {
    const float* p = rest_.data() + size_t(s) * n_ * 3;
    for (int i = 0; i + 1 < n_; ++i) {
      len_[size_t(s) * n_ + i] = (Eigen::Map<const Eigen::Vector3f>(p + 3 * (i + 1)) -
                                  Eigen::Map<const Eigen::Vector3f>(p + 3 * i))
                                     .norm();
      if (i + 2 < n_)
        bendLen_[size_t(s) * n_ + i] = (Eigen::Map<const Eigen::Vector3f>(p + 3 * (i + 2)) -
                                        Eigen::Map<const Eigen::Vector3f>(p + 3 * i))
                                           .norm();
    }
  }
}

void HairSim::step() {
  const int sub = std::max(1, settings_.substeps);
  const double frameDt = 1.0 / settings_.frameRate;
  const float dt = float(frameDt / sub);
  const Eigen::Vector3f g(0.0f, -settings_.gravity, 0.0f);
  for (int k = 1; k <= sub; ++k) {
    const double t = (frame_ + double(k) / sub) * frameDt;
    const HeadPose pose = headPose(motion_, t, pivot_);
    // Preloaded gravity: the groom was shaped under g in the starting orientation (identity).
    const Eigen::Vector3f gEff = g - pose.rotation * g;
    const Eigen::Vector3f wind = windVelocity(motion_, t, seed_);
    parallel::forRange(0, size_t(strands_), 64, [&](size_t b, size_t e) {
      for (size_t s = b; s < e; ++s) substep(int(s), dt, pose, gEff, wind);
    });
    pose_ = pose;
  }
  ++frame_;
}

void keepOutside(const HeadDistance* head, const HeadDistance* body, float p[3], float margin) {
  for (const HeadDistance* c : {head, body})
    if (c && c->distanceAtLeast(p[0], p[1], p[2]) < margin) c->pushOut(p, margin);
}

void HairSim::substep(int strand, float dt, const HeadPose& pose, const Eigen::Vector3f& gEff,
                      const Eigen::Vector3f& wind) {
  const size_t base = size_t(strand) * n_;
  float* x = x_.data() + 3 * base;
  float* pv = prev_.data() + 3 * base;
  const float* r = rest_.data() + 3 * base;
  const float* len = len_.data() + base;
  const float* bend = bendLen_.data() + base;
  // The groom carried by the head, once per substep (the shape pull's targets).
  thread_local std::vector<float> target;
  target.resize(size_t(3 * n_));
  const Eigen::Matrix3f& Rm = pose.rotation;
  for (int i = 0; i < n_; ++i) {
    const float* q = r + 3 * i;
    for (int a = 0; a < 3; ++a)
      target[3 * i + a] = Rm(a, 0) * q[0] + Rm(a, 1) * q[1] + Rm(a, 2) * q[2] + pose.translation[a];
  }
  const float keep = 1.0f - settings_.damping;
  const float drag = std::min(1.0f, settings_.windDrag * dt);
  const int pinned = std::min(n_, 2);
  const float wdt[3] = {wind.x() * dt, wind.y() * dt, wind.z() * dt};
  const float gdt[3] = {gEff.x() * dt * dt, gEff.y() * dt * dt, gEff.z() * dt * dt};
  for (int i = 0; i < pinned; ++i)
    for (int a = 0; a < 3; ++a) {
      pv[3 * i + a] = x[3 * i + a];
      x[3 * i + a] = target[3 * i + a];
    }
  for (int i = 3 * pinned; i < 3 * n_; ++i) {
    const int a = i % 3;
    float v = (x[i] - pv[i]) * keep;
    v += drag * (wdt[a] - v);
    pv[i] = x[i];
    x[i] += v + gdt[a];
  }
  const float denom = n_ > 1 ? float(n_ - 1) : 1.0f;
  for (int it = 0; it < std::max(1, settings_.iterations); ++it) {
    for (int i = pinned; i < n_; ++i) {
      const float s = 1.0f - float(i) / denom;
      const float w = settings_.shapeStiffness * std::max(s * s, settings_.shapeFloor);
      for (int a = 0; a < 3; ++a) x[3 * i + a] += w * (target[3 * i + a] - x[3 * i + a]);
    }
    for (int i = 0; i + 2 < n_; ++i) {
      float* p0 = x + 3 * i;
      float* p2 = x + 3 * (i + 2);
      const float d[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
      const float l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (l <= 1e-12f) continue;
      const float k = settings_.bendStiffness * (l - bend[i]) / l;
      if (i < pinned) {
        for (int a = 0; a < 3; ++a) p2[a] -= k * d[a];
      } else {
        for (int a = 0; a < 3; ++a) {
          p0[a] += 0.5f * k * d[a];
          p2[a] -= 0.5f * k * d[a];
        }
      }
    }
    for (int i = pinned - 1; i + 1 < n_; ++i) {
      if (i < 0) continue;
      float* p0 = x + 3 * i;
      float* p1 = x + 3 * (i + 1);
      const float d[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const float l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (l <= 1e-12f) continue;
      const float k = (l - len[i]) / l;
      if (i < pinned) {
        for (int a = 0; a < 3; ++a) p1[a] -= k * d[a];
      } else {
        for (int a = 0; a < 3; ++a) {
          p0[a] += 0.5f * k * d[a];
          p1[a] -= 0.5f * k * d[a];
        }
      }
    }
  }
  // Length exactly from the root outward (follow-the-leader), then collision in the head's frame.
  const bool collide = head_ || body_;
  for (int i = pinned; i < n_; ++i) {
    float* p0 = x + 3 * (i - 1);
    float* p1 = x + 3 * i;
    const float d[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const float l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (l > 1e-12f)
      for (int a = 0; a < 3; ++a) p1[a] = p0[a] + d[a] * (len[i - 1] / l);
    if (collide) {
      Eigen::Vector3f local = Rm.transpose() * (Eigen::Map<Eigen::Vector3f>(p1) - pose.translation);
      const Eigen::Vector3f before = local;
      keepOutside(head_, body_, local.data(), settings_.collisionMargin);
      if (local != before) Eigen::Map<Eigen::Vector3f>{p1} = pose.apply(local);
    }
  }
}

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
void arcLengths(const float* p, int count, std::vector<float>& acc) {
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
      arcLengths(p, n, acc);
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
      arcLengths(r, n, acc);
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
