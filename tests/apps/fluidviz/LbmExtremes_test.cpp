// The LBM solver at the edges of what it can do, through the fluidviz command (in-process, as
// Cli_test.cpp): each case ends either with a correct result or with exit code 2 (refused before
// running, nothing written) or 3 (stopped while running), and a message that says where, why and
// what to change. After an exit 3 the snapshots already written stay, the .pvd lists exactly
// those, and none contains a NaN.
// Scene: lid-driven unit cavity, 32 x 32 nodes (24 for the run that succeeds), lid 1 m/s.
// tau = 1/2 + 3 u_lb N / Re, so Re = u_lb N / (tau - 1/2) / 3 sets tau.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "apps/fluidviz/Commands.h"
#include "tests/apps/fluidviz/CliTestSupport.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "tests/support/TextFiles.h"

namespace fs = std::filesystem;
using fluidviz::app::dispatch;

namespace {

using fluidviz::test::Result;

class LbmExtremes : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fluidviz_lbm_extremes_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "cav.json") << R"({ "name": "cav",
      "lbm": { "domain_size": [1, 1], "resolution": 32, "reynolds": 100, "lattice_velocity": 0.1,
               "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}},
               "end_time": 20.0, "check_interval": 100 },
      "output": { "snapshots": 10 } })";
  }
  void TearDown() override { fs::remove_all(dir_); }

  Result run(const std::vector<std::string>& sets) {
    std::vector<std::string> args{"run", (dir_ / "cav.json").string(), "-o", out().string()};
    for (const auto& s : sets) {
      args.push_back("--set");
      args.push_back(s);
    }
    std::ostringstream o, e;
    const int code = dispatch(args, o, e, false);
    return {code, o.str(), e.str()};
  }
  fs::path out() const { return dir_ / "out"; }

  // Every file the .pvd lists exists and holds finite values only; returns how many.
  int checkSeries() {
    std::ifstream pvd(out() / "cav.pvd");
    std::stringstream text;
    text << pvd.rdbuf();
    const std::string s = text.str();
    const std::regex file("file=\"([^\"]+)\"");
    int listed = 0;
    for (auto it = std::sregex_iterator(s.begin(), s.end(), file); it != std::sregex_iterator(); ++it) {
      const fs::path vti = out() / (*it)[1].str();
      EXPECT_TRUE(fs::exists(vti)) << vti;
      const fluidviz::FieldSet f = fluidviz::readVti(vti);
      for (const auto& sc : f.scalars)
        for (double v : sc.values) EXPECT_TRUE(std::isfinite(v)) << vti << " " << sc.name;
      for (const auto& ve : f.vectors)
        for (const auto& v : ve.values) EXPECT_TRUE(v.allFinite()) << vti << " " << ve.name;
      ++listed;
    }
    int onDisk = 0;
    if (fs::exists(out() / "cav"))
      for (const auto& e : fs::directory_iterator(out() / "cav")) {
        EXPECT_EQ(e.path().extension(), ".vti") << "left over: " << e.path();
        ++onDisk;
      }
    EXPECT_EQ(onDisk, listed) << "the .pvd lists every snapshot on disk, and only those";
    return listed;
  }

  fs::path dir_;
};

void expectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in: " << text;
}

// tau = 0.5 + 1e-4 with the lid at lattice speed 0.17 (Mach 0.29): BGK refuses it.
TEST_F(LbmExtremes, TauNextToHalfWithFastLidBgkIsRefused) {
  const Result r = run({"lbm.reynolds=163200", "lbm.lattice_velocity=0.17"});
  EXPECT_EQ(r.code, 2) << r.err;
  expectContains(r.err, "key 'lbm.resolution' gives tau = 0.5001, too close to 1/2");
  expectContains(r.err, "raise lbm.resolution to at least");
  expectContains(r.err, "lbm.collision = trt");
  EXPECT_FALSE(fs::exists(out())) << "refused input writes nothing";
}

