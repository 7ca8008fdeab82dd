#pragma once
// A triangle mesh of a surface: vertex positions and counter-clockwise faces (seen from outside,
// so that (b - a) x (c - a) points along the outward normal), and the two built-in closed
// surfaces of issue 24: a subdivided icosahedron projected onto a sphere and a torus.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products of the users of a mesh

namespace fluidviz::surface {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;

  int vertexCount() const { return static_cast<int>(vertices.size()); }
  int faceCount() const { return static_cast<int>(faces.size()); }
};

/// The icosahedron subdivided `level` times (each triangle into four at its edge mid-points),
/// every new vertex projected onto the sphere of `radius` about the origin: 10 * 4^level + 2
/// vertices (level 4: 2562) and 20 * 4^level faces.
TriangleMesh makeIcosphere(double radius, int level);

/// The torus of major radius R and minor radius r (R > r > 0) about the z axis, sampled on an
/// n (around z) x m (around the tube) grid of vertices, each quad split into two triangles:
/// n * m vertices, 2 n m faces, Euler characteristic 0. Needs n, m >= 3.
TriangleMesh makeTorus(double majorRadius, double minorRadius, int n, int m);

}  // namespace fluidviz::surface
