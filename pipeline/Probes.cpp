#include "pipeline/Probes.h"

#include <ostream>

#include "fieldviz/io/CsvTable.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/OutputPath.h"
#include "fieldviz/render/LinePlot.h"
#include "pipeline/PictureText.h"
#include "pipeline/SceneValidation.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

Vec3 toVec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

probe::ProbeLine lineOf(const ProbeOutput& p) {
  return {toVec(p.start), toVec(p.end), p.samples};
}

fs::path referencePath(const ProbeOutput& p, const fs::path& sceneFile) {
  const fs::path ref(p.reference);
  return ref.is_absolute() ? ref : sceneFile.parent_path() / ref;
}

// One unit table for pictures, probes and plots (PictureText.h).
std::string unitOf(ProbeField f) { return fieldUnits(choiceName(f)); }

ScalarField probedField(const FieldSet& fields, ProbeField f) {
  const std::string name = choiceName(f);
  if (const ScalarField* s = fields.findScalar(name)) return *s;
  const VectorField& velocity = *fields.findVector("velocity");
  const int component = f == ProbeField::velocity_x ? 0 : (f == ProbeField::velocity_y ? 1 : 2);
  ScalarField s{name, velocity.grid, std::vector<double>(velocity.values.size())};
  for (std::size_t n = 0; n < s.values.size(); ++n) s.values[n] = velocity.values[n][component];
  return s;
}

void validateProbe(const ProbeOutput& p, const std::string& sceneFile) {
  if (p.name.empty() ||
      p.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") !=
          std::string::npos)
    throw ParamError("name", "is \"" + p.name + "\"; allowed: letters, digits, '_' and '-' (it "
                             "names the probe's files)");
  if (!(lineOf(p).length() > 0.0)) throw ParamError("end", "equals start; give a line");
  if (p.reference.empty()) return;
  if (p.reference_position.empty() || p.reference_value.empty())
    throw ParamError(p.reference_position.empty() ? "reference_position" : "reference_value",
                     "is empty; name the reference's column (a reference is given)");
  try {
    readProbeReference(p, sceneFile);
  } catch (const FileError& e) {
    throw ParamError("reference", e.what());
  }
}

// The profile, the line and the deviation as a CSV table.
CsvTable profileTable(const SceneParams& scene, const ProbeOutput& p,
                      const std::vector<probe::ProfilePoint>& profile,
                      const probe::ProfileDeviation* deviation) {
  CsvTable t;
  const probe::ProbeLine line = lineOf(p);
  t.comments.push_back("scene " + scene.name + ", probe " + p.name + ": " + choiceName(p.field) +
                       " along the line from (" + formatShortest(p.start[0]) + ", " +
                       formatShortest(p.start[1]) + ", " + formatShortest(p.start[2]) + ") to (" +
                       formatShortest(p.end[0]) + ", " + formatShortest(p.end[1]) + ", " +
                       formatShortest(p.end[2]) + ") m, " + std::to_string(line.samples) +
                       " samples; nan: outside the grid");
  if (deviation)
    t.comments.push_back("deviation from " + p.reference + " (" + p.reference_value + " x " +
                         formatShortest(p.reference_scale) + "): max " +
                         formatNumber(deviation->max, 3) + ", rms " +
                         formatNumber(deviation->rms, 3) + " " + unitOf(p.field) + " over " +
                         std::to_string(deviation->compared) + " points inside the grid");
  t.names = {"distance (m)", "x (m)", "y (m)", "z (m)",
             choiceName(p.field) + " (" + unitOf(p.field) + ")"};
  t.columns.resize(5);
  for (const probe::ProfilePoint& q : profile) {
    t.columns[0].push_back(q.distance);
    for (int a = 0; a < 3; ++a) t.columns[1 + a].push_back(q.position[a]);
    t.columns[4].push_back(q.value);
  }
  return t;
}

