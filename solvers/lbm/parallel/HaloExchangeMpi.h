#pragma once
// The ghost-layer exchange of issue 18 over MPI, for arrays of `planes` structure-of-arrays
// planes (PopulationArrays: plane q of f_q at q * stride; a field: planes = 1). Header-only and
// included only by targets built with FLUIDVIZ_MPI (fluidviz_lbm itself stays MPI-free, so the
// serial build needs no MPI). One nonblocking receive and send per HaloLink (HaloPlan.h), all
// posted before any wait: no ordering between ranks can deadlock, and a rank that is its own
// neighbour (one block along a periodic axis) just exchanges with itself.
#include <mpi.h>

#include <cstdint>
#include <type_traits>
#include <vector>

#include "solvers/lbm/parallel/HaloPlan.h"

namespace fluidviz::lbm {

template <class T>
MPI_Datatype mpiTypeOf() {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, float> ||
                std::is_same_v<T, std::int64_t>);
  if constexpr (std::is_same_v<T, double>) return MPI_DOUBLE;
  else if constexpr (std::is_same_v<T, float>) return MPI_FLOAT;
  else return MPI_INT64_T;
}

/// Copies box `b` of every plane into `out` (plane-major, then x fastest) or back.
template <class T, bool Pack>
void copyBox(const LocalBlock& block, const HaloBox& b, T* data, int planes, std::int64_t stride,
             T* buffer) {
  std::int64_t n = 0;
  for (int q = 0; q < planes; ++q)
    for (int k = b.begin[2]; k < b.end[2]; ++k)
      for (int j = b.begin[1]; j < b.end[1]; ++j) {
        T* row = data + q * stride + block.index(b.begin[0], j, k);
        const int len = b.end[0] - b.begin[0];
        for (int i = 0; i < len; ++i, ++n) {
          if constexpr (Pack) buffer[n] = row[i];
          else row[i] = buffer[n];
        }
      }
}

/// Fills the ghost nodes of `data` (the local array of `block`) from the neighbours. Collective
/// over `comm`: every rank calls it with its own links. `skipTag` >= 0 leaves the messages of
/// that direction index undelivered (tests only: proves the tests can see a missing direction).
template <class T>
void exchangeHalo(MPI_Comm comm, const LocalBlock& block, const std::vector<HaloLink>& links,
                  T* data, int planes, std::int64_t stride, int skipTag = -1) {
  std::vector<std::vector<T>> sendBuffers(links.size()), receiveBuffers(links.size());
  std::vector<MPI_Request> requests;
  requests.reserve(2 * links.size());
  for (std::size_t l = 0; l < links.size(); ++l) {
    const HaloLink& link = links[l];
    receiveBuffers[l].resize(static_cast<std::size_t>(planes * link.receive.nodeCount()));
    requests.emplace_back();
    MPI_Irecv(receiveBuffers[l].data(), static_cast<int>(receiveBuffers[l].size()), mpiTypeOf<T>(),
              link.neighbour, link.receiveTag, comm, &requests.back());
  }
  for (std::size_t l = 0; l < links.size(); ++l) {
    const HaloLink& link = links[l];
    sendBuffers[l].resize(static_cast<std::size_t>(planes * link.send.nodeCount()));
    copyBox<T, true>(block, link.send, data, planes, stride, sendBuffers[l].data());
    requests.emplace_back();
    MPI_Isend(sendBuffers[l].data(), static_cast<int>(sendBuffers[l].size()), mpiTypeOf<T>(),
              link.neighbour, link.sendTag, comm, &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  for (std::size_t l = 0; l < links.size(); ++l)
    if (links[l].receiveTag != skipTag)
      copyBox<T, false>(block, links[l].receive, data, planes, stride, receiveBuffers[l].data());
}

}  // namespace fluidviz::lbm
