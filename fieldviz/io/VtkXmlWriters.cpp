#include "fieldviz/io/VtkXmlWriters.h"

#include <cmath>

#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/vtk/ImageDataAdapter.h"
#include "fieldviz/vtk/VtkMessageCollector.h"

namespace fluidviz {

namespace {

void configureForParaView(vtkXMLWriter* writer) {
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes: a third smaller and faster than base64
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();  // arrays over 4 GiB stay readable
}

std::string failureReason(vtkXMLWriter* writer, const VtkMessageCollector& messages) {
  std::string reason = messages.summary();
  const unsigned long code = writer->GetErrorCode();
  const std::string codeText = describeVtkErrorCode(code);
  if (!codeText.empty() && reason.find(codeText) == std::string::npos)
    reason += (reason.empty() ? "" : " ") + ("(" + codeText + ")");
  return reason.empty() ? "the VTK writer reported failure" : reason;
}

void writeWithVtk(vtkXMLWriter* writer, vtkDataObject* data, const std::filesystem::path& path) {
  configureForParaView(writer);
  writer->SetInputData(data);
  writeOutputAtomically(path, [&](const std::filesystem::path& tmp) {
    VtkMessageCollector messages;
    messages.watchAlgorithm(writer);
    writer->SetFileName(tmp.c_str());
    const bool ok = writer->Write() == 1;
    if (!ok || messages.hasErrors() || writer->GetErrorCode() != vtkErrorCode::NoError)
      throw FileError(path, "cannot write " + path.string() + ": " + failureReason(writer, messages));
  });
}

// FileInfo as field data; names already present (e.g. the reader's length_unit) are replaced.
void addFileInfo(vtkDataObject* data, const FileInfo& info) {
  vtkFieldData* fd = data->GetFieldData();
  for (const auto& [name, value] : info.strings) {
    vtkNew<vtkStringArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    fd->RemoveArray(name.c_str());
    fd->AddArray(a);
  }
  if (std::isfinite(info.time)) {
    vtkNew<vtkDoubleArray> t;
    t->SetName("TimeValue");
    t->InsertNextValue(info.time);
    fd->RemoveArray("TimeValue");
    fd->AddArray(t);
  }
}

}  // namespace

void writeVti(const FieldSet& fields, const std::filesystem::path& path) {
  vtkSmartPointer<vtkImageData> image = toImageData(fields);
  vtkNew<vtkXMLImageDataWriter> writer;
  writeWithVtk(writer, image, path);
}

vtkSmartPointer<vtkImageData> snapshotImage(const FieldSet& fields, const PointMask& masked,
                                            const FileInfo& info) {
  vtkSmartPointer<vtkImageData> image = toImageData(fields);
  addValidPointMask(image, masked);
  addFileInfo(image, info);
  return image;
}

void writeVti(const FieldSet& fields, const PointMask& masked, const std::filesystem::path& path,
              const FileInfo& info) {
  vtkNew<vtkXMLImageDataWriter> writer;
  writeWithVtk(writer, snapshotImage(fields, masked, info), path);
}

void writeVtp(vtkPolyData* polyData, const std::filesystem::path& path, const FileInfo& info) {
  if (!polyData) throw std::invalid_argument("writeVtp: no poly data given for " + path.string());
  addFileInfo(polyData, info);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writeWithVtk(writer, polyData, path);
}

}  // namespace fluidviz
