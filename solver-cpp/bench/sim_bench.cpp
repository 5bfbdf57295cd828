// One 24 Hz step of HairSim (SimSettings defaults: 2 substeps x 3 iterations) for 1,000 / 3,000 /
// 10,000 guides of 32 points, single thread and with the thread pool, no head collider (the
// dynamics alone). Usage: sim_bench [threads]   (default: the hardware's thread count)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "hair_sim.hpp"
#include "parallel.hpp"

using namespace hairsketch;

static std::vector<float> radialGroom(int strands, int n) {
  std::vector<float> p;
  p.reserve(size_t(strands) * n * 3);
  for (int s = 0; s < strands; ++s) {
    const double ph = 2.399963 * s, th = 0.2 + 1.2 * ((s * 37) % 101) / 101.0;
    const float ox = float(std::sin(th) * std::cos(ph)), oy = float(std::cos(th)),
                oz = float(std::sin(th) * std::sin(ph));
    for (int i = 0; i < n; ++i) {
      const float r = 0.1f + 0.008f * i;
      p.insert(p.end(), {r * ox, r * oy, r * oz});
    }
  }
  return p;
}

int main(int argc, char** argv) {
  const int hw = argc > 1 ? std::atoi(argv[1]) : int(std::thread::hardware_concurrency());
  for (int threads : {1, hw}) {
    parallel::setThreadCount(threads);
    for (int guides : {1000, 3000, 10000}) {
      const std::vector<float> g = radialGroom(guides, 32);
      HairSim sim;
      sim.init(g.data(), guides, 32, nullptr, Eigen::Vector3f::Zero(), SimMotion::HeadTurn, 1);
      sim.step();  // warm up
      const int frames = 10;
      const auto t0 = std::chrono::steady_clock::now();
      for (int k = 0; k < frames; ++k) sim.step();
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
          frames;
      std::printf("threads %d  guides %5d x 32  step %.2f ms\n", parallel::threadCount(), guides,
                  ms);
    }
    // A whole groom: 30,000 strands of 100 points, 3,000 of them guides, the rest following.
    {
      const int strands = 30000, n = 100;
      const std::vector<float> g = radialGroom(strands, n);
      std::vector<uint32_t> start(strands + 1);
      for (int s = 0; s <= strands; ++s) start[s] = uint32_t(s) * n;
      MotionInput in;
      in.points = g.data();
      in.strandStart = start.data();
      in.strandCount = strands;
      in.motion = SimMotion::HeadTurn;
      in.maxGuides = 3000;
      StrandMotion m;
      const auto t0 = std::chrono::steady_clock::now();
      m.init(in);
      const auto t1 = std::chrono::steady_clock::now();
      const int frames = 10;
      for (int k = 0; k < frames; ++k) m.step();
      const auto t2 = std::chrono::steady_clock::now();
      std::printf("threads %d  groom 30000 x 100 (3000 guides)  init %.1f ms  frame %.2f ms\n",
                  parallel::threadCount(),
                  std::chrono::duration<double, std::milli>(t1 - t0).count(),
                  std::chrono::duration<double, std::milli>(t2 - t1).count() / frames);
    }
    if (hw <= 1) break;
  }
  return 0;
}
