#include "pipeline/SphGridOutputs.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <ostream>

#include "fieldviz/core/ParamRanges.h"
#include "fieldviz/io/FileError.h"
#include "fieldviz/io/PvdSeries.h"
#include "fieldviz/io/VtkXmlWriters.h"
#include "pipeline/PictureText.h"
#include "pipeline/Checkpoint.h"
#include "pipeline/SceneValidation.h"
#include "pipeline/SphDerivedArrays.h"
#include "filters/resample/ParticleResampler.h"
#include "filters/resample/vtk/ParticleSetVtk.h"
#include "fieldviz/scene/ParamVisitors.h"
#include "filters/isosurface/vtk/Isosurface.h"
#include "solvers/sph/SphSolver.h"

namespace fluidviz {

namespace fs = std::filesystem;

namespace {

// --- names ------------------------------------------------------------------------------------

// "<name>_grid", "<name>_grid2", ... : the default stem of entry i of a list.
std::string defaultStem(const SceneParams& scene, const std::string& what, std::size_t i) {
  return scene.name + "_" + what + (i == 0 ? "" : std::to_string(i + 1));
}

std::string gridFile(const SceneParams& s, std::size_t i) {
  const std::string& f = s.output.grids[i].file;
  return f.empty() ? defaultStem(s, "grid", i) + ".vti" : f;
}
std::string surfaceFile(const SceneParams& s, std::size_t i) {
  const std::string& f = s.output.free_surface[i].file;
  return f.empty() ? defaultStem(s, "free_surface", i) + ".vtp" : f;
}
std::string stemOf(const std::string& file) { return fs::path(file).stem().string(); }

// "<stem>/<stem>_0003.vti": the file of snapshot `index` of a series.
fs::path seriesFile(const std::string& file, int index) {
  char number[16];
  std::snprintf(number, sizeof number, "_%04d", index);
  const std::string stem = stemOf(file);
  return fs::path(stem) / (stem + number + fs::path(file).extension().string());
}

bool showsSurface(const ViewOutput& v) { return v.show != ViewShow::particles; }
bool showsParticles(const ViewOutput& v) { return v.show != ViewShow::surface; }

// --- checks -----------------------------------------------------------------------------------

void rejectForOtherSolvers(const SceneParams& scene) {
  const std::pair<const char*, bool> lists[] = {{"output.grids", !scene.output.grids.empty()},
                                                {"output.free_surface",
                                                 !scene.output.free_surface.empty()},
                                                {"output.views", !scene.output.views.empty()}};
  for (const auto& [key, listed] : lists)
    if (listed)
      throw ParamError(key, "is only available for solver sph (it resamples particles); the "
                            "scene's solver is " + choiceName(scene.solver) + ": remove " + key);
}

// --- computing --------------------------------------------------------------------------------

// The SPH domain box: every grid of the run covers it (plus the padding).
resample::Bounds domainBounds(const sph::SphParams& p) {
  resample::Bounds b;
  for (int a = 0; a < 3; ++a) {
    b.lower[a] = p.domain_lower[a];
    b.upper[a] = p.dimension == 2 && a == 2 ? p.domain_lower[a] : p.domain_upper[a];
  }
  return b;
}

std::array<double, 6> boxOf(const resample::Bounds& b) {
  return {b.lower.x(), b.upper.x(), b.lower.y(), b.upper.y(), b.lower.z(), b.upper.z()};
}

// The fluid particles with "speed" (withDerived) and "mass" (the solver's particle mass), so
// that the resampler takes V_j = m_j / rho_j.
particles::ParticleSet resamplingParticles(const sph::SphSolver& solver) {
  particles::ParticleSet s = withDerived(solver.fluid());
  s.scalars.push_back({"mass", std::vector<double>(s.size(), solver.particleMass())});
  return s;
}

resample::ParticleResampleParams resamplerParams(const SphResampleParams& g,
                                                 const sph::SphParams& p) {
  resample::ParticleResampleParams r = g;
  r.dimension = p.dimension;
  r.mass_array = "mass";
  r.density_array = "density";
  r.particle_spacing = p.particle_spacing;  // the lattice spacing: default h = 1.3 dx, grid dx
  return r;
}

// The free surface's iso value: `level`, or half the bulk value of the field.
double surfaceLevel(const FreeSurfaceParams& f, const sph::SphParams& p) {
  if (f.level) return *f.level;
  return f.field == SurfaceField::color ? 0.5 : 0.5 * p.rest_density;
}

isosurface::IsosurfaceParams contourParams(const FreeSurfaceParams& f, const sph::SphParams& p) {
  isosurface::IsosurfaceParams iso = f;
  iso.array = choiceName(f.field);
  iso.value = surfaceLevel(f, p);
  return iso;
}

// Arrays a picture may colour particles by / a surface by.
std::vector<std::string> particleArrays(const particles::ParticleSet& s) {
  std::vector<std::string> names;
  for (const auto& a : s.scalars) names.push_back(a.name);
  for (const auto& a : s.vectors) names.push_back(a.name);
  return names;
}

std::vector<std::string> surfaceArrays(const FreeSurfaceParams& f) {
  std::vector<std::string> names = resample::splitArrayList(f.grid.arrays);
  for (const char* n : {resample::kColorArray, resample::kMaskArray,
                        resample::kSummationDensityArray})
    names.push_back(n);
  return names;
}

void requireOneOf(const std::string& key, const std::string& name,
                  const std::vector<std::string>& allowed, const std::string& what) {
  if (name.empty() || std::find(allowed.begin(), allowed.end(), name) != allowed.end()) return;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw ParamError(key, "is \"" + name + "\", which " + what + " do not have; allowed one of {" +
                            list + "} or empty");
}

ParticleStyle particleStyleOf(const ViewOutput& v, const sph::SphParams& p) {
  ParticleStyle style = v.particles;
  style.radius = v.particles.sphere_radius.value_or(0.5 * p.particle_spacing);
  return style;
}

}  // namespace

std::string viewFile(const SceneParams& s, std::size_t i) {
  const std::string& f = s.output.views[i].file;
  return f.empty() ? defaultStem(s, "view", i) + ".png" : f;
}

// --- validation -------------------------------------------------------------------------------

void validateSphGridOutputs(const SceneParams& scene) {
  if (scene.solver != SolverKind::sph) return rejectForOtherSolvers(scene);
  std::vector<std::string> taken = imageFileNames(scene);
  const auto& out = scene.output;
  for (std::size_t i = 0; i < out.grids.size(); ++i)
    requireOutputFileName("output.grids[" + std::to_string(i) + "].file", gridFile(scene, i), ".vti",
                  taken);
  for (std::size_t i = 0; i < out.free_surface.size(); ++i) {
    const std::string key = "output.free_surface[" + std::to_string(i) + "]";
    requireOutputFileName(key + ".file", surfaceFile(scene, i), ".vtp", taken);
    withKeyPrefix(key + ".", [&] { params::checkRanges(contourParams(out.free_surface[i],
                                                                  scene.sph)); });
  }
  for (std::size_t i = 0; i < out.views.size(); ++i) {
    const std::string key = "output.views[" + std::to_string(i) + "]";
    requireOutputFileName(key + ".file", viewFile(scene, i), ".png", taken);
    withKeyPrefix(key + ".", [&] { validateView3DParams(out.views[i]); });
    withKeyPrefix(key + ".surface.", [&] { params::checkRanges(out.views[i].surface); });
    withKeyPrefix(key + ".particles.", [&] {
      params::checkRanges(particleStyleOf(out.views[i], scene.sph));
    });
  }
}

void checkSphGridOutputs(const SceneParams& scene, const sph::SphSolver& solver) {
  const auto& out = scene.output;
  if (out.grids.empty() && out.free_surface.empty() && out.views.empty()) return;
  const particles::ParticleSet particles = resamplingParticles(solver);
  const resample::Bounds box = domainBounds(scene.sph);
  // planResampling makes every choice and check of a run (arrays, grid memory) without the sums.
  auto plan = [&](const std::string& key, const SphResampleParams& g) {
    withKeyPrefix(key, [&] {
      try {
        resample::planResampling(particles, resamplerParams(g, scene.sph), &box);
      } catch (const std::invalid_argument& e) {
        throw ParamError("", e.what());
      }
    });
  };
  for (std::size_t i = 0; i < out.grids.size(); ++i)
    plan("output.grids[" + std::to_string(i) + "].", out.grids[i]);
  for (std::size_t i = 0; i < out.free_surface.size(); ++i)
    plan("output.free_surface[" + std::to_string(i) + "].grid.", out.free_surface[i].grid);
  for (std::size_t i = 0; i < out.views.size(); ++i) {
    const ViewOutput& v = out.views[i];
    const std::string key = "output.views[" + std::to_string(i) + "].";
    if (showsSurface(v)) {
      plan(key + "free_surface.grid.", v.free_surface.grid);
      requireOneOf(key + "surface.color_by", v.surface.color_by, surfaceArrays(v.free_surface),
                   "the surface (free_surface.grid.arrays and the resampler's)");
    }
    if (showsParticles(v))
      requireOneOf(key + "particles.color_by", v.particles.color_by, particleArrays(particles),
                   "the particles");
  }
}

// --- running ----------------------------------------------------------------------------------

struct SphGridOutputs::Impl {
  const SceneParams& scene;
  fs::path dir;
  std::ostream& log;
  resample::Bounds box;
  // .pvd series of the every_snapshot outputs, by file name of the final state.
  std::map<std::string, std::unique_ptr<PvdSeries>> series;
  std::vector<fs::path> earlierFiles;  // of the snapshots before a resume

