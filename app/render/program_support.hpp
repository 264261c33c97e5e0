// What every program builder shares: linking with a named error, text
// inserted after the "#version" line (defines, the frustum.glsl snippet), and
// uniform lookup that names the first missing uniform.
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

#include <string>
#include <string_view>

namespace render::detail {

inline constexpr const char* kProgramsBuild = "render::Programs::build()";

// `text` inserted after the "#version" line, which must stay first.
std::string insert_after_version(std::string_view source, std::string_view text);

// gl::Program::build with "render::Programs::build(): <name> program: ..." errors.
frustum::Result<gl::Program> link(const gl::Functions& fn, std::string_view vertex, std::string_view fragment,
                                  const char* name);

// Looks up uniforms, remembering the first that is missing.
class UniformFinder {
public:
    UniformFinder(const gl::Functions& fn, const gl::Program& program, const char* program_name)
        : fn_(fn), program_(program), program_name_(program_name) {}

    void find(GLint& location, const char* name);
    // "render::Programs::build(): <program> program has no active uniform <name>"
    frustum::Status status() const;

private:
    const gl::Functions& fn_;
    const gl::Program& program_;
    const char* program_name_;
    std::string missing_;
};

} // namespace render::detail
