"""Chapter 18's Cornell box in Blender's Cycles, for the path-tracing benchmark (make bench:
tests/perf/ch18/cycles_bench.sh). Run headless:

    blender -b --factory-startup --python cornell_cycles.py -- OUT.png SAMPLES SEED

It builds scenes/chapter18-path-tracing.lua's box with bpy: the same boxes (raybook's (x, y, z)
is Blender's (x, -z, y), a rotation, so nothing is mirrored), the same camera (39.3° vertical
field of view, 160 x 160), Lambertian walls of the same linear reflectances, and the lamp's face
emitting radiance (17, 12, 4) (an Emission shader of strength 1 emits its colour as radiance).
The film is raybook's: a box pixel filter, the Standard view transform (sRGB, no Filmic curve),
no denoiser, no clamping, and path lengths up to 64 of every kind, as raybook's max_depth. It
prints "render_seconds S": the time of bpy.ops.render.render alone, on 2 threads.
"""
import math
import sys
import time

import bpy
from mathutils import Matrix, Vector

out, samples, seed = sys.argv[sys.argv.index("--") + 1:][:3]
samples, seed = int(samples), int(seed)

# Start from nothing.
for o in list(bpy.data.objects):
    bpy.data.objects.remove(o, do_unlink=True)
scene = bpy.context.scene


def to_blender(x, y, z):
    """raybook's (x, y, z), y up, to Blender's z-up frame: a quarter turn about x."""
    return Vector((x, -z, y))


def material(name, colour, emission=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes, links = m.node_tree.nodes, m.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*colour, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert
    if emission is None:
        links.new(diffuse.outputs["BSDF"], output.inputs["Surface"])
    else:
        glow = nodes.new("ShaderNodeEmission")
        glow.inputs["Color"].default_value = (*emission, 1.0)
        glow.inputs["Strength"].default_value = 1.0
        add = nodes.new("ShaderNodeAddShader")
        links.new(diffuse.outputs["BSDF"], add.inputs[0])
        links.new(glow.outputs["Emission"], add.inputs[1])
        links.new(add.outputs["Shader"], output.inputs["Surface"])
    return m


white = material("white", (0.725, 0.71, 0.68))
red = material("red", (0.63, 0.065, 0.05))
green = material("green", (0.14, 0.45, 0.091))
lamp = material("lamp", (0.78, 0.78, 0.78), emission=(17.0, 12.0, 4.0))


def unit_cube(name, mat, transform):
    """raybook's gr.cube ([0, 1]^3) under the raybook transform `transform` (a Matrix)."""
    mesh = bpy.data.meshes.new(name)
    corners = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    verts = []
    for c in corners:
        p = transform @ Vector((*c, 1.0))
        verts.append(to_blender(p.x, p.y, p.z))
    faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    mesh.from_pydata([tuple(v) for v in verts], [], faces)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    obj.data.materials.append(mat)
    scene.collection.objects.link(obj)


def translate(x, y, z):
    return Matrix.Translation((x, y, z))


def scale(x, y, z):
    return Matrix.Diagonal((x, y, z, 1.0))


def rotate_y(degrees):
    return Matrix.Rotation(math.radians(degrees), 4, "Y")


def slab(name, mat, sx, sy, sz, x, y, z):
    unit_cube(name, mat, translate(x, y, z) @ scale(sx, sy, sz))


# The box, as scenes/chapter18-path-tracing.lua builds it.
slab("floor", white, 5.76, 0.1, 5.692, -0.1, -0.1, 0)
slab("ceiling", white, 5.76, 0.1, 5.692, -0.1, 5.488, 0)
slab("back", white, 5.76, 5.688, 0.1, -0.1, -0.1, 5.592)
slab("left", red, 0.1, 5.688, 5.692, 5.56, -0.1, 0)
slab("right", green, 0.1, 5.688, 5.692, -0.1, -0.1, 0)
slab("lamp", lamp, 1.30, 0.0002, 1.05, 2.13, 5.4879, 2.27)


def block(name, height, degrees, x, z):
    # raybook applies translate, scale, rotate, translate in the order written.
    unit_cube(name, white, translate(x, 0, z) @ rotate_y(degrees) @ scale(1.65, height, 1.65)
              @ translate(-0.5, 0, -0.5))


block("short", 1.65, -17, 1.855, 1.69)
block("tall", 3.30, 17, 3.685, 3.5125)

# The camera: at (2.78, 2.73, -8), looking along +z, up +y; 39.3° vertically.
cam_data = bpy.data.cameras.new("camera")
cam_data.sensor_fit = "VERTICAL"
cam_data.angle = math.radians(39.3)
cam = bpy.data.objects.new("camera", cam_data)
cam.location = to_blender(2.78, 2.73, -8.0)
cam.rotation_euler = to_blender(0, 0, 1).to_track_quat("-Z", "Y").to_euler()
scene.collection.objects.link(cam)
scene.camera = cam

# No world light: black background.
world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

# Cycles on the CPU, raybook's film.
scene.render.engine = "CYCLES"
c = scene.cycles
c.device = "CPU"
c.samples = samples
c.seed = seed
c.use_adaptive_sampling = False
c.use_denoising = False
c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = 64
c.transparent_max_bounces = 64
c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
c.caustics_reflective = c.caustics_refractive = True
c.pixel_filter_type = "BOX"
c.filter_width = 1.0
scene.render.resolution_x = scene.render.resolution_y = 160
scene.render.resolution_percentage = 100
scene.render.threads_mode = "FIXED"
scene.render.threads = 2
scene.view_settings.view_transform = "Standard"
scene.view_settings.look = "None"
scene.view_settings.exposure = 0.0
scene.view_settings.gamma = 1.0
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_depth = "8"
scene.render.image_settings.color_mode = "RGB"
scene.render.filepath = out

start = time.perf_counter()
bpy.ops.render.render(write_still=True)
print(f"render_seconds {time.perf_counter() - start:.4f}")
