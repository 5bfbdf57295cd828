"""Builds a head-like mesh in Blender (bpy, the Blender module from PyPI, in build/bpy-venv) and
exports it with Blender's own glTF exporter, as an artist would, for the loader's tests.

usage: blender_gltf_head.py OUTDIR

The head is a UV sphere (squashed to a skull's proportions) joined with a cylinder for the neck,
in metres, with a material whose base colour is an image texture (so the export carries a PNG, as
real exports do). It is written twice into OUTDIR:
  Head.gltf + Head.bin + skin.png   export_format GLTF_SEPARATE
  Embedded.gltf                     export_format GLTF_EMBEDDED (one buffer, the PNG inside it,
                                    as a data: URI; Blender offers this form only with the
                                    add-on preference allow_embedded_format on)
Prints ONE line of JSON on stdout: Blender's version, the files written, and what Blender holds
(the reference for the tests): the triangle count of the evaluated mesh and its bounds in glTF's
axes (Y up: glTF (x, y, z) = Blender (x, z, -y)), in metres. On failure: a message on stderr and
exit status 1.
"""

import json
import os
import sys


def build_head(bpy):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=32, ring_count=16, radius=1.0)
    skull = bpy.context.active_object
    # Blender is Z up, front -Y: 15 cm wide, 19 cm deep, 22 cm tall
    skull.scale = (0.075, 0.095, 0.11)
    bpy.ops.mesh.primitive_cylinder_add(
        vertices=24, radius=0.05, depth=0.14, location=(0.0, 0.01, -0.13)
    )
    neck = bpy.context.active_object
    bpy.ops.object.select_all(action="DESELECT")
    skull.select_set(True)
    neck.select_set(True)
    bpy.context.view_layer.objects.active = skull
    bpy.ops.object.join()
    head = bpy.context.active_object
    head.name = "Head"
    head.data.name = "Head"
    # the scales into the vertices, so the file's node carries no transform of its own
    bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)

    # a base-colour texture: a small generated picture the exporter writes as a PNG
    image = bpy.data.images.new("skin", width=8, height=8)
    image.pixels[:] = [c for i in range(64) for c in (0.8, 0.6 - 0.01 * i, 0.5, 1.0)]
    material = bpy.data.materials.new("Skin")
    if material.node_tree is None:  # node-based by default since Blender 5.0
        material.use_nodes = True
    nodes = material.node_tree.nodes
    bsdf = next(n for n in nodes if n.type == "BSDF_PRINCIPLED")
    tex = nodes.new("ShaderNodeTexImage")
    tex.image = image
    material.node_tree.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    head.data.materials.append(material)
    return head


def reference(bpy, head):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = head.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    mesh.calc_loop_triangles()
    triangles = len(mesh.loop_triangles)
    world = head.matrix_world
    points = [world @ v.co for v in mesh.vertices]
    gltf = [(p.x, p.z, -p.y) for p in points]
    evaluated.to_mesh_clear()
    return {
        "triangles": triangles,
        "min": [min(p[a] for p in gltf) for a in range(3)],
        "max": [max(p[a] for p in gltf) for a in range(3)],
    }


def main(argv):
    if len(argv) != 1:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    out = argv[0]
    os.makedirs(out, exist_ok=True)
    import bpy  # imported here: a missing bpy is reported, not a trace

    bpy.ops.wm.read_factory_settings(use_empty=True)
    head = build_head(bpy)
    ref = reference(bpy, head)

    written = {}
    separate = os.path.join(out, "Head.gltf")
    result = bpy.ops.export_scene.gltf(filepath=separate, export_format="GLTF_SEPARATE")
    if "FINISHED" not in result:
        print(f"blender_gltf_head: the separate export returned {sorted(result)}", file=sys.stderr)
        return 1
    written["separate"] = sorted(
        f for f in os.listdir(out) if f.startswith("Head.") or f.endswith(".png")
    )

    # the embedded form is offered only with the add-on's preference on (Blender 4.2 and later)
    prefs = bpy.context.preferences.addons["io_scene_gltf2"].preferences
    prefs.allow_embedded_format = True
    embedded = os.path.join(out, "Embedded.gltf")
    result = bpy.ops.export_scene.gltf(filepath=embedded, export_format="GLTF_EMBEDDED")
    if "FINISHED" not in result:
        print(f"blender_gltf_head: the embedded export returned {sorted(result)}", file=sys.stderr)
        return 1
    written["embedded"] = ["Embedded.gltf"]

    print(json.dumps({"blender": bpy.app.version_string, "files": written, **ref}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
