#pragma once
// Coarse-graining of the Boolean field (Frisch et al. 1987, section 3): the density and current of
// the lattice gas are ensemble averages, estimated here by averaging the occupation numbers over
// blocks of bx x by nodes and over a window of time steps. The result sits on a regular grid of
// block centres (fieldviz core types), so the filters that run on LBM output run on it unchanged.
#include <cstdint>
#include <vector>

#include "fieldviz/core/Field.h"
#include "solvers/fhp/lattice/BitLattice.h"

namespace fluidviz::fhp {

class BlockAverager {
 public:
  /// bx must divide nx and by must divide ny; throws std::invalid_argument naming them otherwise.
  BlockAverager(int nx, int ny, int bx, int by);

  /// Adds the current state (one time sample).
  void add(const BitLattice& lattice);
  int samples() const { return samples_; }
  void clear();

  /// Per block: "density" (particles per fluid node), "velocity" (current / density, links per
  /// step; zero where a block has no fluid or no particle). Node spacing is `linkLength` (the
  /// length of one lattice link in scene units); the grid's origin is the centre of block (0, 0).
  FieldSet fields(double linkLength = 1.0) const;

  /// Mean current per fluid node, per block (links per step): jx, jy.
  std::vector<double> currentX() const;
  std::vector<double> currentY() const;
  std::vector<double> densityPerNode() const;
  /// Fraction of the nodes of each block that are fluid (0 before the first sample).
  std::vector<double> fluidFraction() const;
  /// The sums of the samples so far, for checkpoints.
  std::vector<double> sums() const;
  void restoreSums(const std::vector<double>& sums, int samples);
  int blocksX() const { return nbx_; }
  int blocksY() const { return nby_; }

 private:
  int nx_, ny_, bx_, by_, nbx_, nby_;
  int samples_ = 0;
  std::vector<double> count_, jx_, jy_, fluidNodes_;
};

}  // namespace fluidviz::fhp
