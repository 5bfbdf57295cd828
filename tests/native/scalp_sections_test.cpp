// Sections and ties (scalp_sections.hpp, gathered_tail.hpp "Whole sections"): partings split the
// scalp, and a tie that gathers its section takes every strand rooted there. On a sphere head
// (radius 1, scalp above y = -0.25), each fraction is checked against an independent side test
// on the roots (the plane the parting was drawn in), not against the code's own labels.
#include "scalp_sections.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "curve_params.hpp"
#include "engine_settings.hpp"
#include "hair_engine.hpp"
#include "sphere_mesh.hpp"

// Each test file is a namespace of its own: the build compiles several files as one (unity).
namespace scalp_sections_test {

using namespace hairsketch;
using Eigen::Vector3d;
using Eigen::Vector3f;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A parting on the unit sphere in the plane {p : p . n = d}, from one scalp edge to the other
// over the top (stopping `shortOf` radians before the scalp's edge at y = -0.25 on each side).
std::vector<Vector3d> partingInPlane(const Vector3d& n, double d, double shortOf = 0.1) {
  const Vector3d nn = n.normalized();
  const Vector3d c = d * nn;
  const double r = std::sqrt(1 - d * d);
  Vector3d up = Vector3d::UnitY() - Vector3d::UnitY().dot(nn) * nn;
  up.normalize();
  const Vector3d side = nn.cross(up);
  std::vector<Vector3d> out;
  for (double a = -kPi; a <= kPi; a += 0.02) {
    const Vector3d p = c + r * (std::cos(a) * up + std::sin(a) * side);
    if (p.y() > -0.25 + std::sin(shortOf)) out.push_back(p * 1.01);
  }
  return out;
}

struct Scene {
  hairsketch_test::Mesh head = hairsketch_test::uvSphere(0, 0, 0, 1.0, 48, 96);
  std::vector<double> points, params;
  std::vector<uint32_t> start{0}, paramStart{0};
  std::vector<uint8_t> kinds, extend;
  Scene() { hairsketch_test::markScalpAbove(head, -0.25); }

