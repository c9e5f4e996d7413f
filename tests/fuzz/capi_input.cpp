#include "tests/fuzz/capi_input.h"

#include "tests/fuzz/promises.h"

#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace sheaf::fuzz {
namespace {

/// The input read front to back; past its end every read gives zeros.
class Bytes {
  public:
    Bytes(const uint8_t* data, size_t size) : data_(data), size_(size) {}
    bool done() const { return at_ >= size_; }
    uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
    uint32_t u32() {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= uint32_t(u8()) << (8 * i);
        return v;
    }
    /// A float a host might pass: small values mostly, and the extremes.
    float f32() {
        const uint8_t tag = u8();
        switch (tag % 10) {
        case 0:
            return float(int(u8()) - 128) / 16.0f;
        case 1:
            return float(int(u8()) - 128);
        case 2:
            return std::numeric_limits<float>::quiet_NaN();
        case 3:
            return std::numeric_limits<float>::infinity();
        case 4:
            return -std::numeric_limits<float>::infinity();
        case 5:
            return (u8() & 1 ? -1.0f : 1.0f) * 1e30f;
        case 6:
            return std::numeric_limits<float>::denorm_min();
        case 7: {
            const uint32_t bits = u32();
            float f;
            std::memcpy(&f, &bits, sizeof f);
            return f;
        }
        default:
            return float(u8()) / 64.0f;
        }
    }
    /// An integer around [lo, hi], now and then far outside it.
    int64_t in(int64_t lo, int64_t hi) {
        if (hi < lo) hi = lo;
        const uint8_t tag = u8();
        if (tag < 224) return lo + int64_t(u8()) % (hi - lo + 1);
        switch (tag % 6) {
        case 0:
            return lo - 1;
        case 1:
            return hi + 1;
        case 2:
            return std::numeric_limits<int32_t>::min();
        case 3:
            return std::numeric_limits<int32_t>::max();
        case 4:
            return int64_t(u32());
        default:
            return -int64_t(u32());
        }
    }
    /// A short string of the input's bytes (NUL-free).
    std::string text(size_t most) {
        const size_t n = u8() % (most + 1);
        std::string s;
        for (size_t i = 0; i < n && !done(); ++i) {
            const char c = char(u8());
            s += c ? c : ' ';
        }
        return s;
    }
    template <size_t N> const char* pick(const char* const (&options)[N]) {
        return options[u8() % N];
    }

  private:
    const uint8_t* data_;
    size_t size_;
    size_t at_ = 0;
};

/// Calls the C ABI and checks the promise of a failed call.
class Host {
  public:
    Host(Bytes& in, std::FILE* log, CapiMode mode) : in_(in), log_(log), mode_(mode) {
        if (sheafSceneNew(&scene_) != SHEAF_OK) broken("sheafSceneNew failed");
        if (sheafRendererNew(&renderer_) != SHEAF_OK) broken("sheafRendererNew failed");
        if (mode_ == CapiMode::Accels) {
            const float eye[3] = {2, 4, -11}, at[3] = {0, 0, 0}, up[3] = {0, 1, 0};
            const float light[3] = {-6, 12, -9}, white[3] = {1, 1, 1};
            check("sheafSceneSetCamera", sheafSceneSetCamera(scene_, eye, at, up, 50));
            check("sheafSceneAddPointLight", sheafSceneAddPointLight(scene_, light, white));
        }
    }
    ~Host() {
        sheafRendererRelease(renderer_);
        sheafSceneRelease(scene_);
    }

