#pragma once
// An OSMesa OpenGL core-profile context rendering into its own RGBA buffer in main memory: the
// way to render with Debian's VTK (built for X only) on a machine without a display.
// See docs/design.md, "Off-screen rendering", and render/GlInterposers.cpp for the two glvnd traps.
#include <cstdint>
#include <vector>

namespace fluidviz {

class OsMesaContext {
 public:
  /// Creates a 3.2+ core-profile context (Mesa's llvmpipe gives 4.5) with a width x height RGBA8
  /// colour buffer, 24-bit depth and 8-bit stencil, and makes it current. The first context of a
  /// process also checks that the executable resolves GL the OSMesa way; throws
  /// std::runtime_error naming the fix if not, or if the size is outside [1, 16384] px.
  OsMesaContext(int width, int height);
  ~OsMesaContext();
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  /// Binds this context and its buffer to the calling thread.
  void makeCurrent();
  bool isCurrent() const;

  int width() const { return width_; }
  int height() const { return height_; }
  /// The colour buffer: RGBA8, bottom row first (OpenGL's order).
  const std::vector<std::uint8_t>& buffer() const { return buffer_; }

 private:
  int width_;
  int height_;
  std::vector<std::uint8_t> buffer_;
  void* context_ = nullptr;  // OSMesaContext; void* keeps GL headers out of this header
};

}  // namespace fluidviz
