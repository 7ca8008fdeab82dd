#include "fieldviz/core/LengthUnit.h"

#include <cctype>

namespace fluidviz {

bool isLengthUnitName(const std::string& name) {
  if (name.empty() || name.size() > 16) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) &&
        std::string("_^/-.").find(c) == std::string::npos)
      return false;
  return true;
}

void validateLengthUnit(const LengthUnitParams& params) {
  if (!isLengthUnitName(params.units))
    throw ParamError("units", "is '" + params.units + "'; allowed: " + kLengthUnitAllowed);
}

}  // namespace fluidviz
