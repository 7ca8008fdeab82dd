#pragma once
// A roller: rigid disc turning about its fixed centre, surface velocity omega x (x - centre).
#include <string>
#include <vector>

#include "solvers/lbm/LbmParams.h"
#include "solvers/lbm/boundaries/SolidBody.h"

namespace fluidviz::lbm {

/// The solid body of roller r (counter-clockwise positive angular velocity).
SolidBody rotatingRoller(const RollerParams& r, std::string name);

/// The solid bodies of a scene: its rollers ("rollers[i]"), then `extra` (e.g. a fixed outer
/// cylinder); a node inside several belongs to the first.
std::vector<SolidBody> sceneBodies(const LbmParams& p, std::vector<SolidBody> extra);

}  // namespace fluidviz::lbm
