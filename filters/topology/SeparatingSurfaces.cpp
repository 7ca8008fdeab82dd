#include "filters/topology/SeparatingSurfaces.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "fieldviz/core/Sampling.h"
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

/// Four consecutive front points around the edge p[1]-p[2], copied (the surface's point array
/// grows while they are used); `smooth`: p[0] and p[3] exist (not an end of an open chain).
struct FrontSegment {
  std::array<Vec3, 4> p;
  bool smooth = false;
};

/// Where one front point went in one step.
struct Advance {
  Vec3 point;
  bool ended = false;  ///< the point's streamline ended (boundary, stagnation, mask, a point)
};

/// The world curve of points separatrix_offset cells from the saddle in its eigenplane, with
/// edges at most max_edge / 8 cells long (the front turns fastest next to a spiral saddle,
/// where a coarse polygon's dents fold it most).
std::vector<Vec3> seedCurve(const Grid& g, const Vec3& centre, const SaddlePlane& plane,
                            double offsetCells, double maxEdge) {
  const double circumference = 2 * M_PI * offsetCells;
  const int n = std::max(8, static_cast<int>(std::ceil(circumference / (maxEdge / 8))));
  std::vector<Vec3> points(n);
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    const Vec3 d = std::cos(a) * plane.u + std::sin(a) * plane.w;
    points[k] = centre + d * (offsetCells / cellsBetween(g, d, Vec3::Zero()));
  }
  return points;
}

