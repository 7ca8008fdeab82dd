#pragma once
// Overlays of a FieldImageScene are stacked in z above the field plane, in the order they must
// cover each other: level 1 texture images (LIC), 2 line outlines, 3 lines, 4 arrowhead
// outlines, 5 arrowheads. The camera is
// parallel, so the small z offsets do not move anything in the picture.
#include "fieldviz/render/FieldImage.h"

namespace fluidviz {

inline double overlayDepth(FieldImageScene& scene, int level) {
  return scene.planeZ() + level * (scene.overlayZ() - scene.planeZ());
}

}  // namespace fluidviz
