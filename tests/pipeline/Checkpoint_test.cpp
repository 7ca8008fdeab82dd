// The checkpoint file (pipeline/Checkpoint.h): what is written reads back exactly;
// a corrupt (one flipped bit), truncated, padded, foreign, other-version or missing file is
// refused with a FileError naming the file and what is wrong; the temporary names of the atomic
// writer are recognised (core/AtomicFile.h).
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "fieldviz/core/AtomicFile.h"
#include "fieldviz/io/FileError.h"
#include "pipeline/Checkpoint.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
void writeBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

class CheckpointFile : public test::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    header_.solver = "lbm";
    header_.sceneJson = R"({"name":"x"})";
    header_.step = 1234;
    header_.time = 0.1 + 0.2;
    header_.snapshots = {{0.125, "x/x_0001.vti"}, {0.25, "x/x_0002.vti"}};
    values_ = {1.0, -0.0, 1e-300, 3.141592653589793};
    writeCheckpoint(file(), header_, [&](StateWriter& w) {
      w.putVector(values_);
      w.put<std::int32_t>(-7);
    });
  }
  fs::path file() const { return dir_ / "x.checkpoint"; }
  // The FileError message of reading the file, or "" if it reads.
  std::string readError() const {
    try {
      readCheckpoint(file());
    } catch (const FileError& e) {
      EXPECT_EQ(e.path(), file());
      return e.what();
    }
    return "";
  }
  CheckpointHeader header_;
  std::vector<double> values_;
};

TEST_F(CheckpointFile, ReadsBackExactly) {
  LoadedCheckpoint c = readCheckpoint(file());
  EXPECT_EQ(c.header.solver, "lbm");
  EXPECT_EQ(c.header.sceneJson, header_.sceneJson);
  EXPECT_EQ(c.header.step, 1234);
  EXPECT_EQ(c.header.time, 0.1 + 0.2);  // bit-exact
  ASSERT_EQ(c.header.snapshots.size(), 2u);
  EXPECT_EQ(c.header.snapshots[1].time, 0.25);
  EXPECT_EQ(c.header.snapshots[1].file, "x/x_0002.vti");
  std::vector<double> v;
  c.state.getVector(v, 4);
  EXPECT_EQ(v, values_);
  EXPECT_TRUE(std::signbit(v[1]));
  EXPECT_EQ(c.state.get<std::int32_t>(), -7);
  EXPECT_EQ(c.state.remaining(), 0u);
  EXPECT_EQ(readBytes(file()).substr(0, 20), "fluidviz checkpoint\n");
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path(), file()) << "only the checkpoint, no temporary file";
}

TEST_F(CheckpointFile, EveryFlippedBitIsDetected) {
  const std::string good = readBytes(file());
  // Every byte of the file, one bit each (the file is ~150 bytes).
  for (std::size_t at = 0; at < good.size(); ++at) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ (1 << (at % 8)));
    writeBytes(file(), bad);
    EXPECT_NE(readError(), "") << "flipped bit in byte " << at << " went unnoticed";
  }
  std::string bad = good;
  bad[good.size() / 2] ^= 0x10;
  writeBytes(file(), bad);
  EXPECT_NE(readError().find("checkpoint " + file().string() +
                             " is corrupt: its checksum does not match its contents"),
            std::string::npos)
      << readError();
}

TEST_F(CheckpointFile, TruncatedOrPaddedIsRefused) {
  const std::string good = readBytes(file());
  writeBytes(file(), good.substr(0, good.size() - 9));
  EXPECT_NE(readError().find("is truncated or padded: " + std::to_string(good.size() - 9) +
                             " bytes, its header announces " + std::to_string(good.size())),
            std::string::npos)
      << readError();
  writeBytes(file(), good.substr(0, 25));
  EXPECT_NE(readError().find("is truncated: 25 bytes"), std::string::npos) << readError();
  writeBytes(file(), good + "x");
  EXPECT_NE(readError().find("is truncated or padded"), std::string::npos) << readError();
  writeBytes(file(), "");
  EXPECT_NE(readError().find("is not a fluidviz checkpoint"), std::string::npos) << readError();
}

TEST_F(CheckpointFile, ForeignFileIsRefused) {
  writeBytes(file(), "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\"/>\n");
  EXPECT_NE(readError().find("checkpoint " + file().string() + " is not a fluidviz checkpoint"),
            std::string::npos)
      << readError();
  EXPECT_NE(readError().find("start the run again without --resume"), std::string::npos);
}

TEST_F(CheckpointFile, OtherFormatVersionIsRefused) {
  std::string bytes = readBytes(file());
  bytes[20] = 2;  // the u32 after the magic
  writeBytes(file(), bytes);
  EXPECT_NE(readError().find("has format version 2; this fluidviz reads version 1"),
            std::string::npos)
      << readError();
}

TEST_F(CheckpointFile, MissingFileIsNamed) {
  fs::remove(file());
  EXPECT_NE(readError().find("no checkpoint " + file().string()), std::string::npos)
      << readError();
}

TEST_F(CheckpointFile, ValidChecksumOverMalformedContentsIsRefused) {
  // A well-formed envelope around a payload that ends inside the header: malformed, not a crash.
  writeCheckpoint(file(), header_, [](StateWriter&) {});
  std::string bytes = readBytes(file());
  StateWriter w;
  w.put<std::uint64_t>(1u << 30);  // a string length past the end
  const std::string payload(reinterpret_cast<const char*>(w.bytes().data()), w.bytes().size());
  std::string forged = bytes.substr(0, 20) + bytes.substr(20, 4);
  const std::uint64_t size = payload.size();
  forged += std::string(reinterpret_cast<const char*>(&size), 8) + payload;
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a 64
  for (unsigned char c : forged) hash = (hash ^ c) * 1099511628211ull;
  forged += std::string(reinterpret_cast<const char*>(&hash), 8);
  writeBytes(file(), forged);
  EXPECT_NE(readError().find("is malformed: a count of 1073741824 items"), std::string::npos)
      << readError();
}

TEST(AtomicFileNames, TemporaryNamesAreRecognised) {
  EXPECT_EQ(temporaryFileWriter(".flow_0003.tmp4242_7.vti"), 4242);
  EXPECT_EQ(temporaryFileWriter("out/.flow.tmp17_0.pvd"), 17);
  EXPECT_EQ(temporaryFileWriter(".x.tmp5_12.checkpoint"), 5);
  EXPECT_EQ(temporaryFileWriter("flow_0003.vti"), -1);
  EXPECT_EQ(temporaryFileWriter("flow.tmp4242_7.vti"), -1) << "temporary names start with '.'";
  // What writeAtomically really uses.
  fs::path seen;
  writeAtomically(fs::temp_directory_path() / "fluidviz_atomic_name.vti",
                  [&](const fs::path& tmp) {
                    seen = tmp;
                    std::ofstream(tmp) << "x";
                  });
  EXPECT_EQ(temporaryFileWriter(seen), static_cast<long>(::getpid())) << seen;
  fs::remove(fs::temp_directory_path() / "fluidviz_atomic_name.vti");
}

}  // namespace
}  // namespace fluidviz
