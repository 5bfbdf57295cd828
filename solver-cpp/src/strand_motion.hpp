// The whole groom in motion (strand_motion.cpp): the strands that are not simulated follow the
// guides HairSim steps (hair_sim.hpp).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "hair_sim.hpp"

namespace hairsketch {

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
