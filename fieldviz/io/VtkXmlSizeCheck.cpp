#include "fieldviz/io/VtkXmlSizeCheck.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <vtkType.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "fieldviz/core/ByteSize.h"
#include "fieldviz/io/FileError.h"

namespace fluidviz {

namespace {

// Bytes a compressed block may claim beyond the end of the file (see below).
constexpr double kTruncationSlack = 64.0 * 1024 * 1024;

struct FileFacts {
  std::filesystem::path path;
  double size = 0;                // bytes
  bool compressed = false;        // root attribute compressor="..."
  int headerWord = 4;             // header_type UInt32 (4) or UInt64 (8)
  bool bigEndian = false;         // byte_order="BigEndian"
  bool appendedBase64 = false;    // <AppendedData encoding="base64">
  std::int64_t appendedPosition = 0;
};

std::string attribute(vtkXMLDataElement* e, const char* name) {
  const char* v = e ? e->GetAttribute(name) : nullptr;
  return v ? v : "";
}

std::string arrayLabel(vtkXMLDataElement* array) {
  const std::string name = attribute(array, "Name");
  const char* parent = array->GetParent() ? array->GetParent()->GetName() : nullptr;
  return "array '" + name + "'" + (parent ? std::string(" in <") + parent + ">" : "");
}

std::string whole(double n) {
  std::ostringstream s;
  s << std::fixed;
  s.precision(0);
  s << n;
  return s.str();
}

// Counts are computed in double: extents of +-2^31 multiply past 64 bits, and attributes may say
// 1e300 (converting that to an integer would be undefined behaviour).
double numberAttribute(vtkXMLDataElement* e, const char* name) {
  double v = 0;
  if (!e || !e->GetScalarAttribute(name, v) || !(v > 0)) return 0;
  return v;
}

double extentCount(vtkXMLDataElement* e, const char* name, bool cells) {
  double ext[6];
  if (!e || e->GetVectorAttribute(name, 6, ext) != 6) return 0;
  double n = 1;
  for (int a = 0; a < 3; ++a) {
    const double nodes = ext[2 * a + 1] - ext[2 * a] + 1;
    if (!(nodes >= 1)) return 0;  // empty or inverted extent: VTK refuses it without allocating
    n *= cells ? std::max(nodes - 1, 1.0) : nodes;
  }
  return n;
}

// Points or cells of the piece `piece` (structured: its Extent and the dataset's WholeExtent,
// which is what VTK allocates; unstructured: NumberOfPoints / cell counts).
double pieceCount(vtkXMLDataElement* piece, bool cells) {
  if (!piece) return 0;
  double n = extentCount(piece, "Extent", cells);
  n = std::max(n, extentCount(piece->GetParent(), "WholeExtent", cells));
  if (!cells) return std::max(n, numberAttribute(piece, "NumberOfPoints"));
  double sum = numberAttribute(piece, "NumberOfCells");
  for (const char* kind : {"NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"})
    sum += numberAttribute(piece, kind);
  return std::max(n, sum);
}

// Tuples VTK allocates for `array` before reading it; 0 where the data decide (connectivity).
double tuplesOf(vtkXMLDataElement* array) {
  if (array->GetAttribute("NumberOfTuples")) return numberAttribute(array, "NumberOfTuples");
  vtkXMLDataElement* parent = array->GetParent();
  if (!parent || !parent->GetName()) return 0;
  const std::string section = parent->GetName();
  vtkXMLDataElement* piece = parent->GetParent();
  if (section == "PointData" || section == "Points") return pieceCount(piece, false);
  if (section == "CellData") return pieceCount(piece, true);
  if (attribute(array, "Name") == "offsets")  // <Verts>, <Lines>, <Strips>, <Polys>
    return numberAttribute(piece, ("NumberOf" + section).c_str()) + 1;
  return 0;
}

double wordSize(const std::string& type) {
  if (type == "Bit") return 0.125;
  if (type == "Int8" || type == "UInt8" || type == "Char" || type == "String") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  return 8;
}

double capacityFor(const FileFacts& f, vtkXMLDataElement* array) {
  // ASCII: "0 " per 8-byte value.
  if (arrayEncodingOf(array) == ArrayEncoding::Ascii) return f.size * 8.0;
  return f.compressed ? f.size * kMaxCompressionRatio : f.size;
}

void refuse(const FileFacts& f, vtkXMLDataElement* array, const std::string& problem) {
  throw FileError(f.path, "file " + f.path.string() + " is corrupt: " + arrayLabel(array) + " " +
                              problem,
                  attribute(array, "Name"));
}

// An appended array's offset must be a plain byte count: VTK reads "offset=\":0\"" as no offset
// and then decompresses from wherever its stream stands (a fuzz finding: a 1.9 GB block).
void requirePlainOffset(const FileFacts& f, vtkXMLDataElement* array) {
  const char* offset = array->GetAttribute("offset");
  if (!offset) return;
  std::string text(offset);
  const auto first = text.find_first_not_of(" \t\r\n"), last = text.find_last_not_of(" \t\r\n");
  text = first == std::string::npos ? "" : text.substr(first, last - first + 1);
  if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
    refuse(f, array, "has offset=\"" + std::string(offset) +
                         "\"; allowed: a byte count (digits only) into <AppendedData>");
}

// The memory VTK allocates for the array must be data the file can actually hold.
void requireArrayFitsFile(const FileFacts& f, vtkXMLDataElement* array) {
  double components = 1;
  if (array->GetAttribute("NumberOfComponents"))
    components = numberAttribute(array, "NumberOfComponents");
  const double tuples = tuplesOf(array);
  const double values = tuples * components;
  const double bytes = values * wordSize(attribute(array, "type"));
  const double capacity = capacityFor(f, array);
  if (bytes > capacity) {
    std::ostringstream what;
    what << "would need " << formatBytes(bytes) << " (" << whole(tuples) << " tuples x "
         << whole(components)
         << " components), more than the file's " << formatBytes(f.size)
         << " can hold; refused before allocating";
    refuse(f, array, what.str());
  }
}

// Sequential reader of the bytes of a data header at a file position, raw or base64.
class HeaderStream {
 public:
  HeaderStream(const std::filesystem::path& path, std::int64_t position, bool base64)
      : in_(path, std::ios::binary), base64_(base64) {
    in_.seekg(position);
  }

