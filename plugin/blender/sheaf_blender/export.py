"""The evaluated depsgraph as a Sheaf scene, through the C ABI (docs/blender.md).

Blender is right-handed with Z up; so is Sheaf's world, and its camera takes an explicit up
vector, so coordinates pass through unchanged and the camera gets its own +Y as up.

- Geometry: each evaluated mesh is read once with foreach_get into NumPy (positions, loop
  triangles, split normals, the active render UV map), its face corners merged where position,
  normal and UV agree, split by material slot, and added once; every object or instance that
  shows it is an object placing that mesh with its world matrix (row-major 3x4).
- A last Subdivision Surface modifier (Catmull-Clark) goes to sheafSceneAddSubdivisionMesh as
  cage plus level when the loaded library has that function; otherwise Blender applies it.
- Lights: point, spot, sun, and area lights as a grid of cosine-weighted points.
- Camera: perspective or orthographic, with sensor fit and lens shift.
- World: the background colour, and the ambient weight of every material (materials.py).
"""

import math
import tempfile

import numpy as np

from . import capi
from .materials import MaterialExporter, ambient_from_world, world_color

GEOMETRY_TYPES = {'MESH', 'CURVE', 'SURFACE', 'FONT', 'META'}
# Renderable kinds Sheaf has no geometry for (reported once per object).
UNSUPPORTED_TYPES = {'CURVES', 'POINTCLOUD', 'VOLUME', 'GPENCIL'}

# Blender's Depth pass is 1e10 where nothing was hit (Sheaf's depth is +inf there).
BACKGROUND_DEPTH = 1.0e10

# Area lights become AREA_GRID x AREA_GRID points.
AREA_GRID = 3


def object_flags(obj):
    """Blender's ray visibility as Sheaf's object flags."""
    flags = 0
    if not getattr(obj, "visible_camera", True):
        flags |= capi.SHEAF_OBJECT_NO_IMAGE
    if not getattr(obj, "visible_shadow", True):
        flags |= capi.SHEAF_OBJECT_NO_SHADOW
    if not getattr(obj, "visible_glossy", True):
        flags |= capi.SHEAF_OBJECT_NO_REFLECTION
    return flags


class ExportError(Exception):
    pass


class Cancelled(Exception):
    pass


class CameraInfo:
    """What the engine needs to turn Sheaf's depth (distance along the ray) into Blender's
    (distance along the view axis)."""

    def __init__(self, ortho, half_y, shift_x, shift_y):
        self.ortho = ortho
        self.half_y = half_y  # perspective: tan(fov_y / 2)
        self.shift_x = shift_x  # image widths
        self.shift_y = shift_y  # image heights

    def axis_depth(self, depth, region=None):
        """depth: (h, w) Sheaf depth, top row first: the whole image, or with `region`
        (x, y, full_width, full_height: sheafFrameGetRegion, y from the top) a part of it.
        Returns the view-axis depth with BACKGROUND_DEPTH where nothing was hit."""
        h, w = depth.shape
        x0, y0, fw, fh = region if region is not None else (0, 0, w, h)
        out = depth.astype(np.float32, copy=True)
        if not self.ortho:
            half_x = self.half_y * fw / fh
            sx = (2.0 * (np.arange(x0, x0 + w) + 0.5) / fw - 1.0 + 2.0 * self.shift_x) * half_x
            sy = (1.0 - 2.0 * (np.arange(y0, y0 + h) + 0.5) / fh + 2.0 * self.shift_y) * self.half_y
            cos = 1.0 / np.sqrt(1.0 + sx[None, :] ** 2 + sy[:, None] ** 2)
            out *= cos.astype(np.float32)
        out[~np.isfinite(out)] = BACKGROUND_DEPTH
        return out


class Exported:
    """A scene built for one render: the Sheaf scene and what the engine needs beside it."""

    def __init__(self, scene, camera, mesh_names, warnings, tempdir):
        self.scene = scene
        self.camera = camera
        self.mesh_names = mesh_names
        self.warnings = warnings
        self.tempdir = tempdir

    def describe_mesh(self, mesh_id):
        if 0 <= mesh_id < len(self.mesh_names):
            return self.mesh_names[mesh_id]
        return None

    def release(self):
        if self.scene is not None:
            self.scene.release()
            self.scene = None
        if self.tempdir is not None:
            self.tempdir.cleanup()
            self.tempdir = None