    void step() {
        const uint8_t op = in_.u8();
        if (mode_ == CapiMode::Accels && op >= 160) return add_lattice_mesh();
        switch (op % 20) {
        case 0:
            add_material();
            break;
        case 1:
            add_mesh();
            break;
        case 2:
            add_object();
            break;
        case 3:
            check("sheafSceneSetObjectFlags",
                  sheafSceneSetObjectFlags(scene_, id(objects_), uint32_t(in_.in(0, 8))));
            break;
        case 4: {
            const auto p = vec(3), c = vec(3);
            check("sheafSceneAddPointLight", sheafSceneAddPointLight(scene_, maybe(p), maybe(c)));
            break;
        }
        case 5: {
            const auto p = vec(3), l = vec(3), u = vec(3);
            check("sheafSceneSetCamera",
                  sheafSceneSetCamera(scene_, maybe(p), maybe(l), maybe(u), in_.f32()));
            break;
        }
        case 6: {
            const auto c = vec(3);
            check("sheafSceneSetBackground", sheafSceneSetBackground(scene_, maybe(c)));
            break;
        }
        case 7:
            add_light();
            break;
        case 8:
            set_camera();
            break;
        case 9: {
            const auto lengths = vec(3);
            check("sheafSceneSetCameraLens",
                  sheafSceneSetCameraLens(scene_, in_.f32(), in_.f32(), maybe(lengths)));
            break;
        }
        case 10:
            check("sheafSceneSetCameraFocus",
                  sheafSceneSetCameraFocus(scene_, in_.f32(), in_.f32()));
            break;
        case 11:
            set_uvs();
            break;
        case 12:
            add_subdivision();
            break;
        case 13:
            set_load_option();
            break;
        case 14:
            add_texture();
            break;
        case 15:
        case 16:
            set_setting();
            break;
        case 17:
            check("sheafSceneCommit", sheafSceneCommit(scene_));
            break;
        case 18:
            // A few renders an input: more find nothing new and slow the fuzzer down.
            if (renders_ < 3) ++renders_, render_small(scene_, log_, renderer_);
            break;
        default:
            query();
            break;
        }
    }

    void finish() {
        if (!check("sheafSceneCommit", sheafSceneCommit(scene_))) return;
        // The renderer as the calls left it, region.* included (render_small then sets the
        // whole frame, for what follows).
        render_small(scene_, log_, renderer_);
        if (mode_ == CapiMode::Calls) return;
        // Every accel finds brute force's hits (ties to the lower primitive), so the images
        // are equal; a render that fails must fail under all of them.
        static const char* const accels[] = {"brute",    "crsh",    "rah",   "bvh",
                                             "crsh-bvh", "rah-bvh", "strips"};
        std::vector<float> first;
        for (const char* accel : accels) {
            if (sheafRendererSetString(renderer_, "accel", accel) != SHEAF_OK)
                broken(std::string("accel=") + accel + " was refused");
            const std::vector<float> image = render_small(scene_, log_, renderer_);
            if (accel == accels[0]) {
                first = image;
            } else if (image.empty() != first.empty()) {
                broken(std::string("accel=") + accel + (image.empty() ? " failed" : " rendered") +
                       " where accel=brute " + (first.empty() ? "failed" : "rendered"));
            } else if (!image.empty() &&
                       std::memcmp(image.data(), first.data(), image.size() * sizeof(float))) {
                size_t i = 0;
                while (image[i] == first[i]) ++i;
                broken(std::string("accel=") + accel + ": pixel " + std::to_string(i / 4) +
                       " channel " + std::to_string(i % 4) + " is " + std::to_string(image[i]) +
                       ", " + std::to_string(first[i]) + " under accel=brute");
            }
        }
    }

  private:
    bool check(const char* call, SheafError e) {
        if (e == SHEAF_OK) {
            if (log_) std::fprintf(log_, "  %s ok\n", call);
            return true;
        }
        const std::string message = failure(call, e);
        if (log_) std::fprintf(log_, "  %s error %d: %s\n", call, int(e), message.c_str());
        return false;
    }
    std::vector<float> vec(size_t n) {
        std::vector<float> v(n);
        for (float& f : v) f = in_.f32();
        return v;
    }
    /// The data, or now and then NULL where a pointer is asked for.
    template <class T> const T* maybe(const std::vector<T>& v) {
        return in_.u8() < 16 ? nullptr : v.data();
    }
    /// An id among `count` made so far, now and then one past them or far out.
    uint32_t id(uint32_t count) { return uint32_t(in_.in(0, count)); }
    /// A count of at most `most`.
    uint32_t count(uint32_t most) { return in_.u8() % (most + 1); }

    void add_material() {
        SheafMaterialDesc d;
        sheafMaterialDescInit(&d);
        const uint8_t fields = in_.u8();
        if (fields & 1)
            for (float& c : d.color) c = in_.f32();
        if (fields & 2) d.ambient = in_.f32(), d.diffuse = in_.f32();
        if (fields & 4) d.specular = in_.f32(), d.phong_exponent = in_.f32();
        if (fields & 8) d.mirror = in_.f32();
        if (fields & 16) d.transmission = in_.f32(), d.ior = in_.f32();
        if (fields & 32)
            for (float& c : d.emission) c = in_.f32();
        if (fields & 64) d.texture = int32_t(in_.in(-1, int64_t(textures_)));
        uint32_t out = 0;
        if (check("sheafSceneAddMaterial",
                  sheafSceneAddMaterial(scene_, fields & 128 ? nullptr : &d, &out)))
            ++materials_;
    }

