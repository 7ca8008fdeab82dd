#pragma once
// 3D pictures: a camera that frames the data from an azimuth and elevation, lights, an outline
// box, a colour legend, and turntable frames, on top of OffscreenRenderer. Actors come from
// SurfaceRendering.h, ParticleRendering.h and VolumeRendering.h.
//
//   Scene3D scene(view);                       // View3DParams: size, camera, background, ...
//   scene.add(makeSurfaceActor(surface, style).actor);
//   scene.renderToPng("ball.png");            // frames the camera on everything added
//
// Camera convention: `up` is the world axis that points up in the picture. At azimuth 0 and
// elevation 0 the camera looks horizontally at the data's centre from the "front": from +z
// when up = y (x to the right), from -y when up = z (x to the right), from +y when up = x.
// Azimuth turns the camera about the up axis (positive: towards the picture's right side),
// elevation lifts it above the horizontal plane.
#include <array>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "fieldviz/core/Params.h"
#include "fieldviz/render/OffscreenRenderer.h"
#include "fieldviz/render/PictureStyle.h"
#include "fieldviz/render/RgbaImage.h"

class vtkProp;
class vtkRenderer;
class vtkScalarsToColors;

namespace fluidviz {

enum class Axis { x, y, z };
constexpr std::array<Choice<Axis>, 3> paramChoices(Axis) {
  return {{{Axis::x, "x"}, {Axis::y, "y"}, {Axis::z, "z"}}};
}

enum class Projection { perspective, parallel };
constexpr std::array<Choice<Projection>, 2> paramChoices(Projection) {
  return {{{Projection::perspective, "perspective"}, {Projection::parallel, "parallel"}}};
}

// Units and ranges of the members: their describe() declarations below.
struct CameraParams {
  double azimuth = 30.0;    ///< turn about the up axis from the front view
  double elevation = 20.0;  ///< angle above the horizontal plane
  double zoom = 1.0;        ///< 1: the data's bounding sphere just fits; 2: twice as close
  Axis up = Axis::y;
  Projection projection = Projection::perspective;
  double view_angle = 30.0;  ///< vertical field of view of the perspective camera

  template <class V>
  static void describe(V& v) {
    v(&CameraParams::azimuth, {.key = "azimuth", .unit = "deg",
                               .description = "turn about the up axis from the front view",
                               .min = -360, .max = 360});
    v(&CameraParams::elevation, {.key = "elevation", .unit = "deg",
                                 .description = "angle above the horizontal plane",
                                 .min = -89, .max = 89});
    v(&CameraParams::zoom, {.key = "zoom",
                            .description = "1: the bounding sphere of the data just fits; "
                                           "larger is closer",
                            .min = 0, .max = 50, .minExclusive = true});
    v(&CameraParams::up, {.key = "up", .description = "world axis pointing up in the picture"});
    v(&CameraParams::projection, {.key = "projection",
                                  .description = "perspective or parallel (orthographic)"});
    v(&CameraParams::view_angle, {.key = "view_angle", .unit = "deg",
                                  .description = "vertical field of view (perspective)",
                                  .min = 1, .max = 120});
  }
};

struct View3DParams {
  int width = kDefaultPictureWidth;
  int height = 600;
  Background background = Background::white;
  bool outline = true;               ///< draw the box around the data's bounds
  bool scalar_bar = true;            ///< draw the colour legend of array-coloured props
  int multisamples = 4;              ///< anti-aliasing samples per pixel; 0: exact
  int turntable_frames = 0;          ///< frames of a full turn about the up axis
  CameraParams camera;

  template <class V>
  static void describe(V& v) {
    v(&View3DParams::width, {.key = "width", .unit = "px", .description = "picture width",
                             .min = 16, .max = 8192});
    v(&View3DParams::height, {.key = "height", .unit = "px", .description = "picture height",
                              .min = 16, .max = 8192});
    v(&View3DParams::background, {.key = "background",
                                  .description = "white (black text) or dark (white text)"});
    v(&View3DParams::outline, {.key = "outline", .description = "box around the data bounds"});
    v(&View3DParams::scalar_bar,
      {.key = "scalar_bar", .description = "colour legend for array-coloured props"});
    v(&View3DParams::multisamples, {.key = "multisamples",
                                    .description = "anti-aliasing samples per pixel; 0: none",
                                    .min = 0, .max = 16});
    v(&View3DParams::turntable_frames,
      {.key = "turntable_frames",
       .description = "frames of a full turn about the up axis (numbered PNGs); 0: none",
       .min = 0, .max = 3600});
    v(&View3DParams::camera, {.key = "camera", .description = "camera placement"});
  }
};

/// Range and choice checks of every key. Throws ParamError.
void validateView3DParams(const View3DParams& params);

/// Background and text/outline colours of View3DParams::background.
Rgb backgroundColor(Background background);
Rgb foregroundColor(Background background);

/// Places the renderer's active camera so that the sphere around `bounds` (xmin, xmax, ymin,
/// ymax, zmin, zmax) fits the picture (width x height px) at zoom 1, seen from the params'
/// azimuth and elevation; resets the clipping range.
void frameCamera(vtkRenderer* renderer, const std::array<double, 6>& bounds, int width,
                 int height, const CameraParams& params);

class Scene3D {
 public:
  /// Throws ParamError for bad params, std::runtime_error if no OpenGL context can be made.
  explicit Scene3D(const View3DParams& params);
  ~Scene3D();
  Scene3D(const Scene3D&) = delete;
  Scene3D& operator=(const Scene3D&) = delete;

  OffscreenRenderer& renderer();
  const View3DParams& params() const;

  /// Adds an actor or volume; the camera frames everything added.
  void add(vtkProp* prop);
  /// Frames and outlines this box (xmin, xmax, ymin, ymax, zmin, zmax) instead of the props'
  /// bounds (e.g. the whole grid around an isosurface).
  void setBounds(const std::array<double, 6>& bounds);
  /// Shows a colour legend for `colors` titled `title` (if params.scalar_bar).
  void setLegend(vtkScalarsToColors* colors, const std::string& title);
  /// Shows `title` centred at the top of the picture.
  void setTitle(const std::string& title);

  /// Frames the camera on the props' bounds (with the params' azimuth) and renders.
  RgbaImage render();
  void renderToPng(const std::filesystem::path& file);
  /// params.turntable_frames pictures, frame i at azimuth + 360 i / frames, written as
  /// <stem>_0000.png, <stem>_0001.png, ... (each atomically); returns the paths.
  std::vector<std::filesystem::path> renderTurntable(const std::filesystem::path& stem);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fluidviz
