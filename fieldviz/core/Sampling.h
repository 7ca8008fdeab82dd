#pragma once
// Bilinear (2D) and trilinear (3D) interpolation of node-centred fields.
#include <optional>

#include "fieldviz/core/Field.h"

namespace fluidviz {

/// Value at world position p, or nullopt when p lies outside the grid's bounding box.
std::optional<double> sample(const ScalarField& f, const Vec3& p);
std::optional<Vec3> sample(const VectorField& f, const Vec3& p);

/// Same, with p given in continuous index coordinates (node i at coordinate i); the hot path of
/// integrators, which work in cell units.
std::optional<Vec3> sampleIndexSpace(const VectorField& f, const Vec3& q);
std::optional<double> sampleIndexSpace(const ScalarField& f, const Vec3& q);

}  // namespace fluidviz
