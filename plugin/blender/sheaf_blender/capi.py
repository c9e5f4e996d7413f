"""ctypes bindings of the Sheaf C ABI (plugin/capi/include/sheaf/sheaf.h, docs/capi.md).

The structures and prototypes below mirror sheaf.h field for field; keep them in step with it.
Every call that returns a SheafError goes through `_check`, which raises `SheafError` with the
message of sheafGetLastError. Nothing here imports bpy, so the module also works outside Blender.

Small wrapper classes (Scene, Renderer, Frame) own one reference each and release it on
`release()` or when used as context managers.
"""

import ctypes
import ctypes.util
import os
from ctypes import (
    CFUNCTYPE,
    POINTER,
    Structure,
    byref,
    c_char_p,
    c_double,
    c_float,
    c_int,
    c_int32,
    c_longlong,
    c_size_t,
    c_uint32,
    c_void_p,
)

# The major version this binding speaks: the soname is libsheaf.so.MAJOR.
ABI_MAJOR = 0
LIBRARY_SONAME = "libsheaf.so.%d" % ABI_MAJOR

# ---- enum SheafError ----
SHEAF_OK = 0
SHEAF_ERROR_INVALID_ARGUMENT = 1
SHEAF_ERROR_INVALID_SETTING = 2
SHEAF_ERROR_SCENE = 3
SHEAF_ERROR_RENDER = 4
SHEAF_ERROR_IO = 5
SHEAF_ERROR_OUT_OF_MEMORY = 6
SHEAF_ERROR_CANCELLED = 7
SHEAF_ERROR_UNKNOWN = 99

# ---- enum SheafTextureMapping ----
SHEAF_MAPPING_UV = 0
SHEAF_MAPPING_PLANAR = 1
SHEAF_MAPPING_SPHERICAL = 2
SHEAF_MAPPING_CYLINDRICAL = 3
SHEAF_MAPPING_TORUS = 4

# ---- enum SheafLightType ----
SHEAF_LIGHT_POINT = 0
SHEAF_LIGHT_SPOT = 1
SHEAF_LIGHT_PARALLEL = 2

# ---- enum SheafProjection ----
SHEAF_PROJECTION_PERSPECTIVE = 0
SHEAF_PROJECTION_ORTHOGRAPHIC = 1
SHEAF_PROJECTION_FISHEYE = 2
SHEAF_PROJECTION_ULTRA_WIDE_ANGLE = 3
SHEAF_PROJECTION_OMNIMAX = 4
SHEAF_PROJECTION_PANORAMIC = 5
SHEAF_PROJECTION_CYLINDER_1 = 6
SHEAF_PROJECTION_CYLINDER_2 = 7
SHEAF_PROJECTION_CYLINDER_3 = 8
SHEAF_PROJECTION_CYLINDER_4 = 9
SHEAF_PROJECTION_SPHERICAL = 10

# ---- enum SheafSubdivScheme (only in libraries that export sheafSceneAddSubdivisionMesh) ----
SHEAF_SUBDIV_CATMULL_CLARK = 0
SHEAF_SUBDIV_LOOP = 1

# C enums are int-sized on every platform Blender runs on.
c_enum = c_int

SheafScene = c_void_p
SheafRenderer = c_void_p
SheafFrame = c_void_p


class SheafMaterialDesc(Structure):
    _fields_ = [
        ("color", c_float * 3),
        ("ambient", c_float),
        ("diffuse", c_float),
        ("specular", c_float),
        ("phong_exponent", c_float),
        ("mirror", c_float),
        ("transmission", c_float),
        ("ior", c_float),
        ("emission", c_float * 3),
        ("texture", c_int32),
    ]


class SheafLightDesc(Structure):
    _fields_ = [
        ("type", c_enum),
        ("position", c_float * 3),
        ("direction", c_float * 3),
        ("color", c_float * 3),
        ("spot_radius", c_float),
        ("spot_falloff", c_float),
        ("spot_tightness", c_float),
        ("fade_distance", c_float),
        ("fade_power", c_float),
        ("shadowless", c_int),
    ]


