"""The Sheaf render engine: Blender's side only. Export is export.py, the library capi.py.

Every failure becomes self.report({'ERROR'}, ...); nothing raised here reaches Blender.
"""

import math
import re
import time
import traceback

import bpy
import numpy as np

from . import capi, export, properties

# Extra passes Blender does not know: (name, channels, chan_id, socket type, Sheaf pass).
TESTS_PASS = ("Sheaf Tests", 1, "X", 'VALUE', "tests")

# The last statistics per scene name, for the panel: {"stats": {...}, "summary": str, ...}.
LAST_STATS = {}


def last_stats(scene_name):
    return LAST_STATS.get(scene_name)


def poll_cancel(engine):
    """Blender's test_break() of a running engine (a module function, so that tests can stand
    in for the Esc key, which a headless Blender has not)."""
    return engine.test_break()


class RenderError(Exception):
    pass


def describe_error(e, exported=None):
    """A one-line message; Sheaf's 'mesh N' gets the Blender object it came from."""
    text = str(e) or e.__class__.__name__
    if exported is not None:
        m = re.search(r"\bmesh (\d+)\b", text)
        if m:
            name = exported.describe_mesh(int(m.group(1)))
            if name:
                text = "%s [mesh %s is %s]" % (text, m.group(1), name)
    return text


def summary_line(stats):
    """The statistics the render stats line and the panel show first."""

    def count(x):
        for unit, div in (("G", 1e9), ("M", 1e6), ("k", 1e3)):
            if abs(x) >= div:
                return "%.2f%s" % (x / div, unit)
        return "%d" % x

    share = stats.get("tests.share_of_brute_force", 0.0)
    return "Sheaf | %s primitives | rays %s | tests %s (%.2f%% of brute force) | %.0f ms" % (
        count(stats.get("scene.primitives", 0)),
        count(stats.get("rays.secondary", 0)),
        count(stats.get("tests.total", 0)),
        100.0 * share,
        stats.get("time_ms.frame", 0.0),
    )


def layer_passes(view_layer):
    """The Sheaf passes (output.passes) the view layer's result is filled from: the image and
    the depth (the Depth pass, and the empty pixels of a transparent film) always, the normals
    and the test counts when the layer shows them. The frame keeps only these."""
    passes = ["combined", "depth"]
    if view_layer.use_pass_normal:
        passes.append("normal")
    settings = getattr(view_layer, "sheaf", None)
    if settings is None or settings.use_pass_tests:
        passes.append(TESTS_PASS[4])
    return passes


def border_region(scene, width, height):
    """(x, y, w, h) of the region to fill, in Blender's pixels (y = 0 the bottom row)."""
    r = scene.render
    if not r.use_border:
        return 0, 0, width, height
    # As Blender rounds them (round_fl_to_int: halves up, not Python's round to even).
    x0 = int(math.floor(r.border_min_x * width + 0.5))
    x1 = int(math.floor(r.border_max_x * width + 0.5))
    y0 = int(math.floor(r.border_min_y * height + 0.5))
    y1 = int(math.floor(r.border_max_y * height + 0.5))
    return x0, y0, x1 - x0, y1 - y0


