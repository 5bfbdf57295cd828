"""Checks a hairsketch .usda export with Pixar's own reader (usd-core, in build/usd-venv).

usage: check_usd.py FILE.usda --box XMIN YMIN ZMIN XMAX YMAX ZMAX [--dump FILE.json]

Opens the stage with pxr.Usd.Stage.Open and checks, on each BasisCurves prim of the groom
(/hairsketch/groom/hair, the strands, and /hairsketch/groom/guides):
  - curveVertexCounts: every count 2..255, their sum = the number of points (usd-core's own
    validators do not check this, see docs/export.md);
  - type "linear", widths: one per point, finite and > 0;
  - points: finite and inside the box;
  - primvars:displayColor: one colour per curve;
  - the groom_* primvars as Unreal's USD groom reader takes them: each has the type and
    interpolation of GROOM_PRIMVARS and one value per curve (uniform) or per point (vertex);
    groom_guide 0 on the strands, 1 on the guides; groom_id unique in each prim; a group id
    always with the same group name; root UVs in [0, 1] and surface_uv_coordinate equal to them;
    fewer guides than strands, every guide a copy of the strand with its id (so it lies on a
    strand), every group with a guide; each strand's closest guides are guides of its group,
    their weights >= 0 summing to 1;
and on /hairsketch/groom: an Xform with the GroomAPI schema applied. The layer: metersPerUnit
0.1, upAxis Y, defaultPrim /hairsketch.
On success prints ONE line on stdout: the JSON of the layer's customLayerData
"hairsketch:session", compact, for the caller to compare with the session it exported; a summary
goes to stderr. --dump writes the strands' roots, ids and groups, and the guides' ids, as JSON.
On any failure: a message on stderr and exit status 1 (2 for bad arguments).
"""

import argparse
import array
import json
import math
import sys

MAX_POINTS_PER_CURVE = 255

# name: (scalar type name, interpolation); "guides only": on the strands only
GROOM_PRIMVARS = {
    "groom_guide": ("int", "uniform"),
    "groom_id": ("int", "uniform"),
    "groom_group_id": ("int", "uniform"),
    "groom_group_name": ("string", "uniform"),
    "groom_root_uv": ("float2", "uniform"),
    "groom_color": ("float3", "vertex"),
    "groom_closest_guides": ("float3", "uniform"),
    "groom_guide_weights": ("float3", "uniform"),
}
STRANDS_ONLY = {"groom_closest_guides", "groom_guide_weights"}


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

    groom = stage.GetPrimAtPath("/hairsketch/groom")
    require(groom.IsValid(), "no prim /hairsketch/groom")
    require(groom.IsA(UsdGeom.Xform), f"/hairsketch/groom is a {groom.GetTypeName()}, not Xform")
    # GroomAPI is Unreal's schema, not registered with usd-core (GetAppliedSchemas leaves it
    # out): read the prim's authored apiSchemas list op
    op = groom.GetMetadata("apiSchemas")
    schemas = list(op.ApplyOperations([])) if op is not None else []
    require("GroomAPI" in schemas, f"/hairsketch/groom has the API schemas {schemas}, not GroomAPI")

    hair = check_curves(stage, "/hairsketch/groom/hair", box, guide=0)
    guides = check_curves(stage, "/hairsketch/groom/guides", box, guide=1)
    check_guides(hair, guides)

    data = stage.GetRootLayer().customLayerData
    text = data.get("hairsketch:session")
    require(isinstance(text, str), "customLayerData has no string hairsketch:session")
    try:
        session = json.loads(text)
    except ValueError as e:
        raise CheckFailed(f"hairsketch:session is not JSON: {e}") from None
    return session, hair, guides


