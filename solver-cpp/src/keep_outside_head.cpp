// Keeping grown strands outside a closed mesh (the head, or the body) after detail has moved their
// points: strand_growth.hpp keepOutsideHead.
#include <algorithm>
#include <cmath>
#include <vector>

#include "head_distance.hpp"
#include "parallel.hpp"
#include "strand_growth.hpp"

namespace hairsketch {

static void keepStrandOutside(const HeadDistance& head, float margin, Strands& strands, size_t st,
                              size_t& moved);

size_t keepOutsideHead(const HeadDistance& head, float margin, Strands& strands,
                       const std::vector<uint32_t>* only) {
  if (!head.built()) return 0;
  const size_t nS = only                          ? only->size()
                    : strands.strandStart.empty() ? 0
                                                  : strands.strandStart.size() - 1;
  // Strands are independent: chunks of them in parallel, each counting its own moves.
  const int chunks = int(std::min<size_t>(size_t(parallel::threadCount()) * 4, nS / 256 + 1));
  std::vector<size_t> movedBy(size_t(std::max(chunks, 1)), 0);
  parallel::forChunks(nS, chunks, [&](int c, size_t s0, size_t s1) {
    size_t& moved = movedBy[size_t(c)];
    for (size_t i = s0; i < s1; ++i)
      keepStrandOutside(head, margin, strands, only ? (*only)[i] : i, moved);
  });
  size_t moved = 0;
  for (size_t m : movedBy) moved += m;
  return moved;
}

static void keepStrandOutside(const HeadDistance& head, float margin, Strands& strands, size_t st,
                              size_t& moved) {
  {
    const uint32_t a = strands.strandStart[st], b = strands.strandStart[st + 1];
    // each point's distance as found (a lower bound on it: 0 at the root, margin once pushed out)
    thread_local std::vector<float> dist;
    dist.assign(b - a, 0.f);
    for (uint32_t p = a + 1; p < b; ++p) {
      float* q = strands.points.data() + 3 * size_t(p);
      const float d = head.distance(q[0], q[1], q[2]);
      dist[p - a] = d;
      if (d < margin) {
        head.pushOut(q, margin);
        dist[p - a] = 0.f;
        ++moved;
      }
    }
    // A segment between two points outside can still cut a corner of the head (a curl over a
    // convex part, a point pushed out far): its ends move out by the midpoint's depth. The
    // interpolated distance changes by at most sqrt(3) times the step (at most 1 along each
    // axis), so a midpoint is not looked up when both ends are far enough out for it to be
    // outside half the margin; after a first pass that moved points, every midpoint is.
    constexpr float kLipschitz = 1.7321f;
    for (int pass = 0; pass < 6; ++pass) {
      bool any = false;
      for (uint32_t p = a; p + 1 < b; ++p) {
        float* q0 = strands.points.data() + 3 * size_t(p);
        float* q1 = q0 + 3;
        if (pass == 0) {
          const float dx = q1[0] - q0[0], dy = q1[1] - q0[1], dz = q1[2] - q0[2];
          const float half = 0.5f * kLipschitz * std::sqrt(dx * dx + dy * dy + dz * dz);
          if (std::min(dist[p - a], dist[p + 1 - a]) - half >= 0.5f * margin) continue;
        }
        float g[3];
        const float dm = head.distance(0.5f * (q0[0] + q1[0]), 0.5f * (q0[1] + q1[1]),
                                       0.5f * (q0[2] + q1[2]), g);
        if (dm >= 0.5f * margin) continue;
        const float len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (!(len > 0.5f)) continue;
        const float move = std::min(margin - dm, 0.1f) / len;
        for (float* q : {q0, q1}) {
          if (q == strands.points.data() + 3 * size_t(a)) continue;  // the root stays
          for (int e = 0; e < 3; ++e) q[e] += move * g[e];
        }
        dist[p - a] = dist[p + 1 - a] = 0.f;  // moved: looked up again next to it
        any = true;
        ++moved;
      }
      if (!any) break;
    }
  }
}

}  // namespace hairsketch
