#include "filters/topology/SeparatingSurfaces.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "filters/streamlines/Streamline.h"
#include "filters/topology/Separatrices3D.h"

namespace fluidviz::topology {

namespace {
using streamlines::StepInfo;
using streamlines::StreamlineTracer;
using streamlines::TerminationReason;

/// A front: a chain of surface vertices, closed (the first front) or open (after a break).
struct FrontChain {
  std::vector<int> vertices;
  bool closed = false;
};

/// Where one front point went in one step.
struct Advance {
  Vec3 point;
  bool ended = false;  ///< the point's streamline ended (boundary, stagnation, mask, a point)
};

/// The world curve of points separatrix_offset cells from the saddle in its eigenplane, with
/// enough points that its edges are at most max_edge / 2 cells long.
std::vector<Vec3> seedCurve(const Grid& g, const Vec3& centre, const SaddlePlane& plane,
                            double offsetCells, double maxEdge) {
  const double circumference = 2 * M_PI * offsetCells;
  const int n = std::max(8, static_cast<int>(std::ceil(circumference / (maxEdge / 2))));
  std::vector<Vec3> points(n);
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    const Vec3 d = std::cos(a) * plane.u + std::sin(a) * plane.w;
    points[k] = centre + d * (offsetCells / cellsBetween(g, d, Vec3::Zero()));
  }
  return points;
}

/// Grows one surface. The tracers carry a point by at most one step's arc length.
class FrontGrower {
 public:
  FrontGrower(const VectorField& field, const std::vector<CriticalPoint3D>& points,
              const TopologyParams& params, const StreamlineTracer& tracer, int origin)
      : g_(field.grid), points_(points), params_(params), tracer_(tracer), origin_(origin) {}

  SeparatingSurface grow(const SaddlePlane& plane) {
    const SeparatingSurfaceParams& sp = params_.separating_surface;
    surface_.origin = origin_;
    surface_.outgoing = plane.outgoing;
    FrontChain first{{}, true};
    for (const Vec3& p : seedCurve(g_, points_[origin_].position, plane,
                                   params_.separatrix_offset, sp.max_edge))
      first.vertices.push_back(addVertex(p));
    std::vector<FrontChain> front{first};
    const double step = sp.max_edge / 4;
    for (travelled_ = 0; !front.empty(); travelled_ += step) {
      if (travelled_ >= sp.max_length) return finish(SurfaceEnd::max_length);
      if (static_cast<int>(surface_.triangles.size()) >= sp.max_triangles)
        return finish(SurfaceEnd::max_triangles);
      std::vector<FrontChain> next;
      for (const FrontChain& chain : front)
        for (FrontChain& c : advanceChain(chain)) next.push_back(std::move(c));
      front = std::move(next);
    }
    return finish(SurfaceEnd::front_ended);
  }

 private:
  int addVertex(const Vec3& p) {
    surface_.points.push_back(p);
    return static_cast<int>(surface_.points.size()) - 1;
  }

  SeparatingSurface finish(SurfaceEnd end) {
    surface_.end = end;
    return std::move(surface_);
  }

  /// Carries the point along its streamline (forward for unstable manifolds) by one step; it
  /// ends like a separatrix, near a critical point other than its saddle. Unlike a 1D
  /// separatrix it may stay near its own saddle for many steps: the surface of a spiral saddle
  /// winds around it while it grows (by exp(2 pi Re/Im) per turn), so that point never stops it.
  Advance advancePoint(const Vec3& p) const {
    const double r = params_.separatrix_stop_radius;
    bool nearPoint = false;
    const streamlines::StopRule stop = [&](const StepInfo& s) {
      nearPoint = nearestCriticalPoint(g_, points_, s.point, r, origin_) >= 0;
      return nearPoint;
    };
    const streamlines::Streamline line = tracer_.trace(p, stop);
    if (line.points.empty()) return {p, true};
    const Vec3& last = surface_.outgoing ? line.points.back() : line.points.front();
    return {last, line.reason() != TerminationReason::max_length || nearPoint};
  }

  /// Moves every point of the chain, triangulates the strip between the old and the new chain,
  /// and returns the new chain split where points ended (pieces of one point are dropped).
  std::vector<FrontChain> advanceChain(const FrontChain& chain) {
    const int n = static_cast<int>(chain.vertices.size());
    std::vector<Advance> moved(n);
#pragma omp parallel for schedule(dynamic, 16) if (n > 512)  // small fronts: no fork cost
    for (int k = 0; k < n; ++k) moved[k] = advancePoint(surface_.points[chain.vertices[k]]);

    std::vector<int> newVertex(n);
    for (int k = 0; k < n; ++k) {
      const bool stayed = cellsBetween(g_, moved[k].point, surface_.points[chain.vertices[k]]) < 1e-9;
      newVertex[k] = stayed ? chain.vertices[k] : addVertex(moved[k].point);
    }
    // The new front, as (vertex, ended) along the chain.
    std::vector<std::pair<int, bool>> line;
    const int edges = chain.closed ? n : n - 1;
    for (int k = 0; k < edges; ++k) {
      const int k1 = (k + 1) % n;
      line.emplace_back(newVertex[k], moved[k].ended);
      for (int m : stitchStrip(chain.vertices[k], chain.vertices[k1], newVertex[k], newVertex[k1]))
        line.emplace_back(m, false);
    }
    if (!chain.closed) line.emplace_back(newVertex[n - 1], moved[n - 1].ended);
    return splitAtEnds(line, chain.closed);
  }

