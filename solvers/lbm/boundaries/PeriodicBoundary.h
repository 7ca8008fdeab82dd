#pragma once
// Periodic sides: a population leaving the box through one side enters through the opposite one,
// i.e. node indices along a periodic axis are taken modulo the node count.
namespace fluidviz::lbm {

/// i in [-1, n] (one step outside at most) mapped back into [0, n).
inline int wrapPeriodic(int i, int n) { return i < 0 ? i + n : (i >= n ? i - n : i); }

}  // namespace fluidviz::lbm
