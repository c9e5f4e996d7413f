// Small mesh files written by the tests (test code only): OBJ, PLY (ASCII and binary) and glTF
// (.gltf with an embedded buffer, .glb) of a unit quad, in a fresh temporary folder.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace sheaf::test {

/// A fresh folder under the system's temporary folder, named after the test.
inline std::filesystem::path temp_folder(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("sheaf_io_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

/// The quad x, y in [-1, 1] at z = 0, facing +z, with texture coordinates 0..1.
inline const char* kQuadObj = "# a quad\n"
                              "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                              "vn 0 0 1\n"
                              "f 1/1/1 2/2/1 3/3/1 4/4/1\n";

inline const char* kQuadPly = "ply\nformat ascii 1.0\n"
                              "element vertex 4\n"
                              "property float x\nproperty float y\nproperty float z\n"
                              "property float nx\nproperty float ny\nproperty float nz\n"
                              "property float s\nproperty float t\n"
                              "element face 1\nproperty list uchar int vertex_indices\n"
                              "end_header\n"
                              "-1 -1 0 0 0 1 0 0\n1 -1 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n"
                              "-1 1 0 0 0 1 0 1\n"
                              "4 0 1 2 3\n";

/// The quad as binary little-endian PLY (positions only, two triangles).
inline std::string write_binary_ply(const std::filesystem::path& path) {
    std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 4\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "element face 2\nproperty list uchar uint vertex_indices\nend_header\n";
    const float v[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    s.append(reinterpret_cast<const char*>(v), sizeof v);
    const uint32_t tris[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& t : tris) {
        s.push_back(char(3));
        s.append(reinterpret_cast<const char*>(t), sizeof t);
    }
    return write_text(path, s);
}

/// The glTF buffer of the quad: positions, normals, texture coordinates, 16-bit indices.
inline std::string quad_gltf_buffer() {
    const float pos[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const float nrm[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const float uv[8] = {0, 1, 1, 1, 1, 0, 0, 0}; // glTF's t runs down the image
    const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    std::string b;
    b.append(reinterpret_cast<const char*>(pos), sizeof pos);
    b.append(reinterpret_cast<const char*>(nrm), sizeof nrm);
    b.append(reinterpret_cast<const char*>(uv), sizeof uv);
    b.append(reinterpret_cast<const char*>(idx), sizeof idx);
    return b; // 140 bytes
}

inline std::string base64(const std::string& in) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const uint32_t n = uint8_t(in[i]) << 16 | uint8_t(in[i + 1]) << 8 | uint8_t(in[i + 2]);
        out += {k[n >> 18], k[(n >> 12) & 63], k[(n >> 6) & 63], k[n & 63]};
    }
    if (i + 1 == in.size()) {
        const uint32_t n = uint8_t(in[i]) << 16;
        out += {k[n >> 18], k[(n >> 12) & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const uint32_t n = uint8_t(in[i]) << 16 | uint8_t(in[i + 1]) << 8;
        out += {k[n >> 18], k[(n >> 12) & 63], k[(n >> 6) & 63], '='};
    }
    return out;
}

/// glTF JSON for the quad placed by two nodes: one moved up by 2, one scaled by 2.
/// `uri`: the buffer's "uri" member (with its comma), or "" for a .glb's binary chunk.
inline std::string quad_gltf_json(const std::string& uri) {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],)"
           R"("nodes":[{"name":"up","mesh":0,"translation":[0,2,0]},)"
           R"({"name":"big","mesh":0,"scale":[2,2,2]}],)"
           R"("meshes":[{"name":"quad","primitives":[{"attributes":)"
           R"({"POSITION":0,"NORMAL":1,"TEXCOORD_0":2},"indices":3}]}],)"
           R"("buffers":[{"byteLength":140)" +
           uri +
           R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},)"
           R"({"buffer":0,"byteOffset":48,"byteLength":48},)"
           R"({"buffer":0,"byteOffset":96,"byteLength":32},)"
           R"({"buffer":0,"byteOffset":128,"byteLength":12}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3",)"
           R"("min":[-1,-1,0],"max":[1,1,0]},)"
           R"({"bufferView":1,"componentType":5126,"count":4,"type":"VEC3"},)"
           R"({"bufferView":2,"componentType":5126,"count":4,"type":"VEC2"},)"
           R"({"bufferView":3,"componentType":5123,"count":6,"type":"SCALAR"}]})";
}

inline std::string write_gltf(const std::filesystem::path& path) {
    return write_text(path, quad_gltf_json(R"(,"uri":"data:application/octet-stream;base64,)" +
                                           base64(quad_gltf_buffer()) + "\""));
}

inline std::string write_glb(const std::filesystem::path& path) {
    std::string json = quad_gltf_json("");
    while (json.size() % 4) json += ' ';
    std::string bin = quad_gltf_buffer();
    while (bin.size() % 4) bin += '\0';
    auto u32 = [](std::string& s, uint32_t v) { s.append(reinterpret_cast<const char*>(&v), 4); };
    std::string glb;
    u32(glb, 0x46546C67); // "glTF"
    u32(glb, 2);
    u32(glb, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(glb, uint32_t(json.size()));
    u32(glb, 0x4E4F534A); // "JSON"
    glb += json;
    u32(glb, uint32_t(bin.size()));
    u32(glb, 0x004E4942); // "BIN"
    glb += bin;
    return write_text(path, glb);
}

} // namespace sheaf::test
