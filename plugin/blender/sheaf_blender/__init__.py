"""Sheaf for Blender: the Sheaf render engine (libsheaf's C ABI through ctypes) as a Blender
render engine. See docs/blender.md.

Modules: capi (the bindings), export (the depsgraph to a Sheaf scene), materials (Principled
BSDF and world), engine (the RenderEngine), properties (settings), ui (panels)."""

bl_info = {
    "name": "Sheaf",
    "author": "The Sheaf authors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Properties > Render > Render Engine > Sheaf",
    "description": "Renders with Sheaf: raster primary visibility and a coherent ray-space "
                   "hierarchy for every secondary ray",
    "doc_url": "",
    "category": "Render",
}

if "bpy" in locals():
    import importlib

    for _m in (capi, materials, export, properties, engine, ui):  # noqa: F821
        importlib.reload(_m)
else:
    from . import capi, materials, export, properties, engine, ui

import bpy  # noqa: E402


def register():
    properties.register()
    bpy.utils.register_class(engine.SheafRenderEngine)
    ui.register()


def unregister():
    ui.unregister()
    bpy.utils.unregister_class(engine.SheafRenderEngine)
    properties.unregister()
