// Sections of the scalp: partings (dividing curves, method S4.5) split the scalp into regions,
// as a hairdresser's partings do; a tie that gathers its whole section (gathered_tail.hpp) takes
// every strand rooted in it.
//
// The scalp is mapped to a plane by the azimuthal equidistant projection about the head's up
// axis through its centre c: a point p, d = (p - c) / |p - c|, goes to
//   (u, v) = acos(d_y) (d_x, d_z) / |(d_x, d_z)|
// (the crown at the origin, the one singular direction straight down, under the neck, where no
// scalp is). On a kGrid x kGrid raster of [-pi, pi]^2:
//   scalp cells: cells holding a root, grown by kDilate cells (so the raster has no gaps between
//     roots);
//   walls: each parting's polyline drawn with a disc of kWallRadius cells, each end carried on
//     along its direction by kPartingReach (world units, as an angle at the head's radius), so a
//     parting that stops short of the scalp's edge still reaches it; with closeNear (ties from
//     any hand) each end is carried on to the scalp's edge or another parting when one lies
//     within kCloseReach ahead of it, as a stylist ends a parting a little short of the hairline
//     or of the parting it meets, and left open otherwise;
//   sections: the 4-connected components of scalp cells that are not walls; a component holding
//     less than kMinShare of the roots is no section of its own (it joins its neighbour);
//   every other cell (walls, off the scalp) takes the section of the nearest cell that has one
//     (breadth-first, 4-connected).
// So a parting that is closed, or runs from edge to edge (ear to ear over the crown, forehead to
// nape), bounds a section, and one that does not leaves the scalp in one piece. No parting: one
// section. Deterministic (no randomness).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace hairsketch {

class ScalpSections {
 public:
  static constexpr int kGrid = 256;
  static constexpr int kDilate = 2;
  static constexpr float kWallRadius = 1.0f;
  static constexpr float kPartingReach = 0.35f;  // world units (3.5 cm)
  static constexpr float kMinShare = 0.01f;
  // Closing near (ties from any hand): how far an end looks for the scalp's edge or another
  // parting (world units, 5.5 cm: a parting drawn from above ends where the head's outline
  // is, its widest part, 4-5 cm above the hairline over the ears), and how far off its own
  // direction it may turn (cosine).
  static constexpr float kCloseReach = 0.55f;
  static constexpr float kCloseCosine = 0.0f;

  // roots: every root of the hair (the full set, so previews and full growth agree); partings:
  // the dividing curves' polylines. closeNear: an end is carried on to the nearest cell ahead of
  // it (within 90 degrees of its direction, cost distance x (2 - cosine)) off the scalp or on
  // another parting (or on its own line past twice the reach, a loop) within kCloseReach, and
  // not at all when there is none; off, each end runs on kPartingReach along its direction.
  void build(const std::vector<Eigen::Vector3f>& roots, const Eigen::Vector3f& centre,
             const std::vector<std::vector<Eigen::Vector3f>>& partings, bool closeNear = false);
  // The section of a point on or near the scalp (or of the scalp under it, seen from the centre);
  // 0 before build.
  int section(const Eigen::Vector3f& p) const;
  // The section a strand is combed into: that of its point `reach` along it (arc length) from
  // its root, or of its tip when it is shorter; points: count x 3 floats, root first. Hair at a
  // parting goes the way it is combed, so a root just one side of the line whose hair sets off
  // across it belongs to the other side.
  int combedSection(const float* points, size_t count, float reach) const;
  int count() const { return count_; }

 private:
  Eigen::Vector3f centre_ = Eigen::Vector3f::Zero();
  std::vector<int16_t> label_;  // per cell: its section (every cell has one after build)
  int count_ = 0;
  Eigen::Vector2f plane(const Eigen::Vector3f& p) const;
  Eigen::Vector2f closingTarget(const std::vector<Eigen::Vector2f>& uv, bool first,
                                const Eigen::Vector2f& dir, int self,
                                const std::vector<uint8_t>& scalp,
                                const std::vector<int16_t>& owner, float reachCells) const;
  int cellOf(const Eigen::Vector2f& uv) const;
};

}  // namespace hairsketch
