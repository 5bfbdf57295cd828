// The whole groom in motion (strand_motion.cpp): a subset of the strands is simulated as guides
// (HairSim, hair_sim.hpp) and every strand is bound to one of them; where a follower's points go
// each frame is computed from its guide by whoever draws or exports it (model/guideFollowers.ts,
// and the same in the strand shader), so nothing here grows with the strand count per frame.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "hair_sim.hpp"

namespace hairsketch {

// A grown groom in motion: the strands as the engine grows them (any point count each), a
// subset simulated as guides and every strand bound to one.
//   Guides: every k-th strand with two points or more (k chosen so at most maxGuides), each
//     resampled by arc length to guidePoints points; a tie's strands (a braid, bun or ponytail
//     tail: tailCurve >= 0) all follow one guide of their own tail, so the tail moves as one
//     bunch and stays gathered past its tie.
//   Binding: every other strand with two points or more is bound to one of the 6 guides whose
//     roots are nearest its own (a uniform grid over the guides' roots, searched ring by ring):
//     the one whose root and point halfway along lie nearest its own (the root's distance
//     squared weighted 4 to 1), so hair parted the other way rides a guide going its way; each of
//     its points at its own arc length from the root along the guide (along(), in guide points), at
//     most the guide's tip.
// A guide strand is bound to its own resampled guide the same way.
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
  SimSettings settings;
};

class StrandMotion {
 public:
  void init(const MotionInput& in);
  // Advances the guides one frame.
  void step() { sim_.step(); }
  const HairSim& guides() const { return sim_; }
  const HeadPose& pose() const { return sim_.pose(); }
  int frame() const { return sim_.frame(); }
  int guideCount() const { return sim_.strandCount(); }
  // The strands simulated (their indices), each strand's guide (an index into them, or -1: fewer
  // than two points, it rides the head) and each point's place along its guide (0 .. G - 1, in
  // guide points: its arc length from the root, at most the guide's; 0 where it has no guide).
  const std::vector<int>& guideStrands() const { return guides_; }
  const std::vector<int32_t>& guideOf() const { return guideOf_; }
  const std::vector<float>& along() const { return along_; }

 private:
  HairSim sim_;
  std::vector<int> guides_;
  std::vector<int32_t> guideOf_;
  std::vector<float> along_;
};

}  // namespace hairsketch
