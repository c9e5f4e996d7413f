// The C ABI's frames: size, passes, statistics, text reports and image files.
#include "capi_internal.h"
#include "text_out.h"

#include "core/base/error.h"
#include "core/frame/assemble.h"
#include "io/image/image_io.h"

#include <algorithm>
#include <cstring>

using namespace sheaf::capi;

namespace {

const sheaf::Frame& frame_of(SheafFrame f) {
    return require(f, "frame")->frame;
}

/// Throws when the frame lacks the pass (output.passes left it out).
void check_pass(const sheaf::Frame& f, const char* name) {
    if (!sheaf::frame_has_pass(f, name)) throw InvalidArgument(sheaf::missing_pass(f, name));
}

} // namespace

extern "C" {

SHEAF_API SheafError sheafFrameRetain(SheafFrame frame) {
    return barrier([&] { sheaf_retain(require(frame, "frame")); });
}

SHEAF_API SheafError sheafFrameRelease(SheafFrame frame) {
    return barrier([&] { sheaf_release(require(frame, "frame")); });
}

SHEAF_API SheafError sheafFrameGetSize(SheafFrame frame, int* width, int* height) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        require(width, "width");
        require(height, "height");
        *width = f.width;
        *height = f.height;
    });
}

SHEAF_API SheafError sheafFrameGetRegion(SheafFrame frame, int* x, int* y, int* full_width,
                                         int* full_height) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        require(x, "x");
        require(y, "y");
        require(full_width, "full_width");
        require(full_height, "full_height");
        *x = f.x;
        *y = f.y;
        *full_width = f.full_width > 0 ? f.full_width : f.width;
        *full_height = f.full_height > 0 ? f.full_height : f.height;
    });
}

SHEAF_API SheafError sheafFrameLoadImage(const char* path, SheafFrame* out) {
    return barrier([&] {
        require(out, "out");
        *out = nullptr;
        auto frame = std::make_unique<SheafFrameT>();
        const char* p = require(path, "path");
        try {
            frame->frame = sheaf::read_frame_image(p);
        } catch (const sheaf::RenderError& e) {
            throw IoError(e.what());
        }
        *out = frame.release();
    });
}

SHEAF_API SheafError sheafFrameAssemble(const SheafFrame* parts, size_t count, SheafFrame* out) {
    return barrier([&] {
        require(out, "out");
        *out = nullptr;
        if (count > 0) require(parts, "parts");
        std::vector<const sheaf::Frame*> frames;
        for (size_t i = 0; i < count; ++i) {
            if (!parts[i]) throw InvalidArgument("parts[" + std::to_string(i) + "] is null");
            frames.push_back(&frame_of(parts[i]));
        }
        auto frame = std::make_unique<SheafFrameT>();
        frame->frame = sheaf::assemble_frame(frames);
        *out = frame.release();
    });
}

SHEAF_API SheafError sheafFrameGetPass(SheafFrame frame, const char* pass, float* dst,
                                       size_t float_count) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        const std::string name = require(pass, "pass");
        const size_t pixels = size_t(f.width) * size_t(f.height);
        size_t channels = 0;
        if (name == "combined")
            channels = 4;
        else if (name == "depth" || name == "object_id" || name == "tests")
            channels = 1;
        else if (name == "normal" || name == "albedo")
            channels = 3;
        else
            throw InvalidArgument(
                "unknown pass '" + name +
                "'; known passes: combined, depth, normal, albedo, object_id, tests");
        const size_t needed = pixels * channels;
        if (float_count < needed)
            throw InvalidArgument("pass '" + name + "' needs " + std::to_string(needed) +
                                  " floats; the buffer holds " + std::to_string(float_count));
        require(dst, "dst");
        check_pass(f, name.c_str());
        if (name == "combined") {
            std::memcpy(dst, f.rgba.data(), needed * sizeof(float));
        } else if (name == "depth") {
            std::memcpy(dst, f.depth.data(), pixels * sizeof(float));
        } else if (name == "object_id") {
            for (size_t i = 0; i < pixels; ++i)
                dst[i] = f.object_id[i] == 0xFFFFFFFFu ? -1.0f : float(f.object_id[i]);
        } else if (name == "tests") {
            for (size_t i = 0; i < pixels; ++i) dst[i] = float(f.tests[i]);
        } else {
            const std::vector<sheaf::Vec3>& v = name == "normal" ? f.normal : f.albedo;
            for (size_t i = 0; i < pixels; ++i) {
                dst[3 * i] = v[i].x;
                dst[3 * i + 1] = v[i].y;
                dst[3 * i + 2] = v[i].z;
            }
        }
    });
}

SHEAF_API SheafError sheafFrameGetStatCount(SheafFrame frame, size_t* count) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        *require(count, "count") = f.stats.entries().size();
    });
}

SHEAF_API SheafError sheafFrameGetStat(SheafFrame frame, size_t index, const char** key,
                                       double* value) {
    return barrier([&] {
        const auto& entries = frame_of(frame).stats.entries();
        if (index >= entries.size())
            throw InvalidArgument("statistic index " + std::to_string(index) +
                                  " is out of range (" + std::to_string(entries.size()) +
                                  " statistics)");
        if (key) *key = entries[index].first.c_str();
        if (value) *value = entries[index].second;
    });
}

SHEAF_API SheafError sheafFrameGetStatByName(SheafFrame frame, const char* key, double* value) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        const char* k = require(key, "key");
        require(value, "value");
        if (!f.stats.has(k)) throw InvalidArgument(std::string("unknown statistic '") + k + "'");
        *value = f.stats.get(k);
    });
}

SHEAF_API SheafError sheafFrameGetText(SheafFrame frame, const char* what, char* buf, size_t size,
                                       size_t* needed) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        const std::string w = require(what, "what");
        std::string text;
        if (w == "stats.json")
            text = f.stats.to_json();
        else if (w == "stats.table")
            text = f.stats.to_table();
        else if (w == "settings")
            for (const auto& [key, value] : f.settings) text += key + "=" + value + "\n";
        else if (w == "backend")
            text = f.backend_line;
        else
            throw InvalidArgument("unknown text '" + w +
                                  "'; known: stats.json, stats.table, settings, backend");
        copy_text(text, buf, size, needed);
    });
}

SHEAF_API SheafError sheafFrameSaveImage(SheafFrame frame, const char* path) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        const char* p = require(path, "path");
        try {
            sheaf::write_image(f, p);
        } catch (const sheaf::RenderError& e) {
            throw IoError(e.what());
        }
    });
}

SHEAF_API SheafError sheafFrameSavePass(SheafFrame frame, const char* pass, const char* path) {
    return barrier([&] {
        const sheaf::Frame& f = frame_of(frame);
        const std::string name = require(pass, "pass");
        const char* p = require(path, "path");
        const auto& known = sheaf::pass_names();
        if (std::find(known.begin(), known.end(), name) == known.end())
            throw InvalidArgument("unknown pass '" + name +
                                  "'; passes: combined, depth, normal, albedo, object_id, tests");
        check_pass(f, name.c_str());
        try {
            sheaf::write_pass_image(f, name, p);
        } catch (const sheaf::RenderError& e) {
            throw IoError(e.what());
        }
    });
}

} // extern "C"
