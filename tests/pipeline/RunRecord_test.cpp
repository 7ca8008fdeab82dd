// A run's record (pipeline/RunRecord.h, issue 16): <name>_run.json and the scene copy's header
// say which fluidviz made the files, when, with how many threads, with which derived units, and
// how the run ended; and a second run never mixes its files with an earlier run's (issue 16,
// defect 6: a second run into the same folder left the first run's later snapshots beside the
// new ones, and ParaView's file-series grouping then mixed two runs).
#include <omp.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>
#include <vtkAbstractArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataReader.h>

#include "fieldviz/core/BuildInfo.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/scene/SceneFile.h"
#include "pipeline/RunRecord.h"
#include "tests/pipeline/PipelineTestSupport.h"

namespace fs = std::filesystem;

namespace fluidviz {
namespace {

using test::sceneFromText;

// 16 x 16 cavity, 0.5 s (dt = u_lattice dx / U = 0.1 / 16 s: 80 steps): `snapshots` snapshots.
std::string smallCavity(int snapshots) {
  return R"({ "name": "cav", "solver": "lbm",
    "lbm": { "domain_size": [1, 1], "resolution": 16, "reynolds": 10, "lattice_velocity": 0.1,
             "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}},
             "end_time": 0.5 },
    "output": { "snapshots": )" + std::to_string(snapshots) + R"(, "images": [] } })";
}

std::vector<std::string> filesUnder(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path().lexically_relative(dir).generic_string());
  std::sort(files.begin(), files.end());
  return files;
}

scene::json readJson(const fs::path& file) {
  std::ifstream in(file);
  return scene::json::parse(in);
}

class RunRecordTest : public test::TempDirTest {};

// Before: the second run (2 snapshots) succeeded and left cav_0003.vti and cav_0004.vti of the
// first (4 snapshots) beside its own.
TEST_F(RunRecordTest, SecondRunIntoTheSameFolderIsRefusedAndNothingChanges) {
  runInto(sceneFromText(smallCavity(4)), "out");
  const std::vector<std::string> before = filesUnder(dir_ / "out");
  try {
    runInto(sceneFromText(smallCavity(2)), "out");
    FAIL() << "a second run into a folder holding an earlier run must be refused";
  } catch (const FileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("holds an earlier run of scene 'cav'"), std::string::npos) << m;
    EXPECT_NE(m.find("--replace"), std::string::npos) << m;
    EXPECT_NE(m.find("-o"), std::string::npos) << m;
  }
  EXPECT_EQ(filesUnder(dir_ / "out"), before) << "a refused run writes and removes nothing";
}

TEST_F(RunRecordTest, ReplaceRemovesTheEarlierRunsFilesFirst) {
  runInto(sceneFromText(smallCavity(4)), "out");
  std::ofstream(dir_ / "out" / "notes.txt") << "the user's own file\n";
  RunOptions options = optionsFor("out", false, -1);
  options.replace = true;
  const RunSummary second = runScene(sceneFromText(smallCavity(2)), options);

  std::vector<std::string> written;
  for (const fs::path& f : second.files)
    written.push_back(f.lexically_relative(dir_ / "out").generic_string());
  written.push_back("notes.txt");  // not the earlier run's: kept
  std::sort(written.begin(), written.end());
  EXPECT_EQ(filesUnder(dir_ / "out"), written)
      << "only the second run's files (and the user's own) are left";
  EXPECT_FALSE(fs::exists(dir_ / "out" / "cav" / "cav_0004.vti"));
}

