#pragma once
// One cache line of populations (8 doubles or 16 floats) as a value type with the arithmetic of a
// scalar, so that the collision operators (CollisionBGK.h, CollisionTRT.h) and nodeMoments
// (Equilibrium.h), written for a scalar T, run unchanged on W nodes at once (T = LineOf<double>).
// Built on the GCC/Clang vector extension: the compiler lowers a 64-byte vector to one AVX-512
// register, two AVX2 or four SSE registers, whichever the enclosing function's target allows.
//
// Why a hand-vectorised line rather than the auto-vectorised node loop: the stream-collide step
// must write its Q result planes with streaming (non-temporal) stores of whole cache lines
// (StreamCollidePull.h explains the measurements), and GCC has no way to ask for those in an
// auto-vectorised loop. streamLine() below stores one line with the widest streaming store of
// the instruction set `Isa` (IsaV4: one 64-byte store; IsaV3: two 32-byte; IsaBase: four
// 16-byte on x86-64, a plain store elsewhere).
#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "solvers/lbm/kernel/KernelInline.h"

#if defined(__x86_64__) || defined(_M_X64)
#include <immintrin.h>
#define FLUIDVIZ_LBM_X86 1
#endif

// AVX2 and AVX-512 code paths (picked at run time, LbmSolverImpl.cpp) need GCC's target
// attribute; other compilers build the baseline path only.
#if defined(FLUIDVIZ_LBM_X86) && defined(FLUIDVIZ_MULTI_ISA)
#define FLUIDVIZ_LBM_MULTI_ISA 1
#endif

namespace fluidviz::lbm {

inline constexpr int kCacheLineBytes = 64;

template <class T>
struct LineRaw;
template <>
struct LineRaw<double> {
  typedef double type __attribute__((vector_size(kCacheLineBytes)));
  typedef std::int64_t mask __attribute__((vector_size(kCacheLineBytes)));
};
template <>
struct LineRaw<float> {
  typedef float type __attribute__((vector_size(kCacheLineBytes)));
  typedef std::int32_t mask __attribute__((vector_size(kCacheLineBytes)));
};

template <class T>
struct LineOf {
  using Raw = typename LineRaw<T>::type;
  using Scalar = T;
  static constexpr int width = kCacheLineBytes / static_cast<int>(sizeof(T));
  using Mask = typename LineRaw<T>::mask;
  Raw v;

  LineOf() = default;
  /// Broadcast (implicit, as for a scalar: `T x = 0`, `T(1.5)` in the collision code).
  FLUIDVIZ_LBM_INLINE LineOf(double s) {  // NOLINT(google-explicit-constructor)
    const T t = static_cast<T>(s);
    for (int i = 0; i < width; ++i) v[i] = t;
  }
  /// Broadcast of a value known only at run time, through its bit pattern: GCC lowers the
  /// constructor's lane loop for such a value into one masked move per lane (16 in float);
  /// vector + scalar is one broadcast, and adding to integer 0 keeps every bit (even of -0.0).
  /// (For constants the constructor is folded and better: the collision's stay in registers.)
  FLUIDVIZ_LBM_INLINE static LineOf broadcast(T s) {
    std::remove_reference_t<decltype(Mask{}[0])> bits;
    std::memcpy(&bits, &s, sizeof bits);
    return fromRaw((Raw)(Mask{} + bits));
  }
  FLUIDVIZ_LBM_INLINE static LineOf fromRaw(Raw r) {
    LineOf x;
    x.v = r;
    return x;
  }
  /// W consecutive values from any address.
  FLUIDVIZ_LBM_INLINE static LineOf load(const T* p) {
    Raw r;
    std::memcpy(&r, p, sizeof r);
    return fromRaw(r);
  }
  FLUIDVIZ_LBM_INLINE void store(T* p) const { std::memcpy(p, &v, sizeof v); }
  /// width all-ones lanes, then width zero lanes: the width lanes from element width - k are
  /// "lanes < k".
  static constexpr auto kBelow = [] {
    std::array<std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>, 2 * width> t{};
    for (int i = 0; i < width; ++i) t[i] = -1;
    return t;
  }();
  /// All bits set in lanes [from, to), clear elsewhere (0 <= from <= to <= width). From a
  /// table in memory: with a constant lane-index vector GCC folds each lane's compare into a
  /// scalar test and blends lane by lane with conditional moves (5x slower float mixed lines).
  FLUIDVIZ_LBM_INLINE static Mask lanes(int from, int to) {
    Mask below[2];  // lanes < to, lanes < from
    std::memcpy(&below[0], kBelow.data() + (width - to), sizeof(Mask));
    std::memcpy(&below[1], kBelow.data() + (width - from), sizeof(Mask));
    return below[0] & ~below[1];
  }
  /// The lanes `inside` (lanes()) of a, the others of b (bitwise, so that garbage in the unused
  /// lanes of a cannot leak, not even a NaN).
  /// The lanes `inside` of a, zero bits elsewhere.
  FLUIDVIZ_LBM_INLINE static LineOf keep(Mask inside, LineOf a) {
    return fromRaw((Raw)((Mask)a.v & inside));
  }
  FLUIDVIZ_LBM_INLINE static LineOf select(Mask inside, LineOf a, LineOf b) {
    return fromRaw((Raw)(((Mask)a.v & inside) | ((Mask)b.v & ~inside)));
  }

