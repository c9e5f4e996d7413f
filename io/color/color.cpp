#include "io/color/color.h"

#include "core/base/error.h"
#include "io/color/sheaf_ocio_config.h" // generated: kShippedOcioConfig

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;

namespace sheaf::io {
namespace {

OCIO::ConstConfigRcPtr load_config(const DisplayOptions& o, std::string& name) {
    try {
        if (!o.config.empty()) {
            name = o.config;
            return OCIO::Config::CreateFromFile(o.config.c_str());
        }
        if (const char* env = std::getenv("OCIO"); env && *env) {
            name = std::string("$OCIO (") + env + ")";
            return OCIO::Config::CreateFromFile(env);
        }
        name = "Sheaf's shipped config";
        std::istringstream in(shipped_ocio_config());
        return OCIO::Config::CreateFromStream(in);
    } catch (const OCIO::Exception& e) {
        throw RenderError("OpenColorIO config " + name + ": " + e.what());
    }
}

std::string join(const std::vector<std::string>& v) {
    std::string out;
    for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
    return out;
}

} // namespace

const std::string& shipped_ocio_config() {
    static const std::string text(kShippedOcioConfig);
    return text;
}

std::vector<std::string> ocio_displays(const DisplayOptions& options) {
    std::string name;
    const auto config = load_config(options, name);
    std::vector<std::string> out;
    for (int i = 0; i < config->getNumDisplays(); ++i) out.emplace_back(config->getDisplay(i));
    return out;
}

void apply_display_transform(float* rgba, size_t pixels, const DisplayOptions& o) {
    std::string name;
    const auto config = load_config(o, name);
    const std::string display = o.display.empty() ? config->getDefaultDisplay() : o.display;
    std::vector<std::string> displays;
    for (int i = 0; i < config->getNumDisplays(); ++i) displays.emplace_back(config->getDisplay(i));
    if (std::find(displays.begin(), displays.end(), display) == displays.end())
        throw RenderError("display '" + display + "' is not in " + name +
                          "; displays: " + join(displays));
    const std::string view = o.view.empty() ? config->getDefaultView(display.c_str()) : o.view;
    std::vector<std::string> views;
    for (int i = 0; i < config->getNumViews(display.c_str()); ++i)
        views.emplace_back(config->getView(display.c_str(), i));
    if (std::find(views.begin(), views.end(), view) == views.end())
        throw RenderError("view '" + view + "' is not a view of display '" + display + "' in " +
                          name + "; views: " + join(views));
    try {
        auto t = OCIO::DisplayViewTransform::Create();
        t->setSrc(OCIO::ROLE_SCENE_LINEAR);
        t->setDisplay(display.c_str());
        t->setView(view.c_str());
        OCIO::ConstProcessorRcPtr processor;
        if (o.looks.empty()) {
            processor = config->getProcessor(t);
        } else {
            // Looks apply in scene-linear before the display transform.
            std::istringstream list(o.looks);
            for (std::string look; std::getline(list, look, ',');)
                if (!config->getLook(look.c_str())) {
                    std::vector<std::string> looks;
                    for (int i = 0; i < config->getNumLooks(); ++i)
                        looks.emplace_back(config->getLookNameByIndex(i));
                    throw RenderError("look '" + look + "' is not in " + name + "; looks: " +
                                      (looks.empty() ? std::string("none") : join(looks)));
                }
            auto group = OCIO::GroupTransform::Create();
            auto lt = OCIO::LookTransform::Create();
            lt->setSrc(OCIO::ROLE_SCENE_LINEAR);
            lt->setDst(OCIO::ROLE_SCENE_LINEAR);
            lt->setLooks(o.looks.c_str());
            group->appendTransform(lt);
            group->appendTransform(t);
            processor = config->getProcessor(group);
        }
        auto cpu = processor->getDefaultCPUProcessor();
        OCIO::PackedImageDesc img(rgba, long(pixels), 1, 4);
        cpu->apply(img);
    } catch (const OCIO::Exception& e) {
        throw RenderError(std::string("OpenColorIO (") + name + "): " + e.what());
    }
}

} // namespace sheaf::io