    void add_mesh() {
        const uint32_t vertices = count(32), triangles = count(32);
        const auto positions = vec(size_t(vertices) * 3);
        std::vector<uint32_t> indices(size_t(triangles) * 3);
        for (uint32_t& i : indices) i = uint32_t(in_.in(0, int64_t(vertices) - 1));
        const bool normals = in_.u8() & 1;
        const auto n = normals ? vec(size_t(vertices) * 3) : std::vector<float>{};
        uint32_t out = 0;
        if (check("sheafSceneAddMesh",
                  sheafSceneAddMesh(scene_, vertices ? maybe(positions) : nullptr, vertices,
                                    triangles ? maybe(indices) : nullptr, triangles,
                                    normals && vertices ? n.data() : nullptr, &out))) {
            ++meshes_;
            mesh_vertices_.push_back(vertices);
        }
    }

    /// A mesh on a lattice of 1/16 from -8 to 8, with a material (mirror, glass or matte) and
    /// placed as it is.
    void add_lattice_mesh() {
        const uint32_t triangles = 1 + in_.u8();
        std::vector<float> positions(size_t(triangles) * 9);
        for (float& f : positions) f = float(int(in_.u8()) - 128) / 16.0f;
        std::vector<uint32_t> indices(size_t(triangles) * 3);
        for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
        uint32_t mesh = 0, material = 0, object = 0;
        if (!check("sheafSceneAddMesh",
                   sheafSceneAddMesh(scene_, positions.data(), triangles * 3, indices.data(),
                                     triangles, nullptr, &mesh)))
            return;
        ++meshes_;
        mesh_vertices_.push_back(triangles * 3);
        SheafMaterialDesc d;
        sheafMaterialDescInit(&d);
        const uint8_t kind = in_.u8();
        d.color[0] = 0.3f + 0.1f * float(kind & 7);
        d.color[1] = 0.3f + 0.1f * float((kind >> 3) & 7);
        if (kind % 3 == 1) d.mirror = 0.8f;
        if (kind % 3 == 2) d.transmission = 0.7f, d.ior = 1.5f;
        if (!check("sheafSceneAddMaterial", sheafSceneAddMaterial(scene_, &d, &material))) return;
        ++materials_;
        if (check("sheafSceneAddObject",
                  sheafSceneAddObject(scene_, mesh, material, nullptr, nullptr, &object)))
            ++objects_;
    }

    void add_object() {
        const uint32_t mesh = id(meshes_), material = id(materials_);
        const auto transform = vec(12);
        const uint8_t how = in_.u8();
        const std::string name = in_.text(12);
        uint32_t out = 0;
        if (check("sheafSceneAddObject",
                  sheafSceneAddObject(scene_, mesh, material, how & 1 ? transform.data() : nullptr,
                                      how & 2 ? name.c_str() : nullptr, &out)))
            ++objects_;
    }

    void add_light() {
        SheafLightDesc d;
        sheafLightDescInit(&d);
        d.type = int(in_.in(0, 2));
        const uint8_t fields = in_.u8();
        if (fields & 1)
            for (float& p : d.position) p = in_.f32();
        if (fields & 2)
            for (float& p : d.direction) p = in_.f32();
        if (fields & 4)
            for (float& c : d.color) c = in_.f32();
        if (fields & 8)
            d.spot_radius = in_.f32(), d.spot_falloff = in_.f32(), d.spot_tightness = in_.f32();
        if (fields & 16) d.fade_distance = in_.f32(), d.fade_power = in_.f32();
        if (fields & 32) d.shadowless = int(in_.in(0, 1));
        check("sheafSceneAddLight",
              sheafSceneAddLight(scene_, fields & 128 ? nullptr : &d, nullptr));
    }

