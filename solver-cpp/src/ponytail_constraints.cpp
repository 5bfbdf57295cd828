#include "ponytail_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "stream_constraints.hpp"

namespace hairsketch {

namespace {

// Calls fn(i, j, k, position) for every grid point within the world-space box centre +- half.
template <class Fn>
void forPointsInBox(const Grid& g, const Eigen::Vector3d& centre, double half, Fn&& fn) {
  const Eigen::Vector3d lo = (centre.array() - half - g.origin.array()) / g.step;
  const Eigen::Vector3d hi = (centre.array() + half - g.origin.array()) / g.step;
  const int i0 = std::max(0, int(std::ceil(lo.x()))),
            i1 = std::min(g.nx - 1, int(std::floor(hi.x())));
  const int j0 = std::max(0, int(std::ceil(lo.y()))),
            j1 = std::min(g.ny - 1, int(std::floor(hi.y())));
  const int k0 = std::max(0, int(std::ceil(lo.z()))),
            k1 = std::min(g.nz - 1, int(std::floor(hi.z())));
  for (int k = k0; k <= k1; ++k)
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) fn(i, j, k, g.position(i, j, k));
}

// Distance of q to the circle, with the axial offset w, radial distance rho and radial unit e.
struct CircleCoords {
  double w, rho, dist;
  Eigen::Vector3d e;
};

CircleCoords circleCoords(const PonytailCircle& c, const Eigen::Vector3d& q, double tiny) {
  CircleCoords cc;
  const Eigen::Vector3d r = q - c.centre;
  cc.w = r.dot(c.axis);
  const Eigen::Vector3d radial = r - cc.w * c.axis;
  cc.rho = radial.norm();
  cc.e = cc.rho > tiny ? Eigen::Vector3d(radial / cc.rho) : Eigen::Vector3d::Zero();
  cc.dist = std::hypot(cc.w, cc.rho - c.radius);
  return cc;
}

}  // namespace

Status parsePonytailParams(const double* p, size_t count, PonytailParams& out) {
  // The layout (curve_params.hpp): 2 + 7 m numbers without gather, 3 + 7 m with it, 4 + 7 m with
  // gather and section.
  static_assert(kPonytailTightness == 0 && kPonytailGather == 1 && kPonytailSection == 2 &&
                    kPonytailParamCount == 3,
                "the three ponytail layouts below assume tightness, gather, section");
  if (count < 2)
    return Status::Error(
        StatusCode::InvalidInput,
        "ponytail parameter block needs [tightness, (gather,) circles, ...], has " +
            std::to_string(count) + " numbers");
  for (size_t i = 0; i < count; ++i)
    if (!std::isfinite(p[i]))
      return Status::Error(StatusCode::NonFinite,
                           "ponytail parameter " + std::to_string(i) + " is not finite");
  const bool hasSection = count >= 4 && (count - 4) % 7 == 0;
  const bool hasGather = hasSection || (count >= 3 && (count - 3) % 7 == 0);
  const size_t S = hasSection ? 3 : hasGather ? 2 : 1;  // scalars, then the circle count m
  const double m = p[S];
  if (!(m >= 1) || std::floor(m) != m || m > 1e6)
    return Status::Error(StatusCode::InvalidInput,
                         "ponytail circle count must be a positive integer");
  const size_t circles = size_t(m);
  if (count != S + 1 + 7 * circles)
    return Status::Error(StatusCode::InvalidInput,
                         "ponytail parameter block has " + std::to_string(count) +
                             " numbers, expected " + std::to_string(S + 1) + " + 7 * " +
                             std::to_string(circles) + " = " + std::to_string(S + 1 + 7 * circles));
  out.gather = 0;
  if (hasGather) {
    const double g = p[kPonytailGather];
    if (g != 0 && g != 1)
      return Status::Error(StatusCode::InvalidInput, "ponytail gather must be 0 or 1");
    out.gather = int(g);
  }
  out.section = false;
  if (hasSection) {
    const double v = p[kPonytailSection];
    if (v != 0 && v != 1)
      return Status::Error(StatusCode::InvalidInput, "ponytail section must be 0 or 1");
    out.section = v != 0;
  }
  out.tightness = p[kPonytailTightness];
  out.circles.resize(circles);
  for (size_t k = 0; k < circles; ++k) {
    const double* b = p + S + 1 + 7 * k;
    PonytailCircle& c = out.circles[k];
    c.centre = Eigen::Vector3d(b[0], b[1], b[2]);
    const Eigen::Vector3d a(b[3], b[4], b[5]);
    if (!(a.norm() > 0))
      return Status::Error(StatusCode::InvalidInput,
                           "ponytail circle " + std::to_string(k) + " has a zero axis");
    c.axis = a.normalized();
    c.radius = b[6];
    if (!(c.radius > 0))
      return Status::Error(StatusCode::InvalidInput,
                           "ponytail circle " + std::to_string(k) + " radius must be > 0");
  }
  return Status::Ok();
}

