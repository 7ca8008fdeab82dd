#pragma once
// A VTK renderer drawing off-screen into an OSMesa context: no X display, no window. Owns the
// context, a vtkGenericOpenGLRenderWindow of the same size and one vtkRenderer. Callers add props
// (actors, volumes, 2D text and scalar bars), set the camera, and render to an RgbaImage or PNG.
//
//   OffscreenRenderer r(400, 300);
//   r.addProp(sphereActor);
//   r.resetCamera();
//   writePicture(r.render(), "sphere.png");
//
// Several renderers may exist at the same time or one after another in a process; each render()
// makes its own context current first. Not thread-safe: use one thread for all rendering.
#include <array>
#include <filesystem>
#include <memory>

#include "fieldviz/render/RgbaImage.h"

class vtkCamera;
class vtkProp;
class vtkRenderer;
class vtkRenderWindow;

namespace fluidviz {

using Rgb = std::array<double, 3>;  ///< colour, each channel in [0, 1]

class OffscreenRenderer {
 public:
  /// width, height: image size in px, each in [1, 16384]. Throws std::runtime_error if out of
  /// range or if no OpenGL context can be made (with the reason and the fix).
  OffscreenRenderer(int width, int height, const Rgb& background = {1.0, 1.0, 1.0});
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  int width() const;
  int height() const;

  /// Adds an actor, volume or 2D actor; the renderer keeps a reference.
  void addProp(vtkProp* prop);
  void removeProp(vtkProp* prop);
  void setBackground(const Rgb& color);
  /// Multisample anti-aliasing samples per pixel, [0, 16]; 0 (default) draws every pixel with
  /// one sample, so flat colours come out exact.
  void setMultiSamples(int samples);
  /// Places the camera so that all visible props fit (vtkRenderer::ResetCamera).
  void resetCamera();

  vtkCamera* camera();
  vtkRenderer* renderer();
  vtkRenderWindow* window();

  /// Renders the scene and returns the picture, top row first, alpha = 255. Throws
  /// std::runtime_error with VTK's message if the window or renderer reported an error.
  RgbaImage render();
  /// render() and write the result as PNG (atomically).
  void renderToPng(const std::filesystem::path& file);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fluidviz
