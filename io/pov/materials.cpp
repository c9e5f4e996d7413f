// PovTexture -> Material, Pigment, NormalPattern, MaterialSwitch (see materials.h).
#include "io/pov/materials.h"

#include "io/pov/builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace sheaf::io::pov {

namespace {

constexpr int kMaxDepth = 12; // nested texture maps; deeper ones use their first entry

std::string key_of(const Material& m) {
    const float* f[] = {&m.color.x,
                        &m.color.y,
                        &m.color.z,
                        &m.emission.x,
                        &m.emission.y,
                        &m.emission.z,
                        &m.ambient,
                        &m.diffuse,
                        &m.specular,
                        &m.phong_exponent,
                        &m.mirror,
                        &m.transmission,
                        &m.ior,
                        &m.brilliance,
                        &m.blinn,
                        &m.blinn_exponent,
                        &m.metallic,
                        &m.mirror_color.x,
                        &m.mirror_color.y,
                        &m.mirror_color.z,
                        &m.mirror_min,
                        &m.mirror_falloff,
                        &m.fade_color.x,
                        &m.fade_color.y,
                        &m.fade_color.z,
                        &m.fade_distance,
                        &m.fade_power,
                        &m.caustics,
                        &m.irid,
                        &m.irid_thickness,
                        &m.irid_turbulence,
                        &m.irid_wavelength.x,
                        &m.irid_wavelength.y,
                        &m.irid_wavelength.z};
    // The values' bits, not their decimal text: formatting 34 floats was a third of reading a
    // scene of many objects (advanced/abyss.pov). Bits tell apart all the values text did.
    std::string k(sizeof f / sizeof f[0] * sizeof(float) + 5, '\0');
    char* at = k.data();
    for (const float* v : f) std::memcpy(at, v, sizeof(float)), at += sizeof(float);
    for (const bool b : {bool(m.mirror_fresnel), bool(m.mirror_metallic), bool(m.conserve_energy),
                         bool(m.conserve_diffuse), bool(m.fresnel_split)})
        *at++ = b ? '1' : '0';
    return k;
}

double max3(const std::array<double, 3>& a) {
    return std::max({a[0], a[1], a[2]});
}

// The share of light a pigment lets through, averaged over its colours: a list pattern's
// (checker, hexagon ...) entries alike, a map's over the pattern's values 0..1 as the map
// blends them (a map clear but for thin lines at its ends lets most light through).
double mean_pass(const PovPigment* pg) {
    if (!pg) return 0;
    if (!pg->patterned || pg->entries.empty()) return pg->color[3] + pg->color[4];
    std::vector<double> pass;
    for (const PovMapEntry& e : pg->entries)
        pass.push_back(e.pigment ? mean_pass(e.pigment.get()) : e.color[3] + e.color[4]);
    const auto& es = pg->entries;
    const bool map = !pattern_is_list(pg->pattern.kind) && !pg->average &&
                     pg->pattern.kind != PatternKind::Image;
    if (!map || es.size() < 2) {
        double sum = 0;
        for (double v : pass) sum += v;
        return sum / double(pass.size());
    }
    // Piecewise linear between the entries, flat before the first and after the last.
    auto at = [&](size_t i) { return std::clamp(es[i].value, 0.0, 1.0); };
    double sum = pass.front() * at(0) + pass.back() * (1.0 - at(es.size() - 1));
    for (size_t i = 0; i + 1 < es.size(); ++i)
        sum += 0.5 * (pass[i] + pass[i + 1]) * std::max(0.0, at(i + 1) - at(i));
    return sum;
}

// One finish for a layered texture: POV-Ray lights each layer with its own and weighs them by
// what the layers above let through; Sheaf takes the finish of the top-most layer that is
// mostly opaque (the bottom one when none is), which carries most of the weight.
const PovFinish& layer_finish(const PovTexture& t) {
    if (t.below.empty() || mean_pass(t.pigment.get()) < 0.5) return t.finish;
    for (auto it = t.below.rbegin(); it != t.below.rend(); ++it)
        if (mean_pass((*it)->pigment.get()) < 0.5) return (*it)->finish;
    return t.below.front()->finish;
}

// Calls visit(layer, above) for a layered texture's layers from the top down, `above` the share
// of light the layers above it let through (their colour maps' transparency averaged), while
// that share is more than `reached`.
template <class Visit> void for_layers(const PovTexture& t, double reached, Visit visit) {
    double above = 1;
    auto one = [&](const PovTexture& l) {
        visit(l, above);
        above *= std::clamp(mean_pass(l.pigment.get()), 0.0, 1.0);
    };
    one(t);
    for (auto it = t.below.rbegin(); it != t.below.rend() && above > reached; ++it) one(**it);
}

} // namespace

