#pragma once
// The properties of the LIC proxy: the texture's (lic::LicParams, as output.lic[] and
// `fluidviz lic`), the blend of the texture with a scalar (LicBlendParams: color_by, lic_weight,
// mask_color) and the colour map and range of that scalar (FieldImageParams' colormap, range_min,
// range_max). Every key is the declaration of the scene and the CLI, not a copy; the picture keys
// of FieldImageParams that a texture has no use for (title, axes, ...) are left out.
#include <array>
#include <string_view>

#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/LicBlend.h"
#include "filters/lic/LicParams.h"

namespace fluidviz::paraview {

/// Forwards to V the declarations whose key is one of `keys`.
template <class V, std::size_t N>
struct OnlyKeys {
  V& v;
  std::array<std::string_view, N> keys;

  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    for (std::string_view k : keys)
      if (k == info.key) v(member, info);
  }
};

struct LicProxyParams : lic::LicParams, LicBlendParams, FieldImageParams {
  // No scalar under the texture unless the user names one (the CLI's default is speed, which
  // needs a picture; a proxy's output is the texture first).
  LicProxyParams() { color_by = ""; }

  template <class V>
  static void describe(V& v) {
    lic::LicParams::describe(v);
    LicBlendParams::describe(v);
    OnlyKeys<V, 3> colours{v, {"colormap", "range_min", "range_max"}};
    FieldImageParams::describe(colours);
  }
};

}  // namespace fluidviz::paraview
