# Writes quad.gltf (+ quad.bin, quadrants.png) with Blender's own glTF exporter:
# a 2 x 2 quad in Blender's XZ plane facing +Y (towards the viewer), its UVs
# upright as seen from +Y, and a material whose base colour is a 2 x 2 texture
# (top-left red, top-right green, bottom-left blue, bottom-right white).
#   blender -b --factory-startup --python tests/data/gltf/blender/make_quad.py
import os
import bpy

here = os.path.dirname(os.path.abspath(__file__))
bpy.ops.wm.read_factory_settings(use_empty=True)

mesh = bpy.data.meshes.new("Quad")
verts = [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)]
mesh.from_pydata(verts, [], [(0, 3, 2, 1)])  # counter-clockwise seen from +Y
mesh.update()
uv = mesh.uv_layers.new(name="UVMap")
corner_uv = {0: (1, 0), 1: (0, 0), 2: (0, 1), 3: (1, 1)}
for loop in mesh.loops:
    uv.data[loop.index].uv = corner_uv[loop.vertex_index]
obj = bpy.data.objects.new("Quad", mesh)
bpy.context.scene.collection.objects.link(obj)

image = bpy.data.images.new("quadrants", width=2, height=2, alpha=False)
# Blender's pixel rows start at the bottom.
image.pixels = [0, 0, 1, 1,  1, 1, 1, 1,   # bottom: blue, white
                1, 0, 0, 1,  0, 1, 0, 1]   # top: red, green
image.filepath_raw = os.path.join(here, "quadrants.png")
image.file_format = "PNG"
image.save()

material = bpy.data.materials.new("Quadrants")
material.use_nodes = True
nodes = material.node_tree.nodes
texture = nodes.new("ShaderNodeTexImage")
texture.image = image
texture.interpolation = "Closest"
bsdf = nodes["Principled BSDF"]
material.node_tree.links.new(texture.outputs["Color"], bsdf.inputs["Base Color"])
mesh.materials.append(material)

bpy.ops.export_scene.gltf(filepath=os.path.join(here, "quad.gltf"), export_format="GLTF_SEPARATE",
                          export_materials="EXPORT", export_image_format="AUTO")
