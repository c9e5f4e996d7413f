// POV-Ray's mesh camera (Projection::Mesh): a sample's primary ray leaves a face of the
// scene's camera meshes along its normal, the face chosen by the camera's distribution (see
// Camera::mesh_distribution), as POV-Ray 3.7 chooses it. Host-and-device.
#pragma once

#include "core/geometry/ray.h"
#include "core/raster/camera.h"
#include "core/scene/scene_view.h"

#include <cfloat>

namespace sheaf {

namespace mesh_camera_detail {

/// Distribution 3: the first face of the first mesh whose uv triangle holds (u, v), and the
/// point's barycentric weights there (POV-Ray's formula); false when none does.
SHEAF_HD_INLINE bool uv_face(const SceneView& s, float u, float v, uint32_t& face, float& b1,
                             float& b2, float& b3) {
    if (!s.camera_uv_cells) return false;
    const float g = float(kCameraUvGrid);
    const uint32_t cu = uint32_t(hdm::fminf(hdm::fmaxf(u * g, 0.0f), g - 1.0f));
    const uint32_t cv = uint32_t(hdm::fminf(hdm::fmaxf(v * g, 0.0f), g - 1.0f));
    const uint32_t cell = cv * kCameraUvGrid + cu;
    for (uint32_t k = s.camera_uv_cells[cell]; k < s.camera_uv_cells[cell + 1]; ++k) {
        const CameraFace& f = s.camera_faces[s.camera_uv_faces[k]];
        const float scale =
            (f.s[1] - f.s[0]) * (f.t[2] - f.t[0]) - (f.s[2] - f.s[0]) * (f.t[1] - f.t[0]);
        if (!(scale != 0)) continue; // no area in uv space
        const float w1 = ((f.s[1] - u) * (f.t[2] - v) - (f.s[2] - u) * (f.t[1] - v)) / scale;
        const float w2 = ((f.s[2] - u) * (f.t[0] - v) - (f.s[0] - u) * (f.t[2] - v)) / scale;
        const float w3 = ((f.s[0] - u) * (f.t[1] - v) - (f.s[1] - u) * (f.t[0] - v)) / scale;
        if (w1 < 0 || w2 < 0 || w3 < 0) continue;
        face = s.camera_uv_faces[k];
        b1 = w1, b2 = w2, b3 = w3;
        return true;
    }
    return false;
}

} // namespace mesh_camera_detail

/// The mesh camera's ray for sample (x, y) of a cam.width x cam.height grid of samples,
/// cam.samples x cam.samples to a pixel; false where the sample has no face (it stays black).
SHEAF_HD_INLINE bool mesh_camera_ray(const SceneView& s, const CameraFrame& cam, int x, int y,
                                     Ray& r) {
    using namespace mesh_camera_detail;
    if (s.camera_mesh_count == 0) return false;
    const int n = cam.samples > 0 ? cam.samples : 1;
    const uint32_t width = uint32_t(cam.width / n); // in pixels
    // POV-Ray 3.7's mesh camera shows the faces of row j - 1 in pixel row j (row 0 its own),
    // as measured against povray (its demo meshes are built a row lower to match).
    const uint32_t px = uint32_t(x / n), py = uint32_t(y / n), row = py > 0 ? py - 1 : 0;
    const uint32_t pixel = row * width + px;
    float b1 = 1.0f / 3, b2 = 1.0f / 3, b3 = 1.0f / 3; // the centroid
    uint32_t face = 0;
    bool smooth = false;
    switch (cam.mesh_distribution) {
    case 0: { // sample k of the pixel's s: mesh k (modulo the rays; more rays than samples:
              // an even share of them), face = the pixel
        const uint32_t k = uint32_t(x % n + n * (y % n)), s_count = uint32_t(n * n);
        const uint32_t rays = cam.mesh_rays > 0 ? cam.mesh_rays : 1u;
        const uint32_t mesh = rays <= s_count ? k % rays : uint32_t(uint64_t(k) * rays / s_count);
        if (mesh >= s.camera_mesh_count || pixel >= s.camera_meshes[mesh].count) return false;
        face = s.camera_meshes[mesh].first + pixel;
        break;
    }
    case 1: // the meshes' faces one after another
        if (pixel >= s.camera_face_count) return false;
        face = pixel;
        break;
    case 2: { // the meshes side by side, each a band of columns (POV-Ray's indexing)
        const uint32_t meshes = s.camera_mesh_count;
        const uint32_t mesh = uint32_t(float(px) / (float(width) / float(meshes)));
        const uint32_t index = row * (width / meshes) + px;
        if (mesh >= meshes || index >= s.camera_meshes[mesh].count) return false;
        face = s.camera_meshes[mesh].first + index;
        break;
    }
    default: { // 3: the first mesh's uv coordinates at the pixel's top left corner, as
               // POV-Ray's (its samples spread around it)
        const float u = (float(x) + 0.5f - 0.5f * float(n)) / float(cam.width);
        const float v = 1.0f - (float(y) + 0.5f - 0.5f * float(n)) / float(cam.height);
        if (!uv_face(s, u, v, face, b1, b2, b3)) return false;
        smooth = cam.mesh_smooth;
        break;
    }
    }
    const CameraFace& f = s.camera_faces[face];
    Vec3 origin = f.a * b1 + f.b * b2 + f.c * b3;
    Vec3 dir = f.n;
    if (smooth) {
        const Vec3 sn = f.na * b1 + f.nb * b2 + f.nc * b3;
        const float l = length(sn);
        if (l > 0) dir = sn / l;
    }
    origin = origin + dir * cam.mesh_offset; // POV-Ray's location z
    if (cam.mesh_reverse) dir = -dir;        // its direction z < 0
    const CameraMeshRef& m = s.camera_meshes[f.mesh];
    const Vec3 d = m.normal_to_world.vector(dir);
    const float len = length(d);
    if (!(len > 0) || !(len <= FLT_MAX)) return false;
    r.origin = m.to_world.point(origin);
    r.dir = d / len;
    r.tmin = 0.0f;
    r.tmax = FLT_MAX;
    return true;
}

} // namespace sheaf
