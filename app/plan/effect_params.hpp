// Every effect value and its default, once. frustum-demo's effect option
// rows (demo/effect_options.hpp) write into it; render, the window's viewer
// state, the reports and the web page hold one; the renderer's options
// (render::RenderOptions) are one plus what a frame adds (size, depth path,
// MSAA, tint, lighting). Values left unset are derived from the scene by
// resolve_effects(), the same way for every command. Pure data: no GL.
#pragma once

#include "plan/curved_mirror.hpp"
#include "plan/effect.hpp"
#include "plan/fog_options.hpp"
#include "plan/mirror_placement.hpp"
#include "plan/scene_fit.hpp"
#include "plan/stereo.hpp"
#include "plan/view_links.hpp"

#include <frustum/result.hpp>
#include <scene/scene.hpp>

#include <optional>
#include <string>

namespace plan {

struct EffectParams {
    int tile_columns = 3, tile_rows = 2;                // --tiles: the tiles effect's crop grid (§5.1)
    bool tile_borders = false;                          // --tile-borders
    MirrorMethod mirror_method = MirrorMethod::Oblique; // --mirror: mirror and frustum effects
    MirrorRequest mirror_place;                         // --mirror-plane, --mirror-rect; unset: the scene's or a floor
    CurvedMirrorOptions curved;                         // --patches, --sagitta, --cap
    bool sagitta_given = false;                         // else fit_sagitta_m() of the mirror
    int lens_grid = 16;                                 // --lens-grid: lens_grid x lens_grid tiles (§5.4)
    float lens_power = 2.0f;                            // --lens-power: p of eq. 34 (> 1 magnifies)
    EffectFit fit;                                      // --slit, --pivot, --lens-center, --lens-radius
    std::optional<FogOptions> fog;                      // --fog, --fog-density, --fog-color; unset: none
    bool stereo = false;                                // --stereo: side-by-side eyes, each its own pair
    float ipd_m = kDefaultIpdM;                         // --ipd-m
    std::optional<float> convergence_m;                 // --convergence-m; unset: default_convergence_m()
    int recursion_depth = 4;                            // --recursion-depth: links passed through, 0..8
    LinkSet recursion_links = LinkSet::Mirrors;         // --recursion-links
};

// What resolve_effects() derived for a scene and a frame size.
struct ResolvedEffects {
    EffectParams params;               // the sagitta fitted when it was not given
    std::optional<std::string> placed; // where the mirror went ("mirror: floor under the model, ..."); empty: the scene's
    // An explicit value that cannot work for this scene, as the usage error
    // naming it (an explicit --sagitta above what the mirror allows): render
    // refuses the run, the window the curved effect.
    std::optional<std::string> refused;
};

// Gives `scene` the mirror params.mirror_place asks for (a floor when the
// scene has none) and derives what params leave unset: the curved mirror's
// sagitta (fit_sagitta_m()). `refused` names an explicit --sagitta above
// what the mirror allows (max_sagitta_m()). The one route from the options
// to a frame: render, the window (at start-up, for each panel change and
// each scene file) and the reports call it. (Counts per pixel are the
// frame's: render refuses a --tiles or --lens-grid its --size cannot hold,
// the window's frame caps them at each framebuffer size, window/frame.hpp.)
// `camera`, the frame's main camera when known, lets a derived mirror stand
// where that camera sees it (place_mirror()).
ResolvedEffects resolve_effects(const EffectParams& params, scene::Scene& scene,
                                const frustum::MatrixPair<float>* camera = nullptr);

// The stereo rig params ask for, the convergence derived from the scene's
// mirror and bounds as seen from `camera` when unset; empty without stereo.
std::optional<StereoRig> stereo_rig(const EffectParams& params, const frustum::MatrixPair<float>& camera,
                                    const scene::Scene& scene);

} // namespace plan
