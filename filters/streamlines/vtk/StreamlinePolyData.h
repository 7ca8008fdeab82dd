#pragma once
// Streamlines <-> vtkPolyData, the layout every fluidviz .vtp of streamlines has:
//   one polyline cell per line that has at least one point, in line order (a line stopped at its
//   seed - stagnation, a zero field - is a zero-length cell of its seed twice, because VTK rejects
//   polylines of one point; a seed outside the grid or on a NaN gives no points and no cell, its
//   index is skipped in `seed_id`);
//   point arrays  speed             |v| at the point (field units, e.g. m/s)
//                 integration_time  s, 0 at the seed, negative on the backward branch
//   cell arrays   reason            int, TerminationReason of the line's downstream end (forward
//                                   branch; the backward branch's when only that was traced)
//                 reason_backward   int, TerminationReason of the upstream end when both
//                                   directions were traced (0 = not_traced otherwise)
//                 seed_id           index of the seed the line started from
//   field data    reason_names      strings: reason_names[code] is the name of reason code
//                                   `code` ("not_traced", "domain_exit", "stagnation", ...)
#include <string>
#include <vector>

#include <vtkPolyData.h>  // complete type: the returned smart pointer converts to vtkPolyData*
#include <vtkSmartPointer.h>

#include "fieldviz/core/Field.h"
#include "filters/streamlines/Streamline.h"

class vtkDataSet;

namespace fluidviz::streamlines {

/// The lines as poly data (layout above).
vtkSmartPointer<vtkPolyData> streamlinesToPolyData(const std::vector<Streamline>& lines);

/// Points of every cell of `polyData` (polylines in cell order), for drawing.
std::vector<std::vector<Vec3>> polylinePoints(vtkPolyData* polyData);

/// The points of any data set as seeds (vtkStreamTracer's seed source convention).
std::vector<Vec3> seedsFromDataSet(vtkDataSet* seeds);

/// Number of lines per termination reason, as "closed_loop 12, domain_exit 3".
std::string summarizeReasons(const std::vector<Streamline>& lines);

}  // namespace fluidviz::streamlines
