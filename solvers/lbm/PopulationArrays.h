#pragma once
// Structure-of-arrays storage of the populations: plane q holds f_q of every node, x fastest,
// so the stream-collide kernel reads and writes each plane with unit stride (vectorisable).
// Planes are cache-line aligned; the owner may pad their stride off multiples of 4 KiB and shift
// the second array, so that the 9 read and 9 write streams do not alias in the L1 cache.
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>

namespace fluidviz::lbm {

class PopulationArrays {
 public:
  PopulationArrays() = default;
  /// Memory is left uninitialised: the owner first-touches it in parallel with the same row
  /// partition as the kernel.
  /// paddingDoubles: added to the plane stride; baseOffsetDoubles: shift of plane 0 from the
  /// allocation (give two arrays different shifts so that reads and writes do not alias).
  PopulationArrays(int planes, std::int64_t nodes, std::int64_t paddingDoubles,
                   std::int64_t baseOffsetDoubles)
      : stride_(roundUp(nodes, 512) + paddingDoubles) {
    const std::size_t bytes =
        static_cast<std::size_t>(planes * stride_ + baseOffsetDoubles) * sizeof(double);
    data_.reset(static_cast<double*>(std::aligned_alloc(kAlignment, roundUp(bytes, kAlignment))));
    if (!data_) throw std::bad_alloc();
    base_ = data_.get() + baseOffsetDoubles;
  }
  double* data() { return base_; }
  const double* data() const { return base_; }
  std::int64_t stride() const { return stride_; }  ///< doubles between planes q and q + 1

 private:
  static constexpr std::size_t kAlignment = 64;
  static std::int64_t roundUp(std::int64_t n, std::int64_t m) { return (n + m - 1) / m * m; }
  struct Free {
    void operator()(double* p) const { std::free(p); }
  };
  std::int64_t stride_ = 0;
  double* base_ = nullptr;
  std::unique_ptr<double[], Free> data_;
};

}  // namespace fluidviz::lbm
