// libFuzzer target: CSV bytes -> readCsv (the reference tables of output.probes and
// output.time_series, `fluidviz plot`'s input) and the column look-ups the callers make, then
// formatCsv of what was read.
#include "fieldviz/io/CsvTable.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace fluidviz;
  const std::filesystem::path file = fuzz::writeInputFile(data, size, ".csv");
  fuzz::expectOnlyBadInputErrors([&] {
    const CsvTable table = readCsv(file);
    for (const std::string& name : table.names) table.column(name, file);
    table.column("T", file);  // FileError naming the columns unless there is one
    formatCsv(table);
  });
  return 0;
}
