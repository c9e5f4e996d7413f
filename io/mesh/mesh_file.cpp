// Mesh files through Assimp (see mesh_file.h): the import, the walk over the node tree, and the
// conversion of each placed mesh into a sheaf::Mesh, checked.
#include "io/mesh/mesh_file.h"

#include "core/base/error.h"
#include "core/scene/scene.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <strings.h>
#include <tuple>
#include <vector>

namespace sheaf::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kExtensions[] = {".obj", ".ply", ".gltf", ".glb"};
constexpr size_t kMaxNodeDepth = 1024;

std::string lower_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// Assimp 5.2's ASCII PLY reader leaks what it has read when a value is not a number (found by
// the PLY fuzzer: LeakSanitizer, each malformed file), and reads on: every value of an ASCII
// body must be a number. `in` stands after the header's end_header line.
void check_ply_ascii_body(const std::string& path, std::istream& in, int header_lines) {
    // One read and one pass of strtod over the body: a stream per line cost a fifth of the
    // load of a large file.
    const std::string body{std::istreambuf_iterator<char>(in), {}};
    const char* p = body.c_str();
    long line = header_lines + 1;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') line += *p++ == '\n';
        if (*p == '\0') {
            if (p == body.c_str() + body.size()) return;
        } else {
            char* end = nullptr;
            std::strtod(p, &end);
            if (end != p && (*end == ' ' || *end == '\t' || *end == '\r' || *end == '\n' ||
                             end == body.c_str() + body.size())) {
                p = end;
                continue;
            }
        }
        throw SceneError(path + ":" + std::to_string(line) +
                         ": a value of the PLY data is not a number");
    }
}

// Assimp sizes its PLY arrays by the header's element counts before reading them; a header
// that claims more elements than the file has bytes would make it allocate without bound.
// Assimp 5.2 also loops for ever on a header without its end_header line.
void check_ply_header(const std::string& path, uintmax_t file_size) {
    constexpr int kMaxHeaderLines = 4096;
    std::ifstream in(path, std::ios::binary);
    std::string line;
    bool ascii = false;
    for (int n = 0; n < kMaxHeaderLines && std::getline(in, line); ++n) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        // Assimp reads a header line up to a NUL and the rest as a line of its own: after a
        // comment, "ver list undice" made it loop without end (found by the PLY fuzzer).
        if (line.find('\0') != std::string::npos)
            throw SceneError(path + ":" + std::to_string(n + 1) +
                             ": a NUL byte in the PLY header, which is text");
        if (line == "end_header") {
            if (ascii) check_ply_ascii_body(path, in, n + 1);
            return;
        }
        std::istringstream words(line);
        std::string keyword, name, count;
        if (!(words >> keyword)) continue;
        // Assimp leaks what it has read when a header line is not one it knows, or the format
        // line's version is not a number (found by the PLY fuzzer under LeakSanitizer).
        if (n == 0 ? keyword != "ply"
                   : keyword != "format" && keyword != "comment" && keyword != "obj_info" &&
                         keyword != "element" && keyword != "property")
            throw SceneError(path + ":" + std::to_string(n + 1) +
                             ": not a line of a PLY header (ply, format, comment, obj_info, "
                             "element, property, end_header)");
        if (keyword == "property") {
            // property TYPE NAME, or property list COUNT_TYPE ITEM_TYPE NAME: anything else
            // (a missing name, an unknown type) made Assimp free what it had not allocated
            // (found by the PLY fuzzer under AddressSanitizer).
            static const char* const kTypes[] = {
                "char", "uchar", "short", "ushort", "int",   "uint",   "float",   "double",
                "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};
            auto type = [](const std::string& t) {
                return std::find(std::begin(kTypes), std::end(kTypes), t) != std::end(kTypes);
            };
            std::vector<std::string> w;
            for (std::string x; words >> x;) w.push_back(x);
            const bool ok =
                !w.empty() && (w[0] == "list" ? w.size() == 4 && type(w[1]) && type(w[2])
                                              : w.size() == 2 && type(w[0]));
            if (!ok)
                throw SceneError(path + ":" + std::to_string(n + 1) +
                                 ": a PLY property is 'property TYPE NAME' or 'property list "
                                 "TYPE TYPE NAME', TYPE one of PLY's number types");
        }
        if (keyword == "format" && n != 1)
            throw SceneError(path + ":" + std::to_string(n + 1) +
                             ": a PLY header has one format line, its second");
        if (keyword == "format") {
            std::string version;
            words >> name >> version;
            char* end = nullptr;
            std::strtod(version.c_str(), &end);
            if ((name != "ascii" && name != "binary_little_endian" &&
                 name != "binary_big_endian") ||
                version.empty() || end != version.c_str() + version.size())
                throw SceneError(path + ":" + std::to_string(n + 1) +
                                 ": the PLY format line is not 'format ascii|"
                                 "binary_little_endian|binary_big_endian VERSION'");
            ascii = name == "ascii";
        }
        if (keyword != "element") continue;
        words >> name >> count;
        const bool digits = !count.empty() && count.size() < 20 &&
                            std::all_of(count.begin(), count.end(),
                                        [](unsigned char c) { return std::isdigit(c); });
        if (!digits || std::stoull(count) > file_size)
            throw SceneError(path + ": the PLY header declares " + count + " '" + name +
                             "' elements, more than the file can hold (" +
                             std::to_string(file_size) + " bytes)");
    }
    throw SceneError(path + ": the PLY header has no end_header line" +
                     (in ? " in its first " + std::to_string(kMaxHeaderLines) + " lines"
                         : std::string(" (the file ends first)")));
}

