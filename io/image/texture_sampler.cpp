#include "io/image/texture_sampler.h"

#include "core/base/error.h"

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <cmath>
#include <memory>

namespace sheaf::io {
namespace {

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
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

class OiioSampler final : public TextureSampler {
  public:
    /// `gamma`: the scene's working gamma; texels are read into that space (linear^(1/gamma)).
    explicit OiioSampler(float gamma) : ts_(texture_system()), inv_gamma_(1 / gamma) {}

    void add(const Texture& tex) {
        const std::string where = tex.origin.empty() ? "" : " (asked for at " + tex.origin + ")";
        auto in = OIIO::ImageInput::open(tex.path);
        if (!in)
            throw SceneError(tex.path + ": cannot read texture" + where + ": " + OIIO::geterror());
        const OIIO::ImageSpec spec = in->spec();
        bool srgb;
        if (tex.colorspace == "srgb")
            srgb = true;
        else if (tex.colorspace == "linear" || tex.colorspace == "data")
            srgb = false;
        else {
            // Follow the file: what it says, else 8- and 16-bit images are sRGB, float is linear.
            const std::string cs = spec.get_string_attribute("oiio:ColorSpace");
            if (!cs.empty())
                srgb = cs == "sRGB";
            else
                srgb = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                       spec.format.basetype == OIIO::TypeDesc::UINT16;
        }
        const OIIO::ustring file(tex.path);
        ts_->invalidate(file); // a file changed since another scene read it is read anew
        entries_.push_back({file, srgb, tex.colorspace == "data",
                            std::max(1, std::min(3, spec.nchannels)), spec.width, spec.height});
    }

    Vec3 sample(uint32_t index, float s, float t) const override {
        const Entry& e = entries_[index];
        OIIO::TextureOpt opt;
        opt.swrap = opt.twrap = OIIO::TextureOpt::WrapPeriodic;
        // One sample per pixel centre, no footprint: the finest level, bilinear.
        opt.mipmode = OIIO::TextureOpt::MipModeNoMIP;
        opt.interpmode = OIIO::TextureOpt::InterpBilinear;
        float rgb[3] = {0, 0, 0};
        // Texture coordinates put t = 0 at the bottom of the image, OpenImageIO at the top.
        if (!ts_->texture(e.file, opt, s, 1.0f - t, 0, 0, 0, 0, e.channels, rgb))
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
        OIIO::ustring file;
        bool srgb;
        bool data; // values as stored (a bump map's heights): no decoding, no working gamma
        int channels;
        int width, height;
    };
    OIIO::TextureSystem* ts_;
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
