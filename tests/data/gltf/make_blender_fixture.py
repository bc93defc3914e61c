# Writes blender-cube.glb with Blender's own glTF exporter: the fixture of
# tests/core/gltf_blender_test.cpp, a file as a Blender user exports it.
#   blender -b --factory-startup --python tests/data/gltf/make_blender_fixture.py -- tests/data/gltf/blender-cube.glb
# (Debian's blender 3.4.1; scripts/install-deps.sh --peer installs it.)
import math
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

# A 2 m cube, rotated and lifted: the exporter splits its 8 corners into 24
# vertices (one normal per face) and turns Blender's z-up into glTF's y-up.
bpy.ops.mesh.primitive_cube_add(size=2.0, location=(0.2, -0.1, 0.3), rotation=(0.0, 0.0, math.radians(25.0)))
cube = bpy.context.active_object
cube.name = "Jade"

# Glass-like jade as Blender 3.4 exports a volume: transmission on the
# Principled BSDF, a Volume Absorption node, and the thickness on the
# "glTF Material Output" group the exporter reads (KHR_materials_volume, _ior).
material = bpy.data.materials.new("jade")
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
bsdf = nodes["Principled BSDF"]
bsdf.inputs["Transmission"].default_value = 1.0
bsdf.inputs["IOR"].default_value = 1.45
absorption = nodes.new("ShaderNodeVolumeAbsorption")
absorption.inputs["Color"].default_value = (0.3, 0.7, 0.5, 1.0)
absorption.inputs["Density"].default_value = 2.0
links.new(absorption.outputs["Volume"], nodes["Material Output"].inputs["Volume"])
group = bpy.data.node_groups.new("glTF Material Output", "ShaderNodeTree")
group.inputs.new("NodeSocketFloat", "Thickness")
settings = nodes.new("ShaderNodeGroup")
settings.node_tree = group
settings.inputs["Thickness"].default_value = 1.0
cube.data.materials.append(material)

# A 1000 W point light and a 3 W/m^2 sun (the exporter writes candela and lux).
bpy.ops.object.light_add(type="POINT", location=(3.0, -2.0, 4.0))
bpy.context.active_object.data.energy = 1000.0
bpy.ops.object.light_add(type="SUN", location=(0.0, 0.0, 5.0), rotation=(math.radians(30.0), 0.0, 0.0))
bpy.context.active_object.data.energy = 3.0

bpy.ops.object.camera_add(location=(0.0, -8.0, 2.0), rotation=(math.radians(80.0), 0.0, 0.0))
bpy.context.active_object.name = "View"
bpy.context.active_object.data.angle_y = math.radians(35.0)
scene.camera = bpy.context.active_object
scene.render.resolution_x = scene.render.resolution_y = 512

bpy.ops.export_scene.gltf(filepath=out, export_format="GLB", export_cameras=True, export_lights=True,
                          export_apply=True)
