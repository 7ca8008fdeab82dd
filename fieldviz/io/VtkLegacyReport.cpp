#include "fieldviz/io/VtkLegacyReport.h"

#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkXMLWriter.h>

#include <exception>
#include <string>

#include "fieldviz/io/DataSetChecks.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlKinds.h"
#include "fieldviz/vtk/VtkMessageCollector.h"

namespace fluidviz {

namespace {

void readEveryArray(vtkDataSetReader* reader) {
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllFieldsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
}

// VTK's reader with every array, and fluidviz's checks of what it made.
vtkSmartPointer<vtkDataSet> readCheckedDataSet(const std::filesystem::path& path) {
  VtkMessageCollector messages;
  VtkUnobservedMessagesCapture capture(messages);
  vtkNew<vtkDataSetReader> reader;
  messages.watchAlgorithm(reader);
  reader->SetFileName(path.c_str());
  readEveryArray(reader);
  reader->Update();
  // Warnings too: VTK's legacy reader only warns ("Error reading ascii data. Possible mismatch
  // of datasize with declaration.") when the data stop short, and leaves the rest unset.
  if (messages.hasErrors() || !messages.warnings().empty() ||
      reader->GetErrorCode() != vtkErrorCode::NoError)
    throw FileError(path, "file " + path.string() + " is corrupt or truncated" +
                              (messages.summary().empty() ? "" : ": " + messages.summary()));
  vtkSmartPointer<vtkDataSet> data = reader->GetOutput();
  if (!data)
    throw FileError(path, "file " + path.string() +
                              " holds no dataset (a legacy VTK file of structured points, a "
                              "structured, rectilinear or unstructured grid, or poly data)");
  requireConsistentDataSet(data, path);
  return data;
}

}  // namespace

std::string legacyVtkReport(const std::filesystem::path& path) {
  try {
    vtkSmartPointer<vtkDataSet> data = readCheckedDataSet(path);
    // vtkXMLDataSetWriter would pick the writer, but does not pass WriteToOutputString on.
    const VtkXmlKind* kind = kindForVtkType(data->GetDataObjectType());
    if (!kind || !kind->makeWriter)
      return "ER\n\nfile " + path.string() + " holds a dataset type fluidviz cannot read";
    vtkSmartPointer<vtkXMLWriter> writer = kind->makeWriter();
    writer->SetInputData(data);
    writer->SetDataModeToBinary();
    writer->SetCompressorTypeToNone();
    writer->WriteToOutputStringOn();
    if (writer->Write() != 1) return "ER\n\nfile " + path.string() + " cannot be converted";
    return "OK " + std::to_string(data->GetDataObjectType()) + "\n" + writer->GetOutputString();
  } catch (const FileError& e) {
    return "ER\n" + e.arrayName() + "\n" + e.what();
  } catch (const std::exception& e) {
    return "ER\n\nfile " + path.string() + " cannot be read: " + e.what();
  }
}

}  // namespace fluidviz