std::vector<double> ponytailRadiusSlopes(const PonytailParams& prm) {
  const auto& C = prm.circles;
  const size_t m = C.size();
  std::vector<double> slope(m, 0.0);
  if (m < 2) return slope;
  for (size_t k = 0; k < m; ++k) {
    const size_t a = k == 0 ? 0 : k - 1, b = k + 1 == m ? m - 1 : k + 1;
    const double axial = (C[b].centre - C[a].centre).dot(C[k].axis);
    if (std::abs(axial) > 1e-12) slope[k] = (C[b].radius - C[a].radius) / axial;
  }
  return slope;
}

size_t ponytailBlueStart(const double* spine, size_t n, const PonytailParams& prm) {
  if (n == 0 || prm.circles.empty()) return 0;
  const Eigen::Vector3d c = prm.circles.back().centre;
  size_t best = 0;
  double bestD = INFINITY;
  for (size_t i = 0; i < n; ++i) {
    const double d = (Eigen::Vector3d(spine[3 * i], spine[3 * i + 1], spine[3 * i + 2]) - c).norm();
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  return best;
}

namespace {

// gather = 1 (ponytail_constraints.hpp): the body, the blue spine part and the funnel.
void appendGatheredConstraints(const Grid& g, const double* spine, size_t n, bool extend,
                               const PonytailParams& prm, std::vector<Constraint>& out,
                               std::vector<ConstraintColour>* colours) {
  const double tube = 0.5 * std::sqrt(3.0) * g.step;
  const double tiny = 1e-9 * g.step;
  const auto& C = prm.circles;
  // (1) purple, the body: the frusta between consecutive circles (a lone circle: its disc).
  for (size_t k = 0; k < C.size(); ++k) {
    const PonytailCircle& A = C[k];
    const PonytailCircle& B = C[k + 1 < C.size() ? k + 1 : k];
    const Eigen::Vector3d seg = B.centre - A.centre;
    const double len2 = seg.squaredNorm();
    if (k + 1 == C.size() && C.size() > 1) break;
    const double reach = std::max(A.radius, B.radius) * 1.5 + tube;
    const Eigen::Vector3d mid = 0.5 * (A.centre + B.centre);
    forPointsInBox(
        g, mid, 0.5 * std::sqrt(len2) + reach, [&](int i, int j, int kk, const Eigen::Vector3d& q) {
          double t = 0;
          if (len2 > tiny * tiny) {
            t = (q - A.centre).dot(seg) / len2;
            if (t < 0 || t > 1) return;
          }
          const Eigen::Vector3d c = A.centre + t * seg;
          const Eigen::Vector3d a = ((1 - t) * A.axis + t * B.axis).normalized();
          const double R = (1 - t) * A.radius + t * B.radius;
          const Eigen::Vector3d rel = q - c;
          const double w = rel.dot(a);
          if (len2 <= tiny * tiny && std::abs(w) > 0.5 * g.step) return;
          const Eigen::Vector3d radial = rel - w * a;
          const double rho = radial.norm();
          const double shell = std::max(tube, 0.5 * R);
          if (rho > R + shell) return;
          const Eigen::Vector3d e =
              rho > tiny ? Eigen::Vector3d(radial / rho) : Eigen::Vector3d::Zero();
          const double axial = seg.dot(a);
          const double slope = std::abs(axial) > 1e-12 ? (B.radius - A.radius) / axial : 0.0;
          const double radialPart =
              rho <= R ? slope * rho / R : slope - kPonytailHold * (rho - R) / shell;
          out.push_back({g.index(i, j, kk), (a + radialPart * e).normalized()});
          if (colours) colours->push_back(ConstraintColour::Purple);
        });
  }
  // (2) blue, the spine from near the last circle on.
  const size_t start = ponytailBlueStart(spine, n, prm);
  if (n > start + 1) appendStreamConstraints(g, spine + 3 * start, n - start, extend, out, colours);
  // (3) green, the funnel from C1 back to the scalp.
  const PonytailCircle& c1 = C.front();
  double back = 0;  // L: how far back (along -a) the funnel reaches
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d p(spine[3 * i], spine[3 * i + 1], spine[3 * i + 2]);
    back = std::max(back, -(p - c1.centre).dot(c1.axis));
  }
  back += g.step;
  const double mouth = std::max(kPonytailRingOuter * c1.radius, c1.radius + 2 * g.step);
  const double widest = mouth + kPonytailFunnelSlope * back;
  forPointsInBox(g, c1.centre - 0.5 * back * c1.axis, std::hypot(0.5 * back, widest),
                 [&](int i, int j, int k, const Eigen::Vector3d& q) {
                   const CircleCoords cc = circleCoords(c1, q, tiny);
                   if (cc.w > 0 || cc.w < -back) return;
                   const double F = mouth + kPonytailFunnelSlope * -cc.w;
                   if (cc.rho > F) return;
                   const Eigen::Vector3d aim = c1.centre + c1.radius * std::sqrt(cc.rho / F) * cc.e;
                   const Eigen::Vector3d d = aim - q;
                   const double dn = d.norm();
                   // on C1's disc itself: along the axis
                   const Eigen::Vector3d dir =
                       dn > 0.25 * g.step ? Eigen::Vector3d(d / dn) : c1.axis;
                   out.push_back({g.index(i, j, k), prm.tightness * dir});
                   if (colours) colours->push_back(ConstraintColour::Green);
                 });
}

}  // namespace

