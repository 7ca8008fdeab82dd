#pragma once
// Grouping of nearby points (single linkage): points closer than a radius, directly or through a
// chain of such neighbours, share a label — except that a group never grows beyond a bounding
// box diagonal of `max_diameter`, so that dense points (zeros of noise) do not chain into one
// group spanning the domain. A hash grid of buckets of the radius' size keeps it near-linear in
// the number of points.
#include <vector>

#include "filters/topology/CriticalPoint.h"

namespace fluidviz::topology {

/// Label (0 .. count-1, in order of first appearance) of each point's group.
std::vector<int> singleLinkageLabels(const std::vector<Vec2>& points, double radius,
                                     double max_diameter = 1e300);

/// Largest cluster diameter (cells) the topology filter allows for a given cluster_radius.
inline double maxClusterDiameter(double cluster_radius) { return 3.0 * cluster_radius; }

/// Indices of the points in each group, groups ordered by their first member.
std::vector<std::vector<int>> groupsFromLabels(const std::vector<int>& labels);

}  // namespace fluidviz::topology
