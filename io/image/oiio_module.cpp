// The image module: every OpenImageIO call of Sheaf, behind the plain-C table of
// io/image/image_module_abi.h. Built as libsheaf_image.so.0 and loaded by libsheaf at the
// first image it reads or writes, so that processes that touch no image never load
// OpenImageIO. No call lets an exception out.
#include "io/image/image_module_abi.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

namespace {

void put(char* error, size_t size, const std::string& message) {
    if (error && size > 0) std::snprintf(error, size, "%s", message.c_str());
}

/// Runs `body`; an exception becomes SHEAF_IMAGE_FAILED with its message.
template <class F> int guarded(char* error, size_t size, F&& body) {
    try {
        return int(body());
    } catch (const std::exception& e) {
        put(error, size, e.what());
    } catch (...) {
        put(error, size, "OpenImageIO failed");
    }
    return SHEAF_IMAGE_FAILED;
}

OIIO::TypeDesc type_desc(int type) {
    switch (type) {
    case SHEAF_PIXEL_UINT8: return OIIO::TypeDesc::UINT8;
    case SHEAF_PIXEL_UINT16: return OIIO::TypeDesc::UINT16;
    case SHEAF_PIXEL_HALF: return OIIO::TypeDesc::HALF;
    default: return OIIO::TypeDesc::FLOAT;
    }
}

void fill_info(const OIIO::ImageSpec& spec, SheafImageInfo* info) {
    info->width = spec.width, info->height = spec.height, info->channels = spec.nchannels;
    switch (spec.format.basetype) {
    case OIIO::TypeDesc::UINT8: info->type = SHEAF_PIXEL_UINT8; break;
    case OIIO::TypeDesc::UINT16: info->type = SHEAF_PIXEL_UINT16; break;
    case OIIO::TypeDesc::HALF: info->type = SHEAF_PIXEL_HALF; break;
    case OIIO::TypeDesc::FLOAT: info->type = SHEAF_PIXEL_FLOAT; break;
    default: info->type = SHEAF_PIXEL_OTHER;
    }
    info->x = spec.x, info->y = spec.y;
    info->full_width = spec.full_width, info->full_height = spec.full_height;
    info->all_float = 1;
    for (int c = 0; c < spec.nchannels; ++c)
        info->all_float &= spec.channelformat(c) == OIIO::TypeDesc::FLOAT ? 1 : 0;
    std::snprintf(info->colorspace, sizeof info->colorspace, "%s",
                  spec.get_string_attribute("oiio:ColorSpace").c_str());
}

/// Opens `path` and fills *info; null (the message in `error`) when it cannot be read.
std::unique_ptr<OIIO::ImageInput> open_input(const char* path, SheafImageInfo* info, char* error,
                                             size_t size) {
    // Only a regular file: OpenImageIO hands a folder to libheif, which then reads without end
    // and takes gigabytes (found by the C ABI fuzzer with a texture path of "/"), and a device
    // such as /dev/zero never ends.
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::is_regular_file(status)) {
        put(error, size,
            std::string(path) + (ec || !std::filesystem::exists(status)
                                     ? ": no such file"
                                     : ": not an image file (a folder or a device)"));
        return nullptr;
    }
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) put(error, size, OIIO::geterror());
    else fill_info(in->spec(), info);
    return in;
}

int write_image(const SheafImageWrite* im, char* error, size_t size) {
    return guarded(error, size, [&] {
        OIIO::ImageSpec spec(im->width, im->height, im->channels, OIIO::TypeDesc::FLOAT);
        if (im->channel_names) spec.channelnames.assign(im->channel_names,
                                                        im->channel_names + im->channels);
        bool one_type = true;
        for (int c = 1; c < im->channels; ++c) one_type &= im->types[c] == im->types[0];
        if (one_type) {
            spec.set_format(type_desc(im->types[0]));
        } else {
            for (int c = 0; c < im->channels; ++c)
                spec.channelformats.push_back(type_desc(im->types[c]));
        }
        if (im->full_width > 0 && im->full_height > 0) {
            spec.x = im->x, spec.y = im->y;
            spec.full_width = im->full_width, spec.full_height = im->full_height;
        }
        if (im->alpha_channel >= 0) spec.alpha_channel = im->alpha_channel;
        if (im->z_channel >= 0) spec.z_channel = im->z_channel;
        for (int a = 0; a < im->attribute_count; ++a)
            spec.attribute(im->attributes[2 * a], im->attributes[2 * a + 1]);
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(im->path);
        if (!out) {
            put(error, size, OIIO::geterror());
            return SHEAF_IMAGE_FAILED;
        }
        if (!out->open(im->path, spec)) {
            put(error, size, out->geterror());
            return SHEAF_IMAGE_FAILED;
        }
        if (!out->write_image(OIIO::TypeDesc::FLOAT, im->pixels)) {
            put(error, size, out->geterror());
            out->close();
            return SHEAF_IMAGE_FAILED;
        }
        if (!out->close()) {
            put(error, size, out->geterror());
            return SHEAF_IMAGE_FAILED;
        }
        return SHEAF_IMAGE_OK;
    });
}

