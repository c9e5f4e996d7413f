#include "io/image/image_module.h"

#include "core/base/error.h"
#include "core/base/module_loader.h"

#include <mutex>

namespace sheaf::io {

namespace {

std::string module_build_path() {
#ifdef SHEAF_IMAGE_MODULE_BUILD_PATH
    return SHEAF_IMAGE_MODULE_BUILD_PATH;
#else
    return {};
#endif
}

} // namespace

const SheafImageModule& image_module() {
    static std::once_flag once;
    static const SheafImageModule* module = nullptr;
    static std::string error;
    std::call_once(once, [] {
        const OpenedModule m = open_module(
            module_candidates("SHEAF_IMAGE_MODULE", SHEAF_IMAGE_MODULE_FILE, module_build_path()),
            SHEAF_IMAGE_MODULE_ENTRY, [](void* symbol, std::string& why) -> const void* {
                if (!symbol) return nullptr;
                const SheafImageModule* t = reinterpret_cast<SheafImageModuleEntry>(symbol)(
                    SHEAF_IMAGE_MODULE_ABI, sheaf_image_layout());
                if (!t) why = "built from another version of Sheaf";
                return t;
            });
        module = static_cast<const SheafImageModule*>(m.table);
        if (!module)
            error = "images cannot be read or written: the image module " SHEAF_IMAGE_MODULE_FILE
                    " was not found or not loadable (" +
                    m.tried + ")";
    });
    if (!module) throw RenderError(error);
    return *module;
}

void encode_image(const ImageToWrite& im) {
    const SheafImageModule& m = image_module();
    std::vector<const char*> names, attributes;
    for (const std::string& n : im.channel_names) names.push_back(n.c_str());
    for (const auto& [k, v] : im.attributes) attributes.push_back(k.c_str()), attributes.push_back(v.c_str());
    if (!names.empty() && int(names.size()) != im.channels)
        throw RenderError(im.path + ": cannot write image: " + std::to_string(names.size()) +
                          " channel names for " + std::to_string(im.channels) + " channels");
    if (int(im.types.size()) != im.channels)
        throw RenderError(im.path + ": cannot write image: " + std::to_string(im.types.size()) +
                          " channel types for " + std::to_string(im.channels) + " channels");
    const SheafImageWrite w{im.path.c_str(),
                            im.width,
                            im.height,
                            im.channels,
                            im.x,
                            im.y,
                            im.full_width,
                            im.full_height,
                            names.empty() ? nullptr : names.data(),
                            im.types.data(),
                            im.alpha_channel,
                            im.z_channel,
                            attributes.data(),
                            int(im.attributes.size()),
                            im.pixels};
    char error[1024] = "";
    if (m.write(&w, error, sizeof error) != SHEAF_IMAGE_OK)
        throw RenderError(im.path + ": cannot write image: " + error);
}

ImageReader::ImageReader(const std::string& path) : module_(image_module()) {
    char error[1024] = "";
    if (module_.open(path.c_str(), &info_, &reader_, error, sizeof error) != SHEAF_IMAGE_OK)
        throw RenderError(error);
}

ImageReader::~ImageReader() {
    if (reader_) module_.close(reader_);
}

std::optional<std::string> ImageReader::describe(int channel, const char* attribute) const {
    if (!reader_) return std::nullopt;
    const int n = module_.describe(reader_, channel, attribute, nullptr, 0);
    if (n < 0) return std::nullopt;
    std::string out(size_t(n) + 1, '\0');
    module_.describe(reader_, channel, attribute, out.data(), out.size());
    out.resize(size_t(n));
    return out;
}

std::vector<float> ImageReader::read(int channels) {
    if (!reader_) throw RenderError("an image read twice");
    std::vector<float> pixels(size_t(info_.width) * size_t(info_.height) * size_t(channels));
    char error[1024] = "";
    void* r = reader_;
    reader_ = nullptr; // read closes it, whatever it returns
    if (module_.read(r, channels, pixels.data(), error, sizeof error) != SHEAF_IMAGE_OK)
        throw RenderError(error);
    return pixels;
}

} // namespace sheaf::io
