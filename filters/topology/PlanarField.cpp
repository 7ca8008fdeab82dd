#include "filters/topology/PlanarField.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fieldviz/core/Params.h"

namespace fluidviz::topology {

BilinearPatch BilinearPatch::fromCorners(const Vec2& f00, const Vec2& f10, const Vec2& f01,
                                         const Vec2& f11) {
  return {f00, f10 - f00, f01 - f00, f11 - f10 - f01 + f00};
}

Mat2 BilinearPatch::jacobian(double s, double t) const {
  Mat2 j;
  j.col(0) = c1 + c3 * t;
  j.col(1) = c2 + c3 * s;
  return j;
}

PlanarField::PlanarField(const VectorField& field, int slice) : grid_(field.grid) {
  grid_.validate();
  if (grid_.dims[0] < 2 || grid_.dims[1] < 2)
    throw std::invalid_argument("topology of '" + field.name + "' needs at least 2 x 2 nodes, " +
                                "the grid has " + grid_.describe());
  if (field.values.size() != grid_.nodeCount())
    throw std::invalid_argument("field '" + field.name + "' has " +
                                std::to_string(field.values.size()) + " values for " +
                                std::to_string(grid_.nodeCount()) + " nodes");
  slice_ = grid_.is2D() ? 0 : slice;
  if (slice_ < 0 || slice_ >= grid_.dims[2])
    throw ParamError("slice_index", "is " + std::to_string(slice) + "; allowed: [0, " +
                                        std::to_string(grid_.dims[2] - 1) + "] for the grid " +
                                        grid_.describe());
  nx_ = grid_.dims[0];
  ny_ = grid_.dims[1];
  u_.resize(static_cast<std::size_t>(nx_) * ny_);
  v_.resize(u_.size());
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const Vec3& w = field.values[grid_.index(i, j, slice_)];
      const std::size_t n = static_cast<std::size_t>(j) * nx_ + i;
      u_[n] = w.x() / grid_.spacing[0];
      v_[n] = w.y() / grid_.spacing[1];
    }
  buildGradientTable();
}

std::array<int, 2> PlanarField::cellOf(const Vec2& q) const {
  const int i = std::clamp(static_cast<int>(std::floor(q.x())), 0, nx_ - 2);
  const int j = std::clamp(static_cast<int>(std::floor(q.y())), 0, ny_ - 2);
  return {i, j};
}

BilinearPatch PlanarField::cellPatch(int i, int j) const {
  return BilinearPatch::fromCorners(node(i, j), node(i + 1, j), node(i, j + 1),
                                    node(i + 1, j + 1));
}

Vec2 PlanarField::operator()(const Vec2& q) const {
  const double x = std::clamp(q.x(), 0.0, double(nx_ - 1));
  const double y = std::clamp(q.y(), 0.0, double(ny_ - 1));
  const auto c = cellOf({x, y});
  const double s = x - c[0], t = y - c[1];
  return (1 - s) * (1 - t) * node(c[0], c[1]) + s * (1 - t) * node(c[0] + 1, c[1]) +
         (1 - s) * t * node(c[0], c[1] + 1) + s * t * node(c[0] + 1, c[1] + 1);
}

Mat2 PlanarField::jacobianFiniteDifference(const Vec2& q) const {
  Mat2 j;
  const double hi[2] = {double(nx_ - 1), double(ny_ - 1)};
  for (int a = 0; a < 2; ++a) {
    Vec2 lo = q, up = q;
    lo[a] = std::max(q[a] - 1.0, 0.0);
    up[a] = std::min(q[a] + 1.0, hi[a]);
    j.col(a) = ((*this)(up) - (*this)(lo)) / (up[a] - lo[a]);
  }
  return j;
}

Mat2 PlanarField::jacobianInterpolant(const Vec2& q, const std::array<int, 2>& cell) const {
  const double s = std::clamp(q.x() - cell[0], 0.0, 1.0);
  const double t = std::clamp(q.y() - cell[1], 0.0, 1.0);
  return cellPatch(cell[0], cell[1]).jacobian(s, t);
}

namespace {
/// Cells (along one axis, `count` cells) whose closed interval holds x: two on an interior node.
std::vector<int> cellsHolding(double x, int count) {
  constexpr double kOnNode = 1e-9;  // cells
  const int k = static_cast<int>(std::lround(x));
  if (std::abs(x - k) <= kOnNode && k > 0 && k < count) return {k - 1, k};
  return {std::clamp(static_cast<int>(std::floor(x)), 0, count - 1)};
}
}  // namespace

Mat2 PlanarField::jacobianAtPoint(const Vec2& q) const {
  const std::vector<int> is = cellsHolding(q.x(), nx_ - 1), js = cellsHolding(q.y(), ny_ - 1);
  Mat2 sum = Mat2::Zero();
  for (int j : js)
    for (int i : is) sum += jacobianInterpolant(q, {i, j});
  return sum / static_cast<double>(is.size() * js.size());
}

Mat2 PlanarField::toWorldJacobian(const Mat2& j_index) const {
  const double h[2] = {grid_.spacing[0], grid_.spacing[1]};
  Mat2 j;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) j(r, c) = j_index(r, c) * h[r] / h[c];
  return j;
}

void PlanarField::buildGradientTable() {
  std::vector<double> norms(static_cast<std::size_t>(nx_) * ny_);
#pragma omp parallel for schedule(static)
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      // Masked (NaN) nodes add nothing: one NaN would otherwise spread through the summed-area
      // table and leave every point's gradient scale NaN (all points degenerate).
      const double n = toWorldJacobian(jacobianFiniteDifference(Vec2(i, j))).squaredNorm();
      norms[static_cast<std::size_t>(j) * nx_ + i] = std::isfinite(n) ? n : 0.0;
    }
  jacobian_rms_ = WindowRms(norms, nx_, ny_);
}

double PlanarField::gradientScale(const Vec2& q, double radius) const {
  return jacobian_rms_.around(q, radius);
}

Vec3 PlanarField::toWorld(const Vec2& q) const {
  return {grid_.origin[0] + q.x() * grid_.spacing[0], grid_.origin[1] + q.y() * grid_.spacing[1],
          grid_.origin[2] + slice_ * grid_.spacing[2]};
}

Vec2 PlanarField::toIndex(const Vec3& p) const {
  return {(p.x() - grid_.origin[0]) / grid_.spacing[0],
          (p.y() - grid_.origin[1]) / grid_.spacing[1]};
}

Vec2 PlanarField::toWorldDirection(const Vec2& d) const {
  return Vec2(d.x() * grid_.spacing[0], d.y() * grid_.spacing[1]).normalized();
}

double PlanarField::distanceToBoundary(const Vec2& q) const {
  return std::min({q.x(), q.y(), nx_ - 1 - q.x(), ny_ - 1 - q.y()});
}

}  // namespace fluidviz::topology
