// fluidviz plot: a picture of a CSV's columns, and the errors a user's file gets (exit code 2,
// the file, the columns there are, the line of a bad value) with nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "apps/fluidviz/Commands.h"
#include "tests/support/PngFiles.h"

namespace fluidviz {
namespace {

namespace fs = std::filesystem;

class PlotCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fluidviz_plot_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    write("series.csv", "# a test\nt (s),E (J),v (m/s)\n0,0,1\n1,2,nan\n2,3,0.5\n");
    write("ref.csv", "t,E\n0.5,1\n1.5,2.5\n");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  int run(std::vector<std::string> args) {
    out_.str("");
    err_.str("");
    return app::dispatch(args, out_, err_, false);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
  std::ostringstream out_, err_;
};

TEST_F(PlotCommand, DrawsColumnsAndReference) {
  ASSERT_EQ(run({"plot", file("series.csv"), "--y", "E", "--reference", file("ref.csv"),
                 "--width", "500", "--height", "300", "-o", file("p.png")}), 0) << err_.str();
  const RgbaImage img = testing::readPngImage(dir_ / "p.png");
  EXPECT_EQ(img.width, 500);
  EXPECT_EQ(img.height, 300);
  ASSERT_EQ(run({"plot", file("series.csv"), "-o", file("all.png")}), 0) << err_.str();
  EXPECT_TRUE(fs::exists(dir_ / "all.png"));
}

TEST_F(PlotCommand, ErrorsAreBadInputAndWriteNothing) {
  EXPECT_EQ(run({"plot", file("none.csv"), "-o", file("p.png")}), 2);
  EXPECT_NE(err_.str().find("cannot read " + file("none.csv")), std::string::npos) << err_.str();
  EXPECT_EQ(run({"plot", file("series.csv"), "--y", "u", "-o", file("p.png")}), 2);
  EXPECT_NE(err_.str().find("has no column 'u'; its columns: t (s), E (J), v (m/s)"),
            std::string::npos) << err_.str();
  EXPECT_EQ(run({"plot", file("series.csv"), "--x", "time", "-o", file("p.png")}), 2);
  EXPECT_NE(err_.str().find("has no column 'time'"), std::string::npos) << err_.str();
  write("bad.csv", "t,E\n0,1\n1,x2\n");
  EXPECT_EQ(run({"plot", file("bad.csv"), "-o", file("p.png")}), 2);
  EXPECT_NE(err_.str().find("line 3: 'x2' in column 'E' is not a finite number"),
            std::string::npos) << err_.str();
  EXPECT_EQ(run({"plot", file("series.csv"), "--reference", file("bad.csv"), "-o", file("p.png")}),
            2);
  EXPECT_EQ(run({"plot", file("series.csv")}), 2);  // no -o
  EXPECT_NE(err_.str().find("needs -o"), std::string::npos) << err_.str();
  EXPECT_FALSE(fs::exists(dir_ / "p.png"));
}

}  // namespace
}  // namespace fluidviz
