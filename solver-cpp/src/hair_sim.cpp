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

Eigen::Vector3f windVelocity(SimMotion motion, double t, uint32_t seed, float from, float mean) {
  if (motion != SimMotion::Wind) return Eigen::Vector3f::Zero();
  // Gusts: a few seeded sinusoids, ramped in over the first second.
  const double ramp = std::min(1.0, t);
  double speed = mean;
  for (uint32_t k = 0; k < 3; ++k) {
    const double f = 0.3 + 0.7 * unit(seed, 2 * k), ph = 2 * kPi * unit(seed, 2 * k + 1);
    speed += 0.5 * mean * std::sin(2 * kPi * f * t + ph);
  }
  // from the front (+z) give or take pi / 8, then turned about the vertical axis by `from`
  const double dir = 2 * kPi * unit(seed, 99) * 0.25 - kPi / 8;
  const double x = std::sin(dir), z = -std::cos(dir);
  const double c = std::cos(double(from)), sn = std::sin(double(from));
  return float(ramp * speed) * Eigen::Vector3f(float(x * c + z * sn), 0.0f, float(z * c - x * sn));
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
    const Eigen::Vector3f wind =
        kUnitsPerMetre * windVelocity(motion_, t, seed_, settings_.windFrom, settings_.windSpeed);
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

}  // namespace hairsketch
