#include "plan/effect.hpp"

namespace render {

std::string_view to_string(Effect effect) {
    switch (effect) {
    case Effect::Plain: return "plain";
    case Effect::Mirror: return "mirror";
    case Effect::Tiles: return "tiles";
    case Effect::Frustum: return "frustum";
    case Effect::Curved: return "curved";
    case Effect::Lens: return "lens";
    case Effect::NonAffine: return "nonaffine";
    case Effect::Portal: return "portal";
    case Effect::Recursion: return "recursion";
    }
    return "?";
}

std::optional<Effect> parse_effect(std::string_view text) {
    for (Effect effect : kAllEffects) {
        if (text == to_string(effect)) {
            return effect;
        }
    }
    return std::nullopt;
}

std::string_view to_string(MirrorMethod method) {
    switch (method) {
    case MirrorMethod::Oblique: return "oblique";
    case MirrorMethod::Rectangle: return "rectangle";
    case MirrorMethod::ReflectOnly: return "reflect_only";
    }
    return "?";
}

std::optional<MirrorMethod> parse_mirror_method(std::string_view text) {
    for (MirrorMethod method : {MirrorMethod::Oblique, MirrorMethod::Rectangle, MirrorMethod::ReflectOnly}) {
        if (text == to_string(method)) {
            return method;
        }
    }
    return std::nullopt;
}

} // namespace render
