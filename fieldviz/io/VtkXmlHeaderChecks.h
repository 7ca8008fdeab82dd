#pragma once
// Checks of a VTK XML file's header (the element tree vtkXMLReader::UpdateInformation parsed) for
// what VTK's readers accept silently or answer with a crash or a huge allocation:
//   - Origin, Spacing or WholeExtent that are not numbers ("nan", "abc"): VTK keeps its default
//     (origin 0, spacing 1) and reads the data onto another grid;
//   - extents whose node count does not fit a grid, or pieces outside the whole extent;
//   - a header that declares more points than this machine has memory for (WholeExtent
//     "0 100000 0 100000 0 100000"): refused before VTK allocates, with the memory it would need;
//   - arrays holding more values than the header's extent, point count, NumberOfComponents and
//     type give: VTK reads what it needs and ignores the rest, giving a scrambled field.
// Every problem throws FileError naming the file and, where it applies, the array.
#include <filesystem>

class vtkXMLDataElement;
class vtkXMLDataParser;

namespace fluidviz {

/// After VTK's information pass, first: every element inside PointData, CellData, FieldData,
/// Points, Coordinates and the cell blocks is a DataArray or an Array (VTK reads any element
/// there as an array, so a misspelt <DataArraY> escaped every array check; found by fuzzing).
void checkSectionElements(vtkXMLDataParser* parser, const std::filesystem::path& path);

/// After VTK's information pass: the array of every <Points> element has 3 components (x, y, z),
/// as vtkPoints needs. VTK's reader does not refuse another count (a misspelt NumberOfComponents
/// reads as 1): vtkPoints::SetData rejects the array and the reader leaks it and the vtkPoints on
/// that error path (a vtkFloatArray, its iterator and a vtkPoints per file; found by fuzzing,
/// tests/fuzz/regressions/vtp_reader/leak-vtp-reader-1.vtp). Refused here, before VTK reads data.
void checkPointCoordinates(vtkXMLDataParser* parser, const std::filesystem::path& path);

/// After VTK's information pass, before its errors are looked at: every DataArray has a type VTK
/// knows (VTK's own message names the type but not the array).
void checkArrayTypes(vtkXMLDataParser* parser, const std::filesystem::path& path);

/// Before reading the data: attributes, extents, pieces and the memory reading would take.
/// `dataType` is the <VTKFile type>: "ImageData", "RectilinearGrid", "StructuredGrid" (extents),
/// "PolyData" or "UnstructuredGrid" (point and cell counts); other types are not checked here.
void checkVtkXmlHeader(vtkXMLDataParser* parser, const char* dataType,
                       const std::filesystem::path& path);

/// A .pvti/.pvtu summary and one of its pieces (element trees): every array the summary declares
/// (<PPointData>, <PCellData>, <PPoints>) is in the piece with the same type and component count.
/// VTK's summary readers allocate by the summary's declaration and copy the piece's bytes into
/// it: Float64 points declared for Float32 ones read as coordinates like 1e-106 (seen with a
/// hand-written summary). Throws FileError naming the summary, the piece (`source`) and the array.
void checkSummaryMatchesPiece(vtkXMLDataElement* summaryRoot, vtkXMLDataElement* pieceRoot,
                              const std::filesystem::path& summary, const std::string& source);

/// After reading: no array holds values beyond those its header declares.
void checkNoValuesBeyondDeclared(vtkXMLDataParser* parser, const char* dataType,
                                 const std::filesystem::path& path);

}  // namespace fluidviz
