// Our OpenGL function loader: a global pointer per GL function we use, filled at run time
// from the active backend's GetProcAddress. `glFoo` is a macro for that pointer, so code
// (ours and Dear ImGui's OpenGL3 backend, built with IMGUI_IMPL_OPENGL_LOADER_CUSTOM)
// calls GL as usual. Add a function by adding one line to CB_GL_FUNCTIONS.
#pragma once

#include <GL/glcorearb.h>

#include <string>

// X-macro: (PFN type, name).
#define CB_GL_FUNCTIONS(X)                                          \
  X(PFNGLGETERRORPROC, glGetError)                                  \
  X(PFNGLGETSTRINGPROC, glGetString)                                \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                            \
  X(PFNGLVIEWPORTPROC, glViewport)                                  \
  X(PFNGLSCISSORPROC, glScissor)                                    \
  X(PFNGLCLEARCOLORPROC, glClearColor)                              \
  X(PFNGLCLEARPROC, glClear)                                        \
  X(PFNGLENABLEPROC, glEnable)                                      \
  X(PFNGLDISABLEPROC, glDisable)                                    \
  X(PFNGLISENABLEDPROC, glIsEnabled)                                \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)                \
  X(PFNGLBLENDEQUATIONPROC, glBlendEquation)                        \
  X(PFNGLBLENDEQUATIONSEPARATEPROC, glBlendEquationSeparate)        \
  X(PFNGLFINISHPROC, glFinish)                                      \
  X(PFNGLFLUSHPROC, glFlush)                                        \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                            \
  X(PFNGLREADPIXELSPROC, glReadPixels)                              \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                              \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                    \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)              \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                    \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)    \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)          \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)      \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                    \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                  \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)            \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                  \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)            \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample) \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                            \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                      \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                            \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                        \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                              \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                        \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                        \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                              \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                        \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                              \
  X(PFNGLBUFFERDATAPROC, glBufferData)                              \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                        \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                    \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)              \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                    \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)    \
  X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, glDisableVertexAttribArray)  \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)            \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)            \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                              \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                          \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, glDrawArraysInstanced)            \
  X(PFNGLDRAWELEMENTSBASEVERTEXPROC, glDrawElementsBaseVertex)      \
  X(PFNGLCREATESHADERPROC, glCreateShader)                          \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                          \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                          \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                        \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                            \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                  \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                        \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                        \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                          \
  X(PFNGLDETACHSHADERPROC, glDetachShader)                          \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                            \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                          \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                              \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)              \
  X(PFNGLGETATTRIBLOCATIONPROC, glGetAttribLocation)                \
  X(PFNGLBINDATTRIBLOCATIONPROC, glBindAttribLocation)              \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                \
  X(PFNGLUNIFORM2FPROC, glUniform2f)                                \
  X(PFNGLUNIFORM4FPROC, glUniform4f)                                \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                  \
  X(PFNGLPOLYGONMODEPROC, glPolygonMode)                            \
  X(PFNGLGETTEXPARAMETERIVPROC, glGetTexParameteriv)                \
  X(PFNGLISPROGRAMPROC, glIsProgram)                                \
  X(PFNGLGETSTRINGIPROC, glGetStringi)                              \
  X(PFNGLBINDSAMPLERPROC, glBindSampler)                            \
  X(PFNGLLINEWIDTHPROC, glLineWidth)

#define CB_GL_DECLARE(type, name) extern type cb_##name;
CB_GL_FUNCTIONS(CB_GL_DECLARE)
#undef CB_GL_DECLARE

// The aliases (#define glClear cb_glClear, ...): a macro cannot define macros, so they are
// spelled out in gl_aliases.h, one per line of CB_GL_FUNCTIONS (a test checks they match).
#include "gl/gl_aliases.h"

namespace cb {

using GlProcLoader = void* (*)(const char* name);

// Fills every pointer from `get_proc` (the current context's GetProcAddress). Returns
// false and names the first missing function in `missing`.
bool load_gl_functions(GlProcLoader get_proc, std::string& missing);

}  // namespace cb
