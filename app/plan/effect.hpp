// What the renderer can draw (one image per Effect) and how the mirror
// effect builds its reflection camera, with their command-line names.
#pragma once

#include <optional>
#include <string_view>

namespace plan {

enum class Effect {
    Plain,   // the scene from the camera
    Mirror,  // plus the planar mirror's reflection (paper §5.2 / §5.3)
    Tiles,   // the plain frame stitched from cropped tiles (paper §5.1)
    Frustum, // an outside view with the camera frustums drawn from their key points (paper §3.2)
    Curved,  // a convex cap in place of the planar mirror, reflected patch by patch (paper §4.3)
    Lens,      // a magnifier at the scene's lens spot, one lens frustum per tile (paper §5.4)
    NonAffine, // a crossed-slits frustum of six planes, eq. 36 per vertex (paper §6)
    // Portals and recursion (docs/portals.md):
    Portal,    // a portal pair beside the model: through the entry, the scene from the exit
    Recursion, // two facing mirrors (or a portal facing itself) seen recursively, --depth levels
};

// The effects built from the camera's eye (the near plane's frame, the
// mirror's fit, the portal's and the recursion's placement): an
// orthographic camera, whose eye is at infinity, has none.
inline constexpr bool effect_needs_finite_eye(Effect effect) {
    return effect == Effect::Curved || effect == Effect::Lens || effect == Effect::NonAffine ||
           effect == Effect::Portal || effect == Effect::Recursion;
}

inline constexpr Effect kAllEffects[] = {Effect::Plain, Effect::Mirror, Effect::Tiles, Effect::Frustum,
                                        Effect::Curved, Effect::Lens,   Effect::NonAffine,
                                        Effect::Portal, Effect::Recursion};

// "plain", "mirror", "tiles", "frustum", "curved", "lens", "nonaffine", "portal", "recursion".
std::string_view to_string(Effect effect);
// Inverse of to_string(Effect); empty for any other text.
std::optional<Effect> parse_effect(std::string_view text);

enum class MirrorMethod {
    // frustum::mirror(): reflect (§5.2, eq. 16) then oblique near plane =
    // the mirror plane, cropped to the mirror's screen rectangle (§5.1).
    Oblique,
    // frustum::mirror_rectangle(MirrorFit::Exact) (§5.3 with docs/errata.md
    // erratum 5): the unreflected scene from the reflected eye through the
    // mirror rectangle.
    Rectangle,
    // frustum::reflect() alone, cropped: no oblique near plane, so what lies
    // behind the mirror shows up in it. A counter-example for tests and demos.
    ReflectOnly,
};

// "oblique", "rectangle", "reflect_only".
std::string_view to_string(MirrorMethod method);
// Inverse of to_string(MirrorMethod); empty for any other text.
std::optional<MirrorMethod> parse_mirror_method(std::string_view text);

} // namespace plan