def render_size(scene):
    r = scene.render
    return (int(r.resolution_x * r.resolution_percentage / 100),
            int(r.resolution_y * r.resolution_percentage / 100))


def export_depsgraph(lib, depsgraph, width, height, check_cancel=None):
    """Builds a Sheaf scene from `depsgraph` for a width x height image. Raises ExportError,
    capi.SheafError or Cancelled; warnings are collected in the result."""
    warnings = []
    tempdir = tempfile.TemporaryDirectory(prefix="sheaf_blender_")
    scene = lib.new_scene()
    try:
        ex = _Exporter(lib, scene, depsgraph, tempdir.name, warnings.append, check_cancel)
        camera = ex.camera(width, height)
        ex.world()
        ex.instances()
        return Exported(scene, camera, ex.mesh_names, warnings, tempdir)
    except BaseException:
        scene.release()
        tempdir.cleanup()
        raise


def matrix_3x4(m):
    """A mathutils 4x4 matrix as 12 floats, row-major [R | t]."""
    return [m[r][c] for r in range(3) for c in range(4)]


def _normalized(v):
    n = math.sqrt(sum(x * x for x in v))
    if n == 0 or not math.isfinite(n):
        raise ExportError("a zero or non-finite axis in an object's matrix")
    return [x / n for x in v]


