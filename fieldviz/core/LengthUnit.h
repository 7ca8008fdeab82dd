#pragma once
// The length unit of a grid's coordinates, for printed sizes (length, area, volume) and picture
// labels (speed in unit/s). Only a name: nothing is converted. The declaration below drives the
// --units option, its help and its row in docs/units.md.
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz {

/// The names --units and length_unit allow (e.g. m, mm, cells, deg, lattice_units); no spaces,
/// so that printed sizes stay one word per value.
constexpr const char* kLengthUnitAllowed = "1 to 16 letters, digits or _^/-.";

struct LengthUnitParams {
  std::string units = "m";

  template <class V>
  static void describe(V& v) {
    v(&LengthUnitParams::units,
      {.key = "units",
       .description = std::string("length unit of the grid's coordinates in printed sizes and "
                                  "picture labels, only a name (nothing is converted): ") +
                      kLengthUnitAllowed +
                      "; when not given: the file's field-data string length_unit, else m"});
  }
};

/// True when `name` is an allowed unit name (kLengthUnitAllowed).
bool isLengthUnitName(const std::string& name);

/// Throws ParamError("units", "is 'a b'; allowed ...") for a name that is not allowed.
void validateLengthUnit(const LengthUnitParams& params);

}  // namespace fluidviz