void appendPonytailConstraints(const Grid& g, const double* spine, size_t n, bool extend,
                               const PonytailParams& prm, std::vector<Constraint>& out,
                               std::vector<ConstraintColour>* colours) {
  if (prm.gather == 1 && !prm.circles.empty()) {
    appendGatheredConstraints(g, spine, n, extend, prm, out, colours);
    return;
  }
  const double tube = 0.5 * std::sqrt(3.0) * g.step;
  const double tiny = 1e-9 * g.step;
  const std::vector<double> slope = ponytailRadiusSlopes(prm);
  // (1) purple, near each circle.
  for (size_t k = 0; k < prm.circles.size(); ++k) {
    const PonytailCircle& c = prm.circles[k];
    forPointsInBox(g, c.centre, c.radius + tube,
                   [&](int i, int j, int kk, const Eigen::Vector3d& q) {
                     const CircleCoords cc = circleCoords(c, q, tiny);
                     if (cc.dist > tube) return;
                     out.push_back({g.index(i, j, kk), (c.axis + slope[k] * cc.e).normalized()});
                     if (colours) colours->push_back(ConstraintColour::Purple);
                   });
  }
  // (2) blue, the spine from near the last circle on.
  const size_t start = ponytailBlueStart(spine, n, prm);
  if (n > start + 1) appendStreamConstraints(g, spine + 3 * start, n - start, extend, out, colours);
  // (3) green, the centripetal ring on C1's plane.
  if (prm.circles.empty()) return;
  const PonytailCircle& c1 = prm.circles.front();
  const double outer = kPonytailRingOuter * c1.radius, inner = kPonytailRingInner * c1.radius;
  forPointsInBox(g, c1.centre, outer + g.step, [&](int i, int j, int k, const Eigen::Vector3d& q) {
    const CircleCoords cc = circleCoords(c1, q, tiny);
    if (std::abs(cc.w) > 0.5 * g.step || cc.rho < inner || cc.rho > outer) return;
    if (cc.dist <= tube) return;  // purple owns it
    out.push_back({g.index(i, j, k), prm.tightness * (c1.centre - q).normalized()});
    if (colours) colours->push_back(ConstraintColour::Green);
  });
}

}  // namespace hairsketch
