// User-function evaluation and the float built-ins (see function.h).
#include "io/pov/function.h"
#include "io/pov/function_scene.h"

#include "core/scene/function.h"

#include <cmath>
#include <map>

namespace sheaf::io::pov {

namespace {

/// The language's float built-ins of one argument, as the C library computes them (a scene's
/// #declare X = log(1000) must give 3 exactly, as in POV-Ray); compiled programs use the
/// shared host-and-device math of core/scene/function.h instead.
double std_math(FnMath m, double a) {
    switch (m) {
    case FnMath::Sin:
        return std::sin(a);
    case FnMath::Cos:
        return std::cos(a);
    case FnMath::Tan:
        return std::tan(a);
    case FnMath::Asin:
        return std::asin(a);
    case FnMath::Acos:
        return std::acos(a);
    case FnMath::Atan:
        return std::atan(a);
    case FnMath::Sinh:
        return std::sinh(a);
    case FnMath::Cosh:
        return std::cosh(a);
    case FnMath::Tanh:
        return std::tanh(a);
    case FnMath::Asinh:
        return std::asinh(a);
    case FnMath::Acosh:
        return std::acosh(a);
    case FnMath::Atanh:
        return std::atanh(a);
    case FnMath::Sqrt:
        return std::sqrt(a);
    case FnMath::Exp:
        return std::exp(a);
    case FnMath::Log10:
        return std::log10(a);
    case FnMath::Ln:
        return std::log(a);
    case FnMath::Abs:
        return std::fabs(a);
    case FnMath::Int:
        return std::trunc(a);
    case FnMath::Floor:
        return std::floor(a);
    case FnMath::Ceil:
        return std::ceil(a);
    case FnMath::Degrees:
        return a * 180.0 / M_PI;
    case FnMath::Radians:
        return a * M_PI / 180.0;
    }
    return std::nan("");
}

bool truth(double d) {
    return std::fabs(d) > 1e-10;
}

} // namespace

const std::map<std::string, FnMath>& math_builtins() {
    static const std::map<std::string, FnMath> m = {
        {"sin", FnMath::Sin},         {"cos", FnMath::Cos},     {"tan", FnMath::Tan},
        {"asin", FnMath::Asin},       {"acos", FnMath::Acos},   {"atan", FnMath::Atan},
        {"sinh", FnMath::Sinh},       {"cosh", FnMath::Cosh},   {"tanh", FnMath::Tanh},
        {"asinh", FnMath::Asinh},     {"acosh", FnMath::Acosh}, {"atanh", FnMath::Atanh},
        {"sqrt", FnMath::Sqrt},       {"exp", FnMath::Exp},     {"log", FnMath::Log10},
        {"ln", FnMath::Ln},           {"abs", FnMath::Abs},     {"int", FnMath::Int},
        {"floor", FnMath::Floor},     {"ceil", FnMath::Ceil},   {"degrees", FnMath::Degrees},
        {"radians", FnMath::Radians},
    };
    return m;
}

bool is_float_builtin(const std::string& name) {
    return math_builtins().count(name) || name == "atan" || name == "atan2" || name == "pow" ||
           name == "mod" || name == "div" || name == "min" || name == "max" || name == "select";
}

bool eval_builtin(const std::string& name, const std::vector<double>& a, double& out) {
    const size_t n = a.size();
    if (auto it = math_builtins().find(name); it != math_builtins().end() && n == 1) {
        out = std_math(it->second, a[0]);
        return true;
    }
    if (name == "atan") { // atan(y, x) is atan2
        if (n != 2) return false;
        out = std::atan2(a[0], a[1]);
        return true;
    }
    if (name == "atan2" || name == "pow" || name == "mod" || name == "div") {
        if (n != 2) return false;
        if (name == "atan2")
            out = std::atan2(a[0], a[1]);
        else if (name == "pow")
            out = std::pow(a[0], a[1]);
        else if (name == "mod")
            out = std::fmod(a[0], a[1]);
        else
            out = std::trunc(a[0] / a[1]);
        return true;
    }
    if (name == "min" || name == "max") {
        if (n < 1) return false;
        out = a[0];
        for (size_t i = 1; i < n; ++i)
            out = name == "min" ? std::min(out, a[i]) : std::max(out, a[i]);
        return true;
    }
    if (name == "select") {
        if (n == 3)
            out = a[0] < 0 ? a[1] : a[2];
        else if (n == 4)
            out = a[0] < 0 ? a[1] : (a[0] == 0 ? a[2] : a[3]);
        else
            return false;
        return true;
    }
    return false;
}

namespace {

double eval_node(const FnNode& n, const double* p, int np, uint64_t& steps) {
    if (steps == 0) throw FnStepsExceeded{};
    --steps;
    switch (n.kind) {
    case FnNode::Const:
        return n.value;
    case FnNode::Param:
        return n.param < np ? p[n.param] : 0.0;
    case FnNode::Builtin: {
        std::vector<double> a;
        for (const FnNode& c : n.args) a.push_back(eval_node(c, p, np, steps));
        double out = 0;
        eval_builtin(n.name, a, out); // checked when compiled
        return out;
    }
    case FnNode::Call: {
        std::vector<double> a;
        for (const FnNode& c : n.args) a.push_back(eval_node(c, p, np, steps));
        if (n.fn->pigment && a.size() == 3) {
            if (steps == 0) throw FnStepsExceeded{};
            --steps;
            return n.fn->pigment->at(n.component, a[0], a[1], a[2]);
        }
        return n.fn->eval(a.data(), int(a.size()), steps);
    }
    case FnNode::Operator:
        break;
    }
    switch (n.op) {
    case FnOp::Neg:
        return -eval_node(n.args[0], p, np, steps);
    case FnOp::Not:
        return truth(eval_node(n.args[0], p, np, steps)) ? 0.0 : 1.0;
    case FnOp::Cond:
        return truth(eval_node(n.args[0], p, np, steps)) ? eval_node(n.args[1], p, np, steps)
                                                         : eval_node(n.args[2], p, np, steps);
    default:
        break;
    }
    const double a = eval_node(n.args[0], p, np, steps), b = eval_node(n.args[1], p, np, steps);
    switch (n.op) {
    case FnOp::Add:
        return a + b;
    case FnOp::Sub:
        return a - b;
    case FnOp::Mul:
        return a * b;
    case FnOp::Div:
        return a / b;
    case FnOp::Lt:
        return a < b;
    case FnOp::Le:
        return a <= b;
    case FnOp::Gt:
        return a > b;
    case FnOp::Ge:
        return a >= b;
    case FnOp::Eq:
        return std::fabs(a - b) <= 1e-10;
    case FnOp::Ne:
        return std::fabs(a - b) > 1e-10;
    case FnOp::And:
        return truth(a) && truth(b);
    case FnOp::Or:
        return truth(a) || truth(b);
    default:
        return 0;
    }
}

} // namespace

double PigmentFunction::at(int comp, double x, double y, double z) const {
    if (!scene) return 0;
    return fn_component(scene->color_at(x, y, z).data(), comp);
}

double PatternFunction::at(double x, double y, double z) const {
    return scene ? scene->value_at(x, y, z) : 0;
}

double PovFunction::eval(const double* args, int n, uint64_t& steps) const {
    if (internal >= 0 || pattern || pigment) {
        if (steps == 0) throw FnStepsExceeded{};
        --steps;
        // x, y, z and the most parameters an internal function takes (f_helix1: 7).
        double a[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
        for (int i = 0; i < n && i < 10; ++i) a[i] = args[i];
        if (pigment) return pigment->at(int(FnComponent::Gray), a[0], a[1], a[2]);
        return pattern ? pattern->at(a[0], a[1], a[2])
                       : fn_internal(internal, a[0], a[1], a[2], a + 3);
    }
    return eval_node(body, args, n, steps);
}

} // namespace sheaf::io::pov
