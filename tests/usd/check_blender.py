"""Imports a hairsketch .usda export into Blender (bpy, the Blender module from PyPI, in
build/bpy-venv) and reports what Blender made of it.

usage: check_blender.py [--motion] FILE.usda

Runs Blender's own USD importer (bpy.ops.wm.usd_import) on an empty scene and prints ONE line
of JSON on stdout: for every hair Curves object, its name, curve and point counts, and each
attribute's domain, data type and length, and the first curve's surface_uv_coordinate; plus
Blender's version. With --motion (a motion export) also whether Blender plays it: the scene's
frame range and rate, and for the hair (a Curves object) and the head (a Mesh) what they are at
the first frame, the next and the last: the hair's last point, the head's world rotation (Euler
angles; Blender turns the Y-up stage to Z-up). On failure: a message on stderr and exit status 1.
"""

import json
import sys


def curves_report(bpy):
    objects = {}
    for ob in bpy.data.objects:
        if ob.type != "CURVES":
            continue
        curves = ob.data
        attributes = {}
        for a in curves.attributes:
            attributes[a.name] = [a.domain, a.data_type, len(a.data)]
        first_uv = None
        uv = curves.attributes.get("surface_uv_coordinate")
        if uv is not None and len(uv.data) > 0:
            first_uv = list(uv.data[0].vector)
        objects[ob.name] = {
            "curves": len(curves.curves),
            "points": len(curves.points),
            "attributes": attributes,
            "first_uv": first_uv,
        }
    return objects


def motion_report(bpy):
    scene = bpy.context.scene
    out = {"frames": [scene.frame_start, scene.frame_end], "fps": scene.render.fps}
    for name in ("hair", "head"):
        ob = bpy.data.objects.get(name)
        if ob is None:
            out[name] = None
            continue
        samples = []
        for f in (scene.frame_start, scene.frame_start + 1, scene.frame_end):
            scene.frame_set(f)
            ev = ob.evaluated_get(bpy.context.evaluated_depsgraph_get())
            if ob.type == "CURVES":
                p = ev.data.attributes["position"].data
                samples.append(list(p[len(p) - 1].vector))
            else:
                samples.append(list(ev.matrix_world.to_euler()))
        out[name] = {"type": ob.type, "samples": samples}
    return out


def main(argv):
    motion = argv[:1] == ["--motion"]
    if motion:
        argv = argv[1:]
    if len(argv) != 1:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    import bpy  # imported here: a missing bpy is reported, not a trace

    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = bpy.ops.wm.usd_import(filepath=argv[0])
    if "FINISHED" not in result:
        print(f"check_blender: the USD import returned {sorted(result)}", file=sys.stderr)
        return 1
    out = {"blender": bpy.app.version_string, "objects": curves_report(bpy)}
    if motion:
        out.update(motion_report(bpy))
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
