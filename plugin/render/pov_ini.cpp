// POV-Ray .ini files and Key=Value options (see pov_ini.h).
#include "pov_ini.h"

#include "pov_switches.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

namespace render {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

/// A value in double quotes loses them (Input_File_Name="scene.pov").
std::string unquote(const std::string& s) {
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return s.substr(1, s.size() - 2);
    return s;
}

/// POV-Ray's booleans: on off true false yes no 1 0.
bool parse_bool(const std::string& key, const std::string& value, const std::string& where) {
    const std::string v = lower(value);
    if (v == "on" || v == "true" || v == "yes" || v == "1") return true;
    if (v == "off" || v == "false" || v == "no" || v == "0") return false;
    throw SwitchError(where + ": " + key + "=" + value + ": expected on or off");
}

std::string integer(const std::string& key, const std::string& value, const std::string& where) {
    char* end = nullptr;
    const long n = std::strtol(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || n < -1000000000L || n > 1000000000L)
        throw SwitchError(where + ": " + key + "=" + value + ": expected a whole number");
    return std::to_string(n);
}

std::string number(const std::string& key, const std::string& value, const std::string& where) {
    char* end = nullptr;
    std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0')
        throw SwitchError(where + ": " + key + "=" + value + ": expected a number");
    return value;
}

/// Keys whose effect is on the console, the display, the process or speed: accepted, no effect.
const std::set<std::string>& silent_keys() {
    static const std::set<std::string> keys = {"pause_when_done",
                                               "display",
                                               "verbose",
                                               "all_console",
                                               "debug_console",
                                               "fatal_console",
                                               "render_console",
                                               "statistic_console",
                                               "warning_console",
                                               "all_file",
                                               "debug_file",
                                               "fatal_file",
                                               "render_file",
                                               "statistic_file",
                                               "warning_file",
                                               "test_abort",
                                               "test_abort_count",
                                               "pre_scene_command",
                                               "pre_frame_command",
                                               "post_scene_command",
                                               "post_frame_command",
                                               "user_abort_command",
                                               "fatal_error_command",
                                               "pre_scene_return",
                                               "pre_frame_return",
                                               "post_scene_return",
                                               "post_frame_return",
                                               "user_abort_return",
                                               "fatal_error_return",
                                               "output_to_file",
                                               "bounding",
                                               "bounding_method",
                                               "bounding_threshold",
                                               "remove_bounds",
                                               "split_unions",
                                               "light_buffer",
                                               "vista_buffer",
                                               "draw_vistas",
                                               "render_block_size",
                                               "render_block_step",
                                               "render_pattern",
                                               "preview_start_size",
                                               "preview_end_size",
                                               "version",
                                               "display_gamma",
                                               "palette",
                                               "buffer_output",
                                               "buffer_size",
                                               "continue_trace",
                                               "create_ini",
                                               "work_threads",
                                               "antialias_threshold",
                                               "antialias_gamma",
                                               "antialias_depth",
                                               "jitter",
                                               "jitter_amount",
                                               "sampling_method",
                                               "bits_per_color",
                                               "dither",
                                               "dither_method",
                                               "high_reproducibility",
                                               "real_time_raytracing",
                                               "clockless_animation",
                                               "radiosity_vain_pretrace",
                                               "include_header",
                                               "output_file_type",
                                               "file_gamma",
                                               "odd_field"};
    return keys;
}

/// Keys that would change the picture in ways Sheaf does not model, with the value they
/// have when they change nothing ("" for any value that is off).
bool unused_but_harmless(const std::string& key, const std::string& value) {
    const std::string v = lower(value);
    const bool off = v == "off" || v == "false" || v == "no" || v == "0";
    if (key == "field_render" || key == "grayscale_output" || key == "output_alpha" ||
        key == "radiosity_from_file" || key == "radiosity_to_file")
        return off;
    if (key == "quality") return std::strtod(v.c_str(), nullptr) >= 9;
    return false;
}

} // namespace

bool is_ini_file(const std::string& word) {
    std::string w = lower(word);
    if (!w.empty() && w.back() == ']') {
        const size_t open = w.rfind('[');
        if (open == std::string::npos) return false;
        w = w.substr(0, open);
    }
    return w.size() > 4 && w.compare(w.size() - 4, 4, ".ini") == 0;
}

