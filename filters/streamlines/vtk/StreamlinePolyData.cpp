#include "filters/streamlines/vtk/StreamlinePolyData.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <map>

namespace fluidviz::streamlines {

namespace {

constexpr TerminationReason kAllReasons[] = {
    TerminationReason::not_traced,  TerminationReason::domain_exit, TerminationReason::stagnation,
    TerminationReason::max_length,  TerminationReason::max_steps,   TerminationReason::closed_loop,
    TerminationReason::nan_in_field, TerminationReason::too_close};

vtkSmartPointer<vtkIntArray> intArray(const char* name) {
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  return a;
}

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  return a;
}

// The legend of the integer reason codes, so that ParaView users can read them.
vtkSmartPointer<vtkStringArray> reasonNames() {
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("reason_names");
  for (TerminationReason r : kAllReasons) {
    names->InsertValue(static_cast<vtkIdType>(r), toString(r));
  }
  return names;
}

}  // namespace

vtkSmartPointer<vtkPolyData> streamlinesToPolyData(const std::vector<Streamline>& lines) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  auto speed = doubleArray("speed"), time = doubleArray("integration_time");
  auto reason = intArray("reason"), reasonBackward = intArray("reason_backward"),
       seedId = intArray("seed_id");
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const Streamline& line = lines[l];
    if (line.points.empty()) continue;
    // A seed alone is written twice: VTK's cell links reject polylines of one point.
    const std::size_t n = std::max<std::size_t>(line.points.size(), 2);
    cells->InsertNextCell(static_cast<vtkIdType>(n));
    for (std::size_t m = 0; m < n; ++m) {
      const std::size_t k = std::min(m, line.points.size() - 1);
      const Vec3& p = line.points[k];
      cells->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
      speed->InsertNextValue(line.speeds[k]);
      time->InsertNextValue(line.times[k]);
    }
    reason->InsertNextValue(static_cast<int>(line.reason()));
    reasonBackward->InsertNextValue(
        static_cast<int>(line.forward_end == TerminationReason::not_traced
                             ? TerminationReason::not_traced
                             : line.backward_end));
    seedId->InsertNextValue(static_cast<int>(l));
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetLines(cells);
  poly->GetPointData()->AddArray(speed);
  poly->GetPointData()->AddArray(time);
  poly->GetPointData()->SetActiveScalars("speed");
  poly->GetCellData()->AddArray(reason);
  poly->GetCellData()->AddArray(reasonBackward);
  poly->GetCellData()->AddArray(seedId);
  poly->GetFieldData()->AddArray(reasonNames());
  return poly;
}

std::vector<std::vector<Vec3>> polylinePoints(vtkPolyData* polyData) {
  std::vector<std::vector<Vec3>> lines;
  vtkCellArray* cells = polyData->GetLines();
  if (!cells) return lines;
  vtkNew<vtkIdList> ids;
  for (cells->InitTraversal(); cells->GetNextCell(ids);) {
    std::vector<Vec3> line;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      double p[3];
      polyData->GetPoint(ids->GetId(k), p);
      line.emplace_back(p[0], p[1], p[2]);
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<Vec3> seedsFromDataSet(vtkDataSet* seeds) {
  std::vector<Vec3> out;
  if (!seeds) return out;
  for (vtkIdType i = 0; i < seeds->GetNumberOfPoints(); ++i) {
    double p[3];
    seeds->GetPoint(i, p);
    out.emplace_back(p[0], p[1], p[2]);
  }
  return out;
}

std::string summarizeReasons(const std::vector<Streamline>& lines) {
  std::map<std::string, int> counts;
  for (const Streamline& line : lines) ++counts[toString(line.reason())];
  std::string text;
  for (const auto& [name, n] : counts)
    text += (text.empty() ? "" : ", ") + name + " " + std::to_string(n);
  return text.empty() ? "none" : text;
}

}  // namespace fluidviz::streamlines