    void set_camera() {
        SheafCameraDesc d;
        sheafCameraDescInit(&d);
        d.projection = int(in_.in(0, 10));
        const uint8_t fields = in_.u8();
        if (fields & 1)
            for (float& p : d.position) p = in_.f32();
        if (fields & 2)
            for (float& p : d.look_at) p = in_.f32();
        if (fields & 4)
            for (float& p : d.up) p = in_.f32();
        if (fields & 8) d.fov_y_degrees = in_.f32(), d.ortho_height = in_.f32();
        if (fields & 16) d.shift[0] = in_.f32(), d.shift[1] = in_.f32();
        check("sheafSceneSetCameraDesc",
              sheafSceneSetCameraDesc(scene_, fields & 128 ? nullptr : &d));
    }

    void set_uvs() {
        const uint32_t mesh = id(meshes_);
        // The mesh's own vertex count mostly; now and then another.
        uint32_t vertices = mesh < mesh_vertices_.size() ? mesh_vertices_[mesh] : 0;
        if (in_.u8() < 32) vertices = count(40);
        const auto uvs = vec(size_t(vertices) * 2);
        check("sheafSceneSetMeshUvs",
              sheafSceneSetMeshUvs(scene_, mesh, vertices ? maybe(uvs) : nullptr, vertices));
    }

    void add_subdivision() {
        const uint32_t vertices = count(16), faces = count(8);
        const auto positions = vec(size_t(vertices) * 3);
        std::vector<uint32_t> sizes(faces);
        size_t corners = 0;
        for (uint32_t& s : sizes) corners += s = uint32_t(in_.in(3, 5));
        if (corners > 4096) corners = 0, sizes.assign(faces, 0);
        std::vector<uint32_t> indices(corners);
        for (uint32_t& i : indices) i = uint32_t(in_.in(0, int64_t(vertices) - 1));
        const uint32_t creases = count(4);
        std::vector<uint32_t> crease_edges(size_t(creases) * 2);
        for (uint32_t& i : crease_edges) i = uint32_t(in_.in(0, int64_t(vertices) - 1));
        const auto sharpness = vec(creases);
        const bool uvs = in_.u8() & 1;
        const auto uv = uvs ? vec(size_t(vertices) * 2) : std::vector<float>{};
        const int scheme = int(in_.in(0, 1));
        // Level 0..3 mostly (a cage of 8 pentagons at 8 is 2.6 million quads: slow, not
        // wrong); now and then out of the range 0..8.
        const int level = int(in_.in(0, 3));
        uint32_t out = 0;
        if (check("sheafSceneAddSubdivisionMesh",
                  sheafSceneAddSubdivisionMesh(
                      scene_, vertices ? maybe(positions) : nullptr, vertices,
                      faces ? maybe(sizes) : nullptr, faces, corners ? maybe(indices) : nullptr,
                      creases ? maybe(crease_edges) : nullptr, creases ? maybe(sharpness) : nullptr,
                      creases, uvs && vertices ? uv.data() : nullptr, scheme, level, &out))) {
            ++meshes_;
            mesh_vertices_.push_back(0);
        }
    }

    void set_load_option() {
        static const char* const keys[] = {"include_path",
                                           "strict",
                                           "image_width",
                                           "image_height",
                                           "initial_frame",
                                           "final_frame",
                                           "frame",
                                           "initial_clock",
                                           "final_clock",
                                           "cyclic_animation",
                                           "clock",
                                           "declare",
                                           "limit.parse_steps",
                                           "limit.objects",
                                           "limit.data_mib",
                                           "limit.loop_iterations",
                                           "limit.macro_calls",
                                           "limit.function_terms",
                                           "subdivision.limit",
                                           "subdivision.boundary",
                                           "no.such.key",
                                           ""};
        static const char* const values[] = {"",          "0",
                                             "1",         "-1",
                                             "2",         "1e308",
                                             "nan",       "inf",
                                             "x=1",       "=",
                                             "edge_only", "edge_and_corner",
                                             "none",      "18446744073709551616",
                                             "0x10"};
        const char* key = in_.pick(keys);
        const std::string value = in_.u8() & 1 ? std::string(in_.pick(values)) : in_.text(16);
        check("sheafSceneSetLoadOption",
              sheafSceneSetLoadOption(scene_, in_.u8() < 8 ? nullptr : key, value.c_str()));
    }

