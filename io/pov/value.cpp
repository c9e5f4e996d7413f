// Value helpers: type names for messages, colour conversion and sRGB decoding.
#include "io/pov/value.h"

#include <cmath>

namespace sheaf::io::pov {

const char* type_name(VType t) {
    switch (t) {
    case VType::None:
        return "nothing";
    case VType::Float:
        return "a float";
    case VType::Vector:
        return "a vector";
    case VType::Color:
        return "a colour";
    case VType::String:
        return "a string";
    case VType::Array:
        return "an array";
    case VType::Function:
        return "a function";
    case VType::Object:
        return "an object";
    case VType::Texture:
        return "a texture";
    case VType::Material:
        return "a material";
    case VType::Pigment:
        return "a pigment";
    case VType::Normal:
        return "a normal";
    case VType::Finish:
        return "a finish";
    case VType::Interior:
        return "an interior";
    case VType::Transform:
        return "a transform";
    case VType::Camera:
        return "a camera";
    case VType::ColorMap:
        return "a colour map";
    case VType::File:
        return "a file";
    case VType::Other:
        return "a block";
    }
    return "?";
}

double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

Color5 to_color(const Value& v) {
    Color5 c{0, 0, 0, 0, 0};
    if (v.type == VType::Float) {
        c[0] = c[1] = c[2] = v.v[0];
    } else if (v.type == VType::Color) {
        for (int i = 0; i < 5; ++i) c[i] = v.v[i];
    } else if (v.type == VType::Vector) {
        for (int i = 0; i < v.dim && i < 5; ++i) c[i] = v.v[i];
    }
    return c;
}

} // namespace sheaf::io::pov
