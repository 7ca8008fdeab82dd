#pragma once
// Colouring a mapper's input by one of its point arrays through a fluidviz colour map: the
// shared step of surface, particle and volume pictures (the legend shows the same table).
#include <array>
#include <optional>
#include <string>

#include <vtkLookupTable.h>
#include <vtkSmartPointer.h>

class vtkDataSet;
class vtkMapper;

namespace fluidviz {

struct ArrayColoring {
  vtkSmartPointer<vtkLookupTable> table;  ///< spans `range`; for the legend too
  double range[2] = {0.0, 1.0};           ///< values drawn with the map's first and last colour
  std::string title;                      ///< array name, "|name|" for vectors
};

/// Smallest and largest finite value of point array `array` of `data` (the magnitude for 3
/// components). Throws std::invalid_argument naming the array (and listing the arrays present)
/// if it is missing, has another component count, or has no finite value.
std::array<double, 2> finitePointArrayRange(vtkDataSet* data, const std::string& array);

/// Makes `mapper` colour its input by point array `array` through colour map `colormap`, over
/// [rangeMin, rangeMax] (each defaulting to the array's finite extreme; a constant array gets a
/// range around its value). Throws std::invalid_argument for a bad array (see above), an
/// unknown colour map, or rangeMin >= rangeMax.
ArrayColoring colorByPointArray(vtkMapper* mapper, vtkDataSet* data, const std::string& array,
                                const std::string& colormap, std::optional<double> rangeMin,
                                std::optional<double> rangeMax);

/// The range colorByPointArray uses (exposed for volume rendering, which has no vtkMapper).
std::array<double, 2> colorRange(vtkDataSet* data, const std::string& array,
                                 std::optional<double> rangeMin, std::optional<double> rangeMax);

}  // namespace fluidviz
