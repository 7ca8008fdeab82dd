#pragma once
// Named colour maps: t in [0, 1] -> RGB by piecewise-linear interpolation of published control
// points. No VTK here (ColorMapVtk.h adapts a map to a vtkLookupTable).
//
// References:
//   viridis, inferno: S. van der Walt, N. Smith, "A better default colormap for Matplotlib",
//     SciPy 2015; values from matplotlib 3.6 `_cm_listed.py` (256-entry tables).
//   coolwarm: K. Moreland, "Diverging Color Maps for Scientific Visualization", ISVC 2009,
//     LNCS 5876, pp. 92-103; the 33-sample table as published (matplotlib `_cm.py`).
#include <array>
#include <string>
#include <vector>

namespace fluidviz {

class ColorMap {
 public:
  using Color = std::array<double, 3>;  ///< RGB, each channel in [0, 1]

  /// The map called `name`; throws std::invalid_argument listing the allowed names otherwise.
  static const ColorMap& byName(const std::string& name);
  /// All names byName accepts, in a fixed order.
  static std::vector<std::string> names();

  /// Evenly spaced control points from t = 0 to t = 1 (at least 2).
  ColorMap(std::string name, std::vector<Color> controlPoints);

  const std::string& name() const { return name_; }
  /// Colour at t; t is clamped to [0, 1], NaN gives the colour at 0.
  Color map(double t) const;
  const std::vector<Color>& controlPoints() const { return points_; }

 private:
  std::string name_;
  std::vector<Color> points_;
};

}  // namespace fluidviz
