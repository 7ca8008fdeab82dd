#pragma once
// Which part of a partitioned image a rank owns, for filters that compute on the whole input on
// every rank and keep one rank's share of the result (fvPvTopology, fvPvStreamlines): the cells
// of its piece, split as ParaView splits image data (vtkExtentTranslator, block mode). Pieces
// share their boundary nodes, so their cells tile the grid and every cell has one owner.
#include <array>

namespace fluidviz {
namespace paraview {

struct OwnedPart {
  int lo[3], hi[3];   ///< the piece's node extent, relative to the whole extent's start
  int lastNode[3];    ///< the whole extent's last node along each axis, relative to its start

  /// Cell (i, j) of a 2D field and node layer `layer` along z (the layer analysed in 3D data):
  /// cells lo..hi-1 along x and y, layers lo..hi-1 along z, and the grid's last layer belongs to
  /// the piece that ends there.
  bool owns(const std::array<int, 2>& cell, int layer) const;

  /// The cell that holds world point p of an image with `origin` and `spacing` (clamped to the
  /// grid: a point on the last node's face is in the last cell); an axis of one node is not
  /// split. Every point belongs to exactly one piece.
  bool ownsPoint(const double p[3], const double origin[3], const double spacing[3]) const;
};

/// The part of piece `piece` of `pieces` of the node extent `whole`.
OwnedPart ownedPart(const int whole[6], int piece, int pieces);

}  // namespace paraview
}  // namespace fluidviz
