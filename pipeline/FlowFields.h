#pragma once
// Fields derived from a velocity field for pictures and snapshots (speed, vorticity, the
// Q-criterion), and z slices of 3D fields. Computed only when an output asks for them.
#include <optional>
#include <string>

#include "fieldviz/core/Field.h"
#include "fieldviz/render/FieldImage.h"

namespace fluidviz {

/// Layer k of a field as a 2D field at that layer's height. Throws std::invalid_argument naming
/// the field when k is outside [0, nz - 1].
VectorField sliceZ(const VectorField& field, int k);
ScalarField sliceZ(const ScalarField& field, int k);

/// The field with vz = 0: the part in the xy plane that LIC, streamlines and topology of a z
/// layer follow (they integrate dx/dt = vx, dy/dt = vy only).
VectorField inPlaneVelocity(const VectorField& velocity);

/// omega = dv/dx - du/dy (1/s for m/s over m) of a 2D field: central differences inside,
/// one-sided first-order differences on the border nodes. NaN values propagate to neighbours.
/// Throws std::invalid_argument for a 3D field or fewer than 2 nodes along x or y.
ScalarField vorticity(const VectorField& velocity, const std::string& name = "vorticity");

/// omega = curl v (1/s) of a 3D field, per node, with the differences of vorticity() along x, y
/// and z. Throws std::invalid_argument for a 2D field or fewer than 2 nodes along x or y.
VectorField vorticityVector(const VectorField& velocity, const std::string& name = "vorticity");

/// Q = (|Omega|^2 - |S|^2) / 2 (1/s^2) of a 3D field, S and Omega the symmetric (strain) and
/// antisymmetric (rotation) parts of the velocity gradient (Hunt, Wray & Moin 1988, CTR report
/// S88): Q > 0 where rotation dominates strain, the vortex cores. Same differences and errors as
/// vorticityVector.
ScalarField qCriterion(const VectorField& velocity, const std::string& name = "q_criterion");

/// The scalars every velocity field offers: "speed" (|v|) and "vorticity"; nullopt otherwise.
std::optional<ScalarField> derivedScalar(const VectorField& velocity, const std::string& name);

/// A signed field (vorticity) is drawn with a range symmetric about 0, so that the middle colour
/// of a diverging map means "no rotation": sets range_min = -m, range_max = m (m = largest
/// finite |value|, 1 if all are 0) unless either bound is given.
void useSymmetricRange(const ScalarField& field, FieldImageParams& picture);

}  // namespace fluidviz
