// The prepared scene in the executing side's memory: each of PreparedScene's arrays copied
// once per frame, and the SceneView of them that every launch takes by value. Image textures
// stay behind (OpenImageIO is host-only): scenes that use them render on the CPU backend.
#pragma once

#include "core/scene/scene_view.h"
#include "core/wavefront/buffer.h"

#include <cstdint>
#include <vector>

namespace sheaf::wavefront {

template <class Exec> class DeviceScene {
  public:
    DeviceScene(Exec& exec, const PreparedScene& p) : exec_(exec) {
        SceneView& v = view;
        v = SceneView(p); // counts and plain values; every pointer is replaced below
        v.tris = put(p.tris);
        v.normals = put(p.normals);
        v.uvs = put(p.uvs);
        v.prim_object = put(p.prim_object);
        v.prim_sphere = put(p.prim_sphere);
        v.prim_flags = put(p.prim_flags);
        v.object_begin = put(p.object_begin);
        v.object_sphere = put(p.object_sphere);
        v.object_material = put(p.object_material);
        v.shapes = put(p.shapes);
        v.shape_material = put(p.shape_material);
        v.csg = put(p.csg);
        v.csg_children = put(p.csg_children);
        v.analytic_root = put(p.analytic_root);
        v.materials = put(p.materials);
        v.pigments = put(p.pigments);
        v.pigment_entries = put(p.pigment_entries);
        v.normal_patterns = put(p.normal_patterns);
        v.material_switches = put(p.material_switches);
        v.material_entries = put(p.material_entries);
        v.lights = put(p.lights);
        v.textures = nullptr;
        v.sampler = nullptr;
    }

    SceneView view;

  private:
    template <class T> const T* put(const std::vector<T>& src) {
        if (src.empty()) return nullptr;
        DeviceBuffer<uint8_t, Exec> b(exec_, src.size() * sizeof(T));
        b.upload(reinterpret_cast<const uint8_t*>(src.data()), src.size() * sizeof(T));
        const T* p = reinterpret_cast<const T*>(b.data());
        buffers_.push_back(std::move(b));
        return p;
    }

    Exec& exec_;
    std::vector<DeviceBuffer<uint8_t, Exec>> buffers_;
};

} // namespace sheaf::wavefront
