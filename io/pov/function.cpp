// User-function evaluation and the float built-ins (see function.h).
#include "io/pov/function.h"

#include "core/scene/function.h"

#include <cmath>
#include <map>

namespace sheaf::io::pov {

namespace {

using Fn1 = double (*)(double);

const std::map<std::string, Fn1>& unary() {
    static const std::map<std::string, Fn1> m = {
        {"sin", [](double a) { return std::sin(a); }},
        {"cos", [](double a) { return std::cos(a); }},
        {"tan", [](double a) { return std::tan(a); }},
        {"asin", [](double a) { return std::asin(a); }},
        {"acos", [](double a) { return std::acos(a); }},
        {"sinh", [](double a) { return std::sinh(a); }},
        {"cosh", [](double a) { return std::cosh(a); }},
        {"tanh", [](double a) { return std::tanh(a); }},
        {"asinh", [](double a) { return std::asinh(a); }},
        {"acosh", [](double a) { return std::acosh(a); }},
        {"atanh", [](double a) { return std::atanh(a); }},
        {"sqrt", [](double a) { return std::sqrt(a); }},
        {"exp", [](double a) { return std::exp(a); }},
        {"log", [](double a) { return std::log10(a); }},
        {"ln", [](double a) { return std::log(a); }},
        {"abs", [](double a) { return std::fabs(a); }},
        {"int", [](double a) { return std::trunc(a); }},
        {"floor", [](double a) { return std::floor(a); }},
        {"ceil", [](double a) { return std::ceil(a); }},
        {"degrees", [](double a) { return a * 180.0 / M_PI; }},
        {"radians", [](double a) { return a * M_PI / 180.0; }},
    };
    return m;
}

bool truth(double d) {
    return std::fabs(d) > 1e-10;
}

} // namespace

bool is_float_builtin(const std::string& name) {
    return unary().count(name) || name == "atan" || name == "atan2" || name == "pow" ||
           name == "mod" || name == "div" || name == "min" || name == "max" || name == "select";
}

bool eval_builtin(const std::string& name, const std::vector<double>& a, double& out) {
    const size_t n = a.size();
    if (auto it = unary().find(name); it != unary().end()) {
        if (n != 1) return false;
        out = it->second(a[0]);
        return true;
    }
    if (name == "atan") {
        if (n == 1)
            out = std::atan(a[0]);
        else if (n == 2)
            out = std::atan2(a[0], a[1]);
        else
            return false;
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
    switch (n.op) {
    case FnNode::Const:
        return n.value;
    case FnNode::Param:
        return n.param < np ? p[n.param] : 0.0;
    case FnNode::Neg:
        return -eval_node(n.args[0], p, np, steps);
    case FnNode::Not:
        return truth(eval_node(n.args[0], p, np, steps)) ? 0.0 : 1.0;
    case FnNode::Cond:
        return truth(eval_node(n.args[0], p, np, steps)) ? eval_node(n.args[1], p, np, steps)
                                                         : eval_node(n.args[2], p, np, steps);
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
    default:
        break;
    }
    const double a = eval_node(n.args[0], p, np, steps), b = eval_node(n.args[1], p, np, steps);
    switch (n.op) {
    case FnNode::Add:
        return a + b;
    case FnNode::Sub:
        return a - b;
    case FnNode::Mul:
        return a * b;
    case FnNode::Div:
        return a / b;
    case FnNode::Lt:
        return a < b;
    case FnNode::Le:
        return a <= b;
    case FnNode::Gt:
        return a > b;
    case FnNode::Ge:
        return a >= b;
    case FnNode::Eq:
        return std::fabs(a - b) <= 1e-10;
    case FnNode::Ne:
        return std::fabs(a - b) > 1e-10;
    case FnNode::And:
        return truth(a) && truth(b);
    case FnNode::Or:
        return truth(a) || truth(b);
    default:
        return 0;
    }
}

} // namespace

double PigmentFunction::at(int comp, double x, double y, double z) const {
    const FnView v{nullptr, nullptr, &pattern, &pigment, entries.data()};
    return fn_pigment(v, pigment, comp, x, y, z);
}

double PovFunction::eval(const double* args, int n, uint64_t& steps) const {
    if (internal >= 0 || pattern || pigment) {
        if (steps == 0) throw FnStepsExceeded{};
        --steps;
        double a[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (int i = 0; i < n && i < 8; ++i) a[i] = args[i];
        if (pigment) return pigment->at(int(FnComponent::Gray), a[0], a[1], a[2]);
        return pattern ? fn_pattern(*pattern, a[0], a[1], a[2])
                       : fn_internal(internal, a[0], a[1], a[2], a + 3);
    }
    return eval_node(body, args, n, steps);
}

} // namespace sheaf::io::pov
