#pragma once
// Volume rendering of a scalar field on a 3D grid: emission-absorption ray casting with a colour
// map and an opacity ramp as transfer functions.
//   mapper "auto": vtkSmartVolumeMapper; under OSMesa llvmpipe (OpenGL 4.5 core) it picks GPU
//                  ray casting (checked by the tests), on anything else its own fall-back.
//   mapper "gpu":  vtkGPUVolumeRayCastMapper.    mapper "cpu": vtkFixedPointVolumeRayCastMapper.
// Opacity: 0 below range_min + opacity_start (range_max - range_min), rising linearly to
// `opacity` at range_max, per grid spacing of ray length (vtkVolumeProperty's scalar opacity
// unit distance), so the look does not change with the grid resolution. Nodes with NaN (resampled
// nodes without particle support) are drawn fully transparent.
#include <optional>
#include <string>

#include <vtkColorTransferFunction.h>
#include <vtkVolume.h>
#include <vtkSmartPointer.h>

#include "fieldviz/core/Params.h"
#include "fieldviz/render/ColorMap.h"

class vtkImageData;

namespace fluidviz {

enum class VolumeMapper { automatic, gpu, cpu };
constexpr std::array<Choice<VolumeMapper>, 3> paramChoices(VolumeMapper) {
  return {{{VolumeMapper::automatic, "auto"}, {VolumeMapper::gpu, "gpu"}, {VolumeMapper::cpu, "cpu"}}};
}

struct VolumeStyle {
  std::string colormap = "inferno";  ///< one of ColorMap::names()
  std::optional<double> range_min;   ///< value of the first colour; empty: array minimum
  std::optional<double> range_max;   ///< value of the last colour; empty: array maximum
  double opacity = 0.3;              ///< opacity at range_max per grid spacing
  double opacity_start = 0.1;        ///< fraction of the range that stays transparent
  VolumeMapper mapper = VolumeMapper::automatic;
  bool shade = false;                ///< gradient-based lighting of the volume

  template <class V>
  static void describe(V& v) {
    v(&VolumeStyle::colormap,
      {.key = "colormap", .description = "colour map", .choices = ColorMap::names()});
    v(&VolumeStyle::range_min,
      {.key = "range_min", .description = "value of the first colour; empty: array minimum"});
    v(&VolumeStyle::range_max,
      {.key = "range_max", .description = "value of the last colour; empty: array maximum"});
    v(&VolumeStyle::opacity, {.key = "opacity",
                              .description = "opacity at range_max per grid spacing of ray",
                              .min = 0, .max = 1, .minExclusive = true});
    v(&VolumeStyle::opacity_start,
      {.key = "opacity_start", .description = "fraction of the range left transparent",
       .min = 0, .max = 1, .maxExclusive = true});
    v(&VolumeStyle::mapper,
      {.key = "mapper",
       .description = "auto (vtkSmartVolumeMapper), gpu (GPU ray casting) or cpu (fixed point)"});
    v(&VolumeStyle::shade, {.key = "shade", .description = "gradient-based lighting"});
  }
};

struct VolumeProp {
  vtkSmartPointer<vtkVolume> volume;
  vtkSmartPointer<vtkColorTransferFunction> colors;  ///< for the legend
  double range[2] = {0.0, 1.0};
  std::string title;  ///< the array name
};

/// Volume of point array `array` (1 component) of a 3D image; its non-finite values are drawn
/// transparent. Throws ParamError for bad style keys, std::invalid_argument naming the array if
/// it is missing, has another component count or no finite value, or if the image is 2D.
VolumeProp makeVolume(vtkImageData* image, const std::string& array, const VolumeStyle& style);

}  // namespace fluidviz
