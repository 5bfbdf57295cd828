// One 24 Hz step of HairSim (SimSettings defaults: 2 substeps x 2 iterations) for 1,000 / 3,000 /
// 10,000 guides of 32 points, single thread and with the thread pool: the median of 20 steps
// with no head collider (the dynamics alone), then with a head (a sphere of radius 0.95 under
// the roots, its distance grid at 0.03: about the app's head and cell, in its world units of
// 10 cm, so the settings' gravity and margin are the app's).
// Usage: sim_bench [threads [fixed]]   (threads: default the hardware's thread count; fixed: the
// pool's adaptive switch off, so the loops go to the threads even when they do not pay, as on a
// loaded machine where the default runs them serially)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "hair_sim.hpp"
#include "head_distance.hpp"
#include "parallel.hpp"
#include "strand_motion.hpp"

using namespace hairsketch;

static std::vector<float> radialGroom(int strands, int n) {
  std::vector<float> p;
  p.reserve(size_t(strands) * n * 3);
  for (int s = 0; s < strands; ++s) {
    const double ph = 2.399963 * s, th = 0.2 + 1.2 * ((s * 37) % 101) / 101.0;
    const float ox = float(std::sin(th) * std::cos(ph)), oy = float(std::cos(th)),
                oz = float(std::sin(th) * std::sin(ph));
    for (int i = 0; i < n; ++i) {
      const float r = 1.f + 0.08f * i;
      p.insert(p.end(), {r * ox, r * oy, r * oz});
    }
  }
  return p;
}

// A UV sphere of radius r about the origin, poles on y.
static void sphere(float r, std::vector<float>& v, std::vector<uint32_t>& t) {
  const int nu = 64, nv = 32;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double th = 3.14159265358979 * j / nv, ph = 2 * 3.14159265358979 * i / nu;
      v.insert(v.end(), {float(r * std::sin(th) * std::cos(ph)), float(r * std::cos(th)),
                         float(r * std::sin(th) * std::sin(ph))});
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const uint32_t a = j * nu + i, b = j * nu + (i + 1) % nu, c = a + nu, d = b + nu;
      t.insert(t.end(), {a, b, c, b, d, c});
    }
}

// The median of `frames` steps (after one to warm up), in ms.
static double stepMs(const std::vector<float>& groom, int guides, const HeadDistance* head) {
  HairSim sim;
  sim.init(groom.data(), guides, 32, head, Eigen::Vector3f(0, -0.1f, 0), SimMotion::HeadTurn, 1);
  sim.step();
  std::vector<double> ms;
  for (int k = 0; k < 20; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    sim.step();
    ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

int main(int argc, char** argv) {
  const int hw = argc > 1 ? std::atoi(argv[1]) : int(std::thread::hardware_concurrency());
  if (argc > 2 && std::string(argv[2]) == "fixed") parallel::setAdaptive(false);
  std::vector<float> hv;
  std::vector<uint32_t> ht;
  sphere(0.95f, hv, ht);
  HeadMeshView mesh;
  mesh.positions = hv.data();
  mesh.vertexCount = hv.size() / 3;
  mesh.indices = ht.data();
  mesh.triangleCount = ht.size() / 3;
  HeadDistance head;
  if (!head.build(mesh, 0.03, 3).ok()) return 1;
  for (int threads : {1, hw}) {
    parallel::setThreadCount(threads);
    for (int guides : {1000, 3000, 10000}) {
      const std::vector<float> g = radialGroom(guides, 32);
      const double bare = stepMs(g, guides, nullptr), withHead = stepMs(g, guides, &head);
      std::printf("threads %d  guides %5d x 32  step %.2f ms  with a head %.2f ms\n",
                  parallel::threadCount(), guides, bare, withHead);
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
