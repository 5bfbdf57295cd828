// Guide-strand dynamics for playing a motion (settle, head turn, nod, wind) over a groom.
//
// Each guide is a chain of points integrated by Verlet and corrected by position-based
// constraints, `substeps` times per frame, each substep running `iterations` sweeps of:
//   segment length (each segment back to its groomed length, the root side held when pinned);
//   local bending (the distance between points i and i + 2 back to its groomed value);
//   global shape (each point pulled toward its groomed place carried by the head, the pull
//     strongest at the root and fading as (1 - s)^2 along the strand, s in [0, 1], to a floor
//     of shapeFloor at the tip);
// then collision (every point pushed out of the head's and the body's signed distances,
// HeadDistance::pushOut; the body moves rigidly with the head; a distance is read only where
// the cheap lower bound distanceAtLeast says the point could be within the margin).
// The first two points of every strand are pinned to the groom carried by the head transform.
// Gravity preloading: the groom is the rest shape, so the gravity a point feels is
//   g - R * R0^T * g (R the head's rotation now, R0 at the start): zero while the head keeps its
//   starting orientation, so the hair does not sag when the simulation starts.
// Deterministic: the motion is a function of time and seed; loops split with parallel.hpp write
// disjoint strands, so results do not depend on the thread count. Strands are independent: each
// pack of eight (one per SIMD lane) runs all of a frame's substeps while it is in cache, every
// lane the same bits as its strand stepped alone.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace hairsketch {

class HeadDistance;

enum class SimMotion { Settle = 0, HeadTurn = 1, Nod = 2, Wind = 3 };

// A rigid head pose: world = rotation * groom + translation (about `pivot`, see headPose).
struct HeadPose {
  Eigen::Matrix3f rotation = Eigen::Matrix3f::Identity();
  Eigen::Vector3f translation = Eigen::Vector3f::Zero();
  Eigen::Vector3f apply(const Eigen::Vector3f& p) const { return rotation * p + translation; }
};

// The head's pose at time t (seconds) for a motion, rotating about `pivot` (e.g. the neck).
// Settle and Wind keep the head still; Head turn yaws ±60° and Nod pitches ±25° (smooth, period
// 2 s, starting at rest with zero velocity).
HeadPose headPose(SimMotion motion, double t, const Eigen::Vector3f& pivot);
// The wind velocity at time t (m/s; zero but for Wind), gusting deterministically from the seed:
// from the direction `from` (radians about the vertical axis: 0 the face's side, +z; pi / 2 the
// head's left, +x), give or take a seeded pi / 8, at `speed` m/s give or take half of it.
Eigen::Vector3f windVelocity(SimMotion motion, double t, uint32_t seed, float from = 0.f,
                             float speed = 3.f);
// The app's world units per metre (1 unit = 10 cm): the simulation works in world units, so the
// wind (m/s) is scaled by this (it was used as units/s, a tenth of its speed: no visible motion).
constexpr float kUnitsPerMetre = 10.0f;

struct SimSettings {
  int substeps = 2;
  int iterations = 2;  // stiffnesses below set so 2 sweeps pull as far as 3 at 0.2 / 0.5 did
  double frameRate = 24;
  // Lengths are the app's world units (1 unit = 10 cm): 9.81 m/s^2 is 98.1 units/s^2.
  float gravity = 98.1f;          // world units/s^2 along -y
  float damping = 0.02f;          // velocity lost per substep
  float shapeStiffness = 0.285f;  // global shape pull at the root, per iteration
  // The pull never fades below this fraction of shapeStiffness (at the tips): with gravity
  // preloaded a displaced tip feels no weight, and this brings it back to the groom (a time
  // constant of about 0.7 s at the defaults) instead of leaving it where the motion flung it.
  float shapeFloor = 0.035f;
  float bendStiffness = 0.65f;
  float windDrag = 0.5f;  // per second, toward the wind velocity
  // Wind (the Wind motion; windVelocity): where it comes from (radians about the vertical axis,
  // 0 the front) and its mean speed (m/s; its gusts add and take up to half of it).
  float windFrom = 0.f;
  float windSpeed = 3.f;
  // Points are kept this far outside the head and the body (2 mm: the distance grids' zero is
  // within a cell of the surface).
  float collisionMargin = 0.02f;
};

class HairSim {
 public:
  // points: strandCount * pointsPerStrand * 3 floats (strand-major), the groom in the head's
  // starting frame. head may be null (no collision); it must outlive the simulation.
  // body may be null too (no bust).
  void init(const float* points, int strandCount, int pointsPerStrand, const HeadDistance* head,
            const Eigen::Vector3f& pivot, SimMotion motion, uint32_t seed,
            const SimSettings& settings = SimSettings(), const HeadDistance* body = nullptr);
  // Advances one frame (1 / frameRate seconds).
  void step();
  int frame() const { return frame_; }
  double time() const { return frame_ / settings_.frameRate; }
  const HeadPose& pose() const { return pose_; }
  const std::vector<float>& positions() const { return x_; }
  const std::vector<float>& rest() const { return rest_; }
  int strandCount() const { return strands_; }
  int pointsPerStrand() const { return n_; }

 private:
  // One substep's head pose and the velocity (wind * dt) and displacement (gravity * dt^2) it
  // adds.
  struct SubstepForces {
    HeadPose pose;
    float wdt[3], gdt[3];
  };
  // All the substeps of a frame for the strands first .. first + 7 (fewer at the end).
  void stepPack(size_t first, const SubstepForces* forces, int substeps, float dt);
  SimSettings settings_;
  SimMotion motion_ = SimMotion::Settle;
  uint32_t seed_ = 0;
  const HeadDistance* head_ = nullptr;
  const HeadDistance* body_ = nullptr;
  Eigen::Vector3f pivot_ = Eigen::Vector3f::Zero();
  int strands_ = 0, n_ = 0, frame_ = 0;
  HeadPose pose_;
  std::vector<float> rest_, x_, prev_, len_, bendLen_;
};

// Pushes p (head frame) out of the head and the body (either may be null) to `margin`.
void keepOutside(const HeadDistance* head, const HeadDistance* body, float p[3], float margin);
}  // namespace hairsketch
