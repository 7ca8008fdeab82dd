#include "PieceOwnership.h"

#include <algorithm>
#include <cmath>

#include <vtkExtentTranslator.h>
#include <vtkNew.h>

namespace fluidviz {
namespace paraview {

bool OwnedPart::owns(const std::array<int, 2>& cell, int layer) const {
  const bool inZ =
      (layer >= lo[2] && layer < hi[2]) || (layer == hi[2] && hi[2] == lastNode[2]);
  return cell[0] >= lo[0] && cell[0] < hi[0] && cell[1] >= lo[1] && cell[1] < hi[1] && inZ;
}

bool OwnedPart::ownsPoint(const double p[3], const double origin[3],
                          const double spacing[3]) const {
  for (int a = 0; a < 3; ++a) {
    if (lastNode[a] == 0) continue;
    const double x = std::floor((p[a] - origin[a]) / spacing[a]);
    const int cell = int(std::clamp(x, 0.0, double(lastNode[a] - 1)));
    if (cell < lo[a] || cell >= hi[a]) return false;
  }
  return true;
}

OwnedPart ownedPart(const int whole[6], int piece, int pieces) {
  vtkNew<vtkExtentTranslator> translator;
  int wholeCopy[6], extent[6];
  std::copy(whole, whole + 6, wholeCopy);
  translator->PieceToExtentThreadSafe(piece, pieces, 0, wholeCopy, extent,
                                      vtkExtentTranslator::BLOCK_MODE, 0);
  OwnedPart part{};
  for (int a = 0; a < 3; ++a) {
    part.lo[a] = extent[2 * a] - whole[2 * a];
    part.hi[a] = extent[2 * a + 1] - whole[2 * a];
    part.lastNode[a] = whole[2 * a + 1] - whole[2 * a];
  }
  return part;
}

}  // namespace paraview
}  // namespace fluidviz
