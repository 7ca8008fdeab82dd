#pragma once
// The texts of a scene's pictures: titles from templates (output.images[].title,
// output.lic[].title; defaults kImageTitleTemplate, kLicTitleTemplate in SceneParams.h) and
// legend titles with units, in one place for every solver and picture.
//
// Placeholders of a title (fieldviz/core/TextTemplate.h):
//   {name}    the scene's name          {field}  the field drawn ("vorticity")
//   {units}   the field's units ("1/s") {time}   the time of the drawn state, s
//   {solver}  lbm or sph
//   {KEY}     any scene key with a value: its dotted path from the scene's root
//             ({lbm.reynolds}, {sph.viscosity}), or its last part when that names one key of
//             the solver's section ({reynolds}).
#include <string>
#include <string_view>

#include "pipeline/SceneParams.h"

namespace fluidviz {

/// The units of a field a picture may show ("m/s", "1/s", "Pa"); "1" for a dimensionless one.
std::string fieldUnits(std::string_view field);
/// A legend title: "vorticity (1/s)".
std::string legendTitleOf(std::string_view field);
/// A legend title that names the field as shown ("|velocity|") with the field's units:
/// "|velocity| (m/s)".
std::string legendTitleOf(std::string_view shown, std::string_view field);

/// What a picture shows, for its title.
struct PictureSubject {
  std::string field;  ///< as the scene names it: "speed", "vorticity"
  double time = 0;    ///< s
};

/// `titleTemplate` with its placeholders filled in for `subject` (empty stays empty). Throws
/// ParamError on key `key` for an unknown or valueless placeholder, naming those there are.
std::string pictureTitle(const SceneParams& scene, const std::string& key,
                         const std::string& titleTemplate, const PictureSubject& subject);

/// Every title template of the scene's pictures expands (checked before the run): ParamError
/// naming the key ("output.images[0].title") otherwise.
void validatePictureTitles(const SceneParams& scene);

}  // namespace fluidviz
