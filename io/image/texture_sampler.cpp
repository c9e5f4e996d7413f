#include "io/image/texture_sampler.h"

#include "core/base/error.h"
#include "io/image/image_module.h"

#include <cmath>
#include <memory>

namespace sheaf::io {
namespace {

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

class OiioSampler final : public TextureSampler {
  public:
    /// `gamma`: the scene's working gamma; texels are read into that space (linear^(1/gamma)).
    explicit OiioSampler(float gamma) : module_(image_module()), inv_gamma_(1 / gamma) {}

    void add(const Texture& tex) {
        const std::string where = tex.origin.empty() ? "" : " (asked for at " + tex.origin + ")";
        SheafImageInfo spec{};
        const void* handle = nullptr;
        char error[1024] = "";
        if (module_.texture_open(tex.path.c_str(), &spec, &handle, error, sizeof error) !=
            SHEAF_IMAGE_OK)
            throw SceneError(tex.path + ": cannot read texture" + where + ": " + error);
        bool srgb;
        if (tex.colorspace == "srgb")
            srgb = true;
        else if (tex.colorspace == "linear" || tex.colorspace == "data")
            srgb = false;
        else if (spec.colorspace[0]) // follow the file: what it says,
            srgb = std::string(spec.colorspace) == "sRGB";
        else // else 8- and 16-bit images are sRGB, float is linear
            srgb = spec.type == SHEAF_PIXEL_UINT8 || spec.type == SHEAF_PIXEL_UINT16;
        entries_.push_back({handle, srgb, tex.colorspace == "data",
                            std::max(1, std::min(3, spec.channels)), spec.width, spec.height});
    }

    Vec3 sample(uint32_t index, float s, float t) const override {
        const Entry& e = entries_[index];
        float rgb[3] = {0, 0, 0};
        // Texture coordinates put t = 0 at the bottom of the image, OpenImageIO at the top.
        if (!module_.texture_sample(e.texture, s, 1.0f - t, e.channels, rgb))
            return Vec3(1, 0, 1);
        if (e.channels == 1) rgb[1] = rgb[2] = rgb[0];
        if (e.srgb)
            for (float& c : rgb) c = srgb_to_linear(c);
        if (inv_gamma_ != 1 && !e.data)
            for (float& c : rgb) c = c > 0 ? std::pow(c, inv_gamma_) : c;
        return {rgb[0], rgb[1], rgb[2]};
    }

    void size(uint32_t index, int& width, int& height) const override {
        width = entries_[index].width, height = entries_[index].height;
    }

  private:
    struct Entry {
        const void* texture; // the module's handle
        bool srgb;
        bool data; // values as stored (a bump map's heights): no decoding, no working gamma
        int channels;
        int width, height;
    };
    const SheafImageModule& module_;
    float inv_gamma_;
    std::vector<Entry> entries_;
};

} // namespace

void attach_texture_sampler(PreparedScene& scene) {
    if (scene.textures.empty()) return;
    auto sampler = std::make_shared<OiioSampler>(scene.working_gamma);
    for (const Texture& t : scene.textures) sampler->add(t);
    scene.sampler = std::move(sampler);
}

} // namespace sheaf::io