// Assimp 5.2's OBJ reader leaks the meshes it has built when a face names a vertex, texture
// coordinate or normal that does not exist (found by the OBJ fuzzer: LeakSanitizer, when the
// face is in a second object), and names no line. So every index is checked here first, with
// its place, against counts taken as Assimp takes them (a count here must never exceed
// Assimp's, or an index it refuses would pass):
// - lines end at '\n', '\r' and '\f' (no NUL byte: Assimp stops there); a line holding a
//   backslash joins the next to it, so the next starts no statement, and a statement line
//   with one is an error;
// - a statement is its line's first character: `v` then a blank is a vertex of 3, 4 (w not
//   0) or 6 numbers; any line from `vt` a texture coordinate, from `vn` a normal (each must be
//   `vt` of 2 or 3 numbers, `vn` of 3); `f`, `l` or `p` a face, line or point whose first
//   word is followed by indices; between `cstype` and `end`, nothing. A line starting with a
//   blank is nothing to Assimp;
// - a number starts with a digit or a sign, or is nan or inf (Assimp counts no other);
// - an index is I, I/T, I//N or I/T/N: not 0, up to the file's count of its kind, or negative
//   back from the count so far; T names a normal where no texture coordinate but a normal
//   came before (as Assimp reads it); T and N count only in a file that has some;
// - a face has 3 corners or more, a line 2 points or more.
void check_obj_indices(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    if (const size_t nul = text.find('\0'); nul != std::string::npos) {
        const long nul_line = long(std::count(text.begin(), text.begin() + long(nul), '\n')) + 1;
        const size_t from = text.rfind('\n', nul);
        throw SceneError(path + ":" + std::to_string(nul_line) + ":" +
                         std::to_string(from == std::string::npos ? nul + 1 : nul - from) +
                         ": a NUL byte; an OBJ file is text");
    }
    static const char* const kinds[3] = {"vertex", "texture coordinate", "normal"};
    static const char* const plurals[3] = {"vertices", "texture coordinates", "normals"};
    struct Place {
        long index = 0, line = 0, col = 0;
    };
    long counts[3] = {0, 0, 0};
    Place highest[3];  // the highest index, where it first appears
    Place backward[3]; // the first relative index reaching back beyond the start
    auto error = [&](const Place& at, const std::string& what) {
        return SceneError(path + ":" + std::to_string(at.line) + ":" + std::to_string(at.col) +
                          ": " + what);
    };
    auto blank = [](char c) { return c == ' ' || c == '\t'; };
    auto line_end = [](char c) { return c == '\n' || c == '\r' || c == '\f'; };
    const char* const end = text.c_str() + text.size();
    long line = 1;
    bool joined = false, cstype = false;
    const char* p = text.c_str();
    if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) p += 3; // a BOM
    while (p < end) {
        const char* const start = p;
        const char* eol = p;
        while (eol < end && !line_end(*eol)) ++eol;
        const bool backslash = std::memchr(start, '\\', size_t(eol - start)) != nullptr;
        const bool continuation = joined;
        joined = backslash;
        auto col = [&](const char* at) { return long(at - start) + 1; };
        auto number = [&](const char*& q) {
            const bool nan_inf = (end - q >= 3) && (strncasecmp(q, "nan", 3) == 0 ||
                                                    strncasecmp(q, "inf", 3) == 0);
            char* after = nullptr;
            const double v = std::strtod(q, &after);
            if (!(std::isdigit(static_cast<unsigned char>(*q)) || *q == '-' || *q == '+' ||
                  nan_inf) ||
                after == q || after > eol || (after < eol && !blank(*after) && *after != '#'))
                throw error({0, line, col(q)}, "expected a number");
            q = after;
            return v;
        };
        const char c0 = start < eol ? *start : '\n', c1 = start + 1 < eol ? start[1] : '\n';
        if (continuation) {
            // Part of the line before: no statement.
        } else if (cstype) {
            if (c0 == 'e' && std::string_view(start, size_t(eol - start)).substr(0, 3) == "end")
                cstype = false;
        } else if (c0 == 'c') {
            cstype = std::string_view(start, size_t(eol - start)).substr(0, 6) == "cstype";
        } else if (c0 == 'v' && (blank(c1) || c1 == 't' || c1 == 'n')) {
            const int kind = blank(c1) ? 0 : c1 == 't' ? 1 : 2;
            const char* q = start + (kind == 0 ? 1 : 2);
            if (backslash) throw error({0, line, 1}, "a line continued with \\ is not read here");
            if (kind > 0 && (q == eol || !blank(*q)))
                throw error({0, line, 1}, std::string("expected ") + (kind == 1 ? "vt" : "vn") +
                                              " and a blank");
            size_t n = 0;
            double w = 1; // a vertex's fourth number
            for (;;) {
                while (q < eol && blank(*q)) ++q;
                if (q == eol || *q == '#') break;
                const double value = number(q);
                if (++n == 4) w = value;
            }
            const bool fits = kind == 0 ? n == 3 || n == 6 || (n == 4 && w != 0)
                              : kind == 1 ? n == 2 || n == 3
                                          : n == 3;
            if (!fits)
                throw error({0, line, 1},
                            kind == 0 ? "a vertex is 3 numbers, 4 (w not 0) or 6 (a colour), not " +
                                            std::to_string(n) + (n == 4 ? " with w 0" : "")
                            : kind == 1 ? "a texture coordinate is 2 or 3 numbers, not " +
                                              std::to_string(n)
                                        : "a normal is 3 numbers, not " + std::to_string(n));
            ++counts[kind];
        } else if (c0 == 'f' || c0 == 'l' || c0 == 'p') {
            if (backslash) throw error({0, line, 1}, "a line continued with \\ is not read here");
            const char* q = start;
            while (q < eol && !blank(*q)) ++q; // the statement's word
            int corners = 0;
            for (;; ++corners) {
                while (q < eol && blank(*q)) ++q;
                if (q == eol || *q == '#') break;
                const Place at{0, line, col(q)};
                for (int pos = 0; pos < 3; ++pos) {
                    if (pos > 0) {
                        if (q == eol || *q != '/') break;
                        ++q;
                        if (q == eol || *q == '/' || blank(*q)) continue; // 1//3
                    }
                    if (!std::isdigit(static_cast<unsigned char>(*q)) && *q != '-' && *q != '+')
                        break;
                    char* after = nullptr;
                    errno = 0;
                    const long i = std::strtol(q, &after, 10);
                    q = after;
                    // A second index names a normal where no texture coordinate but a
                    // normal came before.
                    const int kind = pos == 1 && counts[1] == 0 && counts[2] > 0 ? 2 : pos;
                    if (i == 0 || errno == ERANGE)
                        throw error(at, "the " + std::string(kinds[kind]) + " index " +
                                            std::to_string(i) + " is not an index (1 is the first)");
                    if (i > highest[kind].index) highest[kind] = {i, line, at.col};
                    if (i < 0 && -i > counts[kind] && backward[kind].index == 0)
                        backward[kind] = {i, line, at.col};
                }
                if (q < eol && !blank(*q))
                    throw error(at, "expected vertex indices (I, I/T, I//N or I/T/N)");
            }
            // Assimp's validation would refuse a face of one or two corners with a message
            // about its own structures.
            if (c0 == 'f' && corners < 3)
                throw error({0, line, 1}, "a face has 3 corners or more, this one " +
                                              std::to_string(corners) +
                                              " (a line is an l line, a point a p line)");
            // A line of one point is no segment: a mesh of only such lines has no vertices,
            // and Assimp leaks the meshes before it (found by the OBJ fuzzer).
            if (c0 == 'l' && corners == 1)
                throw error({0, line, 1}, "a line has 2 points or more, this one 1 (a point "
                                          "is a p line)");
        }
        if (eol < end && *eol == '\n') ++line;
        p = eol + 1;
    }
    for (int kind = 0; kind < 3; ++kind) {
        if (kind > 0 && counts[kind] == 0) continue;
        const std::string k = kinds[kind];
        if (backward[kind].index != 0)
            throw error(backward[kind], "the " + k + " index " +
                                            std::to_string(backward[kind].index) +
                                            " reaches back before the first " + k);
        if (highest[kind].index > counts[kind])
            throw error(highest[kind], "the " + k + " index " +
                                           std::to_string(highest[kind].index) +
                                           " is out of range (the file has " +
                                           std::to_string(counts[kind]) + " " + plurals[kind] +
                                           ")");
    }
}

