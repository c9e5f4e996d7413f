// The prepared scene in the executing side's memory, copied once per frame, and the SceneView
// of it that every launch takes by value. The small arrays (materials, lights, CSG nodes ...)
// are packed into one buffer and copied at once, one host wait instead of one each; an array
// of at least kOwnCopy bytes (a large mesh's triangles) is copied on its own, where the copy's
// fixed cost is small against its transfer and packing would add a pass over its bytes on the
// host. Image textures stay behind (OpenImageIO is host-only): scenes that use them render on
// the CPU backend.
#pragma once

#include "core/render/photon_pass.h"
#include "core/rsh/cull_units.h"
#include "core/scene/scene_view.h"
#include "core/wavefront/buffer.h"

#include <cstdint>
#include <cstring>
#include <functional>
#include <vector>

namespace sheaf::wavefront {

/// The culling units (core/rsh/cull_units.h) on the executing side.
struct CullView {
    const uint32_t* begin = nullptr; // count + 1 entries
    const Sphere* sphere = nullptr;
    const uint32_t* object = nullptr;
    const uint32_t* object_units = nullptr; // objects + 1 entries
    uint32_t count = 0;
};

template <class Exec> class DeviceScene {
  public:
    static constexpr size_t kOwnCopy = size_t(1) << 20;

    /// `photons`: the frame's photon map (shot on the host, core/render/photon_pass.h), or none.
    DeviceScene(Exec& exec, const PreparedScene& p, const CullUnits& units,
                const PhotonMap* photons = nullptr)
        : exec_(exec) {
        SceneView& v = view;
        v = SceneView(p); // counts and plain values; every pointer is replaced below
        if (photons) {
            v.photon_map = photons->view();
            put(photons->photons, v.photon_map.photons);
        }
        put(p.tris, v.tris);
        put(p.normals, v.normals);
        put(p.uvs, v.uvs);
        put(p.prim_object, v.prim_object);
        put(p.prim_sphere, v.prim_sphere);
        put(p.prim_flags, v.prim_flags);
        put(p.object_begin, v.object_begin);
        put(p.object_sphere, v.object_sphere);
        put(p.object_material, v.object_material);
        put(p.shapes, v.shapes);
        put(p.polys, v.polys);
        put(p.glyphs, v.glyphs);
        put(p.glyph_segments, v.glyph_segments);
        put(p.revolutions, v.revolutions);
        put(p.revolution_segments, v.revolution_segments);
        put(p.blobs, v.blobs);
        put(p.blob_elements, v.blob_elements);
        put(p.isosurfaces, v.isosurfaces);
        put(p.julias, v.julias);
        put(p.fn_programs, v.functions.programs);
        put(p.fn_code, v.functions.code);
        put(p.fn_patterns, v.functions.patterns);
        put(p.fn_pigments, v.functions.pigments);
        put(p.fn_pigment_entries, v.functions.pigment_entries);
        put(p.shape_material, v.shape_material);
        put(p.csg, v.csg);
        put(p.csg_children, v.csg_children);
        put(p.analytic_root, v.analytic_root);
        put(p.materials, v.materials);
        put(p.pigments, v.pigments);
        put(p.pigment_entries, v.pigment_entries);
        put(p.normal_patterns, v.normal_patterns);
        put(p.slope_entries, v.slope_entries);
        put(p.normal_map_entries, v.normal_map_entries);
        put(p.material_switches, v.material_switches);
        put(p.warps, v.warps);
        put(p.material_entries, v.material_entries);
        put(p.media, v.media);
        put(p.medium_densities, v.medium_densities);
        put(p.media_containers, v.media_containers);
        put(p.media_solids, v.media_solids);
        put(p.lights, v.lights);
        put(p.rainbows, v.rainbows);
        put(p.camera_faces, v.camera_faces);
        put(p.camera_meshes, v.camera_meshes);
        put(p.camera_uv_cells, v.camera_uv_cells);
        put(p.camera_uv_faces, v.camera_uv_faces);
        put(units.begin, cull.begin);
        put(units.sphere, cull.sphere);
        put(units.object, cull.object);
        put(units.object_units, cull.object_units);
        cull.count = uint32_t(units.count());
        v.textures = nullptr;
        v.sampler = nullptr;
        packed_ = DeviceBuffer<uint8_t, Exec>(exec, staging_.size());
        packed_.upload(staging_.data(), staging_.size());
        for (const auto& point : pointers_) point(packed_.data());
        staging_ = {}, pointers_ = {};
        // The same device copy; only now, after the packed arrays' pointers are set (a small
        // warp table is packed, and its pointer was null until the line above).
        v.functions.warps = v.warps;
    }

    SceneView view;
    CullView cull;

  private:
    // A large src is copied into a buffer of its own; a small one is appended to the staging
    // bytes at an offset aligned for any of the scene's types (buffers are at least
    // 16-aligned), and dst is pointed at it once the packed buffer exists.
    template <class T> void put(const std::vector<T>& src, const T*& dst) {
        static_assert(alignof(T) <= 16, "the packed scene buffer aligns arrays to 16 bytes");
        dst = nullptr;
        const size_t bytes = src.size() * sizeof(T);
        if (bytes == 0) return;
        if (bytes >= kOwnCopy) {
            DeviceBuffer<uint8_t, Exec> b(exec_, bytes);
            b.upload(reinterpret_cast<const uint8_t*>(src.data()), bytes);
            dst = reinterpret_cast<const T*>(b.data());
            own_.push_back(std::move(b));
            return;
        }
        const size_t offset = (staging_.size() + 255) / 256 * 256;
        staging_.resize(offset + bytes);
        std::memcpy(staging_.data() + offset, src.data(), bytes);
        pointers_.push_back(
            [&dst, offset](const uint8_t* base) { dst = reinterpret_cast<const T*>(base + offset); });
    }

    Exec& exec_;
    std::vector<uint8_t> staging_;
    std::vector<std::function<void(const uint8_t*)>> pointers_;
    DeviceBuffer<uint8_t, Exec> packed_;
    std::vector<DeviceBuffer<uint8_t, Exec>> own_;
};

} // namespace sheaf::wavefront
