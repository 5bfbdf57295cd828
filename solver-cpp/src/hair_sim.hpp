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
// The wind velocity at time t (m/s; zero but for Wind), gusting deterministically from the seed.
Eigen::Vector3f windVelocity(SimMotion motion, double t, uint32_t seed);
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

// A follower's point placed (StrandMotion's update): q, put back at `length` from `prev` (the
// strand's point before, already placed; null for a root), then kept out of the head and body
// (head frame by `pose`; both null: not checked) at `margin`, ending outside.
Eigen::Vector3f placeFollowerPoint(Eigen::Vector3f q, const Eigen::Vector3f* prev, float length,
                                   const HeadPose& pose, const HeadDistance* head,
                                   const HeadDistance* body, float margin);

// The strands that are not simulated follow their guides: each is bound once to the guide whose
// root is nearest its own (brute force over the guides) and its point i is its groomed point
// carried by the head plus guide point j's displacement from its own carried groom (j = i scaled
// to the guide's point count).
class GuideFollowers {
 public:
  void bind(const float* points, int strandCount, int pointsPerStrand, const HairSim& guides);
  // Writes strandCount * pointsPerStrand * 3 floats.
  void update(const HairSim& guides, float* out) const;
  const std::vector<int32_t>& guideOf() const { return guide_; }

 private:
  std::vector<float> rest_;
  std::vector<int32_t> guide_;
  int strands_ = 0, n_ = 0;
};

// A grown groom in motion: the strands as the engine grows them (any point count each), a
// subset simulated as guides and the rest carried by them.
//   Guides: every k-th strand with two points or more (k chosen so at most maxGuides), each
//     resampled by arc length to guidePoints points; a tie's strands (a braid, bun or ponytail
//     tail: tailCurve >= 0) all follow one guide of their own tail, so the tail moves as one
//     bunch and stays gathered past its tie.
//   Followers: every other strand is bound to the guide whose root is nearest its own (a uniform
//     grid over the guides' roots, searched ring by ring), point i at its own arc-length fraction
//     t_i; it is its groomed point carried by the head plus the guide's displacement at t_i,
//     then put back at its groomed distance from the point before (follow-the-leader, so
//     lengths hold). Points that start within `nearHead` of the head or body are kept outside.
// A guide strand itself is carried by its resampled guide the same way.
struct MotionInput {
  const float* points = nullptr;          // points[3 * point + axis]
  const uint32_t* strandStart = nullptr;  // strandCount + 1 entries
  int strandCount = 0;
  const int32_t* tailCurves = nullptr;  // may be null (no ties)
  const HeadDistance* head = nullptr;
  const HeadDistance* body = nullptr;
  Eigen::Vector3f pivot = Eigen::Vector3f::Zero();
  SimMotion motion = SimMotion::Settle;
  uint32_t seed = 0;
  int maxGuides = 3000;
  int guidePoints = 32;
  float nearHead = 1.0f;  // world units (10 cm)
  SimSettings settings;
};

class StrandMotion {
 public:
  void init(const MotionInput& in);
  void step();
  // The strands now, in the input's layout.
  const std::vector<float>& points() const { return out_; }
  const HairSim& guides() const { return sim_; }
  const HeadPose& pose() const { return sim_.pose(); }
  int frame() const { return sim_.frame(); }
  int guideCount() const { return sim_.strandCount(); }
  // The strands simulated (their indices), and each strand's guide (an index into them, or -1).
  const std::vector<int>& guideStrands() const { return guides_; }
  const std::vector<int32_t>& guideOf() const { return guideOf_; }

 private:
  void update();
  HairSim sim_;
  const HeadDistance* head_ = nullptr;
  const HeadDistance* body_ = nullptr;
  std::vector<float> rest_, out_;
  std::vector<float> disp_;  // per guide point: its displacement now (update)
  std::vector<uint32_t> start_;
  std::vector<int> guides_;
  std::vector<int32_t> guideOf_;  // per strand, -1 for none (fewer than two points)
  std::vector<float> along_;      // per point: position along its guide, in guide points
  std::vector<uint8_t> near_;     // per point: 1 where collision is checked
  float margin_ = 0;
};

}  // namespace hairsketch