bool layers_lit_alike(const PovTexture& t) {
    auto lit = [](const PovFinish& f) {
        PovFinish g = f;
        g.phong = g.phong_size = g.specular = g.roughness = 0; // added layer by layer
        if (!g.reflection_variable) g.reflection = g.reflection_min = {0, 0, 0}; // added
        return g;
    };
    const PovFinish first = lit(layer_finish(t));
    bool alike = true;
    for_layers(t, 1e-3, [&](const PovTexture& l, double) { // layers that some light reaches
        const bool shows = mean_pass(l.pigment.get()) < 1 - 1e-3;
        alike = alike && !(shows && !(lit(l.finish) == first));
    });
    return alike;
}

namespace {

// The reflection of a layered texture. POV-Ray adds the reflection of every layer it reaches
// (it stops below a layer that lets nothing through), each in full: not weighed by its own
// opacity nor by the layers above. Sheaf adds them (their minimum too, where variable), with
// the falloff, Fresnel and metallic of the top-most layer that reflects; layers that differ in
// those are warned (layers_lit_alike).
PovFinish layer_reflection(const PovTexture& t, PovFinish f) {
    const PovFinish* form = nullptr;
    std::array<double, 3> sum{0, 0, 0}, sum_min{0, 0, 0};
    for_layers(t, 1.0 / 255, [&](const PovTexture& l, double) {
        const PovFinish& lf = l.finish;
        if (!(max3(lf.reflection) > 0 || max3(lf.reflection_min) > 0)) return;
        if (!form) form = &lf;
        for (int c = 0; c < 3; ++c) {
            sum[c] += lf.reflection[c];
            sum_min[c] += lf.reflection_variable ? lf.reflection_min[c] : lf.reflection[c];
        }
    });
    if (!form) return f;
    f.reflection = sum;
    f.reflection_variable = form->reflection_variable;
    f.reflection_min = form->reflection_variable ? sum_min : std::array<double, 3>{0, 0, 0};
    f.fresnel = form->fresnel;
    f.reflection_falloff = form->reflection_falloff;
    f.reflection_metallic = form->reflection_metallic;
    return f;
}

// The highlights of a layered texture. POV-Ray adds every layer's phong and specular, weighed
// not by that layer's own opacity (a clear varnish layer shines in full) but by what the
// layers above it let through. Sheaf adds the strengths so weighed, with the size of the
// top-most layer that has each.
struct Highlights {
    double phong = 0, phong_size = 40, specular = 0, roughness = 0.05;
};

Highlights layer_highlights(const PovTexture& t) {
    Highlights h;
    bool phong_sized = false, specular_sized = false;
    for_layers(t, 0, [&](const PovTexture& l, double above) {
        const PovFinish& f = l.finish;
        if (f.phong > 0) {
            h.phong += f.phong * above;
            if (!phong_sized) h.phong_size = f.phong_size, phong_sized = true;
        }
        if (f.specular > 0) {
            h.specular += f.specular * above;
            if (!specular_sized) h.roughness = f.roughness, specular_sized = true;
        }
    });
    return h;
}

} // namespace

