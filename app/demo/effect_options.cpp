#include "demo/effect_options.hpp"

#include "demo/option_values.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>

namespace demo {
namespace {

constexpr float kMaxDepthM = 1000.0f; // --slit, --pivot (as nonaffine-report)

std::string got(const std::string& value) { return ", got '" + value + "'"; }

// A value naming one of an enum's values (`parse`, its name table) into
// `field`; else the usage error "unknown <what> 'x' (expected <choices>)".
template <class Value, class Parse>
std::optional<Failure> apply_name(Value& field, const std::string& value, const Parse& parse, const char* what,
                                  const char* choices) {
    const std::optional<Value> parsed = parse(value);
    if (!parsed) {
        return usage(std::string("unknown ") + what + " '" + value + "' (expected " + choices + ")");
    }
    field = *parsed;
    return std::nullopt;
}

std::optional<Failure> apply_tiles(plan::EffectParams& s, const std::string& value) {
    const auto tiles = parse_pair(value, kMaxTileSide);
    if (!tiles) {
        return usage("--tiles must be NxM (columns x rows, each >= 1)" + got(value));
    }
    std::tie(s.tile_columns, s.tile_rows) = *tiles;
    return std::nullopt;
}

std::optional<Failure> apply_tile_borders(plan::EffectParams& s, const std::string&) {
    s.tile_borders = true;
    return std::nullopt;
}

std::optional<Failure> apply_mirror(plan::EffectParams& s, const std::string& value) {
    return apply_name(s.mirror_method, value, plan::parse_mirror_method, "mirror method",
                      "oblique, rectangle or reflect_only");
}

std::optional<Failure> apply_mirror_plane(plan::EffectParams& s, const std::string& value) {
    const auto v = parse_numbers(value, 4);
    if (!v || glm::length(glm::vec3((*v)[0], (*v)[1], (*v)[2])) < 1e-6f) {
        return usage("--mirror-plane must be a,b,c,d (the plane a x + b y + c z + d = 0, finite numbers, "
                     "(a, b, c) not zero)" + got(value));
    }
    s.mirror_place.plane = glm::vec4((*v)[0], (*v)[1], (*v)[2], (*v)[3]);
    return std::nullopt;
}

std::optional<Failure> apply_mirror_rect(plan::EffectParams& s, const std::string& value) {
    const auto v = parse_numbers(value, 9);
    if (!v || glm::length(glm::cross(glm::vec3((*v)[3], (*v)[4], (*v)[5]), glm::vec3((*v)[6], (*v)[7], (*v)[8]))) <
                  1e-9f) {
        return usage("--mirror-rect must be cx,cy,cz,ax,ay,az,bx,by,bz (centre and two sides, finite numbers, "
                     "the sides neither zero nor parallel)" + got(value));
    }
    std::array<float, 9> rect{};
    std::copy(v->begin(), v->end(), rect.begin());
    s.mirror_place.rect = rect;
    return std::nullopt;
}

std::optional<Failure> apply_patches(plan::EffectParams& s, const std::string& value) {
    const auto patches = parse_count(value, plan::kMaxCurvedPatches);
    if (!patches) {
        return usage("--patches must be a whole number in 1.." + std::to_string(plan::kMaxCurvedPatches) +
                     got(value));
    }
    s.curved.patches = *patches;
    return std::nullopt;
}

std::optional<Failure> apply_sagitta(plan::EffectParams& s, const std::string& value) {
    const auto sagitta_m = parse_number(value);
    if (!sagitta_m || !(*sagitta_m >= 0.0f)) {
        return usage("--sagitta must be a length in metres >= 0" + got(value));
    }
    s.curved.sagitta_m = *sagitta_m;
    s.sagitta_given = true;
    return std::nullopt;
}

std::optional<Failure> apply_cap(plan::EffectParams& s, const std::string& value) {
    return apply_name(s.curved.shape, value, plan::parse_cap_shape, "cap shape", "sphere or cylinder");
}

std::optional<Failure> apply_lens_grid(plan::EffectParams& s, const std::string& value) {
    const auto grid = parse_count(value, kMaxLensGrid);
    if (!grid) {
        return usage("--lens-grid must be a whole number in 1.." + std::to_string(kMaxLensGrid) + got(value));
    }
    s.lens_grid = *grid;
    return std::nullopt;
}

std::optional<Failure> apply_lens_power(plan::EffectParams& s, const std::string& value) {
    const auto power = parse_number(value);
    if (!power || !(*power > 0.0f && *power <= kMaxLensPower)) {
        return usage("--lens-power must be a number in (0, 2]" + got(value));
    }
    s.lens_power = *power;
    return std::nullopt;
}

std::optional<Failure> apply_lens_center(plan::EffectParams& s, const std::string& value) {
    const auto v = parse_numbers(value, 2);
    if (!v || std::abs((*v)[0]) > 1.0f || std::abs((*v)[1]) > 1.0f) {
        return usage("--lens-center must be x,y with each in [-1, 1] (0,0 is the frame's centre, 1,1 its top "
                     "right corner)" + got(value));
    }
    s.fit.lens_center = glm::vec2((*v)[0], (*v)[1]);
    return std::nullopt;
}

std::optional<Failure> apply_lens_radius(plan::EffectParams& s, const std::string& value) {
    const auto radius = parse_number(value);
    if (!radius || !(*radius > 0.0f && *radius <= 1.0f)) {
        return usage("--lens-radius must be a fraction of the frame's half height in (0, 1]" + got(value));
    }
    s.fit.lens_radius = *radius;
    return std::nullopt;
}

std::optional<Failure> apply_depth(std::optional<float>& slot, const char* name, const std::string& value) {
    const auto depth_m = parse_number(value);
    if (!depth_m || !(*depth_m > 0.0f && *depth_m <= kMaxDepthM)) {
        return usage(std::string(name) + " must be a depth in (0, 1000] metres" + got(value));
    }
    slot = *depth_m;
    return std::nullopt;
}

std::optional<Failure> apply_slit(plan::EffectParams& s, const std::string& value) {
    return apply_depth(s.fit.slit_m, "--slit", value);
}

std::optional<Failure> apply_pivot(plan::EffectParams& s, const std::string& value) {
    return apply_depth(s.fit.pivot_m, "--pivot", value);
}

// Fog (render/fog_pass.hpp): depth decoded with each pass's own pair.

std::optional<Failure> apply_fog(plan::EffectParams& s, const std::string&) {
    if (!s.fog) {
        s.fog = plan::FogOptions{};
    }
    return std::nullopt;
}

std::optional<Failure> apply_fog_density(plan::EffectParams& s, const std::string& value) {
    const auto density = parse_number(value);
    if (!density || !(*density > 0.0f && *density <= 1000.0f)) {
        return usage("--fog-density must be a number in (0, 1000] per metre" + got(value));
    }
    apply_fog(s, value);
    s.fog->density_per_m = *density;
    return std::nullopt;
}

std::optional<Failure> apply_fog_color(plan::EffectParams& s, const std::string& value) {
    const auto v = parse_numbers(value, 3);
    if (!v || std::any_of(v->begin(), v->end(), [](float c) { return !(c >= 0.0f && c <= 1.0f); })) {
        return usage("--fog-color must be r,g,b with each in [0, 1] (sRGB-encoded)" + got(value));
    }
    apply_fog(s, value);
    s.fog->color = glm::vec3((*v)[0], (*v)[1], (*v)[2]);
    return std::nullopt;
}


// Stereo (--stereo, --ipd-m, --convergence-m).

constexpr float kMaxIpdM = 10.0f;

std::optional<Failure> apply_stereo(plan::EffectParams& s, const std::string&) {
    s.stereo = true;
    return std::nullopt;
}

std::optional<Failure> apply_ipd(plan::EffectParams& s, const std::string& value) {
    const auto ipd_m = parse_number(value);
    if (!ipd_m || !(*ipd_m >= 0.0f && *ipd_m <= kMaxIpdM)) {
        return usage("--ipd-m must be a distance in [0, 10] metres" + got(value));
    }
    s.ipd_m = *ipd_m;
    return std::nullopt;
}

std::optional<Failure> apply_convergence(plan::EffectParams& s, const std::string& value) {
    return apply_depth(s.convergence_m, "--convergence-m", value);
}


// The portal and recursion effects (docs/portals.md).

std::optional<Failure> apply_recursion_depth(plan::EffectParams& s, const std::string& value) {
    const auto depth = value == "0" ? std::optional<int>(0) : parse_count(value, plan::kMaxRecursionDepth);
    if (!depth) {
        return usage("--recursion-depth must be a whole number in 0.." + std::to_string(plan::kMaxRecursionDepth) +
                     got(value));
    }
    s.recursion_depth = *depth;
    return std::nullopt;
}

std::optional<Failure> apply_recursion_links(plan::EffectParams& s, const std::string& value) {
    return apply_name(s.recursion_links, value, plan::parse_link_set, "recursion links", "mirrors or portals");
}


} // namespace

const std::vector<EffectOption>& effect_options() {
    static const std::vector<EffectOption> table = {
        {"--tiles", "NxM", "tiles effect: columns x rows, each >= 1 and at most one per pixel (default 3x2)",
         apply_tiles, kRender | kWindow, "4x3", slider(1, kMaxTileSide, true, true, 2, 'x')},
        {"--tile-borders", nullptr, "tiles effect: draw each tile's border", apply_tile_borders},
        {"--mirror", "M",
         "reflection camera: oblique (reflect + oblique near plane, default) |\n"
         "rectangle (reflected eye through the mirror) | reflect_only (no near\n"
         "plane: shows what is behind the mirror)",
         apply_mirror, kRender | kWindow, "rectangle", choice("oblique|rectangle|reflect_only")},
        {"--mirror-plane", "a,b,c,d",
         "a mirror on the plane a x + b y + c z + d = 0, reflecting towards\n"
         "(a, b, c): a square of the model's diagonal under the model's centre\n"
         "(default: the scene's node \"mirror\", else a floor under the model)",
         apply_mirror_plane, kRender | kWindow, "0,1,0,0"},
        {"--mirror-rect", "c,a,b",
         "a mirror rectangle: nine numbers cx,cy,cz,ax,ay,az,bx,by,bz, its centre\n"
         "and two sides; reflects towards a x b",
         apply_mirror_rect, kRender | kWindow, "0,0,0,1,0,0,0,1,0"},
        {"--patches", "N", "curved effect: the convex cap in G x G patches, 1..64 (default 4)", apply_patches, kRender | kWindow, "8",
         slider(1, plan::kMaxCurvedPatches, true)},
        {"--sagitta", "M",
         "curved effect: the cap's bulge at its centre in metres (default a fifth\n"
         "of the mirror's half-diagonal; 0 = the planar mirror; at most half of it)",
         apply_sagitta, kRender | kWindow | kCurvedReport, "0.1", slider(0.0f, 10.0f, false, true)},
        {"--cap", "C", "curved effect: sphere (default) | cylinder (axis along the mirror's\nsecond side)",
         apply_cap, kRender | kWindow | kCurvedReport, "cylinder", choice("sphere|cylinder")},
        {"--lens-grid", "N", "lens effect: N x N tiles, 1..128 (default 16, at most one per pixel)",
         apply_lens_grid, kRender | kWindow, "8", slider(1, kMaxLensGrid, true)},
        {"--lens-power", "P", "lens effect: p of eq. 34, in (0, 2] (default 2; 1 = no lens; stronger powers make tiles degenerate in single precision)", apply_lens_power, kRender | kWindow | kLensReport, "1.5",
         slider(0.0f, kMaxLensPower)},
        {"--lens-center", "x,y",
         "lens effect: the lens centre in the frame, each in [-1, 1] (default:\n"
         "the scene's lens node, else the model's centre as seen)",
         apply_lens_center, kRender | kWindow, "0.1,-0.2", slider(-1.0f, 1.0f, false, false, 2)},
        {"--lens-radius", "R",
         "lens effect: the lens radius as a fraction of the frame's half height,\n"
         "(0, 1] (default: the lens node's, else half the model's as seen,\n"
         "within 0.1..0.4)",
         apply_lens_radius, kRender | kWindow, "0.3", slider(0.0f, 1.0f)},
        {"--slit", "M",
         "nonaffine effect: the slit's depth in front of the eye, (0, 1000] m,\n"
         "below --pivot (default a third of the pivot)",
         apply_slit, kRender | kWindow, "2", slider(0.0f, kMaxDepthM, false, true)},
        {"--pivot", "M",
         "nonaffine effect: where the slit planes meet the camera's side planes,\n"
         "(0, 1000] m, below the far distance (default: the model centre's depth)",
         apply_pivot, kRender | kWindow, "5", slider(0.0f, kMaxDepthM, false, true)},
        // Fog (render/fog_pass.hpp).
        {"--fog", nullptr,
         "plain and mirror effects: distance fog from the depth buffer, the\n"
         "reflection decoded with its own oblique pair (default: the sky's\n"
         "colour, half fog one scene diagonal away)",
         apply_fog},
        {"--fog-density", "D", "fog per metre, (0, 1000] (implies --fog; default ln 2 / the scene's diagonal)",
         apply_fog_density, kRender | kWindow, "0.05", slider(0.0f, 1000.0f, false, true)},
        {"--fog-color", "r,g,b", "the fog's sRGB colour, each in [0, 1] (implies --fog; default the sky)",
         apply_fog_color, kRender | kWindow, "0.5,0.6,0.7", slider(0.0f, 1.0f, false, false, 3)},
        // Stereo.
        {"--stereo", nullptr,
         "left and right eyes side by side, each its own camera pair, with its\n"
         "own mirror reflection, lens and tiles (each eye half the width)",
         apply_stereo},
        {"--ipd-m", "M", "stereo: interpupillary distance, [0, 10] m (default 0.064)", apply_ipd, kRender | kWindow,
         "0.1", slider(0.0f, kMaxIpdM, false, true)},
        {"--convergence-m", "M",
         "stereo: depth of the zero-disparity plane, (0, 1000] m beyond the near\n"
         "plane (default: the mirror's centre, else the model's centre)",
         apply_convergence, kRender | kWindow, "4", slider(0.0f, kMaxDepthM, false, true)},
        // The portal and recursion effects (docs/portals.md).
        {"--recursion-depth", "N",
         "recursion effect: links passed through, 0..8 (default 4; 0 = the plain\n"
         "frame with the mirrors' or portal's own colours)",
         apply_recursion_depth, kRender | kWindow, "2", slider(0, plan::kMaxRecursionDepth, true)},
        {"--recursion-links", "L",
         "recursion effect: mirrors (two facing mirrors beside the model, default)\n"
         "| portals (a portal whose exit faces its entry)",
         apply_recursion_links, kRender | kWindow, "portals", choice("mirrors|portals")},
    };
    return table;
}

const EffectOption* find_effect_option(std::string_view name) {
    for (const EffectOption& option : effect_options()) {
        if (name == option.name) {
            return &option;
        }
    }
    return nullptr;
}

std::optional<Failure> check_effect_settings(const plan::EffectParams& settings) {
    if (settings.mirror_place.plane && settings.mirror_place.rect) {
        return usage("--mirror-plane and --mirror-rect both place the mirror; give one of them");
    }
    const long long tiles = static_cast<long long>(settings.tile_columns) * settings.tile_rows;
    if (tiles > kMaxTiles) {
        return usage("--tiles " + std::to_string(settings.tile_columns) + "x" + std::to_string(settings.tile_rows) +
                     " is " + std::to_string(tiles) + " tiles, over the limit of " + std::to_string(kMaxTiles));
    }
    return std::nullopt;
}

} // namespace demo