  // One state's particles and the grids made from them (keyed by their parameters: a grid
  // shared by several outputs is computed once).
  struct State {
    const sph::SphSolver& solver;
    particles::ParticleSet particles;
    std::map<std::string, resample::ResampleResult> grids;
    std::map<std::string, vtkSmartPointer<vtkPolyData>> surfaces;
  };

  Impl(const SceneParams& s, fs::path d, std::ostream& l)
      : scene(s), dir(std::move(d)), log(l), box(domainBounds(s.sph)) {}

  State stateOf(const sph::SphSolver& solver) { return {solver, resamplingParticles(solver), {}, {}}; }

  const FieldSet& grid(State& st, const SphResampleParams& g) {
    const std::string key = scene::writeParams(static_cast<const resample::ParticleResampleParams&>(g)).dump();
    auto it = st.grids.find(key);
    if (it == st.grids.end())
      it = st.grids.emplace(key, resample::resampleParticles(st.particles,
                                                             resamplerParams(g, scene.sph), &box))
               .first;
    return it->second.fields;
  }

  vtkSmartPointer<vtkPolyData> surface(State& st, const FreeSurfaceParams& f) {
    const isosurface::IsosurfaceParams iso = contourParams(f, scene.sph);
    const std::string key = scene::writeParams(f.grid).dump() + scene::writeParams(iso).dump();
    if (auto it = st.surfaces.find(key); it != st.surfaces.end()) return it->second;
    const FieldSet& fields = grid(st, f.grid);
    const auto& values = fields.findScalar(choiceName(f.field))->values;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (double x : values)
      if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    vtkSmartPointer<vtkPolyData> result;
    if (!(iso.value > lo && iso.value < hi)) {
      log << scene.name << ": warning: no free surface at t = " << st.solver.time() << " s: "
          << choiceName(f.field) << " spans [" << lo << ", " << hi << "], level " << iso.value
          << " is outside; writing an empty surface\n";
      result = vtkSmartPointer<vtkPolyData>::New();
    } else {
      result = isosurface::extractIsosurface(fields, iso);
    }
    st.surfaces.emplace(key, result);
    return result;
  }

