#pragma once
// A ParaView .pvd collection: the index of a time series of snapshot files.
// The .pvd is rewritten atomically after every snapshot, and a snapshot is only accepted once its
// file exists, so a run that is killed leaves a .pvd listing exactly the complete snapshots.
//
//   PvdSeries series(out / "flow.pvd");          // writes an empty collection (fails fast)
//   writeVti(fields, out / "flow_0003.vti");       // the snapshot first ...
//   series.add(0.3, "flow_0003.vti");              // ... then the index
#include <filesystem>
#include <string>
#include <vector>

namespace fluidviz {

class PvdSeries {
 public:
  struct Entry {
    double time = 0.0;      ///< simulation time of the snapshot (scene units, s)
    std::string file;       ///< path relative to the .pvd's folder, '/' separated
  };

  /// Writes an empty collection to `pvdPath` (replacing an older one), so an unwritable folder is
  /// reported before a long run starts. Throws FileError naming the path and the OS reason.
  explicit PvdSeries(std::filesystem::path pvdPath);
  /// Continues a series (a resumed run): rewrites the .pvd with `entries` (their files exist).
  PvdSeries(std::filesystem::path pvdPath, std::vector<Entry> entries);

  /// Records a snapshot and rewrites the .pvd. `dataFile` is absolute or relative to the .pvd's
  /// folder and must exist. Throws std::invalid_argument if the time is not finite or not later
  /// than the previous one, FileError if the file is missing or the .pvd cannot be written.
  void add(double time, const std::filesystem::path& dataFile);

  const std::filesystem::path& path() const { return pvdPath_; }
  const std::vector<Entry>& entries() const { return entries_; }
  /// The .pvd document as written.
  std::string xml() const;

 private:
  std::string relativeToPvdFolder(const std::filesystem::path& dataFile) const;
  void rewrite() const;

  std::filesystem::path pvdPath_;
  std::vector<Entry> entries_;
};

}  // namespace fluidviz
