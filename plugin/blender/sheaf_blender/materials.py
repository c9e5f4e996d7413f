"""Blender materials and worlds as SheafMaterialDesc and a background colour (docs/blender.md).

Sheaf's material is POV-Ray's model: colour, ambient, diffuse, a Phong highlight, a mirror
weight, Fresnel-split transmission with an IOR, and emission. The Principled BSDF maps onto it
as follows (the light colours in export.py carry Lambert's 1/pi, so `diffuse` is a weight):

    color          Base Color (linear); an Image Texture on Base Color multiplies it
    diffuse        1 - Metallic              (Sheaf itself scales diffuse by 1 - transmission)
    ambient        luminance of the world colour x (1 - Metallic)
    phong_exponent 2 / alpha^2 - 2 with alpha = Roughness^2, clamped to 1..500
    specular       F0 x (exponent + 1) / 2   (a normalised Phong lobe), F0 = 0.08 x Specular
                   for dielectrics and the luminance of Base Color for metals, mixed by Metallic
    mirror         F0 x gloss with gloss = max(0, 1 - 2 Roughness)^2 (no mirror at Roughness
                   >= 0.5); no dielectric mirror where Sheaf's Fresnel already reflects
    transmission   Transmission x (1 - Metallic)
    ior            IOR
    emission       Emission x Emission Strength
"""

import os

import numpy as np

from . import capi

LUMINANCE = (0.2126, 0.7152, 0.0722)


def luminance(rgb):
    return sum(c * w for c, w in zip(rgb, LUMINANCE))


class MaterialExporter:
    """Materials of one export, each Blender material added once."""

    def __init__(self, scene, lib, tempdir, world_ambient, warn):
        self.scene = scene
        self.lib = lib
        self.tempdir = tempdir
        self.world_ambient = world_ambient
        self.warn = warn
        self.ids = {}
        self.textured = {}
        self.textures = {}
        self._default = None

    def default_material(self):
        """Blender's grey for empty slots and objects without materials."""
        if self._default is None:
            self._default = self._add(base=(0.8, 0.8, 0.8), metallic=0.0, roughness=0.5)
        return self._default

    def material(self, mat):
        """The Sheaf material id of a bpy.types.Material (None: the default)."""
        if mat is None:
            return self.default_material()
        key = mat.original.name_full if mat.original else mat.name_full
        if key not in self.ids:
            self.ids[key], self.textured[key] = self._export(mat)
        return self.ids[key]

    def is_textured(self, mat):
        if mat is None:
            return False
        key = mat.original.name_full if mat.original else mat.name_full
        return self.textured.get(key, False)

    # ---- Blender's material to parameters ----

    def _export(self, mat):
        params = dict(base=tuple(mat.diffuse_color[:3]), metallic=mat.metallic,
                      roughness=mat.roughness)
        texture = -1
        if mat.use_nodes and mat.node_tree:
            surface = _surface_node(mat.node_tree)
            if surface is None:
                self.warn("material '%s': no surface shader; using its viewport colour" % mat.name)
            elif surface.type == 'BSDF_PRINCIPLED':
                params = _principled(surface)
                texture = self._base_color_texture(mat, surface)
            elif surface.type == 'EMISSION':
                c = _value(surface.inputs["Color"])[:3]
                s = _value(surface.inputs["Strength"])
                params = dict(base=(0.0, 0.0, 0.0), metallic=0.0, roughness=1.0,
                              emission=tuple(x * s for x in c))
            elif surface.type == 'BSDF_DIFFUSE':
                params = dict(base=tuple(_value(surface.inputs["Color"])[:3]), metallic=0.0,
                              roughness=1.0)
            elif surface.type == 'BSDF_GLOSSY':
                params = dict(base=tuple(_value(surface.inputs["Color"])[:3]), metallic=1.0,
                              roughness=_value(surface.inputs["Roughness"]))
            elif surface.type == 'BSDF_GLASS':
                params = dict(base=tuple(_value(surface.inputs["Color"])[:3]), metallic=0.0,
                              roughness=_value(surface.inputs["Roughness"]), transmission=1.0,
                              ior=_value(surface.inputs["IOR"]))
            else:
                self.warn("material '%s': the %s shader is not supported; using its viewport "
                          "colour" % (mat.name, surface.bl_label))
        return self._add(texture=texture, **params), texture >= 0

    def _add(self, base, metallic, roughness, specular=0.5, transmission=0.0, ior=1.45,
             emission=(0.0, 0.0, 0.0), texture=-1):
        d = self.scene.material_desc()
        metallic = min(max(float(metallic), 0.0), 1.0)
        roughness = min(max(float(roughness), 0.0), 1.0)
        transmission = min(max(float(transmission), 0.0), 1.0) * (1.0 - metallic)
        alpha = max(roughness * roughness, 1e-3)
        exponent = min(max(2.0 / (alpha * alpha) - 2.0, 1.0), 500.0)
        f0 = (1.0 - metallic) * 0.08 * max(float(specular), 0.0) + metallic * luminance(base)
        gloss = max(0.0, 1.0 - 2.0 * roughness) ** 2
        d.color[:] = [max(float(c), 0.0) for c in base]
        d.diffuse = 1.0 - metallic
        d.ambient = self.world_ambient * (1.0 - metallic)
        d.phong_exponent = exponent
        d.specular = f0 * (exponent + 1.0) / 2.0
        # Metals reflect by F0; dielectrics by their Fresnel F0 unless they transmit, where
        # Sheaf's own Fresnel split already gives the reflection.
        d.mirror = gloss * (metallic * luminance(base)
                            + (1.0 - metallic) * (1.0 - transmission) * 0.08 * specular)
        d.transmission = transmission
        d.ior = max(float(ior), 1.0)
        d.emission[:] = [max(float(c), 0.0) for c in emission]
        d.texture = texture
        return self.scene.add_material(d)

    def _base_color_texture(self, mat, principled):
        sock = principled.inputs["Base Color"]
        if not sock.is_linked:
            return -1
        node = sock.links[0].from_node
        if node.type != 'TEX_IMAGE' or node.image is None:
            self.warn("material '%s': Base Color is driven by a %s node, which is not supported;"
                      " using its value" % (mat.name, node.bl_label))
            return -1
        return self.texture(node.image)

    def texture(self, image):
        """The Sheaf texture id of a bpy.types.Image: its file when it is one on disk, else its
        pixels written to a temporary OpenEXR file through sheafWriteImage."""
        # Path, colour space and pixels come from the user's image, not the depsgraph's copy.
        if image.original is not None:
            image = image.original
        key = image.name_full
        if key in self.textures:
            return self.textures[key]
        import bpy

        colorspace = image.colorspace_settings.name
        path = bpy.path.abspath(image.filepath, library=image.library) if image.filepath else ""
        on_disk = (image.source == 'FILE' and not image.packed_file and path
                   and os.path.isfile(path))
        if on_disk:
            space = "srgb" if colorspace == "sRGB" else (
                "linear" if colorspace in ("Linear", "Non-Color", "Raw") else "")
        else:
            w, h = image.size
            if w == 0 or h == 0:
                self.warn("image '%s' has no pixels; texture ignored" % image.name)
                self.textures[key] = -1
                return -1
            px = np.empty(w * h * 4, dtype=np.float32)
            image.pixels.foreach_get(px)
            # Blender's pixels are bottom row first, sheafWriteImage's top row first.
            px = px.reshape(h, w, 4)[::-1]
            path = os.path.join(self.tempdir, "texture%d.exr" % len(self.textures))
            self.lib.write_image(path, px)
            # Byte images give their stored (encoded) values, float images scene-linear ones.
            space = "srgb" if (not image.is_float and colorspace == "sRGB") else "linear"
        tid = self.scene.add_texture(path, capi.SHEAF_MAPPING_UV, None, space)
        self.textures[key] = tid
        return tid


