// POV-Ray switch translation: each +X/-X word becomes the equivalent long option.
#include "pov_switches.h"

#include "pov_ini.h"

#include <cctype>
#include <cstdlib>

namespace render {

namespace {

bool is_number(const std::string& s) {
    if (s.empty()) return false;
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end && *end == '\0';
}

bool is_positive_integer(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

/// A word after --sweep that is a grid axis: KEY=VALUES, not an option.
bool is_sweep_axis(const std::string& s) {
    const size_t eq = s.find('=');
    return eq != std::string::npos && eq > 0 && s[0] != '-' && s[0] != '+';
}

bool is_integer(const std::string& s) {
    return is_positive_integer(s) ||
           (s.size() > 1 && s[0] == '-' && is_positive_integer(s.substr(1)));
}

/// The animation switches: +K<clock>, +KFI<n>, +KFF<n>, +KI<clock>, +KF<clock>, +KC.
void translate_clock_switch(const std::string& word, std::vector<std::string>& out) {
    std::string rest = word.substr(2);
    for (char& c : rest) c = char(std::toupper(static_cast<unsigned char>(c)));
    const std::string value = word.substr(
        2 + (rest.rfind("FI", 0) == 0 || rest.rfind("FF", 0) == 0                            ? 2
             : rest.rfind("I", 0) == 0 || rest.rfind("F", 0) == 0 || rest.rfind("C", 0) == 0 ? 1
                                                                                             : 0));
    auto need = [&](bool ok, const char* what) {
        if (!ok)
            throw SwitchError("POV-Ray switch '" + word + "': expected " + what +
                              " with no space, e.g. +KFI1 +KFF24 +KI0 +KF1, or +K0.5");
    };
    if (rest.rfind("FI", 0) == 0 || rest.rfind("FF", 0) == 0) {
        need(is_integer(value), "a frame number");
        out.insert(out.end(), {rest[1] == 'I' ? "--initial-frame" : "--final-frame", value});
    } else if (rest.rfind("C", 0) == 0) {
        need(value.empty(), "nothing after +KC");
        out.push_back(word[0] == '-' ? "--no-cyclic-animation" : "--cyclic-animation");
    } else if (rest.rfind("I", 0) == 0 || rest.rfind("F", 0) == 0) {
        need(is_number(value), "a clock value");
        out.insert(out.end(), {rest[0] == 'I' ? "--initial-clock" : "--final-clock", value});
    } else {
        need(is_number(value), "a clock value");
        out.insert(out.end(), {"--clock", value});
    }
}

} // namespace

/// Appends the translation of one POV-Ray switch (a word starting with + or one of -A, -D,
/// -KC); returns false when `word` is not one.
bool translate_switch(const std::string& word, std::vector<std::string>& out) {
    if (word.size() < 2) return false;
    const char sign = word[0], letter = char(std::toupper(static_cast<unsigned char>(word[1])));
    const std::string rest = word.substr(2);
    if (sign == '-') {
        if (word[1] == 'A' && (rest.empty() || is_number(rest))) {
            out.insert(out.end(), {"--set", "aa.samples=1"});
            return true;
        }
        if (word == "-D") {
            out.push_back("--no-display");
            return true;
        }
        if (word == "-KC" || word == "-kc") {
            out.push_back("--no-cyclic-animation");
            return true;
        }
        return false;
    }
    if (sign != '+') return false;
    switch (letter) {
    case 'W':
    case 'H':
        if (!is_positive_integer(rest))
            throw SwitchError(std::string("POV-Ray switch '") + word + "': expected +" + letter +
                              " followed by a number of pixels, e.g. +" + letter +
                              (letter == 'W' ? "640" : "480"));
        out.insert(out.end(), {std::string("-") + letter, rest});
        return true;
    case 'O':
    case 'I':
    case 'L':
        if (rest.empty())
            throw SwitchError(std::string("POV-Ray switch '") + word + "': expected +" + letter +
                              (letter == 'L' ? "DIRECTORY" : "FILE") + " with no space");
        out.insert(out.end(), {letter == 'O'   ? "-o"
                               : letter == 'I' ? "--input"
                                               : "--include-path",
                               rest});
        return true;
    case 'A':
        if (!rest.empty() && !is_number(rest))
            throw SwitchError("POV-Ray switch '" + word +
                              "': expected +A or +A followed by a threshold, e.g. +A0.3");
        out.insert(out.end(), {"--set", "aa.samples=" + std::to_string(kPovAntialiasSamples)});
        return true;
    case 'D':
        if (!rest.empty()) break;
        out.push_back("--no-display");
        return true;
    case 'K':
        translate_clock_switch(word, out);
        return true;
    case 'S':
    case 'E': {
        const char what = rest.empty() ? 0 : char(std::toupper(static_cast<unsigned char>(rest[0])));
        if (what == 'R' || what == 'C') { // +SR +ER +SC +EC: a part of the image
            if (!is_number(rest.substr(1)) || rest[1] == '-')
                throw SwitchError("POV-Ray switch '" + word + "': expected +" + letter + what +
                                  " followed by a " + (what == 'R' ? "row" : "column") +
                                  " (from 1) or a fraction (0.0 to 1.0), e.g. +" + letter + what +
                                  (letter == 'S' ? "0.5" : "1.0"));
            out.insert(out.end(), {std::string("--") + (letter == 'S' ? "start-" : "end-") +
                                       (what == 'R' ? "row" : "column"),
                                   rest.substr(1)});
            return true;
        }
        if (what != 'F') break;
        if (!is_integer(rest.substr(1)))
            throw SwitchError("POV-Ray switch '" + word + "': expected +" + letter +
                              "F followed by a frame number, e.g. +" + letter + "F2");
        out.insert(out.end(),
                   {letter == 'S' ? "--subset-start-frame" : "--subset-end-frame", rest.substr(1)});
        return true;
    }
    default:
        break;
    }
    throw SwitchError("unknown POV-Ray switch '" + word +
                      "'; known: +W<n> +H<n> +O<file> +I<file> +A[threshold] -A +L<dir> +D -D "
                      "+K<clock> +KFI<n> +KFF<n> +KI<clock> +KF<clock> +KC -KC +SF<n> +EF<n> "
                      "+SR<r> +ER<r> +SC<c> +EC<c>");
}

std::vector<std::string> translate_args(const std::vector<std::string>& args) {
    std::vector<std::string> out;
    bool in_sweep = false, axis_seen = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& word = args[i];
        if (in_sweep && is_sweep_axis(word)) {
            out.insert(out.end(), {"--sweep", word});
            axis_seen = true;
            continue;
        }
        // A --sweep with no axis after it is left for CLI11 to report.
        if (in_sweep && !axis_seen) out.push_back("--sweep");
        in_sweep = false;
        if (word == "--") {
            out.insert(out.end(), args.begin() + long(i), args.end());
            return out;
        }
        if (word == "--sweep") {
            in_sweep = true;
            axis_seen = false;
            continue;
        }
        const bool value_of_option =
            !out.empty() &&
            (out.back() == "-o" || out.back() == "--output" || out.back() == "--preset" ||
             out.back() == "--stats-json" || out.back() == "--report" ||
             out.back() == "--include-path" || out.back() == "--set" || out.back() == "--declare");
        if (!value_of_option && is_ini_file(word)) {
            if (!out.empty() && (out.back() == "-i" || out.back() == "--input")) out.pop_back();
            const std::vector<std::string> ini = read_ini_file(word);
            out.insert(out.end(), ini.begin(), ini.end());
            continue;
        }
        if (value_of_option || !translate_switch(word, out)) {
            if (value_of_option || !translate_ini_option(word, "command line", out))
                out.push_back(word);
        }
    }
    if (in_sweep && !axis_seen) out.push_back("--sweep");
    return out;
}

} // namespace render