bool translate_ini_option(const std::string& word, const std::string& where,
                          std::vector<std::string>& out) {
    const size_t eq = word.find('=');
    if (eq == std::string::npos || eq == 0 || word[0] == '-' || word[0] == '+') return false;
    const std::string key = lower(trim(word.substr(0, eq)));
    const std::string value = unquote(trim(word.substr(eq + 1)));
    const std::string shown = trim(word.substr(0, eq));
    if (key == "input_file_name") {
        out.insert(out.end(), {"--input", value});
    } else if (key == "output_file_name") {
        std::string file = value;
        if (std::filesystem::path(file).extension().empty()) file += ".png";
        out.insert(out.end(), {"-o", file});
    } else if (key == "width" || key == "height") {
        out.insert(out.end(), {key == "width" ? "-W" : "-H", integer(shown, value, where)});
    } else if (key == "antialias") {
        out.insert(out.end(), {"--set", parse_bool(shown, value, where)
                                            ? "aa.samples=" + std::to_string(kPovAntialiasSamples)
                                            : "aa.samples=1"});
    } else if (key == "library_path") {
        out.insert(out.end(), {"--include-path", value});
    } else if (key == "initial_frame" || key == "final_frame" || key == "subset_start_frame" ||
               key == "subset_end_frame") {
        std::string option = "--" + key;
        std::replace(option.begin(), option.end(), '_', '-');
        out.insert(out.end(), {option, integer(shown, value, where)});
    } else if (key == "initial_clock" || key == "final_clock" || key == "clock") {
        std::string option = "--" + key;
        std::replace(option.begin(), option.end(), '_', '-');
        out.insert(out.end(), {option, number(shown, value, where)});
    } else if (key == "cyclic_animation") {
        out.push_back(parse_bool(shown, value, where) ? "--cyclic-animation"
                                                      : "--no-cyclic-animation");
    } else if (key == "start_row" || key == "end_row" || key == "start_column" ||
               key == "end_column") {
        std::string option = "--" + key;
        std::replace(option.begin(), option.end(), '_', '-');
        out.insert(out.end(), {option, number(shown, value, where)});
    } else if (key == "declare") {
        out.insert(out.end(), {"--declare", value});
    } else if (silent_keys().count(key)) {
        // no effect on Sheaf's picture
    } else if (unused_but_harmless(key, value)) {
        // at its default: nothing to say
    } else if (key == "field_render" || key == "grayscale_output" || key == "output_alpha" ||
               key == "radiosity_from_file" || key == "radiosity_to_file" || key == "quality") {
        std::cerr << "render: warning: " << where << ": " << shown << "=" << value
                  << " is not used (Sheaf renders the whole image at full quality)\n";
    } else {
        return false;
    }
    return true;
}

std::vector<std::string> read_ini_file(const std::string& spec) {
    std::string path = spec, section;
    if (!spec.empty() && spec.back() == ']') {
        const size_t open = spec.rfind('[');
        path = spec.substr(0, open);
        section = lower(spec.substr(open + 1, spec.size() - open - 2));
    }
    std::ifstream in(path);
    if (!in) throw SwitchError(path + ": cannot read the .ini file");
    std::vector<std::string> out;
    std::string line, current;
    bool found = section.empty(), antialias = false, in_wanted = section.empty();
    std::string depth, input, output_type = "n";
    bool has_output = false;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = path + ":" + std::to_string(number);
        const size_t semi = line.find(';');
        const std::string text = trim(semi == std::string::npos ? line : line.substr(0, semi));
        if (text.empty()) continue;
        if (text.front() == '[') {
            if (text.back() != ']')
                throw SwitchError(where + ": expected ']' after the section name");
            current = lower(trim(text.substr(1, text.size() - 2)));
            in_wanted = !section.empty() && current == section;
            found = found || in_wanted;
            continue;
        }
        if (!in_wanted) continue;
        const size_t eq = text.find('=');
        if (text[0] != '+' && text[0] != '-' && eq != std::string::npos) {
            const std::string key = lower(trim(text.substr(0, eq)));
            const std::string value = unquote(trim(text.substr(eq + 1)));
            if (key == "antialias_depth") {
                depth = integer("Antialias_Depth", value, where);
                continue;
            }
            if (key == "antialias") antialias = parse_bool("Antialias", value, where);
            if (key == "output_file_type") output_type = lower(value);
            if (key == "output_file_name") has_output = true;
            if (key == "input_file_name") {
                // Relative to the current folder, as POV-Ray reads it, else next to the .ini.
                input = value;
                const std::filesystem::path beside =
                    std::filesystem::path(path).parent_path() / value;
                std::error_code ec;
                if (!std::filesystem::exists(value, ec) && std::filesystem::exists(beside, ec))
                    input = beside.string();
                out.insert(out.end(), {"--input", input});
                continue;
            }
            if (!translate_ini_option(text, where, out))
                std::cerr << "render: warning: " << where << ": '" << trim(text.substr(0, eq))
                          << "' is not a POV-Ray option render knows; ignored\n";
            continue;
        }
        // Switches, several to a line: +W200 +H200, and Key=Value words among them.
        size_t at = 0;
        while (at < text.size()) {
            const size_t end = text.find_first_of(" \t", at);
            const std::string word = text.substr(at, end == std::string::npos ? end : end - at);
            at = end == std::string::npos ? text.size() : text.find_first_not_of(" \t", end);
            if (word.empty()) continue;
            try {
                if (!translate_switch(word, out) && !translate_ini_option(word, where, out))
                    throw SwitchError("'" + word + "' is neither a switch nor Key=Value");
            } catch (const SwitchError& e) {
                const std::string message = e.what();
                throw SwitchError(message.rfind(where, 0) == 0 ? message : where + ": " + message);
            }
        }
    }
    if (!found) throw SwitchError(path + ": no section [" + section + "]");
    if (antialias && !depth.empty())
        out.insert(
            out.end(),
            {"--set", "aa.samples=" + std::to_string(std::clamp(std::atoi(depth.c_str()), 1, 8))});
    if (!input.empty() && !has_output) {
        // POV-Ray names the image after the scene, in the current folder.
        const char* ext = output_type == "e" ? ".exr" : output_type == "h" ? ".hdr" : ".png";
        out.insert(out.end(), {"-o", std::filesystem::path(input).stem().string() + ext});
    }
    // The .ini's image is the default: -o on the command line wins, and --check writes none.
    for (std::string& word : out)
        if (word == "-o") word = "--default-output";
    return out;
}

} // namespace render
