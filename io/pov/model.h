// The reader's intermediate scene, in POV-Ray's own (left-handed) coordinates: objects with
// their shapes, meshes and CSG children, textures reduced to what the core Material can show,
// lights and the camera. builder.cpp turns it into a sheaf::Scene.
#pragma once

#include "core/geometry/shape.h"
#include "core/math/affine.h"
#include "core/scene/scene.h"
#include "io/pov/lexer.h"

#include <array>
#include <memory>
#include <vector>

namespace sheaf::io::pov {

/// A POV-Ray colour: red, green, blue, filter, transmit.
using Color5 = std::array<double, 5>;

struct PovFinish {
    std::array<double, 3> ambient{0.1, 0.1, 0.1};
    std::array<double, 3> emission{0, 0, 0};
    std::array<double, 3> reflection{0, 0, 0};
    double diffuse = 0.6;
    double specular = 0, roughness = 0.05;
    double phong = 0, phong_size = 40;
};

struct PovTexture {
    Color5 pigment{0, 0, 0, 0, 0}; // solid colour (patterns: the average of their map)
    PovFinish finish;
};

/// A light source (POV-Ray coordinates). Area lights become jittered samples in the builder.
struct PovLight {
    Light light; // position, colour, type, spot parameters, fade, shadowless
    Vec3 point_at{0, 0, 0};
    bool area = false;
    Vec3 axis1, axis2;
    int n1 = 1, n2 = 1;
};

enum class PovKind { Shape, Mesh, Csg, Light };

/// An object. Transforms are applied as they are parsed: `local` maps the shape's canonical
/// space (shape.h), a mesh's own coordinates, or nothing (CSG) to POV-Ray world space.
struct PovObject {
    PovKind kind = PovKind::Shape;
    Shape shape;
    std::shared_ptr<const Mesh> mesh;
    CsgOp op = CsgOp::Union;
    std::vector<PovObject> children;
    Affine local;
    std::shared_ptr<const PovTexture> texture; // null: inherited (or the default texture)
    double ior = 0;                            // 0: not set
    bool inverse = false;
    PovLight light;
    Token where; // the keyword that started it, for warnings
};

struct PovCamera {
    bool orthographic = false;
    Vec3 location{0, 0, 0}, direction{0, 0, 1}, right{1.33f, 0, 0}, up{0, 1, 0}, sky{0, 1, 0};
    Vec3 look_at{0, 0, 1};
    bool has_look_at = false;
    double angle = 0; // degrees, 0: not given
    Affine transform; // applied after everything else
};

/// Everything the parser collected.
struct PovModel {
    std::vector<PovObject> objects;
    bool has_camera = false;
    PovCamera camera;
    Color5 background{0, 0, 0, 0, 0};
    double assumed_gamma = 0; // 0: not given
    double version = 3.7;
    bool version_given = false;
    std::array<double, 3> ambient_light{1, 1, 1};
    int max_trace_level = -1;
    PovTexture default_texture;
};

} // namespace sheaf::io::pov
