#pragma once
// Unlit single-colour actors the pictures draw on top of their fields: overlay lines and glyphs,
// and the outline of a 3D domain. Unlit so that the colour on screen is the colour asked for.
#include <vtkActor.h>
#include <vtkSmartPointer.h>

#include <array>

#include "fieldviz/render/OffscreenRenderer.h"

class vtkPolyData;

namespace fluidviz {

/// `data` (lines or polygons) in one colour, its scalars ignored.
vtkSmartPointer<vtkActor> flatActor(vtkPolyData* data, const Rgb& colour);

/// The 12 edges of the box `bounds` (xmin, xmax, ymin, ymax, zmin, zmax), 1.5 px wide.
vtkSmartPointer<vtkActor> outlineActor(const std::array<double, 6>& bounds, const Rgb& colour);

}  // namespace fluidviz