// The same with TRT is allowed (TRT is stable for any tau > 1/2 in the linear regime), but the
// 32-node lattice cannot carry Re 1.6e5: it stops while running and says where and why.
TEST_F(LbmExtremes, TauNextToHalfWithFastLidTrtStopsWithStepPlaceAndCause) {
  const Result r = run({"lbm.collision=trt", "lbm.reynolds=163200", "lbm.lattice_velocity=0.17"});
  EXPECT_EQ(r.code, 3) << r.err;
  expectContains(r.err, "tau = 0.5001");
  expectContains(r.err, "unstable at step ");
  expectContains(r.err, " at node (");
  EXPECT_TRUE(r.err.find("not positive") != std::string::npos ||
              r.err.find("exceeds 0.5") != std::string::npos ||
              r.err.find("NaN") != std::string::npos)
      << r.err;
  expectContains(r.err, "raise lbm.resolution or lower lbm.reynolds");
  checkSeries();
}

// Lattice speed 0.5 (Mach 0.87) is outside the declared range; 0.2 passes the range but not the
// Mach limit 0.3: both refused, naming the key and the value to use.
TEST_F(LbmExtremes, LatticeSpeedBeyondTheLimitsIsRefused) {
  Result r = run({"lbm.lattice_velocity=0.5"});
  EXPECT_EQ(r.code, 2) << r.err;
  expectContains(r.err, "key 'lbm.lattice_velocity' is 0.5, outside the allowed range (0, 0.4]");
  r = run({"lbm.lattice_velocity=0.2"});
  EXPECT_EQ(r.code, 2) << r.err;
  expectContains(r.err, "Mach = lattice_velocity * sqrt(3) = 0.3464, above 0.3");
  expectContains(r.err, "lower lbm.lattice_velocity to at most 0.173");
  EXPECT_FALSE(fs::exists(out()));
}

// Just inside the Mach limit (lattice speed 0.17) at Re 100 on 24 nodes: runs, and the flow is
// physical: driven by the lid (max speed > 0.2 m/s) and never faster than it.
TEST_F(LbmExtremes, LatticeSpeedJustInsideTheLimitRuns) {
  const Result r = run({"lbm.collision=trt", "lbm.lattice_velocity=0.17", "lbm.resolution=24",
                        "lbm.end_time=5"});
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(checkSeries(), 11);  // t = 0 and the 10 snapshots (issue 16)
  const fluidviz::FieldSet last = fluidviz::readVti(out() / "cav/cav_0010.vti");
  double maxSpeed = 0;
  for (const auto& v : last.findVector("velocity")->values) maxSpeed = std::max(maxSpeed, v.norm());
  EXPECT_GT(maxSpeed, 0.2);
  EXPECT_LT(maxSpeed, 1.0);
}

// Re 1e5 on 32 nodes: BGK refuses (tau = 0.50096) and names a resolution that works -- the
// suggested resolution passes `fluidviz check`. TRT at Re 5000 (tau = 0.5019) runs into the
// instability of the under-resolved corner vortices and stops; the snapshot written before
// (step 640 of 6400) stays, listed in the .pvd, without NaN.
TEST_F(LbmExtremes, ReynoldsBeyondTheResolution) {
  Result r = run({"lbm.reynolds=1e5"});
  EXPECT_EQ(r.code, 2) << r.err;
  const std::smatch m = [&] {
    std::smatch match;
    std::regex_search(r.err, match, std::regex("raise lbm.resolution to at least ([0-9]+)"));
    return match;
  }();
  ASSERT_EQ(m.size(), 2u) << r.err;
  {
    std::ostringstream o, e;
    const int code = dispatch({"check", (dir_ / "cav.json").string(), "--set", "lbm.reynolds=1e5",
                               "--set", "lbm.resolution=" + m[1].str()},
                              o, e, false);
    EXPECT_EQ(code, 0) << "the suggested resolution " << m[1] << " is accepted: " << e.str();
  }
  r = run({"lbm.collision=trt", "lbm.reynolds=5000"});
  EXPECT_EQ(r.code, 3) << r.err;
  expectContains(r.err, "unstable at step ");
  expectContains(r.err, "tau is close to 1/2");
  EXPECT_GE(checkSeries(), 1) << "the snapshot before the instability is kept";
  // The run record says how the run ended (pipeline/RunRecord.h).
  const std::string record = fluidviz::testing::readText(out() / "cav_run.json");
  expectContains(record, "\"outcome\": \"unstable\"");
  expectContains(record, "tau is close to 1/2");
}

}  // namespace
