#pragma once
// LIC pictures: a LIC texture blended with a colour-mapped scalar (LicBlend.h rule), with the
// title and colour legend of field pictures (FieldImage.h), optionally streamlines on top
// (StreamlineOverlay.h). Texture pixels map 1:1 onto picture pixels: the picture is sized so
// that the field area is exactly as large as the texture.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/LicBlend.h"
#include "fieldviz/render/StreamlineOverlay.h"

namespace fluidviz {

/// Streamlines to draw over a picture.
struct LineOverlay {
  std::vector<std::vector<Vec3>> lines;  ///< world coordinates, points in downstream order
  StreamlineStyle style;
};

/// Sets picture.width and picture.height so that the field of `field` (a 2D grid) fills exactly
/// `fieldWidth` px horizontally and (fieldWidth * Ly / Lx) px vertically, with the title and
/// legend around it and no spare margin. Throws ParamError("width"/"height") when the picture
/// would exceed FieldImageParams' 8192 px limit.
void fitPictureToField(const ScalarField& field, FieldImageParams& picture, int fieldWidth);

struct LicPicture {
  RgbaImage image;
  PixelRect texture;                ///< picture pixels covered by the texture (whole numbers)
  std::array<double, 2> range{};    ///< colour range used for the blend and the legend
};

/// A LIC picture's scene before anything is drawn over it: the picture fitted to the texture
/// (fitPictureToField), the texture blended with `colour` in place. For pictures that add their
/// own overlays (topology glyphs); arguments and errors as renderLicPicture.
struct LicScene {
  std::unique_ptr<FieldImageScene> scene;
  PixelRect texture;              ///< picture pixels covered by the texture
  std::array<double, 2> range{};  ///< colour range used for the blend and the legend
};
LicScene makeLicScene(const ScalarField& texture, const std::vector<std::uint8_t>& mask,
                      const ScalarField& colour, FieldImageParams picture,
                      const LicBlendParams& blend);

/// The LIC picture. `texture` is the LIC image on its pixel-centre grid (values in [0, 1]),
/// `mask` one entry per texture pixel or empty, `colour` the scalar on the 2D field grid the
/// texture covers. picture.width/height are replaced (fitPictureToField). Throws ParamError for
/// bad parameters (keys of FieldImageParams, LicBlendParams, StreamlineStyle).
LicPicture renderLicPicture(const ScalarField& texture, const std::vector<std::uint8_t>& mask,
                            const ScalarField& colour, FieldImageParams picture,
                            const LicBlendParams& blend,
                            const std::vector<LineOverlay>& lines = {});

/// A field picture and the colour range its colours and legend use.
struct FieldPicture {
  RgbaImage image;
  std::array<double, 2> range{};
};

/// A field picture (FieldImage.h) with streamlines on top; picture size as given.
FieldPicture renderFieldPicture(const ScalarField& field, const FieldImageParams& picture,
                             const std::vector<LineOverlay>& lines = {});

}  // namespace fluidviz
