#include "filters/topology/ScalarCriticalPoints.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fieldviz/core/Params.h"
#include "filters/topology/WindowRms.h"
#include "filters/topology/ZeroClustering.h"

namespace fluidviz::topology {

namespace {

/// One z-slice of a scalar field with nodal central-difference derivatives (world units).
class ScalarSlice {
 public:
  ScalarSlice(const ScalarField& f, int slice) : grid_(f.grid) {
    grid_.validate();
    if (grid_.dims[0] < 3 || grid_.dims[1] < 3)
      throw std::invalid_argument("critical points of '" + f.name + "' need at least 3 x 3 "
                                  "nodes, the grid has " + grid_.describe());
    if (f.values.size() != grid_.nodeCount())
      throw std::invalid_argument("field '" + f.name + "' has " + std::to_string(f.values.size()) +
                                  " values for " + std::to_string(grid_.nodeCount()) + " nodes");
    slice_ = grid_.is2D() ? 0 : slice;
    if (slice_ < 0 || slice_ >= grid_.dims[2])
      throw ParamError("slice_index", "is " + std::to_string(slice) + "; allowed: [0, " +
                                          std::to_string(grid_.dims[2] - 1) + "]");
    nx_ = grid_.dims[0];
    ny_ = grid_.dims[1];
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) values_.push_back(f.values[grid_.index(i, j, slice_)]);
    gradient_.resize(values_.size());
    hessian_.resize(values_.size());
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) computeDerivatives(i, j);
    buildHessianTable();
  }

  /// RMS Frobenius norm of the nodal Hessians in the square window of half-width `radius`
  /// cells around q (summed-area table), the scale det H is judged against.
  double hessianScale(const Vec2& q, double radius) const { return hessian_rms_.around(q, radius); }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double value(int i, int j) const { return values_[id(i, j)]; }
  std::size_t id(int i, int j) const { return static_cast<std::size_t>(j) * nx_ + i; }
  const Mat2& nodeHessian(int i, int j) const { return hessian_[id(i, j)]; }

  /// Bilinear interpolation of the nodal gradient and Hessian at index-space q.
  std::pair<Vec2, Mat2> derivativesAt(const Vec2& q) const {
    const int i = std::clamp(static_cast<int>(std::floor(q.x())), 0, nx_ - 2);
    const int j = std::clamp(static_cast<int>(std::floor(q.y())), 0, ny_ - 2);
    const double s = std::clamp(q.x() - i, 0.0, 1.0), t = std::clamp(q.y() - j, 0.0, 1.0);
    const double w[4] = {(1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t};
    const std::size_t n[4] = {id(i, j), id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)};
    Vec2 g = Vec2::Zero();
    Mat2 h = Mat2::Zero();
    for (int k = 0; k < 4; ++k) {
      g += w[k] * gradient_[n[k]];
      h += w[k] * hessian_[n[k]];
    }
    return {g, h};
  }
  Vec3 toWorld(const Vec2& q) const {
    return {grid_.origin[0] + q.x() * grid_.spacing[0], grid_.origin[1] + q.y() * grid_.spacing[1],
            grid_.origin[2] + slice_ * grid_.spacing[2]};
  }
  double dx() const { return grid_.spacing[0]; }
  double dy() const { return grid_.spacing[1]; }

 private:
  // Central differences (one-sided at the boundary) of the values and of the gradient.
  void computeDerivatives(int i, int j) {
    const int il = std::max(i - 1, 0), ir = std::min(i + 1, nx_ - 1);
    const int jl = std::max(j - 1, 0), jr = std::min(j + 1, ny_ - 1);
    const double hx = (ir - il) * dx(), hy = (jr - jl) * dy();
    gradient_[id(i, j)] = {(value(ir, j) - value(il, j)) / hx, (value(i, jr) - value(i, jl)) / hy};
    Mat2 h;
    const int ci = std::clamp(i, 1, nx_ - 2), cj = std::clamp(j, 1, ny_ - 2);
    h(0, 0) = (value(ci + 1, j) - 2 * value(ci, j) + value(ci - 1, j)) / (dx() * dx());
    h(1, 1) = (value(i, cj + 1) - 2 * value(i, cj) + value(i, cj - 1)) / (dy() * dy());
    h(0, 1) = h(1, 0) = (value(ir, jr) - value(ir, jl) - value(il, jr) + value(il, jl)) / (hx * hy);
    hessian_[id(i, j)] = h;
  }

  void buildHessianTable() {
    std::vector<double> squares(hessian_.size());
    for (std::size_t n = 0; n < hessian_.size(); ++n) squares[n] = hessian_[n].squaredNorm();
    hessian_rms_ = WindowRms(squares, nx_, ny_);
  }

