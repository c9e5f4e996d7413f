// Values of the POV-Ray language: floats, vectors (2 to 5 components), colours, strings,
// arrays, user functions, and declared objects, textures and other blocks.
#pragma once

#include "io/pov/model.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sheaf::io::pov {

struct PovFunction;
struct ArrayValue;

enum class VType {
    None,
    Float,
    Vector,
    Color,
    String,
    Array,
    Function,
    Object,
    Texture,
    Material,
    Pigment,
    Normal,
    Finish,
    Interior,
    Transform,
    Camera,
    ColorMap,
    File,
    Other, // a declared block the reader only accepts (normal, fog, media...): `str` names it
};

const char* type_name(VType t);

/// An unsupported feature met while a #declare was read: reported when the declared value is
/// used, so that include files full of declarations a scene never uses do not warn.
struct PendingWarning {
    Token where;
    std::string what;
    bool approximation = false; // Parser::approximated's, else Parser::unsupported's
};

struct Value {
    VType type = VType::None;
    int dim = 1;               // Float 1, Vector 2..5, Color 5
    double v[5] = {};          // Float, Vector, Color (r, g, b, f, t)
    std::string str;           // String; Other: the block's keyword
    std::shared_ptr<void> ptr; // Array, Function, Object, Texture, ... (by type)
    /// What its declaration met that is unsupported; raised again at each use.
    std::shared_ptr<const std::vector<PendingWarning>> pending;

    template <class T> T& as() const { return *static_cast<T*>(ptr.get()); }
    bool numeric() const {
        return type == VType::Float || type == VType::Vector || type == VType::Color;
    }

    static Value number(double d) {
        Value x;
        x.type = VType::Float;
        x.v[0] = d;
        return x;
    }
    static Value vec(int n, const double* c) {
        Value x;
        x.type = n == 1 ? VType::Float : VType::Vector;
        x.dim = n;
        for (int i = 0; i < n; ++i) x.v[i] = c[i];
        return x;
    }
    static Value vec3(double a, double b, double c) {
        const double d[3] = {a, b, c};
        return vec(3, d);
    }
    static Value color(const Color5& c) {
        Value x;
        x.type = VType::Color;
        x.dim = 5;
        for (int i = 0; i < 5; ++i) x.v[i] = c[i];
        return x;
    }
    static Value string(std::string s) {
        Value x;
        x.type = VType::String;
        x.str = std::move(s);
        return x;
    }
    template <class T> static Value boxed(VType t, T object) {
        Value x;
        x.type = t;
        x.ptr = std::make_shared<T>(std::move(object));
        return x;
    }
};

/// An array: its sizes per dimension and the elements, row-major (None: not yet assigned).
/// Its elements count against the reader's memory budget while it lives.
struct ArrayValue {
    std::vector<size_t> sizes;
    std::vector<Value> elements;
    size_t* budget = nullptr; // bytes in use, shared with the reader
    size_t bytes = 0;
    ~ArrayValue() {
        if (budget) *budget -= bytes;
    }
};

/// sRGB-encoded component to linear.
double srgb_to_linear(double c);
/// A value as a POV-Ray colour (floats fill r, g, b; vectors give rgb, rgbf, rgbft).
Color5 to_color(const Value& v);

} // namespace sheaf::io::pov
