"""Checks a hairsketch .usda export with Pixar's own reader (usd-core, in build/usd-venv).

usage: check_usd.py FILE.usda --box XMIN YMIN ZMIN XMAX YMAX ZMAX

Opens the stage with pxr.Usd.Stage.Open and checks, on the BasisCurves prim /hairsketch/hair:
  - curveVertexCounts: every count 2..255, their sum = the number of points (usd-core's own
    validators do not check this, see docs/export.md);
  - type "linear", widths: one per point, finite and > 0;
  - points: finite and inside the box;
  - primvars:displayColor: one colour per curve;
  - the layer: metersPerUnit 0.1, upAxis Y, defaultPrim /hairsketch.
On success prints ONE line on stdout: the JSON of the layer's customLayerData
"hairsketch:session", compact, for the caller to compare with the session it exported; a summary
goes to stderr. On any failure: a message on stderr and exit status 1 (2 for bad arguments).
"""

import argparse
import array
import json
import math
import sys

MAX_POINTS_PER_CURVE = 255


class CheckFailed(Exception):
    pass


def require(ok, message):
    if not ok:
        raise CheckFailed(message)


def floats(vt_array):
    """The float32 values of a Vt float / Vec3f array, flat (through its buffer: fast)."""
    view = memoryview(vt_array)
    require(view.format == "f", f"expected float32 values, got buffer format {view.format}")
    out = array.array("f")
    out.frombytes(view.cast("B"))
    return out


def all_finite(values):
    """True when every value is finite (one inf or nan makes the exact sum non-finite)."""
    try:
        return math.isfinite(math.fsum(values))
    except (OverflowError, ValueError):  # inf - inf
        return False


def check(path, box):
    from pxr import Usd, UsdGeom  # imported here: a missing usd-core is reported, not a trace

    stage = Usd.Stage.Open(path)
    require(stage is not None, "Usd.Stage.Open returned nothing")

    mpu = UsdGeom.GetStageMetersPerUnit(stage)
    require(
        UsdGeom.StageHasAuthoredMetersPerUnit(stage) and abs(mpu - 0.1) < 1e-12,
        f"metersPerUnit is {mpu}, not an authored 0.1",
    )
    up = UsdGeom.GetStageUpAxis(stage)
    require(up == UsdGeom.Tokens.y, f"upAxis is {up}, not Y")
    default_prim = stage.GetDefaultPrim()
    require(
        default_prim and str(default_prim.GetPath()) == "/hairsketch",
        f"defaultPrim is {default_prim.GetPath() if default_prim else None}, not /hairsketch",
    )

    prim = stage.GetPrimAtPath("/hairsketch/hair")
    require(prim.IsValid(), "no prim /hairsketch/hair")
    require(prim.IsA(UsdGeom.BasisCurves), f"/hairsketch/hair is a {prim.GetTypeName()}, not BasisCurves")
    curves = UsdGeom.BasisCurves(prim)

    curve_type = curves.GetTypeAttr().Get()
    require(curve_type == UsdGeom.Tokens.linear, f'curve type is "{curve_type}", not "linear"')

    counts = curves.GetCurveVertexCountsAttr().Get()
    require(counts is not None and len(counts) > 0, "curveVertexCounts is empty")
    counts = list(counts)
    for i, c in enumerate(counts):
        require(
            2 <= c <= MAX_POINTS_PER_CURVE,
            f"curveVertexCounts[{i}] = {c}, not within 2..{MAX_POINTS_PER_CURVE}",
        )

    points = curves.GetPointsAttr().Get()
    require(points is not None, "no points")
    n_points = len(points)
    require(
        sum(counts) == n_points,
        f"curveVertexCounts sum to {sum(counts)} but there are {n_points} points",
    )
    xyz = floats(points)
    require(len(xyz) == 3 * n_points, "points are not 3 floats each")
    lo, hi = box[:3], box[3:]
    if not all_finite(xyz):
        i = next(k for k, v in enumerate(xyz) if not math.isfinite(v)) // 3
        raise CheckFailed(f"points[{i}] is not finite: {tuple(points[i])}")
    for a in range(3):
        axis = xyz[a::3]
        if n_points and (min(axis) < lo[a] or max(axis) > hi[a]):
            i = next(k for k, v in enumerate(axis) if not lo[a] <= v <= hi[a])
            raise CheckFailed(f"points[{i}] = {tuple(points[i])} is outside the box {box}")

    widths = curves.GetWidthsAttr().Get()
    require(widths is not None, "no widths")
    require(len(widths) == n_points, f"{len(widths)} widths for {n_points} points")
    interp = curves.GetWidthsInterpolation()
    require(interp == UsdGeom.Tokens.vertex, f'widths interpolation is "{interp}", not "vertex"')
    w = floats(widths)
    if n_points and not (all_finite(w) and min(w) > 0):
        i = next(k for k, v in enumerate(w) if not (math.isfinite(v) and v > 0))
        raise CheckFailed(f"widths[{i}] = {w[i]} is not a finite positive width")

    colours = curves.GetDisplayColorPrimvar()
    require(colours and colours.HasValue(), "no primvars:displayColor")
    colour_values = colours.Get()
    require(
        len(colour_values) == len(counts),
        f"{len(colour_values)} displayColor values for {len(counts)} curves",
    )

    data = stage.GetRootLayer().customLayerData
    text = data.get("hairsketch:session")
    require(isinstance(text, str), "customLayerData has no string hairsketch:session")
    try:
        session = json.loads(text)
    except ValueError as e:
        raise CheckFailed(f"hairsketch:session is not JSON: {e}") from None
    return session, len(counts), n_points


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("file")
    parser.add_argument("--box", nargs=6, type=float, required=True, metavar="V")
    args = parser.parse_args(argv)
    try:
        session, n_curves, n_points = check(args.file, args.box)
    except CheckFailed as e:
        print(f"check_usd: {args.file}: {e}", file=sys.stderr)
        return 1
    except Exception as e:  # the reader's own errors (a malformed layer) are failures too
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        print(f"check_usd: {args.file}: {type(e).__name__}: {first}", file=sys.stderr)
        return 1
    print(json.dumps(session, separators=(",", ":"), ensure_ascii=False))
    print(f"check_usd: ok, {n_curves} curves, {n_points} points", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
