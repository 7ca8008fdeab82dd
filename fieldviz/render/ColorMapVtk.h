#pragma once
// ColorMap -> vtkLookupTable, for mappers and scalar bars.
#include <vtkSmartPointer.h>

#include <array>

#include "fieldviz/render/ColorMap.h"

class vtkLookupTable;

namespace fluidviz {

/// A lookup table of `entries` colours, entry i = map(i / (entries - 1)), spanning values
/// [rangeMin, rangeMax] (rangeMin < rangeMax). Values outside the range get the end colours;
/// NaN gets `nanColor`. entries in [2, 65536].
vtkSmartPointer<vtkLookupTable> makeLookupTable(const ColorMap& map, double rangeMin,
                                                double rangeMax, int entries = 256,
                                                const std::array<double, 3>& nanColor = {0.5, 0.5,
                                                                                         0.5});

}  // namespace fluidviz
