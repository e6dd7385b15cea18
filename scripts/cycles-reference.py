"""Path-traced reference of a glTF scene with Blender Cycles, in this project's units.

    blender -b --factory-startup -P scripts/cycles-reference.py -- SCENE.gltf OUT.exr \
        [--width 320] [--height 180] [--spp 256] [--seed 0] [--threads 0] [--bounces 64]
        [--probe X,Y,Z,NX,NY,NZ]

Blender (Debian package `blender`, 3.4.1 on Debian 12, the version the shared references name) is a
tool for making references, not a dependency of the renderer. The scene is set up the way
shared/reference/CONVENTIONS.md describes its references: Lambertian Diffuse BSDF (roughness 0)
with baseColorFactor x baseColorTexture (sRGB-decoded), alpha MASK as a cut-out at alphaCutoff,
one-sided emission unless doubleSided, an ideal sun of strength E, ideal point lights of power 4 pi I,
black world, a box filter one pixel wide, up to 64 bounces, no clamping, no denoiser, float32 EXR of
linear radiance. Spot lights become point lights of power 4 pi I whose light shader multiplies
their emission by the glTF falloff t^2, t = clamp((cos theta - cos outer) / max(1e-3, cos inner - cos
outer), 0, 1), theta measured from the spot's axis, as CONVENTIONS.md's references emulate them
(Cycles' own spot falloff is not the glTF one).
--probe replaces the scene's camera by a 180-degree equidistant fisheye at the point (X, Y, Z) of the
glTF's world, looking along (NX, NY, NZ): what a surface there with that normal sees, for
scripts/probe-irradiance.py to integrate into its irradiance (with --bounces 0, the first bounce it
gathers from directly lit surfaces).
The glTF importer's own light units are not used: light strengths are set from the file's values.
"""
import argparse
import json
import math
import os
import sys

import bpy
import numpy

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which numpy 1.24 removed.
if "bool" not in numpy.__dict__:
    numpy.bool = bool


def fail(msg):
    print("cycles-reference: " + msg, file=sys.stderr)
    sys.exit(1)


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cycles-reference.py")
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--width", type=int, default=320)
    p.add_argument("--height", type=int, default=180)
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--threads", type=int, default=0)
    p.add_argument("--bounces", type=int, default=64)
    p.add_argument("--probe", default=None)
    a = p.parse_args(argv)
    if a.probe is not None:
        try:
            a.probe = [float(v) for v in a.probe.split(",")]
        except ValueError:
            a.probe = []
        if len(a.probe) != 6 or not any(a.probe[3:]):
            fail("--probe: want X,Y,Z,NX,NY,NZ with a non-zero normal")
    if a.width < 1 or a.height < 1 or a.spp < 1 or a.bounces < 0:
        fail("width, height and spp must be positive, bounces not negative")
    return a


def load_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{path}: {e}")