/// Grows one surface; each trace carries a point by the arc length of its time step.
class FrontGrower {
 public:
  FrontGrower(const VectorField& field, const std::vector<CriticalPoint3D>& points,
              const TopologyParams& params, const StreamlineTracer& tracer, int origin)
      : field_(field), g_(field.grid), points_(points), params_(params), tracer_(tracer),
        origin_(origin) {}

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
    for (double travelled = 0; !front.empty(); travelled += step) {
      if (travelled >= sp.max_length) return finish(SurfaceEnd::max_length);
      if (static_cast<int>(surface_.triangles.size()) >= sp.max_triangles)
        return finish(SurfaceEnd::max_triangles);
      frontSpeed_ = 0.0;
      for (const FrontChain& chain : front)
        for (int v : chain.vertices) frontSpeed_ = std::max(frontSpeed_, cellSpeed(surface_.points[v]));
      if (!(frontSpeed_ > 0)) break;
      std::vector<FrontChain> next;
      for (const FrontChain& chain : front)
        for (FrontChain& c : advanceChain(chain, step)) next.push_back(std::move(c));
      front = std::move(next);
    }
    return finish(SurfaceEnd::front_ended);
  }

 private:
  /// |v| in cells per unit time at world point p (0 outside the grid or where v is not finite).
  double cellSpeed(const Vec3& p) const {
    const std::optional<Vec3> v = sampleIndexSpace(field_, g_.toIndexSpace(p));
    if (!v || !v->allFinite()) return 0.0;
    return Vec3(v->x() / g_.spacing[0], v->y() / g_.spacing[1], v->z() / g_.spacing[2]).norm();
  }

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
  Advance advancePoint(const Vec3& p, double arc) const {
    const double r = params_.separatrix_stop_radius;
    bool nearPoint = false;
    const streamlines::StopRule stop = [&](const StepInfo& s) {
      nearPoint = nearestCriticalPoint(g_, points_, s.point, r, origin_) >= 0;
      return nearPoint;
    };
    const streamlines::Streamline line = tracer_.trace(p, stop, arc);
    if (line.points.empty()) return {p, true};
    const Vec3& last = surface_.outgoing ? line.points.back() : line.points.front();
    return {last, line.reason() != TerminationReason::max_length || nearPoint};
  }

  /// Moves every point of the chain, triangulates the strip between the old and the new chain,
  /// and returns the new chain split where points ended (pieces of one point are dropped).
  std::vector<FrontChain> advanceChain(const FrontChain& chain, double step) {
    const int n = static_cast<int>(chain.vertices.size());
    std::vector<Advance> moved(n);
#pragma omp parallel for schedule(dynamic, 16) if (n > 512)  // small fronts: no fork cost
    for (int k = 0; k < n; ++k) {
      const Vec3& p = surface_.points[chain.vertices[k]];
      moved[k] = advancePoint(p, step * cellSpeed(p) / frontSpeed_);
    }

    std::vector<int> newVertex(n);
    for (int k = 0; k < n; ++k) {
      const bool stayed = cellsBetween(g_, moved[k].point, surface_.points[chain.vertices[k]]) < 1e-9;
      newVertex[k] = stayed ? chain.vertices[k] : addVertex(moved[k].point);
    }
    // The new front, as (vertex, ended) along the chain.
    std::vector<std::pair<int, bool>> line;
    const int edges = chain.closed ? n : n - 1;
    const auto segment = [&](int k) {
      FrontSegment c;
      c.smooth = chain.closed || (k >= 1 && k + 2 < n);
      for (int i = 0; i < 4; ++i) {
        const int m = chain.closed ? ((k - 1 + i) % n + n) % n : std::clamp(k - 1 + i, 0, n - 1);
        c.p[i] = surface_.points[chain.vertices[m]];
      }
      return c;
    };
    for (int k = 0; k < edges; ++k) {
      const int k1 = (k + 1) % n;
      line.emplace_back(newVertex[k], moved[k].ended);
      const int pieces = piecesOf(surface_.points[newVertex[k]], surface_.points[newVertex[k1]]);
      for (const auto& m : stitchStrip(chain.vertices[k], chain.vertices[k1], newVertex[k],
                                       newVertex[k1], segment(k), pieces, step))
        line.push_back(m);
    }
    if (!chain.closed) line.emplace_back(newVertex[n - 1], moved[n - 1].ended);
    return splitAtEnds(line, chain.closed);
  }

  /// Triangulates the strip between old edge a-b and its image A-B (a -> A, b -> B). Where A-B
  /// is longer than max_edge / 2 the old edge is split into as many pieces, at points of the
  /// Catmull-Rom curve through the old front (not its chord, whose dent e^2/8r would be carried
  /// on), and those points are carried by the same time step (Hultquist's insertion), so that
  /// the strip stays the image of the old front. Returns the new front points between A and B.
  std::vector<std::pair<int, bool>> stitchStrip(int a, int b, int A, int B,
                                                const FrontSegment& oldFront, int pieces,
                                                double step) {
    std::vector<int> before{a}, after{A};
    std::vector<std::pair<int, bool>> inserted;
    for (int j = 1; j < pieces; ++j) {
      const Vec3 m = onCurve(oldFront, double(j) / pieces);
      const Advance moved = advancePoint(m, step * cellSpeed(m) / frontSpeed_);
      before.push_back(addVertex(m));
      after.push_back(addVertex(moved.point));
      inserted.emplace_back(after.back(), moved.ended);
    }
    before.push_back(b);
    after.push_back(B);
    for (int j = 0; j < pieces; ++j) addQuad(before[j], before[j + 1], after[j + 1], after[j]);
    return inserted;
  }

  /// How many pieces the strip of an edge is cut into: new front edges at most max_edge / 2.
  int piecesOf(const Vec3& A, const Vec3& B) const {
    const double half = params_.separating_surface.max_edge / 2;
    return std::max(1, static_cast<int>(std::ceil(cellsBetween(g_, A, B) / half)));
  }

  /// The point at parameter s in [0, 1] between p[1] and p[2] on the Catmull-Rom spline through
  /// the four points (linear at the ends of an open chain): new points lie on the front curve,
  /// not on its chord.
  static Vec3 onCurve(const FrontSegment& c, double s) {
    const Vec3 &p0 = c.p[0], &p1 = c.p[1], &p2 = c.p[2], &p3 = c.p[3];
    if (!c.smooth) return p1 + (p2 - p1) * s;
    const double s2 = s * s, s3 = s2 * s;
    return 0.5 * ((2 * p1) + (p2 - p0) * s + (2 * p0 - 5 * p1 + 4 * p2 - p3) * s2 +
                  (3 * p1 - p0 - 3 * p2 + p3) * s3);
  }

  /// Two triangles of the quad a, b, B, A (a -> A and b -> B along the flow), split along its
  /// shorter diagonal; both turn the way a -> b -> A does.
  void addQuad(int a, int b, int B, int A) {
    const auto& P = surface_.points;
    if (cellsBetween(g_, P[a], P[B]) < cellsBetween(g_, P[b], P[A])) {
      addTriangle(a, b, B);
      addTriangle(a, B, A);
    } else {
      addTriangle(a, b, A);
      addTriangle(b, B, A);
    }
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

  const VectorField& field_;
  const Grid& g_;
  const std::vector<CriticalPoint3D>& points_;
  const TopologyParams& params_;
  const StreamlineTracer& tracer_;
  int origin_;
  double frontSpeed_ = 0.0;  ///< largest |v| (cells per unit time) on the current front
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
  sp.step = std::min(sp.step, params.separating_surface.max_edge / 4);  // within one front step
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
