// The interface between libsheaf and the image module (libsheaf_image.so.0, built from
// io/image/oiio_module.cpp): every call that reads or writes an image file through
// OpenImageIO. libsheaf never links OpenImageIO: loading it and the ~250 libraries it pulls in
// costs about 0.4 s of start-up, which a process that reads and writes no image (`render
// --version`, `--check`, a host that only renders to memory) should not pay. libsheaf
// dlopen()s the module at the first image read or written (io/image/image_module.cpp).
//
// Plain C types only cross: the module is built without the core. A table of another ABI
// version or with other struct sizes is refused. No call throws; each returns
// SHEAF_IMAGE_OK or writes its message into `error`.
#pragma once

#include <stddef.h>

#define SHEAF_IMAGE_MODULE_ABI 2
#define SHEAF_IMAGE_MODULE_ENTRY "sheaf_image_module"
#define SHEAF_IMAGE_MODULE_FILE "libsheaf_image.so.0"

extern "C" {

enum SheafImageStatus { SHEAF_IMAGE_OK = 0, SHEAF_IMAGE_FAILED = 1 };

/// Sample types, of a file's pixels or of a channel to write.
enum SheafPixelType {
    SHEAF_PIXEL_UINT8 = 0,
    SHEAF_PIXEL_UINT16 = 1,
    SHEAF_PIXEL_HALF = 2,
    SHEAF_PIXEL_FLOAT = 3,
    SHEAF_PIXEL_OTHER = 4 // read only: any other stored type
};

/// What an image file says of itself.
struct SheafImageInfo {
    int width, height, channels;
    int type;             // SheafPixelType of its pixels (of the first channel)
    int x, y;             // where the pixels lie in the whole image (OpenEXR's data window)
    int full_width, full_height; // the whole image (OpenEXR's display window)
    int all_float;        // 1 when every channel is stored as 32-bit float
    char colorspace[64];  // its "oiio:ColorSpace" attribute, empty when it names none
};

/// An image to write: `pixels` holds width x height x channels floats, row by row from the
/// top; the file stores them as `types` say (one per channel).
struct SheafImageWrite {
    const char* path;
    int width, height, channels;
    int x, y, full_width, full_height; // the pixels' place in a whole image; 0 0 0 0: none
    const char* const* channel_names; // `channels` names, or null for the format's defaults
    const int* types;                 // `channels` SheafPixelType values
    int alpha_channel, z_channel;     // -1: as the default names say (RGBA: alpha 3)
    const char* const* attributes;    // key, value, key, value, ...
    int attribute_count;              // pairs
    const float* pixels;
};

struct SheafImageModule {
    int abi_version;         // SHEAF_IMAGE_MODULE_ABI
    size_t layout;           // sheaf_image_layout() of the module's build
    const char* library;     // "OpenImageIO 2.4.7"
    int (*write)(const SheafImageWrite* image, char* error, size_t error_size);
    /// Opens `path` for reading and fills *info; *reader is released by read or close.
    int (*open)(const char* path, SheafImageInfo* info, void** reader, char* error,
                size_t error_size);
    /// Reads the first `channels` channels of the image as floats into `out` (width x height
    /// x channels), then closes the reader.
    int (*read)(void* reader, int channels, float* out, char* error, size_t error_size);
    void (*close)(void* reader);
    /// Channel `c`'s name (or the string attribute `name` when c < 0) of an open reader into
    /// `out` (`size` bytes, terminated); returns the length it has, which may exceed size - 1,
    /// or -1 when there is no such channel or attribute.
    int (*describe)(void* reader, int c, const char* name, char* out, size_t size);
    /// Opens `path` for filtered sampling through OpenImageIO's texture cache (read again if
    /// it changed since an earlier open) and fills *info; *texture lives as long as the process.
    int (*texture_open)(const char* path, SheafImageInfo* info, const void** texture,
                        char* error, size_t error_size);
    /// Bilinear, periodic, at the finest level, (s, t) from the top left; `channels` floats
    /// into `out`. 0 when the texture cannot be read.
    int (*texture_sample)(const void* texture, float s, float t, int channels, float* out);
};

/// The module's one export: its table, or null when `abi_version` / `layout` differ.
typedef const SheafImageModule* (*SheafImageModuleEntry)(int abi_version, size_t layout);

} // extern "C"

/// The sizes of the structs that cross, folded into one number.
constexpr size_t sheaf_image_layout() {
    return sizeof(SheafImageInfo) * 10007u + sizeof(SheafImageWrite) * 101u +
           sizeof(SheafImageModule);
}
