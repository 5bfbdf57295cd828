"""Renders a hairsketch .usda export with Blender Cycles (bpy) from the app's front view.

usage: blender-compare.py FILE.usda OUT.png SIZE SAMPLES LOOK_JSON [represented]

The hair gets a Principled Hair BSDF in its melanin parametrisation: Melanin and Melanin
Redness read the export's `melanin` (per point) and `redness` (per curve) attributes through
Attribute nodes (the colour model's grey strands and ombre come with them), Roughness and
Random Color from the session's hairLook (LOOK_JSON). The head and bust get a plain skin
Principled BSDF. Lights as the app's (web/viewer/viewer.ts): a key sun along
KEY_LIGHT_DIRECTION (3, 5, 4), a rim sun from (-4, 2, -3), a grey world for the hemisphere
light. The camera is the app's front still view (web/viewer/namedViews.ts namedView('front',
lowest) with the bust's floor, vertical field of view 35 degrees), in app units (1 = 10 cm)
mapped through the imported hair's own transform. Cycles on the CPU, SAMPLES samples, SIZE x SIZE.
The export's strands are one hair wide (80 um at the root); with `represented` each is widened
as the app draws it (web/viewer/strandWidth.ts representedWidth: the 100,000 hairs of a head
shared among the strands, at most 1.2 mm), so the two show the same density.
"""

import json
import math
import sys


def main(argv):
    if len(argv) not in (5, 6) or (len(argv) == 6 and argv[5] != "represented"):
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    path, out, size, samples, look_json = argv[:5]
    represented = len(argv) == 6
    size, samples, look = int(size), int(samples), json.loads(look_json)
    import bpy
    from mathutils import Matrix, Vector

    bpy.ops.wm.read_factory_settings(use_empty=True)
    if "FINISHED" not in bpy.ops.wm.usd_import(filepath=path):
        print("blender-compare: the USD import failed", file=sys.stderr)
        return 1
    hair = [o for o in bpy.data.objects if o.type == "CURVES"]
    meshes = [o for o in bpy.data.objects if o.type == "MESH"]
    if not hair:
        print("blender-compare: no hair curves in the file", file=sys.stderr)
        return 1
    strands = max(hair, key=lambda o: len(o.data.points))
    for o in hair:
        if o is not strands:
            o.hide_render = True  # guides
    to_world = strands.matrix_world.copy()
    if represented:
        # the app's rule: 100,000 hairs of 75 um shared among the strands, at most 1.2 mm wide
        # (the export's root is 80 um: the same factor on every point keeps its taper)
        k = min(100_000 / max(len(strands.data.curves), 1), 0.012 / 0.00075)
        radius = strands.data.attributes["radius"]
        values = [0.0] * len(radius.data)
        radius.data.foreach_get("value", values)
        radius.data.foreach_set("value", [v * k for v in values])

    mat = bpy.data.materials.new("hair")
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    bsdf = nt.nodes.new("ShaderNodeBsdfHairPrincipled")
    bsdf.parametrization = "MELANIN"
    if hasattr(bsdf, "model"):
        bsdf.model = "CHIANG"
    bsdf.inputs["Roughness"].default_value = look.get("roughness", 0.3)
    bsdf.inputs["Radial Roughness"].default_value = look.get("roughness", 0.3)
    bsdf.inputs["Random Color"].default_value = look.get("variation", 0.2) / 2
    bsdf.inputs["Melanin"].default_value = look.get("melanin", 0.4)
    bsdf.inputs["Melanin Redness"].default_value = look.get("redness", 0.25)
    attrs = strands.data.attributes
    for name, socket in (("melanin", "Melanin"), ("redness", "Melanin Redness")):
        if attrs.get(name) is not None:
            node = nt.nodes.new("ShaderNodeAttribute")
            node.attribute_name = name
            nt.links.new(node.outputs["Fac"], bsdf.inputs[socket])
    output = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(bsdf.outputs[0], output.inputs["Surface"])
    strands.data.materials.clear()
    strands.data.materials.append(mat)

    skin = bpy.data.materials.new("skin")
    skin.use_nodes = True
    p = skin.node_tree.nodes["Principled BSDF"]
    p.inputs["Base Color"].default_value = (0.76, 0.47, 0.34, 1)  # #e2b59c in linear light
    p.inputs["Roughness"].default_value = 0.62
    for m in meshes:
        m.data.materials.clear()
        m.data.materials.append(skin)

    scene = bpy.context.scene
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.8, 0.82, 0.86, 1)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6
    scene.world = world

    def app_dir(x, y, z):
        return (to_world.to_3x3() @ Vector((x, y, z))).normalized()

    def sun(name, direction, energy, color):
        data = bpy.data.lights.new(name, "SUN")
        data.energy = energy
        data.color = color
        data.angle = math.radians(2)
        ob = bpy.data.objects.new(name, data)
        # a sun shines along its -Z: point -Z away from the light's direction
        ob.rotation_euler = (-direction).to_track_quat("-Z", "Y").to_euler()
        scene.collection.objects.link(ob)

    sun("key", app_dir(3, 5, 4), 4.0, (1, 1, 1))
    sun("rim", app_dir(-4, 2, -3), 1.5, (0.75, 0.83, 1.0))

    # the app's front still view (namedViews.ts): hair and bust framed down to `floor`
    local_min_y = min(pt.position.y for pt in strands.data.points)
    floor = min(-2.4, local_min_y, -3.3)
    scale = (1.2 - floor) / (1.2 + 2.4)
    target = Vector((0, -0.55 + (floor + 2.4) / 2, 0))
    position = target + (Vector((2.6, 0.9, 7.0)) - Vector((0, -0.55, 0))) * scale
    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.angle_y = math.radians(35)
    cam = bpy.data.objects.new("camera", cam_data)
    eye = to_world @ position
    look_at = to_world @ target
    up = app_dir(0, 1, 0)
    forward = (look_at - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    rot = Matrix((right, true_up, -forward)).transposed()
    cam.matrix_world = Matrix.Translation(eye) @ rot.to_4x4()
    scene.collection.objects.link(cam)
    scene.camera = cam

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = samples
    scene.cycles.use_denoising = False
    scene.render.resolution_x = size
    scene.render.resolution_y = size
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    # Cycles' suns and world light the scene about 2.7 times as brightly as the app lights it
    # (the same skin colour read 211 against 134 in sRGB on the cheek): exposure evens it out,
    # so the hair's colours compare at the same lighting level
    scene.view_settings.exposure = -1.43
    scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
    print(json.dumps({"file": out, "strands": len(strands.data.curves), "floor": floor}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
