#pragma once
// What every picture of the project shares: its default width, the colour of masked nodes and
// the background choice.
#include <array>

#include "fieldviz/core/Params.h"

namespace fluidviz {

/// Width of a picture (px) when a scene or a command gives none: field images, LIC pictures
/// and textures, 3D views.
inline constexpr int kDefaultPictureWidth = 800;

/// RGB in [0, 1] of what is not fluid: solids, masked nodes and NaN values, in LIC pictures
/// (LicBlendParams::mask_color's default) and field pictures alike.
inline constexpr std::array<double, 3> kMaskedGrey{0.75, 0.75, 0.75};

/// white: black text and outlines; dark: white ones.
enum class Background { white, dark };
constexpr std::array<Choice<Background>, 2> paramChoices(Background) {
  return {{{Background::white, "white"}, {Background::dark, "dark"}}};
}

}  // namespace fluidviz
