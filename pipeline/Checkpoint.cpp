#include "pipeline/Checkpoint.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include "fieldviz/core/AtomicFile.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "pipeline/StopSignals.h"
#include "fieldviz/scene/SceneFile.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[] = "fluidviz checkpoint\n";
constexpr std::size_t kMagicSize = sizeof(kMagic) - 1;
constexpr std::size_t kHeaderSize = kMagicSize + sizeof(std::uint32_t) + sizeof(std::uint64_t);
constexpr std::size_t kChecksumSize = sizeof(std::uint64_t);

// FNV-1a, 64 bit (Fowler, Noll, Vo; IETF draft-eastlake-fnv): detects truncation and bit rot.
struct Fnv1a64 {
  std::uint64_t hash = 14695981039346656037ull;
  void add(const void* data, std::size_t size) {
    const auto* p = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
  }
};

[[noreturn]] void corrupt(const fs::path& file, const std::string& why) {
  throw FileError(file, "checkpoint " + file.string() + " " + why +
                            "; start the run again without --resume");
}

std::vector<std::uint8_t> readWholeFile(const fs::path& file) {
  std::error_code error;
  if (!fs::exists(file, error))
    throw FileError(file, "no checkpoint " + file.string() + " (the run completed and removed it, "
                          "or never wrote one); start the run without --resume");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(file, "cannot read checkpoint " + file.string() + ": " +
                                     std::strerror(errno));
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void writeHeader(StateWriter& w, const CheckpointHeader& h) {
  w.putString(h.solver);
  w.putString(h.sceneJson);
  w.put<std::int64_t>(h.step);
  w.put<double>(h.time);
  w.put<std::uint64_t>(h.snapshots.size());
  for (const PvdSeries::Entry& e : h.snapshots) {
    w.put<double>(e.time);
    w.putString(e.file);
  }
}

CheckpointHeader readHeader(StateReader& r) {
  CheckpointHeader h;
  h.solver = r.getString();
  h.sceneJson = r.getString();
  h.step = r.get<std::int64_t>();
  h.time = r.get<double>();
  const auto n = r.get<std::uint64_t>();
  if (n > r.remaining() / 16) throw StateFormatError("the snapshot count " + std::to_string(n) +
                                                     " exceeds the file");
  for (std::uint64_t k = 0; k < n; ++k) {
    PvdSeries::Entry e;
    e.time = r.get<double>();
    e.file = r.getString();
    h.snapshots.push_back(std::move(e));
  }
  return h;
}

// "lbm.rollers.0.radius" from the JSON pointer "/lbm/rollers/0/radius".
std::string keyOfPointer(const std::string& pointer) {
  std::string key = pointer.substr(pointer.empty() ? 0 : 1);
  for (char& c : key)
    if (c == '/') c = '.';
  return key;
}

// The first key whose value differs, with both values; throws SceneError.
void requireSameSceneJson(const std::string& sceneFile, const fs::path& checkpoint,
                          const std::string& ours, const std::string& theirs) {
  if (ours == theirs) return;
  const scene::json now = scene::json::parse(ours).flatten();
  scene::json then;
  try {
    then = scene::json::parse(theirs).flatten();
  } catch (const scene::json::exception&) {
    corrupt(checkpoint, "holds an unreadable scene");
  }
  std::string key = "(scene)", here = "?", there = "?";
  for (auto it = now.begin(); it != now.end(); ++it)
    if (!then.contains(it.key()) || then[it.key()] != it.value()) {
      key = keyOfPointer(it.key());
      here = it.value().dump();
      there = then.contains(it.key()) ? then[it.key()].dump() : "(absent)";
      break;
    }
  if (key == "(scene)")
    for (auto it = then.begin(); it != then.end(); ++it)
      if (!now.contains(it.key())) {
        key = keyOfPointer(it.key());
        here = "(absent)";
        there = it.value().dump();
        break;
      }
  throw scene::SceneError(sceneFile, key,
                          "is " + here + " here but " + there + " in the checkpoint " +
                              checkpoint.string() +
                              "; a resumed run needs the scene it started with (only "
                              "description, checkpoint.*, output.images, output.lic and "
                              "output.streamlines may change): give the same scene and --set "
                              "options, or start the run again without --resume");
}

// Removes temporary files (core/AtomicFile.h naming) whose writer process no longer runs.
void removeStaleTemporaryFiles(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) return;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    const long pid = temporaryFileWriter(entry.path());
    if (pid <= 0 || pid == static_cast<long>(getpid())) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // still running
    fs::remove(entry.path(), error);
  }
}