  FLUIDVIZ_LBM_INLINE LineOf& operator+=(LineOf o) {
    v += o.v;
    return *this;
  }
  FLUIDVIZ_LBM_INLINE LineOf& operator-=(LineOf o) {
    v -= o.v;
    return *this;
  }
  FLUIDVIZ_LBM_INLINE friend LineOf operator+(LineOf a, LineOf b) { return fromRaw(a.v + b.v); }
  FLUIDVIZ_LBM_INLINE friend LineOf operator-(LineOf a, LineOf b) { return fromRaw(a.v - b.v); }
  FLUIDVIZ_LBM_INLINE friend LineOf operator*(LineOf a, LineOf b) { return fromRaw(a.v * b.v); }
  FLUIDVIZ_LBM_INLINE friend LineOf operator/(LineOf a, LineOf b) { return fromRaw(a.v / b.v); }
  FLUIDVIZ_LBM_INLINE friend LineOf operator-(LineOf a) { return fromRaw(-a.v); }
};

/// Baseline x86-64 (SSE2) or any other CPU.
struct IsaBase {
  static constexpr const char* name = "baseline";
  template <class T>
  FLUIDVIZ_LBM_INLINE static void streamLine(T* p, const LineOf<T>& x) {
#if defined(FLUIDVIZ_LBM_X86)
    const T* s = reinterpret_cast<const T*>(&x.v);
    for (int i = 0; i < LineOf<T>::width; i += 16 / int(sizeof(T))) {
      if constexpr (sizeof(T) == 8)
        _mm_stream_pd(reinterpret_cast<double*>(p) + i, _mm_loadu_pd(reinterpret_cast<const double*>(s) + i));
      else
        _mm_stream_ps(reinterpret_cast<float*>(p) + i, _mm_loadu_ps(reinterpret_cast<const float*>(s) + i));
    }
#else
    x.store(p);
#endif
  }
};

#if defined(FLUIDVIZ_LBM_MULTI_ISA)
// The raw GCC builtins rather than the intrinsics: an intrinsic carries its own target attribute
// and cannot be inlined into the generic kernel template (whose target is only known where it
// is instantiated, LbmSolverImpl.cpp); a builtin is checked where the code is finally emitted.
typedef double Double4 __attribute__((vector_size(32)));
typedef float Float8 __attribute__((vector_size(32)));

/// x86-64-v3: AVX2, FMA. Only usable in functions compiled for that target.
struct IsaV3 {
  static constexpr const char* name = "x86-64-v3 (AVX2)";
  template <class T>
  FLUIDVIZ_LBM_INLINE static void streamLine(T* p, const LineOf<T>& x) {
    if constexpr (sizeof(T) == 8) {
      const Double4 lo = {x.v[0], x.v[1], x.v[2], x.v[3]}, hi = {x.v[4], x.v[5], x.v[6], x.v[7]};
      __builtin_ia32_movntpd256(reinterpret_cast<double*>(p), lo);
      __builtin_ia32_movntpd256(reinterpret_cast<double*>(p) + 4, hi);
    } else {
      const Float8 lo = {x.v[0], x.v[1], x.v[2], x.v[3], x.v[4], x.v[5], x.v[6], x.v[7]},
                   hi = {x.v[8], x.v[9], x.v[10], x.v[11], x.v[12], x.v[13], x.v[14], x.v[15]};
      __builtin_ia32_movntps256(reinterpret_cast<float*>(p), lo);
      __builtin_ia32_movntps256(reinterpret_cast<float*>(p) + 8, hi);
    }
  }
};

/// x86-64-v4: AVX-512, one register per line. Only usable in functions compiled for that target.
struct IsaV4 {
  static constexpr const char* name = "x86-64-v4 (AVX-512)";
  template <class T>
  FLUIDVIZ_LBM_INLINE static void streamLine(T* p, const LineOf<T>& x) {
    if constexpr (sizeof(T) == 8)
      __builtin_ia32_movntpd512(reinterpret_cast<double*>(p), x.v);
    else
      __builtin_ia32_movntps512(reinterpret_cast<float*>(p), x.v);
  }
};
#endif

/// Makes the streaming stores of this thread visible to the others (before a barrier):
/// x86 orders non-temporal stores only with SFENCE.
inline void fenceStreamingStores() {
#if defined(FLUIDVIZ_LBM_X86)
  _mm_sfence();
#endif
}

}  // namespace fluidviz::lbm