class _Exporter:
    def __init__(self, lib, scene, depsgraph, tempdir, warn, check_cancel):
        self.lib = lib
        self.scene = scene
        self.depsgraph = depsgraph
        self.bscene = depsgraph.scene
        self.warn = warn
        self.check_cancel = check_cancel
        self.mesh_names = []
        self.meshes = {}  # geometry key -> [(material slot, sheaf mesh id, textured uvs)]
        self.tempdir = tempdir
        self.materials = None
        self.skipped = set()

    # ---- camera ----

    def camera(self, width, height):
        cam_obj = self.bscene.camera
        if cam_obj is None:
            raise ExportError("the scene has no camera")
        cam_obj = cam_obj.evaluated_get(self.depsgraph)
        cam = cam_obj.data
        if width <= 0 or height <= 0:
            raise ExportError("the image is %d x %d pixels; it needs at least one" % (width, height))
        r = self.bscene.render
        if abs(r.pixel_aspect_x - r.pixel_aspect_y) > 1e-6:
            self.warn("non-square pixels (pixel aspect %g:%g) are rendered square"
                      % (r.pixel_aspect_x, r.pixel_aspect_y))
        if cam.type not in ('PERSP', 'ORTHO'):
            raise ExportError("camera '%s': %s cameras are not supported (perspective and "
                              "orthographic are)" % (cam_obj.name, cam.type.lower()))
        fit = cam.sensor_fit
        if fit == 'AUTO':
            sensor = cam.sensor_width
            fit = 'HORIZONTAL' if width >= height else 'VERTICAL'
        else:
            sensor = cam.sensor_width if fit == 'HORIZONTAL' else cam.sensor_height
        viewfac = width if fit == 'HORIZONTAL' else height

        mw = cam_obj.matrix_world
        pos = list(mw.translation)
        forward = _normalized([-mw[i][2] for i in range(3)])
        up = _normalized([mw[i][1] for i in range(3)])

        d = self.scene.camera_desc()
        d.position[:] = pos
        d.look_at[:] = [p + f for p, f in zip(pos, forward)]
        d.up[:] = up
        shift_x = cam.shift_x * viewfac / width
        shift_y = cam.shift_y * viewfac / height
        d.shift[:] = [shift_x, shift_y]
        if cam.type == 'ORTHO':
            d.projection = capi.SHEAF_PROJECTION_ORTHOGRAPHIC
            d.ortho_height = cam.ortho_scale * height / viewfac
            half_y = 0.5 * d.ortho_height
        else:
            d.projection = capi.SHEAF_PROJECTION_PERSPECTIVE
            half_y = 0.5 * height * sensor / (cam.lens * viewfac)
            d.fov_y_degrees = math.degrees(2.0 * math.atan(half_y))
        self.scene.set_camera(d)
        self.depth_of_field(cam_obj, cam, forward)
        return CameraInfo(cam.type == 'ORTHO', half_y, shift_x, shift_y)

    def depth_of_field(self, cam_obj, cam, forward):
        """Blender's depth of field as Cycles reads it: an aperture of radius focal length /
        (2 f-stop) (1 / (2 f-stop) for orthographic cameras), in scene units, sharp at the
        focus distance (or the focus object's depth along the view)."""
        dof = cam.dof
        if not dof.use_dof or dof.aperture_fstop <= 0:
            return
        scale = self.bscene.unit_settings.scale_length or 1.0
        if cam.type == 'ORTHO':
            radius = 1.0 / (2.0 * dof.aperture_fstop)
        else:
            radius = cam.lens * 1e-3 / (2.0 * dof.aperture_fstop) / scale
        distance = dof.focus_distance
        if dof.focus_object is not None:
            to = dof.focus_object.matrix_world.translation - cam_obj.matrix_world.translation
            distance = sum(t * f for t, f in zip(to, forward))
        if distance <= 0:
            self.warn("camera '%s': depth of field with its focus behind the camera is left out"
                      % cam_obj.name)
            return
        if dof.aperture_blades >= 3:
            self.warn("camera '%s': %d aperture blades are rendered as a round lens"
                      % (cam_obj.name, dof.aperture_blades))
        self.scene.set_camera_focus(radius, distance)

    # ---- world ----

    def world(self):
        rgb, warning = world_color(self.bscene.world)
        if warning:
            self.warn(warning)
        self.scene.set_background(rgb)
        self.materials = MaterialExporter(self.scene, self.lib, self.tempdir,
                                          ambient_from_world(rgb), self.warn)

    # ---- objects ----

    def instances(self):
        for n, inst in enumerate(self.depsgraph.object_instances):
            if self.check_cancel and n % 64 == 0 and self.check_cancel():
                raise Cancelled()
            obj = inst.object
            if obj.type == 'LIGHT':
                self.light(obj, inst.matrix_world.copy())
            elif obj.type in GEOMETRY_TYPES and inst.show_self:
                self.geometry(inst, obj)
            elif obj.type in UNSUPPORTED_TYPES and obj.name not in self.skipped:
                self.skipped.add(obj.name)
                self.warn("object '%s': %s objects are not exported" % (obj.name, obj.type.lower()))

    def geometry(self, inst, obj):
        # Evaluated meshes are shared by linked duplicates without modifiers and by every
        # instance of one object; other kinds of geometry are evaluated per object.
        key = obj.data.as_pointer() if obj.type == 'MESH' and obj.data else obj.as_pointer()
        parts = self.meshes.get(key)
        if parts is None:
            parts = self.meshes[key] = self.upload(obj)
        if not parts:
            return
        transform = matrix_3x4(inst.matrix_world)
        flags = object_flags(obj) if self.lib.has_object_flags else 0
        for slot, mesh_id in parts:
            material_id = self.materials.material(slot_material(obj, slot))
            object_id = self.scene.add_object(mesh_id, material_id, transform, obj.name)
            if flags:
                self.scene.set_object_flags(object_id, flags)

    def upload(self, obj):
        """Adds obj's evaluated geometry; returns [(material slot, mesh id)]."""
        sub = self.subdivision_modifier(obj)
        if sub is not None and self.lib.has_subdivision:
            parts = self.upload_subdivision(obj, *sub)
            if parts is not None:
                return parts
        try:
            mesh = obj.to_mesh()
        except RuntimeError as e:
            self.warn("object '%s': no mesh (%s)" % (obj.name, e))
            return []
        if mesh is None:
            return []
        try:
            return self.upload_mesh(obj, mesh)
        finally:
            obj.to_mesh_clear()

    def upload_mesh(self, obj, mesh):
        data = mesh_arrays(mesh)
        if data is None:
            return []
        parts = []
        for slot, positions, normals, uvs, indices in data:
            mesh_id = self.scene.add_mesh(positions, indices, normals)
            if uvs is not None:
                self.scene.set_mesh_uvs(mesh_id, uvs)
            self.name_mesh(mesh_id, "object '%s' (material slot %d)" % (obj.name, slot + 1))
            parts.append((slot, mesh_id))
            mat = slot_material(obj, slot)
            if uvs is None and mat is not None:
                self.materials.material(mat)
                if self.materials.is_textured(mat):
                    self.warn("object '%s': material '%s' has an image texture but the mesh has "
                              "no UV map" % (obj.name, mat.name))
        return parts

    def name_mesh(self, mesh_id, text):
        while len(self.mesh_names) <= mesh_id:
            self.mesh_names.append(None)
        self.mesh_names[mesh_id] = text

    # ---- subdivision surfaces ----

    def subdivision_modifier(self, obj):
        """(modifier, level) when obj's last modifier is an enabled Catmull-Clark Subdivision
        Surface, else None."""
        if obj.type != 'MESH' or not obj.modifiers:
            return None
        mod = obj.modifiers[-1]
        render = self.depsgraph.mode == 'RENDER'
        if mod.type != 'SUBSURF' or not (mod.show_render if render else mod.show_viewport):
            return None
        if getattr(mod, "subdivision_type", 'CATMULL_CLARK') != 'CATMULL_CLARK':
            return None
        level = mod.render_levels if render else mod.levels
        r = self.bscene.render
        if r.use_simplify:
            level = min(level, r.simplify_subdivision_render if render else r.simplify_subdivision)
        if level <= 0:
            return None
        return mod, level

    def upload_subdivision(self, obj, mod, level):
        """Sends the cage and level to sheafSceneAddSubdivisionMesh. Returns None to let
        Blender's own subdivision be used instead."""
        # Blender's boundary smoothing and limit surface as OpenSubdiv's rules (scene options).
        self.scene.set_option(
            "subdivision.boundary",
            "edge_only" if getattr(mod, "boundary_smooth", 'ALL') == 'ALL' else "edge_and_corner")
        self.scene.set_option("subdivision.limit",
                              "1" if getattr(mod, "use_limit_surface", False) else "0")
        mesh = cage_mesh(obj, mod, self.depsgraph)
        if mesh is None:
            return None
        try:
            cage = cage_arrays(mesh, mod.use_creases)
        finally:
            obj.to_mesh_clear()
        if cage is None:
            return None
        slot, positions, face_sizes, face_indices, crease_edges, sharpness, loop_uvs, loop_verts = cage
        if slot < 0:
            self.note_fallback(obj, "its faces use several materials")
            return None
        mat = slot_material(obj, slot)
        uvs = None
        self.materials.material(mat)
        if self.materials.is_textured(mat) and loop_uvs is not None:
            uvs = vertex_uvs(len(positions), loop_verts, loop_uvs)
            if uvs is None:
                self.note_fallback(obj, "its UV map has seams (Sheaf takes one UV per cage vertex)")
                return None
        try:
            mesh_id = self.scene.add_subdivision_mesh(
                positions, face_sizes, face_indices, crease_edges, sharpness, uvs,
                capi.SHEAF_SUBDIV_CATMULL_CLARK, level)
        except capi.SheafError as e:
            self.warn("object '%s': Sheaf could not subdivide the cage (%s); Blender's subdivision "
                      "is used" % (obj.name, e))
            return None
        self.name_mesh(mesh_id, "object '%s' (subdivision cage)" % obj.name)
        return [(slot, mesh_id)]

    def note_fallback(self, obj, why):
        self.warn("object '%s': Blender applies the Subdivision Surface modifier because %s"
                  % (obj.name, why))

    # ---- lights ----

    def light(self, obj, mw):
        light = obj.data
        color = [c * light.energy for c in light.color]
        pos = list(mw.translation)
        direction = _normalized([-mw[i][2] for i in range(3)])
        shadowless = not getattr(light, "use_shadow", True)
        kind = light.type
        if kind == 'SUN':
            d = self.scene.light_desc()
            d.type = capi.SHEAF_LIGHT_PARALLEL
            d.direction[:] = direction
            d.color[:] = [c / math.pi for c in color]
            d.shadowless = shadowless
            self.scene.add_light(d)
            return
        if kind in ('POINT', 'SPOT'):
            d = self.scene.light_desc()
            d.type = capi.SHEAF_LIGHT_POINT if kind == 'POINT' else capi.SHEAF_LIGHT_SPOT
            d.position[:] = pos
            fade = max(light.shadow_soft_size, 0.01)
            # Cycles: intensity P / (4 pi) W/sr; Lambert's 1/pi; Sheaf's fade with power 2
            # tends to 2 fade^2 / d^2, so colour = P / (8 pi^2 fade^2).
            d.color[:] = [c / (8.0 * math.pi ** 2 * fade * fade) for c in color]
            d.fade_distance = fade
            d.fade_power = 2.0
            d.shadowless = shadowless
            if kind == 'SPOT':
                d.direction[:] = direction
                half = math.degrees(light.spot_size) / 2.0
                d.spot_falloff = min(max(half, 1e-3), 180.0)
                d.spot_radius = d.spot_falloff * (1.0 - light.spot_blend)
                d.spot_tightness = 0.0
            self.scene.add_light(d)
            return
        if kind == 'AREA':
            self.area_light(light, mw, color, direction, shadowless)
            return
        self.warn("light '%s': %s lights are not supported" % (obj.name, kind.lower()))

    def area_light(self, light, mw, color, direction, shadowless):
        sx = light.size
        sy = light.size_y if light.shape in ('RECTANGLE', 'ELLIPSE') else light.size
        disk = light.shape in ('DISK', 'ELLIPSE')
        n = AREA_GRID
        # Cell centres of an n x n grid on [-1/2, 1/2]^2, mapped to the disk when round.
        u = (np.arange(n) + 0.5) / n - 0.5
        gx, gy = np.meshgrid(u, u)
        gx, gy = gx.ravel(), gy.ravel()
        if disk:
            gx, gy = _concentric_disk(2 * gx, 2 * gy)
            gx, gy = gx / 2, gy / 2
        count = len(gx)
        fade = max(0.5 * min(sx, sy) / n, 0.01)
        # Cycles: an area light of power P has radiant intensity P / 4 along its normal,
        # falling with cos; each of the `count` points carries its share.
        scale = 1.0 / (4.0 * count * 2.0 * math.pi * fade * fade)
        for x, y in zip(gx, gy):
            p = mw @ _vec((x * sx, y * sy, 0.0))
            d = self.scene.light_desc()
            d.type = capi.SHEAF_LIGHT_SPOT
            d.position[:] = list(p)
            d.direction[:] = direction
            d.spot_radius = 90.0  # the front hemisphere, times cos(angle)
            d.spot_falloff = 90.0
            d.spot_tightness = 1.0
            d.color[:] = [c * scale for c in color]
            d.fade_distance = fade
            d.fade_power = 2.0
            d.shadowless = shadowless
            self.scene.add_light(d)