  void add(CurveKindCode kind, const std::vector<Vector3d>& pts, const std::vector<double>& prm) {
    for (const Vector3d& p : pts) points.insert(points.end(), {p.x(), p.y(), p.z()});
    params.insert(params.end(), prm.begin(), prm.end());
    start.push_back(uint32_t(points.size() / 3));
    paramStart.push_back(uint32_t(params.size()));
    kinds.push_back(uint8_t(kind));
    extend.push_back(0);
  }
  void parting(const std::vector<Vector3d>& pts) {
    add(CurveKindCode::Dividing, pts, {1, 0.5, 0, 0});
    for (size_t i = 0; i < pts.size(); ++i) {  // unit normals, one per point (outward)
      const Vector3d n = pts[i].normalized();
      params.insert(params.end(), {n.x(), n.y(), n.z()});
    }
    paramStart.back() = uint32_t(params.size());
  }
  // A ponytail whose tie sits `off` out from the sphere in direction dir, hanging 2 units down;
  // small drawn circles (radius 0.05), so its thickness is the hair's.
  // `pressed`: where the stroke began on the head (default: under the tie, along dir).
  void ponytail(const Vector3d& dir, bool section, double off = 0.08,
                const Vector3d& pressed = Vector3d::Zero()) {
    std::vector<Vector3d> spine;
    Vector3d p = dir.normalized() * (1 + off);
    spine.push_back((pressed.isZero() ? dir : pressed).normalized() * 0.98);
    for (int i = 0; i < 24; ++i) {
      spine.push_back(p);
      const Vector3d out = Vector3d(p.x(), 0, p.z()).normalized();
      p += 0.1 * (i < 2 ? (0.7 * out - 0.7 * Vector3d::UnitY()).normalized() : -Vector3d::UnitY());
    }
    std::vector<double> prm = {0.6, 1, section ? 1.0 : 0.0};
    std::vector<double> circles;
    int m = 0;
    for (size_t i = 1; i + 1 < spine.size(); i += 2) {
      const Vector3d t = (spine[i + 1] - spine[i - 1]).normalized();
      circles.insert(circles.end(),
                     {spine[i].x(), spine[i].y(), spine[i].z(), t.x(), t.y(), t.z(), 0.05});
      ++m;
    }
    prm.push_back(m);
    prm.insert(prm.end(), circles.begin(), circles.end());
    add(CurveKindCode::Ponytail, spine, prm);
  }
  void braid(const Vector3d& dir) {
    std::vector<Vector3d> pts;
    Vector3d p = dir.normalized() * 1.02;
    pts.push_back(p);
    p = dir.normalized() * 1.12;
    for (int i = 0; i < 16; ++i) {
      pts.push_back(p);
      p += 0.1 * -Vector3d::UnitY();
    }
    add(CurveKindCode::Braid, pts, {0.3, 6, 0.5, 0.4, 1});
  }
  void bun(const Vector3d& dir) {
    const Vector3d n = dir.normalized();
    const Vector3d u = n.cross(Vector3d::UnitX()).normalized(), v = n.cross(u);
    std::vector<Vector3d> loop;
    for (int i = 0; i <= 24; ++i) {
      const double a = 2 * kPi * i / 24;
      loop.push_back((n + 0.2 * (std::cos(a) * u + std::sin(a) * v)).normalized() * 1.01);
    }
    add(CurveKindCode::Bun, loop, {0, 0.35, 2.5, 1});
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
  // A coarse grid (the field does not place gathered hair), natural fall, sections on (and the
  // session's ties when `ties`).
  void run(HairEngine& e, uint32_t seed = 7, bool sections = true, bool ties = false) const {
    Grid g;
    g.origin = Vector3d(-1.75, -3.25, -1.75);
    g.step = 0.25;
    g.nx = 15;
    g.ny = 20;
    g.nz = 15;
    ASSERT_TRUE(e.setGrid(g, kDefaultOmega, "exact").ok());
    ASSERT_TRUE(e.setScalp(head.positions.data(), head.positions.size() / 3, head.indices.data(),
                           head.indices.size() / 3, head.scalp.data(), Vector3d::Zero())
                    .ok());
    double settings[kEngineSettingCount] = {};
    settings[kSettingFall] = 1;
    settings[kSettingSections] = sections ? 1 : 0;
    settings[kSettingTies] = ties ? 1 : 0;
    ASSERT_TRUE(e.setSettings(settings, kEngineSettingCount).ok());
    ASSERT_TRUE(e.setCurves(view()).ok());
    ASSERT_TRUE(e.solve().ok());
    RootParams rp;
    rp.thetaStepDeg = 3;
    rp.phiStepDeg = 3;
    rp.seed = seed;
    GrowthParams gp;
    gp.maxLength = 4;
    gp.maxSegments = 200;
    ASSERT_TRUE(e.grow(rp, gp).ok());
  }
};

// Of the strands whose root passes `in`, the share the curve `curve` laid.
template <typename In>
double share(const HairEngine& e, int curve, In in) {
  size_t total = 0, taken = 0;
  const std::vector<int32_t>& by = e.strandTailCurves();
  const Strands& s = e.strands();
  for (size_t k = 0; k < by.size(); ++k) {
    const float* r = &s.points[3 * s.strandStart[k]];
    if (!in(Vector3d(r[0], r[1], r[2]))) continue;
    ++total;
    taken += by[k] == curve;
  }
  return total ? double(taken) / double(total) : 0;
}

// The gathered strands' spread 2 units below the head (2 std of their crossing points of the
// plane y = yAt, averaged over both axes).
double spreadAt(const HairEngine& e, int curve, double yAt) {
  const Strands& s = e.strands();
  std::vector<Eigen::Vector2d> pts;
  for (size_t k = 0; k + 1 < s.strandStart.size(); ++k) {
    if (e.strandTailCurves()[k] != curve) continue;
    for (uint32_t q = s.strandStart[k]; q + 1 < s.strandStart[k + 1]; ++q) {
      const double y0 = s.points[3 * q + 1], y1 = s.points[3 * q + 4];
      if ((y0 - yAt) * (y1 - yAt) > 0 || y0 == y1) continue;
      const double f = (y0 - yAt) / (y0 - y1);
      pts.emplace_back(s.points[3 * q] + f * (s.points[3 * q + 3] - s.points[3 * q]),
                       s.points[3 * q + 2] + f * (s.points[3 * q + 5] - s.points[3 * q + 2]));
      break;
    }
  }
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p;
  mean /= double(std::max<size_t>(pts.size(), 1));
  double var = 0;
  for (const auto& p : pts) var += (p - mean).squaredNorm();
  return 2 * std::sqrt(var / double(std::max<size_t>(pts.size(), 1)) / 2);
}

std::vector<Vector3f> sphereRoots() {
  std::vector<Vector3f> roots;
  for (double t = 1; t < 104; t += 1.5)
    for (double p = 0; p < 360; p += 1.5) {
      const double a = t * kPi / 180, b = p * kPi / 180;
      roots.emplace_back(float(std::sin(a) * std::sin(b)), float(std::cos(a)),
                         float(std::sin(a) * std::cos(b)));
    }
  return roots;
}

std::vector<std::vector<Vector3f>> asFloat(const std::vector<Vector3d>& line) {
  std::vector<Vector3f> out;
  for (const Vector3d& p : line) out.push_back(p.cast<float>());
  return {out};
}

}  // namespace

TEST(ScalpSections, PartingsThatReachTheEdgeSplitTheScalpAndOthersDoNot) {
  const std::vector<Vector3f> roots = sphereRoots();
  ScalpSections none;
  none.build(roots, Vector3f::Zero(), {});
  EXPECT_EQ(none.count(), 1);
  // a centre parting from the front hairline to the nape, stopping 6 degrees short of the edge
  ScalpSections centre;
  centre.build(roots, Vector3f::Zero(), asFloat(partingInPlane(Vector3d::UnitX(), 0)));
  ASSERT_EQ(centre.count(), 2);
  size_t wrong = 0, total = 0;
  const int left = centre.section(Vector3f(0.7f, 0.7f, 0)),
            right = centre.section({-0.7f, 0.7f, 0});
  EXPECT_NE(left, right);
  for (const Vector3f& r : roots) {
    if (std::abs(r.x()) < 0.05f) continue;  // on the parting
    ++total;
    wrong += centre.section(r) != (r.x() > 0 ? left : right);
  }
  EXPECT_EQ(wrong, 0u) << "of " << total;
  // a parting from the forehead to the crown only bounds nothing
  std::vector<Vector3d> half = partingInPlane(Vector3d::UnitX(), 0);
  half.resize(half.size() / 2);
  ScalpSections open;
  open.build(roots, Vector3f::Zero(), asFloat(half));
  EXPECT_EQ(open.count(), 1);
}

// Ties from any hand: a parting that a stylist ends a little short of the hairline (0.5 to
// 3.8 cm on this 10 cm sphere) still closes its section, the roots on each side of its plane
// falling on their own side, and 4.8 cm; 7.5 cm short it stays open. Without closing near, 3.8 cm
// short is past the old 3.5 cm run-on and bounds nothing (what users met).
TEST(ScalpSections, APartingEndingShortOfTheEdgeClosesWithinFourCentimetres) {
  const std::vector<Vector3f> roots = sphereRoots();
  // over the crown from ear to ear, a little behind the top (a half-up's parting)
  const Vector3d n = Vector3d(0, 0.25, 1).normalized();
  const double d = -0.2;
  // the scalp's raster reaches y = -0.25 (the last roots at 101.5 degrees, grown by two cells)
  for (double shortOf : {0.05, 0.15, 0.25, 0.38}) {
    ScalpSections s;
    s.build(roots, Vector3f::Zero(), asFloat(partingInPlane(n, d, shortOf)), true);
    ASSERT_EQ(s.count(), 2) << shortOf * 10 << " cm short";
    const int front = s.section(Vector3f(0, 0.8f, 0.6f)), back = s.section({0, 0.2f, -0.98f});
    EXPECT_NE(front, back);
    size_t wrong = 0, total = 0;
    for (const Vector3f& r : roots) {
      const double side = r.cast<double>().dot(n) - d;
      if (std::abs(side) < 0.08) continue;  // on the parting or its run-on
      ++total;
      wrong += s.section(r) != (side > 0 ? front : back);
    }
    EXPECT_LE(double(wrong), 0.002 * double(total)) << shortOf * 10 << " cm short";
  }
  ScalpSections old;
  old.build(roots, Vector3f::Zero(), asFloat(partingInPlane(n, d, 0.38)), false);
  EXPECT_EQ(old.count(), 1);
  // 4.8 cm short (a parting drawn from above to the head's outline) closes too
  ScalpSections outline;
  outline.build(roots, Vector3f::Zero(), asFloat(partingInPlane(n, d, 0.48)), true);
  EXPECT_EQ(outline.count(), 2);
  ScalpSections far;
  far.build(roots, Vector3f::Zero(), asFloat(partingInPlane(n, d, 0.75)), true);
  EXPECT_EQ(far.count(), 1);
}

// A side parting from the hairline above the left ear towards a centre parting, stopping 4.2 cm
// short of it, meets it: three sections (the left front, the left back, the right); the old
// 3.5 cm run-on does not reach it.
TEST(ScalpSections, APartingEndingShortOfAnotherMeetsIt) {
  const std::vector<Vector3f> roots = sphereRoots();
  std::vector<Vector3d> centre = partingInPlane(Vector3d::UnitX(), 0);
  // in the plane z = 0 from the left edge up towards the top, stopping at x = sin(0.42)
  std::vector<Vector3d> side;
  for (double a = 104; a > 0; a -= 1) {
    const double t = a * kPi / 180;
    if (std::sin(t) < std::sin(0.42)) break;
    side.push_back(Vector3d(std::sin(t), std::cos(t), 0) * 1.01);
  }
  std::vector<std::vector<Vector3f>> both = asFloat(centre);
  both.push_back(asFloat(side)[0]);
  ScalpSections s;
  s.build(roots, Vector3f::Zero(), both, true);
  ASSERT_EQ(s.count(), 3);
  const int leftFront = s.section({0.6f, 0.6f, 0.5f}), leftBack = s.section({0.6f, 0.6f, -0.5f});
  const int right = s.section({-0.6f, 0.6f, 0});
  EXPECT_NE(leftFront, leftBack);
  EXPECT_NE(leftFront, right);
  EXPECT_NE(leftBack, right);
  ScalpSections open;
  open.build(roots, Vector3f::Zero(), both, false);
  EXPECT_EQ(open.count(), 2);
}

// Hair at a parting goes the way it is combed: a strand rooted 5 mm left of a centre parting
// belongs to the left while it sets off left or along the line, and to the right when its
// first 1.5 cm cross the line; a strand shorter than the reach counts at its tip.
TEST(ScalpSections, AStrandBelongsToTheSideItIsCombedTo) {
  ScalpSections centre;
  centre.build(sphereRoots(), Vector3f::Zero(), asFloat(partingInPlane(Vector3d::UnitX(), 0)));
  ASSERT_EQ(centre.count(), 2);
  const int left = centre.section(Vector3f(0.7f, 0.7f, 0)),
            right = centre.section({-0.7f, 0.7f, 0});
  const Vector3f root = Vector3f(0.05f, 1, 0.2f).normalized();
  auto strand = [&](const Vector3f& dir, int n, float step) {
    std::vector<float> p;
    for (int i = 0; i < n; ++i) {
      const Vector3f q = root + float(i) * step * dir;
      p.insert(p.end(), {q.x(), q.y(), q.z()});
    }
    return p;
  };
  ASSERT_EQ(centre.section(root), left);
  const std::vector<float> out = strand(Vector3f(1, 0, 0), 10, 0.05f);
  const std::vector<float> along = strand(Vector3f(0, 0, 1), 10, 0.05f);
  const std::vector<float> across = strand(Vector3f(-1, 0, 0), 10, 0.05f);
  const std::vector<float> stub = strand(Vector3f(-1, 0, 0), 3, 0.05f);  // 1 cm: its tip
  EXPECT_EQ(centre.combedSection(out.data(), 10, 0.15f), left);
  EXPECT_EQ(centre.combedSection(along.data(), 10, 0.15f), left);
  EXPECT_EQ(centre.combedSection(across.data(), 10, 0.15f), right);
  EXPECT_EQ(centre.combedSection(stub.data(), 3, 0.15f), right);
  EXPECT_EQ(centre.combedSection(across.data(), 1, 0.15f), left);  // a root alone
}

TEST(SectionTies, WithNoPartingEveryTieKindGathersTheWholeHead) {
  const auto all = [](const Vector3d&) { return true; };
  for (int kind = 0; kind < 3; ++kind) {
    Scene sc;
    const Vector3d back(0, 0.45, -1);
    if (kind == 0) sc.ponytail(back, true);
    if (kind == 1) sc.braid(Vector3d(0, 0.2, -1));
    if (kind == 2) sc.bun(back);
    HairEngine e;
    sc.run(e);
    const double got = share(e, 0, all);
    std::printf("[sections] kind %d gathers %.1f %% of the head\n", kind, 100 * got);
    EXPECT_GE(got, 0.95) << "kind " << kind;
    if (kind == 2) {
      // a whole head of 40 cm hair coils into a bun about 8-10 cm across: the widest extent of
      // its strands' points square to the bun's axis (off the scalp, more than 1 cm out)
      const Vector3d axis = back.normalized();
      const Vector3d c = axis * 1.0;
      const Strands& st = e.strands();
      double widest = 0;
      for (size_t k = 0; k + 1 < st.strandStart.size(); ++k) {
        if (e.strandTailCurves()[k] != 0) continue;
        for (uint32_t q = st.strandStart[k]; q < st.strandStart[k + 1]; ++q) {
          const Vector3d p(st.points[3 * q], st.points[3 * q + 1], st.points[3 * q + 2]);
          if ((p - c).dot(axis) < 0.1) continue;
          const Vector3d r = (p - c) - (p - c).dot(axis) * axis;
          widest = std::max(widest, r.norm());
        }
      }
      std::printf("[sections] the bun of a whole head of 40 cm hair: %.1f cm across\n",
                  20 * widest);
      EXPECT_GE(20 * widest, 7.0);
      EXPECT_LE(20 * widest, 11.0);
    }
  }
}

TEST(SectionTies, ACentrePartingAndMirroredTiesGatherOneSideEach) {
  Scene sc;
  sc.parting(partingInPlane(Vector3d::UnitX(), 0));
  sc.ponytail(Vector3d(0.9, 0.3, -0.4), true);
  sc.ponytail(Vector3d(-0.9, 0.3, -0.4), true);
  HairEngine e;
  sc.run(e);
  const auto leftSide = [](const Vector3d& r) { return r.x() > 0.03; };
  const auto rightSide = [](const Vector3d& r) { return r.x() < -0.03; };
  const double ll = share(e, 1, leftSide), lr = share(e, 1, rightSide);
  const double rr = share(e, 2, rightSide), rl = share(e, 2, leftSide);
  std::printf("[sections] pigtails: left tie %.1f %% / %.1f %%, right tie %.1f %% / %.1f %%\n",
              100 * ll, 100 * lr, 100 * rr, 100 * rl);
  EXPECT_GE(ll, 0.95);
  EXPECT_GE(rr, 0.95);
  EXPECT_LT(lr, 0.05);
  EXPECT_LT(rl, 0.05);
}

TEST(SectionTies, HalfUpGathersTheTopSectionAndLeavesTheRestLoose) {
  // an ear-to-ear parting over the crown in the plane z = -0.35; the tie behind the crown
  Scene sc;
  sc.parting(partingInPlane(Vector3d::UnitZ(), -0.35));
  sc.ponytail(Vector3d(0, 0.85, -0.2), true, 0.05);
  HairEngine e;
  sc.run(e);
  const auto top = [](const Vector3d& r) { return r.z() > -0.32; };
  const auto rest = [](const Vector3d& r) { return r.z() < -0.38; };
  const double t = share(e, 1, top), b = share(e, 1, rest);
  std::printf("[sections] half-up: top %.1f %%, rest %.1f %%\n", 100 * t, 100 * b);
  EXPECT_GE(t, 0.95);
  EXPECT_LT(b, 0.05);
}

TEST(SectionTies, WithTiesOnATieGathersTheSectionItsStrokeWasPressedIn) {
  // the half-up parting (z = -0.35); the stroke pressed in front of it, on the top section
  // (z -0.27), its band behind it (z -0.55): with ties on it gathers the top, as the hand meant;
  // with ties off (sessions saved before) the section under its band, as before
  const auto top = [](const Vector3d& r) { return r.z() > -0.32; };
  const auto rest = [](const Vector3d& r) { return r.z() < -0.38; };
  double shares[2][2];
  for (int on = 0; on < 2; ++on) {
    Scene sc;
    sc.parting(partingInPlane(Vector3d::UnitZ(), -0.35));
    sc.ponytail(Vector3d(0, 0.84, -0.55), true, 0.05, Vector3d(0, 0.96, -0.27));
    HairEngine e;
    sc.run(e, 7, true, on == 1);
    shares[on][0] = share(e, 1, top);
    shares[on][1] = share(e, 1, rest);
    std::printf("[sections] pressed in front of the parting, ties %s: top %.1f %%, rest %.1f %%\n",
                on ? "on" : "off", 100 * shares[on][0], 100 * shares[on][1]);
  }
  EXPECT_LT(shares[0][0], 0.05);  // ties off: the band's section, behind
  EXPECT_GE(shares[0][1], 0.95);
  EXPECT_GE(shares[1][0], 0.95);  // ties on: the pressed section, the top
  EXPECT_LT(shares[1][1], 0.05);
}

TEST(SectionTies, TheTailHoldsItsHairAndTheCombedHairLiesOnTheScalp) {
  // the same tie at the back: of the whole head, and of one side (a centre parting)
  Scene whole, halfHead;
  const Vector3d back(0, 0.3, -1);
  whole.ponytail(back, true);
  halfHead.parting(partingInPlane(Vector3d::UnitX(), 0));
  halfHead.ponytail(Vector3d(0.25, 0.3, -1), true);
  HairEngine a, b;
  whole.run(a);
  halfHead.run(b);
  size_t na = 0, nb = 0;
  for (int32_t c : a.strandTailCurves()) na += c == 0;
  for (int32_t c : b.strandTailCurves()) nb += c == 1;
  const double ra = spreadAt(a, 0, -1.4), rb = spreadAt(b, 1, -1.4);
  std::printf(
      "[sections] tail spread %.3f for %zu strands, %.3f for %zu: ratio %.3f, "
      "sqrt of the counts' %.3f\n",
      ra, na, rb, nb, ra / rb, std::sqrt(double(na) / double(nb)));
  EXPECT_NEAR(ra / rb, std::sqrt(double(na) / double(nb)), 0.12 * std::sqrt(double(na) / nb));
  // between the root and the tie (points farther than 0.3 from the tie's centre, above it) no
  // gathered strand is more than 1.5 cm off the sphere
  const Vector3d tie = back.normalized() * 1.08;
  const Strands& s = a.strands();
  double worst = 0;
  for (size_t k = 0; k + 1 < s.strandStart.size(); ++k) {
    if (a.strandTailCurves()[k] != 0) continue;
    for (uint32_t q = s.strandStart[k]; q < s.strandStart[k + 1]; ++q) {
      const Vector3d p(s.points[3 * q], s.points[3 * q + 1], s.points[3 * q + 2]);
      if ((p - tie).norm() < 0.3) break;  // at the tie
      worst = std::max(worst, p.norm() - 1);
    }
  }
  std::printf("[sections] combed hair: at most %.2f cm off the scalp\n", 10 * worst);
  EXPECT_LE(worst, 0.15);
}

TEST(SectionTies, TheSameSeedGrowsTheSameStrandsAndSectionsOffKeepTheOldHair) {
  Scene sc;
  sc.parting(partingInPlane(Vector3d::UnitX(), 0));
  sc.ponytail(Vector3d(0.9, 0.3, -0.4), true);
  HairEngine a, b, off, old;
  sc.run(a, 7);
  sc.run(b, 7);
  ASSERT_EQ(a.strands().points.size(), b.strands().points.size());
  EXPECT_EQ(std::memcmp(a.strands().points.data(), b.strands().points.data(),
                        a.strands().points.size() * sizeof(float)),
            0);
  // sections off: the tie's section flag changes nothing (the hair of a tie without it)
  Scene plain;
  plain.parting(partingInPlane(Vector3d::UnitX(), 0));
  plain.ponytail(Vector3d(0.9, 0.3, -0.4), false);
  sc.run(off, 7, false);
  plain.run(old, 7, false);
  ASSERT_EQ(off.strands().points.size(), old.strands().points.size());
  EXPECT_EQ(std::memcmp(off.strands().points.data(), old.strands().points.data(),
                        off.strands().points.size() * sizeof(float)),
            0);
}

}  // namespace scalp_sections_test
