// The inputs libFuzzer found to crash or exhaust memory in the .vti/.vtp readers (issue 8;
// tests/fuzz, kept in tests/fuzz/regressions/). Each must now be refused with FileError naming the
// file, the array and what is wrong, before VTK allocates what the damaged header asks for
// (fieldviz/io/VtkXmlSizeCheck.h). This suite runs in the Release build as well as under ASan.
#include <gtest/gtest.h>

#include <string>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlReaders.h"

namespace fluidviz {
namespace {

struct Finding {
  const char* file;    // under tests/fuzz/regressions/
  const char* array;   // the array FileError names
  const char* reason;  // words of the message saying what is wrong
};

std::string regression(const char* file) {
  return std::string(FLUIDVIZ_SOURCE_DIR) + "/tests/fuzz/regressions/" + file;
}

// The regression input `f.file` is refused by `read(path)` naming the file, the array, `reason`.
template <class Read>
void expectRefusedBy(const Finding& f, Read&& read) {
  const std::string path = regression(f.file);
  try {
    read(path);
    FAIL() << f.file << " was read without error";
  } catch (const FileError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(std::string("'") + f.array + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(f.reason), std::string::npos) << message;
    EXPECT_EQ(e.arrayName(), f.array);
  }
}

void expectRefused(const Finding& f, bool polyData) {
  expectRefusedBy(f, [&](const std::string& path) { polyData ? void(readVtp(path)) : void(readVti(path)); });
}

// A regression input (legacy .vtk or another grid kind) is refused by readImageData with a message naming the file and
// holding `reason`.
void expectLegacyRefused(const char* file, const std::string& reason) {
  const std::string path = regression(file);
  try {
    readImageData(path);
    FAIL() << path << " was read without error";
  } catch (const FileError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
  }
}

// Appended offset "0" -> "1": the compression header is read one byte late and says
// 0 blocks of 2^63 bytes; VTK 9.1 reads a block past the (empty) list and allocates that.
TEST(FuzzFindings, MisalignedCompressionHeaderIsRefused) {
  expectRefused({"vti_reader/appended_offset_off_by_one_misreads_compression_header.vti",
                 "velocity", "inconsistent compression header"},
                false);
}

// Appended offset="0" -> ":0" (LZ4, found by the first CI run): VTK parses no offset and
// decompresses from wherever its stream stands, asking for a 1.9 GB block.
TEST(FuzzFindings, OffsetThatIsNotAByteCountIsRefused) {
  expectRefused({"vti_reader/offset_not_a_number_decompresses_from_nowhere.vti", "velocity",
                 "has offset=\":0\"; allowed: a byte count"},
                false);
}

// <DataArray> -> <DataArraY> with NumberOfComponents 111111113 (found by the CI run of
// 2026-11-24, a 30 s timeout under ASan): VTK reads any element inside <PointData> as an
// array and allocated 12 x 111111113 floats; every array check looked only at <DataArray>.
TEST(FuzzFindings, MisspeltArrayElementIsRefused) {
  expectRefused({"vti_reader/misspelt_dataarray_element_escapes_the_checks.vti",
                 "veloc                ity", "element <DataArraY>"},
                false);
}

// NumberOfComponents="-3" (found by a CI fuzz run of 2026-11-24): VTK sized a std::vector with
// the negative count: std::length_error, an abort.
TEST(FuzzFindings, NegativeComponentCountIsRefused) {
  expectRefused({"vti_reader/negative_component_count_aborts_vtk.vti", "velocity",
                 "has NumberOfComponents=\"-3\"; allowed: a whole number >= 1"},
                false);
}

// "DataArray" pasted into an inline base64 header: a block of 96 compressed bytes claims to
// expand to 2e5 GiB, which VTK allocates before decompressing.
TEST(FuzzFindings, ImpossibleCompressionRatioIsRefused) {
  expectRefused({"vti_reader/inline_base64_header_garbled_block_size.vti", "velocity",
                 "has a compressed block that would expand"},
                false);
}

// No format attribute (so appended, by its offset) and a garbled header: 538976288 blocks, whose
// size list VTK allocates (2 GB) before reading it.
TEST(FuzzFindings, BlockCountBeyondTheFileIsRefused) {
  expectRefused({"vti_reader/format_missing_compression_header_block_count_2gb.vti", "velded",
                 "listing 538976288 blocks, more than the file's remaining"},
                false);
}

// '=' inside an inline base64 compression header: VTK decodes it as zero bits and reads on, a
// compressed size of 9e18 bytes, which it allocates before reading.
TEST(FuzzFindings, CompressedSizeBeyondTheFileIsRefused) {
  expectRefused({"vti_reader/base64_padding_inside_compression_header.vti", "velocity",
                 "GB, more than the file's remaining"},
                false);
}

// The last cell offset read from the data is 2^34: VTK sizes the connectivity (137 GB) by it.
TEST(FuzzFindings, ConnectivityLongerThanTheFileIsRefused) {
  expectRefused({"vtp_reader/verts_last_offset_2e34.vtp", "connectivity",
                 "(17179869184 point ids, the last of the offsets)"},
                true);
}

// NumberOfComponents misspelt "NumberOfoCmponents" in <Points> (a 240 s run from seed 777, issue
// 25): the coordinates read as 1 component, vtkPoints::SetData rejects them and VTK's reader
// leaked the array and the vtkPoints (LeakSanitizer: 5 allocations, 495 bytes). Refused before VTK
// reads the data; fuzz_vtp_reader_replay runs the input under ASan with leak detection.
TEST(FuzzFindings, PointCoordinatesWithoutThreeComponentsAreRefused) {
  expectRefused({"vtp_reader/misspelt_points_components_leaks_in_vtk.vtp", "Points",
                 "have 1 component(s) (no NumberOfComponents attribute); allowed: "
                 "NumberOfComponents=\"3\""},
                true);
}

// A FIELD array header of type "i" followed by bytes (the first 20 inputs of the first CI-style
// run of fuzz_vtk_legacy_reader, issue 15): VTK 9.1's vtkStructuredGridReader::ReadMetaDataSimple
// dereferenced the null array it makes of an unknown type (a segmentation fault). Refused by the
// size check, which follows FIELD blocks array by array, before VTK reads the file.
TEST(FuzzFindings, LegacyFieldArrayOfUnknownTypeIsRefused) {
  const char* file = "vtk_legacy_reader/field_array_of_unknown_type_crashes_vtk.vtk";
  expectLegacyRefused(file, "(field array step) has type 'i");
  expectLegacyRefused(file, "allowed: bit, char");
}

// A FIELD array named "step" followed by 0x8b bytes (fuzz_long.sh, vtk_legacy_reader seed
// 1057018792, issue 25). VTK's legacy reader accepts it; the child process then handed the
// dataset over as legacy bytes, which VTK's legacy writer wrote with the name as it is, and the
// parent's re-read crashed on them (SEGV in vtkRectilinearGridReader::ReadMeshSimple, exit 139).
// The child now hands over VTK XML, whose reader refuses the name with a message.
TEST(FuzzFindings, LegacyArrayNameThatCannotBeReadBackIsRefused) {
  expectLegacyRefused("vtk_legacy_reader/array_name_vtk_cannot_read_back_crashed_the_reread.vtk",
                      " cannot be read: Error parsing XML");
}

// Points 1e17 apart in x with a few nodes' worth of points (the CI-style fuzz run of
// fuzz_vtk_legacy_reader after the XML hand-over): the automatic spacing gave 1e14 nodes along
// x, counted in an int (UBSan: overflow). Counted in double, the image is refused by its size.
TEST(FuzzFindings, LegacyBoundsTooWideForAnImageAreRefused) {
  expectLegacyRefused("vtk_legacy_reader/bounds_1e17_wide_overflowed_the_image_size.vtk",
                      "nodes, more than the limit 2e+08");
}

// A <DataArray> in <FieldData> without a type attribute ("pyte", fuzz_vtk_xml_grids' first
// minute): VTK 9.1's information pass dereferenced the array it could not make (SEGV). The
// element checks now run on VTK's parse before that pass.
TEST(FuzzFindings, FieldDataArrayWithoutTypeIsRefusedBeforeVtkReadsTheHeader) {
  expectRefusedBy({"vtk_xml_grids/fielddata_array_without_type_crashed_vtk_information_pass.vtu",
                   "step", "array 'step' has type (none); allowed: Int8"},
                  [](const std::string& path) { readImageData(path); });
}

// One corrupt byte in the zlib block of a .vtu's cell types (fuzz_vtk_xml_grids, LeakSanitizer):
// VTK 9.1's reader leaked the types array on that error path. The types are read through VTK's
// parser first and a short read is refused before VTK's reader runs.
TEST(FuzzFindings, CorruptCellTypesAreRefusedBeforeVtkReadsThem) {
  expectRefusedBy({"vtk_xml_grids/corrupt_cell_types_leaked_vtk_types_array.vtu", "types",
                   "holds fewer than the 2 cell types that NumberOfCells declares"},
                  [](const std::string& path) { readImageData(path); });
}

// A .vtu cell naming point 3539887779605394692 (fuzz_vtk_xml_grids): VTK's XML reader keeps it,
// and vtkCellDataToPointData's threads read far outside the points (SIGBUS). The legacy reader's
// geometry checks (DataSetChecks.h) now run on every dataset read.
TEST(FuzzFindings, XmlCellNamingAPointThatDoesNotExistIsRefused) {
  expectLegacyRefused("vtk_xml_grids/cell_naming_point_3.5e18_crashed_cell_to_point_threads.vtu",
                      ": cell 0 names point 3539887779605394692, outside [0, 5]");
}

// A damaged compression header of a <FieldData> array (fuzz_vtk_xml_grids, out of memory: an
// 8 GB block list): VTK reads field data already in its information pass, before the size checks
// ran. Their header part now runs on VTK's bare parse first.
TEST(FuzzFindings, FieldDataCompressionHeaderIsCheckedBeforeVtkReadsIt) {
  expectRefusedBy({"vtk_xml_grids/fielddata_compression_header_2e9_blocks_read_in_information_pass.vtr",
                   "step", "has a compression header listing 2067070977 blocks"},
                  [](const std::string& path) { readImageData(path); });
}

// Cells whose bounding boxes all span the grid (the stop-30 CI run: a 42 s timeout of
// fuzz_vtk_xml_grids inside vtkProbeFilter; the finding itself was not kept, this .vts has the
// same shape): 200 x 200 points folded onto two corners make every cell overlap every other, and
// the probe tests each of the 40000 nodes against 39601 cells. Refused before the probe runs.
TEST(FuzzFindings, CellsThatAllOverlapAreRefusedBeforeTheProbe) {
  expectLegacyRefused("vtk_xml_grids/points_folded_onto_two_corners_made_the_probe_hang.vts",
                      ": its cells overlap; resampling would test each node of the image against");
}

// <DataArrayPDataArray Name="velocity" NumberOfComponents="6"> inside a .pvtu's <PPointData>
// (fuzz_vtk_xml_grids, ASan heap-buffer-overflow in vtkXMLPDataReader::ReadPieceData): VTK read
// the misspelt element as the summary's velocity and copied 6 components per point out of the
// piece's 3. The summary's sections may now hold only PDataArray and PArray elements.
TEST(FuzzFindings, MisspeltSummaryArrayElementIsRefused) {
  expectLegacyRefused(
      "vtk_xml_grids/misspelt_pdataarray_declaring_6_components_overflowed_the_piece_copy.pvtu",
      "element <DataArrayPDataArray> 'velocity' inside <PPointData> is not an array (allowed: "
      "PDataArray, PArray)");
}

// Coordinates with format="text" (fuzz_vtk_xml_grids, out of memory: malloc(5222748468) in the
// stop-35 CI run): VTK reads any format but "binary" as ASCII, but the check for values past the
// declared extent probed such an array as inline binary, and the text's digits, decoded as base64,
// made a compression header of 3.5e9 blocks (14 GB). The probe now reads as VTK does.
TEST(FuzzFindings, ArraysOfAnUnknownFormatAreProbedAsAscii) {
  const vtkSmartPointer<vtkImageData> image =
      readImageData(regression("vtk_xml_grids/ascii_coordinates_probed_as_binary_asked_14gb.vtr"));
  // The grid is resampled onto image nodes (readImageData); p = x + 3 y is linear, so every
  // node carries exactly x + 3 y of its position.
  double bounds[6];
  image->GetBounds(bounds);
  EXPECT_EQ(bounds[0], 0.0);
  EXPECT_EQ(bounds[1], 2.0);
  EXPECT_EQ(bounds[2], 0.0);
  EXPECT_EQ(bounds[3], 1.0);
  vtkDataArray* p = image->GetPointData()->GetArray("p");
  ASSERT_NE(p, nullptr);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    double x[3];
    image->GetPoint(i, x);
    EXPECT_NEAR(p->GetTuple1(i), x[0] + 3 * x[1], 1e-12) << "node " << i;
  }
}

}  // namespace
}  // namespace fluidviz
