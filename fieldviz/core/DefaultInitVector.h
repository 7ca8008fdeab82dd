#pragma once
// std::vector whose resize() leaves new elements of trivial types uninitialised (default-
// initialised) instead of zeroing them. For large scratch arrays that a parallel loop fills at
// once: zeroing would write every page from one thread first (serial page faults and a wasted
// pass over memory), while the parallel fill touches each page from the thread that uses it.
#include <memory>
#include <vector>

namespace fluidviz {

template <class T, class Base = std::allocator<T>>
struct DefaultInitAllocator : Base {
  using Base::Base;
  template <class U>
  struct rebind {
    using other =
        DefaultInitAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
  };
  template <class U>
  void construct(U* p) noexcept(noexcept(::new (static_cast<void*>(p)) U)) {
    ::new (static_cast<void*>(p)) U;  // default-initialisation: no zeroing for trivial U
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    std::allocator_traits<Base>::construct(static_cast<Base&>(*this), p,
                                           std::forward<Args>(args)...);
  }
};

template <class T>
using DefaultInitVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace fluidviz