class SheafCameraDesc(Structure):
    _fields_ = [
        ("projection", c_enum),
        ("position", c_float * 3),
        ("look_at", c_float * 3),
        ("up", c_float * 3),
        ("fov_y_degrees", c_float),
        ("ortho_height", c_float),
        ("shift", c_float * 2),
    ]


SheafErrorCallback = CFUNCTYPE(None, c_void_p, c_enum, c_char_p)
SheafProgressCallback = CFUNCTYPE(c_int, c_void_p, c_float)

_f = POINTER(c_float)
_u32 = POINTER(c_uint32)

# name: (restype, argtypes), exactly as declared in sheaf.h. c_enum return types are SheafError.
_PROTOTYPES = {
    "sheafGetLastError": (c_enum, [POINTER(c_char_p)]),
    "sheafSetErrorCallback": (None, [SheafErrorCallback, c_void_p]),
    "sheafGetVersion": (None, [POINTER(c_int), POINTER(c_int), POINTER(c_int)]),
    "sheafGetVersionString": (c_char_p, []),
    "sheafGetDefaultSceneName": (c_char_p, []),
    "sheafGetBuiltinSceneCount": (c_enum, [POINTER(c_size_t)]),
    "sheafGetBuiltinSceneName": (c_enum, [c_size_t, POINTER(c_char_p)]),
    "sheafMaterialDescInit": (None, [POINTER(SheafMaterialDesc)]),
    "sheafSceneNew": (c_enum, [POINTER(SheafScene)]),
    "sheafSceneRetain": (c_enum, [SheafScene]),
    "sheafSceneRelease": (c_enum, [SheafScene]),
    "sheafSceneLoadBuiltin": (c_enum, [SheafScene, c_char_p]),
    "sheafSceneLoadFile": (c_enum, [SheafScene, c_char_p]),
    "sheafSceneSetLoadOption": (c_enum, [SheafScene, c_char_p, c_char_p]),
    "sheafSceneGetWarningCount": (c_enum, [SheafScene, POINTER(c_size_t)]),
    "sheafSceneGetWarning": (c_enum, [SheafScene, c_size_t, POINTER(c_char_p)]),
    "sheafSceneAddMaterial": (c_enum, [SheafScene, POINTER(SheafMaterialDesc), _u32]),
    "sheafSceneAddMesh": (c_enum, [SheafScene, _f, c_uint32, _u32, c_uint32, _f, _u32]),
    "sheafSceneAddObject": (c_enum, [SheafScene, c_uint32, c_uint32, _f, c_char_p, _u32]),
    "sheafSceneAddPointLight": (c_enum, [SheafScene, _f, _f]),
    "sheafSceneSetCamera": (c_enum, [SheafScene, _f, _f, _f, c_float]),
    "sheafSceneSetBackground": (c_enum, [SheafScene, _f]),
    "sheafSceneAddTexture": (c_enum, [SheafScene, c_char_p, c_enum, _f, c_char_p, _u32]),
    "sheafSceneSetMeshUvs": (c_enum, [SheafScene, c_uint32, _f, c_uint32]),
    "sheafLightDescInit": (None, [POINTER(SheafLightDesc)]),
    "sheafSceneAddLight": (c_enum, [SheafScene, POINTER(SheafLightDesc), _u32]),
    "sheafCameraDescInit": (None, [POINTER(SheafCameraDesc)]),
    "sheafSceneSetCameraDesc": (c_enum, [SheafScene, POINTER(SheafCameraDesc)]),
    "sheafSceneSetCameraLens": (c_enum, [SheafScene, c_float, c_float, _f]),
    "sheafSceneSetCameraFocus": (c_enum, [SheafScene, c_float, c_float]),
    "sheafSceneCommit": (c_enum, [SheafScene]),
    "sheafRendererNew": (c_enum, [POINTER(SheafRenderer)]),
    "sheafRendererRetain": (c_enum, [SheafRenderer]),
    "sheafRendererRelease": (c_enum, [SheafRenderer]),
    "sheafRendererSetString": (c_enum, [SheafRenderer, c_char_p, c_char_p]),
    "sheafRendererSetInt": (c_enum, [SheafRenderer, c_char_p, c_longlong]),
    "sheafRendererSetFloat": (c_enum, [SheafRenderer, c_char_p, c_double]),
    "sheafRendererSetBool": (c_enum, [SheafRenderer, c_char_p, c_int]),
    "sheafRendererUnset": (c_enum, [SheafRenderer, c_char_p]),
    "sheafRendererGetString": (
        c_enum,
        [SheafRenderer, c_char_p, c_char_p, c_size_t, POINTER(c_size_t)],
    ),
    "sheafRendererLoadPreset": (c_enum, [SheafRenderer, c_char_p]),
    "sheafRendererSetProgressCallback": (
        c_enum,
        [SheafRenderer, SheafProgressCallback, c_void_p],
    ),
    "sheafGetSettingCount": (c_enum, [POINTER(c_size_t)]),
    "sheafGetSettingInfo": (
        c_enum,
        [c_size_t, POINTER(c_char_p), POINTER(c_char_p), POINTER(c_char_p), POINTER(c_char_p)],
    ),
    "sheafRender": (c_enum, [SheafRenderer, SheafScene, POINTER(SheafFrame)]),
    "sheafFrameRetain": (c_enum, [SheafFrame]),
    "sheafFrameRelease": (c_enum, [SheafFrame]),
    "sheafFrameGetSize": (c_enum, [SheafFrame, POINTER(c_int), POINTER(c_int)]),
    "sheafFrameGetRegion": (c_enum, [SheafFrame, POINTER(c_int), POINTER(c_int), POINTER(c_int),
                                     POINTER(c_int)]),
    "sheafFrameGetPass": (c_enum, [SheafFrame, c_char_p, _f, c_size_t]),
    "sheafFrameGetStatCount": (c_enum, [SheafFrame, POINTER(c_size_t)]),
    "sheafFrameGetStat": (c_enum, [SheafFrame, c_size_t, POINTER(c_char_p), POINTER(c_double)]),
    "sheafFrameGetStatByName": (c_enum, [SheafFrame, c_char_p, POINTER(c_double)]),
    "sheafFrameGetText": (
        c_enum,
        [SheafFrame, c_char_p, c_char_p, c_size_t, POINTER(c_size_t)],
    ),
    "sheafFrameSaveImage": (c_enum, [SheafFrame, c_char_p]),
    "sheafFrameSavePass": (c_enum, [SheafFrame, c_char_p, c_char_p]),
    "sheafWriteImage": (c_enum, [c_char_p, c_int, c_int, c_int, _f, c_int]),
}

