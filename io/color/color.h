// Colour management through OpenColorIO: scene-linear renders shown through a display/view
// (and optional looks) of a config: the one given, else $OCIO, else the config Sheaf ships
// (io/color/sheaf.ocio, compiled into the library).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sheaf::io {

struct DisplayOptions {
    std::string config;  // a config file; empty: $OCIO, else the shipped config
    std::string display; // empty: the config's default display
    std::string view;    // empty: the display's default view
    std::string looks;   // comma-separated looks, empty for none
};

/// The text of the shipped config.
const std::string& shipped_ocio_config();

/// Converts `pixels` scene-linear RGBA pixels (4 floats each, alpha untouched) in place to
/// display-referred values. Throws RenderError naming an unknown display, view or look and the
/// ones the config has, or a config that does not load.
void apply_display_transform(float* rgba, size_t pixels, const DisplayOptions& options);

/// Displays and views of the config the options select, for messages and hosts.
std::vector<std::string> ocio_displays(const DisplayOptions& options);

} // namespace sheaf::io
