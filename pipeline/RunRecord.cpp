#include "pipeline/RunRecord.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <set>
#include <sstream>

#include "fieldviz/core/BuildInfo.h"
#include "fieldviz/core/Params.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"

namespace fluidviz {

namespace fs = std::filesystem;

const char* outcomeName(RunOutcome outcome) {
  switch (outcome) {
    case RunOutcome::completed: return "completed";
    case RunOutcome::steady_state: return "steady_state";
    case RunOutcome::unstable: return "unstable";
    case RunOutcome::interrupted: return "interrupted";
  }
  return "unknown";
}

namespace {

std::string utcNow() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// "completed at t = 60 s after 76800 steps" (plus the reason for an early stop).
std::string outcomeLine(const RunRecord& r) {
  std::string line = std::string(outcomeName(r.outcome)) + " at t = " + formatNumber(r.time, 6) +
                     " s after " + std::to_string(r.steps) + " steps";
  if (!r.message.empty()) line += ": " + r.message;
  return line;
}

// The scene copy's header: scene files allow // comments, so the copy stays re-runnable.
std::string sceneCopyText(const RunRecord& r, const scene::json& effectiveScene) {
  std::string text = "// Effective scene (every default spelled out), written by " +
                     r.provenance.line() + "\n// from " + r.sceneFile + "; run " + outcomeLine(r) +
                     "\n";
  for (const std::string& l : lines(r.solverDescription)) text += "// " + l + "\n";
  return text + effectiveScene.dump(2) + "\n";
}

std::string relativeTo(const fs::path& dir, const fs::path& file) {
  return file.lexically_relative(dir).generic_string();
}

void addIfFile(const fs::path& p, std::set<fs::path>& files) {
  std::error_code e;
  if (fs::is_regular_file(p, e)) files.insert(p.lexically_normal());
}

// The files an earlier run's record lists (nothing if it has none or it does not parse).
void addRecordedFiles(const fs::path& dir, const std::string& name, std::set<fs::path>& files) {
  std::ifstream in(runRecordPath(dir, name));
  if (!in) return;
  const scene::json record = scene::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!record.is_object() || !record.contains("files") || !record["files"].is_array()) return;
  for (const scene::json& f : record["files"]) {
    if (!f.is_string()) continue;
    const fs::path p = (dir / f.get<std::string>()).lexically_normal();
    // Only files inside dir: a record edited by hand must not make --replace delete elsewhere.
    const std::string rel = relativeTo(dir.lexically_normal(), p);
    if (!rel.empty() && rel.rfind("..", 0) != 0) addIfFile(p, files);
  }
}

}  // namespace

Provenance Provenance::now() {
  const BuildInfo& b = buildInfo();
  return Provenance{b.version, b.commit, b.dirty, utcNow(), omp_get_max_threads()};
}

std::string Provenance::line() const {
  return "fluidviz " + BuildInfo{version, commit, modified}.describe() + ", " + date + ", " +
         std::to_string(threads) + (threads == 1 ? " thread" : " threads");
}

scene::json Provenance::toJson() const {
  return {{"version", version}, {"commit", commit}, {"modified", modified},
          {"date", date},       {"threads", threads}};
}

fs::path runRecordPath(const fs::path& dir, const std::string& name) {
  return dir / (name + "_run.json");
}

void writeRunRecord(const fs::path& dir, const std::string& name,
                    const scene::json& effectiveScene, RunRecord record) {
  const fs::path sceneCopy = dir / (name + "_scene.json");
  writeTextOutput(sceneCopy, sceneCopyText(record, effectiveScene));
  if (std::find(record.files.begin(), record.files.end(), sceneCopy) == record.files.end())
    record.files.push_back(sceneCopy);
  // Sorted and unique: a resumed run lists the same files as an uninterrupted one.
  std::set<std::string> names;
  for (const fs::path& f : record.files) names.insert(relativeTo(dir, f));
  const scene::json files(names);
  const scene::json j = {{"fluidviz", record.provenance.toJson()},
                         {"scene_file", record.sceneFile},
                         {"solver", lines(record.solverDescription)},
                         {"outcome", outcomeName(record.outcome)},
                         {"message", record.message},
                         {"steps", record.steps},
                         {"time", record.time},
                         {"files", files},
                         {"scene", effectiveScene}};
  writeTextOutput(runRecordPath(dir, name), j.dump(2) + "\n");
}

std::vector<fs::path> earlierRunFiles(const fs::path& dir, const std::string& name) {
  std::set<fs::path> files;
  addRecordedFiles(dir, name, files);
  for (const std::string& f : {name + ".pvd", name + "_scene.json", name + "_run.json",
                               name + ".checkpoint"})
    addIfFile(dir / f, files);
  std::error_code e;
  if (fs::is_directory(dir / name, e))
    for (const fs::directory_entry& entry : fs::directory_iterator(dir / name, e))
      addIfFile(entry.path(), files);
  return {files.begin(), files.end()};
}

void claimOutputFolder(const fs::path& dir, const std::string& name, bool replace) {
  const std::vector<fs::path> files = earlierRunFiles(dir, name);
  if (files.empty()) return;
  if (!replace) {
    std::string some;
    for (std::size_t i = 0; i < std::min<std::size_t>(files.size(), 3); ++i)
      some += (i ? ", " : "") + files[i].string();
    if (files.size() > 3) some += ", ...";
    throw FileError(dir, dir.string() + " holds an earlier run of scene '" + name + "' (" +
                             std::to_string(files.size()) + " files: " + some +
                             "); a new run would mix its files with them. Give --replace to "
                             "remove them first, or another output folder with -o");
  }
  for (const fs::path& f : files) {
    std::error_code e;
    if (!fs::remove(f, e) && e)
      throw FileError(f, "cannot remove " + f.string() + " of the earlier run: " + e.message());
  }
  std::error_code e;
  if (fs::is_directory(dir / name, e) && fs::is_empty(dir / name, e)) fs::remove(dir / name, e);
}

}  // namespace fluidviz