# Functions newer libraries may export; bound only when present (hasattr on the CDLL).
_OPTIONAL_PROTOTYPES = {
    "sheafSceneAddSubdivisionMesh": (
        c_enum,
        [
            SheafScene,
            _f,  # positions
            c_uint32,  # vertex_count
            _u32,  # face_sizes
            c_uint32,  # face_count
            _u32,  # face_indices
            _u32,  # crease_edges (2 vertex indices per crease)
            _f,  # crease_sharpness
            c_uint32,  # crease_count
            _f,  # uvs
            c_enum,  # SheafSubdivScheme
            c_int,  # level
            _u32,  # out_mesh_id
        ],
    ),
    "sheafSceneSetObjectFlags": (c_enum, [SheafScene, c_uint32, c_uint32]),
    "sheafGetPresetList": (c_enum, [c_char_p, c_size_t, POINTER(c_size_t)]),
}

# Object flags (sheafSceneSetObjectFlags).
SHEAF_OBJECT_NO_SHADOW = 1
SHEAF_OBJECT_NO_REFLECTION = 2
SHEAF_OBJECT_NO_IMAGE = 4


class SheafError(Exception):
    """A failed Sheaf call: `code` is the SheafError value, the text sheafGetLastError's."""

    def __init__(self, code, message):
        super().__init__(message)
        self.code = code
        self.message = message


