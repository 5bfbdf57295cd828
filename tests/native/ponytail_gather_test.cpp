// Ponytail gathering end to end (method S4.6): a sphere head, a ponytail (or two mirror twins)
// with circles computed the way web/model/ponytailGeometry.ts does, solve, grow, and measure
// the tail's cross-section at mid-length (between C1 and the spine's end): the strands crossing
// the plane normal to the spine there, their PCA widths (2 std along each principal axis) and
// their ratio.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "hair_engine.hpp"
#include "ponytail_constraints.hpp"
#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace ponytail_gather_test {

using namespace hairsketch;
using Eigen::Vector3d;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Unit direction of spherical coordinates as the presets use them: theta from +y, phi from +z
// toward +x (uvSphere's parameterisation), so phi = 180 is the back (-z).
Vector3d sphericalDir(double thetaDeg, double phiDeg) {
  const double t = thetaDeg * kPi / 180, p = phiDeg * kPi / 180;
  return {std::sin(t) * std::sin(p), std::cos(t), std::sin(t) * std::cos(p)};
}

std::vector<Vector3d> resample(const std::vector<Vector3d>& dense, double step) {
  std::vector<Vector3d> out{dense.front()};
  double acc = 0;
  for (size_t i = 1; i < dense.size(); ++i) {
    Vector3d a = dense[i - 1];
    double seg = (dense[i] - a).norm();
    while (acc + seg >= step) {
      const double f = (step - acc) / seg;
      a = a + f * (dense[i] - a);
      out.push_back(a);
      seg = (dense[i] - a).norm();
      acc = 0;
    }
    acc += seg;
  }
  return out;
}

struct TailSpec {
  double theta, phi;       // root on the unit sphere
  double out, fall;        // world units (presets.ts PonytailSpec)
  double gather, width;    // C1's radius, the tail's widest radius
  double tightness = 0.6;  // S4.6 default
  double gatherMode = -1;  // < 0: the old block (no gather scalar); else appended as given
};

struct Tail {
  std::vector<Vector3d> spine;
  std::vector<double> params;  // the protocol's ponytail block
  PonytailParams parsed;
};

// presets.ts ponytailFrom: the spine leaves the head slanting down and bends until it hangs
// straight down; circles on every 2nd spine point from the gather (index 4) on, axis = the
// central-difference tangent, radius = the profiles' half distance (gather, widening to width,
// back to gather past 70% of the tail).
Tail makeTail(const TailSpec& s, double step) {
  Tail t;
  const Vector3d outDir = sphericalDir(s.theta, s.phi);
  std::vector<Vector3d> dense{outDir * 1.0};
  Vector3d dir = (outDir + Vector3d(0, -0.5, 0)).normalized(), p = dense[0];
  const double ds = step / 4;
  for (double len = 0; len < s.out + s.fall; len += ds) {
    if (len > s.out) dir = (dir + Vector3d(0, -0.1, 0)).normalized();
    p += dir * ds;
    dense.push_back(p);
  }
  t.spine = resample(dense, step);
  const int n = int(t.spine.size()), gatherAt = 4;
  auto radius = [&](int i) {
    if (i <= gatherAt) return s.gather;
    const double f = double(i - gatherAt) / (n - 1 - gatherAt);
    return s.gather + (s.width - s.gather) * std::pow(std::sin(kPi * std::min(1.0, f * 1.4)), 0.7);
  };
  t.params = {s.tightness};
  if (s.gatherMode >= 0) t.params.push_back(s.gatherMode);
  std::vector<double> circles;
  int m = 0;
  for (int i = gatherAt; i < n; i += 2) {
    const Vector3d tan =
        (t.spine[std::min(n - 1, i + 1)] - t.spine[std::max(0, i - 1)]).normalized();
    const Vector3d c = t.spine[i];
    circles.insert(circles.end(), {c.x(), c.y(), c.z(), tan.x(), tan.y(), tan.z(), radius(i)});
    ++m;
  }
  t.params.push_back(m);
  t.params.insert(t.params.end(), circles.begin(), circles.end());
  EXPECT_TRUE(parsePonytailParams(t.params.data(), t.params.size(), t.parsed).ok());
  return t;
}