/// Faces as the post-processing steps assume them: each with a vertex or more, and each mesh's
/// primitive types those of its faces (types are set again from the faces: a reader's wrong
/// types make Triangulate assert).
void check_faces(const std::string& path, const aiScene& scene) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        aiMesh* mesh = scene.mMeshes[m];
        if (!mesh) throw SceneError(path + ": mesh " + std::to_string(m) + " is missing");
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const unsigned n = mesh->mFaces[f].mNumIndices;
            if (n == 0 || !mesh->mFaces[f].mIndices)
                throw SceneError(path + ": face " + std::to_string(f) + " of mesh " +
                                 std::to_string(m) + " has no vertices");
            types |= n == 1   ? aiPrimitiveType_POINT
                     : n == 2 ? aiPrimitiveType_LINE
                     : n == 3 ? aiPrimitiveType_TRIANGLE
                              : aiPrimitiveType_POLYGON;
        }
        mesh->mPrimitiveTypes = types;
    }
}

/// Checks the path and imports it with `flags`; the scene lives as long as `importer`.
const aiScene* import(Assimp::Importer& importer, const std::string& path, unsigned flags) {
    if (!is_mesh_file(path))
        throw SceneError(path + ": not a mesh file; mesh files are " +
                         std::string(mesh_file_extensions()));
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw SceneError(path + ": is a directory, not a mesh file");
    if (!fs::exists(path, ec)) throw SceneError(path + ": no such file");
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) throw SceneError(path + ": cannot read the file (" + ec.message() + ")");
    if (lower_extension(path) == ".ply") check_ply_header(path, size);
    if (lower_extension(path) == ".obj") check_obj_indices(path);
    // Points and lines are not surfaces: SortByPType removes them.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    auto failed = [&] {
        std::string why = importer.GetErrorString();
        if (why.empty()) why = "Assimp could not read it";
        return SceneError(path + ": " + why);
    };
    // Read and validated first, checked, then post-processed: Debian's Assimp is built with
    // its assertions on, and a post-processing step given faces it does not expect aborts the
    // process (a PLY face with no vertices stopped the host in Triangulate).
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    if (!scene) throw failed();
    check_faces(path, *scene);
    scene = importer.ApplyPostProcessing(flags | aiProcess_ValidateDataStructure);
    if (!scene) throw failed();
    if (!scene->mRootNode || scene->mNumMeshes == 0)
        throw SceneError(path + ": the file has no faces (only points, lines or nothing)");
    return scene;
}

