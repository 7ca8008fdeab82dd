#pragma once
// Critical points of a scalar field on a 2D grid (here: the stream function psi) with Morse
// classification.
//
// Detection is combinatorial (piecewise-linear Morse theory; Banchoff 1967, Edelsbrunner et al.
// 2003): on the Freudenthal triangulation of the grid (each cell split along its (0,0)-(1,1)
// diagonal) the link of an interior node is the 6-cycle of neighbours (1,0), (1,1), (0,1),
// (-1,0), (-1,-1), (0,-1). Counting the sign changes k of f(neighbour) - f(node) around it
// (ties broken by node number, "simulation of simplicity"):
//   k = 0, all lower -> maximum;  k = 0, all higher -> minimum;  k = 2 -> regular;
//   k = 2m, m >= 2   -> saddle of multiplicity m - 1 (m = 3: monkey saddle).
// The index of grad f there is 1 - k/2. Nodes closer than cluster_radius are merged (indices
// added), as for vector field zeros.
// Location: Newton steps x <- x - H^-1 g on the bilinearly interpolated nodal central-difference
// gradient g and Hessian H (second order), starting at the node.
// Classification (Morse lemma): a single node with |det H| > det_threshold * G^2 (G: RMS
// Frobenius norm of H within gradient_scale_radius cells) whose index is sign(det H) is Morse:
// det H < 0 saddle, det H > 0 minimum (tr H > 0) or maximum (tr H < 0). Otherwise: degenerate
// saddle (index <= -1, e.g. the monkey saddle x^3 - 3xy^2 with index -2) or degenerate
// (index >= 0).
#include <array>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "filters/topology/CriticalPoint.h"
#include "filters/topology/TopologyParams.h"

namespace fluidviz::topology {

enum class ScalarCriticalType { Minimum, Maximum, Saddle, DegenerateSaddle, Degenerate };

/// "minimum", "maximum", "saddle", "degenerate_saddle", "degenerate".
std::string toString(ScalarCriticalType t);

struct ScalarCriticalPoint {
  Vec3 position{0, 0, 0};          ///< world (Newton-refined for single Morse nodes)
  std::array<int, 2> node{0, 0};   ///< grid node the combinatorial test flagged (first of cluster)
  ScalarCriticalType type = ScalarCriticalType::Degenerate;
  int index = 0;                   ///< index of grad f: 1 - (link sign changes) / 2, summed
  bool morse = false;
  Mat2 hessian = Mat2::Zero();     ///< world units (f / m^2)
  double det = 0.0, trace = 0.0;   ///< of the Hessian
  double normalized_det = 0.0;     ///< det H / G^2 (G: local RMS norm of H)
  int cluster_size = 1;            ///< flagged nodes merged into this point
};

/// Critical points of slice params.slice_index of `f` (its only slice in 2D), interior nodes
/// only (the link of a boundary node is incomplete).
std::vector<ScalarCriticalPoint> findScalarCriticalPoints(const ScalarField& f,
                                                          const TopologyParams& params);

}  // namespace fluidviz::topology
