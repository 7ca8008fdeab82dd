#pragma once
// Structure-of-arrays storage of the populations: plane q holds f_q of every node, x fastest,
// so the stream-collide kernel reads and writes each plane with unit stride (vectorisable).
// Planes are cache-line aligned (the stream-collide kernel writes whole lines, StreamCollidePull.h,
// so node n starts a line in every plane iff n % (64 / sizeof(T)) == 0); the owner may pad their
// stride off multiples of 4 KiB by whole lines and shift the second array by whole lines, so that
// the Q read and Q write streams do not alias in the L1 cache. Large arrays are 2 MiB aligned and
// ask Linux for transparent huge pages: the 2 Q streams of a step then need 2 Q TLB entries per
// 2 MiB instead of per 4 KiB.
// T = double or float (lbm.precision).
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <stdexcept>
#if defined(__linux__)
#include <sys/mman.h>
#endif

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
      : stride_(roundUp<std::int64_t>(nodes, 512) + paddingValues) {
    if ((stride_ * sizeof(T)) % kAlignment != 0 || (baseOffsetValues * sizeof(T)) % kAlignment != 0)
      throw std::invalid_argument("PopulationArrays: padding and offset must be whole cache lines");
    // + one spare line: the kernel may load a whole line starting at the last node of a plane.
    const std::size_t bytes =
        static_cast<std::size_t>(planes * stride_ + baseOffsetValues) * sizeof(T) + kAlignment;
    const std::size_t alignment = bytes >= kHugePage ? kHugePage : kAlignment;
    const std::size_t allocated = roundUp(bytes, alignment);
    data_.reset(static_cast<T*>(std::aligned_alloc(alignment, allocated)));
    if (!data_) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (alignment == kHugePage) madvise(data_.get(), allocated, MADV_HUGEPAGE);  // a hint only
#endif
    base_ = data_.get() + baseOffsetValues;
  }
  T* data() { return base_; }
  const T* data() const { return base_; }
  std::int64_t stride() const { return stride_; }  ///< values between planes q and q + 1

 private:
  static constexpr std::size_t kAlignment = 64;  // a cache line
  static constexpr std::size_t kHugePage = std::size_t(2) << 20;
  template <class I>
  static I roundUp(I n, I m) { return (n + m - 1) / m * m; }
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::int64_t stride_ = 0;
  T* base_ = nullptr;
  std::unique_ptr<T[], Free> data_;
};

using PopulationArrays = PopulationArraysOf<double>;

}  // namespace fluidviz::lbm