def slot_material(obj, slot):
    """The material of obj's slot (object- or data-linked), else the mesh's own list (objects
    that geometry nodes make carry no slots), else None."""
    if slot < len(obj.material_slots):
        return obj.material_slots[slot].material
    materials = getattr(obj.data, "materials", None)
    if materials is not None and slot < len(materials):
        return materials[slot]
    return None


def _vec(t):
    from mathutils import Vector

    return Vector(t)


def _concentric_disk(a, b):
    """Shirley and Chiu's square-to-disk map of points in [-1, 1]^2."""
    r = np.where(np.abs(a) > np.abs(b), a, b)
    phi = np.where(np.abs(a) > np.abs(b), (math.pi / 4) * b / np.where(a == 0, 1, a),
                   (math.pi / 2) - (math.pi / 4) * a / np.where(b == 0, 1, b))
    return r * np.cos(phi), r * np.sin(phi)


# ---- mesh data through foreach_get ----


def _get(collection, attr, dtype, per_item):
    out = np.empty(len(collection) * per_item, dtype=dtype)
    collection.foreach_get(attr, out)
    return out.reshape(-1, per_item) if per_item > 1 else out


def _render_uv_layer(mesh):
    layers = mesh.uv_layers
    for layer in layers:
        if layer.active_render:
            return layer
    return layers.active


