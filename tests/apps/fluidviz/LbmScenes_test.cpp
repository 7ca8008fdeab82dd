// LBM scenes through the fluidviz command (in-process): a 3D scene (lattice D3Q19) writes 3D .vti
// snapshots and draws one z layer; derived fields (vorticity, stream function) are drawn when an
// image asks for them; a 3D picture without a layer is refused before running.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "apps/fluidviz/Commands.h"
#include "fieldviz/io/VtkXmlReaders.h"

namespace fs = std::filesystem;
using fluidviz::app::dispatch;

namespace {

class LbmScenes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_lbm_scenes_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int run(const std::string& scene, std::string& err) {
    std::ofstream(dir_ / "scene.json") << scene;
    std::ostringstream o, e;
    const int code =
        dispatch({"run", (dir_ / "scene.json").string(), "-o", out().string()}, o, e, false);
    err = e.str();
    return code;
  }
  fs::path out() const { return dir_ / "out"; }
  fs::path dir_;
};

// 16 x 16 x 8 nodes cavity with a lid sliding along x, 2 snapshots.
std::string cavity3d(const std::string& images) {
  return R"({ "name": "c3",
    "lbm": { "lattice": "D3Q19", "collision": "trt", "domain_size": [1, 1], "domain_depth": 0.5,
             "resolution": 16, "reynolds": 20, "lattice_velocity": 0.1,
             "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}}, "end_time": 2.0 },
    "output": { "snapshots": 2, "images": )" + images + " } }";
}

TEST_F(LbmScenes, ThreeDimensionalSceneWritesThreeDimensionalSnapshots) {
  std::string err;
  ASSERT_EQ(run(cavity3d(R"([{"field": "speed", "slice_index": 4},
                             {"field": "vorticity", "slice_index": 4},
                             {"field": "stream_function", "slice_index": 4}])"), err), 0) << err;
  EXPECT_NE(err.find("lattice 16 x 16 x 8 nodes"), std::string::npos) << err;
  const fluidviz::FieldSet f = fluidviz::readVti(out() / "c3/c3_0002.vti");
  EXPECT_EQ(f.grid.dims[0], 16);
  EXPECT_EQ(f.grid.dims[1], 16);
  EXPECT_EQ(f.grid.dims[2], 8);
  EXPECT_NEAR(f.grid.origin[2], 0.5 / 16, 1e-12);  // node-centred along z too
  const auto& u = f.findVector("velocity")->values;
  double maxSpeed = 0, maxZ = 0;
  for (const auto& v : u) {
    maxSpeed = std::max(maxSpeed, v.norm());
    maxZ = std::max(maxZ, std::abs(v.z()));
  }
  EXPECT_GT(maxSpeed, 0.2);   // driven by the lid
  EXPECT_LT(maxSpeed, 1.0);   // never faster than the lid
  EXPECT_GT(maxZ, 1e-4);      // the end walls z = 0, 0.5 make the flow three-dimensional
  for (const char* png : {"c3_speed.png", "c3_vorticity.png", "c3_stream_function.png"})
    EXPECT_TRUE(fs::exists(out() / png)) << png;
}

TEST_F(LbmScenes, ThreeDimensionalPictureNeedsALayer) {
  std::string err;
  EXPECT_EQ(run(cavity3d(R"([{"field": "speed"}])"), err), 2);
  EXPECT_NE(err.find("key 'output.images[0].slice_index' is -1; a 3D scene (lattice D3Q19, 8 "
                     "nodes along z) draws one z layer: give slice_index in [0, 7]"),
            std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(out()));
}

}  // namespace
