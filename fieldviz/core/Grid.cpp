#include "fieldviz/core/Grid.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fluidviz {

bool Grid::contains(const Vec3& p) const {
  const Vec3 q = toIndexSpace(p);
  const double eps = 1e-9;
  for (int a = 0; a < 3; ++a)
    if (q[a] < -eps || q[a] > dims[a] - 1 + eps) return false;
  return true;
}

bool Grid::sameShape(const Grid& o) const {
  if (dims != o.dims) return false;
  for (int a = 0; a < 3; ++a) {
    const double tol = 1e-9 * std::max(1.0, std::abs(spacing[a]));
    if (std::abs(origin[a] - o.origin[a]) > tol || std::abs(spacing[a] - o.spacing[a]) > tol)
      return false;
  }
  return true;
}

void Grid::validate() const {
  static const char* axis = "xyz";
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 1)
      throw std::invalid_argument(std::string("grid dims along ") + axis[a] + " is " +
                                  std::to_string(dims[a]) + "; allowed: >= 1");
    if (!(spacing[a] > 0.0) || !std::isfinite(spacing[a]))
      throw std::invalid_argument(std::string("grid spacing along ") + axis[a] + " is " +
                                  std::to_string(spacing[a]) + "; allowed: finite and > 0");
    if (!std::isfinite(origin[a]))
      throw std::invalid_argument(std::string("grid origin along ") + axis[a] + " is not finite");
  }
}

std::string Grid::describe() const {
  std::ostringstream s;
  s << dims[0] << "x" << dims[1] << "x" << dims[2] << " nodes, spacing (" << spacing[0] << ", "
    << spacing[1] << ", " << spacing[2] << ")";
  return s.str();
}

}  // namespace fluidviz