/// Calls fn(node, mesh index, node-to-file transform) for every mesh every node places.
template <class Fn>
void for_each_placement(const std::string& path, const aiScene* scene, Fn&& fn) {
    struct Item {
        const aiNode* node;
        aiMatrix4x4 parent;
        size_t depth;
    };
    std::vector<Item> stack{{scene->mRootNode, aiMatrix4x4(), 0}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        if (it.depth > kMaxNodeDepth)
            throw SceneError(path + ": the node tree is deeper than " +
                             std::to_string(kMaxNodeDepth) + " levels");
        const aiMatrix4x4 global = it.parent * it.node->mTransformation;
        for (unsigned i = 0; i < it.node->mNumMeshes; ++i) {
            const unsigned m = it.node->mMeshes[i];
            if (m >= scene->mNumMeshes)
                throw SceneError(path + ": a node names mesh " + std::to_string(m) +
                                 ", which does not exist");
            fn(*it.node, m, global);
        }
        for (unsigned c = it.node->mNumChildren; c-- > 0;)
            if (it.node->mChildren[c])
                stack.push_back({it.node->mChildren[c], global, it.depth + 1});
    }
}

Vec3 point(const aiMatrix4x4& m, const aiVector3D& v) {
    const aiVector3D p = m * v;
    return {p.x, p.y, p.z};
}