  std::unique_ptr<Scene3D> viewScene(State& st, const ViewOutput& v, std::size_t i) {
    auto scene3d = std::make_unique<Scene3D>(static_cast<const View3DParams&>(v));
    const std::string title = pictureTitle(scene, "output.views[" + std::to_string(i) + "].title",
                                           v.title, {v.particles.color_by, st.solver.time()});
    if (!title.empty()) scene3d->setTitle(title);
    const bool twoD = scene.sph.dimension == 2;
    const ParticleStyle particleStyle = particleStyleOf(v, scene.sph);
    if (showsSurface(v)) {
      const vtkSmartPointer<vtkPolyData> s = surface(st, v.free_surface);
      if (s->GetNumberOfPoints() > 0) {
        const SurfaceActor a = makeSurfaceActor(s, v.surface);
        if (twoD) {  // isolines: thick, unlit, in front of the particles (seen from +z)
          a.actor->GetProperty()->SetLineWidth(3.0f);
          a.actor->GetProperty()->SetLighting(false);
          a.actor->SetPosition(0.0, 0.0, 2.0 * particleStyle.radius);
        }
        scene3d->add(a.actor);
        if (a.coloring)
          scene3d->setLegend(a.coloring->table, legendTitleOf(a.coloring->title, v.surface.color_by));
      }
    }
    if (showsParticles(v)) {
      const ParticleActor a = makeParticleActor(resample::toPolyData(st.particles), particleStyle);
      scene3d->add(a.actor);
      if (a.coloring)
        scene3d->setLegend(a.coloring->table, legendTitleOf(a.coloring->title, v.particles.color_by));
    }
    scene3d->setBounds(boxOf(box));
    return scene3d;
  }

  // Writes `file` (via `write`) either as the final state or as snapshot `index` of its series.
  template <class Write>
  void output(const std::string& file, int index, std::vector<fs::path>& written,
              const Write& write, double time) {
    if (index == 0) {
      write(dir / file);
      written.push_back(dir / file);
      return;
    }
    const fs::path relative = seriesFile(file, index);
    fs::create_directories(dir / relative.parent_path());
    write(dir / relative);  // the file first, then the index
    series.at(file)->add(time, relative);
    written.push_back(dir / relative);
  }

