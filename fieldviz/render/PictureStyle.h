#pragma once
// What every picture of the project shares: its default width and the background choice.
#include <array>

#include "fieldviz/core/Params.h"

namespace fluidviz {

/// Width of a picture (px) when a scene or a command gives none: field images, LIC pictures
/// and textures, 3D views.
inline constexpr int kDefaultPictureWidth = 800;

/// white: black text and outlines; dark: white ones.
enum class Background { white, dark };
constexpr std::array<Choice<Background>, 2> paramChoices(Background) {
  return {{{Background::white, "white"}, {Background::dark, "dark"}}};
}

}  // namespace fluidviz
