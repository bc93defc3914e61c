# Renders a Lucent scene with Blender's Cycles, the production path tracer a
# user of this machine would pick instead of Lucent: its single scattering
# (volume_bounces 0) or its full transport. Run by lucent-bench-peer
# (bench/cycles_peer.cpp), never by the tests:
#
#   blender -b --factory-startup -noaudio --python-exit-code 1 \
#           --python bench/cycles/render_scene.py -- PEER_SCENE.json
#
# PEER_SCENE.json is written by lucent-bench-peer (bench/peer_bench.cpp):
#   {"mesh": "mesh.obj", "camera": {"position", "target", "up", "fov_y", "width", "height"},
#    "lights": [{"position": [x, y, z], "intensity": [r, g, b]}],          W/sr, point lights
#    "medium": {"sigma_s": [r, g, b], "sigma_a": [r, g, b], "g": g},        1/length
#    "volume_bounces": 0,                     0: single scattering; else the most a path takes
#    "renders": [{"name": "n16", "samples": 16, "seed": 3}, ...], "threads": 2, "output": "dir"}
# After one untimed render of a sample (Cycles' first render sets up its
# kernels and BVH), each render writes dir/cycles-NAME.pfm (linear RGB) and a
# row "NAME,T" of dir/cycles-times.csv, with T the time of Cycles' render call
# alone: Blender's start and the scene's set-up are left out, as Lucent's
# loading is left out of its times.
import json
import math
import sys
import time
from array import array

import bpy
from mathutils import Matrix, Vector


