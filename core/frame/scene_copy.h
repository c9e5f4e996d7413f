// The prepared scene in the executing side's memory, and the SceneView of it that every launch
// takes by value. It is copied once per frame, or once for many frames where the exec outlives
// them (SceneKeep). The small arrays (materials, lights, CSG nodes ...)
// are packed into one buffer and copied at once, one host wait instead of one each; an array
// of at least kOwnCopy bytes (a large mesh's triangles) is copied on its own, where the copy's
// fixed cost is small against its transfer and packing would add a pass over its bytes on the
// host. Image textures stay behind (OpenImageIO is host-only): scenes that use them render on
// the CPU backend.
#pragma once

#include "core/base/content_hash.h"
#include "core/frame/buffer.h"
#include "core/frame/photon_pass.h"
#include "core/rsh/cull_units.h"
#include "core/scene/scene_view.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

namespace sheaf::wavefront {

/// The culling units (core/rsh/cull_units.h) on the executing side.
struct CullView {
    const uint32_t* begin = nullptr; // count + 1 entries
    const Sphere* sphere = nullptr;
    const uint32_t* object = nullptr;
    const uint32_t* object_units = nullptr; // objects + 1 entries
    uint32_t count = 0;
    BvhView bvh;       // accel=bvh (CullUnits::bvh); empty otherwise
    StripsView strips; // accel=strips (CullUnits::strips); empty otherwise
};

/// The units in host memory, for an exec that reads it (no copy).
inline CullView host_cull_view(const CullUnits& u) {
    return {u.begin.data(),
            u.sphere.data(),
            u.object.data(),
            u.object_units.data(),
            uint32_t(u.count()),
            u.bvh ? u.bvh->view() : BvhView{},
            u.strips ? u.strips->view() : StripsView{}};
}

/// The units' BVH, or an empty one.
inline const Bvh& units_bvh(const CullUnits& u) {
    static const Bvh none;
    return u.bvh ? *u.bvh : none;
}

/// The units' strips, or empty ones.
inline const Strips& units_strips(const CullUnits& u) {
    static const Strips none;
    return u.strips ? *u.strips : none;
}

template <class Exec> class DeviceScene {
  public:
    static constexpr size_t kOwnCopy = size_t(1) << 20;

    /// `photons`: the frame's photon map (shot on the host, core/frame/photon_pass.h), or none.
    DeviceScene(Exec& exec, const PreparedScene& p, const CullUnits& units,
                const PhotonMap* photons = nullptr)
        : exec_(exec) {
        SceneView v;
        CullView c;
        std::vector<uint8_t> staging;
        arrays(p, units, photons, v, c, [&](const auto& src, const auto*&) { put(src, staging); });
        packed_ = DeviceBuffer<uint8_t, Exec>(exec, staging.size());
        packed_.upload(staging.data(), staging.size());
        for (Slot& slot : slots_)
            if (slot.packed) slot.at = packed_.data() + slot.offset;
        bytes_ += staging.size();
        bind(p, units, photons);
    }
    DeviceScene(const DeviceScene&) = delete;
    DeviceScene& operator=(const DeviceScene&) = delete;

    /// What this copy holds, as compared between frames (SceneKeep): every array it copies,
    /// in order, lengths included.
    static Digest content(const PreparedScene& p, const CullUnits& units,
                          const PhotonMap* photons) {
        ContentHasher h;
        h.add_value(photons ? 1 : 0);
        SceneView v;
        CullView c;
        arrays(p, units, photons, v, c, [&](const auto& src, const auto*&) { h.add(src); });
        return h.digest();
    }

    /// Points `view` and `cull` at this copy for `p`, whose arrays are the ones copied
    /// (content() equal): the counts and plain values come from `p`, the arrays from here.
    void bind(const PreparedScene& p, const CullUnits& units, const PhotonMap* photons) {
        SceneView& v = view;
        v = SceneView(p); // counts and plain values; every pointer is replaced below
        if (photons) v.photon_map = photons->view();
        size_t k = 0;
        arrays(p, units, photons, v, cull, [&](const auto& src, const auto*& dst) {
            using T = typename std::decay_t<decltype(src)>::value_type;
            dst = static_cast<const T*>(static_cast<const void*>(slots_.at(k++).at));
        });
        cull.count = uint32_t(units.count());
        const BvhView b = units_bvh(units).view();
        cull.bvh.node_count = b.node_count, cull.bvh.prim_count = b.prim_count;
        cull.bvh.unbounded_count = b.unbounded_count;
        const StripsView sv = units_strips(units).view();
        cull.strips.top.node_count = sv.top.node_count,
        cull.strips.top.prim_count = sv.top.prim_count;
        cull.strips.top.unbounded_count = sv.top.unbounded_count;
        cull.strips.strip_count = sv.strip_count;
        v.textures = nullptr;
        v.sampler = nullptr;
        // The same device copy, the packed arrays' pointers set above (a small warp table is
        // packed).
        v.functions.warps = v.warps;
    }

    /// Device memory this copy holds.
    size_t bytes() const { return bytes_; }
    const Exec& exec() const { return exec_; }

    SceneView view;
    CullView cull;

  private:
    /// f(host array, the view's pointer to it) for every array the device needs, in one fixed
    /// order: the copy, its content digest and the view's pointers all walk this list.
    template <class F>
    static void arrays(const PreparedScene& p, const CullUnits& units, const PhotonMap* photons,
                       SceneView& v, CullView& cull, F&& f) {
        if (photons) f(photons->photons, v.photon_map.photons);
        f(p.tris, v.tris);
        f(p.normals, v.normals);
        f(p.uvs, v.uvs);
        f(p.prim_object, v.prim_object);
        f(p.prim_sphere, v.prim_sphere);
        f(p.analytic_box, v.analytic_box);
        f(p.prim_flags, v.prim_flags);
        f(p.object_begin, v.object_begin);
        f(p.object_sphere, v.object_sphere);
        f(p.object_material, v.object_material);
        f(p.shapes, v.shapes);
        f(p.polys, v.polys);
        f(p.glyphs, v.glyphs);
        f(p.glyph_segments, v.glyph_segments);
        f(p.revolutions, v.revolutions);
        f(p.revolution_segments, v.revolution_segments);
        f(p.blobs, v.blobs);
        f(p.blob_elements, v.blob_elements);
        f(p.isosurfaces, v.isosurfaces);
        f(p.julias, v.julias);
        f(p.fn_programs, v.functions.programs);
        f(p.fn_code, v.functions.code);
        f(p.fn_patterns, v.functions.patterns);
        f(p.fn_pigments, v.functions.pigments);
        f(p.fn_pigment_entries, v.functions.pigment_entries);
        f(p.shape_material, v.shape_material);
        f(p.csg, v.csg);
        f(p.csg_children, v.csg_children);
        f(p.analytic_root, v.analytic_root);
        f(p.materials, v.materials);
        f(p.pigments, v.pigments);
        f(p.pigment_entries, v.pigment_entries);
        f(p.normal_patterns, v.normal_patterns);
        f(p.slope_entries, v.slope_entries);
        f(p.normal_map_entries, v.normal_map_entries);
        f(p.material_switches, v.material_switches);
        f(p.warps, v.warps);
        f(p.material_entries, v.material_entries);
        f(p.media, v.media);
        f(p.medium_densities, v.medium_densities);
        f(p.density_grids, v.density_grids);
        f(p.density_voxels, v.density_voxels);
        f(p.media_containers, v.media_containers);
        f(p.media_solid_bvh.nodes, v.media_solid_bvh.nodes);
        f(p.media_solid_bvh.prims, v.media_solid_bvh.prims);
        f(p.media_solid_bvh.unbounded, v.media_solid_bvh.unbounded);
        f(p.lights, v.lights);
        f(p.rainbows, v.rainbows);
        f(p.camera_faces, v.camera_faces);
        f(p.camera_meshes, v.camera_meshes);
        f(p.camera_uv_cells, v.camera_uv_cells);
        f(p.camera_uv_faces, v.camera_uv_faces);
        f(units.begin, cull.begin);
        f(units.sphere, cull.sphere);
        f(units.object, cull.object);
        f(units.object_units, cull.object_units);
        f(units_bvh(units).nodes, cull.bvh.nodes);
        f(units_bvh(units).prims, cull.bvh.prims);
        f(units_bvh(units).unbounded, cull.bvh.unbounded);
        const Strips& strips = units_strips(units);
        f(strips.top.nodes, cull.strips.top.nodes);
        f(strips.top.prims, cull.strips.top.prims);
        f(strips.top.unbounded, cull.strips.top.unbounded);
        f(strips.strips, cull.strips.strips);
        f(strips.planes, cull.strips.planes);
        f(strips.meta, cull.strips.meta);
        f(strips.index, cull.strips.index);
        f(strips.ids, cull.strips.ids);
        f(strips.verts, cull.strips.verts);
    }

    /// Where one array lives: in a buffer of its own, or at `offset` in the packed buffer.
    struct Slot {
        bool packed = false;
        size_t offset = 0;
        const uint8_t* at = nullptr; // null for an empty array
    };

    // A large src is copied into a buffer of its own; a small one is appended to the staging
    // bytes at an offset aligned for any of the scene's types (buffers are at least
    // 16-aligned), and its slot points into the packed buffer once that exists.
    template <class T> void put(const std::vector<T>& src, std::vector<uint8_t>& staging) {
        static_assert(alignof(T) <= 16, "the packed scene buffer aligns arrays to 16 bytes");
        Slot& slot = slots_.emplace_back();
        const size_t bytes = src.size() * sizeof(T);
        if (bytes == 0) return;
        if (bytes >= kOwnCopy) {
            DeviceBuffer<uint8_t, Exec> b(exec_, bytes);
            b.upload(reinterpret_cast<const uint8_t*>(src.data()), bytes);
            slot.at = b.data();
            bytes_ += bytes;
            own_.push_back(std::move(b));
            return;
        }
        slot.packed = true;
        slot.offset = (staging.size() + 255) / 256 * 256;
        staging.resize(slot.offset + bytes);
        std::memcpy(staging.data() + slot.offset, src.data(), bytes);
    }

    Exec& exec_;
    std::vector<Slot> slots_;
    DeviceBuffer<uint8_t, Exec> packed_;
    std::vector<DeviceBuffer<uint8_t, Exec>> own_;
    size_t bytes_ = 0;
};

/// The scene an exec that outlives its frames copied last, kept on its side for the next
/// frame: a frame whose arrays have the same content (a 128-bit digest of every array the copy
/// holds, so an edited or another scene is copied anew) binds the kept copy instead of copying
/// it again. It holds one scene; a new one replaces it, the old freed first.
template <class Exec> class SceneKeep {
  public:
    /// The copy of `p` on `exec`'s side; `reused`: whether it is the one kept from before.
    DeviceScene<Exec>& scene(Exec& exec, const PreparedScene& p, const CullUnits& units,
                             const PhotonMap* photons, bool& reused) {
        const Digest content = DeviceScene<Exec>::content(p, units, photons);
        reused = kept_ && content_ == content && &kept_->exec() == &exec;
        if (reused) {
            kept_->bind(p, units, photons);
            return *kept_;
        }
        kept_.reset();
        kept_ = std::make_unique<DeviceScene<Exec>>(exec, p, units, photons);
        content_ = content;
        return *kept_;
    }
    /// Frees the kept copy.
    void clear() { kept_.reset(); }
    bool holds() const { return kept_ != nullptr; }

  private:
    std::unique_ptr<DeviceScene<Exec>> kept_;
    Digest content_;
};

} // namespace sheaf::wavefront