RgbaImage profilePlot(const SceneParams& scene, const ProbeOutput& p, const std::string& key,
                      double time, const std::vector<probe::ProfilePoint>& profile,
                      const std::vector<probe::ReferencePoint>& reference) {
  PlotSeries sim{"simulation", {}, {}, PlotMarks::line};
  for (const probe::ProfilePoint& q : profile) {
    sim.x.push_back(q.distance);
    sim.y.push_back(q.value);
  }
  std::vector<PlotSeries> series{sim};
  if (!reference.empty()) {
    PlotSeries ref{p.reference_label, {}, {}, PlotMarks::markers};
    for (const probe::ReferencePoint& r : reference) {
      ref.x.push_back(r.distance);
      ref.y.push_back(r.value);
    }
    series.push_back(ref);
  }
  LinePlotParams params;
  params.title = p.title.empty() ? scene.name + ": " + choiceName(p.field) + " along " + p.name
                                 : pictureTitle(scene, key, p.title, {choiceName(p.field), time});
  params.x_label = "distance along " + p.name + " (m)";
  params.y_label = choiceName(p.field) + " (" + unitOf(p.field) + ")";
  return renderLinePlot(series, params);
}

}  // namespace

void validateProbes(const SceneParams& scene, const std::string& sceneFile) {
  const auto& probes = scene.output.probes;
  if (!probes.empty() && scene.solver != SolverKind::lbm)
    throw ParamError("output.probes", "is given for solver " + choiceName(scene.solver) +
                                          "; line probes sample a grid (solver lbm only)");
  std::vector<std::string> taken;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const std::string key = "output.probes[" + std::to_string(i) + "]";
    withKeyPrefix(key + ".", [&] { validateProbe(probes[i], sceneFile); });
    requireOutputFileName(key + ".name", scene.name + "_" + probes[i].name + ".csv", ".csv", taken);
  }
}

std::vector<probe::ReferencePoint> readProbeReference(const ProbeOutput& p,
                                                      const fs::path& sceneFile) {
  const fs::path file = referencePath(p, sceneFile);
  const CsvTable table = readCsv(file);
  const std::vector<double>& s = table.column(p.reference_position, file);
  const std::vector<double>& v = table.column(p.reference_value, file);
  std::vector<probe::ReferencePoint> points;
  for (std::size_t r = 0; r < s.size(); ++r) points.push_back({s[r], p.reference_scale * v[r]});
  return points;
}

void writeProbes(const SceneParams& scene, const FieldSet& fields, double time,
                 const fs::path& sceneFile, const fs::path& dir, std::ostream& log,
                 std::vector<fs::path>& written) {
  for (std::size_t i = 0; i < scene.output.probes.size(); ++i) {
    const ProbeOutput& p = scene.output.probes[i];
    const ScalarField field = probedField(fields, p.field);
    const std::vector<probe::ProfilePoint> profile = probe::sampleLine(field, lineOf(p));
    std::vector<probe::ReferencePoint> reference;
    probe::ProfileDeviation deviation;
    if (!p.reference.empty()) {
      reference = readProbeReference(p, sceneFile);
      deviation = probe::compareWithReference(field, lineOf(p), reference);
      log << scene.name << ": probe " << p.name << ": " << choiceName(p.field)
          << " deviates from " << p.reference << " by max " << formatNumber(deviation.max, 3)
          << ", rms " << formatNumber(deviation.rms, 3) << " " << unitOf(p.field) << " ("
          << deviation.compared << " points)\n";
    }
    const std::string stem = scene.name + "_" + p.name;
    writeTextOutput(dir / (stem + ".csv"),
                    formatCsv(profileTable(scene, p, profile,
                                           p.reference.empty() ? nullptr : &deviation)));
    written.push_back(dir / (stem + ".csv"));
    writePicture(profilePlot(scene, p, "output.probes[" + std::to_string(i) + "].title", time,
                             profile, reference), dir / (stem + ".png"));
    written.push_back(dir / (stem + ".png"));
  }
}

}  // namespace fluidviz
