// The OpenGL functions the renderer calls, as pointers fetched from the context's own
// GetProcAddress (OSMesaGetProcAddress, eglGetProcAddress). Nothing links an OpenGL library
// directly: libOSMesa exports gl* symbols itself, and a binary that also linked libGL would
// resolve them to whichever library comes first, so calls made under the other backend's
// context would silently do nothing. Each backend fills this table; the renderer calls through
// the one of the context current when it was created.
#pragma once

// GL 1.1 functions are declared by gl.h (their types by decltype); later ones have PFN types.
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

namespace hexgait {

// X(name without "gl", pointer type): every function renderer.cc and gl_context*.cc call.
#define HEXGAIT_GL_FUNCTIONS(X)                                              \
  X(AttachShader, PFNGLATTACHSHADERPROC)                                     \
  X(BindBuffer, PFNGLBINDBUFFERPROC)                                         \
  X(BindFramebuffer, PFNGLBINDFRAMEBUFFERPROC)                               \
  X(BindRenderbuffer, PFNGLBINDRENDERBUFFERPROC)                             \
  X(BindVertexArray, PFNGLBINDVERTEXARRAYPROC)                               \
  X(BlitFramebuffer, PFNGLBLITFRAMEBUFFERPROC)                               \
  X(BufferData, PFNGLBUFFERDATAPROC)                                         \
  X(CheckFramebufferStatus, PFNGLCHECKFRAMEBUFFERSTATUSPROC)                 \
  X(Clear, decltype(&::glClear))                                             \
  X(ClearColor, decltype(&::glClearColor))                                   \
  X(CompileShader, PFNGLCOMPILESHADERPROC)                                   \
  X(CreateProgram, PFNGLCREATEPROGRAMPROC)                                   \
  X(CreateShader, PFNGLCREATESHADERPROC)                                     \
  X(DeleteBuffers, PFNGLDELETEBUFFERSPROC)                                   \
  X(DeleteFramebuffers, PFNGLDELETEFRAMEBUFFERSPROC)                         \
  X(DeleteProgram, PFNGLDELETEPROGRAMPROC)                                   \
  X(DeleteRenderbuffers, PFNGLDELETERENDERBUFFERSPROC)                       \
  X(DeleteShader, PFNGLDELETESHADERPROC)                                     \
  X(DeleteVertexArrays, PFNGLDELETEVERTEXARRAYSPROC)                         \
  X(Disable, decltype(&::glDisable))                                         \
  X(DrawArrays, decltype(&::glDrawArrays))                                   \
  X(Enable, decltype(&::glEnable))                                           \
  X(EnableVertexAttribArray, PFNGLENABLEVERTEXATTRIBARRAYPROC)               \
  X(Finish, decltype(&::glFinish))                                           \
  X(Flush, decltype(&::glFlush))                                             \
  X(FramebufferRenderbuffer, PFNGLFRAMEBUFFERRENDERBUFFERPROC)               \
  X(GenBuffers, PFNGLGENBUFFERSPROC)                                         \
  X(GenFramebuffers, PFNGLGENFRAMEBUFFERSPROC)                               \
  X(GenRenderbuffers, PFNGLGENRENDERBUFFERSPROC)                             \
  X(GenVertexArrays, PFNGLGENVERTEXARRAYSPROC)                               \
  X(GetError, decltype(&::glGetError))                                       \
  X(GetIntegerv, decltype(&::glGetIntegerv))                                 \
  X(GetProgramInfoLog, PFNGLGETPROGRAMINFOLOGPROC)                           \
  X(GetProgramiv, PFNGLGETPROGRAMIVPROC)                                     \
  X(GetShaderInfoLog, PFNGLGETSHADERINFOLOGPROC)                             \
  X(GetShaderiv, PFNGLGETSHADERIVPROC)                                       \
  X(GetString, decltype(&::glGetString))                                     \
  X(GetUniformLocation, PFNGLGETUNIFORMLOCATIONPROC)                         \
  X(LinkProgram, PFNGLLINKPROGRAMPROC)                                       \
  X(PixelStorei, decltype(&::glPixelStorei))                                 \
  X(ReadPixels, decltype(&::glReadPixels))                                   \
  X(RenderbufferStorage, PFNGLRENDERBUFFERSTORAGEPROC)                       \
  X(RenderbufferStorageMultisample, PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC) \
  X(ShaderSource, PFNGLSHADERSOURCEPROC)                                     \
  X(Uniform1f, PFNGLUNIFORM1FPROC)                                           \
  X(Uniform1i, PFNGLUNIFORM1IPROC)                                           \
  X(Uniform3fv, PFNGLUNIFORM3FVPROC)                                         \
  X(UniformMatrix4fv, PFNGLUNIFORMMATRIX4FVPROC)                             \
  X(UseProgram, PFNGLUSEPROGRAMPROC)                                         \
  X(VertexAttribPointer, PFNGLVERTEXATTRIBPOINTERPROC)                       \
  X(Viewport, decltype(&::glViewport))

struct GlApi {
#define HEXGAIT_GL_MEMBER(name, type) type name = nullptr;
  HEXGAIT_GL_FUNCTIONS(HEXGAIT_GL_MEMBER)
#undef HEXGAIT_GL_MEMBER
};

// Fills `api` through `get_proc` ("glClear" -> its address). Returns false, naming the first
// function it could not find in `missing`.
using GlGetProc = void* (*)(const char* name);
bool LoadGlApi(GlGetProc get_proc, GlApi* api, std::string* missing);

// The table of the context made current last on this thread (GlContext::Create), or nullptr.
const GlApi* CurrentGlApi();
void SetCurrentGlApi(const GlApi* api);

}  // namespace hexgait
