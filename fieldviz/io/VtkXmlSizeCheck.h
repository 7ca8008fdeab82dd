#pragma once
// Refuses VTK XML files whose sizes cannot be true before VTK allocates memory for them.
// VTK's XML readers allocate what the file's header says: every array gets (points or cells of
// the Extent / NumberOfPoints ...) x NumberOfComponents values, and compressed data is read in
// blocks whose sizes come from a per-array header. A corrupt or hostile file (one wrong digit in
// an extent or an offset) can ask for terabytes: VTK then throws std::bad_alloc or is killed.
// Found by fuzzing (tests/fuzz, fuzz_vti_reader / fuzz_vtp_reader; issue 8).
//
// The check compares what the header asks for with what the file can hold: uncompressed data
// needs its bytes in the file (ASCII needs >= 2 characters per value: "0 "); compressed data
// expands at most kMaxCompressionRatio times (zlib's deflate limit is 1032:1, LZ4's 255:1; LZMA
// reaches ~7000:1 on long zero runs). Files that pass are read by VTK as before.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include <vtkXMLDataElement.h>

class vtkXMLDataParser;

namespace fluidviz {

/// Calls visit(element) for e and every element nested in it (depth first) named `name`.
template <class F>
void forEachElement(vtkXMLDataElement* e, const char* name, F&& visit) {
  if (!e) return;
  if (e->GetName() && std::strcmp(e->GetName(), name) == 0) visit(e);
  for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
    forEachElement(e->GetNestedElement(i), name, visit);
}

/// Calls visit(element) for every array element nested in e: "DataArray" (numbers) and "Array"
/// (strings); VTK allocates both from their headers.
template <class F>
void forEachArrayElement(vtkXMLDataElement* e, F&& visit) {
  forEachElement(e, "DataArray", visit);
  forEachElement(e, "Array", visit);
}

inline constexpr double kMaxCompressionRatio = 16384.0;

/// requirePlausibleSizes' header checks (sizes against the file, offsets, compression headers
/// read from the file's bytes) of the <FieldData> arrays alone, on a bare parse of the file:
/// VTK's information pass already reads field-data values (a damaged compression header there
/// asked for 8 GB; fuzz_vtk_xml_grids), the other arrays wait for the header checks.
void requirePlausibleFieldDataHeaders(vtkXMLDataParser* parser,
                                      const std::filesystem::path& path);

/// `parser` is the reader's parser after UpdateInformation() (the XML structure is read, no data
/// yet). Throws FileError naming the file, the array and the memory it would need.
void requirePlausibleSizes(vtkXMLDataParser* parser, const std::filesystem::path& path);

/// Lends a parser its own stream of the file for the checks' reads (the reader opens one only for
/// Update()), and takes it back when it goes out of scope. `ok()` is false if the file cannot be
/// opened.
class ParserStreamLoan {
 public:
  ParserStreamLoan(vtkXMLDataParser* parser, const std::filesystem::path& path);
  ~ParserStreamLoan();
  ParserStreamLoan(const ParserStreamLoan&) = delete;
  ParserStreamLoan& operator=(const ParserStreamLoan&) = delete;
  bool ok() const { return static_cast<bool>(stream_); }

 private:
  vtkXMLDataParser* parser_;
  std::ifstream stream_;
};

/// How VTK reads an array (vtkXMLDataReader::ReadArrayValues): an `offset` attribute means
/// appended data whatever `format` says; otherwise format="binary" is inline base64, and anything
/// else (also no format) is ASCII. Every check that asks VTK for an array's values must read it
/// the same way: read as inline binary, an ASCII array's text became a compression header that
/// asked for 5 GB (fuzz_vtk_xml_grids).
enum class ArrayEncoding { Appended, InlineBinary, Ascii };
ArrayEncoding arrayEncodingOf(vtkXMLDataElement* array);

/// Uncompressed bytes a compressed array's header announces (blocks x block size, the last block
/// partial); nullopt if the file is not compressed or the header cannot be read. Lets a check see
/// whether data goes on past the declared values without asking VTK for a word at the very end:
/// VTK 9.1 then reads the size of a block past its list (garbage, sometimes a huge allocation).
std::optional<double> compressedArrayBytes(vtkXMLDataParser* parser,
                                           const std::filesystem::path& path,
                                           vtkXMLDataElement* array);

}  // namespace fluidviz
