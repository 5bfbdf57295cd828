// Hair growth in the vector field (method S5.2): from each root, append segments l * v(p),
// l = stepFraction * d, v trilinearly interpolated from the field and not normalised (paper §6).
// A strand stops when |v(p)| < minMagnitude, when the next point would leave the bounding
// volume, when the next segment would take its length past maxLength, or after maxSegments.
// With the head's distance grid, hair stays outside the head: a next point closer to the head
// than `margin` loses the inward part of its step (the strand slides along the surface) and is
// pushed out to the margin; when what is left of the step is shorter than minSlide times the
// step the field asked for (the field points into the head), the strand stops there. Hair slides
// over the scalp only: a strand (past its first step) that meets the head where the nearest
// surface is not scalp (the face, the ears, the neck) stops there instead of running down over
// it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "field_system.hpp"
#include "grid.hpp"
#include "head_distance.hpp"
#include "status.hpp"

namespace hairsketch {

struct GrowthParams {
  double stepFraction = 0.5;  // l / d
  double minMagnitude = 0.05;
  double maxLength = 1e30;  // world units
  int maxSegments = 200;
  double margin = 0.02;   // world units kept between hair and head (0.02 = 2 mm)
  double minSlide = 0.3;  // of the step the field asks for
};

// hairArrays.ts StrandArrays: strand s owns points strandStart[s] .. strandStart[s + 1] - 1,
// the first being its root. Every root gives a strand (possibly just the root point).
// An allocator that leaves new elements uninitialised: growth writes every point it keeps, so
// zero-filling the (large, reused) point buffer on each resize would be wasted work.
template <typename T>
struct UninitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitAllocator<U>;
  };
  UninitAllocator() = default;
  template <typename U>
  UninitAllocator(const UninitAllocator<U>&) noexcept {}
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// What growth found of a strand (Strands::flags): kCutAtLine, it ended at a line (the remaining
// length of the strokes around, a hem) rather than at its own length; kLiesOnHead, it is short
// hair that lies on the head (ShapeGrowth::layOnHead's hugs, kHugLength).
enum StrandFlag : uint8_t { kCutAtLine = 1, kLiesOnHead = 2 };

struct Strands {
  std::vector<float, UninitAllocator<float>> points;  // points[3 * point + axis]
  std::vector<uint32_t> strandStart;
  // With the shape rules, one per strand: what growth found (StrandFlag bits); empty without
  // them.
  std::vector<uint8_t> flags;
};

// The field in float, interleaved (v[3 * p + axis]), for cache-friendly interpolation.
std::vector<float> toFloatField(const Field& T);

// Trilinear interpolation of a float field at world point x (x inside the volume).
Eigen::Vector3f interpolateField(const Grid& grid, const float* field, const Eigen::Vector3f& x);

struct CurveReach;
struct ShapeRules;

// With the bust: below this world height the head's own mesh is body, not face (a loaded
// bust's shoulders, chest and back when no body mesh is set; the head's neck where it meets a
// body mesh). World units are 10 cm and heads are placed with the cranium top at y ~ 1; the
// built-in head's chin is at y ~ -1.31, so -1.45 (1.4 cm under that chin) leaves the face, chin
// and jaw to the face rule.
constexpr float kHeadBodyBelowY = -1.45f;

// The body hair rests on (HairEngine's bust setting): a step that would end within `margin` of
// it slides over it and never ends the strand, unlike the head's face rule. The step loses its
// inward part; when what is left is shorter than minSlide times the step the field asked for
// (hair falling straight down onto the top of a shoulder), the strand goes on along the
// tangential part of gravity plus its previous direction (the horizontal direction away from the
// body's centre when both vanish); either way the step is rescaled to the length the field asked
// for (so the strand keeps its length) and pushed out to the margin.
struct BodyCollider {
  const HeadDistance* body = nullptr;  // the body's own mesh (HairEngine::setBody), or null
  // the head mesh is body below kHeadBodyBelowY (a loaded bust is its own body; the head's neck
  // slides like the body's)
  bool headBelow = false;
  bool active() const { return body || headBelow; }
};

// A strand rooted past the end of a curve that ends hair (remaining length <= 0 at its root) is
// at most this long beside that curve (world units), rising to the maximum length away from it.
constexpr double kPastEndLength = 0.2;

// Grows one strand per root. OverMemoryCap (and no strands) if the output would exceed
// maxPoints points in total. With the curves' reach (hair_fall.hpp): a strand rooted where a
// curve still has length stops where the remaining length there falls below zero, and a strand
// where a curve governs the hair may slide over the face (the non-scalp head). With a body
// (BodyCollider, inactive by default: the same bytes as without), hair slides over it.
// lengthCap (optional, one per root): the longest each strand may grow (a soft hairline's short
// hairs, soft_hairline.hpp; infinity: no cap of its own).
Status growStrands(const Grid& grid, const std::vector<float>& field,
                   const std::vector<Eigen::Vector3f>& roots, const GrowthParams& params,
                   Strands& out, size_t maxPoints = size_t(24) << 20,
                   const HeadDistance* head = nullptr, const CurveReach* reach = nullptr,
                   const BodyCollider& body = BodyCollider(), const ShapeRules* shape = nullptr,
                   const float* lengthCap = nullptr);

// Moves every point but the roots that lies closer to the head than `margin` out to it (after
// detail has moved points), of every strand or of the strands listed in `only`. Returns how
// many points moved. Any closed mesh's HeadDistance will do (the body's too).
// (keep_outside_head.cpp)
size_t keepOutsideHead(const HeadDistance& head, float margin, Strands& strands,
                       const std::vector<uint32_t>* only = nullptr);

}  // namespace hairsketch
