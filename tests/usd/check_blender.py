"""Imports a hairsketch .usda export into Blender (bpy, the Blender module from PyPI, in
build/bpy-venv) and reports what Blender made of it.

usage: check_blender.py FILE.usda

Runs Blender's own USD importer (bpy.ops.wm.usd_import) on an empty scene and prints ONE line
of JSON on stdout: for every hair Curves object, its name, curve and point counts, and each
attribute's domain, data type and length, and the first curve's surface_uv_coordinate; plus
Blender's version. On failure: a message on stderr and exit status 1.
"""

import json
import sys


def main(argv):
    if len(argv) != 1:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    import bpy  # imported here: a missing bpy is reported, not a trace

    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = bpy.ops.wm.usd_import(filepath=argv[0])
    if "FINISHED" not in result:
        print(f"check_blender: the USD import returned {sorted(result)}", file=sys.stderr)
        return 1
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
    print(json.dumps({"blender": bpy.app.version_string, "objects": objects}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
