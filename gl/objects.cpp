#include "gl/objects.hpp"

#include <array>
#include <atomic>
#include <iterator>
#include <string>
#include <utility>

namespace gl {
namespace {

std::array<std::atomic<int>, kObjectKindCount> g_live{};

std::atomic<int>& live(ObjectKind kind) { return g_live[static_cast<std::size_t>(kind)]; }

// glGen* and glDelete* of the kinds made one name at a time through them
// (in ObjectKind order); shaders and programs are made by glCreate* (below)
// and deleted by glDelete*(id).
struct NameCalls {
    PFNGLGENBUFFERSPROC Functions::*generate;
    PFNGLDELETEBUFFERSPROC Functions::*destroy;
};
const NameCalls kNameCalls[] = {
    {&Functions::GenBuffers, &Functions::DeleteBuffers},
    {&Functions::GenVertexArrays, &Functions::DeleteVertexArrays},
    {&Functions::GenTextures, &Functions::DeleteTextures},
    {&Functions::GenRenderbuffers, &Functions::DeleteRenderbuffers},
    {&Functions::GenFramebuffers, &Functions::DeleteFramebuffers},
    {nullptr, nullptr}, // Shader
    {nullptr, nullptr}, // Program
    {&Functions::GenQueries, &Functions::DeleteQueries},
};
static_assert(std::size(kNameCalls) == kObjectKindCount, "one entry per ObjectKind");

void delete_object(const Functions& fn, ObjectKind kind, GLuint id) {
    if (kind == ObjectKind::Shader) {
        fn.DeleteShader(id);
    } else if (kind == ObjectKind::Program) {
        fn.DeleteProgram(id);
    } else {
        (fn.*kNameCalls[static_cast<std::size_t>(kind)].destroy)(1, &id);
    }
}

GLuint generate(const Functions& fn, ObjectKind kind) {
    GLuint id = 0;
    if (const auto call = kNameCalls[static_cast<std::size_t>(kind)].generate) {
        (fn.*call)(1, &id);
    }
    return id;
}

std::string stage_name(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER: return "vertex shader";
    case GL_FRAGMENT_SHADER: return "fragment shader";
    default: return "shader stage " + error_name(stage);
    }
}

template <class GetIv, class GetLog>
std::string info_log(GLuint id, GetIv get_iv, GetLog get_log) {
    GLint length = 0;
    get_iv(id, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
    GLsizei written = 0;
    if (length > 0) {
        get_log(id, length, &written, log.data());
    }
    log.resize(static_cast<std::size_t>(written));
    while (!log.empty() && (log.back() == '\n' || log.back() == ' ')) {
        log.pop_back();
    }
    return log;
}

} // namespace

const char* to_string(ObjectKind kind) {
    constexpr const char* kNames[kObjectKindCount] = {"Buffer",      "VertexArray", "Texture",
                                                      "Renderbuffer", "Framebuffer", "Shader",
                                                      "Program",     "Query"};
    return kNames[static_cast<std::size_t>(kind)];
}

int live_object_count(ObjectKind kind) { return live(kind).load(); }

int live_object_count() {
    int total = 0;
    for (const auto& count : g_live) {
        total += count.load();
    }
    return total;
}

Object::Object(const Functions& fn, ObjectKind kind, GLuint id) : fn_(&fn), kind_(kind), id_(id) {
    ++live(kind_);
}

Object::Object(Object&& other) noexcept
    : fn_(other.fn_), kind_(other.kind_), id_(std::exchange(other.id_, 0)) {}

Object& Object::operator=(Object&& other) noexcept {
    if (this != &other) {
        reset();
        fn_ = other.fn_;
        kind_ = other.kind_;
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

void Object::reset() {
    if (id_ != 0) {
        delete_object(*fn_, kind_, id_);
        --live(kind_);
        id_ = 0;
    }
}

template <ObjectKind K>
frustum::Result<GeneratedObject<K>> GeneratedObject<K>::create(const Functions& fn) {
    const GLuint id = generate(fn, K);
    if (id == 0) {
        return frustum::Error{std::string("gl::") + to_string(K) + "::create(): glGen* returned no name"};
    }
    return GeneratedObject(fn, K, id);
}

template class GeneratedObject<ObjectKind::Buffer>;
template class GeneratedObject<ObjectKind::VertexArray>;
template class GeneratedObject<ObjectKind::Texture>;
template class GeneratedObject<ObjectKind::Renderbuffer>;
template class GeneratedObject<ObjectKind::Framebuffer>;
template class GeneratedObject<ObjectKind::Query>;

frustum::Result<Shader> Shader::compile(const Functions& fn, GLenum stage, std::string_view source) {
    return compile(fn, stage, source, "gl::Shader::compile()");
}

frustum::Result<Shader> Shader::compile(const Functions& fn, GLenum stage, std::string_view source,
                                        const char* where) {
    const GLuint id = fn.CreateShader(stage);
    if (id == 0) {
        return frustum::Error{std::string(where) + ": glCreateShader failed for " + stage_name(stage) +
                              ": GL error " + error_name(fn.GetError())};
    }
    Shader shader(fn, ObjectKind::Shader, id);
    const GLchar* text = source.data();
    const GLint length = static_cast<GLint>(source.size());
    fn.ShaderSource(id, 1, &text, &length);
    fn.CompileShader(id);
    GLint compiled = GL_FALSE;
    fn.GetShaderiv(id, GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
        return frustum::Error{std::string(where) + ": " + stage_name(stage) + " failed to compile:\n" +
                              info_log(id, fn.GetShaderiv, fn.GetShaderInfoLog)};
    }
    return shader;
}

frustum::Result<Program> Program::build(const Functions& fn, std::string_view vertex_source,
                                        std::string_view fragment_source) {
    constexpr const char* kWhere = "gl::Program::build()";
    auto vertex = Shader::compile(fn, GL_VERTEX_SHADER, vertex_source, kWhere);
    if (!vertex) {
        return frustum::Error{vertex.error()};
    }
    auto fragment = Shader::compile(fn, GL_FRAGMENT_SHADER, fragment_source, kWhere);
    if (!fragment) {
        return frustum::Error{fragment.error()};
    }
    const GLuint id = fn.CreateProgram();
    if (id == 0) {
        return frustum::Error{std::string(kWhere) + ": glCreateProgram failed: GL error " +
                              error_name(fn.GetError())};
    }
    Program program(fn, ObjectKind::Program, id);
    fn.AttachShader(id, vertex->id());
    fn.AttachShader(id, fragment->id());
    fn.LinkProgram(id);
    fn.DetachShader(id, vertex->id());
    fn.DetachShader(id, fragment->id());
    GLint linked = GL_FALSE;
    fn.GetProgramiv(id, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        return frustum::Error{std::string(kWhere) + ": link failed:\n" +
                              info_log(id, fn.GetProgramiv, fn.GetProgramInfoLog)};
    }
    return program;
}

} // namespace gl
