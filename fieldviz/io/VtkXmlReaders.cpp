#include "fieldviz/io/VtkXmlReaders.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

#include <vtkAppendDataSets.h>
#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataCompressor.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRectilinearGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLReader.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLFileReadTester.h>

#include "fieldviz/io/DataSetChecks.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/ImageSampling.h"
#include "fieldviz/io/InputFile.h"
#include "fieldviz/io/VtkLegacyReader.h"
#include "fieldviz/io/VtkXmlHeaderChecks.h"
#include "fieldviz/io/VtkXmlKinds.h"
#include "fieldviz/io/VtkXmlSizeCheck.h"
#include "fieldviz/vtk/VtkMessageCollector.h"

namespace fluidviz {

namespace {

std::string label(const std::filesystem::path& path) { return "file " + path.string(); }

// VTK's readers only say "cannot read"; this tells the user what the file is instead.
void requireVtkXmlOfType(const std::filesystem::path& path, const std::string& dataType,
                         const char* extension) {
  vtkNew<vtkXMLFileReadTester> tester;
  tester->SetFileName(path.c_str());
  if (!tester->TestReadFile())
    throw FileError(path, label(path) + " is not a VTK XML file (expected " + dataType + " (" +
                              extension + "), starting with <VTKFile type=\"" + dataType +
                              "\">)");
  const char* found = tester->GetFileDataType();
  if (!found || dataType != found)
    throw FileError(path, label(path) + " holds VTK XML " + (found ? found : "of unknown type") +
                              ", expected " + dataType + " (" + extension + ")");
}

[[noreturn]] void throwCorrupt(const std::filesystem::path& path, const std::string& reason) {
  throw FileError(path, label(path) + " is corrupt or truncated" +
                            (reason.empty() ? std::string() : ": " + reason));
}

// The element tree of a VTK XML file (VTK's parser; it stops at <AppendedData>).
vtkSmartPointer<vtkXMLDataParser> parsedXml(const std::filesystem::path& path) {
  VtkMessageCollector messages;
  VtkUnobservedMessagesCapture capture(messages);
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  messages.watch(parser);
  parser->SetFileName(path.c_str());
  if (!parser->Parse() || messages.hasErrors() || !parser->GetRootElement())
    throwCorrupt(path, messages.summary());
  return parser;
}

// Points `reader` at the file with its complaints (and its parser's) going to `messages`.
void watchReader(VtkMessageCollector& messages, vtkXMLReader* reader,
                 const std::filesystem::path& path) {
  messages.watchAlgorithm(reader);
  reader->SetReaderErrorObserver(messages.command());
  reader->SetParserErrorObserver(messages.command());
  reader->SetFileName(path.c_str());
}

// Runs VTK's XML reader of `kind` with its errors collected, and throws if it reported any. The
// header is checked first (VtkXmlHeaderChecks.h, VtkXmlSizeCheck.h): values VTK would silently
// default, and sizes that must be refused before VTK allocates them. The checks read through the
// parser of a second reader of the file, `probe`: they lend its parser streams and move its
// position, so the parser that reads the data starts from VTK's own state.
vtkSmartPointer<vtkDataObject> readOrThrow(const VtkXmlKind& kind,
                                           const std::filesystem::path& path) {
  const char* dataType = kind.fileType;
  VtkMessageCollector messages;
  // Parsing creates XML elements that complain where no observer reaches.
  VtkUnobservedMessagesCapture capture(messages);
  // Our element checks first, on VTK's parse alone: VTK's information pass dereferences what some
  // elements lack (a <DataArray> in <FieldData> without a type: SEGV, fuzz_vtk_xml_grids), and
  // where VTK fails on one of these, ours says which array or attribute.
  vtkSmartPointer<vtkXMLDataParser> elements = parsedXml(path);
  checkSectionElements(elements, path);
  checkArrayTypes(elements, path);
  checkPointCoordinates(elements, path);
  requirePlausibleFieldDataHeaders(elements, path);
  vtkSmartPointer<vtkXMLReader> probe = kind.makeReader();
  watchReader(messages, probe, path);
  probe->UpdateInformation();
  vtkXMLDataParser* parser = probe->GetXMLParser();
  if (parser) {
    // The decompressor exists only once the header has been read, and reports through itself.
    messages.watch(parser);
    messages.watch(parser->GetCompressor());
  }
  checkVtkXmlHeader(parser, dataType, path);
  if (messages.hasErrors() || probe->GetErrorCode() != vtkErrorCode::NoError)
    throwCorrupt(path, messages.summary());
  requirePlausibleSizes(parser, path);  // compression headers, offsets vs file size (fuzzing)
  vtkSmartPointer<vtkXMLReader> reader = kind.makeReader();
  watchReader(messages, reader, path);
  reader->UpdateInformation();
  if (vtkXMLDataParser* dataParser = reader->GetXMLParser()) {
    messages.watch(dataParser);
    messages.watch(dataParser->GetCompressor());
  }
  reader->Update();
  if (messages.hasErrors() || reader->GetErrorCode() != vtkErrorCode::NoError)
    throwCorrupt(path, messages.summary());
  checkNoValuesBeyondDeclared(parser, dataType, path);
  return reader->GetOutputDataObject(0);
}

// ---- Summary files (.pvti, .pvtu, .vtm) and their pieces ---------------------------------------

// The piece files a summary names, as written: <Piece Source> (.pvti, .pvtu), <DataSet file>
// (.vtm; a DataSet without a file is an empty block). Read from the summary's element tree only:
// VTK's summary readers open the pieces already in their information pass, before our checks.
std::vector<std::string> pieceSources(vtkXMLDataElement* root, const std::filesystem::path& summary,
                                      const VtkXmlKind& kind) {
  const bool multiBlock = *kind.pieceType == '\0';
  const char* element = multiBlock ? "DataSet" : "Piece";
  const char* attribute = multiBlock ? "file" : "Source";
  std::vector<std::string> sources;
  forEachElement(root, element, [&](vtkXMLDataElement* e) {
    if (const char* source = e->GetAttribute(attribute))
      sources.emplace_back(source);
    else if (!multiBlock)
      throw FileError(summary, label(summary) + ": a <Piece> has no Source attribute (the file "
                                                "of the piece, relative to this one)");
  });
  if (sources.empty())
    throw FileError(summary, label(summary) + " names no piece files (<" + element + " " +
                                 attribute + "=\"...\">)");
  return sources;
}

// Where VTK looks for a piece: relative to the summary's folder. A piece must stay inside that
// folder: an absolute path or one climbing out with ".." would let a downloaded summary read any
// file of the machine.
std::filesystem::path piecePath(const std::filesystem::path& summary, const std::string& source) {
  const std::filesystem::path relative = std::filesystem::path(source).lexically_normal();
  if (source.empty() || relative.is_absolute() || relative.has_root_name() ||
      (!relative.empty() && *relative.begin() == ".."))
    throw FileError(summary, label(summary) + " names piece '" + source +
                                 "', outside its folder; allowed: a path relative to the "
                                 "folder of " + summary.filename().string() + ", inside it");
  return summary.parent_path() / relative;
}

// The serial kind of a piece: the kind its summary requires (.pvti: ImageData), or for a .vtm
// block whatever serial file it is.
const VtkXmlKind& pieceKind(const std::filesystem::path& piece, const VtkXmlKind& summaryKind) {
  if (*summaryKind.pieceType != '\0') return *kindForFileType(summaryKind.pieceType);
  vtkNew<vtkXMLFileReadTester> tester;
  tester->SetFileName(piece.c_str());
  const char* type = tester->TestReadFile() ? tester->GetFileDataType() : nullptr;
  const VtkXmlKind* kind = type ? kindForFileType(type) : nullptr;
  if (!kind || kind->isSummary())
    throw FileError(piece, label(piece) + " holds " +
                               (type ? "VTK XML " + std::string(type) : "no VTK XML dataset") +
                               "; a block must be an image, rectilinear, structured or "
                               "unstructured grid, or poly data (.vti .vtr .vts .vtu .vtp)");
  return *kind;
}

vtkSmartPointer<vtkDataObject> readCheckedXml(const VtkXmlKind& kind,
                                              const std::filesystem::path& path);

// Every piece gets the checks of a file of its own, and is read once with them; a problem names
// the summary and the piece.
void checkPieces(const std::filesystem::path& summary, const VtkXmlKind& kind) {
  vtkSmartPointer<vtkXMLDataParser> parsed = parsedXml(summary);
  for (const std::string& source : pieceSources(parsed->GetRootElement(), summary, kind)) {
    const std::filesystem::path piece = piecePath(summary, source);
    try {
      requireReadableFile(piece);
      readCheckedXml(pieceKind(piece, kind), piece);
    } catch (const FileError& e) {
      throw FileError(summary, label(summary) + ", piece " + source + ": " + e.what(),
                      e.arrayName());
    }
    checkSummaryMatchesPiece(parsed->GetRootElement(), parsedXml(piece)->GetRootElement(),
                             summary, source);
  }
}

vtkSmartPointer<vtkDataObject> readCheckedXml(const VtkXmlKind& kind,
                                              const std::filesystem::path& path) {
  requireReadableFile(path);
  requireVtkXmlOfType(path, kind.fileType, kind.extension);
  if (kind.isSummary()) checkPieces(path, kind);
  return readOrThrow(kind, path);
}

template <class F>
auto withArrayErrorsAsFileErrors(const std::filesystem::path& path, F&& convert) {
  try {
    return convert();
  } catch (const DataArrayError& e) {
    throw FileError(path, e.what(), e.arrayName());
  } catch (const std::invalid_argument& e) {
    throw FileError(path, e.what());
  }
}

// ---- From a dataset to an image -----------------------------------------------------------------

// A .vtm's blocks as one unstructured grid (VTK's vtkAppendDataSets): every cell of every block,
// point and cell arrays only where all blocks have them (VTK's rule).
vtkSmartPointer<vtkDataSet> mergedBlocks(vtkCompositeDataSet* blocks,
                                         const std::filesystem::path& path) {
  vtkNew<vtkAppendDataSets> append;
  int inputs = 0;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(blocks->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
    auto* block = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (!block || block->GetNumberOfPoints() == 0) continue;
    requireConsistentDataSet(block, path);  // before vtkAppendDataSets reads its cells
    append->AddInputData(block);
    ++inputs;
  }
  if (inputs == 0) throw FileError(path, label(path) + " has no block with points");
  append->Update();
  return append->GetOutput();
}

// The cell arrays without a point array of the same name, as point data too: averaged over the
// cells around each node (VTK's vtkCellDataToPointData). `keepCellData`: the cell arrays stay
// (an image keeps them as they were); else they go, so the resampling sees one array per name.
vtkSmartPointer<vtkDataSet> withCellArraysAsPointData(vtkSmartPointer<vtkDataSet> data,
                                                      bool keepCellData) {
  vtkCellData* cells = data->GetCellData();
  vtkNew<vtkCellDataToPointData> toPoints;
  toPoints->ProcessAllArraysOff();
  int converted = 0;
  for (int i = 0; i < cells->GetNumberOfArrays(); ++i) {
    const char* name = cells->GetArrayName(i);
    if (!name || data->GetPointData()->HasArray(name)) continue;
    toPoints->AddCellDataArray(name);
    ++converted;
  }
  if (converted == 0 && keepCellData) return data;
  toPoints->SetInputData(data);
  toPoints->SetPassCellData(keepCellData);
  toPoints->Update();
  return vtkDataSet::SafeDownCast(toPoints->GetOutputDataObject(0));
}

// NaN or infinite coordinates would make the bounds, and with them the resampled grid, NaN.
void requireFiniteCoordinates(vtkDataSet* data, const std::filesystem::path& path) {
  auto check = [&](vtkDataArray* values, const std::string& what) {
    if (!values) return;
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
      for (int c = 0; c < values->GetNumberOfComponents(); ++c)
        if (!std::isfinite(values->GetComponent(i, c)))
          throw FileError(path, label(path) + ": " + what + " " + std::to_string(i) + " has " +
                                    std::to_string(values->GetComponent(i, c)) +
                                    " as a coordinate; allowed: finite numbers");
  };
  if (auto* points = vtkPointSet::SafeDownCast(data)) {
    if (points->GetPoints()) check(points->GetPoints()->GetData(), "point");
  } else if (auto* grid = vtkRectilinearGrid::SafeDownCast(data)) {
    check(grid->GetXCoordinates(), "x coordinate");
    check(grid->GetYCoordinates(), "y coordinate");
    check(grid->GetZCoordinates(), "z coordinate");
  }
}

// What every reader hands on: an image with point arrays (ImageSampling.h for the others).
vtkSmartPointer<vtkImageData> imageOf(vtkDataObject* data, const ImageSampling& sampling,
                                      const std::filesystem::path& path) {
  VtkMessageCollector messages;
  VtkUnobservedMessagesCapture capture(messages);  // VTK's filters print their warnings
  vtkSmartPointer<vtkDataSet> set = vtkDataSet::SafeDownCast(data);
  if (auto* blocks = vtkCompositeDataSet::SafeDownCast(data)) set = mergedBlocks(blocks, path);
  if (!set) throw FileError(path, label(path) + " holds no dataset");
  requireConsistentDataSet(set, path);
  requireFiniteCoordinates(set, path);
  if (vtkImageData::SafeDownCast(set))
    return vtkImageData::SafeDownCast(withCellArraysAsPointData(set, true));
  set = withCellArraysAsPointData(set, false);
  return withArrayErrorsAsFileErrors(path,
                                     [&] { return resampleToImage(set, sampling, label(path)); });
}

}  // namespace

vtkSmartPointer<vtkImageData> readImageData(const std::filesystem::path& path,
                                            const ImageSampling& sampling) {
  vtkSmartPointer<vtkImageData> image;
  const std::string extension = path.extension().string();
  if (extension == ".vtk") {
    image = imageOf(readLegacyVtk(path), sampling, path);
  } else {
    // Any other extension is read as .vti, as before there were other kinds.
    const VtkXmlKind* kind = kindForExtension(extension);
    image = imageOf(readCheckedXml(kind ? *kind : *kindForExtension(".vti"), path), sampling,
                    path);
  }
  withArrayErrorsAsFileErrors(path, [&] { return gridOf(image, label(path)); });
  return image;
}

FieldSet readVti(const std::filesystem::path& path, std::vector<SkippedArray>* skipped) {
  vtkSmartPointer<vtkImageData> image = readImageData(path);
  ImageDataFields result =
      withArrayErrorsAsFileErrors(path, [&] { return fromImageData(image, label(path)); });
  if (skipped) *skipped = std::move(result.skipped);
  return std::move(result.fields);
}

VectorField readVectorField(const std::filesystem::path& path, const std::string& arrayName) {
  vtkSmartPointer<vtkImageData> image = readImageData(path);
  return withArrayErrorsAsFileErrors(
      path, [&] { return vectorFieldFrom(image, arrayName, label(path)); });
}

ScalarField readScalarField(const std::filesystem::path& path, const std::string& arrayName) {
  vtkSmartPointer<vtkImageData> image = readImageData(path);
  return withArrayErrorsAsFileErrors(
      path, [&] { return scalarFieldFrom(image, arrayName, label(path)); });
}

vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& path) {
  requireReadableFile(path);
  requireVtkXmlOfType(path, "PolyData", ".vtp");
  return vtkPolyData::SafeDownCast(readOrThrow(*kindForExtension(".vtp"), path));
}

}  // namespace fluidviz