def mesh_arrays(mesh):
    """A Blender mesh as Sheaf meshes, one per material slot used:
    [(slot, positions (n,3) f32, normals (n,3) f32, uvs (n,2) f32 or None, indices (t,3) u32)].
    Face corners become one vertex where position, split normal and UV agree."""
    mesh.calc_loop_triangles()
    if len(mesh.loop_triangles) == 0:
        return None
    if hasattr(mesh, "calc_normals_split"):
        mesh.calc_normals_split()  # Blender < 4.1: loop normals on request
    co = _get(mesh.vertices, "co", np.float32, 3)
    loop_vert = _get(mesh.loops, "vertex_index", np.int32, 1)
    loop_normal = _get(mesh.loops, "normal", np.float32, 3) + np.float32(0)  # no -0
    tris = _get(mesh.loop_triangles, "loops", np.int32, 3)
    tri_mat = _get(mesh.loop_triangles, "material_index", np.int32, 1)
    layer = _render_uv_layer(mesh)
    loop_uv = _get(layer.data, "uv", np.float32, 2) + np.float32(0) if layer else None

    columns = [loop_vert[:, None], loop_normal.view(np.int32)]
    if loop_uv is not None:
        columns.append(loop_uv.view(np.int32))
    key = np.ascontiguousarray(np.hstack(columns))
    rows = key.view(np.dtype((np.void, key.dtype.itemsize * key.shape[1]))).ravel()
    _, first, corner = np.unique(rows, return_index=True, return_inverse=True)
    corner = corner.ravel()  # loop -> merged corner

    parts = []
    for slot in np.unique(tri_mat):
        tri_corners = corner[tris[tri_mat == slot]]
        used, local = np.unique(tri_corners, return_inverse=True)
        loops = first[used]
        positions = np.ascontiguousarray(co[loop_vert[loops]], dtype=np.float32)
        normals = np.ascontiguousarray(loop_normal[loops], dtype=np.float32)
        uvs = None if loop_uv is None else np.ascontiguousarray(loop_uv[loops], dtype=np.float32)
        indices = np.ascontiguousarray(local.reshape(-1, 3), dtype=np.uint32)
        parts.append((int(slot), positions, normals, uvs, indices))
    return parts