// The app's box (web/model/grid.ts) at about the 50k preset's step, grown (same lattice) to hold
// every circle of the tails with 2 steps to spare and each spine's end with 6.
Grid appGrid(double step, const std::vector<Tail>& tails) {
  Vector3d lo(-1.7, -2.9, -1.7), hi(1.7, 1.5, 1.7);
  const Vector3d boxLo = lo;
  for (const Tail& t : tails) {
    for (const PonytailCircle& c : t.parsed.circles) {
      lo = lo.cwiseMin((c.centre.array() - (c.radius + 2 * step)).matrix());
      hi = hi.cwiseMax((c.centre.array() + (c.radius + 2 * step)).matrix());
    }
    lo = lo.cwiseMin((t.spine.back().array() - 6 * step).matrix());
    hi = hi.cwiseMax((t.spine.back().array() + 6 * step).matrix());
  }
  Grid g;
  const Eigen::Vector3i below = ((boxLo - lo) / step).array().ceil().cast<int>();
  g.origin = boxLo - step * below.cast<double>();
  g.nx = int(std::ceil((hi.x() - g.origin.x()) / step)) + 1;
  g.ny = int(std::ceil((hi.y() - g.origin.y()) / step)) + 1;
  g.nz = int(std::ceil((hi.z() - g.origin.z()) / step)) + 1;
  g.step = step;
  return g;
}

struct Section {
  size_t count = 0;
  double major = 0, minor = 0, ratio = 0;  // 2 std along the principal axes, minor / major
  double radius = 0;                       // the circles' radius at the section
  double offset = 0;                       // centroid's distance from the spine
  int rootsSameSide = 0;                   // roots on the tail's side of x = 0
};

