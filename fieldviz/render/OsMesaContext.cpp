#include "fieldviz/render/OsMesaContext.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace fluidviz {

namespace {

using GlFunction = void (*)();
using GlxLookup = GlFunction (*)(const GLubyte*);
using GlewInitFunction = unsigned int (*)();
constexpr unsigned int kGlewOk = 0;
constexpr int kMaxSize = 16384;

const char* const kLinkHint =
    " Link the executable with CMake against fluidviz_render (or call "
    "fluidviz_enable_offscreen on it): that adds render/GlInterposers.cpp to it, exports its "
    "symbols and puts libOSMesa ahead of libGL (see fieldviz/CMakeLists.txt).";

OSMesaContext toOsMesa(void* context) { return static_cast<OSMesaContext>(context); }

// Trap 1 (glvnd): GLEW asks glXGetProcAddressARB; it must hand out OSMesa's functions.
void checkProcAddressLookup() {
  auto lookup = reinterpret_cast<GlxLookup>(dlsym(RTLD_DEFAULT, "glXGetProcAddressARB"));
  const GlFunction expected = OSMesaGetProcAddress("glGenBuffers");
  if (lookup == nullptr || expected == nullptr ||
      lookup(reinterpret_cast<const GLubyte*>("glGenBuffers")) != expected)
    throw std::runtime_error(
        "OSMesa rendering: glXGetProcAddressARB does not return OSMesa's GL functions, so VTK "
        "would call glvnd stubs that draw nothing." +
        std::string(kLinkHint));
}

// Direct gl* calls from VTK must bind to libOSMesa's definitions, not glvnd's libOpenGL/libGL.
void checkDirectGlCallsReachOsMesa() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&OSMesaCreateContextAttribs), &info) == 0 ||
      info.dli_fname == nullptr)
    throw std::runtime_error("OSMesa rendering: cannot locate the loaded libOSMesa");
  void* osmesa = dlopen(info.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
  const void* own = osmesa ? dlsym(osmesa, "glClear") : nullptr;
  const void* bound = dlsym(RTLD_DEFAULT, "glClear");
  if (osmesa) dlclose(osmesa);
  if (own == nullptr || own != bound) {
    Dl_info boundInfo{};
    const bool named = bound && dladdr(bound, &boundInfo) && boundInfo.dli_fname;
    throw std::runtime_error(std::string("OSMesa rendering: glClear binds to ") +
                             (named ? boundInfo.dli_fname : "nothing") + " instead of " +
                             info.dli_fname + "." + kLinkHint);
  }
}

// Trap 2: glewInit must accept the missing GLX display (needs a current context).
void checkGlewInitSucceeds() {
  auto glewInit = reinterpret_cast<GlewInitFunction>(dlsym(RTLD_DEFAULT, "glewInit"));
  if (glewInit == nullptr) return;  // a VTK without GLEW needs no interposer
  const unsigned int result = glewInit();
  if (result != kGlewOk)
    throw std::runtime_error("OSMesa rendering: glewInit failed with GLEW error " +
                             std::to_string(result) +
                             "; VTK would log \"GLEW could not be "
                             "initialized\"." +
                             kLinkHint);
}

void checkProcessResolvesGlThroughOsMesa() {
  static std::once_flag checked;
  std::call_once(checked, [] {
    checkProcAddressLookup();
    checkDirectGlCallsReachOsMesa();
    checkGlewInitSucceeds();
  });
}

OSMesaContext createCoreProfileContext() {
  // OSMesa only gives a core profile (which VTK's OpenGL2 backend needs, >= 3.2) when asked.
  // clang-format off
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                            OSMESA_DEPTH_BITS, 24,
                            OSMESA_STENCIL_BITS, 8,
                            OSMESA_ACCUM_BITS, 0,
                            OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3,
                            OSMESA_CONTEXT_MINOR_VERSION, 2,
                            0};
  // clang-format on
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context == nullptr)
    throw std::runtime_error(
        "OSMesa rendering: OSMesaCreateContextAttribs failed to create an "
        "OpenGL 3.2 core-profile context");
  return context;
}

}  // namespace

OsMesaContext::OsMesaContext(int width, int height) : width_(width), height_(height) {
  if (width < 1 || width > kMaxSize || height < 1 || height > kMaxSize)
    throw std::runtime_error("OSMesa rendering: image size " + std::to_string(width) + " x " +
                             std::to_string(height) + " px is outside [1, " +
                             std::to_string(kMaxSize) + "] px per side");
  buffer_.assign(static_cast<std::size_t>(width) * height * 4, 0);
  context_ = createCoreProfileContext();
  try {
    makeCurrent();
    checkProcessResolvesGlThroughOsMesa();
  } catch (...) {
    OSMesaDestroyContext(toOsMesa(context_));
    throw;
  }
}

OsMesaContext::~OsMesaContext() {
  if (isCurrent()) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  OSMesaDestroyContext(toOsMesa(context_));
}

void OsMesaContext::makeCurrent() {
  if (isCurrent()) return;
  if (!OSMesaMakeCurrent(toOsMesa(context_), buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw std::runtime_error("OSMesa rendering: OSMesaMakeCurrent failed for a " +
                             std::to_string(width_) + " x " + std::to_string(height_) +
                             " px buffer");
}

bool OsMesaContext::isCurrent() const { return OSMesaGetCurrentContext() == toOsMesa(context_); }

}  // namespace fluidviz
