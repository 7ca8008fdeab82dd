// Checkpoint state of LbmSolverImpl: what step() evolves, nothing derived from the params.
//   lattice name, sizeof(T), nx, ny, nz (checked on restore)
//   steps_, steady_
//   populations_[current_]: Q planes of nodeCount values each (the plane padding is not saved;
//     solid nodes are saved too, so the array is restored exactly whatever the kernel reads)
//   previousUx_/Uy_/Uz_ (maxVelocityChange's reference; empty before its first call)
// The other population array needs no saving: the next step overwrites every value it reads.
#include <cstring>

#include "solvers/lbm/kernel/LbmSolverImpl.h"

namespace fluidviz::lbm {

template <class L, class T>
void LbmSolverImpl<L, T>::saveState(StateWriter& out) const {
  out.putString(L::name);
  out.put<std::int32_t>(sizeof(T));
  out.put<std::int32_t>(units_.nx);
  out.put<std::int32_t>(units_.ny);
  out.put<std::int32_t>(grid_.dims[2]);
  out.put<std::int64_t>(steps_);
  out.put<std::uint8_t>(steady_ ? 1 : 0);
  const std::int64_t nodes = static_cast<std::int64_t>(grid_.nodeCount());
  const PopulationArraysOf<T>& f = populations_[current_];
  for (int q = 0; q < L::Q; ++q) out.putBytes(f.data() + q * f.stride(), nodes * sizeof(T));
  out.putVector(previousUx_);
  out.putVector(previousUy_);
  out.putVector(previousUz_);
}

template <class L, class T>
void LbmSolverImpl<L, T>::restoreState(StateReader& in) {
  const std::string lattice = in.getString();
  if (lattice != L::name)
    throw StateFormatError("the state is of lattice " + lattice + ", this solver is " + L::name);
  StateReader::requireSame("the population size (bytes)", in.get<std::int32_t>(),
                           static_cast<std::int32_t>(sizeof(T)));
  StateReader::requireSame("nx", in.get<std::int32_t>(), units_.nx);
  StateReader::requireSame("ny", in.get<std::int32_t>(), units_.ny);
  StateReader::requireSame("nz", in.get<std::int32_t>(), grid_.dims[2]);
  const auto steps = in.get<std::int64_t>();
  const bool steady = in.get<std::uint8_t>() != 0;
  const std::int64_t nodes = static_cast<std::int64_t>(grid_.nodeCount());
  PopulationArraysOf<T>& f = populations_[current_];
  for (int q = 0; q < L::Q; ++q) in.getBytes(f.data() + q * f.stride(), nodes * sizeof(T));
  in.getVector(previousUx_);
  in.getVector(previousUy_, static_cast<std::int64_t>(previousUx_.size()));
  in.getVector(previousUz_, static_cast<std::int64_t>(previousUx_.size()));
  if (!previousUx_.empty() && previousUx_.size() != static_cast<std::size_t>(nodes))
    throw StateFormatError("the steady-state reference holds " +
                           std::to_string(previousUx_.size()) + " nodes, the lattice " +
                           std::to_string(nodes));
  steps_ = steps;
  steady_ = steady;
  setOpenSideRules(steps_ + 1);
}

// The rest of the class is instantiated in LbmSolverImpl.cpp.
#define FLUIDVIZ_LBM_STATE_METHODS(L, T)                                  \
  template void LbmSolverImpl<L, T>::saveState(StateWriter&) const; \
  template void LbmSolverImpl<L, T>::restoreState(StateReader&);
FLUIDVIZ_LBM_STATE_METHODS(LatticeD2Q9, double)
FLUIDVIZ_LBM_STATE_METHODS(LatticeD2Q9, float)
FLUIDVIZ_LBM_STATE_METHODS(LatticeD3Q19, double)
FLUIDVIZ_LBM_STATE_METHODS(LatticeD3Q19, float)
#undef FLUIDVIZ_LBM_STATE_METHODS

}  // namespace fluidviz::lbm
