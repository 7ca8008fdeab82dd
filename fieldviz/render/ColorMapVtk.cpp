#include "fieldviz/render/ColorMapVtk.h"

#include <vtkLookupTable.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fluidviz {

vtkSmartPointer<vtkLookupTable> makeLookupTable(const ColorMap& map, double rangeMin,
                                                double rangeMax, int entries,
                                                const std::array<double, 3>& nanColor) {
  if (!(std::isfinite(rangeMin) && std::isfinite(rangeMax) && rangeMin < rangeMax))
    throw std::invalid_argument("lookup table for \"" + map.name() + "\": range [" +
                                std::to_string(rangeMin) + ", " + std::to_string(rangeMax) +
                                "] must be finite with min < max");
  if (entries < 2 || entries > 65536)
    throw std::invalid_argument("lookup table for \"" + map.name() + "\": " +
                                std::to_string(entries) + " entries is outside [2, 65536]");
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(entries);
  table->SetTableRange(rangeMin, rangeMax);
  table->SetNanColor(nanColor[0], nanColor[1], nanColor[2], 1.0);
  table->UseBelowRangeColorOff();
  table->UseAboveRangeColorOff();
  for (int i = 0; i < entries; ++i) {
    const ColorMap::Color c = map.map(static_cast<double>(i) / (entries - 1));
    table->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  return table;
}

}  // namespace fluidviz
