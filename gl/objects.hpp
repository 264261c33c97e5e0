// Move-only owners of GL object names. Each deletes its object with the
// matching glDelete* when destroyed, so the context (and the Functions
// table they point to) must outlive them and be current then.
#pragma once

#include "gl/errors.hpp"
#include "gl/functions.hpp"

#include <frustum/result.hpp>

#include <string_view>

namespace gl {

enum class ObjectKind { Buffer, VertexArray, Texture, Renderbuffer, Framebuffer, Shader, Program, Query };
inline constexpr int kObjectKindCount = 8;

// "Buffer", "VertexArray", ...
const char* to_string(ObjectKind kind);

// GL objects created through these classes and not yet deleted, process-wide;
// a test checks both are 0 after teardown.
int live_object_count(ObjectKind kind);
int live_object_count();

// The shared part: a name, its kind and the table that deletes it.
class Object {
public:
    GLuint id() const { return id_; }
    ObjectKind kind() const { return kind_; }
    explicit operator bool() const { return id_ != 0; }
    // Deletes the object now; the handle becomes empty.
    void reset();

protected:
    explicit Object(ObjectKind kind) : kind_(kind) {}
    Object(const Functions& fn, ObjectKind kind, GLuint id);
    ~Object() { reset(); }
    Object(Object&& other) noexcept;
    Object& operator=(Object&& other) noexcept;

private:
    const Functions* fn_ = nullptr;
    ObjectKind kind_;
    GLuint id_ = 0;
};

// Objects made with glGen*: Buffer, VertexArray, Texture, Renderbuffer,
// Framebuffer, Query.
template <ObjectKind K>
class GeneratedObject final : public Object {
public:
    GeneratedObject() : Object(K) {}
    // Error when glGen* hands out no name, e.g. with no current context.
    static frustum::Result<GeneratedObject> create(const Functions& fn);

private:
    using Object::Object;
};

using Buffer = GeneratedObject<ObjectKind::Buffer>;
using VertexArray = GeneratedObject<ObjectKind::VertexArray>;
using Texture = GeneratedObject<ObjectKind::Texture>;
using Renderbuffer = GeneratedObject<ObjectKind::Renderbuffer>;
using Framebuffer = GeneratedObject<ObjectKind::Framebuffer>;
using Query = GeneratedObject<ObjectKind::Query>;

class Shader final : public Object {
public:
    Shader() : Object(ObjectKind::Shader) {}
    // stage: GL_VERTEX_SHADER or GL_FRAGMENT_SHADER. A compile failure
    // returns the info log: "gl::Shader::compile(): vertex shader failed to compile:\n0:3(1): error: ...".
    static frustum::Result<Shader> compile(const Functions& fn, GLenum stage, std::string_view source);

private:
    friend class Program;
    using Object::Object;
    // compile() with `where` as the error prefix.
    static frustum::Result<Shader> compile(const Functions& fn, GLenum stage, std::string_view source,
                                           const char* where);
};

class Program final : public Object {
public:
    Program() : Object(ObjectKind::Program) {}
    // Compiles both stages and links. Errors say which stage or the link
    // failed and carry the info log, e.g.
    // "gl::Program::build(): fragment shader failed to compile:\n..." or
    // "gl::Program::build(): link failed:\n...".
    static frustum::Result<Program> build(const Functions& fn, std::string_view vertex_source,
                                          std::string_view fragment_source);

private:
    using Object::Object;
};

} // namespace gl