TEST_F(RunRecordTest, RecordSaysWhoMadeTheFilesAndHowTheRunEnded) {
  const RunSummary s = runInto(sceneFromText(smallCavity(2)), "out");
  const scene::json r = readJson(dir_ / "out" / "cav_run.json");
  EXPECT_EQ(r["fluidviz"]["version"], buildInfo().version);
  EXPECT_EQ(r["fluidviz"]["commit"], buildInfo().commit);
  EXPECT_TRUE(std::regex_match(r["fluidviz"]["commit"].get<std::string>(),
                               std::regex("[0-9a-f]{40}|unknown")));
  EXPECT_TRUE(std::regex_match(r["fluidviz"]["date"].get<std::string>(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_EQ(r["fluidviz"]["threads"], omp_get_max_threads());
  EXPECT_EQ(r["outcome"], "completed");
  EXPECT_EQ(r["steps"], s.steps);
  EXPECT_DOUBLE_EQ(r["time"].get<double>(), s.time);
  // The derived lattice units: 16 nodes per metre, tau = 3 nu_lattice + 1/2 with
  // nu_lattice = u_lattice n / Re = 0.1 * 16 / 10 = 0.16.
  ASSERT_GE(r["solver"].size(), 2u);
  EXPECT_NE(r["solver"][0].get<std::string>().find("lattice 16 x 16 nodes"), std::string::npos);
  EXPECT_NE(r["solver"][1].get<std::string>().find("tau = 0.98"), std::string::npos)
      << r["solver"][1];
  for (const auto& f : r["files"]) EXPECT_TRUE(fs::exists(dir_ / "out" / f.get<std::string>())) << f;
  EXPECT_EQ(r["files"].size() + 1, filesUnder(dir_ / "out").size())
      << "every file but the record itself is listed";
  EXPECT_EQ(r["scene"]["lbm"]["resolution"], 16);
}

// The scene copy stays a scene: read back, it gives the effective scene of the record; its
// comment lines carry the provenance and the outcome.
TEST_F(RunRecordTest, SceneCopyIsRerunnableAndSaysWhereItCameFrom) {
  runInto(sceneFromText(smallCavity(2)), "out");
  const fs::path copy = dir_ / "out" / "cav_scene.json";
  const std::string text = test::readText(copy);
  EXPECT_EQ(text.rfind("// Effective scene", 0), 0u) << text.substr(0, 200);
  EXPECT_NE(text.find("fluidviz " + buildInfo().version), std::string::npos);
  EXPECT_NE(text.find("run completed at t = 0.5 s after 80 steps"), std::string::npos)
      << text.substr(0, 400);
  EXPECT_EQ(scene::readSceneFile(copy), readJson(dir_ / "out" / "cav_run.json")["scene"]);
}

// Each snapshot carries the provenance as VTK field data (what ParaView shows in its
// Information panel) and its time as TimeValue, equal to the time the .pvd lists.
TEST_F(RunRecordTest, SnapshotsCarryProvenanceAndTimeAsFieldData) {
  runInto(sceneFromText(smallCavity(2)), "out");
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName((dir_ / "out" / "cav" / "cav_0002.vti").c_str());
  reader->Update();
  vtkFieldData* fd = reader->GetOutput()->GetFieldData();
  auto text = [&](const char* name) -> std::string {
    auto* a = vtkStringArray::SafeDownCast(fd->GetAbstractArray(name));
    return a && a->GetNumberOfValues() == 1 ? a->GetValue(0) : "<missing " + std::string(name) + ">";
  };
  EXPECT_EQ(text("fluidviz_version"), buildInfo().version);
  EXPECT_EQ(text("fluidviz_commit").substr(0, buildInfo().commit.size()), buildInfo().commit);
  EXPECT_EQ(text("scene_name"), "cav");
  EXPECT_NE(text("solver").find("lattice 16 x 16 nodes"), std::string::npos) << text("solver");
  EXPECT_EQ(scene::json::parse(text("scene")), readJson(dir_ / "out" / "cav_run.json")["scene"]);
  vtkDataArray* t = fd->GetArray("TimeValue");
  ASSERT_NE(t, nullptr);
  EXPECT_DOUBLE_EQ(t->GetTuple1(0), 0.5) << "snapshot 2 of 2 is the final state at end_time";
}

}  // namespace
}  // namespace fluidviz
