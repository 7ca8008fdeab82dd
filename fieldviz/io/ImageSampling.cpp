#include "fieldviz/io/ImageSampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkIdList.h>
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

// The image the resampling fills: first node, spacing and node count per axis.
struct Lattice {
  std::array<double, 3> origin{};
  double h = 1.0;
  std::array<double, 3> dims{};
};

// Nodes of axis a of the lattice in [lo, hi]. A flat axis has its one node in every cell.
double nodesBetween(const Lattice& lattice, int a, double lo, double hi) {
  if (lattice.dims[a] == 1) return 1;
  const double first = std::max(0.0, std::ceil((lo - lattice.origin[a]) / lattice.h));
  const double last =
      std::min(lattice.dims[a] - 1, std::floor((hi - lattice.origin[a]) / lattice.h));
  return std::max(0.0, last - first + 1);
}

// What vtkProbeFilter does for an image (ProbePointsImageData): for each cell, every node in the
// cell's bounding box is located in the cell, at a cost proportional to the cell's points. The
// sum of nodes-in-box x points over the cells, per node of the image, is 8 for the hexahedra of
// VTK's office and kitchen flows and 148 for tetrahedra whose corners sit on the image's nodes
// (the worst case: every corner node counts in each of its cells); cells that overlap (a
// corrupt connectivity, a file that is not a mesh) can make it millions: a hang
// (fuzz_vtk_xml_grids).
double probeWork(vtkDataSet* set, const Lattice& lattice) {
  double work = 0;
  double b[6];
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < set->GetNumberOfCells(); ++c) {
    set->GetCellBounds(c, b);
    double nodes = 1;
    for (int a = 0; a < 3 && nodes > 0; ++a)
      nodes *= nodesBetween(lattice, a, b[2 * a], b[2 * a + 1]);
    if (nodes == 0) continue;
    set->GetCellPoints(c, ids);
    work += nodes * static_cast<double>(std::max<vtkIdType>(1, ids->GetNumberOfIds()));
  }
  return work;
}

double probeWorkOf(vtkDataObject* data, const Lattice& lattice) {
  if (auto* set = vtkDataSet::SafeDownCast(data)) return probeWork(set, lattice);
  double work = 0;
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(data)) {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      if (auto* set = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
        work += probeWork(set, lattice);
  }
  return work;
}

void requireBoundedProbeWork(vtkDataObject* data, const Lattice& lattice,
                             const std::string& source) {
  const double nodes = lattice.dims[0] * lattice.dims[1] * lattice.dims[2];
  const double perNode = probeWorkOf(data, lattice) / nodes;
  if (perNode <= ImageSampling::kMaxProbeWorkPerNode) return;
  std::ostringstream msg;
  msg << source << ": its cells overlap; resampling would test each node of the image against "
      << perNode << " cell points on average (cells that tile a domain need 8 to 150, at most "
      << ImageSampling::kMaxProbeWorkPerNode
      << " are allowed); the connectivity is damaged or the file is not a mesh";
  throw std::invalid_argument(msg.str());
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
  requireBoundedProbeWork(data, {{bounds.b[0], bounds.b[2], bounds.b[4]}, h, dims}, source);
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
