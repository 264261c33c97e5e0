// The GL entry points the renderer uses: the OpenGL ES 3.0 set, which
// desktop GL 4.3 core also has, plus two optional extras. Members drop the
// "gl" prefix: fn.DrawArrays(GL_TRIANGLES, 0, 3).
//
// Load once per context (the pointers are only valid with that context
// current) and keep the table at a stable address: gl objects point to it.
#pragma once

#include "gl/context.hpp"
#include "gl/gl_api.hpp"

#include <frustum/result.hpp>

// X(pointer type, name without "gl"): every entry Functions::load() requires.
#define FRUSTUM_GL_REQUIRED_FUNCTIONS(X)                                        \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                    \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                      \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                                          \
    X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation)                          \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                          \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                  \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                              \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                        \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                                    \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                                            \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                            \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                                \
    X(PFNGLBUFFERDATAPROC, BufferData)                                          \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                    \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                  \
    X(PFNGLCLEARPROC, Clear)                                                    \
    X(PFNGLCLEARBUFFERFIPROC, ClearBufferfi)                                    \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                    \
    X(PFNGLCLEARCOLORPROC, ClearColor)                                          \
    X(PFNGLCLEARDEPTHFPROC, ClearDepthf)                                        \
    X(PFNGLCLEARSTENCILPROC, ClearStencil)                                      \
    X(PFNGLCOLORMASKPROC, ColorMask)                                            \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                    \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                    \
    X(PFNGLCREATESHADERPROC, CreateShader)                                      \
    X(PFNGLCULLFACEPROC, CullFace)                                              \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                    \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                          \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                    \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                                    \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                        \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                      \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                  \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                          \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                            \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                            \
    X(PFNGLDEPTHRANGEFPROC, DepthRangef)                                        \
    X(PFNGLDETACHSHADERPROC, DetachShader)                                      \
    X(PFNGLDISABLEPROC, Disable)                                                \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray)              \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                          \
    X(PFNGLDRAWARRAYSINSTANCEDPROC, DrawArraysInstanced)                        \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                        \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                                      \
    X(PFNGLDRAWELEMENTSINSTANCEDPROC, DrawElementsInstanced)                    \
    X(PFNGLENABLEPROC, Enable)                                                  \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                \
    X(PFNGLENDQUERYPROC, EndQuery)                                              \
    X(PFNGLFINISHPROC, Finish)                                                  \
    X(PFNGLFLUSHPROC, Flush)                                                    \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)                \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                      \
    X(PFNGLFRONTFACEPROC, FrontFace)                                            \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                          \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                \
    X(PFNGLGENQUERIESPROC, GenQueries)                                          \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                              \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                        \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                \
    X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap)                                  \
    X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)                            \
    X(PFNGLGETERRORPROC, GetError)                                              \
    X(PFNGLGETFLOATVPROC, GetFloatv)                                            \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                        \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                            \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                      \
    X(PFNGLGETQUERYOBJECTUIVPROC, GetQueryObjectuiv)                            \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                              \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                        \
    X(PFNGLGETSTRINGPROC, GetString)                                            \
    X(PFNGLGETSTRINGIPROC, GetStringi)                                          \
    X(PFNGLGETUNIFORMBLOCKINDEXPROC, GetUniformBlockIndex)                      \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                          \
    X(PFNGLLINEWIDTHPROC, LineWidth)                                            \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                        \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                        \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                                    \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                          \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                          \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                        \
    X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample)  \
    X(PFNGLSCISSORPROC, Scissor)                                                \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                      \
    X(PFNGLSTENCILFUNCPROC, StencilFunc)                                        \
    X(PFNGLSTENCILMASKPROC, StencilMask)                                        \
    X(PFNGLSTENCILOPPROC, StencilOp)                                            \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                          \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                    \
    X(PFNGLTEXSTORAGE2DPROC, TexStorage2D)                                      \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                    \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                            \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                            \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                                            \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                            \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                          \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                                            \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                          \
    X(PFNGLUNIFORMBLOCKBINDINGPROC, UniformBlockBinding)                        \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                              \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                              \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                          \
    X(PFNGLVERTEXATTRIB4FPROC, VertexAttrib4f)                                  \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                        \
    X(PFNGLVIEWPORTPROC, Viewport)

namespace gl {

struct Functions {
#define FRUSTUM_GL_DECLARE_MEMBER(type, name) type name = nullptr;
    FRUSTUM_GL_REQUIRED_FUNCTIONS(FRUSTUM_GL_DECLARE_MEMBER)
#undef FRUSTUM_GL_DECLARE_MEMBER

    // Optional, null when the context lacks them (see clip_control.hpp and
    // debug_output.hpp for the names and conditions). Same signature on
    // GLES (glClipControlEXT, glDebugMessageCallbackKHR) and desktop GL.
    PFNGLCLIPCONTROLEXTPROC ClipControl = nullptr;
    PFNGLDEBUGMESSAGECALLBACKPROC DebugMessageCallback = nullptr;

    // Every required entry point through context.get_proc_address(); the
    // error lists all that are missing, e.g.
    // "gl::Functions::load(): missing required entry points glBlitFramebuffer glReadBuffer (OpenGL ES 3.0 ...)".
    static frustum::Result<Functions> load(const Context& context);
};

} // namespace gl
