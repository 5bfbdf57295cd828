#include "scalp_sections.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace hairsketch {

namespace {
constexpr float kSectionPi = 3.14159265358979323846f;
}  // namespace

Eigen::Vector2f ScalpSections::plane(const Eigen::Vector3f& p) const {
  const Eigen::Vector3f v = p - centre_;
  const float n = v.norm();
  if (!(n > 0)) return Eigen::Vector2f::Zero();
  const Eigen::Vector3f d = v / n;
  const float ang = std::acos(std::clamp(d.y(), -1.f, 1.f));
  const float h = std::hypot(d.x(), d.z());
  if (!(h > 1e-7f)) return Eigen::Vector2f::Zero();
  return Eigen::Vector2f(ang * d.x() / h, ang * d.z() / h);
}

int ScalpSections::cellOf(const Eigen::Vector2f& uv) const {
  auto index = [](float x) {
    return std::clamp(int(std::floor((x + kSectionPi) / (2 * kSectionPi) * float(kGrid))), 0,
                      kGrid - 1);
  };
  return index(uv.y()) * kGrid + index(uv.x());
}

Eigen::Vector2f ScalpSections::closingTarget(const std::vector<Eigen::Vector2f>& uv, bool first,
                                             const Eigen::Vector2f& dir, int self,
                                             const std::vector<uint8_t>& scalp,
                                             const std::vector<int16_t>& owner,
                                             float reachCells) const {
  constexpr int N = kGrid;
  const float cellsPerRad = float(N) / (2 * kSectionPi);
  const Eigen::Vector2f endUv = first ? uv.front() : uv.back();
  const Eigen::Vector2f P = (endUv + Eigen::Vector2f::Constant(kSectionPi)) * cellsPerRad;
  // the parting's own cells near this end are not a wall to close on: only those more than
  // twice the reach along it (a loop drawn back to its start closes)
  std::vector<uint8_t> nearOwn(size_t(N) * N, 0);
  {
    float walked = 0;
    const size_t n = uv.size();
    for (size_t k = 0; k + 1 < n && walked <= 2 * reachCells; ++k) {
      const Eigen::Vector2f a = first ? uv[k] : uv[n - 1 - k];
      const Eigen::Vector2f b = first ? uv[k + 1] : uv[n - 2 - k];
      walked += (b - a).norm() * cellsPerRad;
      const Eigen::Vector2f A = (a + Eigen::Vector2f::Constant(kSectionPi)) * cellsPerRad;
      const Eigen::Vector2f B = (b + Eigen::Vector2f::Constant(kSectionPi)) * cellsPerRad;
      const int steps = std::max(1, int(std::ceil((B - A).norm() * 2)));
      for (int st = 0; st <= steps; ++st) {
        const Eigen::Vector2f Q = A + (B - A) * (float(st) / float(steps));
        for (int dy = -3; dy <= 3; ++dy)
          for (int dx = -3; dx <= 3; ++dx) {
            const int x = int(std::floor(Q.x())) + dx, y = int(std::floor(Q.y())) + dy;
            if (x >= 0 && y >= 0 && x < N && y < N) nearOwn[size_t(y) * N + x] = 1;
          }
      }
    }
  }
  const int r = int(std::ceil(reachCells));
  float best = std::numeric_limits<float>::infinity();
  Eigen::Vector2f target = endUv;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int x = int(std::floor(P.x())) + dx, y = int(std::floor(P.y())) + dy;
      const Eigen::Vector2f C(float(x) + 0.5f, float(y) + 0.5f);
      const Eigen::Vector2f d = C - P;
      const float dist = d.norm();
      if (dist > reachCells || dist < 1e-3f) continue;
      const bool inside = x >= 0 && y >= 0 && x < N && y < N;
      const size_t c = inside ? size_t(y) * N + x : 0;
      const bool edge = !inside || !scalp[c];
      const bool other =
          inside && owner[c] >= 0 && (owner[c] != self || (owner[c] == self && !nearOwn[c]));
      if (!edge && !other) continue;
      // ahead of the end, not behind it: the parting is carried on, not bent back
      const float cosine = d.dot(dir) / dist;
      if (cosine < kCloseCosine) continue;
      const float cost = dist * (2.f - cosine);
      if (cost < best) {
        best = cost;
        target = C / cellsPerRad - Eigen::Vector2f::Constant(kSectionPi);
      }
    }
  return target;
}