Pattern MaterialBuilder::pattern(const PovPattern& pt, const Affine& eff) {
    std::vector<Warp> warps;
    Pattern p = lower_pattern(pt, eff, &warps, p_.model.pattern_defaults());
    if (uv_) { // (u, v, 0) -> the pattern's own space: no world, no mirror
        p.uv = true;
        ++uv_patterns_;
    } else if (!pattern_space_) { // Sheaf world -> POV-Ray world (the z mirror) -> its space
        p.to_pattern = p.to_pattern * pov_to_sheaf();
    }
    if (!chain_.warps.empty() && chain_.uv == p.uv && !pt.bump_map) {
        // In a warped pigment's map: through its chain into its pattern space, then from
        // there into this pattern's (to_pattern relative to the warped pigment's space).
        const bool mirrored = !p.uv && !pattern_space_; // as to_pattern was made above
        const Affine rel =
            mirrored ? p.to_pattern * pov_to_sheaf() * chain_.eff : p.to_pattern * chain_.eff;
        std::vector<Warp> chain = chain_.warps;
        chain.back().to_inner = rel * chain.back().to_inner;
        chain.insert(chain.end(), warps.begin(), warps.end());
        warps = std::move(chain);
        p.to_pattern = chain_.to_pattern;
    }
    p.warp_first = uint32_t(scene_.warps.size());
    p.warp_count = uint32_t(warps.size());
    scene_.warps.insert(scene_.warps.end(), warps.begin(), warps.end());
    if (pt.kind == PatternKind::Function && pt.function) p.program = function(*pt.function);
    if (pt.kind == PatternKind::DensityFile && pt.density) p.grid = density_grid(*pt.density);
    // image_pattern: the image is mapped from this pattern's space (after its warps).
    if (pt.kind == PatternKind::ImagePattern && pt.image)
        p.image = image(*pt.image, Affine(), "data");
    if (pt.kind == PatternKind::PigmentPattern && pt.pigment) {
        // Evaluated at this pattern's point: placed by its own transforms, inheriting nothing.
        const ScopedValue<bool> uv(uv_, false);
        const ScopedValue<bool> space(pattern_space_, true);
        const ScopedValue<WarpChain> chain(chain_, WarpChain{});
        p.pigment = pigment(*pt.pigment, Affine());
    }
    return p;
}

int32_t MaterialBuilder::function_pigment(const PovPigment& pg) {
    // As a pigment_pattern's pigment: at the function's point, placed by its own transforms.
    const ScopedValue<bool> uv(uv_, false);
    const ScopedValue<bool> space(pattern_space_, true);
    const ScopedValue<WarpChain> chain(chain_, WarpChain{});
    return pigment(pg, Affine());
}

Pattern MaterialBuilder::function_pattern(const PovPattern& pt, const Affine& local) {
    const ScopedValue<bool> uv(uv_, false);
    const ScopedValue<bool> space(pattern_space_, true);
    const ScopedValue<WarpChain> chain(chain_, WarpChain{});
    return pattern(pt, local);
}

int32_t MaterialBuilder::normal(const PovNormal& n, const Affine& eff) {
    const ScopedValue<bool> space(uv_, false); // normals are evaluated in space (uv_mapping warned)
    // A map's entries first, placed by its transforms too (the parser left them no maps).
    std::vector<NormalMapEntry> map;
    for (const auto& [value, entry] : n.map)
        map.push_back({float(value), entry ? normal(*entry, eff * n.local) : -1});
    NormalPattern np{pattern(n.pattern, eff * n.local), float(n.amount)};
    np.form = n.form;
    np.delta = float(n.accuracy);
    np.no_bump_scale = n.no_bump_scale;
    if (n.pattern.kind == PatternKind::Image && n.pattern.image)
        np.pattern.image = image(*n.pattern.image, np.pattern.to_pattern, "data");
    np.average = n.average;
    np.map_first = uint32_t(scene_.normal_map_entries.size());
    np.map_count = uint32_t(map.size());
    scene_.normal_map_entries.insert(scene_.normal_map_entries.end(), map.begin(), map.end());
    np.slope_first = uint32_t(scene_.slope_entries.size());
    np.slope_count = uint32_t(n.slope_map.size());
    for (const auto& e : n.slope_map)
        scene_.slope_entries.push_back({float(e[0]), float(e[1]), float(e[2])});
    scene_.normal_patterns.push_back(np);
    return int32_t(scene_.normal_patterns.size() - 1);
}

int32_t MaterialBuilder::function(const PovFunction& f) {
    try {
        return functions_.program(f);
    } catch (const FnCompileError& e) {
        p_.error_at(f.where, e.what());
    }
}