class LibraryNotFound(Exception):
    pass


def library_candidates():
    """Where libsheaf is looked for, in order: $SHEAF_LIBRARY (which wins), the copy shipped in
    the add-on (lib/libsheaf.so.MAJOR), then the system's loader path."""
    env = os.environ.get("SHEAF_LIBRARY")
    if env:
        return [env]
    here = os.path.dirname(os.path.abspath(__file__))
    out = [os.path.join(here, "lib", LIBRARY_SONAME)]
    found = ctypes.util.find_library("sheaf")
    out.append(found or LIBRARY_SONAME)
    return out


def _as_float_ptr(array):
    """A float* into a C-contiguous float32 NumPy array (kept alive by the caller), or NULL."""
    if array is None:
        return None
    return array.ctypes.data_as(_f)


def _as_u32_ptr(array):
    if array is None:
        return None
    return array.ctypes.data_as(_u32)


def _floats(values, n):
    return (c_float * n)(*[float(v) for v in values])


def _bytes(text):
    return None if text is None else str(text).encode("utf-8")


class Library:
    """One loaded libsheaf: the raw functions as attributes (lib.sheafSceneNew, ...) plus checked
    helpers."""

    def __init__(self, path=None):
        candidates = [path] if path else library_candidates()
        errors = []
        self.cdll = None
        for candidate in candidates:
            if os.sep in candidate and not os.path.exists(candidate):
                errors.append("%s: no such file" % candidate)
                continue
            try:
                self.cdll = ctypes.CDLL(candidate)
                self.path = candidate
                break
            except OSError as e:
                errors.append(str(e))
        if self.cdll is None:
            raise LibraryNotFound(
                "libsheaf could not be loaded (set SHEAF_LIBRARY to its path): "
                + "; ".join(errors)
            )
        for name, (restype, argtypes) in _PROTOTYPES.items():
            try:
                fn = getattr(self.cdll, name)
            except AttributeError:
                raise LibraryNotFound("%s does not export %s" % (self.path, name)) from None
            fn.restype = restype
            fn.argtypes = argtypes
            setattr(self, name, fn)
        self.optional = set()
        for name, (restype, argtypes) in _OPTIONAL_PROTOTYPES.items():
            if hasattr(self.cdll, name):
                fn = getattr(self.cdll, name)
                fn.restype = restype
                fn.argtypes = argtypes
                setattr(self, name, fn)
                self.optional.add(name)
        major = self.version()[0]
        if major != ABI_MAJOR:
            raise LibraryNotFound(
                "%s is Sheaf %s; this add-on needs major version %d"
                % (self.path, self.version_string(), ABI_MAJOR)
            )

    # ---- errors ----

    def last_error(self):
        message = c_char_p()
        code = self.sheafGetLastError(byref(message))
        text = message.value.decode("utf-8", "replace") if message.value else ""
        return code, text

    def check(self, code):
        """Raises SheafError for any result other than SHEAF_OK."""
        if code != SHEAF_OK:
            last_code, message = self.last_error()
            raise SheafError(code, message or "sheaf error %d" % code)

    # ---- version, settings ----

    def version(self):
        major, minor, patch = c_int(), c_int(), c_int()
        self.sheafGetVersion(byref(major), byref(minor), byref(patch))
        return major.value, minor.value, patch.value

    def version_string(self):
        return self.sheafGetVersionString().decode()

    @property
    def has_subdivision(self):
        return "sheafSceneAddSubdivisionMesh" in self.optional

    @property
    def has_object_flags(self):
        return "sheafSceneSetObjectFlags" in self.optional

    def preset_list(self):
        """[(name, description)] of the presets the library finds, or None when the library is
        too old to say."""
        if "sheafGetPresetList" not in self.optional:
            return None
        needed = c_size_t()
        self.check(self.sheafGetPresetList(None, 0, byref(needed)))
        buf = ctypes.create_string_buffer(needed.value)
        self.check(self.sheafGetPresetList(buf, needed.value, byref(needed)))
        out = []
        for line in buf.value.decode("utf-8", "replace").splitlines():
            name, _, description = line.partition("\t")
            if name:
                out.append((name, description))
        return out

    def settings(self):
        """Every setting as (key, default, allowed, help), from the library itself."""
        count = c_size_t()
        self.check(self.sheafGetSettingCount(byref(count)))
        out = []
        for i in range(count.value):
            key, default, allowed, help_ = c_char_p(), c_char_p(), c_char_p(), c_char_p()
            self.check(
                self.sheafGetSettingInfo(i, byref(key), byref(default), byref(allowed), byref(help_))
            )
            out.append(
                (
                    key.value.decode(),
                    default.value.decode(),
                    allowed.value.decode(),
                    help_.value.decode(),
                )
            )
        return out

    def write_image(self, path, pixels, display_referred=False):
        """pixels: float32 array (height, width, channels), top row first."""
        import numpy as np

        pixels = np.ascontiguousarray(pixels, dtype=np.float32)
        h, w, c = pixels.shape
        self.check(
            self.sheafWriteImage(_bytes(path), w, h, c, _as_float_ptr(pixels), int(display_referred))
        )

    # ---- handles ----

    def new_scene(self):
        return Scene(self)

    def new_renderer(self):
        return Renderer(self)