  bool read(unsigned char* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
      if (!next(out[i])) return false;
    return true;
  }

 private:
  bool next(unsigned char& byte) {
    if (!base64_) {
      const int c = in_.get();
      if (c == EOF) return false;
      byte = static_cast<unsigned char>(c);
      return true;
    }
    if (pending_ == 0 && !decodeQuad()) return false;
    byte = decoded_[3 - pending_--];
    return true;
  }

  static int sextet(int c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  }

  // Four characters -> up to three bytes, exactly as vtkBase64Utilities::DecodeTriplet: '='
  // decodes as 0 anywhere; '=' third or fourth shortens the group to 1 or 2 bytes, and a short
  // group or an invalid character (whitespace too) ends VTK's read (it then reports the header
  // as truncated).
  bool decodeQuad() {
    if (ended_) return false;
    int s[4];
    int chars[4];
    for (int k = 0; k < 4; ++k) {
      chars[k] = in_.get();
      if (chars[k] == EOF) return false;
      s[k] = chars[k] == '=' ? 0 : sextet(chars[k]);
      if (s[k] < 0) return false;
    }
    decoded_[0] = static_cast<unsigned char>(s[0] << 2 | s[1] >> 4);
    decoded_[1] = static_cast<unsigned char>((s[1] & 15) << 4 | s[2] >> 2);
    decoded_[2] = static_cast<unsigned char>((s[2] & 3) << 6 | s[3]);
    const int bytes = chars[2] == '=' ? 1 : chars[3] == '=' ? 2 : 3;
    if (bytes < 3) {
      std::copy_backward(decoded_, decoded_ + bytes, decoded_ + 3);
      ended_ = true;
    }
    pending_ = bytes;
    return true;
  }