def cage_mesh(obj, mod, depsgraph):
    """The mesh obj's modifier stack gives without its last modifier `mod`: the modifier is
    switched off on the evaluated copy (never on the user's object) while Blender evaluates the
    stack again from the object's pre-modifier mesh. The caller calls obj.to_mesh_clear()."""
    attr = "show_render" if depsgraph.mode == 'RENDER' else "show_viewport"
    setattr(mod, attr, False)
    try:
        return obj.to_mesh(preserve_all_data_layers=True, depsgraph=depsgraph)
    except RuntimeError:
        return None
    finally:
        setattr(mod, attr, True)


def cage_arrays(mesh, use_creases):
    """(slot, positions, face_sizes, face_indices, crease_edges, crease_sharpness, loop_uvs,
    loop_verts) of a cage, slot -1 when its faces use several materials; None when empty."""
    if len(mesh.polygons) == 0:
        return None
    positions = np.ascontiguousarray(_get(mesh.vertices, "co", np.float32, 3))
    starts = _get(mesh.polygons, "loop_start", np.int64, 1)
    sizes = _get(mesh.polygons, "loop_total", np.int64, 1)
    mats = _get(mesh.polygons, "material_index", np.int32, 1)
    loop_vert = _get(mesh.loops, "vertex_index", np.int64, 1)
    # The loops of each face in face order (Blender stores them so; this does not rely on it).
    offsets = np.cumsum(sizes) - sizes
    loops = np.repeat(starts - offsets, sizes) + np.arange(int(sizes.sum()))
    face_indices = np.ascontiguousarray(loop_vert[loops], dtype=np.uint32)
    crease_edges = sharpness = None
    if use_creases and len(mesh.edges):
        crease = None
        try:
            crease = _get(mesh.edges, "crease", np.float32, 1)
        except (AttributeError, TypeError, RuntimeError):
            attr = mesh.attributes.get("crease")
            if attr is not None and attr.domain == 'EDGE':
                crease = _get(attr.data, "value", np.float32, 1)
        if crease is not None and np.any(crease > 0):
            edges = _get(mesh.edges, "vertices", np.int64, 2)
            sel = crease > 0
            crease_edges = np.ascontiguousarray(edges[sel], dtype=np.uint32)
            # Blender's crease c in 0..1 is OpenSubdiv sharpness 10 c^2.
            sharpness = np.ascontiguousarray(10.0 * crease[sel] ** 2, dtype=np.float32)
    layer = _render_uv_layer(mesh)
    loop_uvs = _get(layer.data, "uv", np.float32, 2)[loops] if layer else None
    slot = int(mats[0]) if np.all(mats == mats[0]) else -1
    return (slot, positions, np.ascontiguousarray(sizes, dtype=np.uint32), face_indices,
            crease_edges, sharpness, loop_uvs, loop_vert[loops])


def vertex_uvs(vertex_count, loop_verts, loop_uvs):
    """One UV per vertex when every corner of a vertex has the same UV, else None."""
    uvs = np.zeros((vertex_count, 2), dtype=np.float32)
    uvs[loop_verts] = loop_uvs
    if not np.allclose(uvs[loop_verts], loop_uvs, atol=1e-6):
        return None
    return uvs