class _Handle:
    _release = None

    def __init__(self, lib, handle):
        self.lib = lib
        self.handle = handle

    def release(self):
        if self.handle:
            getattr(self.lib, self._release)(self.handle)
            self.handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.release()

    def __del__(self):
        try:
            self.release()
        except Exception:
            pass


class Scene(_Handle):
    _release = "sheafSceneRelease"

    def __init__(self, lib):
        h = SheafScene()
        lib.check(lib.sheafSceneNew(byref(h)))
        super().__init__(lib, h)
        self.texture_count = 0

    def add_material(self, desc):
        out = c_uint32()
        self.lib.check(self.lib.sheafSceneAddMaterial(self.handle, byref(desc), byref(out)))
        return out.value

    def add_mesh(self, positions, indices, normals=None):
        """positions, normals: float32 (n, 3); indices: uint32 (t, 3). Returns the mesh id."""
        out = c_uint32()
        self.lib.check(
            self.lib.sheafSceneAddMesh(
                self.handle,
                _as_float_ptr(positions),
                len(positions),
                _as_u32_ptr(indices),
                len(indices),
                _as_float_ptr(normals),
                byref(out),
            )
        )
        return out.value

    def add_subdivision_mesh(
        self, positions, face_sizes, face_indices, crease_edges, crease_sharpness, uvs, scheme, level
    ):
        out = c_uint32()
        crease_count = 0 if crease_sharpness is None else len(crease_sharpness)
        self.lib.check(
            self.lib.sheafSceneAddSubdivisionMesh(
                self.handle,
                _as_float_ptr(positions),
                len(positions),
                _as_u32_ptr(face_sizes),
                len(face_sizes),
                _as_u32_ptr(face_indices),
                _as_u32_ptr(crease_edges if crease_count else None),
                _as_float_ptr(crease_sharpness if crease_count else None),
                crease_count,
                _as_float_ptr(uvs),
                scheme,
                int(level),
                byref(out),
            )
        )
        return out.value

    def set_mesh_uvs(self, mesh_id, uvs):
        """uvs: float32 (n, 2), one per vertex of the mesh."""
        self.lib.check(
            self.lib.sheafSceneSetMeshUvs(self.handle, mesh_id, _as_float_ptr(uvs), len(uvs))
        )

    def set_option(self, key, value):
        """sheafSceneSetLoadOption: options for loading files and subdividing."""
        self.lib.check(self.lib.sheafSceneSetLoadOption(self.handle, _bytes(key), _bytes(value)))

    def set_object_flags(self, object_id, flags):
        self.lib.check(self.lib.sheafSceneSetObjectFlags(self.handle, object_id, int(flags)))

    def add_object(self, mesh_id, material_id, transform_3x4=None, name=None):
        t = None if transform_3x4 is None else _floats(transform_3x4, 12)
        out = c_uint32()
        self.lib.check(
            self.lib.sheafSceneAddObject(
                self.handle, mesh_id, material_id, t, _bytes(name), byref(out)
            )
        )
        return out.value

    def add_texture(self, path, mapping=SHEAF_MAPPING_UV, world_to_texture=None, colorspace=None):
        t = None if world_to_texture is None else _floats(world_to_texture, 12)
        out = c_uint32()
        self.lib.check(
            self.lib.sheafSceneAddTexture(
                self.handle, _bytes(path), mapping, t, _bytes(colorspace), byref(out)
            )
        )
        self.texture_count += 1
        return out.value

    def add_light(self, desc):
        out = c_uint32()
        self.lib.check(self.lib.sheafSceneAddLight(self.handle, byref(desc), byref(out)))
        return out.value

    def set_camera(self, desc):
        self.lib.check(self.lib.sheafSceneSetCameraDesc(self.handle, byref(desc)))

    def set_camera_lens(self, angle_degrees, v_angle_degrees, lengths=None):
        """The traced projections' angles and POV-Ray's right, up, direction lengths."""
        l = None if lengths is None else _floats(lengths, 3)
        self.lib.check(
            self.lib.sheafSceneSetCameraLens(self.handle, angle_degrees, v_angle_degrees, l)
        )

    def set_camera_focus(self, lens_radius, focal_distance):
        """Depth of field: the lens radius (0: none) and the sharp plane's distance."""
        self.lib.check(
            self.lib.sheafSceneSetCameraFocus(self.handle, lens_radius, focal_distance)
        )

    def set_background(self, rgb):
        self.lib.check(self.lib.sheafSceneSetBackground(self.handle, _floats(rgb, 3)))

    def commit(self):
        self.lib.check(self.lib.sheafSceneCommit(self.handle))

    def material_desc(self):
        d = SheafMaterialDesc()
        self.lib.sheafMaterialDescInit(byref(d))
        return d

    def light_desc(self):
        d = SheafLightDesc()
        self.lib.sheafLightDescInit(byref(d))
        return d

    def camera_desc(self):
        d = SheafCameraDesc()
        self.lib.sheafCameraDescInit(byref(d))
        return d