  // The final state (every output, `snapshot` empty) or snapshot *snapshot: the every_snapshot
  // grids and surfaces from index 1 on, the views `frames` has a frame for.
  void writeState(const sph::SphSolver& solver, std::optional<int> snapshot,
                  const PictureDestination& pictures, std::vector<fs::path>& written) {
    const auto& out = scene.output;
    State st = stateOf(solver);
    const double t = solver.time();
    const int index = snapshot.value_or(0);  // output(): 0 is the final state's file
    const bool series = !snapshot || *snapshot >= 1;
    for (std::size_t i = 0; i < out.grids.size() && series; ++i)
      if (!snapshot || out.grids[i].every_snapshot)
        output(gridFile(scene, i), index, written,
               [&](const fs::path& f) { writeVti(grid(st, out.grids[i]), f); }, t);
    for (std::size_t i = 0; i < out.free_surface.size() && series; ++i)
      if (!snapshot || out.free_surface[i].every_snapshot)
        output(surfaceFile(scene, i), index, written,
               [&](const fs::path& f) { writeVtp(surface(st, out.free_surface[i]), f); }, t);
    for (std::size_t i = 0; i < out.views.size(); ++i) {
      const ViewOutput& v = out.views[i];
      const std::string file = viewFile(scene, i);
      const std::optional<fs::path> png = pictures.path(file, v);
      if (!png) continue;
      std::unique_ptr<Scene3D> s = viewScene(st, v, i);
      s->renderToPng(*png);
      written.push_back(*png);
      if (!snapshot && v.turntable_frames > 0)
        for (const fs::path& f : s->renderTurntable(dir / (stemOf(file) + "_turntable")))
          written.push_back(f);
    }
  }
};

SphGridOutputs::SphGridOutputs(const SceneParams& scene, fs::path dir, std::ostream& log,
                               bool resumed, const std::vector<PvdSeries::Entry>& earlierSnapshots)
    : impl_(std::make_unique<Impl>(scene, std::move(dir), log)) {
  const auto& out = scene.output;
  if (out.snapshots == 0) return;
  // A file of snapshot k (1-based) that a resumed run continues from.
  auto earlier = [&](const fs::path& relative, int k) {
    const fs::path file = impl_->dir / relative;
    if (!fs::exists(file))
      throw FileError(file, "snapshot " + std::to_string(k) + " of the run being resumed wrote " +
                                file.string() + ", which is missing; start the run again "
                                "without --resume");
    impl_->earlierFiles.push_back(file);
  };
  auto start = [&](const std::string& file, bool every) {
    if (!every) return;
    if (resumed) removeLaterSnapshots(impl_->dir / stemOf(file), stemOf(file), earlierSnapshots.size());
    std::vector<PvdSeries::Entry> entries;
    for (std::size_t k = 1; k <= earlierSnapshots.size(); ++k) {
      const fs::path relative = seriesFile(file, static_cast<int>(k));
      earlier(relative, static_cast<int>(k));
      entries.push_back({earlierSnapshots[k - 1].time, relative.generic_string()});
    }
    impl_->series[file] = std::make_unique<PvdSeries>(impl_->dir / (stemOf(file) + ".pvd"),
                                                      std::move(entries));
  };
  for (std::size_t i = 0; i < out.grids.size(); ++i)
    start(gridFile(scene, i), out.grids[i].every_snapshot);
  for (std::size_t i = 0; i < out.free_surface.size(); ++i)
    start(surfaceFile(scene, i), out.free_surface[i].every_snapshot);
}

const std::vector<fs::path>& SphGridOutputs::earlierFiles() const { return impl_->earlierFiles; }

SphGridOutputs::~SphGridOutputs() = default;

void SphGridOutputs::snapshot(const sph::SphSolver& solver, int index,
                              const PictureDestination& frames, std::vector<fs::path>& written) {
  if (index < 0) throw std::invalid_argument("SphGridOutputs::snapshot: index must be >= 0");
  const auto& out = impl_->scene.output;
  const auto every = [](const auto& list) {
    return std::any_of(list.begin(), list.end(), [](const auto& o) { return o.every_snapshot; });
  };
  if (every(out.grids) || every(out.free_surface) || every(out.views))
    impl_->writeState(solver, index, frames, written);
}

void SphGridOutputs::finalState(const sph::SphSolver& solver, std::vector<fs::path>& written) {
  const auto& out = impl_->scene.output;
  if (out.grids.empty() && out.free_surface.empty() && out.views.empty()) return;
  impl_->writeState(solver, std::nullopt, PictureDestination::finalPictures(impl_->dir), written);
  for (const auto& [file, s] : impl_->series) written.push_back(s->path());
}

}  // namespace fluidviz
