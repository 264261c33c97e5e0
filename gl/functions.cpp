#include "gl/functions.hpp"

#include "gl/clip_control.hpp"
#include "gl/debug_output.hpp"

#include <string>

namespace gl {
namespace {

template <class F>
void load_optional(const Context& context, const char* name, F& function) {
    function = name == nullptr ? nullptr : reinterpret_cast<F>(context.get_proc_address(name));
}

} // namespace

frustum::Result<Functions> Functions::load(const Context& context) {
    Functions fn;
    std::string missing;
#define FRUSTUM_GL_LOAD_MEMBER(type, name)                                        \
    fn.name = reinterpret_cast<type>(context.get_proc_address("gl" #name));      \
    if (fn.name == nullptr) {                                                     \
        missing += " gl" #name;                                                   \
    }
    FRUSTUM_GL_REQUIRED_FUNCTIONS(FRUSTUM_GL_LOAD_MEMBER)
#undef FRUSTUM_GL_LOAD_MEMBER
    if (!missing.empty()) {
        return frustum::Error{"gl::Functions::load(): missing required entry points" + missing +
                              " (" + context.describe().version_text + ")"};
    }
    load_optional(context, clip_control_entry_point(context), fn.ClipControl);
    load_optional(context, debug_callback_entry_point(context), fn.DebugMessageCallback);
    return fn;
}

} // namespace gl
