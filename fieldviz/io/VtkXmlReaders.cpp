#include "fieldviz/io/VtkXmlReaders.h"

#include <cerrno>
#include <cstring>
#include <fstream>

#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkDataCompressor.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLFileReadTester.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/ImageSampling.h"
#include "fieldviz/io/InputFile.h"
#include "fieldviz/io/VtkLegacyReader.h"
#include "fieldviz/io/VtkXmlHeaderChecks.h"
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

// Runs a VTK XML reader with its errors collected, and throws if it reported any. The header is
// checked between VTK's information pass and the data pass (VtkXmlHeaderChecks.h): values VTK
// would silently default, and sizes that must be refused before VTK allocates them.
template <class Reader>
void watchReader(VtkMessageCollector& messages, Reader* reader, const std::filesystem::path& path) {
  messages.watchAlgorithm(reader);
  reader->SetReaderErrorObserver(messages.command());
  reader->SetParserErrorObserver(messages.command());
  reader->SetFileName(path.c_str());
}

// Runs a VTK XML reader with its errors collected, and throws if it reported any. The header is
// checked first (VtkXmlHeaderChecks.h, VtkXmlSizeCheck.h): values VTK would silently default,
// and sizes that must be refused before VTK allocates them. The checks read through the parser
// of a second reader of the file, `probe`: they lend its parser streams and move its position,
// so the parser that reads the data starts from VTK's own state.
template <class Reader>
void readOrThrow(Reader* reader, const char* dataType, const std::filesystem::path& path) {
  VtkMessageCollector messages;
  // Parsing creates XML elements that complain where no observer reaches.
  VtkUnobservedMessagesCapture capture(messages);
  vtkNew<Reader> probe;
  watchReader(messages, probe.Get(), path);
  probe->UpdateInformation();
  vtkXMLDataParser* parser = probe->GetXMLParser();
  if (parser) {
    // The decompressor exists only once the header has been read, and reports through itself.
    messages.watch(parser);
    messages.watch(parser->GetCompressor());
  }
  // Our checks first: where VTK failed on one of these, ours says which array or attribute.
  checkSectionElements(parser, path);
  checkArrayTypes(parser, path);
  checkPointCoordinates(parser, path);
  checkVtkXmlHeader(parser, dataType, path);
  if (messages.hasErrors() || probe->GetErrorCode() != vtkErrorCode::NoError)
    throwCorrupt(path, messages.summary());
  requirePlausibleSizes(parser, path);  // compression headers, offsets vs file size (fuzzing)
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

// An image whose arrays are all cell data (legacy structured points often are) gets them as
// point data too, averaged over the cells around each node (VTK's vtkCellDataToPointData).
vtkSmartPointer<vtkImageData> pointDataOf(vtkSmartPointer<vtkImageData> image) {
  if (image->GetCellData()->GetNumberOfArrays() == 0 ||
      image->GetPointData()->GetNumberOfArrays() > 0)
    return image;
  vtkNew<vtkCellDataToPointData> toPoints;
  toPoints->SetInputData(image);
  toPoints->PassCellDataOn();
  toPoints->Update();
  return vtkImageData::SafeDownCast(toPoints->GetOutput());
}

}  // namespace

vtkSmartPointer<vtkImageData> readImageData(const std::filesystem::path& path,
                                            const ImageSampling& sampling) {
  vtkSmartPointer<vtkImageData> image;
  if (path.extension() == ".vtk") {
    vtkSmartPointer<vtkDataSet> data = readLegacyVtk(path);
    image = withArrayErrorsAsFileErrors(
        path, [&] { return pointDataOf(resampleToImage(data, sampling, label(path))); });
  } else {
    requireReadableFile(path);
    requireVtkXmlOfType(path, "ImageData", ".vti");
    vtkNew<vtkXMLImageDataReader> reader;
    readOrThrow(reader.Get(), "ImageData", path);
    image = reader->GetOutput();
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
  vtkNew<vtkXMLPolyDataReader> reader;
  readOrThrow(reader.Get(), "PolyData", path);
  return reader->GetOutput();
}

}  // namespace fluidviz
