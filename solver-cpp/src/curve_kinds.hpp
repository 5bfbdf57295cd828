// The curve kinds (CurveKindCode, curveParams.ts CurveKind), one entry each: what the solver does
// with a curve of that kind. Its constraints (stream_constraints.hpp, dividing_constraints.hpp,
// ponytail_constraints.hpp, braid_bun.hpp), the tail it lays in growth (gathered_tail.hpp:
// a gathered ponytail, a braid, a bun), and whether its reach ends hair under natural fall or it
// bounds the scalp's sections. curve_set.cpp and hair_engine.cpp look a kind up here instead of
// branching on it, so a new kind is one entry in curve_kinds.cpp.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "constraint_colour.hpp"
#include "constraints.hpp"
#include "curve_set.hpp"
#include "gathered_tail.hpp"
#include "grid.hpp"
#include "status.hpp"

namespace hairsketch {

// One curve of a CurveSetView as its kind sees it (non-owning).
struct KindCurve {
  const double* points = nullptr;  // points[3 * point + axis], count points
  size_t count = 0;
  bool extend = false;             // its hair grows on past the curve
  const double* params = nullptr;  // its parameter block (curve_params.hpp), paramCount numbers
  size_t paramCount = 0;
  const uint8_t* offScalp = nullptr;  // count entries, or null (CurveSetView::offScalp)
  const Eigen::Vector3d* headCentre = nullptr;
};

// Curve c of a well-formed view (curveStart, and paramStart when present, checked).
KindCurve kindCurve(const CurveSetView& curves, size_t c);

// What the engine knows when it builds a curve's tail.
struct TailContext {
  bool fall = false;  // natural fall is on (a ponytail lays its gathered tail only then)
  // Away from the head at the curve's first point (zero: no head).
  Eigen::Vector3f away = Eigen::Vector3f::Zero();
};

struct CurveKindDef {
  CurveKindCode code;
  const char* name;  // in messages: "curves: curve 3 (braid): ..."
  // Parses and checks the curve's parameters, then appends its raw constraints (and with
  // colours, one colour each). who names the curve in an error ("curves: curve 3 (braid)").
  Status (*constraints)(const Grid& grid, const KindCurve& curve, const std::string& who,
                        std::vector<Constraint>& raw, std::vector<ConstraintColour>* colours);
  // The tail the curve lays in growth, or null: its kind lays none. Returns false when this
  // curve lays none (parameters that do not parse, or no tail asked for).
  bool (*tail)(const KindCurve& curve, const TailContext& context, GatheredTail& out);
  bool reach;    // under natural fall its reach ends its hair (hair_fall.hpp ReachCurve)
  bool parting;  // a parting: it bounds the scalp's sections (scalp_sections.hpp)
};

// The entry of a CurveSetView kind code, or null for an unknown one.
const CurveKindDef* curveKind(uint8_t code);

}  // namespace hairsketch