  Grid grid_;
  int slice_ = 0, nx_ = 0, ny_ = 0;
  std::vector<double> values_;
  std::vector<Vec2> gradient_;
  std::vector<Mat2> hessian_;
  WindowRms hessian_rms_;  // of |H|_F
};

/// Neighbour is "lower" than the centre, ties broken by node number (simulation of simplicity).
bool lower(const ScalarSlice& s, int i, int j, int ni, int nj) {
  const double a = s.value(ni, nj), c = s.value(i, j);
  return a < c || (a == c && s.id(ni, nj) < s.id(i, j));
}

/// Sign changes of f(neighbour) - f(node) around the node's link in the Freudenthal
/// triangulation.
int linkSignChanges(const ScalarSlice& s, int i, int j) {
  static const int di[6] = {1, 1, 0, -1, -1, 0};
  static const int dj[6] = {0, 1, 1, 0, -1, -1};
  bool low[6];
  for (int k = 0; k < 6; ++k) low[k] = lower(s, i, j, i + di[k], j + dj[k]);
  int changes = 0;
  for (int k = 0; k < 6; ++k) changes += low[k] != low[(k + 1) % 6];
  return changes;
}

/// Newton refinement from a node; keeps the node if the iteration leaves its neighbourhood.
Vec2 refineLocation(const ScalarSlice& s, const Vec2& start) {
  Vec2 q = start;
  const Vec2 toIndex(1.0 / s.dx(), 1.0 / s.dy());
  for (int it = 0; it < 20; ++it) {
    const auto [g, h] = s.derivativesAt(q);
    if (h.determinant() == 0.0) return start;
    const Vec2 step = (h.inverse() * g).cwiseProduct(toIndex);  // world -> cells
    if (!step.allFinite()) return start;
    q -= step;
    if ((q - start).cwiseAbs().maxCoeff() > 2.0) return start;
    if (step.norm() < 1e-12) break;
  }
  return q;
}

struct FlaggedNode {
  int i, j, index;
};

ScalarCriticalPoint classify(const ScalarSlice& s, const std::vector<FlaggedNode>& flagged,
                             const std::vector<int>& members, const TopologyParams& params) {
  ScalarCriticalPoint p;
  Vec2 q = Vec2::Zero();
  for (int m : members) {
    p.index += flagged[m].index;
    q += Vec2(flagged[m].i, flagged[m].j);
  }
  q /= static_cast<double>(members.size());
  p.node = {flagged[members.front()].i, flagged[members.front()].j};
  p.cluster_size = static_cast<int>(members.size());
  if (members.size() == 1) q = refineLocation(s, q);
  p.position = s.toWorld(q);
  p.hessian = s.derivativesAt(q).second;
  const double g = s.hessianScale(q, params.gradient_scale_radius);
  p.det = p.hessian.determinant();
  p.trace = p.hessian.trace();
  p.normalized_det = g > 0 ? p.det / (g * g) : 0.0;
  const bool nonDegenerate = std::abs(p.det) > params.det_threshold * g * g && p.det != 0.0;
  p.morse = nonDegenerate && p.cluster_size == 1 && p.index == (p.det > 0 ? 1 : -1);
  if (p.morse)
    p.type = p.det < 0 ? ScalarCriticalType::Saddle
                       : (p.trace > 0 ? ScalarCriticalType::Minimum : ScalarCriticalType::Maximum);
  else
    p.type = p.index <= -1 ? ScalarCriticalType::DegenerateSaddle : ScalarCriticalType::Degenerate;
  return p;
}
}  // namespace

std::string toString(ScalarCriticalType t) {
  switch (t) {
    case ScalarCriticalType::Minimum: return "minimum";
    case ScalarCriticalType::Maximum: return "maximum";
    case ScalarCriticalType::Saddle: return "saddle";
    case ScalarCriticalType::DegenerateSaddle: return "degenerate_saddle";
    case ScalarCriticalType::Degenerate: return "degenerate";
  }
  return "degenerate";
}

std::vector<ScalarCriticalPoint> findScalarCriticalPoints(const ScalarField& f,
                                                          const TopologyParams& params) {
  validateTopologyParams(params);
  const ScalarSlice s(f, params.slice_index);
  std::vector<FlaggedNode> flagged;
  for (int j = 1; j < s.ny() - 1; ++j)
    for (int i = 1; i < s.nx() - 1; ++i) {
      const int changes = linkSignChanges(s, i, j);
      if (changes != 2) flagged.push_back({i, j, 1 - changes / 2});
    }
  std::vector<Vec2> positions;
  for (const auto& n : flagged) positions.emplace_back(n.i, n.j);
  std::vector<ScalarCriticalPoint> out;
  for (const auto& members :
       groupsFromLabels(singleLinkageLabels(positions, params.cluster_radius,
                                            maxClusterDiameter(params.cluster_radius))))
    out.push_back(classify(s, flagged, members, params));
  return out;
}

}  // namespace fluidviz::topology
