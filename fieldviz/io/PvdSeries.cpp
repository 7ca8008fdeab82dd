#include "fieldviz/io/PvdSeries.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "fieldviz/core/Params.h"
#include "fieldviz/core/XmlText.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"

namespace fluidviz {

namespace {

// Shortest text that reads back as the same double. Times are written without the round-off of
// their accumulation (withoutRoundOff): ParaView shows 5, not 5.000000000000001.
std::string exactText(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

PvdSeries::PvdSeries(std::filesystem::path pvdPath) : pvdPath_(std::move(pvdPath)) { rewrite(); }

PvdSeries::PvdSeries(std::filesystem::path pvdPath, std::vector<Entry> entries)
    : pvdPath_(std::move(pvdPath)), entries_(std::move(entries)) {
  rewrite();
}

void PvdSeries::add(double time, const std::filesystem::path& dataFile) {
  if (!std::isfinite(time))
    throw std::invalid_argument("series " + pvdPath_.string() + ": snapshot time is not finite");
  if (!entries_.empty() && !(time > entries_.back().time))
    throw std::invalid_argument("series " + pvdPath_.string() + ": snapshot time " +
                                exactText(time) + " is not later than the previous one (" +
                                exactText(entries_.back().time) + ")");
  const std::string relative = relativeToPvdFolder(dataFile);
  if (!std::filesystem::exists(folderOf(pvdPath_) / relative))
    throw FileError(dataFile, "series " + pvdPath_.string() + ": snapshot file " +
                                  (folderOf(pvdPath_) / relative).string() +
                                  " does not exist; write the snapshot before adding it");
  entries_.push_back({time, relative});
  try {
    rewrite();
  } catch (...) {
    entries_.pop_back();  // keep entries() equal to what the .pvd on disk lists
    throw;
  }
}

std::string PvdSeries::xml() const {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_)
    text += "    <DataSet timestep=\"" + exactText(withoutRoundOff(e.time)) + "\" group=\"\" part=\"0\" file=\"" +
            xmlEscaped(e.file) + "\"/>\n";
  text += "  </Collection>\n</VTKFile>\n";
  return text;
}

std::string PvdSeries::relativeToPvdFolder(const std::filesystem::path& dataFile) const {
  if (dataFile.is_relative()) return dataFile.lexically_normal().generic_string();
  const std::filesystem::path folder = std::filesystem::absolute(folderOf(pvdPath_));
  return dataFile.lexically_normal().lexically_relative(folder.lexically_normal()).generic_string();
}

void PvdSeries::rewrite() const { writeTextOutput(pvdPath_, xml()); }

}  // namespace fluidviz
