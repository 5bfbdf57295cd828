#include "hair_sim.hpp"

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
                   uint32_t seed, const SimSettings& settings) {
  settings_ = settings;
  motion_ = motion;
  seed_ = seed;
  head_ = head && head->built() ? head : nullptr;
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

void HairSim::substep(int strand, float dt, const HeadPose& pose, const Eigen::Vector3f& gEff,
                      const Eigen::Vector3f& wind) {
  const size_t base = size_t(strand) * n_;
  auto X = [&](int i) { return Eigen::Map<Eigen::Vector3f>(x_.data() + 3 * (base + i)); };
  auto P = [&](int i) { return Eigen::Map<Eigen::Vector3f>(prev_.data() + 3 * (base + i)); };
  auto R = [&](int i) { return Eigen::Map<const Eigen::Vector3f>(rest_.data() + 3 * (base + i)); };
  const float keep = 1.0f - settings_.damping;
  const float drag = std::min(1.0f, settings_.windDrag * dt);
  const int pinned = std::min(n_, 2);
  for (int i = 0; i < n_; ++i) {
    if (i < pinned) {
      P(i) = X(i);
      X(i) = pose.apply(R(i));
      continue;
    }
    Eigen::Vector3f v = (X(i) - P(i)) * keep;
    v += drag * (wind * dt - v);
    P(i) = X(i);
    X(i) += v + gEff * (dt * dt);
  }
  const float denom = n_ > 1 ? float(n_ - 1) : 1.0f;
  for (int it = 0; it < std::max(1, settings_.iterations); ++it) {
    for (int i = pinned; i < n_; ++i) {
      const float s = 1.0f - float(i) / denom;
      const float w = settings_.shapeStiffness * s * s;
      if (w > 0) X(i) += w * (pose.apply(R(i)) - X(i));
    }
    for (int i = 0; i + 2 < n_; ++i) {
      const float rest = bendLen_[base + i];
      Eigen::Vector3f d = X(i + 2) - X(i);
      const float l = d.norm();
      if (l <= 1e-12f) continue;
      const Eigen::Vector3f c = settings_.bendStiffness * (l - rest) / l * d;
      if (i < pinned)
        X(i + 2) -= c;
      else {
        X(i) += 0.5f * c;
        X(i + 2) -= 0.5f * c;
      }
    }
    for (int i = 0; i + 1 < n_; ++i) {
      const float rest = len_[base + i];
      Eigen::Vector3f d = X(i + 1) - X(i);
      const float l = d.norm();
      if (l <= 1e-12f) continue;
      const Eigen::Vector3f c = (l - rest) / l * d;
      if (i + 1 < pinned) continue;
      if (i < pinned)
        X(i + 1) -= c;
      else {
        X(i) += 0.5f * c;
        X(i + 1) -= 0.5f * c;
      }
    }
  }
  // Length exactly from the root outward (follow-the-leader), then collision in the head's frame.
  for (int i = pinned; i < n_; ++i) {
    Eigen::Vector3f d = X(i) - X(i - 1);
    const float l = d.norm();
    if (l > 1e-12f) X(i) = X(i - 1) + d * (len_[base + i - 1] / l);
    if (head_) {
      Eigen::Vector3f local = pose.rotation.transpose() * (X(i) - pose.translation);
      if (head_->distance(local.x(), local.y(), local.z()) < settings_.collisionMargin) {
        head_->pushOut(local.data(), settings_.collisionMargin);
        X(i) = pose.apply(local);
      }
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

}  // namespace hairsketch
