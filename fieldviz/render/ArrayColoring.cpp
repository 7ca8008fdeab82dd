#include "fieldviz/render/ArrayColoring.h"

#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkLookupTable.h>
#include <vtkMapper.h>
#include <vtkPointData.h>

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fieldviz/render/ColorMap.h"
#include "fieldviz/render/ColorMapVtk.h"

namespace fluidviz {

namespace {

std::string describeArrays(vtkPointData* pd) {
  std::string s;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
    if (vtkDataArray* a = pd->GetArray(i))
      s += (s.empty() ? "" : ", ") + std::string(a->GetName() ? a->GetName() : "?") + "(" +
           std::to_string(a->GetNumberOfComponents()) + ")";
  return s.empty() ? "none" : s;
}

vtkDataArray* requireArray(vtkDataSet* data, const std::string& name) {
  vtkDataArray* a = data->GetPointData()->GetArray(name.c_str());
  if (a == nullptr)
    throw std::invalid_argument("no point array '" + name + "' to colour by; arrays present: " +
                                describeArrays(data->GetPointData()));
  const int c = a->GetNumberOfComponents();
  if (c != 1 && c != 3)
    throw std::invalid_argument("array '" + name + "' has " + std::to_string(c) +
                                " components; colouring needs 1 (value) or 3 (magnitude)");
  return a;
}

}  // namespace

std::array<double, 2> finitePointArrayRange(vtkDataSet* data, const std::string& name) {
  vtkDataArray* a = requireArray(data, name);
  const int c = a->GetNumberOfComponents();
  double lo = INFINITY, hi = -INFINITY;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
    double v = a->GetComponent(i, 0);
    if (c == 3) v = std::hypot(v, a->GetComponent(i, 1), a->GetComponent(i, 2));
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  if (!(lo <= hi)) throw std::invalid_argument("array '" + name + "' has no finite value");
  return {lo, hi};
}

std::array<double, 2> colorRange(vtkDataSet* data, const std::string& array,
                                 std::optional<double> rangeMin, std::optional<double> rangeMax) {
  std::array<double, 2> r{0.0, 1.0};
  if (!rangeMin || !rangeMax) r = finitePointArrayRange(data, array);
  if (rangeMin) r[0] = *rangeMin;
  if (rangeMax) r[1] = *rangeMax;
  if (r[0] == r[1] && !rangeMin && !rangeMax) {  // constant array: centre its colour
    const double pad = r[0] == 0.0 ? 1.0 : 0.5 * std::abs(r[0]);
    r = {r[0] - pad, r[1] + pad};
  }
  if (!(r[0] < r[1])) {
    std::ostringstream s;
    s << "colour range [" << r[0] << ", " << r[1] << "] of array '" << array
      << "' is empty: range_min must be below range_max";
    throw std::invalid_argument(s.str());
  }
  return r;
}

ArrayColoring colorByPointArray(vtkMapper* mapper, vtkDataSet* data, const std::string& array,
                                const std::string& colormap, std::optional<double> rangeMin,
                                std::optional<double> rangeMax) {
  vtkDataArray* a = requireArray(data, array);
  const std::array<double, 2> r = colorRange(data, array, rangeMin, rangeMax);
  ArrayColoring c;
  c.range[0] = r[0], c.range[1] = r[1];
  c.table = makeLookupTable(ColorMap::byName(colormap), r[0], r[1]);
  if (a->GetNumberOfComponents() == 3) c.table->SetVectorModeToMagnitude();
  c.title = a->GetNumberOfComponents() == 3 ? "|" + array + "|" : array;
  mapper->SetScalarVisibility(true);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(array.c_str());
  mapper->SetColorModeToMapScalars();
  mapper->SetLookupTable(c.table);
  mapper->UseLookupTableScalarRangeOn();
  return c;
}

}  // namespace fluidviz
