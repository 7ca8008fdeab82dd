#pragma once
// Is a triangle mesh a 2-manifold the surface solvers can run on? Counts what breaks it (issue 24:
// a clear error naming what is wrong) and the topology: Euler characteristic chi = V - E + F,
// which the Gauss-Bonnet theorem ties to the total curvature (2 pi chi) and the Poincare-Hopf
// theorem to the index sum of a tangent field's critical points.
#include <string>

#include "solvers/surface/mesh/TriangleMesh.h"

namespace fluidviz::surface {

struct ManifoldReport {
  int vertices = 0, edges = 0, faces = 0;
  int eulerCharacteristic = 0;   ///< V - E + F
  int boundaryEdges = 0;         ///< edges of exactly one face (a bordered surface)
  int nonManifoldEdges = 0;      ///< edges of three or more faces
  int inconsistentEdges = 0;     ///< edges whose two faces run them in the same direction
  int degenerateFaces = 0;       ///< repeated vertex, or area below 1e-12 of the mean
  int badIndices = 0;            ///< vertex indices outside [0, V)
  int isolatedVertices = 0;      ///< vertices of no face
  int obtuseFaces = 0;           ///< faces with an angle above 90 degrees (cotangent weights < 0)

  bool closed() const { return boundaryEdges == 0; }
  /// A 2-manifold (closed or bordered), consistently oriented, without degenerate faces.
  bool valid() const {
    return nonManifoldEdges == 0 && inconsistentEdges == 0 && degenerateFaces == 0 &&
           badIndices == 0 && isolatedVertices == 0;
  }
  /// One line naming each defect with its count, or "closed 2-manifold, chi = 2, ...".
  std::string describe() const;
};

ManifoldReport checkManifold(const TriangleMesh& mesh);

/// Throws std::invalid_argument with describe() unless the mesh is a valid closed 2-manifold.
void requireClosedManifold(const TriangleMesh& mesh);

}  // namespace fluidviz::surface
