#pragma once
// Projection onto discretely divergence-free fields: u = v - D^T phi with D D^T phi = D v, D the
// central-difference divergence of PlaneGrid.h. u is the field closest to v (in the sum of
// squares over nodes) with D u = 0: the Helmholtz-Hodge projection (Chorin 1968) written with
// D's adjoint as the gradient, so that the divergence it leaves is the solver's residual only.
// D D^T is symmetric positive semi-definite (constants and, with central differences on a
// periodic grid, the odd-even modes are in its null space) and D v lies in its range, so
// conjugate gradients converge on it where a factorisation would meet zero pivots.
// What it changes (examples/sketch/README.md): a sketched source or sink is pure divergence and
// is removed; the normal velocity at a zero-flux side is not set to zero (D is one-sided there);
// node-to-node zigzags pass unseen, as central differences do not see them.
#include "fieldviz/core/Field.h"
#include "filters/sketch/grid/PlaneGrid.h"

namespace fluidviz::sketch {

struct DivergenceFreeResult {
  VectorField field;
  double divergenceBefore = 0.0;  ///< max |D v| (1/s for v in m/s)
  double divergenceAfter = 0.0;   ///< max |D u|
  int iterations = 0;             ///< of conjugate gradients
};

/// Throws std::runtime_error if conjugate gradients do not reach the tolerance.
DivergenceFreeResult projectDivergenceFree(const VectorField& v, const PlaneGrid& g);

/// max |D v| over the nodes.
double maxDivergence(const VectorField& v, const PlaneGrid& g);

}  // namespace fluidviz::sketch
