#include "plan/effect.hpp"

#include <frustum/detail/enum_names.hpp>

namespace plan {
namespace {

using frustum::detail::EnumName;

constexpr EnumName<Effect> kEffectNames[] = {
    {Effect::Plain, "plain"},   {Effect::Mirror, "mirror"},       {Effect::Tiles, "tiles"},
    {Effect::Frustum, "frustum"}, {Effect::Curved, "curved"},     {Effect::Lens, "lens"},
    {Effect::NonAffine, "nonaffine"}, {Effect::Portal, "portal"}, {Effect::Recursion, "recursion"}};

constexpr EnumName<MirrorMethod> kMirrorMethodNames[] = {{MirrorMethod::Oblique, "oblique"},
                                                         {MirrorMethod::Rectangle, "rectangle"},
                                                         {MirrorMethod::ReflectOnly, "reflect_only"}};

} // namespace

std::string_view to_string(Effect effect) {
    const char* name = frustum::detail::find_enum_name(kEffectNames, effect);
    return name ? name : "?";
}

std::optional<Effect> parse_effect(std::string_view text) {
    return frustum::detail::find_enum_value(kEffectNames, text);
}

std::string_view to_string(MirrorMethod method) {
    const char* name = frustum::detail::find_enum_name(kMirrorMethodNames, method);
    return name ? name : "?";
}

std::optional<MirrorMethod> parse_mirror_method(std::string_view text) {
    return frustum::detail::find_enum_value(kMirrorMethodNames, text);
}

} // namespace plan
