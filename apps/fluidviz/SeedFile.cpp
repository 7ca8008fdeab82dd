#include "apps/fluidviz/SeedFile.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "apps/fluidviz/Commands.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/VtkXmlReaders.h"
#include "filters/streamlines/vtk/StreamlinePolyData.h"

namespace fluidviz::app {

namespace {

// "x,y,z" -> the point; false for anything else (a count other than 3, a non-finite number).
bool parseRow(const std::string& row, Vec3& p) {
  std::stringstream s(row);
  std::string cell;
  int n = 0;
  while (std::getline(s, cell, ',')) {
    if (n == 3) return false;
    try {
      std::size_t used = 0;
      p[n] = std::stod(cell, &used);
      if (cell.find_first_not_of(" \t\r", used) != std::string::npos) return false;
    } catch (const std::exception&) {
      return false;
    }
    if (!std::isfinite(p[n++])) return false;
  }
  return n == 3;
}

bool blank(const std::string& row) { return row.find_first_not_of(" \t\r") == std::string::npos; }

std::vector<Vec3> readCsvSeeds(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw FileError(file, "file " + file.string() + ": cannot open the seeds file");
  std::vector<Vec3> seeds;
  std::string row;
  for (int line = 1; std::getline(in, row); ++line) {
    if (blank(row)) continue;
    Vec3 p;
    if (parseRow(row, p)) {
      seeds.push_back(p);
    } else if (line > 1 || row.find_first_of("0123456789") != std::string::npos) {
      // Only a first row without digits is taken for a header ("x,y,z").
      throw FileError(file, "file " + file.string() + ", line " + std::to_string(line) +
                                ": expected x,y,z (three finite numbers), got '" + row + "'");
    }
  }
  if (seeds.empty()) throw FileError(file, "file " + file.string() + ": has no seed rows x,y,z");
  return seeds;
}

}  // namespace

std::vector<Vec3> readSeedFile(const std::filesystem::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".csv") return readCsvSeeds(file);
  if (ext != ".vtp")
    throw UsageError("--seeds file:" + file.string() + " must be a .csv (x,y,z rows) or a .vtp");
  std::vector<Vec3> seeds = streamlines::seedsFromDataSet(readVtp(file));
  if (seeds.empty()) throw FileError(file, "file " + file.string() + ": has no points");
  return seeds;
}

}  // namespace fluidviz::app
