#include "render/program_support.hpp"

namespace render::detail {

std::string insert_after_version(std::string_view source, std::string_view text) {
    const std::size_t line_end = source.find('\n') + 1;
    return std::string(source.substr(0, line_end)) + std::string(text) + std::string(source.substr(line_end));
}

frustum::Result<gl::Program> link(const gl::Functions& fn, std::string_view vertex, std::string_view fragment,
                                  const char* name) {
    auto program = gl::Program::build(fn, vertex, fragment);
    if (!program) {
        return frustum::Error{std::string(kProgramsBuild) + ": " + name + " program: " + program.error()};
    }
    return program;
}

void UniformFinder::find(GLint& location, const char* name) {
    location = fn_.GetUniformLocation(program_.id(), name);
    if (location < 0 && missing_.empty()) {
        missing_ = name;
    }
}

frustum::Status UniformFinder::status() const {
    if (missing_.empty()) {
        return {};
    }
    return frustum::Error{std::string(kProgramsBuild) + ": " + program_name_ + " program has no active uniform " +
                          missing_};
}

} // namespace render::detail
