// Symbols that must be defined in the EXECUTABLE (not in a library it loads) so that the dynamic
// linker finds them before glvnd's and GLEW's own definitions. fieldviz/CMakeLists.txt builds this
// file as fluidviz_render_interposers and links it whole-archive into every executable that links
// fluidviz_render, exporting the three symbols with --export-dynamic-symbol.
// Why (docs/design.md, "Off-screen rendering"):
//
// 1. Debian's VTK 9.1 loads GL entry points through GLEW, and GLEW (built for GLX) looks them up
//    with glXGetProcAddressARB. Under glvnd that returns dispatch stubs that route to the current
//    *GLX* context; with an OSMesa context current there is none, so every call would go nowhere.
//    While an OSMesa context is current, our glXGetProcAddress[ARB] answers from
//    OSMesaGetProcAddress instead. glX* names and calls with no OSMesa context current go on to
//    the real GLX implementation, so a GLX program linking this still works.
// 2. glewInit() = glewContextInit() (GL entry points and version flags) followed by glxewInit()
//    (GLX extension flags), which fails with GLEW_ERROR_NO_GLX_DISPLAY when there is no X display.
//    By then the GL function pointers are loaded, so with an OSMesa context current that one
//    code is reported as GLEW_OK; otherwise VTK logs "GLEW could not be initialized" on every
//    render and skips part of its set-up (it never marks the window initialized).
#include <GL/glew.h>  // before osmesa.h: GLEW must be the first GL header
// glew.h #undefs GLAPI, which osmesa.h needs (GLEW's own visualinfo.c does the same).
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstring>

namespace {

using GlFunction = void (*)();
using GlxLookup = GlFunction (*)(const GLubyte*);
using GlewInitFunction = GLenum (*)();

bool isGlxName(const GLubyte* name) {
  return std::strncmp(reinterpret_cast<const char*>(name), "glX", 3) == 0;
}

// The definition this one hides: the next one in the dynamic linker's search order (libGLX).
GlFunction lookUpInRealGlx(const char* lookupSymbol, const GLubyte* name) {
  auto real = reinterpret_cast<GlxLookup>(dlsym(RTLD_NEXT, lookupSymbol));
  return real ? real(name) : nullptr;
}

GlFunction lookUp(const char* lookupSymbol, const GLubyte* name) {
  if (name == nullptr) return nullptr;
  if (OSMesaGetCurrentContext() != nullptr && !isGlxName(name))
    return OSMesaGetProcAddress(reinterpret_cast<const char*>(name));
  return lookUpInRealGlx(lookupSymbol, name);
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) GlFunction glXGetProcAddressARB(const GLubyte* name) {
  return lookUp("glXGetProcAddressARB", name);
}

__attribute__((visibility("default"))) GlFunction glXGetProcAddress(const GLubyte* name) {
  return lookUp("glXGetProcAddress", name);
}

__attribute__((visibility("default"))) GLenum glewInit() {
  static const auto real = reinterpret_cast<GlewInitFunction>(dlsym(RTLD_NEXT, "glewInit"));
  if (real == nullptr) return GLEW_ERROR_NO_GL_VERSION;
  const GLenum result = real();
  if (result == GLEW_ERROR_NO_GLX_DISPLAY && OSMesaGetCurrentContext() != nullptr) return GLEW_OK;
  return result;
}

}  // extern "C"
