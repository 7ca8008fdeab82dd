#pragma once
// Summary numbers of a field that tests compare against (step scales, Mach numbers).
#include <algorithm>

#include "fieldviz/core/Field.h"

namespace fluidviz::testing {

/// Largest |v| over the field's nodes.
inline double maxSpeed(const VectorField& f) {
  double m = 0;
  for (const Vec3& v : f.values) m = std::max(m, v.norm());
  return m;
}

}  // namespace fluidviz::testing
