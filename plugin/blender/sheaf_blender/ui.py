"""Panels: the render settings with the last frame's statistics, the view layer's passes, and
Blender's own light, material and world panels opened to the engine."""

import bpy

from . import engine, properties

ENGINE = engine.SheafRenderEngine.bl_idname

# Blender's panels that show light, material and world data (and their context selectors);
# the engine adds itself to their COMPAT_ENGINES. Names missing in a Blender version are skipped.
BLENDER_PANELS = (
    "DATA_PT_context_light",
    "DATA_PT_EEVEE_light",  # type, colour, power, radius, area shape and size
    "DATA_PT_spot",  # spot size and blend
    "EEVEE_MATERIAL_PT_context_material",
    "EEVEE_MATERIAL_PT_surface",  # the node surface (Principled BSDF inputs)
    "EEVEE_MATERIAL_PT_viewport_settings",
    "MATERIAL_PT_custom_props",
    "WORLD_PT_context_world",
    "EEVEE_WORLD_PT_surface",  # the Background colour and strength
    "WORLD_PT_custom_props",
)


class SheafPanel:
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    COMPAT_ENGINES = {ENGINE}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES


class SHEAF_RENDER_PT_settings(SheafPanel, bpy.types.Panel):
    bl_label = "Sheaf"
    bl_context = "render"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        version, error = properties.library_status()
        if error:
            col = layout.column()
            col.alert = True
            col.label(text="libsheaf is not loaded", icon='ERROR')
            for line in _wrap(error, 60):
                col.label(text=line)
            return
        props = context.scene.sheaf
        layout.label(text="libsheaf %s" % version)
        layout.prop(props, "preset")
        if properties._status["preset_error"]:
            row = layout.row()
            row.alert = True
            row.label(text=properties._status["preset_error"], icon='ERROR')
        groups = (
            ("Rays", ("accel", "hierarchy.depth", "hierarchy.arity", "hash.mode", "sort.mode")),
            ("Shading", ("trace.depth", "ao.samples", "ao.distance", "radiosity.samples",
                         "radiosity.depth", "aa.samples")),
            ("Device", ("backend",)),
        )
        for title, keys in groups:
            col = layout.column(heading=title, align=True)
            for key in keys:
                spec = properties.SPECS.get(key)
                if spec is not None:
                    col.prop(props, spec.attr, text=key)


class SHEAF_RENDER_PT_statistics(SheafPanel, bpy.types.Panel):
    bl_label = "Statistics"
    bl_context = "render"
    bl_parent_id = "SHEAF_RENDER_PT_settings"

    ROWS = (
        ("scene.primitives", "Primitives"),
        ("scene.objects", "Objects"),
        ("scene.lights", "Lights"),
        ("rays.primary", "Primary samples"),
        ("rays.shadow", "Shadow rays"),
        ("rays.reflection", "Reflection rays"),
        ("rays.refraction", "Refraction rays"),
        ("rays.ao", "AO rays"),
        ("tests.total", "Intersection tests"),
        ("tests.brute_force", "Brute force would test"),
        ("tests.share_of_brute_force", "Share of brute force"),
        ("time_ms.frame", "Frame time (ms)"),
        ("memory.peak_bytes", "Peak frame memory (MiB)"),
    )

    def draw(self, context):
        layout = self.layout
        last = engine.last_stats(context.scene.name)
        if not last:
            layout.label(text="Render to see the frame's statistics")
            return
        stats = last["stats"]
        grid = layout.grid_flow(row_major=True, columns=2, even_columns=False, align=True)
        for key, label in self.ROWS:
            if key not in stats:
                continue
            v = stats[key]
            if key == "tests.share_of_brute_force":
                text = "%.3f%%" % (100.0 * v)
            elif key == "memory.peak_bytes":
                text = "%.1f" % (v / (1 << 20))
            elif key.startswith("time_ms"):
                text = "%.1f" % v
            else:
                text = "{:,}".format(int(v))
            grid.label(text=label)
            grid.label(text=text)
        if last.get("backend"):
            layout.label(text=last["backend"])
        for w in last.get("warnings", [])[:5]:
            layout.label(text=w, icon='INFO')


class SHEAF_VIEWLAYER_PT_passes(SheafPanel, bpy.types.Panel):
    bl_label = "Passes"
    bl_context = "view_layer"

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        view_layer = context.view_layer
        col = layout.column(heading="Include", align=True)
        col.prop(view_layer, "use_pass_combined")
        col.prop(view_layer, "use_pass_z")
        col.prop(view_layer, "use_pass_normal")
        col.prop(view_layer.sheaf, "use_pass_tests")


def _wrap(text, width):
    words, lines, line = text.split(), [], ""
    for w in words:
        if line and len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = (line + " " + w).strip()
    if line:
        lines.append(line)
    return lines


CLASSES = (SHEAF_RENDER_PT_settings, SHEAF_RENDER_PT_statistics, SHEAF_VIEWLAYER_PT_passes)


def _blender_panels():
    for name in BLENDER_PANELS:
        panel = getattr(bpy.types, name, None)
        if panel is not None and hasattr(panel, "COMPAT_ENGINES"):
            yield panel


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    for panel in _blender_panels():
        panel.COMPAT_ENGINES.add(ENGINE)


def unregister():
    for panel in _blender_panels():
        panel.COMPAT_ENGINES.discard(ENGINE)
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
