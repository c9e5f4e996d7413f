"""Scene and view-layer properties of the Sheaf engine.

The render settings are the library's own named settings: their kinds, ranges, defaults and
help come from sheafGetSettingCount / sheafGetSettingInfo when the add-on registers, so the panel
and the library cannot drift. Choosing a preset (sheafRendererLoadPreset) copies its values into
the panel; at render time the preset is applied first (it may set keys the panel does not show,
such as cull.objects) and the panel's values after it.
"""

import os
import re

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty, \
    StringProperty

from . import capi

# The settings the panel shows, in order.
PANEL_KEYS = (
    "accel",
    "hierarchy.depth",
    "hierarchy.arity",
    "hash.mode",
    "sort.mode",
    "trace.depth",
    "ao.samples",
    "ao.distance",
    "radiosity.samples",
    "radiosity.depth",
    "aa.samples",
    "backend",
)

# Filled at register time from the library: key -> SettingSpec.
SPECS = {}
_status = {"preset_error": None}


class SettingSpec:
    def __init__(self, key, default, allowed, help_):
        self.key = key
        self.default = default
        self.allowed = allowed
        self.help = help_
        self.attr = key.replace(".", "_")
        self.choices = None
        self.kind = "string"
        self.min = self.max = None
        m = re.match(r"one of (.*)$", allowed)
        if m:
            self.kind = "choice"
            self.choices = [c.strip() for c in m.group(1).split(",")]
        elif re.match(r"an integer in ", allowed):
            self.kind = "int"
            lo, hi = allowed[len("an integer in "):].split("..")
            self.min, self.max = int(lo), int(hi)
        elif re.match(r"a number in ", allowed):
            self.kind = "float"
            lo, hi = allowed[len("a number in "):].split("..")
            self.min, self.max = float(lo), float(hi)
        elif allowed.startswith("true or false"):
            self.kind = "bool"

    def parse(self, text):
        """A canonical setting value as the property's Python value."""
        if self.kind == "int":
            return int(text)
        if self.kind == "float":
            return float(text)
        if self.kind == "bool":
            return text == "true"
        return text

    def prop(self):
        name = self.key
        desc = "%s (Sheaf setting '%s'; default %s)" % (self.help[:1].upper() + self.help[1:],
                                                       self.key, self.default or "none")
        if self.kind == "choice":
            items = [(c, c, "%s = %s" % (self.key, c)) for c in self.choices]
            return EnumProperty(name=name, description=desc, items=items, default=self.default)
        if self.kind == "int":
            return IntProperty(name=name, description=desc, default=int(self.default),
                               min=self.min, max=self.max)
        if self.kind == "float":
            soft_max = min(self.max, 1e6)
            return FloatProperty(name=name, description=desc, default=float(self.default),
                                 min=self.min, max=self.max, soft_max=soft_max)
        if self.kind == "bool":
            return BoolProperty(name=name, description=desc, default=self.default == "true")
        return StringProperty(name=name, description=desc, default=self.default)


# ---- presets ----


def preset_dirs():
    """Where preset files are found, in the library's order: $SHEAF_PRESET_PATH, then
    <libdir>/../share/sheaf/presets, then the presets shipped inside the add-on."""
    dirs = [d for d in os.environ.get("SHEAF_PRESET_PATH", "").split(":") if d]
    lib = capi._library
    if lib is not None and os.sep in lib.path:
        dirs.append(os.path.join(os.path.dirname(os.path.realpath(lib.path)), "..", "share",
                                 "sheaf", "presets"))
    dirs.append(os.path.join(os.path.dirname(__file__), "share", "sheaf", "presets"))
    return dirs


def preset_names():
    lib = capi._library
    listed = lib.preset_list() if lib is not None else None
    if listed is not None:  # the library says which presets it finds
        return [name for name, _ in listed]
    names = []
    for d in preset_dirs():
        try:
            files = sorted(os.listdir(d))
        except OSError:
            continue
        for f in files:
            if f.endswith(".xml") and f[:-4] not in names:
                names.append(f[:-4])
    return names


# Blender keeps pointers into the strings an enum callback returns: every list handed out stays
# alive for the session (one per distinct set of preset names), or Blender reads freed memory.
_preset_items = {}


