#include "gl/clip_control.hpp"

#include "gl/errors.hpp"

namespace gl {

const char* clip_control_entry_point(const Context& context) {
    if (context.api() == Api::Gles) {
        return context.has_extension("GL_EXT_clip_control") ? "glClipControlEXT" : nullptr;
    }
    const bool core = context.version_at_least(4, 5) || context.has_extension("GL_ARB_clip_control");
    return core ? "glClipControl" : nullptr;
}

bool supports_zero_to_one_depth(const Functions& fn, const Context& context) {
    return fn.ClipControl != nullptr && clip_control_entry_point(context) != nullptr;
}

frustum::Status set_depth_zero_to_one(const Functions& fn, bool enable) {
    if (fn.ClipControl == nullptr) {
        if (!enable) {
            return {};
        }
        return frustum::Error{"gl::set_depth_zero_to_one(): needs GL_EXT_clip_control, "
                              "GL_ARB_clip_control or GL 4.5; convert the matrices to "
                              "DepthRange::MinusOneToOne instead"};
    }
    // GL_LOWER_LEFT, GL_ZERO_TO_ONE and GL_NEGATIVE_ONE_TO_ONE have the same
    // values in EXT_clip_control, ARB_clip_control and GL 4.5.
    fn.ClipControl(GL_LOWER_LEFT_EXT, enable ? GL_ZERO_TO_ONE_EXT : GL_NEGATIVE_ONE_TO_ONE_EXT);
    return check_error(fn, enable ? "gl::set_depth_zero_to_one(): glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)"
                                  : "gl::set_depth_zero_to_one(): glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE)");
}

} // namespace gl
