#pragma once
// When to run a particle loop on several threads. A parallel region costs a few microseconds
// on an idle machine but up to a scheduler time slice when the cores are shared, because every
// region ends in a barrier; small particle counts therefore run on one thread.
#include <cstdint>

namespace fluidviz::particles {

/// Loops over fewer items than this run serially (`#pragma omp parallel for if(...)`).
inline constexpr std::int64_t kParallelMinItems = 8192;

}  // namespace fluidviz::particles