def _preset_enum(self, context):
    names = tuple(preset_names())
    items = _preset_items.get(names)
    if items is None:
        items = [('NONE', "None", "No preset: the library's defaults and the values below")]
        items += [(n, n, "Apply presets/%s.xml, then the values below" % n) for n in names]
        _preset_items[names] = items
    return items


def _preset_update(self, context):
    """Copies the chosen preset's values into the panel."""
    _status["preset_error"] = None
    name = self.preset
    if name == 'NONE' or not SPECS:
        return
    try:
        lib = capi.library()
        with lib.new_renderer() as r:
            r.load_preset(name)
            values = {key: r.get(key) for key in PANEL_KEYS if key in SPECS}
    except (capi.SheafError, capi.LibraryNotFound) as e:
        _status["preset_error"] = str(e)
        return
    for key, text in values.items():
        spec = SPECS[key]
        setattr(self, spec.attr, spec.parse(text))


def apply_settings(renderer, scene):
    """Sets the renderer from the scene's Sheaf properties: the preset, the panel's keys, the
    image size and Blender's thread count."""
    props = scene.sheaf
    if props.preset != 'NONE':
        renderer.load_preset(props.preset)
    for key in PANEL_KEYS:
        spec = SPECS.get(key)
        if spec is not None:
            renderer.set(key, getattr(props, spec.attr))
    r = scene.render
    if r.threads_mode == 'FIXED':
        renderer.set("threads", int(r.threads))


def settings_text(scene):
    """The panel's settings as 'key=value' lines (for reports and tests)."""
    props = scene.sheaf
    out = ["preset=%s" % props.preset]
    for key in PANEL_KEYS:
        spec = SPECS.get(key)
        if spec is not None:
            out.append("%s=%s" % (key, getattr(props, spec.attr)))
    return out


# ---- property groups ----


def _update_passes(self, context):
    view_layer = context.view_layer if context else None
    if view_layer is not None:
        view_layer.update_render_passes()


class SheafViewLayerSettings(bpy.types.PropertyGroup):
    use_pass_tests: BoolProperty(
        name="Sheaf Tests",
        description="A pass with the exact ray-primitive intersection tests of each pixel's "
                    "secondary rays: where the ray hierarchy works hardest",
        default=True,
        update=_update_passes,
    )


def _make_render_settings_class():
    annotations = {
        "preset": EnumProperty(
            name="Preset",
            description="A preset of the library (presets/*.xml); choosing one copies its values "
                        "into the settings below",
            items=_preset_enum,
            update=_preset_update,
        ),
    }
    for key in PANEL_KEYS:
        spec = SPECS.get(key)
        if spec is not None:
            annotations[spec.attr] = spec.prop()
    return type("SheafRenderSettings", (bpy.types.PropertyGroup,),
                {"__annotations__": annotations, "__module__": __name__})


SheafRenderSettings = None


def library_status():
    """(version text, error text or None) for the panel."""
    err = capi.library_error()
    if err:
        return None, err
    lib = capi.library()
    return lib.version_string(), None


def register():
    global SheafRenderSettings
    SPECS.clear()
    try:
        lib = capi.library()
        for key, default, allowed, help_ in lib.settings():
            SPECS[key] = SettingSpec(key, default, allowed, help_)
    except (capi.LibraryNotFound, capi.SheafError) as e:
        # The add-on still registers: the panel shows why and rendering reports it.
        print("Sheaf:", e)
    SheafRenderSettings = _make_render_settings_class()
    bpy.utils.register_class(SheafRenderSettings)
    bpy.utils.register_class(SheafViewLayerSettings)
    bpy.types.Scene.sheaf = PointerProperty(type=SheafRenderSettings)
    bpy.types.ViewLayer.sheaf = PointerProperty(type=SheafViewLayerSettings)


def unregister():
    global SheafRenderSettings
    del bpy.types.ViewLayer.sheaf
    del bpy.types.Scene.sheaf
    bpy.utils.unregister_class(SheafViewLayerSettings)
    bpy.utils.unregister_class(SheafRenderSettings)
    SheafRenderSettings = None
