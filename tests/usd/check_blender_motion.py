"""Imports a hairsketch motion .usda into Blender (bpy, in build/bpy-venv) and reports whether
Blender plays it: the scene's frame range and rate, and for the hair (a Curves object) and the
head (a Mesh) what they are at frames 0, 1 and the last: the hair's last point, the head's world
rotation (Euler angles; Blender turns the Y-up stage to Z-up).

usage: check_blender_motion.py FILE.usda

Prints ONE line of JSON on stdout. On failure: a message on stderr and exit status 1.
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
        print(f"check_blender_motion: the USD import returned {sorted(result)}", file=sys.stderr)
        return 1
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
    print(json.dumps(out))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
