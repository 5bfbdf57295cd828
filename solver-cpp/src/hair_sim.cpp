#include "hair_sim.hpp"

#include <algorithm>
#include <cmath>

#if defined(__wasm_simd128__)
#include <wasm_simd128.h>
#elif defined(__SSE__)
#include <xmmintrin.h>
#endif

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

namespace {

// Strands are stepped kLanes at a time, one strand per lane of kVec 4-float vectors (GCC and
// Clang vector extensions: SSE natively, simd128 in wasm). A strand's constraints form one chain
// of dependent square roots and divisions along it (latency bound: one strand at a time took
// 2.5 us a substep); eight independent chains side by side keep the pipelines full. Every lane
// does the very operations, in the very order, of the scalar code it replaced (IEEE single
// precision, correctly rounded square roots, no reassociation; neither build has fused
// multiply-adds to contract into), so a strand gets the same bits in any lane, pack or thread,
// as it did stepped alone (the tests check 1 and 3 threads, and strands alone, bit for bit).
typedef float Vec4f __attribute__((vector_size(16)));
typedef int32_t Vec4i __attribute__((vector_size(16)));
constexpr int kVec = 2;
constexpr int kLanes = 4 * kVec;

struct Lanes {
  Vec4f v[kVec];
  float lane(int l) const { return v[l >> 2][l & 3]; }
  void set(int l, float f) { v[l >> 2][l & 3] = f; }
};
struct Mask {
  Vec4i v[kVec];
};

inline Lanes splat(float s) {
  Lanes r;
  for (int j = 0; j < kVec; ++j) r.v[j] = Vec4f{s, s, s, s};
  return r;
}
#define HAIRSKETCH_LANES_OP(op)                               \
  inline Lanes operator op(const Lanes& a, const Lanes& b) {  \
    Lanes r;                                                  \
    for (int j = 0; j < kVec; ++j) r.v[j] = a.v[j] op b.v[j]; \
    return r;                                                 \
  }
HAIRSKETCH_LANES_OP(+)
HAIRSKETCH_LANES_OP(-)
HAIRSKETCH_LANES_OP(*)
HAIRSKETCH_LANES_OP(/)
#undef HAIRSKETCH_LANES_OP

inline Vec4f sqrtVec4(Vec4f a) {
#if defined(__wasm_simd128__)
  return Vec4f(wasm_f32x4_sqrt(v128_t(a)));
#elif defined(__SSE__)
  return Vec4f(_mm_sqrt_ps(__m128(a)));
#else
  return Vec4f{std::sqrt(a[0]), std::sqrt(a[1]), std::sqrt(a[2]), std::sqrt(a[3])};
#endif
}
inline Lanes sqrtLanes(const Lanes& a) {
  Lanes r;
  for (int j = 0; j < kVec; ++j) r.v[j] = sqrtVec4(a.v[j]);
  return r;
}
// Lanes where a <= s (a NaN: false), and where a > s.
inline Mask atMost(const Lanes& a, float s) {
  Mask m;
  for (int j = 0; j < kVec; ++j) m.v[j] = Vec4i(a.v[j] <= Vec4f{s, s, s, s});
  return m;
}
inline Mask above(const Lanes& a, float s) {
  Mask m;
  for (int j = 0; j < kVec; ++j) m.v[j] = Vec4i(a.v[j] > Vec4f{s, s, s, s});
  return m;
}
// m ? a : b, lane by lane.
inline Lanes laneSelect(const Mask& m, const Lanes& a, const Lanes& b) {
  Lanes r;
  for (int j = 0; j < kVec; ++j)
    r.v[j] = Vec4f((m.v[j] & Vec4i(a.v[j])) | (~m.v[j] & Vec4i(b.v[j])));
  return r;
}
inline Lanes lengthOf(const Lanes d[3]) {
  return sqrtLanes(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

// A strand pack's state, lane = strand, [3 * point + axis] (len and bend [point]).
struct PackScratch {
  std::vector<Lanes> x, prev, rest, target, len, bend;
  void resize(int n) {
    for (std::vector<Lanes>* v : {&x, &prev, &rest, &target}) v->resize(size_t(3 * n));
    len.resize(size_t(n));
    bend.resize(size_t(n));
  }
};

}  // namespace

void HairSim::step() {
  const int sub = std::max(1, settings_.substeps);
  const double frameDt = 1.0 / settings_.frameRate;
  const float dt = float(frameDt / sub);
  const Eigen::Vector3f g(0.0f, -settings_.gravity, 0.0f);
  std::vector<SubstepForces> forces(static_cast<size_t>(sub));
  for (int k = 1; k <= sub; ++k) {
    const double t = (frame_ + double(k) / sub) * frameDt;
    SubstepForces& f = forces[size_t(k - 1)];
    f.pose = headPose(motion_, t, pivot_);
    // Preloaded gravity: the groom was shaped under g in the starting orientation (identity).
    const Eigen::Vector3f gEff = g - f.pose.rotation * g;
    const Eigen::Vector3f wind = windVelocity(motion_, t, seed_);
    for (int a = 0; a < 3; ++a) {
      f.wdt[a] = wind[a] * dt;
      f.gdt[a] = gEff[a] * dt * dt;
    }
  }
  // Strands are independent: each pack runs all the substeps while its strands are in cache.
  const size_t packs = (size_t(strands_) + kLanes - 1) / kLanes;
  parallel::forRange(0, packs, 8, [&](size_t b, size_t e) {
    for (size_t p = b; p < e; ++p) stepPack(p * kLanes, forces.data(), sub, dt);
  });
  pose_ = forces.back().pose;
  ++frame_;
}

void keepOutside(const HeadDistance* head, const HeadDistance* body, float p[3], float margin) {
  for (const HeadDistance* c : {head, body})
    if (c && c->distanceAtLeast(p[0], p[1], p[2]) < margin) c->pushOut(p, margin);
}

void HairSim::stepPack(size_t first, const SubstepForces* forces, int sub, float dt) {
  const int n = n_;
  const int lanes = int(std::min<size_t>(kLanes, size_t(strands_) - first));
  thread_local PackScratch scratch;
  scratch.resize(n);
  Lanes* x = scratch.x.data();
  Lanes* pv = scratch.prev.data();
  Lanes* r = scratch.rest.data();
  Lanes* target = scratch.target.data();
  Lanes* len = scratch.len.data();
  Lanes* bend = scratch.bend.data();
  // Gather (a partial pack repeats its last strand in the spare lanes, never written back).
  for (int l = 0; l < kLanes; ++l) {
    const size_t base = (first + size_t(std::min(l, lanes - 1))) * size_t(n);
    const float* xs = x_.data() + 3 * base;
    const float* ps = prev_.data() + 3 * base;
    const float* rs = rest_.data() + 3 * base;
    for (int i = 0; i < 3 * n; ++i) {
      x[i].set(l, xs[i]);
      pv[i].set(l, ps[i]);
      r[i].set(l, rs[i]);
    }
    for (int i = 0; i < n; ++i) {
      len[i].set(l, len_[base + i]);
      bend[i].set(l, bendLen_[base + i]);
    }
  }
  const float keep = 1.0f - settings_.damping;
  const float drag = std::min(1.0f, settings_.windDrag * dt);
  const int pinned = std::min(n, 2);
  const float denom = n > 1 ? float(n - 1) : 1.0f;
  const bool collide = head_ || body_;
  const Lanes half = splat(0.5f), bendK = splat(settings_.bendStiffness);
  for (int k = 0; k < sub; ++k) {
    const HeadPose& pose = forces[k].pose;
    const Eigen::Matrix3f& Rm = pose.rotation;
    const Lanes tr[3] = {splat(pose.translation[0]), splat(pose.translation[1]),
                         splat(pose.translation[2])};
    Lanes rt[3][3];  // R^T
    for (int c = 0; c < 3; ++c)
      for (int j = 0; j < 3; ++j) rt[c][j] = splat(Rm(j, c));
    // The groom carried by the head (the shape pull's targets).
    for (int a = 0; a < 3; ++a) {
      const Lanes m0 = splat(Rm(a, 0)), m1 = splat(Rm(a, 1)), m2 = splat(Rm(a, 2)),
                  t = splat(pose.translation[a]);
      for (int i = 0; i < n; ++i)
        target[3 * i + a] = m0 * r[3 * i] + m1 * r[3 * i + 1] + m2 * r[3 * i + 2] + t;
    }
    for (int i = 0; i < 3 * pinned; ++i) {
      pv[i] = x[i];
      x[i] = target[i];
    }
    const Lanes keepL = splat(keep), dragL = splat(drag);
    const Lanes wdt[3] = {splat(forces[k].wdt[0]), splat(forces[k].wdt[1]),
                          splat(forces[k].wdt[2])};
    const Lanes gdt[3] = {splat(forces[k].gdt[0]), splat(forces[k].gdt[1]),
                          splat(forces[k].gdt[2])};
    for (int i = pinned; i < n; ++i)
      for (int a = 0; a < 3; ++a) {
        Lanes& xi = x[3 * i + a];
        Lanes v = (xi - pv[3 * i + a]) * keepL;
        v = v + dragL * (wdt[a] - v);
        pv[3 * i + a] = xi;
        xi = xi + (v + gdt[a]);
      }
    for (int it = 0; it < std::max(1, settings_.iterations); ++it) {
      for (int i = pinned; i < n; ++i) {
        const float s = 1.0f - float(i) / denom;
        const Lanes w = splat(settings_.shapeStiffness * std::max(s * s, settings_.shapeFloor));
        for (int a = 0; a < 3; ++a)
          x[3 * i + a] = x[3 * i + a] + w * (target[3 * i + a] - x[3 * i + a]);
      }
      for (int i = 0; i + 2 < n; ++i) {
        Lanes* p0 = x + 3 * i;
        Lanes* p2 = x + 3 * (i + 2);
        const Lanes d[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
        const Lanes l = lengthOf(d);
        const Mask skip = atMost(l, 1e-12f);
        const Lanes kk = bendK * (l - bend[i]) / l;
        if (i < pinned) {
          for (int a = 0; a < 3; ++a) p2[a] = laneSelect(skip, p2[a], p2[a] - kk * d[a]);
        } else {
          const Lanes h = half * kk;
          for (int a = 0; a < 3; ++a) {
            p0[a] = laneSelect(skip, p0[a], p0[a] + h * d[a]);
            p2[a] = laneSelect(skip, p2[a], p2[a] - h * d[a]);
          }
        }
      }
      for (int i = std::max(0, pinned - 1); i + 1 < n; ++i) {
        Lanes* p0 = x + 3 * i;
        Lanes* p1 = x + 3 * (i + 1);
        const Lanes d[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
        const Lanes l = lengthOf(d);
        const Mask skip = atMost(l, 1e-12f);
        const Lanes kk = (l - len[i]) / l;
        if (i < pinned) {
          for (int a = 0; a < 3; ++a) p1[a] = laneSelect(skip, p1[a], p1[a] - kk * d[a]);
        } else {
          const Lanes h = half * kk;
          for (int a = 0; a < 3; ++a) {
            p0[a] = laneSelect(skip, p0[a], p0[a] + h * d[a]);
            p1[a] = laneSelect(skip, p1[a], p1[a] - h * d[a]);
          }
        }
      }
    }
    // Length exactly from the root outward (follow-the-leader), then collision in the head's
    // frame.
    for (int i = pinned; i < n; ++i) {
      Lanes* p0 = x + 3 * (i - 1);
      Lanes* p1 = x + 3 * i;
      const Lanes d[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const Lanes l = lengthOf(d);
      const Mask move = above(l, 1e-12f);
      const Lanes f = len[i - 1] / l;
      for (int a = 0; a < 3; ++a) p1[a] = laneSelect(move, p0[a] + d[a] * f, p1[a]);
      if (!collide) continue;
      // In the head's frame, R^T (p - t) for every lane at once, summed as Eigen's product
      // does (m0 v0 + (m1 v1 + m2 v2)): the same bits as the scalar Eigen expression.
      const Lanes v[3] = {p1[0] - tr[0], p1[1] - tr[1], p1[2] - tr[2]};
      Lanes local[3];
      for (int c = 0; c < 3; ++c) local[c] = rt[c][0] * v[0] + (rt[c][1] * v[1] + rt[c][2] * v[2]);
      for (int ln = 0; ln < lanes; ++ln) {
        float q[3] = {local[0].lane(ln), local[1].lane(ln), local[2].lane(ln)};
        const float before[3] = {q[0], q[1], q[2]};
        keepOutside(head_, body_, q, settings_.collisionMargin);
        if (q[0] != before[0] || q[1] != before[1] || q[2] != before[2]) {
          const Eigen::Vector3f out = pose.apply(Eigen::Map<const Eigen::Vector3f>(q));
          for (int a = 0; a < 3; ++a) p1[a].set(ln, out[a]);
        }
      }
    }
  }
  for (int l = 0; l < lanes; ++l) {
    const size_t base = (first + size_t(l)) * size_t(n);
    float* xs = x_.data() + 3 * base;
    float* ps = prev_.data() + 3 * base;
    for (int i = 0; i < 3 * n; ++i) {
      xs[i] = x[i].lane(l);
      ps[i] = pv[i].lane(l);
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
