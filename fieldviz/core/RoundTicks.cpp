#include "fieldviz/core/RoundTicks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fluidviz {

namespace {

std::vector<double> multiplesIn(double lo, double hi, double step) {
  const double slack = 1e-9 * (hi - lo) / step;  // in steps
  const double first = std::ceil(lo / step - slack);
  const double last = std::floor(hi / step + slack);
  std::vector<double> values;
  for (double k = first; k <= last; k += 1) values.push_back(k == 0 ? 0.0 : k * step);
  return values;
}

}  // namespace

RoundTicks roundTicks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw std::invalid_argument("round ticks: the range [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "] is empty or not finite");
  const double decade = std::pow(10.0, std::floor(std::log10((hi - lo) / std::max(target, 2))));
  RoundTicks best;
  int bestMiss = std::numeric_limits<int>::max();
  for (double scale : {0.1, 1.0, 10.0})
    for (double mantissa : {1.0, 2.0, 5.0}) {
      const double step = mantissa * decade * scale;
      std::vector<double> values = multiplesIn(lo, hi, step);
      const int count = static_cast<int>(values.size());
      const int miss = std::abs(count - target) + (count < 2 ? 100 : 0);
      if (miss < bestMiss) {
        bestMiss = miss;
        best = {step, std::move(values)};
      }
    }
  return best;
}

std::string tickLabelFormat(const RoundTicks& ticks) {
  double magnitude = 0;
  for (double v : ticks.values) magnitude = std::max(magnitude, std::abs(v));
  if (magnitude >= 1e6 || (magnitude > 0 && magnitude < 1e-3)) {
    // Enough mantissa digits to tell neighbouring ticks apart.
    const int digits = std::clamp(
        static_cast<int>(std::ceil(std::log10(magnitude / ticks.step) - 1e-9)), 1, 12);
    return "%." + std::to_string(digits) + "e";
  }
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(ticks.step) - 1e-9)), 0, 12);
  return "%." + std::to_string(decimals) + "f";
}

}  // namespace fluidviz