class SheafRenderEngine(bpy.types.RenderEngine):
    bl_idname = "SHEAF"
    bl_label = "Sheaf"
    bl_use_preview = False
    bl_use_postprocess = True
    bl_use_eevee_viewport = True  # Material Preview and Rendered viewports use EEVEE

    def __init__(self):
        self._exported = None
        self._error = None
        self._cancelled = False

    def cancel_requested(self):
        """Whether the user asked to stop (Esc): polled between export steps and by Sheaf's
        progress callback."""
        return poll_cancel(self)

    def _release(self):
        exported = getattr(self, "_exported", None)
        if exported is not None:
            exported.release()
            self._exported = None

    # ---- passes ----

    def update_render_passes(self, scene=None, renderlayer=None):
        self.register_pass(scene, renderlayer, "Combined", 4, "RGBA", 'COLOR')
        if renderlayer.use_pass_z:
            self.register_pass(scene, renderlayer, "Depth", 1, "Z", 'VALUE')
        if renderlayer.use_pass_normal:
            self.register_pass(scene, renderlayer, "Normal", 3, "XYZ", 'VECTOR')
        settings = getattr(renderlayer, "sheaf", None)
        if settings is None or settings.use_pass_tests:
            name, channels, chan_id, kind, _ = TESTS_PASS
            self.register_pass(scene, renderlayer, name, channels, chan_id, kind)

    # ---- export (Blender holds its draw lock here, so scene data is safe to read) ----

    def update(self, data=None, depsgraph=None):
        self._release()
        self._error = None
        self._cancelled = False
        if self.is_preview or depsgraph is None:
            return
        try:
            width, height = export.render_size(depsgraph.scene)
            self.update_stats("", "Sheaf | exporting")
            self._exported = export.export_depsgraph(capi.library(), depsgraph, width, height,
                                                     self.cancel_requested)
        except export.Cancelled:
            self._cancelled = True
        except Exception as e:  # reported by render()
            self._error = e
            if not isinstance(e, (capi.SheafError, capi.LibraryNotFound, export.ExportError)):
                traceback.print_exc()

    # ---- render ----

    def render(self, depsgraph):
        if self.is_preview:
            return
        try:
            self._render(depsgraph)
        except export.Cancelled:
            pass
        except (capi.SheafError, capi.LibraryNotFound, export.ExportError, RenderError) as e:
            self.report({'ERROR'}, "Sheaf: " + describe_error(e, self._exported))
        except Exception as e:
            traceback.print_exc()
            self.report({'ERROR'}, "Sheaf: internal error: %s: %s" % (e.__class__.__name__, e))
        finally:
            self._release()

    def _render(self, depsgraph):
        scene = depsgraph.scene
        if self._cancelled:
            return
        if self._error is not None:
            raise self._error
        width, height = export.render_size(scene)
        if width <= 0 or height <= 0:
            raise RenderError("the image is %d x %d pixels; it needs at least one in each "
                              "direction (check the resolution and its percentage)"
                              % (width, height))
        x0, y0, bw, bh = border_region(scene, width, height)
        if bw <= 0 or bh <= 0:
            raise RenderError("the render region is empty (%d x %d pixels)" % (bw, bh))
        if self._exported is None:  # update() was not called
            self._exported = export.export_depsgraph(capi.library(), depsgraph, width, height,
                                                     self.cancel_requested)
        exported = self._exported
        for w in exported.warnings:
            self.report({'WARNING'}, "Sheaf: " + w)

        lib = capi.library()
        with lib.new_renderer() as renderer:
            properties.apply_settings(renderer, scene)
            renderer.set("width", width)
            renderer.set("height", height)
            if (bw, bh) != (width, height):
                # Only the render region is computed (Sheaf's rows run from the top); its
                # pixels are those of the whole image.
                renderer.set("region.x", x0)
                renderer.set("region.y", height - (y0 + bh))
                renderer.set("region.width", bw)
                renderer.set("region.height", bh)
            renderer.set("output.passes", ",".join(layer_passes(depsgraph.view_layer)))
            self.update_stats("", "Sheaf | preparing the scene")
            exported.scene.commit()
            if self.cancel_requested():
                return

            def progress(done):
                self.update_progress(done)
                return not self.cancel_requested()

            renderer.set_progress_callback(progress)
            self.update_stats("", "Sheaf | rendering")
            start = time.perf_counter()
            try:
                frame = renderer.render(exported.scene)
            except capi.SheafError as e:
                if e.code == capi.SHEAF_ERROR_CANCELLED:
                    return
                raise
            finally:
                renderer.set_progress_callback(None)
        with frame:
            self.write_result(depsgraph, frame, exported, (x0, y0, bw, bh))
            stats = frame.stats()
            backend = frame.text("backend")  # "backend: cpu (why)" / "backend: cuda (device)"
        summary = summary_line(stats)
        LAST_STATS[scene.name] = {
            "stats": stats,
            "summary": summary,
            "seconds": time.perf_counter() - start,
            "settings": properties.settings_text(scene),
            "warnings": list(exported.warnings),
            "backend": backend,
        }
        self.update_stats("", summary)
        self.update_progress(1.0)

    def write_result(self, depsgraph, frame, exported, region):
        x0, y0, bw, bh = region
        scene = depsgraph.scene
        layer_name = depsgraph.view_layer.name
        passes = {"Combined": frame.get_pass("combined")}
        depth = frame.get_pass("depth")[:, :, 0]
        place = frame.region()  # x, y (from the top), full width, full height
        if scene.render.film_transparent:
            empty = ~np.isfinite(depth)
            passes["Combined"][empty] = 0.0
        # With a render region Blender's result is the region: its coordinates start there.
        result = self.begin_result(0, 0, bw, bh, layer=layer_name)
        try:
            layer = result.layers[0]
            for p in layer.passes:
                if p.name == "Combined":
                    data = passes["Combined"]
                elif p.name == "Depth":
                    data = exported.camera.axis_depth(depth, place)[:, :, None]
                elif p.name == "Normal":
                    data = frame.get_pass("normal")
                elif p.name == TESTS_PASS[0]:
                    data = frame.get_pass(TESTS_PASS[4])
                else:
                    continue
                # Sheaf's rows run top to bottom, Blender's bottom to top. A frame of the
                # region holds just its pixels; a whole frame is cut to them.
                data = data[::-1]
                if data.shape[0] != bh or data.shape[1] != bw:
                    data = data[y0:y0 + bh, x0:x0 + bw]
                p.rect.foreach_set(np.ascontiguousarray(data, dtype=np.float32)
                                   .reshape(bw * bh, p.channels))
        except BaseException:
            self.end_result(result, cancel=True)
            raise
        self.end_result(result)
