#include "fieldviz/render/OffscreenRenderer.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkProp.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "fieldviz/render/OsMesaContext.h"

namespace fluidviz {

// A vtkGenericOpenGLRenderWindow draws into whatever context is current; it asks its owner to
// make it current and whether it is, through WindowMakeCurrentEvent / WindowIsCurrentEvent.
// Answering those from our own OSMesa context lets several renderers coexist in one process.
struct OffscreenRenderer::Impl {
  OsMesaContext context;  // declared first: destroyed after the VTK objects that use it
  vtkNew<vtkGenericOpenGLRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  std::vector<std::string> errors;

  Impl(int width, int height) : context(width, height) {
    window->SetSize(width, height);
    window->SetOwnContext(false);
    window->SetIsCurrent(true);
    window->SetReadyForRendering(true);
    window->SetMultiSamples(0);
    window->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &Impl::onMakeCurrent);
    window->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &Impl::onIsCurrent);
    window->AddObserver(vtkCommand::ErrorEvent, this, &Impl::onError);
    renderer->AddObserver(vtkCommand::ErrorEvent, this, &Impl::onError);
    window->AddRenderer(renderer);
  }

  ~Impl() {
    // GL resources (buffers, shaders, textures) must be released while their context is current.
    context.makeCurrent();
    window->Finalize();
    window->RemoveAllObservers();
    renderer->RemoveAllObservers();
  }

  void onMakeCurrent(vtkObject*, unsigned long, void*) { context.makeCurrent(); }
  void onIsCurrent(vtkObject*, unsigned long, void* isCurrent) {
    *static_cast<bool*>(isCurrent) = context.isCurrent();
  }
  void onError(vtkObject*, unsigned long, void* message) {
    errors.emplace_back(message ? static_cast<const char*>(message) : "(no message)");
  }

  void throwIfVtkReportedErrors() {
    if (errors.empty()) return;
    std::string all;
    for (const std::string& e : errors) all += (all.empty() ? "" : "; ") + e;
    errors.clear();
    throw std::runtime_error("off-screen rendering failed: VTK reported: " + all);
  }

  // The finished frame sits in the OSMesa buffer (VTK blits its render target to the default
  // framebuffer in Frame()); OpenGL stores it bottom row first.
  RgbaImage copyBufferTopRowFirst() const {
    RgbaImage image{context.width(), context.height(), {}};
    const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
    image.pixels.resize(rowBytes * image.height);
    const std::uint8_t* source = context.buffer().data();
    for (int y = 0; y < image.height; ++y)
      std::memcpy(image.pixels.data() + y * rowBytes, source + (image.height - 1 - y) * rowBytes,
                  rowBytes);
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
    return image;
  }
};

OffscreenRenderer::OffscreenRenderer(int width, int height, const Rgb& background)
    : impl_(std::make_unique<Impl>(width, height)) {
  setBackground(background);
}

OffscreenRenderer::~OffscreenRenderer() = default;

int OffscreenRenderer::width() const { return impl_->context.width(); }
int OffscreenRenderer::height() const { return impl_->context.height(); }

void OffscreenRenderer::addProp(vtkProp* prop) {
  if (prop == nullptr) throw std::invalid_argument("OffscreenRenderer::addProp: null prop");
  impl_->renderer->AddViewProp(prop);
}

void OffscreenRenderer::removeProp(vtkProp* prop) { impl_->renderer->RemoveViewProp(prop); }

void OffscreenRenderer::setBackground(const Rgb& color) {
  impl_->renderer->SetBackground(color[0], color[1], color[2]);
}

void OffscreenRenderer::setMultiSamples(int samples) {
  if (samples < 0 || samples > 16)
    throw std::invalid_argument("multisamples = " + std::to_string(samples) +
                                " is outside [0, 16]");
  impl_->window->SetMultiSamples(samples);
}

void OffscreenRenderer::resetCamera() { impl_->renderer->ResetCamera(); }

vtkCamera* OffscreenRenderer::camera() { return impl_->renderer->GetActiveCamera(); }
vtkRenderer* OffscreenRenderer::renderer() { return impl_->renderer; }
vtkRenderWindow* OffscreenRenderer::window() { return impl_->window; }

RgbaImage OffscreenRenderer::render() {
  impl_->context.makeCurrent();
  impl_->errors.clear();
  impl_->window->Render();
  impl_->window->WaitForCompletion();
  impl_->throwIfVtkReportedErrors();
  return impl_->copyBufferTopRowFirst();
}

void OffscreenRenderer::renderToPng(const std::filesystem::path& file) { writePicture(render(), file); }

}  // namespace fluidviz
