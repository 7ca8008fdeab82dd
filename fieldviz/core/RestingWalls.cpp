#include "fieldviz/core/RestingWalls.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace fluidviz {

std::string toString(DomainSide side) {
  switch (side) {
    case DomainSide::x_min: return "x_min";
    case DomainSide::x_max: return "x_max";
    case DomainSide::y_min: return "y_min";
    case DomainSide::y_max: return "y_max";
  }
  return "x_min";
}

bool RestingWalls::any() const {
  return maskedCount(solid) > 0 || std::count(sides.begin(), sides.end(), true) > 0;
}

PointMask restingSolidNodes(const VectorField& v, const PointMask& mask) {
  if (mask.empty()) return {};
  const double limit = SolidParams{}.solid_speed * maxFiniteSpeed(v);
  PointMask resting(mask.size(), 0);
  for (std::size_t n = 0; n < mask.size(); ++n)
    resting[n] = mask[n] && v.values[n].allFinite() && v.values[n].norm() <= limit;
  if (maskedCount(resting) == 0) resting.clear();
  return resting;
}

std::string restingSidesText(const std::array<bool, 4>& sides) {
  std::string text;
  for (DomainSide s : kDomainSides)
    if (sides[static_cast<int>(s)]) text += (text.empty() ? "" : " ") + toString(s);
  return text;
}

std::array<bool, 4> parseRestingSides(const std::string& text, const std::string& source) {
  std::array<bool, 4> sides{};
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    const auto* found = std::find_if(kDomainSides.begin(), kDomainSides.end(),
                                     [&](DomainSide s) { return toString(s) == word; });
    if (found == kDomainSides.end())
      throw std::invalid_argument(source + ": field data " + kRestingSidesFieldData + " names '" +
                                  word + "'; allowed: x_min, x_max, y_min, y_max");
    sides[static_cast<int>(*found)] = true;
  }
  return sides;
}

}  // namespace fluidviz
