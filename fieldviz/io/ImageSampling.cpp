#include "fieldviz/io/ImageSampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkResampleToImage.h>

namespace fluidviz {

namespace {

struct Bounds {
  std::array<double, 6> b{};  // xmin xmax ymin ymax zmin zmax
  double points = 0;
};

Bounds boundsOf(vtkDataObject* data) {
  Bounds out;
  if (auto* set = vtkDataSet::SafeDownCast(data)) {
    set->GetBounds(out.b.data());
    out.points = static_cast<double>(set->GetNumberOfPoints());
  } else if (auto* composite = vtkCompositeDataSet::SafeDownCast(data)) {
    composite->GetBounds(out.b.data());
    out.points = static_cast<double>(composite->GetNumberOfPoints());
  }
  return out;
}

// Nodes per axis for a spacing h, from the lower bound on: as many as fit inside the bounds
// (the image stops less than h short of the upper bound rather than reach outside the data);
// flat axes (no extent) get one node.
// Counted in double: extreme bounds (1e30 wide) would overflow an int before the node limit
// refuses them (UBSan, fuzzing).
std::array<double, 3> dimensionsFor(const Bounds& bounds, double h) {
  std::array<double, 3> dims{};
  for (int a = 0; a < 3; ++a) {
    const double extent = bounds.b[2 * a + 1] - bounds.b[2 * a];
    dims[a] = extent > 0 ? std::max(2.0, std::floor(extent / h + 1e-9) + 1) : 1;
  }
  return dims;
}

// About as many nodes as the input has points, equal spacing on every non-flat axis.
double automaticSpacing(const Bounds& bounds) {
  double measure = 1.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a) {
    const double extent = bounds.b[2 * a + 1] - bounds.b[2 * a];
    if (extent > 0) measure *= extent, ++axes;
  }
  const double nodes = std::clamp(bounds.points, 8.0, ImageSampling::kMaxAutomaticNodes);
  return std::pow(measure / nodes, 1.0 / axes);
}

}  // namespace

vtkSmartPointer<vtkImageData> resampleToImage(vtkDataObject* data, const ImageSampling& sampling,
                                              const std::string& source) {
  if (auto* image = vtkImageData::SafeDownCast(data)) return image;
  const Bounds bounds = boundsOf(data);
  if (bounds.points < 1 || !(bounds.b[1] >= bounds.b[0]))
    throw std::invalid_argument(source + " has no points to resample onto an image");
  bool flat = true;
  for (int a = 0; a < 3; ++a) flat = flat && !(bounds.b[2 * a + 1] > bounds.b[2 * a]);
  if (flat) throw std::invalid_argument(source + " has all its points at one place");
  if (!(sampling.spacing >= 0) || !std::isfinite(sampling.spacing))
    throw std::invalid_argument(source + ": the resampling spacing must be >= 0 (0: automatic)");
  const double h = sampling.spacing > 0 ? sampling.spacing : automaticSpacing(bounds);
  const std::array<double, 3> dims = dimensionsFor(bounds, h);
  const double nodes = dims[0] * dims[1] * dims[2];
  if (!(nodes <= ImageSampling::kMaxNodes)) {
    std::ostringstream msg;
    msg << source << ": a spacing of " << h << " gives " << dims[0] << " x " << dims[1] << " x "
        << dims[2] << " = " << nodes << " nodes, more than the limit " << ImageSampling::kMaxNodes
        << "; give a larger --spacing";
    throw std::invalid_argument(msg.str());
  }
  vtkNew<vtkResampleToImage> resample;
  resample->SetInputDataObject(data);
  resample->SetSamplingDimensions(int(dims[0]), int(dims[1]), int(dims[2]));
  // Exactly h on every axis (VTK's input bounds would stretch each axis to its own spacing).
  // At least 2 nodes per non-flat axis: an axis shorter than h gets its own extent as spacing.
  double sampled[6];
  for (int a = 0; a < 3; ++a) {
    const double extent = bounds.b[2 * a + 1] - bounds.b[2 * a];
    sampled[2 * a] = bounds.b[2 * a];
    sampled[2 * a + 1] = bounds.b[2 * a] + std::min(extent, (dims[a] - 1) * h);
  }
  resample->SetUseInputBounds(false);
  resample->SetSamplingBounds(sampled);
  resample->Update();
  vtkSmartPointer<vtkImageData> image = resample->GetOutput();
  // A flat axis (one node) gets spacing 0 from VTK; fluidviz's 2D grids have spacing 1 there.
  double spacing[3];
  image->GetSpacing(spacing);
  for (int a = 0; a < 3; ++a)
    if (dims[a] == 1) spacing[a] = 1.0;
  image->SetSpacing(spacing);
  return image;
}

}  // namespace fluidviz
