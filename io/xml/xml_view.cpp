// <camera>, <light>, <background>, <sky>, <fog> and <settings>: what the scene is seen with.
#include "io/xml/xml_reader.h"

#include "core/base/error.h"
#include "core/settings/settings.h"

#include <cmath>

namespace sheaf::io::xml {
namespace {

void no_children(const XmlContext& ctx, const pugi::xml_node& node) {
    const std::vector<pugi::xml_node> children = child_elements(ctx, node);
    if (!children.empty()) unknown_element(ctx, children[0], node, {});
}

} // namespace

void SceneReader::read_camera(const pugi::xml_node& node) {
    if (camera_seen_) ctx_.fail(node, "a scene has one <camera>; this is the second");
    camera_seen_ = true;
    no_children(ctx_, node);
    Attributes a(ctx_, node);
    Camera c;
    int projection = 0;
    // In Projection's order.
    a.get("projection", projection,
          {"perspective", "orthographic", "fisheye", "ultra_wide_angle", "omnimax", "panoramic",
           "cylinder1", "cylinder2", "cylinder3", "cylinder4", "spherical"});
    c.projection = Projection(projection);
    a.get("position", c.position);
    a.get("look_at", c.look_at);
    a.get("up", c.up);
    if (c.projection == Projection::Perspective)
        a.get("fov", c.fov_y_degrees);
    else if (c.projection == Projection::Orthographic)
        a.get("ortho_height", c.ortho_height);
    if (c.projection == Projection::Perspective || c.projection == Projection::Orthographic) {
        a.get("lens_radius", c.lens_radius);
        a.get("focal_distance", c.focal_distance);
    }
    const bool traced = traced_projection(c.projection);
    if (traced) {
        if (c.projection == Projection::Spherical) c.angle_degrees = 360;
        a.get("angle", c.angle_degrees);
        if (c.projection == Projection::Spherical) {
            c.v_angle_degrees = 0.5f * c.angle_degrees;
            a.get("v_angle", c.v_angle_degrees);
        }
        Vec3 lengths(c.right_length, c.up_length, c.direction_length);
        a.get("lengths", lengths);
        c.right_length = lengths.x, c.up_length = lengths.y, c.direction_length = lengths.z;
    }
    std::vector<float> shift;
    if (a.get_numbers("shift", shift)) {
        if (shift.size() != 2)
            ctx_.fail(node, node.attribute("shift"),
                      "attribute 'shift' of <camera>: expected two numbers (x y), found " +
                          std::to_string(shift.size()));
        c.shift_x = shift[0], c.shift_y = shift[1];
    }
    std::string normal;
    if (a.get("normal", normal) && !normal.empty())
        c.normal = int32_t(lookup(normals_, "normal", normal, node, node.attribute("normal")));
    a.finish();
    if (!(length(c.look_at - c.position) > 0))
        ctx_.fail(node, node.attribute("look_at"), "the camera looks at its own position");
    if (!(c.lens_radius >= 0 && c.lens_radius < 1e30f))
        ctx_.fail(node, node.attribute("lens_radius"), "a camera's lens radius must be >= 0");
    if (c.lens_radius > 0 && !(c.focal_distance > 0 && c.focal_distance < 1e30f))
        ctx_.fail(node, node.attribute("lens_radius"),
                  "a camera with a lens needs a focal_distance > 0 (the sharp plane's)");
    if (!(length(cross(c.look_at - c.position, c.up)) > 0))
        ctx_.fail(node, node.attribute("up"), "the camera's up vector is parallel to its view");
    if (c.projection == Projection::Perspective && !(c.fov_y_degrees > 0 && c.fov_y_degrees < 180))
        ctx_.fail(node, node.attribute("fov"), "the field of view must lie in (0, 180) degrees");
    if (c.projection == Projection::Orthographic && !(c.ortho_height > 0))
        ctx_.fail(node, node.attribute("ortho_height"), "ortho_height must be > 0");
    if (traced && !camera_angle_ok(c.angle_degrees))
        ctx_.fail(node, node.attribute("angle"), "the angle must lie in (0, 3600] degrees");
    if (traced && !camera_angle_ok(c.v_angle_degrees))
        ctx_.fail(node, node.attribute("v_angle"), "v_angle must lie in (0, 3600] degrees");
    if (traced && !(camera_length_ok(c.right_length) && camera_length_ok(c.up_length) &&
                    camera_length_ok(c.direction_length)))
        ctx_.fail(node, node.attribute("lengths"),
                  "the lengths of right, up and direction must be finite numbers > 0");
    scene_.camera = c;
}

void SceneReader::read_light(const pugi::xml_node& node) {
    no_children(ctx_, node);
    Attributes a(ctx_, node);
    Light l;
    int type = 0;
    a.get("type", type, {"point", "spot", "parallel"});
    constexpr LightType kTypes[] = {LightType::Point, LightType::Spot, LightType::Parallel};
    l.type = kTypes[type];
    a.get("color", l.color, true);
    a.get("fade_distance", l.fade_distance);
    a.get("fade_power", l.fade_power);
    a.get("shadowless", l.shadowless);
    if (l.type != LightType::Parallel) a.get("position", l.position);
    if (l.type != LightType::Point) a.get("direction", l.direction);
    if (l.type == LightType::Spot) {
        Vec3 look_at;
        if (a.get("look_at", look_at)) {
            if (node.attribute("direction"))
                ctx_.fail(node, node.attribute("look_at"),
                          "a spot light takes a direction or a look_at point, not both");
            l.direction = look_at - l.position;
        }
        a.get("radius", l.spot_radius);
        a.get("falloff", l.spot_falloff);
        a.get("tightness", l.spot_tightness);
    }
    a.finish();
    if (l.type != LightType::Point && !(length(l.direction) > 0))
        ctx_.fail(node, "the light's direction must not be zero");
    if (l.type == LightType::Spot && !(l.spot_radius >= 0 && l.spot_falloff > 0 &&
                                       l.spot_falloff <= 180 && l.spot_tightness >= 0))
        ctx_.fail(node, "a spot light needs radius >= 0, 0 < falloff <= 180 degrees and "
                        "tightness >= 0");
    if (!(l.fade_distance >= 0 && l.fade_power >= 0))
        ctx_.fail(node, "fade_distance and fade_power must be >= 0");
    scene_.add_light(l);
}

void SceneReader::read_background(const pugi::xml_node& node) {
    if (background_seen_) ctx_.fail(node, "a scene has one <background>; this is the second");
    if (sky_seen_)
        ctx_.fail(node, "a scene has a <background> or a <sky>, not both: rays that leave the "
                        "scene see the sky's pigment instead of the background colour");
    background_seen_ = true;
    no_children(ctx_, node);
    Attributes a(ctx_, node);
    a.get("color", scene_.background, true);
    a.finish();
    a.require("color");
}

void SceneReader::read_sky(const pugi::xml_node& node) {
    if (sky_seen_) ctx_.fail(node, "a scene has one <sky>; this is the second");
    if (background_seen_)
        ctx_.fail(node, "a scene has a <background> or a <sky>, not both: rays that leave the "
                        "scene see the sky's pigment instead of the background colour");
    sky_seen_ = true;
    no_children(ctx_, node);
    Attributes a(ctx_, node);
    std::string pigment;
    a.get("pigment", pigment);
    a.finish();
    a.require("pigment");
    scene_.sky = int32_t(lookup(pigments_, "pigment", pigment, node, node.attribute("pigment")));
}

void SceneReader::read_fog(const pugi::xml_node& node) {
    if (fog_seen_) ctx_.fail(node, "a scene has one <fog>; this is the second");
    fog_seen_ = true;
    no_children(ctx_, node);
    Attributes a(ctx_, node);
    Fog f;
    a.get("distance", f.distance);
    a.get("color", f.color, true);
    a.get("transmit", f.transmit);
    a.finish();
    a.require("distance");
    a.require("color");
    if (!(f.distance > 0))
        ctx_.fail(node, node.attribute("distance"), "the fog's distance must be > 0");
    if (!(f.transmit >= 0 && f.transmit <= 1))
        ctx_.fail(node, node.attribute("transmit"), "the fog's transmit must lie in 0..1");
    scene_.fog.layer[0] = f;
    scene_.fog.count = 1;
}

void SceneReader::read_settings(const pugi::xml_node& node) {
    Attributes(ctx_, node).finish();
    for (const pugi::xml_node& s : child_elements(ctx_, node)) {
        if (std::string_view(s.name()) != "set") unknown_element(ctx_, s, node, {"set"});
        no_children(ctx_, s);
        Attributes a(ctx_, s);
        std::string key, value;
        a.get("key", key);
        a.get("value", value);
        a.finish();
        a.require("key");
        a.require("value");
        std::string canonical;
        try {
            canonical = canonical_setting(key, value);
        } catch (const SettingsError& e) {
            ctx_.fail(s, s.attribute(find_setting(key) ? "value" : "key"), e.what());
        }
        if (!scene_.settings.emplace(key, canonical).second)
            ctx_.fail(s, s.attribute("key"), "setting '" + key + "' is set twice");
    }
}

} // namespace sheaf::io::xml