  /// Triangulates the quad (a, b | A, B) of old edge a-b and its image A-B (a -> A, b -> B),
  /// inserting points on A-B so that no new front edge exceeds max_edge / 2; returns the
  /// inserted vertices in order from A to B.
  std::vector<int> stitchStrip(int a, int b, int A, int B) {
    const double half = params_.separating_surface.max_edge / 2;
    const Vec3 pA = surface_.points[A], pB = surface_.points[B];
    const int pieces = std::max(1, static_cast<int>(std::ceil(cellsBetween(g_, pA, pB) / half)));
    std::vector<int> chain{A};
    for (int j = 1; j < pieces; ++j) chain.push_back(addVertex(pA + (pB - pA) * (double(j) / pieces)));
    chain.push_back(B);
    if (pieces == 1) {
      const auto& P = surface_.points;
      if (cellsBetween(g_, P[a], P[B]) < cellsBetween(g_, P[b], P[A])) {
        addTriangle(a, b, B);
        addTriangle(a, B, A);
      } else {
        addTriangle(a, b, A);
        addTriangle(b, B, A);
      }
      return {};
    }
    // Fans: a to the first half of the new chain, b to the second, one triangle between.
    const int mid = pieces / 2;
    for (int j = 0; j < mid; ++j) addTriangle(a, chain[j + 1], chain[j]);
    addTriangle(a, b, chain[mid]);
    for (int j = mid; j < pieces; ++j) addTriangle(b, chain[j + 1], chain[j]);
    return std::vector<int>(chain.begin() + 1, chain.end() - 1);
  }

  void addTriangle(int a, int b, int c) {
    if (a == b || b == c || a == c) return;  // a point that did not move
    surface_.triangles.push_back({a, b, c});
  }

  /// Pieces of the new front between ended points; a closed front with no ended point stays
  /// closed.
  static std::vector<FrontChain> splitAtEnds(std::vector<std::pair<int, bool>> line, bool closed) {
    const auto ended = std::find_if(line.begin(), line.end(), [](const auto& v) { return v.second; });
    if (closed && ended == line.end()) {
      FrontChain c{{}, true};
      for (const auto& v : line) c.vertices.push_back(v.first);
      return {c};
    }
    if (closed) std::rotate(line.begin(), ended, line.end());  // start at an ended point
    std::vector<FrontChain> pieces;
    FrontChain current;
    const auto flush = [&] {
      if (current.vertices.size() >= 2) pieces.push_back(current);
      current.vertices.clear();
    };
    for (const auto& [vertex, end] : line) {
      if (end) {
        flush();
      } else {
        current.vertices.push_back(vertex);
      }
    }
    flush();
    return pieces;
  }

  const Grid& g_;
  const std::vector<CriticalPoint3D>& points_;
  const TopologyParams& params_;
  const StreamlineTracer& tracer_;
  int origin_;
  double travelled_ = 0.0;
  SeparatingSurface surface_;
};

}  // namespace

const char* toString(SurfaceEnd e) {
  switch (e) {
    case SurfaceEnd::front_ended: return "front_ended";
    case SurfaceEnd::max_length: return "max_length";
    case SurfaceEnd::max_triangles: return "max_triangles";
  }
  return "unknown";
}

std::optional<SaddlePlane> saddlePlane(const CriticalPoint3D& p) {
  if (!p.morse || !isMorseSaddle(p.type)) return std::nullopt;
  const Eigen::EigenSolver<Mat3> solver(p.jacobian);
  int positive = 0;
  for (int k = 0; k < 3; ++k) positive += solver.eigenvalues()[k].real() > 0;
  const bool outgoing = positive == 2;  // 2-saddles: the plane of the two positive ones
  const Eigen::Matrix3cd vectors = solver.eigenvectors();  // a temporary: keep it
  std::vector<Vec3> span;
  for (int k = 0; k < 3; ++k) {
    if ((solver.eigenvalues()[k].real() > 0) != outgoing) continue;
    const Eigen::Vector3cd v = vectors.col(k);
    span.push_back(v.real());
    if (std::abs(solver.eigenvalues()[k].imag()) > 1e-12 * std::abs(solver.eigenvalues()[k])) {
      span.push_back(v.imag());  // a complex pair spans its plane by one eigenvector
      break;
    }
  }
  if (span.size() != 2) return std::nullopt;
  SaddlePlane plane;
  plane.outgoing = outgoing;
  plane.u = span[0].normalized();
  plane.w = (span[1] - span[1].dot(plane.u) * plane.u).normalized();  // Gram-Schmidt
  return plane;
}

std::vector<SeparatingSurface> computeSeparatingSurfaces(const VectorField& field,
                                                         const std::vector<CriticalPoint3D>& points,
                                                         const TopologyParams& params) {
  validateTopologyParams(params);
  streamlines::StreamlineParams sp = params.separatrix_integration;
  sp.max_length = params.separating_surface.max_edge / 4;  // one front step
  sp.step = std::min(sp.step, sp.max_length);
  sp.direction = streamlines::TraceDirection::forward;
  const StreamlineTracer forward(field, sp);
  sp.direction = streamlines::TraceDirection::backward;
  const StreamlineTracer backward(field, sp);
  std::vector<SeparatingSurface> out;
  for (int k = 0; k < static_cast<int>(points.size()); ++k) {
    const auto plane = saddlePlane(points[k]);
    if (!plane) continue;
    FrontGrower grower(field, points, params, plane->outgoing ? forward : backward, k);
    out.push_back(grower.grow(*plane));
  }
  return out;
}

}  // namespace fluidviz::topology
