// Growth with and without the body (a bust the hair slides over): a head on a neck (a sphere of
// radius 1 = 10 cm, as tests/native/body_collider_test.cpp) over capsule shoulders 40 cm wide,
// natural fall, one stream curve down the back, long hair (60 cm, 5 mm steps), solved once with the
// fast solver; then HairEngine::grow at 30K and 100K strands (capped strides of one root set), bust
// off and on, the median (and least) of `runs` growths each, off and on by turns (after one
// untimed growth each), with every thread and with one. Prints milliseconds
// (HairEngine::growMs) and points grown.
//   body_growth_bench [runs=5]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "../../tests/native/body_mesh.hpp"
#include "hair_engine.hpp"
#include "parallel.hpp"

using namespace hairsketch;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  Grid grid;
  grid.step = 0.15;
  grid.origin = {-3.3, -6.0, -3.3};
  grid.nx = grid.nz = 45;
  grid.ny = 52;
  hairsketch_test::Mesh head = hairsketch_test::headOnNeck();
  hairsketch_test::markScalpAbove(head, 0.2);
  const hairsketch_test::Capsule shoulders;
  const hairsketch_test::Mesh body = hairsketch_test::capsuleMesh(shoulders);
  std::vector<double> points;
  for (int i = 0; i <= 12; ++i) {
    const double a = 0.2 + 0.2 * i;
    points.insert(points.end(), {0, 1.05 * std::cos(a), -1.05 * std::sin(a)});
  }
  const std::vector<uint32_t> start{0, uint32_t(points.size() / 3)};
  const std::vector<uint8_t> kinds{0}, extend{1};
  const CurveSetView curves{points.data(), points.size() / 3, start.data(), 1,
                            kinds.data(),  extend.data()};

  HairEngine e;
  Status st = e.setGrid(grid, kDefaultOmega, "fast");
  if (st.ok()) st = e.setFall(true);
  if (st.ok())
    st = e.setScalp(head.positions.data(), head.positions.size() / 3, head.indices.data(),
                    head.indices.size() / 3, head.scalp.data(), Eigen::Vector3d::Zero());
  if (st.ok())
    st = e.setBody(body.positions.data(), body.positions.size() / 3, body.indices.data(),
                   body.indices.size() / 3);
  if (st.ok()) st = e.setCurves(curves);
  if (st.ok()) st = e.solve();
  if (!st.ok()) {
    std::fprintf(stderr, "setup failed: %s\n", st.message.c_str());
    return 1;
  }
  std::printf(
      "grid %dx%dx%d step %.2f, head %zu triangles, body %zu triangles (distance grid "
      "%zu cells), %d runs each\n",
      grid.nx, grid.ny, grid.nz, grid.step, head.indices.size() / 3, body.indices.size() / 3,
      e.bodyDistance().cells(), runs);
  RootParams rp;
  rp.thetaStepDeg = 0.4;
  rp.phiStepDeg = 0.4;
  rp.seed = 5;
  GrowthParams gp;
  gp.maxLength = 6;  // 60 cm
  gp.stepFraction = 1.0 / 3;
  gp.maxSegments = 250;
  const int all = parallel::setThreadCount(int(std::max(1u, std::thread::hardware_concurrency())));
  for (int threads : {all, 1}) {
    parallel::setThreadCount(threads);
    for (int strands : {30000, 100000}) {
      rp.maxStrands = strands;
      std::vector<double> t[2];
      size_t pts[2] = {0, 0};
      for (int bust = 0; bust < 2; ++bust) {  // untimed (roots sampled once, buffers sized)
        e.setBust(bust != 0);
        if (!e.grow(rp, gp).ok()) return 1;
      }
      // off and on by turns, so that a busy machine slows both alike
      for (int r = 0; r < runs; ++r)
        for (int bust = 0; bust < 2; ++bust) {
          e.setBust(bust != 0);
          if (!e.grow(rp, gp).ok()) return 1;
          t[bust].push_back(e.growMs());
          pts[bust] = e.strands().points.size() / 3;
        }
      const double off = median(t[0]), on = median(t[1]);
      std::printf(
          "%d thread%s, %6zu strands: bust off %7.1f ms (min %7.1f; %zu points), on "
          "%7.1f ms (min %7.1f; %zu points): %+.1f %%\n",
          threads, threads == 1 ? " " : "s", e.strands().strandStart.size() - 1, off,
          *std::min_element(t[0].begin(), t[0].end()), pts[0], on,
          *std::min_element(t[1].begin(), t[1].end()), pts[1], 100 * (on / off - 1));
    }
  }
  return 0;
}