    void add_texture() {
        static const char* const paths[] = {"", "/", "/nonexistent/texture.png", "/dev/null",
                                            "/proc/self/status"};
        static const char* const spaces[] = {"", "srgb", "linear", "sRGB", "ACEScg", "no such"};
        const char* path = in_.u8() < 16 ? nullptr : in_.pick(paths);
        const int mapping = int(in_.in(0, 4));
        const auto transform = vec(12);
        const uint8_t how = in_.u8();
        uint32_t out = 0;
        if (check("sheafSceneAddTexture",
                  sheafSceneAddTexture(scene_, path, mapping, how & 1 ? transform.data() : nullptr,
                                       how & 2 ? nullptr : in_.pick(spaces), &out)))
            ++textures_;
    }

    void set_setting() {
        size_t settings = 0;
        if (sheafGetSettingCount(&settings) != SHEAF_OK || settings == 0)
            broken("sheafGetSettingCount failed");
        const char* key = nullptr;
        const char* allowed = nullptr;
        const size_t index = in_.u8() % (settings + 1);
        if (index < settings) {
            if (sheafGetSettingInfo(index, &key, nullptr, &allowed, nullptr) != SHEAF_OK || !key)
                broken("sheafGetSettingInfo failed");
        } else {
            key = in_.u8() & 1 ? "no.such.setting" : nullptr;
        }
        static const char* const strings[] = {"",         "0",       "1",      "-1",
                                              "2",        "4",       "true",   "off",
                                              "cpu",      "cuda",    "crsh",   "bvh",
                                              "crsh-bvh", "rah-bvh", "strips", "brute",
                                              "rah",      "nan",     "1e40",   "combined,depth"};
        switch (in_.u8() % 6) {
        case 0:
            check("sheafRendererSetString",
                  sheafRendererSetString(renderer_, key, in_.pick(strings)));
            break;
        case 1: {
            const std::string s = in_.text(12);
            check("sheafRendererSetString", sheafRendererSetString(renderer_, key, s.c_str()));
            break;
        }
        case 2:
            check("sheafRendererSetInt", sheafRendererSetInt(renderer_, key, in_.in(-1, 8)));
            break;
        case 3:
            check("sheafRendererSetFloat", sheafRendererSetFloat(renderer_, key, in_.f32()));
            break;
        case 4:
            check("sheafRendererSetBool", sheafRendererSetBool(renderer_, key, int(in_.in(0, 1))));
            break;
        default:
            check("sheafRendererUnset", sheafRendererUnset(renderer_, key));
            break;
        }
    }

    /// The read-back calls, with indices in and out of range and small buffers.
    void query() {
        size_t n = 0;
        const char* text = nullptr;
        double used = 0, limit = 0;
        const size_t index = size_t(in_.in(0, 4));
        switch (in_.u8() % 5) {
        case 0:
            check("sheafSceneGetWarningCount", sheafSceneGetWarningCount(scene_, &n));
            break;
        case 1:
            check("sheafSceneGetWarning", sheafSceneGetWarning(scene_, index, &text));
            break;
        case 2:
            check("sheafSceneGetLimitUse",
                  sheafSceneGetLimitUse(scene_, index, &text, &used, &limit));
            break;
        case 3: {
            char buf[8];
            size_t needed = 0;
            check(
                "sheafRendererGetEffective",
                sheafRendererGetEffective(renderer_, scene_, "accel", buf, in_.u8() % 9, &needed));
            break;
        }
        default: {
            static const char* const names[] = {"cornell", "default", "", "no-such-scene"};
            check("sheafSceneLoadBuiltin",
                  sheafSceneLoadBuiltin(scene_, in_.u8() < 16 ? nullptr : in_.pick(names)));
            materials_ = meshes_ = objects_ = textures_ = 0;
            mesh_vertices_.clear();
            break;
        }
        }
    }

    Bytes& in_;
    std::FILE* log_;
    CapiMode mode_;
    SheafScene scene_ = nullptr;
    SheafRenderer renderer_ = nullptr;
    uint32_t materials_ = 0, meshes_ = 0, objects_ = 0, textures_ = 0;
    int renders_ = 0;
    std::vector<uint32_t> mesh_vertices_;
};

} // namespace

int run_capi_input(const uint8_t* data, size_t size, std::FILE* log, CapiMode mode) {
    Bytes in(data, size);
    Host host(in, log, mode);
    // At most 64 calls: an input is one host's short session, not a stress test.
    for (int calls = 0; calls < 64 && !in.done(); ++calls) host.step();
    host.finish();
    return 0;
}

} // namespace sheaf::fuzz
