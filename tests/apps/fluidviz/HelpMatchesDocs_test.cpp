// `fluidviz lic --help` and docs/scenes.md come from the same describe() declarations: for every
// key of output.lic whose option the lic command has, the help line shows the description, unit,
// default and allowed range of the committed docs/scenes.md row. A description edited in one
// place only (a hand-written help text, or docs/scenes.md not regenerated) fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/fluidviz/KeyOptions.h"
#include "fieldviz/core/LengthUnit.h"
#include "fieldviz/io/ImageSampling.h"
#include "pipeline/SceneDocs.h"
#include "pipeline/SceneParams.h"
#include "tests/apps/fluidviz/CliTestSupport.h"

namespace {

using fluidviz::scene::DocRow;

std::string committedDocs() {
  std::ifstream in(std::string(FLUIDVIZ_SOURCE_DIR) + "/docs/scenes.md");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The cells of a Markdown table row "| a | b |", with "\|" read back as '|'.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += '|', ++i;
    } else if (line[i] == '|') {
      const std::size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      out.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  return out;
}

// The docs/scenes.md row of key `key` ("output.lic[].length").
DocRow docsRow(const std::string& docs, const std::string& key) {
  std::istringstream s(docs);
  for (std::string line; std::getline(s, line);) {
    const std::vector<std::string> c = cells(line);
    if (c.size() == 6 && c[0] == "`" + key + "`") return {key, c[1], c[2], c[3], c[4], c[5]};
  }
  return {};
}

// The help of option `flag`: the line that starts with it (after the indent), and the next line
// when CLI11 put the description there (a long option name).
std::string helpLine(const std::string& help, const std::string& flag) {
  std::istringstream s(help);
  std::string found;
  for (std::string line; std::getline(s, line);) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos) continue;
    if (!found.empty()) return start > 10 && line[start] != '-' ? found + " " + line : found;
    const std::string rest = line.substr(start);
    if (rest.rfind(flag + " ", 0) == 0 || rest == flag) found = line;
  }
  return found;
}

}  // namespace

TEST(HelpMatchesDocs, EveryLicKeyOptionShowsItsDocsRow) {
  const std::string docs = committedDocs();
  ASSERT_EQ(docs, fluidviz::sceneDocsMarkdown())
      << "docs/scenes.md is out of date: run `fluidviz docs > docs/scenes.md`";
  const fluidviz::test::Result r = fluidviz::test::run({"lic", "--help"});
  ASSERT_EQ(r.code, 0) << r.err;

  std::vector<DocRow> declared;
  fluidviz::scene::documentParams<fluidviz::LicOutput>(declared, "");
  int compared = 0;
  for (const DocRow& d : declared) {
    const std::string flag = fluidviz::app::optionFlag(d);
    const std::string line = helpLine(r.out, flag);
    if (line.empty()) continue;  // a key without an option of its own (set by --resolution etc.)
    // A scene's title is a template with {time} etc. (pipeline/PictureText.h); the command's
    // --title is plain text, by default what the picture shows of the file it read.
    if (d.key == "title") continue;
    const DocRow row = docsRow(docs, "output.lic[]." + d.key);
    ASSERT_FALSE(row.key.empty()) << "docs/scenes.md has no row output.lic[]." << d.key;
    EXPECT_NE(line.find(row.description), std::string::npos)
        << flag << ": help shows\n"
        << line << "\nbut docs/scenes.md says\n"
        << row.description;
    if (!row.unit.empty())
      EXPECT_NE(line.find("(" + row.unit + ")"), std::string::npos) << flag << ": " << line;
    const std::string plainDefault = row.defaultValue.substr(1, row.defaultValue.size() - 2);
    EXPECT_NE(
        line.find("default " + (row.defaultValue == "(none)" ? row.defaultValue : plainDefault)),
        std::string::npos)
        << flag << ": " << line << " (docs default " << row.defaultValue << ")";
    if (row.allowed != "any")
      EXPECT_NE(line.find("allowed " + row.allowed), std::string::npos)
          << flag << ": " << line << " (docs allowed " << row.allowed << ")";
    ++compared;
  }
  // length, method, kernel, step, seed, grain, vectors, enhance, no-contrast, contrast-sigmas,
  // mask-speed, color-by, weight, colormap, background, axes.
  EXPECT_EQ(compared, 16) << r.out;
}

// `fluidviz resample --order` is declared once (ParticleResampleParams::describe, key order): its
// help line shows the docs/scenes.md row of the scene key output.grids[].order.
TEST(HelpMatchesDocs, ResampleOrderOptionShowsItsDocsRow) {
  const DocRow row = docsRow(committedDocs(), "output.grids[].order");
  ASSERT_FALSE(row.key.empty()) << "docs/scenes.md has no row output.grids[].order";
  const fluidviz::test::Result r = fluidviz::test::run({"resample", "--help"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string line = helpLine(r.out, "--order");
  EXPECT_NE(line.find(row.description), std::string::npos) << line << "\nvs\n" << row.description;
  EXPECT_NE(line.find("default " + row.defaultValue.substr(1, row.defaultValue.size() - 2)),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("allowed " + row.allowed), std::string::npos) << line;
}

TEST(HelpMatchesDocs, FlagsKeepTheirShortNamesAndTheirMessages) {
  const fluidviz::test::Result r = fluidviz::test::run({"lic", "--help"});
  for (const char* flag :
       {"--seed", "--grain", "--weight", "--no-contrast", "--enhance", "--length", "--mask-speed",
        "-a,", "-o,", "--slice", "--resolution", "--range", "--vti"})
    EXPECT_NE(r.out.find(flag), std::string::npos) << flag << " missing from\n" << r.out;
}

// An option declared once by a parameter struct P: `docs` (under docs/) holds its generated
// table, and the help line of `flag` in every grid command shows its description and `wording`
// (its default or range). The rows are returned for further checks.
template <class P>
void expectOptionShowsItsDocsRow(const char* docs, const char* flag,
                                 const std::string& wording) {
  std::vector<DocRow> rows;
  fluidviz::scene::documentParams<P>(rows, "");
  ASSERT_EQ(rows.size(), 1u);
  std::ifstream in(std::string(FLUIDVIZ_SOURCE_DIR) + "/docs/" + docs);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find(fluidviz::scene::markdownTable(rows)), std::string::npos)
      << "docs/" << docs << " lacks the generated table:\n"
      << fluidviz::scene::markdownTable(rows);
  for (const char* command : {"lic", "streamlines", "topology", "isosurface"}) {
    const fluidviz::test::Result r = fluidviz::test::run({command, "--help"});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string line = helpLine(r.out, flag);
    EXPECT_NE(line.find(rows[0].description), std::string::npos) << command << ": " << line;
    EXPECT_NE(line.find(wording), std::string::npos) << command << ": " << line;
  }
}

// --units is declared once (LengthUnitParams): docs/units.md holds its generated table, and the
// help of every command that has the option shows the same description and default.
TEST(HelpMatchesDocs, UnitsOptionShowsItsDocsRowInEveryCommand) {
  expectOptionShowsItsDocsRow<fluidviz::LengthUnitParams>(
      "units.md", "--units", "default \"" + fluidviz::LengthUnitParams{}.units + "\"");
}

// --spacing is declared once (ImageSampling): docs/input_formats.md holds its generated table,
// and the help of every grid command shows the same description and range.
TEST(HelpMatchesDocs, SpacingOptionShowsItsDocsRowInEveryCommand) {
  expectOptionShowsItsDocsRow<fluidviz::ImageSampling>("input_formats.md", "--spacing",
                                                       "allowed > 0");
}

