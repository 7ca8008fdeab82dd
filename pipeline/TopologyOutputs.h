#pragma once
// What `fluidviz topology` and `fluidviz sweep` write about the topology of a planar flow: the
// critical points as CSV, and the topology picture: critical point glyphs (one shape and colour
// per type, fieldviz/render/CriticalPointGlyphs.h) and separatrices (with arrowheads pointing
// downstream) over a LIC picture of the flow coloured by speed (fieldviz/render/LicPicture.h),
// with a legend of the types below the picture.
#include <functional>
#include <string>
#include <vector>

#include "fieldviz/core/Field.h"
#include "fieldviz/core/Params.h"
#include "fieldviz/core/PointMask.h"
#include "fieldviz/render/FieldImage.h"
#include "fieldviz/render/LicBlend.h"
#include "fieldviz/render/RgbaImage.h"
#include "fieldviz/render/StreamlineOverlay.h"
#include "filters/lic/LicParams.h"
#include "filters/topology/CriticalPoint.h"
#include "filters/topology/CriticalPoint3D.h"
#include "filters/topology/Separatrices.h"

namespace fluidviz {

/// The CSV header of critical point tables, exactly as written.
inline constexpr const char* kCriticalPointsCsvHeader =
    "x,y,z,type,index,morse,det,trace,hyperbolic,elliptic,parabolic";

/// One CSV row per point (no header): x,y,z in m, the type name, the Poincare index, morse 0/1,
/// det (1/s^2) and trace (1/s) of the Jacobian, and the sector counts; numbers with 10
/// significant digits.
std::string criticalPointCsvRow(const topology::CriticalPoint& p);
/// Header line and one row per point.
std::string criticalPointsCsv(const std::vector<topology::CriticalPoint>& points);

/// The CSV header of the critical points of a 3D field, exactly as written.
inline constexpr const char* kCriticalPoints3DCsvHeader =
    "x,y,z,type,index,morse,det,trace,index_measured,cluster_size,"
    "eigenvalue1_re,eigenvalue1_im,eigenvalue2_re,eigenvalue2_im,eigenvalue3_re,eigenvalue3_im";
/// One row per point of a 3D field (no header): x,y,z in m, the type name, the index (degree on
/// the sphere), morse 0/1, det (1/s^3) and trace (1/s) of the Jacobian, index_measured 0/1,
/// the number of interpolant zeros merged, the eigenvalues (1/s, larger real part first).
std::string criticalPoint3DCsvRow(const topology::CriticalPoint3D& p);
/// Header line and one row per point.
std::string criticalPoints3DCsv(const std::vector<topology::CriticalPoint3D>& points);
/// (type name, count) of the points present, in the order of CriticalPointType3D.
std::vector<std::pair<std::string, int>> countTypes3D(
    const std::vector<topology::CriticalPoint3D>& points);

/// Under the glyphs: the LIC texture over the speed colours, or the colours only.
enum class TopologyUnderlay { lic, speed };
constexpr std::array<Choice<TopologyUnderlay>, 2> paramChoices(TopologyUnderlay) {
  return {{{TopologyUnderlay::lic, "lic"}, {TopologyUnderlay::speed, "speed"}}};
}

struct TopologyPictureParams {
  TopologyUnderlay underlay = TopologyUnderlay::lic;
  double glyph_size = 16.0;        ///< diameter of a critical point glyph
  bool separatrices = true;        ///< draw the separatrices
  FieldImageParams picture;        ///< title, colour map, legend; size: lic.width (lic) or as given
  lic::LicParams lic;              ///< the LIC texture (lic.width: texture width, px)
  LicBlendParams blend;            ///< colour under the texture (color_by: speed or vorticity)
  StreamlineStyle separatrix_style;  ///< colour, width and arrowheads of the separatrices

  TopologyPictureParams() {
    lic.width = kDefaultPictureWidth;
    separatrix_style.line_width = 2.0;
    separatrix_style.arrow_spacing = 160.0;
  }

  template <class V>
  static void describe(V& v) {
    v(&TopologyPictureParams::underlay,
      {.key = "underlay",
       .description = "under the glyphs: lic (LIC texture over the speed colours) or speed "
                      "(colour map only; cheaper)"});
    v(&TopologyPictureParams::glyph_size, {.key = "glyph_size",
                                           .unit = "px",
                                           .description = "diameter of a critical point glyph",
                                           .min = 4,
                                           .max = 100});
    v(&TopologyPictureParams::separatrices,
      {.key = "separatrices", .description = "draw the separatrices"});
    v(&TopologyPictureParams::picture, {.key = "picture", .description = "title, colours, legend"});
    v(&TopologyPictureParams::lic, {.key = "lic", .description = "LIC texture (background lic)"});
    v(&TopologyPictureParams::blend,
      {.key = "blend", .description = "colour under the LIC texture"});
    v(&TopologyPictureParams::separatrix_style,
      {.key = "separatrix_style", .description = "how separatrices are drawn"});
  }
};

/// Checks every key against its declared range (ParamError naming the key).
void validateTopologyPictureParams(const TopologyPictureParams& p);

/// Nodes for which `solid` is true (e.g. inside rollers) are masked in the LIC texture.
using SolidTest = std::function<bool(const Vec3&)>;

/// The nodes of `mask` as a SolidTest: a point is solid where at least half of its cell's corners
/// are masked (maskFraction >= 0.5); empty for an empty mask. Keeps references to both.
SolidTest maskedCells(const Grid& grid, const PointMask& mask);

/// The topology picture of a 2D velocity field (z layer already taken) with the legend below.
/// Throws ParamError for bad parameters, std::invalid_argument for a field that LIC or the
/// picture cannot use (non-finite values, 3D).
RgbaImage renderTopologyPicture(const VectorField& velocity,
                                const std::vector<topology::CriticalPoint>& points,
                                const std::vector<topology::Separatrix>& separatrices,
                                const TopologyPictureParams& params, const SolidTest& solid = {});

/// "monkey saddle (1)" style legend labels: the types present, in the glyph table's order.
std::vector<std::pair<std::string, int>> countTypes(
    const std::vector<topology::CriticalPoint>& points);

}  // namespace fluidviz