// The strands crossing the plane normal to the spine at mid-length between C1 and the spine's
// end, within `window` x the local radius of the spine.
Section measure(const Tail& t, const Strands& s, double window, double at = 0.5, bool map = false) {
  const PonytailCircle& c1 = t.parsed.circles.front();
  // arc length from the spine point at C1 to the end; the mid point and its tangent
  size_t i1 = 0;
  for (size_t i = 0; i < t.spine.size(); ++i)
    if ((t.spine[i] - c1.centre).norm() < (t.spine[i1] - c1.centre).norm()) i1 = i;
  std::vector<double> acc{0};
  for (size_t i = i1 + 1; i < t.spine.size(); ++i)
    acc.push_back(acc.back() + (t.spine[i] - t.spine[i - 1]).norm());
  const double half = std::max(1e-9, acc.back() * at);
  size_t j = 1;
  while (j + 1 < acc.size() && acc[j] < half) ++j;
  const double f = (half - acc[j - 1]) / (acc[j] - acc[j - 1]);
  const Vector3d a = t.spine[i1 + j - 1], b = t.spine[i1 + j];
  const Vector3d o = a + f * (b - a), n = (b - a).normalized();
  // the circles' radius there: the circle whose centre is nearest o
  Section out;
  double best = INFINITY;
  for (const PonytailCircle& c : t.parsed.circles)
    if ((c.centre - o).norm() < best) {
      best = (c.centre - o).norm();
      out.radius = c.radius;
    }
  const Vector3d u = Vector3d::UnitX().cross(n).cross(n).normalized() * -1, v = n.cross(u);
  if (map)
    std::printf("  centre %.2f %.2f %.2f  n %.2f %.2f %.2f  u %.2f %.2f %.2f  v %.2f %.2f %.2f\n",
                o.x(), o.y(), o.z(), n.x(), n.y(), n.z(), u.x(), u.y(), u.z(), v.x(), v.y(), v.z());
  std::vector<Eigen::Vector2d> pts;
  const bool left = o.x() > 0;
  for (size_t k = 0; k + 1 < s.strandStart.size(); ++k) {
    for (uint32_t q = s.strandStart[k]; q + 1 < s.strandStart[k + 1]; ++q) {
      const Vector3d p0(s.points[3 * q], s.points[3 * q + 1], s.points[3 * q + 2]);
      const Vector3d p1(s.points[3 * q + 3], s.points[3 * q + 4], s.points[3 * q + 5]);
      const double d0 = (p0 - o).dot(n), d1 = (p1 - o).dot(n);
      if ((d0 > 0) == (d1 > 0) || d0 == d1) continue;
      const Vector3d x = p0 + d0 / (d0 - d1) * (p1 - p0) - o;
      if (x.norm() > window * out.radius) continue;
      pts.emplace_back(x.dot(u), x.dot(v));
      const double rx = s.points[3 * s.strandStart[k]];
      if ((rx > 0) == left) ++out.rootsSameSide;
      break;
    }
  }
  out.count = pts.size();
  if (map) {  // density over +-2 r, u across, v down the page
    const int N = 24;
    std::vector<int> cells(N * N, 0);
    for (const auto& p : pts) {
      const int a = int(std::floor((p.x() / out.radius + 2) / 4 * N)),
                b = int(std::floor((p.y() / out.radius + 2) / 4 * N));
      if (a >= 0 && a < N && b >= 0 && b < N) ++cells[b * N + a];
    }
    for (int b = 0; b < N; ++b) {
      std::printf("  |");
      for (int a = 0; a < N; ++a) {
        const int c = cells[b * N + a];
        std::printf("%c", c == 0 ? '.' : c < 3 ? ':' : c < 8 ? 'o' : c < 20 ? 'O' : '#');
      }
      std::printf("|\n");
    }
  }
  if (pts.size() < 3) return out;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= double(pts.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
  cov /= double(pts.size());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(cov);
  out.minor = 2 * std::sqrt(std::max(0.0, es.eigenvalues()(0)));
  out.major = 2 * std::sqrt(std::max(0.0, es.eigenvalues()(1)));
  out.ratio = out.major > 0 ? out.minor / out.major : 0;
  out.offset = mean.norm();
  return out;
}

struct Scene {
  Grid grid;
  hairsketch_test::Mesh head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 48, 96);
  std::vector<Tail> tails;
  std::vector<double> points, params;
  std::vector<uint32_t> start{0}, paramStart{0};
  std::vector<uint8_t> kinds, extend;

  double step;
  explicit Scene(double step_) : step(step_) { hairsketch_test::markScalpAbove(head, -0.25); }
  void add(const TailSpec& spec) {
    tails.push_back(makeTail(spec, step));
    grid = appGrid(step, tails);
    const Tail& t = tails.back();
    for (const Vector3d& p : t.spine) points.insert(points.end(), {p.x(), p.y(), p.z()});
    params.insert(params.end(), t.params.begin(), t.params.end());
    start.push_back(uint32_t(points.size() / 3));
    paramStart.push_back(uint32_t(params.size()));
    kinds.push_back(uint8_t(CurveKindCode::Ponytail));
    extend.push_back(1);
  }
  CurveSetView view() const {
    CurveSetView v;
    v.points = points.data();
    v.pointCount = points.size() / 3;
    v.curveStart = start.data();
    v.curveCount = kinds.size();
    v.kinds = kinds.data();
    v.extend = extend.data();
    v.params = params.data();
    v.paramCount = params.size();
    v.paramStart = paramStart.data();
    return v;
  }
  // The field by the app's own solver at this size (multigrid): the exact factorisation gave the
  // same figures in 10 times the time (19 s here, 160 s on a loaded CI machine).
  Status run(HairEngine& e) const {
    Status st = e.setGrid(grid, kDefaultOmega, "fast");
    if (!st.ok()) return st;
    st = e.setScalp(head.positions.data(), head.positions.size() / 3, head.indices.data(),
                    head.indices.size() / 3, head.scalp.data(), Vector3d::Zero());
    if (!st.ok()) return st;
    st = e.setCurves(view());
    if (!st.ok()) return st;
    st = e.solve();
    if (!st.ok()) return st;
    RootParams rp;
    rp.thetaStepDeg = 2.5;
    rp.phiStepDeg = 2.5;
    rp.seed = 7;
    GrowthParams gp;
    gp.maxLength = 5;
    return e.grow(rp, gp);
  }
};