def check_curves(stage, path, box, guide):
    """Checks one BasisCurves prim of the groom; returns what check_guides and --dump need."""
    from pxr import Sdf, UsdGeom

    prim = stage.GetPrimAtPath(path)
    require(prim.IsValid(), f"no prim {path}")
    require(prim.IsA(UsdGeom.BasisCurves), f"{path} is a {prim.GetTypeName()}, not BasisCurves")
    curves = UsdGeom.BasisCurves(prim)

    curve_type = curves.GetTypeAttr().Get()
    require(curve_type == UsdGeom.Tokens.linear, f'{path}: curve type is "{curve_type}", not "linear"')

    counts = curves.GetCurveVertexCountsAttr().Get()
    require(counts is not None and len(counts) > 0, f"{path}: curveVertexCounts is empty")
    counts = list(counts)
    for i, c in enumerate(counts):
        require(
            2 <= c <= MAX_POINTS_PER_CURVE,
            f"{path}: curveVertexCounts[{i}] = {c}, not within 2..{MAX_POINTS_PER_CURVE}",
        )

    points = curves.GetPointsAttr().Get()
    require(points is not None, f"{path}: no points")
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
    require(colours and colours.HasValue(), f"{path}: no primvars:displayColor")
    colour_values = colours.Get()
    require(
        len(colour_values) == len(counts),
        f"{len(colour_values)} displayColor values for {len(counts)} curves",
    )

    # the groom primvars: type, interpolation, count
    api = UsdGeom.PrimvarsAPI(prim)
    found = {}
    for pv in api.GetPrimvarsWithValues():
        name = pv.GetPrimvarName()
        if not name.startswith("groom_"):
            continue
        require(name in GROOM_PRIMVARS, f"{path}: unexpected primvar {name}")
        want_type, want_interp = GROOM_PRIMVARS[name]
        got_type = str(pv.GetTypeName().scalarType)
        require(got_type == want_type, f"{path}: primvars:{name} is {got_type}, not {want_type}")
        got_interp = pv.GetInterpolation()
        require(
            got_interp == want_interp,
            f'{path}: primvars:{name} interpolation is "{got_interp}", not "{want_interp}"',
        )
        values = pv.ComputeFlattened()
        want_n = len(counts) if want_interp == "uniform" else n_points
        require(len(values) == want_n, f"{path}: primvars:{name} has {len(values)} values, not {want_n}")
        found[name] = values
    want = set(GROOM_PRIMVARS) - (STRANDS_ONLY if guide else set())
    missing = sorted(want - set(found))
    require(not missing, f"{path}: no primvars {missing}")
    if guide:
        require(not STRANDS_ONLY & set(found), f"{path}: guides carry {sorted(STRANDS_ONLY & set(found))}")

    require(
        all(g == guide for g in found["groom_guide"]),
        f"{path}: groom_guide is not {guide} on every curve",
    )
    ids = list(found["groom_id"])
    require(len(set(ids)) == len(ids), f"{path}: groom_id has {len(ids) - len(set(ids))} repeats")
    require(min(ids) >= 0, f"{path}: a groom_id is negative")
    group_ids = list(found["groom_group_id"])
    names = list(found["groom_group_name"])
    name_of = {}
    for g, nm in zip(group_ids, names):
        require(name_of.setdefault(g, nm) == nm, f"{path}: group {g} is named both {name_of[g]} and {nm}")
    uv = floats(found["groom_root_uv"])
    require(all_finite(uv) and min(uv) >= 0 and max(uv) <= 1, f"{path}: a groom_root_uv is outside [0, 1]")
    blender = api.GetPrimvar("surface_uv_coordinate")
    require(blender and blender.HasValue(), f"{path}: no primvars:surface_uv_coordinate")
    require(
        blender.GetTypeName() == Sdf.ValueTypeNames.Float2Array
        and blender.GetInterpolation() == UsdGeom.Tokens.uniform,
        f"{path}: surface_uv_coordinate is not a uniform float2[]",
    )
    require(floats(blender.Get()) == uv, f"{path}: surface_uv_coordinate differs from groom_root_uv")
    starts = [0]
    for c in counts:
        starts.append(starts[-1] + c)
    return {
        "path": path,
        "curves": len(counts),
        "points": n_points,
        "xyz": xyz,
        "starts": starts,
        "ids": ids,
        "group_ids": group_ids,
        "group_names": name_of,
        "closest": list(found.get("groom_closest_guides", [])),
        "weights": list(found.get("groom_guide_weights", [])),
    }