def read_obj(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith('v '):
                vertices.append(tuple(float(x) for x in line.split()[1:4]))
            elif line.startswith('f '):
                faces.append(tuple(int(x.split('/')[0]) - 1 for x in line.split()[1:]))
    return vertices, faces


def medium_material(medium):
    # Cycles' Volume Scatter has sigma_s = density * colour; Volume Absorption
    # sigma_a = density * (1 - colour). A homogeneous volume is sampled
    # analytically (no ray marching).
    mat = bpy.data.materials.new('medium')
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new('ShaderNodeOutputMaterial')
    scatter = nodes.new('ShaderNodeVolumeScatter')
    absorb = nodes.new('ShaderNodeVolumeAbsorption')
    add = nodes.new('ShaderNodeAddShader')
    ds = max(max(medium['sigma_s']), 1e-30)
    da = max(max(medium['sigma_a']), 1e-30)
    scatter.inputs['Density'].default_value = ds
    scatter.inputs['Color'].default_value = tuple(s / ds for s in medium['sigma_s']) + (1.0,)
    scatter.inputs['Anisotropy'].default_value = medium['g']
    absorb.inputs['Density'].default_value = da
    absorb.inputs['Color'].default_value = tuple(1.0 - a / da for a in medium['sigma_a']) + (1.0,)
    links.new(scatter.outputs[0], add.inputs[0])
    links.new(absorb.outputs[0], add.inputs[1])
    # Volume only, no surface shader: the boundary is index-matched, as in Lucent's ss.
    links.new(add.outputs[0], out.inputs['Volume'])
    mat.cycles.homogeneous_volume = True
    return mat


def look_at(position, target, up):
    # Blender's camera looks down its local -Z with +Y up.
    f = (Vector(target) - Vector(position)).normalized()
    r = f.cross(Vector(up)).normalized()
    u = r.cross(f)
    m = Matrix.Identity(4)
    for i in range(3):
        m[i][0], m[i][1], m[i][2], m[i][3] = r[i], u[i], -f[i], position[i]
    return m


def write_pfm(path, image):
    w, h = image.size
    pixels = array('f', [0.0]) * (w * h * 4)
    image.pixels.foreach_get(pixels)
    with open(path, 'wb') as f:
        f.write(b'PF\n%d %d\n-1.0\n' % (w, h))
        rgb = array('f', [0.0]) * (w * h * 3)
        rgb[0::3], rgb[1::3], rgb[2::3] = pixels[0::4], pixels[1::4], pixels[2::4]
        if sys.byteorder != 'little':
            rgb.byteswap()
        rgb.tofile(f)  # rows bottom to top, as Blender and PFM both store them


def main():
    spec = json.load(open(sys.argv[sys.argv.index('--') + 1]))
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene

    vertices, faces = read_obj(spec['mesh'])
    mesh = bpy.data.meshes.new('object')
    mesh.from_pydata(vertices, [], faces)
    mesh.update()
    obj = bpy.data.objects.new('object', mesh)
    obj.data.materials.append(medium_material(spec['medium']))
    scene.collection.objects.link(obj)

    for i, l in enumerate(spec['lights']):
        # Cycles' point light of power P and no radius has intensity P / (4 pi) W/sr.
        light = bpy.data.lights.new('light%d' % i, 'POINT')
        peak = max(max(l['intensity']), 1e-30)
        light.energy = 4.0 * math.pi * peak
        light.color = tuple(c / peak for c in l['intensity'])
        light.shadow_soft_size = 0.0
        o = bpy.data.objects.new('light%d' % i, light)
        o.location = l['position']
        scene.collection.objects.link(o)

    c = spec['camera']
    cam = bpy.data.cameras.new('camera')
    cam.sensor_fit = 'VERTICAL'
    cam.angle_y = math.radians(c['fov_y'])
    cam.clip_start, cam.clip_end = 1e-4, 1e6
    co = bpy.data.objects.new('camera', cam)
    co.matrix_world = look_at(c['position'], c['target'], c['up'])
    scene.collection.objects.link(co)
    scene.camera = co

    world = bpy.data.worlds.new('world')
    world.use_nodes = False
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    r = scene.render
    r.engine = 'CYCLES'
    r.resolution_x, r.resolution_y, r.resolution_percentage = c['width'], c['height'], 100
    r.threads_mode, r.threads = 'FIXED', spec['threads']
    r.image_settings.file_format = 'OPEN_EXR'
    r.image_settings.color_depth = '32'
    cy = scene.cycles
    cy.device = 'CPU'
    cy.use_adaptive_sampling = False
    cy.use_denoising = False
    # volume_bounces 0 is single scattering: no bounce after the first volume
    # scattering event, whose light comes by next-event estimation. The boundary
    # crossings are free (transparent bounces).
    bounces = int(spec['volume_bounces'])
    cy.max_bounces = max(64, bounces)
    cy.volume_bounces = bounces
    cy.diffuse_bounces = cy.glossy_bounces = cy.transmission_bounces = 0
    cy.transparent_max_bounces = 64
    cy.sample_clamp_direct = cy.sample_clamp_indirect = 0.0
    cy.filter_width = 0.01  # a sample at each pixel's centre region, as Lucent's pixel centres

    cy.samples, cy.seed = 1, 0
    bpy.ops.render.render()  # untimed: the first render sets Cycles up

    times = open('%s/cycles-times.csv' % spec['output'], 'w')
    times.write('name,render_seconds\n')
    for render in spec['renders']:
        cy.samples, cy.seed = int(render['samples']), int(render['seed'])
        name = render['name']
        exr = '%s/cycles-%s.exr' % (spec['output'], name)
        start = time.perf_counter()
        bpy.ops.render.render()
        seconds = time.perf_counter() - start
        bpy.data.images['Render Result'].save_render(filepath=exr)
        image = bpy.data.images.load(exr)
        write_pfm('%s/cycles-%s.pfm' % (spec['output'], name), image)
        bpy.data.images.remove(image)
        times.write('%s,%.6f\n' % (name, seconds))
        times.flush()
        print('lucent-peer: %s, %d samples: render_seconds %.4f' % (name, render['samples'], seconds), flush=True)
    times.close()


main()
