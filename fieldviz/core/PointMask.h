#pragma once
// Which nodes of a 2D field are not fluid: NaN/inf velocity, a mask array of the file (nonzero =
// fluid, or vtkValidPointMask), nodes outside the grid of a plane slice, and no-slip solids
// (connected regions of zero velocity). One flag per node (Grid::index): 1 = masked. An empty
// mask masks nothing. Filters see the mask as NaN velocity (withMaskedNaN): critical points skip
// cells with a NaN corner, streamlines and separatrices end there (nan_in_field), LIC draws
// masked pixels in its mask colour.
#include <array>
#include <cstdint>
#include <vector>

#include "fieldviz/core/Field.h"

namespace fluidviz {

using PointMask = std::vector<std::uint8_t>;

/// The point array that flags valid nodes in VTK (vtkProbeFilter, vtkResampleWithDataSet) and
/// ParaView: unsigned char, 1 = valid (fluid), 0 = not (solid, outside the data). fluidviz
/// writes its solid masks under this name and the flow commands read it (validPointFlags).
inline constexpr const char* kValidPointMaskArray = "vtkValidPointMask";
/// vtkValidPointMask values of a mask: 1 where `masked` is 0 (an empty mask: all nodes valid).
std::vector<std::uint8_t> validPointFlags(const PointMask& masked, std::size_t nodes);

/// What counts as a no-slip solid: a 4-connected region of at least solid_min_nodes nodes with
/// |v| <= solid_speed * max|v|. A real stagnation point has |v| = 0 at a node or two at most, a
/// solid body at a whole region.
struct SolidParams {
  /// fraction of max|v| (1), [0, 0.01]; the default 1e-9 takes the rounding left by resampling
  /// (1e-17 of max|v| in the office data) as zero, 0 = exactly zero velocity only
  double solid_speed = 1e-9;
  int solid_min_nodes = 9;   ///< nodes (1), [3, 1e9]
};
/// Throws std::invalid_argument naming the key and its allowed range.
void validateSolidParams(const SolidParams& p);

/// 1 where any component of v is NaN or infinite.
PointMask nonFiniteNodes(const VectorField& v);
/// 1 on the no-slip solids of v (SolidParams); NaN nodes are not part of a solid; none when
/// max|v| = 0.
PointMask solidNodes(const VectorField& v, const SolidParams& params);
/// 1 where the scalar (a mask array: nonzero = fluid) is 0 or not finite.
PointMask zeroNodes(const ScalarField& fluid);
/// The nodes every fluidviz front end (CLI, ParaView plugin) masks in a 2D field read from a file:
/// where `fluid` (the file's vtkValidPointMask or a chosen mask array; nullptr: none) is 0 or not
/// finite, where the velocity is NaN or infinite, and the no-slip solids (SolidParams defaults).
/// Empty when no node is masked.
PointMask flowMask(const VectorField& velocity, const ScalarField* fluid);

/// into |= other (either may be empty).
void addMask(PointMask& into, const PointMask& other);
std::size_t maskedCount(const PointMask& mask);

/// v with `value` at masked nodes.
VectorField withMaskedValue(const VectorField& v, const PointMask& mask, const Vec3& value);
/// v with NaN at masked nodes: the field streamlines and separatrices see.
VectorField withMaskedNaN(const VectorField& v, const PointMask& mask);
/// A scalar with NaN at the masked nodes: pictures draw them in the masked grey
/// (render/PictureStyle.h) and leave them out of the colour range.
ScalarField withMaskedNaN(const ScalarField& s, const PointMask& mask);

/// The 2D cell holding world position p (clamped to the grid; a grid one node wide has cells of
/// one node there): its corner nodes (i, j), (i+1, j), (i, j+1), (i+1, j+1) and p's bilinear
/// coordinates s, t in [0, 1] within it. What maskFraction, cellTouchesFluid and the wall
/// layer's test (filters/topology/WallPoints) read of a mask at a position.
struct CellCorners {
  std::array<std::size_t, 4> nodes;
  double s, t;
};
CellCorners cellCornersAt(const Grid& g, const Vec3& p);

/// The largest |v| over the nodes where v is finite (NaN marks missing data): the scale that
/// SolidParams::solid_speed is a fraction of.
double maxFiniteSpeed(const VectorField& v);

/// Throws std::invalid_argument naming `what` and the grid unless g is 2D (one node in z).
void require2DGrid(const Grid& g, const char* what);

/// Bilinear interpolation of the mask (1 = masked) at 2D world position p, clamped to the grid:
/// a pixel or position is drawn as masked where this is >= 1/2.
double maskFraction(const Grid& g, const PointMask& mask, const Vec3& p);

/// The field critical points are found in: masked nodes NaN except the wall layer (masked nodes
/// with a fluid 4-neighbour), which gets the field's linear continuation from the fluid side
/// (per fluid neighbour n along direction d: 2 v(n) - v(n + d), or v(n) when n + d is not fluid;
/// averaged). The cells between the wall layer and the fluid then hold the zeros that lie on the
/// wall (stagnation points of flow meeting or leaving a body), which the zero velocity of a solid
/// would hide in a degenerate cell.
VectorField withWallLayerContinued(const VectorField& v, const PointMask& mask);

/// True when the cell of 2D position p has at least one fluid corner (critical points of cells
/// with only masked corners lie inside a mask).
bool cellTouchesFluid(const Grid& g, const PointMask& mask, const Vec3& p);

}  // namespace fluidviz