def diffuse_material(mat, gm):
    """Rebuild the importer's node tree as Diffuse BSDF (+ cut-out, + one-sided emission)."""
    nt = mat.node_tree
    principled = next((n for n in nt.nodes if n.type == "BSDF_PRINCIPLED"), None)
    out = next((n for n in nt.nodes if n.type == "OUTPUT_MATERIAL"), None)
    if principled is None or out is None:
        fail(f"material {mat.name}: the importer built no Principled BSDF")
    base_link = principled.inputs["Base Color"].links
    alpha_link = principled.inputs["Alpha"].links
    diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Roughness"].default_value = 0.0
    if base_link:
        nt.links.new(base_link[0].from_socket, diffuse.inputs["Color"])
    else:
        diffuse.inputs["Color"].default_value = principled.inputs["Base Color"].default_value
    shader = diffuse.outputs["BSDF"]

    pbr = gm.get("pbrMetallicRoughness", {})
    if gm.get("alphaMode") == "MASK":
        # Cut-out: the surface exists where alpha >= cutoff (Cycles would treat alpha as coverage).
        if alpha_link:
            alpha = alpha_link[0].from_socket
        else:
            alpha = None
        keep = nt.nodes.new("ShaderNodeMath")
        keep.operation = "GREATER_THAN"
        keep.inputs[1].default_value = gm.get("alphaCutoff", 0.5) - 1e-6
        if alpha is not None:
            nt.links.new(alpha, keep.inputs[0])
        else:
            keep.inputs[0].default_value = pbr.get("baseColorFactor", [1, 1, 1, 1])[3]
        transparent = nt.nodes.new("ShaderNodeBsdfTransparent")
        mix = nt.nodes.new("ShaderNodeMixShader")
        nt.links.new(keep.outputs[0], mix.inputs["Fac"])
        nt.links.new(transparent.outputs[0], mix.inputs[1])
        nt.links.new(shader, mix.inputs[2])
        shader = mix.outputs[0]
    elif gm.get("alphaMode") == "BLEND" and alpha_link:
        transparent = nt.nodes.new("ShaderNodeBsdfTransparent")
        mix = nt.nodes.new("ShaderNodeMixShader")
        nt.links.new(alpha_link[0].from_socket, mix.inputs["Fac"])
        nt.links.new(transparent.outputs[0], mix.inputs[1])
        nt.links.new(shader, mix.inputs[2])
        shader = mix.outputs[0]

    strength = gm.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get(
        "emissiveStrength", 1.0)
    factor = gm.get("emissiveFactor", [0, 0, 0])
    if any(f > 0 for f in factor):
        if "emissiveTexture" in gm:
            fail(f"material {mat.name}: emissive textures are not set up by this script")
        emission = nt.nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (factor[0], factor[1], factor[2], 1.0)
        emission.inputs["Strength"].default_value = strength
        emit = emission.outputs[0]
        if not gm.get("doubleSided", False):
            geometry = nt.nodes.new("ShaderNodeNewGeometry")
            gate = nt.nodes.new("ShaderNodeMixShader")
            nt.links.new(geometry.outputs["Backfacing"], gate.inputs["Fac"])
            nt.links.new(emit, gate.inputs[1])
            emit = gate.outputs[0]  # the second input, left unlinked, is black
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(shader, add.inputs[0])
        nt.links.new(emit, add.inputs[1])
        shader = add.outputs[0]
    nt.links.new(shader, out.inputs["Surface"])
    nt.nodes.remove(principled)


def spot_as_point(obj, spot, intensity):
    """A glTF spot as an ideal point light whose emission a light shader scales by the glTF falloff t^2."""
    import mathutils
    bpy.context.view_layer.update()
    axis = (obj.matrix_world.to_3x3() @ mathutils.Vector((0.0, 0.0, -1.0))).normalized()
    inner, outer = spot.get("innerConeAngle", 0.0), spot.get("outerConeAngle", math.pi / 4)
    cos_outer = math.cos(outer)
    width = max(1e-3, math.cos(inner) - cos_outer)
    light = obj.data
    light.type = "POINT"
    light.energy = 4.0 * math.pi * intensity
    light.shadow_soft_size = 0.0
    light.use_nodes = True
    nodes, links = light.node_tree.nodes, light.node_tree.links
    emission = next(n for n in nodes if n.type == "EMISSION")
    geometry = nodes.new("ShaderNodeNewGeometry")
    dot = nodes.new("ShaderNodeVectorMath")
    dot.operation = "DOT_PRODUCT"
    # In a light's shader Incoming is the direction from the light to the point it lights.
    links.new(geometry.outputs["Incoming"], dot.inputs[0])
    dot.inputs[1].default_value = axis
    t = nodes.new("ShaderNodeMapRange")  # (cos - cos outer) / width, clamped to [0, 1]
    t.clamp = True
    t.inputs["From Min"].default_value = cos_outer
    t.inputs["From Max"].default_value = cos_outer + width
    links.new(dot.outputs["Value"], t.inputs["Value"])
    square = nodes.new("ShaderNodeMath")
    square.operation = "MULTIPLY"
    links.new(t.outputs["Result"], square.inputs[0])
    links.new(t.outputs["Result"], square.inputs[1])
    links.new(square.outputs["Value"], emission.inputs["Strength"])


