#include "apps/fluidviz/Streamlines3D.h"

#include <vtkDataSetSurfaceFilter.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkProbeFilter.h>
#include <vtkProperty.h>
#include <vtkTubeFilter.h>

#include <algorithm>
#include <sstream>

#include "fieldviz/io/FileError.h"
#include "fieldviz/render/SurfaceRendering.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "filters/isosurface/vtk/Isosurface.h"
#include "pipeline/FlowFields.h"

namespace fluidviz::app {

namespace {

const char* kContextFormat = "allowed: slice:z=K | isosurface:ARRAY=V";

// The lines with `array` on their points: their own speed or integration_time, else the field's
// point array interpolated (trilinear) onto them by vtkProbeFilter.
vtkSmartPointer<vtkPolyData> linesWithArray(const FlowInput& in, vtkPolyData* lines,
                                            const std::string& array) {
  if (lines->GetPointData()->GetArray(array.c_str())) return lines;
  if (!in.image->GetPointData()->GetArray(array.c_str()))
    throw UsageError("--color-by is '" + array + "'; allowed: speed, integration_time or a point "
                     "array of " + in.source + ": " + describePointArrays(in.image));
  vtkNew<vtkProbeFilter> probe;
  probe->SetInputData(lines);
  probe->SetSourceData(in.image);
  probe->Update();
  vtkSmartPointer<vtkPolyData> probed = vtkPolyData::SafeDownCast(probe->GetOutput());
  return probed;
}

std::string legendTitle(const FlowInput& in, const std::string& array) {
  if (array == "speed") return "speed |v| (" + in.units + "/s)";
  if (array == "integration_time") return "integration time (s)";
  return array;
}

// Tubes of `radius` cells (the smallest spacing) around the lines, 10 sides.
vtkSmartPointer<vtkPolyData> tubesAround(vtkPolyData* lines, double radius, const Grid& grid) {
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(lines);
  tubes->SetRadius(radius * std::min({grid.spacing[0], grid.spacing[1], grid.spacing[2]}));
  tubes->SetNumberOfSides(10);
  tubes->CappingOn();
  tubes->Update();
  return tubes->GetOutput();
}

SurfaceActor lineActor(const FlowInput& in, vtkPolyData* lines, const Streamlines3DPicture& p) {
  vtkSmartPointer<vtkPolyData> coloured = linesWithArray(in, lines, p.color_by);
  if (p.tube_radius > 0) coloured = tubesAround(coloured, p.tube_radius, in.velocity.grid);
  SurfaceStyle style;
  style.color_by = p.color_by;
  style.colormap = p.colormap;
  SurfaceActor actor;
  try {
    actor = makeSurfaceActor(coloured, style);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--color-by: ") + e.what());
  }
  if (p.tube_radius <= 0) {
    // Lines have no normals: lit only by ambient light they keep their colour-map colours.
    actor.actor->GetProperty()->SetAmbient(1.0);
    actor.actor->GetProperty()->SetDiffuse(0.0);
    actor.actor->GetProperty()->SetSpecular(0.0);
    actor.actor->GetProperty()->SetLineWidth(static_cast<float>(p.line_width));
  }
  return actor;
}

// "slice:z=K": the z layer K of the speed, in greys (the lines keep the colour map).
vtkSmartPointer<vtkActor> sliceContext(const FlowInput& in, const std::string& spec) {
  const int nz = in.velocity.grid.dims[2];
  std::size_t used = 0;
  int k = -1;
  try {
    k = std::stoi(spec.substr(2), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (spec.rfind("z=", 0) != 0 || used == 0 || used + 2 != spec.size())
    throw UsageError("--context is 'slice:" + spec + "'; " + kContextFormat);
  if (k < 0 || k >= nz)
    throw UsageError("--context slice:z=" + std::to_string(k) + " is outside [0, " +
                     std::to_string(nz - 1) + "] for " + in.source);
  FieldSet layer;
  const ScalarField speed = sliceZ(magnitude(in.velocity, "speed"), k);
  layer.grid = speed.grid;
  layer.add(speed);
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(toImageData(layer));
  surface->Update();
  SurfaceStyle style;
  style.color_by = "speed";
  style.colormap = "grayscale";
  style.opacity = 0.8;
  style.specular = 0.0;
  return makeSurfaceActor(surface->GetOutput(), style).actor;
}

// "isosurface:ARRAY=V": that level set, light grey and translucent.
vtkSmartPointer<vtkActor> isosurfaceContext(const FlowInput& in, const std::string& spec) {
  const std::size_t eq = spec.find('=');
  isosurface::IsosurfaceParams params;
  params.array = spec.substr(0, eq);
  try {
    std::size_t used = 0;
    params.value = std::stod(spec.substr(eq + 1), &used);
    if (eq == std::string::npos || params.array.empty() || used + eq + 1 != spec.size())
      throw std::invalid_argument(spec);
  } catch (const std::exception&) {
    throw UsageError("--context is 'isosurface:" + spec + "'; " + kContextFormat);
  }
  params.interpolate_arrays = false;
  vtkSmartPointer<vtkPolyData> surface;
  try {
    surface = isosurface::extractIsosurface(in.image, params, in.source);
  } catch (const std::exception& e) {
    throw UsageError(std::string("--context isosurface: ") + e.what());
  }
  SurfaceStyle style;
  style.color = {0.8, 0.8, 0.8};
  style.opacity = 0.35;
  return makeSurfaceActor(surface, style).actor;
}

vtkSmartPointer<vtkActor> contextActor(const FlowInput& in, const std::string& context) {
  if (context.rfind("slice:", 0) == 0) return sliceContext(in, context.substr(6));
  if (context.rfind("isosurface:", 0) == 0) return isosurfaceContext(in, context.substr(11));
  throw UsageError("--context is '" + context + "'; " + kContextFormat);
}

std::string defaultTitle(const FlowInput& in, const Streamlines3DPicture& p, std::size_t lines) {
  std::ostringstream t;
  t << lines << " streamlines of " << in.array << ", coloured by " << p.color_by;
  if (!p.context.empty()) t << ", with " << p.context;
  return t.str();
}

}  // namespace

std::unique_ptr<Scene3D> streamlinesScene(const FlowInput& in, vtkPolyData* lines,
                                          const Streamlines3DPicture& p) {
  auto scene = std::make_unique<Scene3D>(p.view);
  const SurfaceActor actor = lineActor(in, lines, p);
  scene->add(actor.actor);
  if (actor.coloring) scene->setLegend(actor.coloring->table, legendTitle(in, p.color_by));
  if (!p.context.empty()) scene->add(contextActor(in, p.context));
  const std::string title = p.title ? *p.title : defaultTitle(in, p, lines->GetNumberOfLines());
  if (!title.empty()) scene->setTitle(title);
  std::array<double, 6> bounds;
  in.image->GetBounds(bounds.data());
  scene->setBounds(bounds);
  return scene;
}

}  // namespace fluidviz::app
