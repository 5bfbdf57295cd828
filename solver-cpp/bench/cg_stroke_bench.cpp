// CG on a realistic stroke: 28 x 36 x 28 grid around a head-sized box, one stream curve of
// ~60 segments (d apart) over the top and down the back, extension on. Prints iterations,
// time, and the error against a much tighter solve.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cg_solver.hpp"
#include "stream_constraints.hpp"

using namespace hairsketch;

int main(int argc, char** argv) {
  Grid g;
  g.nx = 28;
  g.ny = 36;
  g.nz = 28;
  g.step = 0.3 / 27;  // 30 cm wide box
  g.origin = {-0.15, 1.3, -0.15};
  const double r = 0.1;  // curve on a 10 cm sphere around (0, 1.6, 0)
  std::vector<double> pts;
  for (double a = 0.05; a < 1.5708; a += g.step / r)
    pts.insert(pts.end(), {0.02, 1.6 + r * std::cos(a), -r * std::sin(a)});
  for (double y = 1.6; y > 1.33; y -= g.step) pts.insert(pts.end(), {0.02, y, -r});
  // A second, sideways curve, so the stroke is not planar.
  std::vector<double> pts2;
  for (double a = 0.3; a < 2.4; a += g.step / r)
    pts2.insert(pts2.end(), {r * std::sin(a), 1.6 + r * std::cos(a), 0.03});
  std::vector<Constraint> raw;
  appendStreamConstraints(g, pts.data(), pts.size() / 3, true, raw);
  appendStreamConstraints(g, pts2.data(), pts2.size() / 3, true, raw);
  const ConstraintSet set = normalizeConstraints(raw);
  std::printf("grid %dx%dx%d = %lld points, curves %zu + %zu points, %zu constraints\n", g.nx, g.ny,
              g.nz, (long long)g.size(), pts.size() / 3, pts2.size() / 3, set.size());
  const double tol = argc > 1 ? std::atof(argv[1]) : CgOptions().errorTolerance;
  CgOptions o;
  o.errorTolerance = tol;
  CgSolver s(o);
  s.setGrid(g, kDefaultOmega);
  s.setConstraints(set);
  Field T;
  const auto t0 = std::chrono::steady_clock::now();
  const Status st = s.solve(T);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "cg (errorTolerance %.0e): %s, %d iterations, %.1f ms, rel residual %.2e, "
      "error bound %.2e\n",
      tol, st.ok() ? "ok" : st.message.c_str(), s.stats().iterations, ms, s.stats().residual,
      s.errorEstimate());
  CgOptions tight;
  tight.errorTolerance = 1e-13;
  tight.residualGate = 1e-12;
  tight.warmStart = false;
  CgSolver ref(tight);
  ref.setGrid(g, kDefaultOmega);
  ref.setConstraints(set);
  Field R;
  ref.solve(R);
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    if (R.col(c).norm() > 0)
      worst = std::max(worst, (T.col(c) - R.col(c)).norm() / R.col(c).norm());
  std::printf("reference: %d iterations; measured relative error %.2e\n", ref.stats().iterations,
              worst);
  return st.ok() ? 0 : 1;
}