void ScalpSections::build(const std::vector<Eigen::Vector3f>& roots, const Eigen::Vector3f& centre,
                          const std::vector<std::vector<Eigen::Vector3f>>& partings,
                          bool closeNear) {
  centre_ = centre;
  constexpr int N = kGrid;
  const float cellsPerRad = float(N) / (2 * kSectionPi);
  std::vector<uint8_t> scalp(size_t(N) * N, 0), wall(size_t(N) * N, 0);
  std::vector<int> rootCell(roots.size());
  float meanRadius = 0;
  for (size_t k = 0; k < roots.size(); ++k) {
    rootCell[k] = cellOf(plane(roots[k]));
    meanRadius += (roots[k] - centre).norm();
  }
  meanRadius = roots.empty() ? 1.f : meanRadius / float(roots.size());
  for (int c : rootCell) {
    const int i = c % N, j = c / N;
    for (int dj = -kDilate; dj <= kDilate; ++dj)
      for (int di = -kDilate; di <= kDilate; ++di) {
        const int x = i + di, y = j + dj;
        if (x >= 0 && y >= 0 && x < N && y < N) scalp[size_t(y) * N + x] = 1;
      }
  }
  // walls: a disc stamped along each segment, in cells
  auto stamp = [&](const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
    const Eigen::Vector2f A = (a + Eigen::Vector2f::Constant(kSectionPi)) * cellsPerRad;
    const Eigen::Vector2f B = (b + Eigen::Vector2f::Constant(kSectionPi)) * cellsPerRad;
    const int steps = std::max(1, int(std::ceil((B - A).norm() * 2)));
    const int r = int(std::ceil(kWallRadius));
    for (int s = 0; s <= steps; ++s) {
      const Eigen::Vector2f P = A + (B - A) * (float(s) / float(steps));
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int x = int(std::floor(P.x())) + dx, y = int(std::floor(P.y())) + dy;
          if (x < 0 || y < 0 || x >= N || y >= N) continue;
          const float cx = float(x) + 0.5f - P.x(), cy = float(y) + 0.5f - P.y();
          if (cx * cx + cy * cy <= (kWallRadius + 0.5f) * (kWallRadius + 0.5f))
            wall[size_t(y) * N + x] = 1;
        }
    }
  };
  const float reach = kPartingReach / std::max(meanRadius, 1e-3f);  // radians
  std::vector<std::vector<Eigen::Vector2f>> lines;
  for (const std::vector<Eigen::Vector3f>& line : partings) {
    if (line.size() < 2) continue;
    std::vector<Eigen::Vector2f> uv;
    for (const Eigen::Vector3f& p : line) uv.push_back(plane(p));
    lines.push_back(std::move(uv));
  }
  // each parting's own cells, before any end is carried on (closing: which wall is another's)
  std::vector<int16_t> owner(size_t(N) * N, -1);
  for (size_t l = 0; l < lines.size(); ++l) {
    std::fill(wall.begin(), wall.end(), uint8_t(0));
    for (size_t k = 0; k + 1 < lines[l].size(); ++k) stamp(lines[l][k], lines[l][k + 1]);
    for (size_t c = 0; c < wall.size(); ++c)
      if (wall[c]) owner[c] = int16_t(l);
  }
  for (size_t c = 0; c < wall.size(); ++c) wall[c] = owner[c] >= 0;
  const float closeCells = kCloseReach / std::max(meanRadius, 1e-3f) * cellsPerRad;
  for (size_t l = 0; l < lines.size(); ++l) {
    const std::vector<Eigen::Vector2f>& uv = lines[l];
    // each end carried on along its direction over its last ~1.5 cm
    for (int end = 0; end < 2; ++end) {
      const size_t last = end == 0 ? 0 : uv.size() - 1;
      size_t back = last;
      const float want = 0.15f / std::max(meanRadius, 1e-3f);
      while (true) {
        const size_t next = end == 0 ? back + 1 : back - 1;
        if (end == 0 ? next >= uv.size() : back == 0) break;
        back = next;
        if ((uv[back] - uv[last]).norm() >= want) break;
      }
      const Eigen::Vector2f dir = uv[last] - uv[back];
      if (!(dir.norm() > 1e-6f)) continue;
      if (!closeNear) {
        stamp(uv[last], uv[last] + dir.normalized() * reach);
        continue;
      }
      const Eigen::Vector2f to =
          closingTarget(uv, end == 0, dir.normalized(), int(l), scalp, owner, closeCells);
      if (to != uv[last]) stamp(uv[last], to);
    }
  }
  // sections: 4-connected components of scalp cells off the walls
  std::vector<int32_t> comp(size_t(N) * N, -1);
  std::vector<size_t> members;  // roots per component
  std::deque<int> queue;
  // breadth-first over the queue: `take(from, to)` says whether cell `to` joins from `from`
  auto spread = [&](auto take) {
    const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    while (!queue.empty()) {
      const int c = queue.front();
      queue.pop_front();
      for (const auto& d : nb) {
        const int x = c % N + d[0], y = c / N + d[1];
        if (x < 0 || y < 0 || x >= N || y >= N) continue;
        if (take(c, y * N + x)) queue.push_back(y * N + x);
      }
    }
  };
  int found = 0;
  for (int c0 = 0; c0 < N * N; ++c0) {
    if (!scalp[c0] || wall[c0] || comp[c0] >= 0) continue;
    comp[c0] = found;
    queue.push_back(c0);
    spread([&](int, int e) {
      if (!scalp[e] || wall[e] || comp[e] >= 0) return false;
      comp[e] = found;
      return true;
    });
    ++found;
  }
  members.assign(size_t(found), 0);
  for (int c : rootCell)
    if (comp[c] >= 0) ++members[size_t(comp[c])];
  // components large enough become sections, numbered in raster order
  std::vector<int32_t> section(size_t(found), -1);
  count_ = 0;
  for (int k = 0; k < found; ++k)
    if (float(members[size_t(k)]) >= kMinShare * float(roots.size()) && members[size_t(k)] > 0)
      section[size_t(k)] = count_++;
  label_.assign(size_t(N) * N, -1);
  for (int c = 0; c < N * N; ++c)
    if (comp[c] >= 0 && section[size_t(comp[c])] >= 0) {
      label_[c] = int16_t(section[size_t(comp[c])]);
      queue.push_back(c);
    }
  if (count_ == 0) {  // no roots, or all in slivers: one section
    count_ = 1;
    std::fill(label_.begin(), label_.end(), int16_t(0));
    return;
  }
  // every other cell: the nearest section's (breadth-first from all sections at once)
  spread([&](int c, int e) {
    if (label_[e] >= 0) return false;
    label_[e] = label_[c];
    return true;
  });
}

int ScalpSections::section(const Eigen::Vector3f& p) const {
  if (label_.empty()) return 0;
  return label_[size_t(cellOf(plane(p)))];
}

int ScalpSections::combedSection(const float* points, size_t count, float reach) const {
  if (count == 0) return 0;
  Eigen::Vector3f at(points[0], points[1], points[2]);
  float walked = 0;
  for (size_t i = 1; i < count; ++i) {
    const Eigen::Vector3f next(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    const float seg = (next - at).norm();
    if (walked + seg >= reach) {
      at += (reach - walked) / std::max(seg, 1e-12f) * (next - at);
      return section(at);
    }
    walked += seg;
    at = next;
  }
  return section(at);
}

}  // namespace hairsketch