int open_image(const char* path, SheafImageInfo* info, void** reader, char* error, size_t size) {
    *reader = nullptr;
    return guarded(error, size, [&] {
        std::unique_ptr<OIIO::ImageInput> in = open_input(path, info, error, size);
        if (!in) return SHEAF_IMAGE_FAILED;
        *reader = in.release();
        return SHEAF_IMAGE_OK;
    });
}

void close_image(void* reader) { delete static_cast<OIIO::ImageInput*>(reader); }

int describe_image(void* reader, int c, const char* name, char* out, size_t size) {
    try {
        const OIIO::ImageSpec& spec = static_cast<OIIO::ImageInput*>(reader)->spec();
        std::string text;
        if (c >= 0) {
            if (c >= spec.nchannels) return -1;
            text = spec.channel_name(c);
        } else {
            const OIIO::ParamValue* p = spec.find_attribute(name, OIIO::TypeDesc::STRING);
            if (!p) return -1;
            text = p->get_string();
        }
        if (out && size > 0) std::snprintf(out, size, "%s", text.c_str());
        return int(text.size());
    } catch (...) {
        return -1;
    }
}

int read_image(void* reader, int channels, float* out, char* error, size_t size) {
    std::unique_ptr<OIIO::ImageInput> in(static_cast<OIIO::ImageInput*>(reader));
    return guarded(error, size, [&] {
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, out)) {
            put(error, size, in->geterror());
            return SHEAF_IMAGE_FAILED;
        }
        return SHEAF_IMAGE_OK;
    });
}

// One texture system for the process, never destroyed. OpenImageIO 2.4's
// TextureSystem::destroy frees the object with a size that does not match its allocation;
// hosts whose allocator trusts sized frees (Blender's jemalloc) had their heap corrupted each
// time a textured scene was released.
OIIO::TextureSystem* texture_system() {
    static OIIO::TextureSystem* ts = [] {
        OIIO::TextureSystem* t = OIIO::TextureSystem::create(false);
        // Keep the cache modest: textures are read on demand, tile by tile.
        t->attribute("max_memory_MB", 512.0f);
        return t;
    }();
    return ts;
}

int texture_open(const char* path, SheafImageInfo* info, const void** texture, char* error,
                 size_t size) {
    *texture = nullptr;
    return guarded(error, size, [&] {
        if (!open_input(path, info, error, size)) return SHEAF_IMAGE_FAILED;
        OIIO::TextureSystem* ts = texture_system();
        const OIIO::ustring file(path);
        ts->invalidate(file); // a file changed since another scene read it is read anew
        *texture = ts->get_texture_handle(file);
        if (!*texture) {
            put(error, size, ts->geterror());
            return SHEAF_IMAGE_FAILED;
        }
        return SHEAF_IMAGE_OK;
    });
}

int texture_sample(const void* texture, float s, float t, int channels, float* out) {
    OIIO::TextureSystem* ts = texture_system();
    OIIO::TextureOpt opt;
    opt.swrap = opt.twrap = OIIO::TextureOpt::WrapPeriodic;
    // One sample per pixel centre, no footprint: the finest level, bilinear.
    opt.mipmode = OIIO::TextureOpt::MipModeNoMIP;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    auto* handle = static_cast<OIIO::TextureSystem::TextureHandle*>(const_cast<void*>(texture));
    return ts->texture(handle, ts->get_perthread_info(), opt, s, t, 0, 0, 0, 0, channels, out)
               ? 1
               : 0;
}

const SheafImageModule kModule = {
    SHEAF_IMAGE_MODULE_ABI, sheaf_image_layout(), "OpenImageIO " OIIO_VERSION_STRING,
    write_image,            open_image,           read_image,
    close_image,            describe_image,       texture_open,
    texture_sample,
};

} // namespace

extern "C" __attribute__((visibility("default"))) const SheafImageModule*
sheaf_image_module(int abi_version, size_t layout) {
    return abi_version == SHEAF_IMAGE_MODULE_ABI && layout == sheaf_image_layout() ? &kModule
                                                                                   : nullptr;
}