// Snapshot number NNNN of "<name>_NNNN.<ext>", or -1.
long snapshotNumber(const fs::path& file, const std::string& name) {
  const std::string stem = file.stem().string(), prefix = name + "_";
  if (stem.size() <= prefix.size() || stem.compare(0, prefix.size(), prefix) != 0) return -1;
  const std::string digits = stem.substr(prefix.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return -1;
  return std::stol(digits);
}


}  // namespace

fs::path checkpointPath(const fs::path& dir, const std::string& name) {
  return dir / (name + ".checkpoint");
}

std::string checkpointSceneJson(const SceneParams& scene) {
  scene::json j = scene::writeParams(scene);
  j.erase("description");
  j.erase("checkpoint");
  j.erase(scene.solver == SolverKind::sph ? "lbm" : "sph");
  for (const char* finalOnly : {"images", "lic", "streamlines"}) j["output"].erase(finalOnly);
  return j.dump();
}

void writeCheckpoint(const fs::path& file, const CheckpointHeader& header,
                     const std::function<void(StateWriter&)>& writeState) {
  StateWriter payload;
  writeHeader(payload, header);
  writeState(payload);
  StateWriter head;
  head.putBytes(kMagic, kMagicSize);
  head.put<std::uint32_t>(kCheckpointFormatVersion);
  head.put<std::uint64_t>(payload.bytes().size());
  Fnv1a64 sum;
  sum.add(head.bytes().data(), head.bytes().size());
  sum.add(payload.bytes().data(), payload.bytes().size());
  writeOutputAtomically(file, [&](const fs::path& tmp) {
    std::FILE* out = std::fopen(tmp.c_str(), "wb");
    if (!out) throw std::runtime_error(std::strerror(errno));
    const bool ok =
        std::fwrite(head.bytes().data(), 1, head.bytes().size(), out) == head.bytes().size() &&
        std::fwrite(payload.bytes().data(), 1, payload.bytes().size(), out) ==
            payload.bytes().size() &&
        std::fwrite(&sum.hash, 1, kChecksumSize, out) == kChecksumSize;
    const int error = errno;
    if (std::fclose(out) != 0 || !ok) throw std::runtime_error(std::strerror(ok ? errno : error));
  });
}

LoadedCheckpoint readCheckpoint(const fs::path& file) {
  std::vector<std::uint8_t> bytes = readWholeFile(file);
  if (bytes.size() < kMagicSize || std::memcmp(bytes.data(), kMagic, kMagicSize) != 0)
    corrupt(file, "is not a fluidviz checkpoint (it does not start with \"fluidviz checkpoint\")");
  if (bytes.size() < kHeaderSize + kChecksumSize)
    corrupt(file, "is truncated: " + std::to_string(bytes.size()) + " bytes");
  std::uint32_t version = 0;
  std::uint64_t payloadSize = 0;
  std::memcpy(&version, bytes.data() + kMagicSize, sizeof version);
  std::memcpy(&payloadSize, bytes.data() + kMagicSize + sizeof version, sizeof payloadSize);
  if (version != kCheckpointFormatVersion)
    corrupt(file, "has format version " + std::to_string(version) + "; this fluidviz reads " +
                      "version " + std::to_string(kCheckpointFormatVersion));
  const std::uint64_t expected = kHeaderSize + payloadSize + kChecksumSize;
  if (bytes.size() != expected)
    corrupt(file, "is truncated or padded: " + std::to_string(bytes.size()) + " bytes, its " +
                      "header announces " + std::to_string(expected));
  Fnv1a64 sum;
  sum.add(bytes.data(), bytes.size() - kChecksumSize);
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - kChecksumSize, kChecksumSize);
  if (stored != sum.hash) corrupt(file, "is corrupt: its checksum does not match its contents");
  bytes.resize(bytes.size() - kChecksumSize);
  LoadedCheckpoint loaded{{}, StateReader(std::move(bytes), kHeaderSize)};
  try {
    loaded.header = readHeader(loaded.state);
  } catch (const StateFormatError& e) {
    corrupt(file, std::string("is malformed: ") + e.what());
  }
  if (loaded.header.solver != "lbm" && loaded.header.solver != "sph")
    corrupt(file, "names an unknown solver \"" + loaded.header.solver + "\"");
  return loaded;
}