Pattern lower_pattern(const PovPattern& pt, const Affine& eff, std::vector<Warp>* warps,
                      const PatternDefaults& scene) {
    Pattern p;
    p.kind = pt.kind;
    p.noise_generator = uint8_t(pt.noise_generator ? pt.noise_generator : scene.noise_generator);
    p.waves = uint16_t(scene.waves);
    p.wave = pt.wave;
    p.octaves = int8_t(std::clamp(pt.octaves, 1, 10));
    p.has_turbulence = pt.has_turbulence;
    p.turbulence = pt.turbulence;
    p.omega = float(pt.omega), p.lambda = float(pt.lambda);
    p.frequency = float(pt.frequency), p.phase = float(pt.phase);
    p.wave_exponent = float(pt.wave_exponent);
    p.vector = pt.vector;
    for (int i = 0; i < 4; ++i) p.param[i] = float(pt.param[i]);
    p.fractal = pt.fractal;
    if (pt.kind == PatternKind::Slope) { // the direction in Sheaf's world; checked when read
        const Affine flip = pov_to_sheaf();
        set_slope(p, pt.slope_point_at ? flip.point(pt.vector) : flip.vector(pt.vector),
                  float(pt.param[0]), float(pt.param[1]), pt.slope_altitude, float(pt.param[2]),
                  float(pt.param[3]), pt.slope_point_at);
    }
    const auto inverse = [](const Affine& a) {
        return std::fabs(a.determinant()) > 1e-30f ? a.inverse() : Affine();
    };
    const size_t n = warps ? pt.warps.size() : 0;
    if (n == 0) {
        p.to_pattern = inverse(eff);
        return p;
    }
    // POV-Ray's chain: the world into the last warp's space (the transforms after it undone),
    // each warp, then back through the transforms declared before it, down to the first.
    p.to_pattern = pt.warps[n - 1].at * inverse(eff);
    p.warp_first = uint32_t(warps->size());
    p.warp_count = uint32_t(n);
    for (size_t i = n; i-- > 0;) {
        Warp w = pt.warps[i].warp;
        w.to_inner = i > 0 ? pt.warps[i - 1].at * inverse(pt.warps[i].at) : inverse(pt.warps[i].at);
        warps->push_back(w);
    }
    return p;
}

int32_t MaterialBuilder::density_grid(const PovDensity& d) {
    auto [it, added] = voxels_.emplace(d.values.get(), uint32_t(scene_.density_voxels.size()));
    if (added)
        scene_.density_voxels.insert(scene_.density_voxels.end(), d.values->begin(),
                                     d.values->end());
    DensityGrid g;
    g.first = it->second;
    g.nx = d.nx, g.ny = d.ny, g.nz = d.nz;
    g.interpolation = uint32_t(d.interpolation);
    scene_.density_grids.push_back(g);
    return int32_t(scene_.density_grids.size() - 1);
}

int32_t MaterialBuilder::image(const PovImage& img, const Affine& to_pattern,
                               const std::string& colorspace) {
    std::ostringstream k;
    k.precision(9);
    k << img.path << '|' << img.map_type << img.once << colorspace;
    for (auto& row : to_pattern.m)
        for (float v : row) k << ',' << v;
    if (auto it = images_.find(k.str()); it != images_.end()) return it->second;
    Texture t;
    t.path = img.path;
    // A uv-mapped image is read at (u, v, 0) (Pattern::uv), planar like any other.
    t.mapping = img.map_type == 1   ? TextureMapping::Spherical
                : img.map_type == 2 ? TextureMapping::Cylindrical
                : img.map_type == 5 ? TextureMapping::Torus
                                    : TextureMapping::Planar;
    t.transform = to_pattern;
    if (t.mapping != TextureMapping::Planar) {
        // POV-Ray's longitude starts at +x and turns toward +z; the core's starts at -z and
        // turns toward +x: (x, y, z) -> (-z, y, -x) takes one to the other.
        Affine swap;
        swap.m[0][0] = swap.m[2][2] = 0;
        swap.m[0][2] = swap.m[2][0] = -1;
        t.transform = swap * to_pattern;
    }
    t.once = img.once;
    t.colorspace = colorspace;
    t.origin = p_.where(img.where);
    scene_.textures.push_back(t);
    const int32_t id = int32_t(scene_.textures.size() - 1);
    images_.emplace(k.str(), id);
    return id;
}

