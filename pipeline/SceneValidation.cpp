#include "pipeline/SceneValidation.h"

#include <algorithm>
#include <filesystem>

#include "pipeline/FlowOutputs.h"
#include "pipeline/PictureText.h"
#include "pipeline/PictureSeries.h"
#include "pipeline/Probes.h"
#include "pipeline/TimeSeries.h"
#include "pipeline/SolverFactory.h"
#include "pipeline/SphGridOutputs.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

void validateSceneName(const SceneParams& scene) {
  if (scene.name.empty() ||
      scene.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") !=
          std::string::npos)
    throw ParamError("name", "is \"" + scene.name +
                                 "\"; allowed: letters, digits, '_' and '-' (it prefixes file names)");
}

void validateImageOutputs(const SceneParams& scene) {
  std::vector<std::string> taken;
  for (std::size_t i = 0; i < scene.output.images.size(); ++i) {
    const std::string key = "output.images[" + std::to_string(i) + "]";
    requireOutputFileName(key + ".file", imageFileName(scene, scene.output.images[i]), ".png",
                          taken);
    withKeyPrefix(key + ".", [&] { validateFieldImageParams(scene.output.images[i]); });
  }
}

}  // namespace

void requireOutputFileName(const std::string& key, const std::string& file,
                           const std::string& extension, std::vector<std::string>& taken) {
  if (file.find('/') != std::string::npos || fs::path(file).extension() != extension ||
      fs::path(file).stem().empty())
    throw ParamError(key, "is \"" + file + "\"; allowed: a plain file name ending in " + extension);
  if (std::find(taken.begin(), taken.end(), file) != taken.end())
    throw ParamError(key, "\"" + file + "\" is written by another output too; give each a file "
                          "name");
  taken.push_back(file);
}

std::string imageFileName(const SceneParams& scene, const ImageOutput& image) {
  return image.file.empty() ? scene.name + "_" + choiceName(image.field) + ".png" : image.file;
}

std::vector<std::string> imageFileNames(const SceneParams& scene) {
  std::vector<std::string> files;
  for (const ImageOutput& image : scene.output.images) files.push_back(imageFileName(scene, image));
  return files;
}

void validateScene(const SceneParams& scene, const std::string& sceneFile) {
  withSceneErrors(sceneFile, [&] {
    validateSceneName(scene);
    validateImageOutputs(scene);
    validatePictureTitles(scene);   // output.images[].title, output.lic[].title
    validateFlowOutputs(scene);     // output.lic and output.streamlines
    for (const ScenePicture& picture : scenePictures(scene))  // every_snapshot, movie, fps
      validatePictureSeries(scene, picture);
    validateSphGridOutputs(scene);  // output.grids, free_surface, views (solver sph only)
    validateProbes(scene, sceneFile);  // output.probes (solver lbm only)
    validateTimeSeries(scene, sceneFile);  // output.time_series
    solverEntry(scene.solver).validate(scene);
  });
}

}  // namespace fluidviz