class Renderer(_Handle):
    _release = "sheafRendererRelease"

    def __init__(self, lib):
        h = SheafRenderer()
        lib.check(lib.sheafRendererNew(byref(h)))
        super().__init__(lib, h)
        self._progress = None

    def set(self, key, value):
        """Sets a setting from a Python value of the matching kind."""
        k = _bytes(key)
        if isinstance(value, bool):
            self.lib.check(self.lib.sheafRendererSetBool(self.handle, k, int(value)))
        elif isinstance(value, int):
            self.lib.check(self.lib.sheafRendererSetInt(self.handle, k, value))
        elif isinstance(value, float):
            self.lib.check(self.lib.sheafRendererSetFloat(self.handle, k, value))
        else:
            self.lib.check(self.lib.sheafRendererSetString(self.handle, k, _bytes(value)))

    def get(self, key):
        needed = c_size_t()
        k = _bytes(key)
        self.lib.check(self.lib.sheafRendererGetString(self.handle, k, None, 0, byref(needed)))
        buf = ctypes.create_string_buffer(needed.value)
        self.lib.check(self.lib.sheafRendererGetString(self.handle, k, buf, needed.value, None))
        return buf.value.decode()

    def load_preset(self, name_or_path):
        self.lib.check(self.lib.sheafRendererLoadPreset(self.handle, _bytes(name_or_path)))

    def set_progress_callback(self, fn):
        """fn(done: float) -> bool (False cancels). None removes it. The callback never raises
        into C: an exception cancels the render."""
        if fn is None:
            self._progress = None
            self.lib.check(self.lib.sheafRendererSetProgressCallback(
                    self.handle, ctypes.cast(None, SheafProgressCallback), None))
            return

        def trampoline(user, done):
            try:
                return 1 if fn(float(done)) else 0
            except Exception:
                return 0

        self._progress = SheafProgressCallback(trampoline)  # kept alive while set
        self.lib.check(self.lib.sheafRendererSetProgressCallback(self.handle, self._progress, None))

    def render(self, scene):
        out = SheafFrame()
        self.lib.check(self.lib.sheafRender(self.handle, scene.handle, byref(out)))
        return Frame(self.lib, out)