PigmentEntry MaterialBuilder::entry(const PovMapEntry& e, const Affine& eff) {
    PigmentEntry out;
    out.value = float(e.value);
    const Color5& c = e.pigment ? e.pigment->color : e.color;
    for (int i = 0; i < 5; ++i) out.color[i] = float(c[i]);
    if (e.pigment && e.pigment->patterned) out.pigment = pigment(*e.pigment, eff);
    return out;
}

int32_t MaterialBuilder::pigment(const PovPigment& pg, const Affine& outer) {
    // A uv-mapped pigment is placed by its own transforms only.
    const Affine eff = pg.uv ? pg.local : outer * pg.local;
    const ScopedValue<bool> uv(uv_, uv_ || pg.uv);
    Pigment out;
    if (!pg.patterned) {
        for (int i = 0; i < 5; ++i) out.color[i] = float(pg.color[i]);
        scene_.pigments.push_back(out);
        return int32_t(scene_.pigments.size() - 1);
    }
    out.solid = false;
    out.average = pg.average;
    out.pattern = pattern(pg.pattern, eff);
    // Entries before the pigment itself: a pigment names only earlier pigments. They are
    // evaluated through this pigment's warps and its classic turbulence (the last stage of
    // POV-Ray's warp list, which marble and wood keep to themselves), as POV-Ray does.
    std::vector<PigmentEntry> entries;
    {
        const Pattern& pp = out.pattern;
        const auto first = scene_.warps.begin() + pp.warp_first;
        std::vector<Warp> warps(first, first + pp.warp_count);
        if (pp.has_turbulence && !bends_by_own_turbulence(pp.kind)) {
            Warp turb;
            turb.kind = WarpKind::Turbulence;
            turb.a = pp.turbulence;
            turb.octaves = pp.octaves;
            turb.f[0] = pp.omega, turb.f[1] = pp.lambda;
            warps.push_back(turb);
        }
        const ScopedValue<WarpChain> chain(
            chain_, warps.empty() ? chain_ : WarpChain{pp.to_pattern, warps, eff, pp.uv});
        entries.reserve(pg.entries.size());
        for (const PovMapEntry& e : pg.entries) entries.push_back(entry(e, eff));
    }
    if (pg.pattern.kind == PatternKind::Image && pg.pattern.image)
        out.pattern.image = image(*pg.pattern.image, Affine()); // from the pattern's space
    out.first = uint32_t(scene_.pigment_entries.size());
    out.count = uint32_t(entries.size());
    scene_.pigment_entries.insert(scene_.pigment_entries.end(), entries.begin(), entries.end());
    scene_.pigments.push_back(out);
    return int32_t(scene_.pigments.size() - 1);
}

uint32_t MaterialBuilder::material(const PovTexture& t, const PovInterior* in,
                                   const PovTexture* inside) {
    const size_t uv_before = uv_patterns_;
    const uint32_t front = material_in(t, in, Affine(), 0);
    uint32_t out = front;
    if (inside) {
        // The same interior behind both faces: the inside material differs in its texture only.
        const int32_t back = int32_t(material_in(*inside, in, Affine(), 0));
        auto [it, added] = insides_.emplace(std::make_pair(front, back), 0);
        if (added) {
            Material m = scene_.materials[front]; // a copy: plain materials are shared
            m.inside = back;
            it->second = scene_.add_material(m);
        }
        out = it->second;
    }
    if (uv_patterns_ > uv_before || uses_uv(front)) uv_materials_.insert(out);
    return out;
}

