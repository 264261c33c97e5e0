// The effect options `render` and `window` share, as one table: each row is
// a name, its value's shape, its help line and the function that applies
// it, so both parsers accept the same names with the same bounds and the
// same messages, and both help texts list the same lines.
#pragma once

#include "demo/failure.hpp"

#include <render/curved_mirror.hpp>
#include <render/effect.hpp>
#include <render/mirror_placement.hpp>
#include <render/scene_fit.hpp>
#include <render/view_links.hpp>
#include <render/view_tree.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace demo {

// --lens-grid N (1..kMaxLensGrid) and --lens-power P (0 < P <= kMaxLensPower):
// the bounds where every tile of eq. 34 stays a valid frustum in single
// precision (measured on the showcase at 64x64 .. 2048x512: power 3 breaks
// at grid 128, power 2 at grid 256, power 5 already at grid 16).
inline constexpr int kMaxLensGrid = 128;
inline constexpr float kMaxLensPower = 2.0f;
inline constexpr int kMaxTileSide = 8192;

// What the effect options set (RenderRequest and WindowRequest are these
// plus their own options). Unset parameters are derived from the scene
// (render/scene_fit.hpp, render/mirror_placement.hpp, docs/any-scene.md).
struct EffectSettings {
    int tile_columns = 3, tile_rows = 2; // --tiles
    bool tile_borders = false;           // --tile-borders
    render::MirrorMethod mirror = render::MirrorMethod::Oblique; // --mirror
    render::MirrorRequest mirror_place;  // --mirror-plane, --mirror-rect
    render::CurvedMirrorOptions curved;  // --patches, --sagitta, --cap
    bool sagitta_given = false;          // else fit_sagitta_m() of the mirror
    int lens_grid = 16;                  // --lens-grid
    float lens_power = 2.0f;             // --lens-power: p of eq. 34
    render::EffectFit fit;               // --slit, --pivot, --lens-center, --lens-radius
    int recursion_depth = 4;             // --recursion-depth
    render::LinkSet recursion_links = render::LinkSet::Mirrors; // --recursion-links
};

struct EffectOption {
    const char* name;  // "--slit"
    const char* value; // "M" for the help line; nullptr: a flag without a value
    const char* help;  // what follows the name in --help (may hold '\n' + indent for more lines)
    // Applies the value; a usage Failure naming the value when it is out of range.
    std::optional<Failure> (*apply)(EffectSettings& settings, const std::string& value);
};

const std::vector<EffectOption>& effect_options();

// The row named `name`; nullptr for any other name.
const EffectOption* find_effect_option(std::string_view name);

// The rows as --help lines, "  --slit M           ...".
std::string effect_options_help();

// Checks that need several options together (e.g. --mirror-plane and
// --mirror-rect are exclusive).
std::optional<Failure> check_effect_settings(const EffectSettings& settings);

} // namespace demo
