#include "filters/lic/PixelVelocity.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "fieldviz/core/Params.h"

namespace fluidviz::lic {

namespace {

void checkFinite(const VectorField& f) {
  for (int k = 0; k < f.grid.dims[2]; ++k)
    for (int j = 0; j < f.grid.dims[1]; ++j)
      for (int i = 0; i < f.grid.dims[0]; ++i)
        if (!f.values[f.grid.index(i, j, k)].allFinite())
          throw NonFiniteFieldError(f.name, {i, j, k});
}

// Layer below slice_height and the linear weight of the layer above.
std::pair<int, double> sliceLayer(const Grid& g, double slice_height) {
  if (g.is2D()) return {0, 0.0};
  const double z0 = g.origin[2], z1 = g.upperCorner().z();
  if (!(slice_height >= z0 && slice_height <= z1)) {
    std::ostringstream s;
    s.precision(10);
    s << "is " << slice_height << " m, outside the grid's z range [" << z0 << ", " << z1 << "]";
    throw ParamError("slice_height", s.str());
  }
  const double q = (slice_height - z0) / g.spacing[2];
  const int k = std::min(static_cast<int>(q), g.dims[2] - 2);
  return {k, q - k};
}

}  // namespace

namespace {

std::string nonFiniteMessage(const std::string& field, const std::array<int, 3>& node,
                             const std::string& remedy) {
  std::ostringstream s;
  s << "LIC: vector field '" << field << "' has a NaN or infinite value at node (" << node[0]
    << ", " << node[1] << ", " << node[2] << "); all values must be finite (" << remedy << ")";
  return s.str();
}

}  // namespace

NonFiniteFieldError::NonFiniteFieldError(std::string field, std::array<int, 3> node)
    : std::invalid_argument(nonFiniteMessage(field, node, maskRemedy("mask_speed"))),
      field_(std::move(field)),
      node_(node) {}

std::string NonFiniteFieldError::message(const std::string& remedy) const {
  return nonFiniteMessage(field_, node_, remedy);
}

std::string NonFiniteFieldError::maskRemedy(const std::string& maskOption) {
  return "give solid regions zero velocity and use " + maskOption + " to mask them";
}

PixelVelocity::PixelVelocity(const VectorField& field, int width, int height, double slice_height,
                             bool speedScaled)
    : width_(width), height_(height), speedScaled_(speedScaled) {
  const Grid& g = field.grid;
  g.validate();
  if (g.dims[0] < 2 || g.dims[1] < 2)
    throw std::invalid_argument("LIC: vector field '" + field.name + "' needs at least 2 x 2 "
                                "nodes in x and y, has " + std::to_string(g.dims[0]) + " x " +
                                std::to_string(g.dims[1]));
  if (field.values.size() != g.nodeCount())
    throw std::invalid_argument("LIC: vector field '" + field.name + "' has " +
                                std::to_string(field.values.size()) + " values for " +
                                std::to_string(g.nodeCount()) + " grid nodes");
  checkFinite(field);
  nx_ = g.dims[0];
  ny_ = g.dims[1];
  toIndexX_ = (nx_ - 1) / double(width);
  toIndexY_ = (ny_ - 1) / double(height);
  // World velocity -> pixel velocity: the image spans (n - 1) spacing metres in width pixels.
  const double sx = width / ((nx_ - 1) * g.spacing[0]);
  const double sy = height / ((ny_ - 1) * g.spacing[1]);
  const auto [k, t] = sliceLayer(g, slice_height);
  v_.resize(2 * static_cast<std::size_t>(nx_) * ny_);
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      Vec3 w = field.values[g.index(i, j, k)];
      if (t > 0.0) w = (1 - t) * w + t * field.values[g.index(i, j, k + 1)];
      const std::size_t n = static_cast<std::size_t>(j) * nx_ + i;
      v_[2 * n] = w.x() * sx;
      v_[2 * n + 1] = w.y() * sy;
      maxSpeed_ = std::max(maxSpeed_, std::hypot(v_[2 * n], v_[2 * n + 1]));
    }
  invMaxSpeed_ = maxSpeed_ > 0 ? 1.0 / maxSpeed_ : 0.0;
  stopSpeed2_ = (1e-9 * maxSpeed_) * (1e-9 * maxSpeed_);
}

}  // namespace fluidviz::lic
