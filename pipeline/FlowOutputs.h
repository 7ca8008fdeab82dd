#pragma once
// The scene's streamline and LIC outputs (output.streamlines, output.lic) of the final state.
#include <filesystem>
#include <vector>

#include "fieldviz/core/Field.h"
#include "pipeline/PictureSeries.h"
#include "pipeline/SceneParams.h"
#include "fieldviz/render/LicPicture.h"

namespace fluidviz {

/// Checks output.lic and output.streamlines: file names (plain, .png / .vtp, unique among all
/// pictures), parameter ranges and combinations (LicParams, StreamlineParams, seeding, picture
/// and style keys), color_by among the scene's fields, draw_on naming pictures that exist.
/// Throws ParamError with the full key ("output.lic[0].length").
void validateFlowOutputs(const SceneParams& scene);

std::string licFileName(const SceneParams& scene, const LicOutput& lic);
std::string streamlinesFileName(const SceneParams& scene, const StreamlinesOutput& out);

/// Lines of output.streamlines for the pictures that show them.
struct SceneLineOverlays {
  std::vector<LineOverlay> lic;     ///< drawn over output.lic pictures
  std::vector<LineOverlay> images;  ///< drawn over output.images pictures
};

/// Traces every output.streamlines entry on `velocity` (seeds inside solid bodies skipped),
/// writes its .vtp into `dir` (appending to `written`) and returns the lines for the pictures.
SceneLineOverlays writeSceneStreamlines(const SceneParams& scene, const VectorField& velocity,
                                        const std::filesystem::path& dir,
                                        std::vector<std::filesystem::path>& written);

/// The lines of every output.streamlines entry on `velocity` for the pictures, as
/// writeSceneStreamlines but without files (for the frames of a snapshot).
SceneLineOverlays sceneStreamlineOverlays(const SceneParams& scene, const VectorField& velocity);

/// `field` with NaN at the nodes inside the scene's solid bodies (the LBM rollers, turning or
/// fixed): pictures draw them in the masked grey, as LIC pictures do, and leave them out of the
/// colour range (a roller's inside would otherwise show its rigid rotation).
ScalarField outsideSceneSolids(const SceneParams& scene, ScalarField field);

/// The field an output.images picture draws (`name`: an ImageField's name) of the grid fields
/// `fields`: a scalar of the set, a velocity component, or vorticity / stream_function computed
/// for it (of the picture's z layer of a 3D field; then slice_index is cleared); NaN inside the
/// scene's solid bodies.
ScalarField sceneImageField(const SceneParams& scene, const FieldSet& fields,
                            const std::string& name, FieldImageParams& picture);

/// Draws every output.lic picture `to` takes of `fields` (velocity + the color_by scalars) at
/// `time`, solid bodies masked, with `lines` on top.
void writeSceneLicPictures(const SceneParams& scene, const FieldSet& fields, double time,
                           const std::vector<LineOverlay>& lines, const PictureDestination& to,
                           std::vector<std::filesystem::path>& written);

/// Draws every output.images and output.lic picture `to` takes of the grid fields `fields` of a
/// grid solver (LBM, FHP) at `time`, with `lines` on top.
void writeSceneGridPictures(const SceneParams& scene, const FieldSet& fields, double time,
                            const SceneLineOverlays& lines, const PictureDestination& to,
                            std::vector<std::filesystem::path>& written);

}  // namespace fluidviz
