#pragma once
// Scalar and vector fields on a regular grid, and a named set of them sharing one grid.
#include <string>
#include <vector>

#include "fieldviz/core/Grid.h"

namespace fluidviz {

struct ScalarField {
  std::string name;
  Grid grid;
  std::vector<double> values;  ///< one per node, x fastest (Grid::index)
};

struct VectorField {
  std::string name;
  Grid grid;
  std::vector<Vec3> values;  ///< one per node; 2D fields keep z = 0
};

/// Arrays that live on the same grid, in the order they were added (the order files list them).
struct FieldSet {
  Grid grid;
  std::vector<ScalarField> scalars;
  std::vector<VectorField> vectors;

  const ScalarField* findScalar(const std::string& name) const;
  const VectorField* findVector(const std::string& name) const;
  /// Add a field; throws std::invalid_argument if its grid or size does not match the set's.
  void add(ScalarField f);
  void add(VectorField f);
  std::vector<std::string> arrayNames() const;
};

/// Speed |v| of every node.
ScalarField magnitude(const VectorField& v, const std::string& name = "speed");

}  // namespace fluidviz
