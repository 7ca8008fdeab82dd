#include "solvers/fhp/kernel/MovingWall.h"

#include <cmath>
#include <vector>

#include "solvers/fhp/kernel/RandomBits.h"
#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {
namespace {

double dot(int i, const std::array<double, 2>& u) { return kCx[i] * u[0] + kCy[i] * u[1]; }

/// Link flows along one run of fluid directions `arc` (consecutive around the hexagon; `ring`:
/// all six, closed): bounce-back leaves channel j short of the equilibrium at u by
/// delta_j = 2 alpha c_j . u, and turns between neighbouring channels must carry the prefix sums
/// of delta from one channel to the next. An open run whose deltas do not sum to 0 (a corner of
/// a staircase) has their mean taken off; on the ring the circulation of least size is taken.
/// flows[l] > 0: particles move from arc[l] to arc[l + 1].
std::vector<double> linkFlows(const std::vector<int>& arc, bool ring, const WallEquilibrium& e,
                              const std::array<double, 2>& u) {
  const std::size_t n = arc.size();
  std::vector<double> delta(n);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += delta[i] = 2.0 * e.alpha * dot(arc[i], u);
  const std::size_t links = ring ? n : n - 1;
  std::vector<double> flows(links);
  double prefix = 0.0, mean = 0.0;
  for (std::size_t l = 0; l < links; ++l) {
    prefix += delta[l] - (ring ? 0.0 : sum / static_cast<double>(n));
    flows[l] = -prefix;
    mean += flows[l] / static_cast<double>(links);
  }
  if (ring)
    for (double& f : flows) f -= mean;
  return flows;
}

}  // namespace

WallEquilibrium wallEquilibrium(Model model, double d) {
  return {d, channelCount(model) * d / 3.0};
}

double flatWallTurnProbability(const WallEquilibrium& e, double speed) {
  const double a = e.alpha * speed;
  return a / ((e.d + 0.5 * a) * (1.0 - e.d + 0.5 * a));
}

WallNodeMotion wallNodeMotion(int x, int y, const std::array<double, 2>& u,
                              unsigned fluidNeighbours, const WallEquilibrium& e) {
  WallNodeMotion m;
  m.x = x;
  m.y = y;
  auto fluid = [&](int c) { return ((fluidNeighbours >> ((c + 6) % 6)) & 1u) != 0; };
  const bool ring = (fluidNeighbours & 0x3Fu) == 0x3Fu;
  std::array<double, 6> best{};
  for (int start = 0; start < kMovingChannels; ++start) {
    if (!fluid(start) || (ring ? start != 0 : fluid(start - 1))) continue;
    std::vector<int> arc;
    for (int c = start; fluid(c) && arc.size() < kMovingChannels; ++c) arc.push_back(c % 6);
    const std::vector<double> flows = linkFlows(arc, ring, e, u);
    for (std::size_t l = 0; l < flows.size(); ++l) {
      const int a = arc[l], b = arc[(l + 1) % arc.size()];
      const int from = flows[l] > 0 ? a : b, to = flows[l] > 0 ? b : a;
      const double q = std::abs(flows[l]) /
                       ((e.d - e.alpha * dot(from, u)) * (1.0 - e.d + e.alpha * dot(to, u)));
      if (q > best[from] + 1e-15) {
        best[from] = q;
        m.turnTo[from] = static_cast<std::int8_t>(to);
        m.threshold[from] = probabilityThreshold(q);
      }
    }
  }
  return m;
}

std::uint8_t turnReflectedParticles(std::uint8_t bounced, const WallNodeMotion& m,
                                    std::uint64_t seed, std::uint64_t t) {
  unsigned state = bounced;
  for (int j = 0; j < kMovingChannels; ++j) {
    const int k = m.turnTo[j];
    if (k < 0 || !((bounced >> j) & 1u) || ((bounced >> k) & 1u) || ((state >> k) & 1u)) continue;
    const std::uint64_t draw = counterHash(seed, t, static_cast<std::uint64_t>(m.y),
                                           static_cast<std::uint64_t>(m.x),
                                           2 + static_cast<std::uint64_t>(j));
    if (draw < m.threshold[j]) state = (state & ~(1u << j)) | (1u << k);
  }
  return static_cast<std::uint8_t>(state);
}

}  // namespace fluidviz::fhp