def _surface_node(tree):
    out = None
    for target in ('CYCLES', 'ALL', 'EEVEE'):
        try:
            out = tree.get_output_node(target)
        except (AttributeError, TypeError):
            out = None
        if out:
            break
    if out is None:
        out = next((n for n in tree.nodes if n.type == 'OUTPUT_MATERIAL'), None)
    if out is None or not out.inputs["Surface"].is_linked:
        return None
    node = out.inputs["Surface"].links[0].from_node
    while node.type == 'REROUTE' and node.inputs[0].is_linked:
        node = node.inputs[0].links[0].from_node
    return node


def _value(socket):
    v = socket.default_value
    try:
        return tuple(v)
    except TypeError:
        return float(v)


def _principled(node):
    i = node.inputs
    c = _value(i["Emission"])[:3]
    strength = _value(i["Emission Strength"]) if "Emission Strength" in i else 1.0
    return dict(
        base=_value(i["Base Color"])[:3],
        metallic=_value(i["Metallic"]),
        roughness=_value(i["Roughness"]),
        specular=_value(i["Specular"]),
        transmission=_value(i["Transmission"]),
        ior=_value(i["IOR"]),
        emission=tuple(x * strength for x in c),
    )


def world_color(world):
    """The world's colour as radiance: a Background node's Color x Strength, else world.color."""
    if world is None:
        return (0.0, 0.0, 0.0), None
    if world.use_nodes and world.node_tree:
        out = None
        try:
            out = world.node_tree.get_output_node('CYCLES') or world.node_tree.get_output_node('ALL')
        except (AttributeError, TypeError):
            pass
        if out is None:
            out = next((n for n in world.node_tree.nodes if n.type == 'OUTPUT_WORLD'), None)
        if out is None or not out.inputs["Surface"].is_linked:
            return (0.0, 0.0, 0.0), None
        node = out.inputs["Surface"].links[0].from_node
        if node.type == 'BACKGROUND':
            color, strength = node.inputs["Color"], node.inputs["Strength"]
            warning = None
            if color.is_linked or strength.is_linked:
                warning = ("world '%s': only a plain Background colour is exported; the nodes "
                           "driving it are ignored" % world.name)
            s = float(strength.default_value)
            return tuple(float(x) * s for x in color.default_value[:3]), warning
        return tuple(world.color), ("world '%s': the %s node is not supported; using the "
                                    "world's viewport colour" % (world.name, node.bl_label))
    return tuple(world.color), None


def ambient_from_world(rgb):
    """Sheaf's ambient is a grey weight: the world's luminance (a Lambertian surface under a
    uniform sky of radiance L reflects albedo x L)."""
    return max(luminance(rgb), 0.0)