struct NormalMatrix {
    aiMatrix3x3 m;
    bool flips = false; // a mirroring transform: triangles turn the other way round
};

NormalMatrix normal_matrix(const aiMatrix4x4& global) {
    aiMatrix3x3 linear(global);
    NormalMatrix n;
    n.flips = linear.Determinant() < 0;
    if (std::fabs(linear.Determinant()) > 1e-30f)
        n.m = linear.Inverse().Transpose();
    else
        n.m = linear;
    return n;
}

std::string mesh_label(const std::string& path, const aiMesh& mesh, unsigned index) {
    std::string s = path + ": mesh " + std::to_string(index);
    if (mesh.mName.length) s += " '" + std::string(mesh.mName.C_Str()) + "'";
    return s;
}

void read_color(const aiScene* scene, const aiMesh& mesh, MeshPart& part) {
    if (mesh.mMaterialIndex >= scene->mNumMaterials || !scene->mMaterials) return;
    const aiMaterial* mat = scene->mMaterials[mesh.mMaterialIndex];
    aiColor4D c;
    if (mat->Get(AI_MATKEY_BASE_COLOR, c) == aiReturn_SUCCESS ||
        mat->Get(AI_MATKEY_COLOR_DIFFUSE, c) == aiReturn_SUCCESS) {
        const Vec3 v(c.r, c.g, c.b);
        if (is_finite(v)) part.has_color = true, part.color = v;
    }
}

MeshPart convert(const std::string& path, const aiScene* scene, const aiNode& node, unsigned index,
                 const aiMatrix4x4& global) {
    const aiMesh& src = *scene->mMeshes[index];
    const std::string label = mesh_label(path, src, index);
    MeshPart part;
    part.name = node.mName.length ? node.mName.C_Str() : src.mName.C_Str();
    read_color(scene, src, part);
    Mesh& mesh = part.mesh;
    if (!src.mVertices && src.mNumVertices) throw SceneError(label + " has no vertex positions");
    const NormalMatrix nm = normal_matrix(global);
    mesh.positions.resize(src.mNumVertices);
    for (unsigned v = 0; v < src.mNumVertices; ++v) {
        if (!is_finite(Vec3(src.mVertices[v].x, src.mVertices[v].y, src.mVertices[v].z)))
            throw SceneError(label + ": vertex " + std::to_string(v) +
                             " is not finite (NaN or infinity)");
        mesh.positions[v] = point(global, src.mVertices[v]);
    }
    if (src.mNormals) {
        mesh.normals.resize(src.mNumVertices);
        for (unsigned v = 0; v < src.mNumVertices; ++v) {
            const aiVector3D n = nm.m * src.mNormals[v];
            const Vec3 u = normalize(Vec3(n.x, n.y, n.z));
            if (!is_finite(Vec3(n.x, n.y, n.z)))
                throw SceneError(label + ": normal " + std::to_string(v) +
                                 " is not finite (NaN or infinity)");
            mesh.normals[v] = u;
        }
    }
    if (src.mTextureCoords[0]) {
        mesh.uvs.resize(2 * size_t(src.mNumVertices));
        for (unsigned v = 0; v < src.mNumVertices; ++v)
            mesh.uvs[2 * v] = src.mTextureCoords[0][v].x,
                         mesh.uvs[2 * v + 1] = src.mTextureCoords[0][v].y;
    }
    mesh.indices.reserve(3 * size_t(src.mNumFaces));
    for (unsigned f = 0; f < src.mNumFaces; ++f) {
        const aiFace& face = src.mFaces[f];
        if (face.mNumIndices != 3) continue; // points and lines left by a failed triangulation
        for (unsigned k = 0; k < 3; ++k)
            if (face.mIndices[k] >= src.mNumVertices)
                throw SceneError(label + ": face " + std::to_string(f) + " names vertex " +
                                 std::to_string(face.mIndices[k]) + ", out of range (" +
                                 std::to_string(src.mNumVertices) + " vertices)");
        const unsigned a = face.mIndices[0], b = face.mIndices[nm.flips ? 2 : 1],
                       c = face.mIndices[nm.flips ? 1 : 2];
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }
    validate_mesh(mesh, label);
    return part;
}

} // namespace

const char* mesh_file_extensions() {
    return ".obj .ply .gltf .glb";
}

bool is_mesh_file(const std::string& path) {
    const std::string ext = lower_extension(path);
    return std::find(std::begin(kExtensions), std::end(kExtensions), ext) != std::end(kExtensions);
}

