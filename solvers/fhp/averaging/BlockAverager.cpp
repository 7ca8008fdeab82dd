#include "solvers/fhp/averaging/BlockAverager.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "solvers/fhp/lattice/TriangularLattice.h"

namespace fluidviz::fhp {

BlockAverager::BlockAverager(int nx, int ny, int bx, int by)
    : nx_(nx), ny_(ny), bx_(bx), by_(by), nbx_(bx > 0 ? nx / bx : 0), nby_(by > 0 ? ny / by : 0) {
  if (bx < 1 || nx % bx != 0)
    throw std::invalid_argument("FHP averaging: block width " + std::to_string(bx) +
                                " must divide the lattice width " + std::to_string(nx));
  if (by < 1 || ny % by != 0)
    throw std::invalid_argument("FHP averaging: block height " + std::to_string(by) +
                                " must divide the lattice height " + std::to_string(ny));
  clear();
}

void BlockAverager::clear() {
  const std::size_t n = static_cast<std::size_t>(nbx_) * nby_;
  count_.assign(n, 0.0);
  jx_.assign(n, 0.0);
  jy_.assign(n, 0.0);
  fluidNodes_.assign(n, 0.0);
  samples_ = 0;
}

void BlockAverager::add(const BitLattice& lattice) {
  if (lattice.nx() != nx_ || lattice.ny() != ny_)
    throw std::invalid_argument("FHP averaging: lattice size differs from the averager's");
#pragma omp parallel for schedule(static)
  for (int by = 0; by < nby_; ++by) {
    for (int y = by * by_; y < (by + 1) * by_; ++y) {
      for (int x = 0; x < nx_; ++x) {
        if (lattice.isSolid(x, y)) continue;
        const std::size_t k = static_cast<std::size_t>(by) * nbx_ + x / bx_;
        const std::uint8_t s = lattice.node(x, y);
        double jx = 0.0, jy = 0.0;
        for (int c = 0; c < kMovingChannels; ++c)
          if (s & (1u << c)) {
            jx += kCx[c];
            jy += kCy[c];
          }
        count_[k] += std::popcount(static_cast<unsigned>(s));
        jx_[k] += jx;
        jy_[k] += jy;
        fluidNodes_[k] += 1.0;
      }
    }
  }
  ++samples_;
}

std::vector<double> BlockAverager::densityPerNode() const {
  std::vector<double> r(count_.size(), 0.0);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (fluidNodes_[k] > 0) r[k] = count_[k] / fluidNodes_[k];
  return r;
}
std::vector<double> BlockAverager::currentX() const {
  std::vector<double> r(jx_.size(), 0.0);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (fluidNodes_[k] > 0) r[k] = jx_[k] / fluidNodes_[k];
  return r;
}
std::vector<double> BlockAverager::currentY() const {
  std::vector<double> r(jy_.size(), 0.0);
  for (std::size_t k = 0; k < r.size(); ++k)
    if (fluidNodes_[k] > 0) r[k] = jy_[k] / fluidNodes_[k];
  return r;
}

std::vector<double> BlockAverager::fluidFraction() const {
  std::vector<double> r(fluidNodes_.size(), 0.0);
  if (samples_ == 0) return r;
  const double nodes = static_cast<double>(bx_) * by_ * samples_;
  for (std::size_t k = 0; k < r.size(); ++k) r[k] = fluidNodes_[k] / nodes;
  return r;
}

std::vector<double> BlockAverager::sums() const {
  std::vector<double> r;
  for (const auto* v : {&count_, &jx_, &jy_, &fluidNodes_}) r.insert(r.end(), v->begin(), v->end());
  return r;
}

void BlockAverager::restoreSums(const std::vector<double>& sums, int samples) {
  const std::size_t n = count_.size();
  if (sums.size() != 4 * n)
    throw std::invalid_argument("FHP averaging: saved sums have the wrong size");
  std::size_t at = 0;
  for (auto* v : {&count_, &jx_, &jy_, &fluidNodes_}) {
    std::copy(sums.begin() + at, sums.begin() + at + n, v->begin());
    at += n;
  }
  samples_ = samples;
}

FieldSet BlockAverager::fields(double linkLength) const {
  Grid g;
  g.dims = {nbx_, nby_, 1};
  g.spacing = {bx_ * linkLength, by_ * kRowSpacing * linkLength, 1.0};
  // Centre of a block: mean x of its nodes, odd rows shifted by half a link.
  g.origin = {((bx_ - 1) / 2.0 + 0.25 * (by_ > 1 ? 1.0 : 0.0)) * linkLength,
              (by_ - 1) / 2.0 * kRowSpacing * linkLength, 0.0};
  const auto rho = densityPerNode(), jx = currentX(), jy = currentY();
  ScalarField density{"density", g, rho};
  VectorField velocity{"velocity", g, std::vector<Vec3>(rho.size(), Vec3::Zero())};
  for (std::size_t k = 0; k < rho.size(); ++k)
    if (rho[k] > 0) velocity.values[k] = Vec3(jx[k] / rho[k], jy[k] / rho[k], 0.0);
  FieldSet set;
  set.grid = g;
  set.add(std::move(density));
  set.add(std::move(velocity));
  return set;
}

}  // namespace fluidviz::fhp