uint32_t MaterialBuilder::material_in(const PovTexture& t, const PovInterior* in,
                                      const Affine& outer, int depth) {
    // A uv-mapped texture's patterns are placed by its own transforms only (what holds it
    // does not move them); its normal and media stay in space, placed as usual.
    const Affine space = outer * t.local;
    const Affine eff = t.uv ? t.uv_local : space;
    const ScopedValue<bool> uv(uv_, uv_ || t.uv);
    if (t.is_map && !t.map_entries.empty()) {
        if (depth >= kMaxDepth) return material_in(*t.map_entries.front().second, in, space, depth);
        std::vector<MaterialEntry> entries;
        for (const auto& [value, sub] : t.map_entries)
            entries.push_back({float(value), material_in(*sub, in, space, depth + 1)});
        MaterialSwitch sw;
        sw.pattern = pattern(t.map_pattern, eff);
        sw.first = uint32_t(scene_.material_entries.size());
        sw.count = uint32_t(entries.size());
        scene_.material_entries.insert(scene_.material_entries.end(), entries.begin(),
                                       entries.end());
        scene_.material_switches.push_back(sw);
        Material m;
        m.select = int32_t(scene_.material_switches.size() - 1);
        return scene_.add_material(m);
    }

    const PovFinish f = t.below.empty() ? t.finish : layer_reflection(t, layer_finish(t));
    Material m;
    m.fresnel_split = false; // POV-Ray: reflection comes from the finish only
    const auto& al = p_.model.ambient_light;
    m.ambient =
        float((f.ambient[0] + f.ambient[1] + f.ambient[2]) / 3 * (al[0] + al[1] + al[2]) / 3);
    // With radiosity, POV-Ray 3.7 drops the classic ambient term: the gathered light takes its
    // place (older #versions keep both).
    if (p_.model.radiosity && p_.model.version >= 3.695) m.ambient = 0;
    m.diffuse = float(f.diffuse);
    m.brilliance = float(f.brilliance);
    Highlights h{f.phong, f.phong_size, f.specular, f.roughness};
    if (!t.below.empty()) h = layer_highlights(t);
    if (h.phong > 0) {
        m.specular = float(h.phong);
        m.phong_exponent = float(std::max(1.0, h.phong_size));
    }
    if (h.specular > 0) {
        m.blinn = float(h.specular);
        m.blinn_exponent = float(std::clamp(1.0 / std::max(h.roughness, 1e-4), 1.0, 10000.0));
    }
    m.metallic = float(std::clamp(f.metallic, 0.0, 1.0));
    const double rmax = max3(f.reflection);
    m.mirror = float(std::clamp(rmax, 0.0, 1.0));
    if (rmax > 0)
        m.mirror_color = Vec3(float(f.reflection[0] / rmax), float(f.reflection[1] / rmax),
                              float(f.reflection[2] / rmax));
    if (f.reflection_variable) {
        m.mirror_min = float(std::clamp(max3(f.reflection_min), 0.0, 1.0));
        m.mirror_falloff = float(std::max(f.reflection_falloff, 0.0));
        m.mirror_fresnel = f.fresnel;
    }
    m.mirror_metallic = f.reflection_metallic;
    m.conserve_energy = f.conserve_energy;
    // POV-Ray's conserve_energy takes what the mirror reflects from what passes through only
    // (its filter colour); the diffuse stays (objects/mesh2.pov's floor).
    m.conserve_diffuse = false;
    if (f.irid > 0) {
        m.irid = float(f.irid);
        m.irid_thickness = float(f.irid_thickness);
        m.irid_turbulence = float(f.irid_turbulence);
        const auto& wl = p_.model.irid_wavelength;
        m.irid_wavelength = Vec3(float(wl[0]), float(wl[1]), float(wl[2]));
    }
    if (in) {
        m.ior = float(in->ior > 0 ? in->ior : 1.0);
        m.fade_distance = float(std::max(in->fade_distance, 0.0));
        m.fade_power = float(std::max(in->fade_power, 0.0));
        // POV-Ray keeps 45 times the value written as the exponent of the caustic gain.
        m.caustics = float(std::max(in->caustics, 0.0) * 45.0);
        m.fade_color =
            Vec3(float(in->fade_color[0]), float(in->fade_color[1]), float(in->fade_color[2]));
        add_media(m, in->media, outer * in->local);
    } else {
        m.ior = 1.0f;
    }

    // The pigment: layers (bottom first, this texture on top), a pattern, or a solid colour.
    const PovPigment black;
    const PovPigment& top = t.pigment ? *t.pigment : black;
    const bool layered = !t.below.empty();
    Color5 base_color = top.color;
    if (layered) {
        std::vector<PigmentEntry> layers;
        for (const PovTextureRef& l : t.below) {
            const PovPigment& lp = l->pigment ? *l->pigment : black;
            const ScopedValue<bool> layer_uv(uv_, l->uv);
            layers.push_back(entry({0, lp.color, std::make_shared<PovPigment>(lp)},
                                   l->uv ? l->uv_local : outer * l->local));
        }
        layers.push_back(entry({0, top.color, std::make_shared<PovPigment>(top)}, eff));
        m.pigment = layer_pigment(layers);
        // The normal of the top-most layer that has one.
        const PovNormal* n = t.normal.get();
        Affine n_eff = space;
        for (auto it = t.below.rbegin(); !n && it != t.below.rend(); ++it)
            if ((*it)->normal) n = (*it)->normal.get(), n_eff = outer * (*it)->local;
        if (n) m.normal = normal(*n, n_eff);
    } else {
        if (top.patterned) {
            m.pigment = pigment(top, eff);
        } else {
            m.color = rgb(top.color);
            m.transmission = float(std::clamp(top.color[3], 0.0, 1.0));
            if (top.color[4] > 0) m.pigment = pigment(top, eff); // transmit needs a pigment
        }
        if (t.normal) m.normal = normal(*t.normal, space);
    }
    // Emission scales the surface colour; patterned surfaces glow with their mean colour.
    Vec3 mean = rgb(base_color);
    if (top.patterned && !top.entries.empty()) {
        mean = Vec3(0.0f);
        for (const PovMapEntry& e : top.entries)
            mean += rgb(e.pigment ? e.pigment->color : e.color);
        mean = mean / float(top.entries.size());
    }
    m.emission = mean * Vec3(float(f.emission[0]), float(f.emission[1]), float(f.emission[2]));

    // Plain materials are shared (media are placed with their object: never shared).
    if (m.pigment < 0 && m.normal < 0 && m.media_count == 0) {
        const std::string key = key_of(m);
        if (auto it = plain_.find(key); it != plain_.end()) return it->second;
        const uint32_t id = scene_.add_material(m);
        plain_.emplace(key, id);
        return id;
    }
    return scene_.add_material(m);
}

