#pragma once
// Structure-of-arrays storage of the populations: plane q holds f_q of every node, x fastest,
// so the stream-collide kernel reads and writes each plane with unit stride (vectorisable).
// Planes are cache-line aligned; the owner may pad their stride off multiples of 4 KiB and shift
// the second array, so that the Q read and Q write streams do not alias in the L1 cache.
// T = double or float (lbm.precision).
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>

namespace fluidviz::lbm {

template <class T>
class PopulationArraysOf {
 public:
  PopulationArraysOf() = default;
  /// Memory is left uninitialised: the owner first-touches it in parallel with the same row
  /// partition as the kernel.
  /// paddingValues: added to the plane stride; baseOffsetValues: shift of plane 0 from the
  /// allocation (give two arrays different shifts so that reads and writes do not alias).
  PopulationArraysOf(int planes, std::int64_t nodes, std::int64_t paddingValues,
                     std::int64_t baseOffsetValues)
      : stride_(roundUp(nodes, 512) + paddingValues) {
    const std::size_t bytes =
        static_cast<std::size_t>(planes * stride_ + baseOffsetValues) * sizeof(T);
    data_.reset(static_cast<T*>(std::aligned_alloc(kAlignment, roundUp(bytes, kAlignment))));
    if (!data_) throw std::bad_alloc();
    base_ = data_.get() + baseOffsetValues;
  }
  T* data() { return base_; }
  const T* data() const { return base_; }
  std::int64_t stride() const { return stride_; }  ///< values between planes q and q + 1

 private:
  static constexpr std::size_t kAlignment = 64;
  static std::int64_t roundUp(std::int64_t n, std::int64_t m) { return (n + m - 1) / m * m; }
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::int64_t stride_ = 0;
  T* base_ = nullptr;
  std::unique_ptr<T[], Free> data_;
};

using PopulationArrays = PopulationArraysOf<double>;

}  // namespace fluidviz::lbm