def main():
    a = parse_args()
    gltf = load_json(a.scene)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        bpy.ops.import_scene.gltf(filepath=os.path.abspath(a.scene), import_shading="NORMALS")
    except RuntimeError as e:
        fail(f"{a.scene}: import failed: {e}")
    scene = bpy.context.scene

    by_name = {m.get("name"): m for m in gltf.get("materials", [])}
    for mat in bpy.data.materials:
        if mat.node_tree is None:
            continue
        gm = by_name.get(mat.name)
        if gm is None:
            fail(f"material {mat.name}: not found by name in {a.scene}")
        diffuse_material(mat, gm)

    # Lights: strengths from the file (the importer's conversion assumes photometric units).
    defs = gltf.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    for obj in list(scene.objects):
        if obj.type != "LIGHT":
            continue
        gl = next((d for d in defs if d.get("name") == obj.data.name), None)
        if gl is None:
            fail(f"light {obj.data.name}: not found by name in {a.scene}")
        colour = gl.get("color", [1, 1, 1])
        intensity = gl.get("intensity", 1.0)
        obj.data.color = colour
        if gl["type"] == "directional":
            obj.data.energy = intensity
            obj.data.angle = 0.0
        elif gl["type"] == "point":
            obj.data.energy = 4.0 * math.pi * intensity
            obj.data.shadow_soft_size = 0.0
        elif gl["type"] == "spot":
            spot_as_point(obj, gl.get("spot", {}), intensity)
        else:
            fail(f"light {obj.data.name}: type {gl['type']} is not supported by this script")
        obj.data.cycles.max_bounces = 1024

    cams = [o for o in scene.objects if o.type == "CAMERA"]
    if not cams:
        fail(f"{a.scene}: no camera")
    # The first camera node of the default scene (CONVENTIONS); the shared scenes have one.
    cam = cams[0]
    gcam = gltf["cameras"][0]["perspective"]
    cam.data.sensor_fit = "VERTICAL"
    cam.data.angle_y = gcam["yfov"]
    cam.data.clip_start = gcam.get("znear", 0.01)
    cam.data.clip_end = gcam.get("zfar", 1000.0)
    scene.camera = cam
    if a.probe is not None:
        import mathutils
        # glTF's +Y up is Blender's +Z (the importer's conversion: (x, y, z) -> (x, -z, y)).
        x, y, z, nx, ny, nz = a.probe
        cam.parent = None
        cam.location = (x, -z, y)
        cam.rotation_mode = "QUATERNION"
        cam.rotation_quaternion = mathutils.Vector((nx, -nz, ny)).normalized().to_track_quat("-Z", "Y")
        cam.data.type = "PANO"
        owner = cam.data if hasattr(cam.data, "panorama_type") else cam.data.cycles
        owner.panorama_type = "FISHEYE_EQUIDISTANT"
        owner.fisheye_fov = math.pi
        cam.data.clip_start = 1e-4

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world

    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = a.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = a.seed
    c.max_bounces = a.bounces
    c.diffuse_bounces = a.bounces
    c.glossy_bounces = a.bounces
    c.transmission_bounces = a.bounces
    c.volume_bounces = 0
    c.transparent_max_bounces = 64
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.pixel_filter_type = "BOX"
    scene.cycles.filter_width = 1.0
    scene.render.threads_mode = "FIXED" if a.threads > 0 else "AUTO"
    if a.threads > 0:
        scene.render.threads = a.threads
    scene.render.resolution_x = a.width
    scene.render.resolution_y = a.height
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    s = scene.render.image_settings
    s.file_format = "OPEN_EXR"
    s.color_mode = "RGB"
    s.color_depth = "32"
    s.exr_codec = "ZIP"
    scene.render.filepath = os.path.abspath(a.out)
    bpy.ops.render.render(write_still=True)
    print(f"cycles-reference: wrote {a.out} ({a.width}x{a.height}, {a.spp} spp)")


main()