std::vector<MeshPart> read_mesh_parts(const std::string& path) {
    Assimp::Importer importer;
    const aiScene* scene =
        import(importer, path,
               aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    std::vector<MeshPart> parts;
    size_t triangles = 0;
    for_each_placement(path, scene, [&](const aiNode& node, unsigned m, const aiMatrix4x4& g) {
        const aiMesh* src = scene->mMeshes[m];
        if (!src || !(src->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return;
        triangles += src->mNumFaces;
        if (triangles > kMaxMeshFileTriangles)
            throw SceneError(path + ": more than " + std::to_string(kMaxMeshFileTriangles) +
                             " triangles once every node places its meshes");
        parts.push_back(convert(path, scene, node, m, g));
    });
    if (parts.empty())
        throw SceneError(path + ": the file has no faces (only points, lines or nothing)");
    return parts;
}

Mesh merge_mesh_parts(const std::vector<MeshPart>& parts) {
    bool all_normals = true, any_uvs = false;
    size_t vertices = 0;
    for (const MeshPart& p : parts) {
        all_normals = all_normals && !p.mesh.normals.empty();
        any_uvs = any_uvs || !p.mesh.uvs.empty();
        vertices += p.mesh.positions.size();
    }
    if (vertices > UINT32_MAX) throw SceneError("a merged mesh has more than 2^32 vertices");
    Mesh out;
    for (const MeshPart& p : parts) {
        const uint32_t base = uint32_t(out.positions.size());
        out.positions.insert(out.positions.end(), p.mesh.positions.begin(), p.mesh.positions.end());
        if (all_normals)
            out.normals.insert(out.normals.end(), p.mesh.normals.begin(), p.mesh.normals.end());
        if (any_uvs) {
            if (p.mesh.uvs.empty())
                out.uvs.resize(out.uvs.size() + 2 * p.mesh.positions.size(), 0.0f);
            else
                out.uvs.insert(out.uvs.end(), p.mesh.uvs.begin(), p.mesh.uvs.end());
        }
        for (uint32_t i : p.mesh.indices) out.indices.push_back(base + i);
    }
    return out;
}

Mesh read_mesh_file(const std::string& path) {
    return merge_mesh_parts(read_mesh_parts(path));
}

PolygonCage read_polygon_cage(const std::string& path) {
    Assimp::Importer importer;
    const aiScene* scene = import(importer, path, aiProcess_SortByPType);
    PolygonCage cage;
    std::map<std::tuple<float, float, float>, uint32_t> welded;
    size_t corners = 0;
    for_each_placement(path, scene, [&](const aiNode&, unsigned m, const aiMatrix4x4& g) {
        const aiMesh* src = scene->mMeshes[m];
        if (!src || !src->mVertices) return;
        const std::string label = mesh_label(path, *src, m);
        const bool flips = normal_matrix(g).flips;
        std::vector<uint32_t> remap(src->mNumVertices);
        for (unsigned v = 0; v < src->mNumVertices; ++v) {
            const Vec3 p = point(g, src->mVertices[v]);
            if (!is_finite(p))
                throw SceneError(label + ": vertex " + std::to_string(v) +
                                 " is not finite (NaN or infinity)");
            auto [it, added] = welded.try_emplace({p.x, p.y, p.z}, uint32_t(cage.positions.size()));
            if (added) cage.positions.push_back(p);
            remap[v] = it->second;
        }
        for (unsigned f = 0; f < src->mNumFaces; ++f) {
            const aiFace& face = src->mFaces[f];
            if (face.mNumIndices < 3) continue;
            corners += face.mNumIndices;
            if (corners > 3 * kMaxMeshFileTriangles)
                throw SceneError(path + ": more than " + std::to_string(3 * kMaxMeshFileTriangles) +
                                 " face corners once every node places its meshes");
            cage.face_sizes.push_back(face.mNumIndices);
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const unsigned i =
                    face.mIndices[flips ? (face.mNumIndices - k) % face.mNumIndices : k];
                if (i >= src->mNumVertices)
                    throw SceneError(label + ": face " + std::to_string(f) + " names vertex " +
                                     std::to_string(i) + ", out of range (" +
                                     std::to_string(src->mNumVertices) + " vertices)");
                cage.face_indices.push_back(remap[i]);
            }
        }
    });
    if (cage.face_sizes.empty())
        throw SceneError(path + ": the file has no faces (only points, lines or nothing)");
    return cage;
}

} // namespace sheaf::io