void print(const char* what, const Section& s) {
  std::printf(
      "[gather] %-34s strands %5zu  widths %.3f x %.3f  ratio %.2f  circle r %.3f  "
      "centroid off %.3f  same side %d\n",
      what, s.count, s.major, s.minor, s.ratio, s.radius, s.offset, s.rootsSameSide);
}

}  // namespace

// Figures (50k-like step 0.1, sphere head of radius 1, 2.5 deg roots), old -> gather = 1, at
// mid-length: one tail at the back (r 0.43 there) widths 0.65 x 0.60 (a hollow ring, 658
// strands) -> about 0.42 x 0.32 (a filled disc, 6026 strands); mirror twins behind the ears
// (r 0.38) 850 strands each, a ring -> about 2970 strands each, ratio 0.63, roots on their own
// side only.
constexpr double kMinRatio = 0.6;
// The bunch's spread (the mean of its two widths, 2 std each; a uniformly filled disc of radius
// r has 2 std = r) is within [0.6 r, 1.2 r].
constexpr double kSpreadLo = 0.6, kSpreadHi = 1.2;

TEST(PonytailGather, OneTailAtTheBackIsARoundFilledBunch) {
  Section before, after;
  for (double mode : {-1.0, 1.0}) {
    Scene sc(0.1);
    sc.add({70, 180, 0.35, 2.0, 0.35, 0.45, 0.6, mode});
    HairEngine e;
    ASSERT_TRUE(sc.run(e).ok());
    const bool map = std::getenv("PONYTAIL_MAP") != nullptr;
    for (double at : {0.0, 0.5}) {
      const Section s = measure(sc.tails[0], e.strands(), 2.5, at, map);
      char label[64];
      std::snprintf(label, sizeof label, "back, %s, at %.1f", mode < 0 ? "old" : "gather", at);
      print(label, s);
      if (at == 0.5) (mode < 0 ? before : after) = s;
    }
  }
  EXPECT_GE(after.ratio, kMinRatio);
  const double spread = 0.5 * (after.major + after.minor);
  EXPECT_GE(spread, kSpreadLo * after.radius);
  EXPECT_LE(spread, kSpreadHi * after.radius);
  EXPECT_LT(after.offset, 0.25 * after.radius);  // centred on the spine
  EXPECT_GT(after.count, 4 * before.count);      // it gathers the hair around its base
}

TEST(PonytailGather, MirrorTwinsEachGatherTheirOwnSide) {
  Section left, right;
  Scene sc(0.1);
  sc.add({74, 115, 0.3, 1.6, 0.3, 0.4, 0.6, 1});
  sc.add({74, -115, 0.3, 1.6, 0.3, 0.4, 0.6, 1});
  HairEngine e;
  ASSERT_TRUE(sc.run(e).ok());
  const bool map = std::getenv("PONYTAIL_MAP") != nullptr;
  left = measure(sc.tails[0], e.strands(), 2.5, 0.5, map);
  right = measure(sc.tails[1], e.strands(), 2.5, 0.5, map);
  print("twin left, gather", left);
  print("twin right, gather", right);
  for (const Section& s : {left, right}) {
    EXPECT_GE(s.ratio, kMinRatio);
    const double spread = 0.5 * (s.major + s.minor);
    EXPECT_GE(spread, kSpreadLo * s.radius);
    EXPECT_LE(spread, kSpreadHi * s.radius);
    EXPECT_LT(s.offset, 0.25 * s.radius);
    EXPECT_GT(s.count, 2000u);
    EXPECT_GE(double(s.rootsSameSide), 0.99 * double(s.count));  // its own side's hair
  }
  // Mirror twins gather mirror bunches.
  EXPECT_NEAR(double(left.count), double(right.count), 0.05 * double(left.count));
}