def check_guides(hair, guides):
    """Guides: fewer than strands, each a copy of the strand with its id, in that strand's
    group, every group with one; the strands' closest guides are guides of their group."""
    require(
        guides["curves"] < hair["curves"],
        f"{guides['curves']} guides for {hair['curves']} strands: not fewer",
    )
    index = {i: k for k, i in enumerate(hair["ids"])}
    for k, gid in enumerate(guides["ids"]):
        require(gid in index, f"guide {k} has the id {gid}, which no strand has")
        s = index[gid]
        a, b = guides["starts"][k], guides["starts"][k + 1]
        c, d = hair["starts"][s], hair["starts"][s + 1]
        require(b - a == d - c, f"guide {k} has {b - a} points, its strand {d - c}")
        gap = max(abs(x - y) for x, y in zip(guides["xyz"][3 * a : 3 * b], hair["xyz"][3 * c : 3 * d]))
        require(gap <= 1e-6, f"guide {k} lies {gap} from its strand")
        require(
            guides["group_ids"][k] == hair["group_ids"][s],
            f"guide {k} is in group {guides['group_ids'][k]}, its strand in {hair['group_ids'][s]}",
        )
    guide_group = dict(zip(guides["ids"], guides["group_ids"]))
    missing = set(hair["group_ids"]) - set(guides["group_ids"])
    require(not missing, f"groups {sorted(missing)} have no guide")
    for s, (ids, ws) in enumerate(zip(hair["closest"], hair["weights"])):
        for g, w in zip(ids, ws):
            require(g == int(g) and int(g) in guide_group, f"strand {s}: closest guide {g} is not a guide's id")
            require(
                guide_group[int(g)] == hair["group_ids"][s],
                f"strand {s}: closest guide {int(g)} is in another group",
            )
            require(w >= 0, f"strand {s}: guide weight {w} < 0")
        require(abs(sum(ws) - 1) <= 1e-4, f"strand {s}: guide weights sum to {sum(ws)}")


def dump(hair, guides):
    """The strands' roots, ids and groups, the guides' ids and the group names, as JSON."""
    roots = []
    for s in range(hair["curves"]):
        p = 3 * hair["starts"][s]
        roots.append([hair["xyz"][p], hair["xyz"][p + 1], hair["xyz"][p + 2]])
    return {
        "roots": roots,
        "ids": hair["ids"],
        "group_ids": hair["group_ids"],
        "group_names": {str(k): v for k, v in sorted(hair["group_names"].items())},
        "guide_ids": guides["ids"],
    }


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("file")
    parser.add_argument("--box", nargs=6, type=float, required=True, metavar="V")
    parser.add_argument("--dump")
    args = parser.parse_args(argv)
    try:
        session, hair, guides = check(args.file, args.box)
    except CheckFailed as e:
        print(f"check_usd: {args.file}: {e}", file=sys.stderr)
        return 1
    except Exception as e:  # the reader's own errors (a malformed layer) are failures too
        first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
        print(f"check_usd: {args.file}: {type(e).__name__}: {first}", file=sys.stderr)
        return 1
    if args.dump:
        with open(args.dump, "w", encoding="utf-8") as f:
            json.dump(dump(hair, guides), f)
    print(json.dumps(session, separators=(",", ":"), ensure_ascii=False))
    names = ", ".join(hair["group_names"][g] for g in sorted(hair["group_names"]))
    print(
        f"check_usd: ok, {hair['curves']} curves, {hair['points']} points, "
        f"{guides['curves']} guides, {len(hair['group_names'])} groups ({names})",
        file=sys.stderr,
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