  std::ifstream in_;
  bool base64_;
  unsigned char decoded_[3] = {};
  int pending_ = 0;
  bool ended_ = false;
};

bool readWord(HeaderStream& s, const FileFacts& f, double& value) {
  unsigned char b[8];
  if (!s.read(b, f.headerWord)) return false;
  std::uint64_t v = 0;
  for (int i = 0; i < f.headerWord; ++i) {
    const int k = f.bigEndian ? i : f.headerWord - 1 - i;
    v = v << 8 | b[k];
  }
  value = static_cast<double>(v);
  return true;
}

// Where VTK starts reading the array's binary data (VTK's SeekInlineDataPosition for inline).
bool dataPosition(const FileFacts& f, vtkXMLDataElement* array, std::int64_t& position,
                  bool& base64) {
  const ArrayEncoding encoding = arrayEncodingOf(array);
  if (encoding == ArrayEncoding::Appended) {
    double offset = 0;
    if (!array->GetScalarAttribute("offset", offset) || !(offset >= 0 && offset < f.size))
      return false;  // VTK finds nothing there and says so
    position = f.appendedPosition + static_cast<std::int64_t>(offset);
    base64 = f.appendedBase64;
    return true;
  }
  if (encoding == ArrayEncoding::Ascii) return false;
  std::ifstream in(f.path, std::ios::binary);
  in.seekg(array->GetXMLByteIndex());
  int c;
  while ((c = in.get()) != EOF && c != '>') {
  }
  while ((c = in.get()) != EOF && std::isspace(c)) {  // as VTK's SeekInlineDataPosition
  }
  if (c == EOF) return false;
  position = static_cast<std::int64_t>(in.tellg()) - 1;
  base64 = true;
  return true;
}

// A compressed array starts with [blocks, block size, last block size, compressed sizes...];
// VTK allocates the size arrays and each block's buffers from it without checking.
void requireCompressionHeaderFitsFile(const FileFacts& f, vtkXMLDataElement* array) {
  std::int64_t position = 0;
  bool base64 = false;
  if (!dataPosition(f, array, position, base64) || position < 0 || position >= f.size) return;
  const double available = (f.size - position) * (base64 ? 0.75 : 1.0);
  HeaderStream s(f.path, position, base64);
  double blocks = 0, blockSize = 0, lastSize = 0;
  // A header cut short is reported by VTK itself as truncated, before it allocates anything.
  if (!readWord(s, f, blocks) || !readWord(s, f, blockSize) || !readWord(s, f, lastSize)) return;
  const double headerBytes = (3 + blocks) * f.headerWord;
  if (headerBytes > available)
    refuse(f, array, "has a compression header listing " + whole(blocks) +
                         " blocks, more than the file's remaining " + formatBytes(available) +
                         " can hold");
  // VTK derives the data size from these three words and reads blocks up to it, also past the
  // listed ones; a header where they disagree makes it read sizes it never allocated.
  if (blocks > 0 && blockSize == 0 && (blocks > 1 || lastSize == 0))
    refuse(f, array, "has a compression header with block size 0");
  if (lastSize > blockSize || (blocks == 0 && lastSize > 0))
    refuse(f, array, "has an inconsistent compression header (" + whole(blocks) +
                         " blocks of " + formatBytes(blockSize) + ", the last of " +
                         formatBytes(lastSize) + ")");
  // VTK allocates each block's compressed bytes, then its uncompressed size, before it reads.
  // A file cut short (sound sizes, missing bytes) is left to VTK, which reports it truncated:
  // a block may claim up to kTruncationSlack more than the file still holds.
  const double remaining = std::max(available - headerBytes, 0.0);
  for (double i = 0; i < blocks; ++i) {
    double compressed = 0;
    if (!readWord(s, f, compressed)) return;
    if (compressed > std::max(remaining, kTruncationSlack))
      refuse(f, array, "has a compressed block of " + formatBytes(compressed) +
                           ", more than the file's remaining " + formatBytes(remaining) +
                           "; refused before allocating");
    const bool partialLast = lastSize > 0 && i == blocks - 1;
    const double uncompressed = partialLast ? lastSize : blockSize;
    if (uncompressed > std::min(compressed, remaining) * kMaxCompressionRatio + 1024)
      refuse(f, array, "has a compressed block that would expand " + formatBytes(compressed) +
                           " into " + formatBytes(uncompressed) +
                           ", more than any compressor does; refused before allocating");
  }
}

// Uncompressed raw appended data starts with one word, its byte count. VTK 9.1 reads a block cut
// short by the end of the file without complaint (the rest of the array keeps whatever memory
// held), so a file truncated inside its last arrays is refused here.
void requireRawDataFitsFile(const FileFacts& f, vtkXMLDataElement* array) {
  std::int64_t position = 0;
  bool base64 = false;
  if (arrayEncodingOf(array) != ArrayEncoding::Appended ||
      !dataPosition(f, array, position, base64) ||
      base64 || position < 0 || position >= f.size)
    return;
  HeaderStream s(f.path, position, false);
  double bytes = 0;
  if (!readWord(s, f, bytes)) return;  // VTK reports a header cut short itself
  const double end = double(position) + f.headerWord + bytes;
  if (end > f.size)
    refuse(f, array, "announces " + formatBytes(bytes) + " of data from byte " +
                         whole(double(position) + f.headerWord) + " on, but the file ends at byte " +
                         whole(f.size) + "; the file is truncated");
}

vtkXMLDataElement* childArrayNamed(vtkXMLDataElement* e, const char* name) {
  for (int i = 0; i < e->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* c = e->GetNestedElement(i);
    if (attribute(c, "Name") == name) return c;
  }
  return nullptr;
}

template <class T>
double wordAs(const unsigned char* bytes) {
  T v;
  std::memcpy(&v, bytes, sizeof v);  // the buffer has no alignment for T
  return static_cast<double>(v);
}

// The last cell offset, read through VTK's own parser (any encoding or compressor; the
// compression header was checked before); false if it cannot be read (VTK then reports it).
bool lastOffset(vtkXMLDataParser* parser, const FileFacts& f, vtkXMLDataElement* offsets,
                double cells, double& value) {
  int type = 0;
  if (!offsets->GetWordTypeAttribute("type", type)) return false;
  if (!(cells <= 9e18)) return false;  // VTK's vtkIdType cannot count that many anyway
  const auto last = static_cast<vtkTypeUInt64>(cells - 1);
  unsigned char word[16] = {};
  std::size_t read = 0;
  const ArrayEncoding encoding = arrayEncodingOf(offsets);
  if (encoding == ArrayEncoding::Appended) {
    double offset = 0;
    if (!offsets->GetScalarAttribute("offset", offset) || !(offset >= 0 && offset < f.size))
      return false;
    read = parser->ReadAppendedData(static_cast<vtkTypeInt64>(offset), word, last, 1, type);
  } else {
    read = parser->ReadInlineData(offsets, encoding == ArrayEncoding::Ascii, word, last, 1, type);
  }
  if (read != 1) return false;
  switch (type) {
    case VTK_TYPE_INT8: value = wordAs<vtkTypeInt8>(word); break;
    case VTK_TYPE_UINT8: value = wordAs<vtkTypeUInt8>(word); break;
    case VTK_TYPE_INT16: value = wordAs<vtkTypeInt16>(word); break;
    case VTK_TYPE_UINT16: value = wordAs<vtkTypeUInt16>(word); break;
    case VTK_TYPE_INT32: value = wordAs<vtkTypeInt32>(word); break;
    case VTK_TYPE_UINT32: value = wordAs<vtkTypeUInt32>(word); break;
    case VTK_TYPE_INT64: value = wordAs<vtkTypeInt64>(word); break;
    case VTK_TYPE_UINT64: value = wordAs<vtkTypeUInt64>(word); break;
    default: return false;  // VTK refuses non-integer offsets itself
  }
  return true;
}

// VTK sizes a cell block's connectivity by its last offset, a value in the data.
void requireConnectivityFitsFile(vtkXMLDataParser* parser, const FileFacts& f,
                                 vtkXMLDataElement* cellBlock) {
  vtkXMLDataElement* piece = cellBlock->GetParent();
  const std::string kind = cellBlock->GetName();
  const double cells = numberAttribute(piece, ("NumberOf" + kind).c_str());
  vtkXMLDataElement* offsets = childArrayNamed(cellBlock, "offsets");
  vtkXMLDataElement* connectivity = childArrayNamed(cellBlock, "connectivity");
  double length = 0;
  if (cells < 1 || !offsets || !connectivity || !lastOffset(parser, f, offsets, cells, length))
    return;
  const double bytes = length * wordSize(attribute(connectivity, "type"));
  const double capacity = capacityFor(f, connectivity);
  if (bytes > capacity)
    refuse(f, connectivity,
           "would need " + formatBytes(bytes) + " (" + whole(length) +
               " point ids, the last of the offsets), more than the file's " + formatBytes(f.size) +
               " can hold; refused before allocating");
}

// An unstructured grid's cell types, read through VTK's parser in chunks before VTK's reader
// does: VTK 9.1 leaks the types array when it cannot read all of them (a corrupt zlib block,
// fuzz_vtk_xml_grids), so a types array that stops short is refused here.
void requireCellTypesReadable(vtkXMLDataParser* parser, const FileFacts& f,
                              vtkXMLDataElement* cells) {
  vtkXMLDataElement* piece = cells->GetParent();
  vtkXMLDataElement* types = childArrayNamed(cells, "types");
  const double count = numberAttribute(piece, "NumberOfCells");
  int type = 0;
  if (!types || !(count >= 1 && count <= 9e18) || !types->GetWordTypeAttribute("type", type))
    return;
  constexpr vtkTypeUInt64 kChunk = 65536;
  std::vector<unsigned char> buffer(kChunk * 8);
  const ArrayEncoding encoding = arrayEncodingOf(types);
  double offset = 0;
  if (encoding == ArrayEncoding::Appended &&
      (!types->GetScalarAttribute("offset", offset) || !(offset >= 0 && offset < f.size)))
    return;  // VTK finds nothing there and says so before it allocates
  const auto total = static_cast<vtkTypeUInt64>(count);
  for (vtkTypeUInt64 start = 0; start < total; start += kChunk) {
    const vtkTypeUInt64 n = std::min(kChunk, total - start);
    const std::size_t read =
        encoding == ArrayEncoding::Appended
            ? parser->ReadAppendedData(static_cast<vtkTypeInt64>(offset), buffer.data(), start,
                                       n, type)
            : parser->ReadInlineData(types, encoding == ArrayEncoding::Ascii, buffer.data(),
                                     start, n, type);
    if (read != n)
      refuse(f, types, "holds fewer than the " + whole(count) +
                           " cell types that NumberOfCells declares (its data are truncated or "
                           "corrupt)");
  }
}

vtkXMLDataElement* findElement(vtkXMLDataElement* e, const char* name) {
  if (!e) return nullptr;
  if (e->GetName() && std::strcmp(e->GetName(), name) == 0) return e;
  for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
    if (vtkXMLDataElement* found = findElement(e->GetNestedElement(i), name)) return found;
  return nullptr;
}

// What the sizes of a file's arrays are judged against; false if the file cannot be sized.
bool factsOf(vtkXMLDataParser* parser, const std::filesystem::path& path, FileFacts& f) {
  vtkXMLDataElement* root = parser->GetRootElement();
  std::error_code ec;
  f.path = path;
  f.size = static_cast<double>(std::filesystem::file_size(path, ec));
  if (ec) return false;
  f.compressed = !attribute(root, "compressor").empty();
  f.headerWord = attribute(root, "header_type") == "UInt64" ? 8 : 4;
  f.bigEndian = attribute(root, "byte_order") == "BigEndian";
  f.appendedBase64 = attribute(findElement(root, "AppendedData"), "encoding") != "raw";
  f.appendedPosition = parser->GetAppendedDataPosition();
  return true;
}

}  // namespace

namespace {

void requirePlausibleHeadersIn(vtkXMLDataElement* e, const FileFacts& f) {
  forEachArrayElement(e, [&](vtkXMLDataElement* array) {
    requirePlainOffset(f, array);
    requireArrayFitsFile(f, array);
    if (f.compressed) requireCompressionHeaderFitsFile(f, array);
  });
}

}  // namespace

void requirePlausibleFieldDataHeaders(vtkXMLDataParser* parser,
                                      const std::filesystem::path& path) {
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  FileFacts f;
  if (!root || !factsOf(parser, path, f)) return;
  forEachElement(root, "FieldData",
                 [&](vtkXMLDataElement* fieldData) { requirePlausibleHeadersIn(fieldData, f); });
}

void requirePlausibleSizes(vtkXMLDataParser* parser, const std::filesystem::path& path) {
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  if (!root) return;
  FileFacts f;
  if (!factsOf(parser, path, f)) return;
  requirePlausibleHeadersIn(root, f);
  // After the headers are known sound: reading an offset runs VTK's decompression. The reader
  // opens its stream only for Update(), so the parser reads from ours meanwhile.
  ParserStreamLoan loan(parser, path);
  for (const char* kind : {"Verts", "Lines", "Strips", "Polys", "Cells"})
    forEachElement(root, kind, [&](vtkXMLDataElement* cellBlock) {
      requireConnectivityFitsFile(parser, f, cellBlock);
    });
  forEachElement(root, "Cells", [&](vtkXMLDataElement* cells) {
    requireCellTypesReadable(parser, f, cells);
  });
  // Last: the checks above name the array whose size is wrong, this one only a file cut short.
  if (!f.compressed) forEachArrayElement(root, [&](vtkXMLDataElement* array) {
      requireRawDataFitsFile(f, array);
    });
}

ParserStreamLoan::ParserStreamLoan(vtkXMLDataParser* parser, const std::filesystem::path& path)
    : parser_(parser), stream_(path, std::ios::binary) {
  parser_->SetStream(&stream_);
}

ParserStreamLoan::~ParserStreamLoan() { parser_->SetStream(nullptr); }

ArrayEncoding arrayEncodingOf(vtkXMLDataElement* array) {
  if (array->GetAttribute("offset")) return ArrayEncoding::Appended;
  return attribute(array, "format") == "binary" ? ArrayEncoding::InlineBinary
                                                : ArrayEncoding::Ascii;
}

std::optional<double> compressedArrayBytes(vtkXMLDataParser* parser,
                                           const std::filesystem::path& path,
                                           vtkXMLDataElement* array) {
  FileFacts f;
  if (!parser || !parser->GetRootElement() || !factsOf(parser, path, f) || !f.compressed)
    return std::nullopt;
  std::int64_t position = 0;
  bool base64 = false;
  if (!dataPosition(f, array, position, base64) || position < 0 || position >= f.size)
    return std::nullopt;
  HeaderStream s(f.path, position, base64);
  double blocks = 0, blockSize = 0, lastSize = 0;
  if (!readWord(s, f, blocks) || !readWord(s, f, blockSize) || !readWord(s, f, lastSize))
    return std::nullopt;
  // Zlib/LZ4/LZMA header: `blocks` blocks of blockSize bytes, the last one lastSize if > 0.
  return blocks * blockSize - (lastSize > 0 ? blockSize - lastSize : 0.0);
}

}  // namespace fluidviz