void removeLaterSnapshots(const fs::path& folder, const std::string& name, std::size_t kept) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) return;
  std::vector<fs::path> later;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    if (snapshotNumber(entry.path(), name) > static_cast<long>(kept)) later.push_back(entry.path());
  for (const fs::path& p : later) fs::remove(p, error);
}

LoadedCheckpoint openCheckpointForResume(const SceneParams& scene, const RunOptions& options) {
  const fs::path file = checkpointPath(options.outputDir, scene.name);
  LoadedCheckpoint loaded = readCheckpoint(file);
  requireSameSceneJson(options.sceneFile, file, checkpointSceneJson(scene),
                       loaded.header.sceneJson);
  for (const PvdSeries::Entry& e : loaded.header.snapshots)
    if (!fs::exists(options.outputDir / e.file))
      throw FileError(options.outputDir / e.file,
                      "checkpoint " + file.string() + " lists snapshot " +
                          (options.outputDir / e.file).string() +
                          ", which is missing; start the run again without --resume");
  removeLaterSnapshots(options.outputDir / scene.name, scene.name, loaded.header.snapshots.size());
  removeStaleTemporaryFiles(options.outputDir);
  removeStaleTemporaryFiles(options.outputDir / scene.name);
  return loaded;
}

void prepareFreshOutput(const SceneParams& scene, const RunOptions& options) {
  std::error_code error;
  fs::remove(checkpointPath(options.outputDir, scene.name), error);
  removeStaleTemporaryFiles(options.outputDir);
  removeStaleTemporaryFiles(options.outputDir / scene.name);
}

RunCheckpointer::RunCheckpointer(const SceneParams& scene, const RunOptions& options)
    : path_(checkpointPath(options.outputDir, scene.name)),
      interval_(scene.checkpoint.interval),
      atSnapshots_(scene.checkpoint.at_snapshots),
      keep_(scene.checkpoint.keep),
      stopAtStep_(options.stopAtStep),
      last_(std::chrono::steady_clock::now()) {}

bool RunCheckpointer::intervalDue() const {
  const std::chrono::duration<double> since = std::chrono::steady_clock::now() - last_;
  return interval_ > 0 && since.count() >= interval_;
}

int RunCheckpointer::stopSignal(long long step) const {
  if (const int signal = pendingStopSignal()) return signal;
  return stopAtStep_ >= 0 && step >= stopAtStep_ ? SIGTERM : 0;
}

void RunCheckpointer::write(const CheckpointHeader& header,
                            const std::function<void(StateWriter&)>& state) {
  writeCheckpoint(path_, header, state);
  last_ = std::chrono::steady_clock::now();
}

void RunCheckpointer::stop(int signal, const CheckpointHeader& header,
                           const std::function<void(StateWriter&)>& state) {
  write(header, state);
  throw RunInterrupted(signal, path_, header.time, header.step);
}

void RunCheckpointer::finish() const {
  if (keep_) return;
  std::error_code error;
  fs::remove(path_, error);
}

}  // namespace fluidviz