// The gather scalar: a block without it is the original layout and gives the original
// constraints; with gather = 0 it gives the same constraints; gather = 1 others.
TEST(PonytailGather, LayoutsAndTheOldConstraintsUnchanged) {
  const Grid g = appGrid(0.1, {});
  const Tail old = makeTail({70, 180, 0.35, 2.0, 0.35, 0.45, 0.6, -1}, 0.1);
  const Tail zero = makeTail({70, 180, 0.35, 2.0, 0.35, 0.45, 0.6, 0}, 0.1);
  const Tail one = makeTail({70, 180, 0.35, 2.0, 0.35, 0.45, 0.6, 1}, 0.1);
  ASSERT_EQ(zero.params.size(), old.params.size() + 1);
  EXPECT_EQ(old.parsed.gather, 0);
  EXPECT_EQ(zero.parsed.gather, 0);
  EXPECT_EQ(one.parsed.gather, 1);
  EXPECT_EQ(zero.parsed.circles.size(), old.parsed.circles.size());
  auto constraints = [&](const Tail& t) {
    std::vector<Constraint> raw;
    std::vector<ConstraintColour> col;
    std::vector<double> spine;
    for (const Vector3d& p : t.spine) spine.insert(spine.end(), {p.x(), p.y(), p.z()});
    appendPonytailConstraints(g, spine.data(), t.spine.size(), true, t.parsed, raw, &col);
    return std::make_pair(raw, col);
  };
  const auto a = constraints(old), b = constraints(zero), c = constraints(one);
  ASSERT_EQ(a.first.size(), b.first.size());
  for (size_t k = 0; k < a.first.size(); ++k) {
    EXPECT_EQ(a.first[k].index, b.first[k].index);
    EXPECT_EQ(a.first[k].target, b.first[k].target);
    EXPECT_EQ(a.second[k], b.second[k]);
  }
  EXPECT_GT(c.first.size(), 3 * a.first.size());
  // gather other than 0 or 1 is refused; sizes of neither layout are refused.
  PonytailParams p;
  std::vector<double> v = one.params;
  v[kPonytailGather] = 2;
  EXPECT_EQ(parsePonytailParams(v.data(), v.size(), p).code, StatusCode::InvalidInput);
  v[kPonytailGather] = 0.5;
  EXPECT_EQ(parsePonytailParams(v.data(), v.size(), p).code, StatusCode::InvalidInput);
  v = one.params;
  v.push_back(0);
  EXPECT_EQ(parsePonytailParams(v.data(), v.size(), p).code, StatusCode::InvalidInput);
  v = {0.6, 1, 1, 0, 0, 0, 0, -1, 0, 0.3};  // gather = 1, one circle
  EXPECT_TRUE(parsePonytailParams(v.data(), v.size(), p).ok());
  EXPECT_EQ(p.gather, 1);
  ASSERT_EQ(p.circles.size(), 1u);
  EXPECT_EQ(p.circles[0].radius, 0.3);
  v.erase(v.begin() + 1);  // the same circle in the old layout
  EXPECT_TRUE(parsePonytailParams(v.data(), v.size(), p).ok());
  EXPECT_EQ(p.gather, 0);
  EXPECT_EQ(p.circles[0].radius, 0.3);
}

}  // namespace ponytail_gather_test