class Frame(_Handle):
    _release = "sheafFrameRelease"

    PASS_CHANNELS = {"combined": 4, "depth": 1, "normal": 3, "albedo": 3, "object_id": 1, "tests": 1}

    def size(self):
        w, h = c_int(), c_int()
        self.lib.check(self.lib.sheafFrameGetSize(self.handle, byref(w), byref(h)))
        return w.value, h.value

    def region(self):
        """(x, y, full_width, full_height): where the frame lies in the whole image (y from
        the top); (0, 0, width, height) unless the renderer's region.* asked for a part."""
        x, y, fw, fh = c_int(), c_int(), c_int(), c_int()
        self.lib.check(self.lib.sheafFrameGetRegion(self.handle, byref(x), byref(y), byref(fw),
                                                    byref(fh)))
        return x.value, y.value, fw.value, fh.value

    def get_pass(self, name):
        """The pass as float32 (height, width, channels), top row first."""
        import numpy as np

        w, h = self.size()
        c = self.PASS_CHANNELS[name]
        out = np.empty((h, w, c), dtype=np.float32)
        self.lib.check(
            self.lib.sheafFrameGetPass(self.handle, _bytes(name), _as_float_ptr(out), out.size)
        )
        return out

    def stats(self):
        """Every statistic, in the frame's order, as a dict."""
        count = c_size_t()
        self.lib.check(self.lib.sheafFrameGetStatCount(self.handle, byref(count)))
        out = {}
        for i in range(count.value):
            key, value = c_char_p(), c_double()
            self.lib.check(self.lib.sheafFrameGetStat(self.handle, i, byref(key), byref(value)))
            out[key.value.decode()] = value.value
        return out

    def text(self, what):
        needed = c_size_t()
        w = _bytes(what)
        self.lib.check(self.lib.sheafFrameGetText(self.handle, w, None, 0, byref(needed)))
        buf = ctypes.create_string_buffer(needed.value)
        self.lib.check(self.lib.sheafFrameGetText(self.handle, w, buf, needed.value, None))
        return buf.value.decode()

    def save_image(self, path):
        self.lib.check(self.lib.sheafFrameSaveImage(self.handle, _bytes(path)))


_library = None
_library_error = None


def library():
    """The process-wide library, loaded on first use. Raises LibraryNotFound."""
    global _library, _library_error
    if _library is None:
        try:
            _library = Library()
            _library_error = None
        except LibraryNotFound as e:
            _library_error = str(e)
            raise
    return _library


def library_error():
    """Why the library could not be loaded, or None."""
    if _library is None and _library_error is None:
        try:
            library()
        except LibraryNotFound:
            pass
    return _library_error
