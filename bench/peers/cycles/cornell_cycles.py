# The Cornell box of scenes/cornell_box.scene, rendered by Blender 3.4's Cycles as a fair peer:
# the same published geometry (mesh data, the same fan triangles), Lambertian Diffuse BSDFs (roughness 0)
# with the same RGB albedos, the same one-sided rectangle emitter of radiance (18.387, 13.9873, 6.75357),
# a black world, and none of Cycles' defaults that bias a comparison (see README.md in this folder).
#
#   blender -b --factory-startup --python cornell_cycles.py -- --res 64 --spp 16 --seed 1 --bounces 64 \
#           --threads 2 --out img.pfm [--exr img.exr] [--png img.png]
#
# Writes a linear float PFM (RGB, bottom row first, as bench/peers/image_error reads it), optionally the
# EXR Cycles wrote and an sRGB ("Standard" view transform) PNG, and prints
#   cycles_render_s T   the wall time of bpy.ops.render.render (scene sync, BVH build and path tracing:
#                       what Blender's own "Time:" line reports, without start-up and file writing)
#   cycles_trace_s T    the path tracing alone: from Cycles' "Sample 0/N" report to the end of the render
import argparse
import array
import math
import os
import re
import struct
import sys
import time

import bpy

WHITE = (0.885809, 0.698859, 0.666422)
GREEN = (0.105421, 0.37798, 0.076425)
RED = (0.570068, 0.0430135, 0.0443706)
LIGHT = (18.387, 13.9873, 6.75357)
SCALE = 0.001  # mm -> m: radiance does not depend on scale, and Blender's camera clipping defaults then fit


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="cornell_cycles.py")
    p.add_argument("--res", type=int, default=64, help="width and height in pixels")
    p.add_argument("--spp", type=int, default=16, help="samples per pixel")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--bounces", type=int, default=64, help="every Cycles bounce cap (Trazo's MaxBounces)")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--out", required=True, help="linear float PFM")
    p.add_argument("--exr", help="also keep the 32-bit EXR Cycles wrote")
    p.add_argument("--png", help="also write an 8-bit sRGB PNG (Standard view transform)")
    return p.parse_args(argv)


def quad(x0, z0, x1, z1, h):
    return [(x0, 0, z0), (x0, h, z0), (x1, h, z1), (x1, 0, z1)]


# The published quads (Cornell's vertex order), each fan-triangulated from its first vertex as Trazo does.
WALLS_WHITE = [
    [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)],  # floor
    [(556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0)],  # ceiling
    [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556, 548.8, 559.2)],  # back
]
WALL_RED = [[(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2), (556, 548.8, 0)]]  # left
WALL_GREEN = [[(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]]  # right
SHORT_BLOCK = [[(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)]] + [
    quad(*s, 165) for s in [(290, 114, 240, 272), (130, 65, 290, 114), (82, 225, 130, 65), (240, 272, 82, 225)]]
TALL_BLOCK = [[(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)]] + [
    quad(*s, 330) for s in [(423, 247, 472, 406), (472, 406, 314, 456), (314, 456, 265, 296), (265, 296, 423, 247)]]
# 130 x 105, 0.1 mm under the ceiling; this vertex order makes its normal -y (it faces the room).
LIGHT_QUAD = [[(343, 548.7, 227), (343, 548.7, 332), (213, 548.7, 332), (213, 548.7, 227)]]


def mesh_object(name, quads, material):
    verts, faces = [], []
    for q in quads:  # no shared vertices: every triangle flat, exactly its own plane
        for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            faces.append(tuple(range(len(verts), len(verts) + 3)))
            verts.extend(tuple(c * SCALE for c in v) for v in tri)
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    for poly in mesh.polygons:
        poly.use_smooth = False
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def empty_node_material(name):
    """A material with an empty node tree, and the tree."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.node_tree.nodes.clear()
    return mat, mat.node_tree


def diffuse_material(name, rgb):
    mat, nt = empty_node_material(name)
    bsdf = nt.nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (*rgb, 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0  # Lambert (Oren-Nayar with sigma 0)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return mat


def emitter_material(name, rgb):
    # Cycles' mesh emission is radiance Strength x Color (no 1/pi) from both faces; the Geometry node's
    # Backfacing output masks the back face, so this is a one-sided emitter, black and opaque (no BSDF:
    # a path that hits it ends), as SPEC §7 defines Trazo's AreaLight.
    mat, nt = empty_node_material(name)
    emission = nt.nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (*rgb, 1.0)
    emission.inputs["Strength"].default_value = 1.0
    geometry = nt.nodes.new("ShaderNodeNewGeometry")
    mix = nt.nodes.new("ShaderNodeMixShader")  # Fac 0: emission; Fac 1 (back face): nothing
    nt.links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    nt.links.new(emission.outputs["Emission"], mix.inputs[1])
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    nt.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    if hasattr(mat.cycles, "sample_as_light"):
        mat.cycles.sample_as_light = True  # next-event estimation on it (the default)
    return mat


def build_scene(args):
    scene = bpy.context.scene
    for obj in list(scene.collection.all_objects):
        bpy.data.objects.remove(obj, do_unlink=True)

    white = diffuse_material("white", WHITE)
    mesh_object("white_walls", WALLS_WHITE, white)
    mesh_object("red_wall", WALL_RED, diffuse_material("red", RED))
    mesh_object("green_wall", WALL_GREEN, diffuse_material("green", GREEN))
    mesh_object("short_block", SHORT_BLOCK, white)
    mesh_object("tall_block", TALL_BLOCK, white)
    mesh_object("light", LIGHT_QUAD, emitter_material("light", LIGHT))

    # Camera at (278, 273, -800) looking along +z, up +y: its local axes are x = -X (so the red wall, at
    # large x, is on the image's left), y = +Y, z = -Z (a Blender camera looks down its local -z).
    cam_data = bpy.data.cameras.new("camera")
    cam_data.sensor_fit = "VERTICAL"
    cam_data.sensor_height = 25.0
    cam_data.lens = 12.5 / math.tan(math.radians(39.3077) / 2)  # 35 mm: vertical FOV 39.3077 degrees
    cam_data.clip_start = 0.001
    cam_data.clip_end = 100.0
    cam = bpy.data.objects.new("camera", cam_data)
    from mathutils import Matrix
    cam.matrix_world = Matrix(((-1, 0, 0, 278 * SCALE), (0, 1, 0, 273 * SCALE), (0, 0, -1, -800 * SCALE),
                               (0, 0, 0, 1)))
    scene.collection.objects.link(cam)
    scene.camera = cam

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    bg = world.node_tree.nodes.get("Background")
    bg.inputs["Color"].default_value = (0, 0, 0, 1)
    bg.inputs["Strength"].default_value = 0.0
    world.cycles.sampling_method = "NONE"  # nothing to sample in a black world
    scene.world = world

    render = scene.render
    render.engine = "CYCLES"
    render.resolution_x = render.resolution_y = args.res
    render.resolution_percentage = 100
    render.pixel_aspect_x = render.pixel_aspect_y = 1
    render.film_transparent = False
    render.use_persistent_data = False
    render.threads_mode = "FIXED"
    render.threads = args.threads

    c = scene.cycles
    c.device = "CPU"
    c.samples = args.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.use_preview_denoising = False
    c.time_limit = 0
    c.seed = args.seed
    c.use_animated_seed = False
    for cap in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces", "volume_bounces",
                "transparent_max_bounces"):
        setattr(c, cap, args.bounces)
    c.min_light_bounces = 0
    c.min_transparent_bounces = 0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.blur_glossy = 0.0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0  # the plain mean over the pixel's area (SPEC §7's pixel)
    if hasattr(c, "use_guiding"):
        c.use_guiding = False  # Cycles 3.4's path guiding is off by default; kept off
    c.use_auto_tile = False
    view_layer = bpy.context.view_layer
    if hasattr(view_layer, "cycles"):
        view_layer.cycles.denoising_store_passes = False

    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.sequencer_colorspace_settings.name = "sRGB"
    return scene


def write_pfm(path, image):
    w, h = image.size
    rgba = array.array("f", [0.0]) * (w * h * 4)
    image.pixels.foreach_get(rgba)  # bottom row first, as PFM stores it
    rgb = array.array("f", [0.0]) * (w * h * 3)
    rgb[0::3], rgb[1::3], rgb[2::3] = rgba[0::4], rgba[1::4], rgba[2::4]
    if sys.byteorder != "little":
        rgb.byteswap()
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(rgb.tobytes())


def main():
    args = parse_args()
    scene = build_scene(args)

    # Blender prints Cycles' progress to stdout ("Fra:1 ... | Time:00:00.23 | ... | Sample 0/16", ...
    # "| Finished"), at 10 ms resolution. Captured during the render, echoed, and read: path tracing runs from
    # "Sample 0/N" to the end, after the scene sync, the shaders, the BVH and the lookup tables.
    sys.stdout.flush()
    log_path = os.path.splitext(args.out)[0] + ".cycles.log"
    saved_fd = os.dup(1)
    with open(log_path, "w+b") as log:
        os.dup2(log.fileno(), 1)
        try:
            t0 = time.perf_counter()
            bpy.ops.render.render(write_still=False)
            render_s = time.perf_counter() - t0
        finally:
            os.dup2(saved_fd, 1)
            os.close(saved_fd)
        log.seek(0)
        text = log.read().decode("utf-8", "replace")
    os.remove(log_path)
    sys.stdout.write(text)
    setup_s = None
    for line in text.splitlines():
        m = re.search(r"Time:(\d+):(\d+(?:\.\d+)?) .*\| Sample 0/", line)
        if m:
            setup_s = 60 * int(m.group(1)) + float(m.group(2))
            break
    trace_s = render_s - setup_s if setup_s is not None else float("nan")

    exr = args.exr or os.path.splitext(args.out)[0] + ".tmp.exr"
    image_settings = scene.render.image_settings
    image_settings.file_format = "OPEN_EXR"
    image_settings.color_depth = "32"
    image_settings.exr_codec = "ZIP"
    image_settings.color_management = "FOLLOW_SCENE"
    result = bpy.data.images["Render Result"]
    result.save_render(exr, scene=scene)  # EXR: scene-linear, no view transform
    loaded = bpy.data.images.load(exr)
    loaded.colorspace_settings.name = "Linear"
    write_pfm(args.out, loaded)
    if not args.exr:
        os.remove(exr)
    if args.png:
        image_settings.file_format = "PNG"
        image_settings.color_depth = "8"
        image_settings.color_mode = "RGB"
        result.save_render(args.png, scene=scene)  # Standard view transform: sRGB transfer, clipped

    print("cycles_version %s" % bpy.app.version_string)
    print("cycles_render_s %.6f" % render_s)
    print("cycles_trace_s %.6f" % trace_s)
    sys.stdout.flush()


if __name__ == "__main__":
    main()
