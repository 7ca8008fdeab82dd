#pragma once
// A roller: rigid disc turning about its fixed centre, surface velocity omega x (x - centre).
#include <string>

#include "solvers/lbm/LbmParams.h"
#include "solvers/lbm/boundaries/SolidBody.h"

namespace fluidviz::lbm {

/// The solid body of roller r (counter-clockwise positive angular velocity).
SolidBody rotatingRoller(const RollerParams& r, std::string name);

}  // namespace fluidviz::lbm
