#pragma once
// Round tick values for legends and axes: multiples of 1, 2 or 5 x 10^k inside a range, about
// five of them (Heckbert 1990, "Nice numbers for graph labels", Graphics Gems I), and a printf
// format that prints them with just the digits their step needs.
#include <string>
#include <vector>

namespace fluidviz {

struct RoundTicks {
  double step = 0;             ///< 1, 2 or 5 x 10^k
  std::vector<double> values;  ///< the multiples of step in [lo, hi], ascending; exact 0 kept
};

/// Ticks of [lo, hi] (lo < hi, both finite): the step of 1/2/5 x 10^k whose tick count is
/// nearest `target` (3 to 7 ticks where possible). A bound within 1e-9 of the range from a
/// multiple counts as that multiple, so that round-off does not drop the 0 of [-1e-17, 5].
/// Throws std::invalid_argument for an empty or non-finite range.
RoundTicks roundTicks(double lo, double hi, int target = 5);

/// printf format for the ticks: fixed notation with as many decimals as the step needs
/// ("%.0f" for a step of 5, "%.2f" for 0.05), exponent notation ("%.2e") when the values are
/// below 1e-3 or above 1e6 in magnitude.
std::string tickLabelFormat(const RoundTicks& ticks);

}  // namespace fluidviz
