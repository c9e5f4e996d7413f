#include "io/pov/function_scene.h"

#include "core/scene/scene_view.h"
#include "core/shading/surface_texture.h"

namespace sheaf::io::pov {

std::array<float, 5> FunctionScene::color_at(double x, double y, double z) const {
    if (pigment < 0) return {0, 0, 0, 0, 0};
    const SurfaceColor c = evaluate_pigment(SceneView(tables), uint32_t(pigment),
                                            Vec3(float(x), float(y), float(z)), 0, 0);
    return {c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit};
}

double FunctionScene::value_at(double x, double y, double z) const {
    if (pattern < 0) return 0;
    return evaluate_fn_pattern(SceneView(tables), uint32_t(pattern), x, y, z);
}

} // namespace sheaf::io::pov
