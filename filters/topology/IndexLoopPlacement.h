#pragma once
// Groups the zeros of the interpolant into critical points and places the index loop of each.
//
// Zeros that are not Morse points on their own (|det J| <= det_threshold * G^2 with J the
// interpolant's exact Jacobian at the zero) and closer than cluster_radius (single linkage,
// diameter at most 3 cluster_radius) form one cluster: around a degenerate zero the bilinear
// interpolant may have several spurious zeros (or none in the right cell), whose det J vanishes
// with their distance, so the index is measured on a loop around the whole cluster (sum of the
// indices it encloses). A Morse zero is a cluster of its own, however close its neighbours: two
// genuine Morse points are never merged into one non-Morse point (issue 15). The loop
// is a circle around the cluster's centroid with radius
//     r = min(extent + loop_radius, extent + (d - extent) / 2, b)
// (extent: farthest member from the centroid, d: nearest zero of another cluster, b: distance to
// the domain boundary), so it encloses exactly the cluster and stays inside the domain. When
// another cluster's zero lies within the extent (d <= extent) the two clusters are merged and the
// placement repeated, unless the merged cluster would exceed the diameter limit: then the cluster
// gets no loop (index not measured). A cluster whose extent reaches the domain boundary gets no
// loop either.
// The centre of a cluster of several zeros is not their centroid but the point of smallest
// Jacobian near it (the degenerate point itself; see computeCentreAndExtent).
#include <vector>

#include "filters/topology/CriticalPointDetector.h"

namespace fluidviz::topology {

struct ZeroCluster {
  std::vector<int> members;  ///< indices into the zero list
  Vec2 centre;               ///< the zero itself, or the smallest-Jacobian point, cells
  double extent = 0.0;       ///< farthest member from the centre, cells
  double loop_radius = 0.0;  ///< cells; 0 when no loop fits in the domain
  bool loopFits() const { return loop_radius > 0.0; }
};

std::vector<ZeroCluster> clusterZerosAndPlaceLoops(const PlanarField& field,
                                                   const std::vector<InterpolantZero>& zeros,
                                                   const TopologyParams& params);

}  // namespace fluidviz::topology
