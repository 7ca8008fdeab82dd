#pragma once
// Where a 2D flow is held at rest by no-slip walls: the nodes of solids at rest and the sides of
// the domain that are walls at rest. On such a wall the whole wall is a line of zeros of the
// velocity, so the zeros a critical-point search finds next to it are the wall itself, not flow
// features; the features there are the wall's attachment and separation points (where the wall
// shear stress changes sign; Helman & Hesselink 1991, "Visualizing vector field topology in fluid
// flows", section 3: the 2D wall topology of skin friction).
#include <array>
#include <string>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/PointMask.h"

namespace fluidviz {

/// The VTK field-data string with which a snapshot names its sides that are no-slip walls at
/// rest, space-separated ("x_min y_min y_max"), each lying half a cell outside the edge nodes
/// (halfway bounce-back on the node-centred lattice). Absent or empty: no such side.
inline constexpr const char* kRestingSidesFieldData = "fluidviz_resting_walls";

enum class DomainSide { x_min, x_max, y_min, y_max };
inline constexpr std::array<DomainSide, 4> kDomainSides{DomainSide::x_min, DomainSide::x_max,
                                                        DomainSide::y_min, DomainSide::y_max};
/// "x_min", "x_max", "y_min", "y_max" (the scene's key of the side, walls.<name>).
std::string toString(DomainSide side);

struct RestingWalls {
  PointMask solid;                ///< 1 on nodes of solids at rest (empty: none)
  std::array<bool, 4> sides{};    ///< by DomainSide: a no-slip wall at rest half a cell outside
  bool side(DomainSide s) const { return sides[static_cast<int>(s)]; }
  bool any() const;
};

/// The masked nodes whose own velocity is finite and zero (|v| <= SolidParams::solid_speed *
/// max|v| of the field, the rule of solidNodes): solids at rest. Masked nodes that carry a wall
/// velocity (rollers), or no value (NaN, missing data), are not. Empty when there is none.
PointMask restingSolidNodes(const VectorField& v, const PointMask& mask);

/// "x_min y_max" for the sides set, "" for none.
std::string restingSidesText(const std::array<bool, 4>& sides);
/// The sides named in `text` (kRestingSidesFieldData's format). Throws std::invalid_argument
/// naming `source`, the word and the allowed names for anything else.
std::array<bool, 4> parseRestingSides(const std::string& text, const std::string& source);

}  // namespace fluidviz
