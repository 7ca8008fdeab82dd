#include "fieldviz/core/Params.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace fluidviz {

std::string joinNames(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

std::string describeRange(const ParamInfo& info) {
  std::ostringstream s;
  s.precision(10);
  if (!info.choices.empty()) {
    s << "one of {" << joinNames(info.choices) << "}";
    return s.str();
  }
  const bool lo = std::isfinite(info.min), hi = std::isfinite(info.max);
  if (lo && hi)
    s << (info.minExclusive ? "(" : "[") << info.min << ", " << info.max
      << (info.maxExclusive ? ")" : "]");
  else if (lo)
    s << (info.minExclusive ? "> " : ">= ") << info.min;
  else if (hi)
    s << (info.maxExclusive ? "< " : "<= ") << info.max;
  else
    s << "any";
  return s.str();
}

bool inRange(double v, const ParamInfo& info) {
  const bool aboveMin = info.minExclusive ? v > info.min : v >= info.min;
  const bool belowMax = info.maxExclusive ? v < info.max : v <= info.max;
  return std::isfinite(v) && aboveMin && belowMax;
}

std::string formatNumber(double value, int digits) {
  std::ostringstream s;
  s.precision(digits);
  s << value;
  return s.str();
}

double withoutRoundOff(double value) {
  if (!std::isfinite(value) || value == 0) return value;
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  return std::strtod(text, nullptr);
}

}  // namespace fluidviz
