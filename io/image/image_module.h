// libsheaf's side of the image module (io/image/image_module_abi.h): loaded at the first
// image read or written, then kept for the life of the process. The readers and writers of
// io/image call these instead of OpenImageIO.
#pragma once

#include "io/image/image_module_abi.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sheaf::io {

/// The loaded module, loading it at the first call (thread-safe). Throws RenderError saying
/// where it was looked for when no module could be loaded.
const SheafImageModule& image_module();

/// One image to write (see SheafImageWrite): `pixels` is width x height x channels floats.
struct ImageToWrite {
    std::string path;
    int width = 0, height = 0, channels = 0;
    int x = 0, y = 0, full_width = 0, full_height = 0; // a part's place in the whole; 0: none
    std::vector<std::string> channel_names; // empty: the format's defaults
    std::vector<int> types;                 // SheafPixelType per channel
    int alpha_channel = -1, z_channel = -1; // -1: the default names' (alpha 3 of RGBA)
    std::vector<std::pair<std::string, std::string>> attributes;
    const float* pixels = nullptr;
};

/// Writes the image. Throws RenderError("<path>: cannot write image: ...").
void encode_image(const ImageToWrite& image);

/// An image opened for reading: its header now, its pixels on read().
class ImageReader {
  public:
    /// Throws RenderError with OpenImageIO's message when `path` cannot be opened.
    explicit ImageReader(const std::string& path);
    ~ImageReader();
    ImageReader(const ImageReader&) = delete;
    ImageReader& operator=(const ImageReader&) = delete;

    const SheafImageInfo& info() const { return info_; }
    /// Channel `channel`'s name, or with channel < 0 the string attribute `attribute`; none
    /// when the file has no such channel or attribute (or after read()).
    std::optional<std::string> describe(int channel, const char* attribute = "") const;
    /// The first `channels` channels as floats, width x height x channels.
    std::vector<float> read(int channels);

  private:
    const SheafImageModule& module_;
    SheafImageInfo info_{};
    void* reader_ = nullptr;
};

} // namespace sheaf::io