void MaterialBuilder::add_media(Material& m, const std::vector<PovMedia>& media,
                                const Affine& space) {
    m.media_first = uint32_t(scene_.media.size());
    for (const PovMedia& pm : media) {
        Medium md;
        md.emission = Vec3(float(pm.emission[0]), float(pm.emission[1]), float(pm.emission[2]));
        md.absorption =
            Vec3(float(pm.absorption[0]), float(pm.absorption[1]), float(pm.absorption[2]));
        md.scattering =
            Vec3(float(pm.scattering[0]), float(pm.scattering[1]), float(pm.scattering[2]));
        md.scatter_type = ScatterType(pm.scatter_type);
        md.eccentricity = float(pm.eccentricity);
        md.extinction = float(pm.extinction);
        md.samples = uint32_t(pm.samples);
        md.light_samples = uint32_t(pm.light_samples);
        std::vector<uint32_t> densities;
        const ScopedValue<bool> space_densities(uv_, false); // a medium has no surface
        for (const auto& d : pm.densities)
            densities.push_back(uint32_t(pigment(*d, space * pm.local)));
        md.density_first = uint32_t(scene_.medium_densities.size());
        md.density_count = uint32_t(densities.size());
        scene_.medium_densities.insert(scene_.medium_densities.end(), densities.begin(),
                                       densities.end());
        scene_.media.push_back(md);
    }
    m.media_count = uint32_t(media.size());
}

uint32_t MaterialBuilder::atmosphere(const std::vector<PovMedia>& media) {
    Material m;
    m.ior = 1.0f;
    add_media(m, media, Affine());
    return scene_.add_material(m);
}

int32_t MaterialBuilder::sky(const std::vector<std::shared_ptr<const PovPigment>>& layers,
                             const Affine& local) {
    if (layers.empty()) return -1;
    if (layers.size() == 1) return pigment(*layers[0], local);
    std::vector<PigmentEntry> entries;
    for (const auto& l : layers) entries.push_back(entry({0, l->color, l}, local));
    return layer_pigment(entries);
}

int32_t MaterialBuilder::layer_pigment(const std::vector<PigmentEntry>& layers) {
    Pigment lp;
    lp.solid = false;
    lp.layers = true;
    lp.first = uint32_t(scene_.pigment_entries.size());
    lp.count = uint32_t(layers.size());
    scene_.pigment_entries.insert(scene_.pigment_entries.end(), layers.begin(), layers.end());
    scene_.pigments.push_back(lp);
    return int32_t(scene_.pigments.size() - 1);
}

} // namespace sheaf::io::pov
