#include "render/face_state.hpp"

namespace render {

GLenum front_face(bool view_flips_winding, bool model_flips_winding) {
    return view_flips_winding != model_flips_winding ? GL_CW : GL_CCW;
}

void set_face_state(const gl::Functions& fn, bool double_sided, bool view_flips_winding,
                    bool model_flips_winding) {
    fn.FrontFace(front_face(view_flips_winding, model_flips_winding));
    if (double_sided) {
        fn.Disable(GL_CULL_FACE);
    } else {
        fn.Enable(GL_CULL_FACE);
        fn.CullFace(GL_BACK);
    }
}

void restore_face_state(const gl::Functions& fn) {
    fn.FrontFace(GL_CCW);
    fn.Disable(GL_CULL_FACE);
}

} // namespace render
