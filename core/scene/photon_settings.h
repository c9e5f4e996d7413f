// Photon mapping's scene data (POV-Ray's photons): the scene's settings, what each object does
// with photons, and what each light sends. The photon pass is core/frame/photon_pass.h; the
// gather at shaded points is core/scene/photon_gather.h.
#pragma once

#include <cstdint>

namespace sheaf {

/// POV-Ray's global `photons { }`. Photons are on when spacing > 0.
struct PhotonSettings {
    /// Distance between neighbouring photons where they reach a target object (world units,
    /// times the target's spacing multiplier).
    float spacing = 0.0f;
    /// > 0 instead of a spacing: the spacing that shoots about this many photons.
    uint32_t count = 0;
    /// Photons gathered at a point: fewer than gather_min widen the search once (to
    /// 3 x radius), more than gather_max narrow it to the gather_max nearest.
    uint32_t gather_min = 20, gather_max = 100;
    /// The search radius; 0: estimated from the stored photons' density, as POV-Ray does.
    /// Either is then scaled by radius_scale.
    float radius = 0.0f, radius_scale = 1.0f;
    /// The wider search is kept when its density differs from the first by less than
    /// expand_tolerance, or when it found fewer than expand_min photons (and some).
    float expand_tolerance = 0.2f;
    uint32_t expand_min = 40;
    /// Searches at most: the first and (steps - 1) wider ones, each by 2 x radius.
    uint32_t steps = 2;
    /// Each photon's direction moves by up to jitter x the angle between photons (hashed).
    float jitter = 0.4f;
    /// Surfaces a photon path meets at most (0: the frame's trace.depth + 1).
    uint32_t max_trace_level = 0;
    /// Paths whose strongest channel falls below this stop.
    float adc_bailout = 1.0f / 255.0f;

    bool enabled() const { return spacing > 0.0f || count > 0; }
};

/// POV-Ray's three-valued photon switches: unset, off, on.
enum class PhotonSwitch : uint8_t { Unset, Off, On };

/// What an object does with photons (POV-Ray's object `photons { }`).
struct PhotonObject {
    /// > 0: a target that lights shoot photons at, spaced by PhotonSettings::spacing times
    /// this multiplier.
    float target = 0.0f;
    PhotonSwitch reflection = PhotonSwitch::Unset, refraction = PhotonSwitch::Unset;
};

/// Whether a photon of a light with switch `light` reflects (or refracts) at an object with
/// switch `object`: POV-Ray's rule, on for one and not off for the other.
inline constexpr bool photon_switch_on(PhotonSwitch object, PhotonSwitch light) {
    return (object == PhotonSwitch::On && light != PhotonSwitch::Off) ||
           (object != PhotonSwitch::Off && light == PhotonSwitch::On);
}

} // namespace sheaf
