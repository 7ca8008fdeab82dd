#pragma once
// Small scenes with many snapshots for the signal and kill tests, written to a folder.
#include <filesystem>
#include <fstream>
#include <string>

namespace fluidviz::test {

/// LBM lid-driven cavity, resolution x resolution nodes, `snapshots` snapshots, a picture.
inline std::filesystem::path writeLbmScene(const std::filesystem::path& dir, int resolution,
                                           double endTime, int snapshots) {
  const std::filesystem::path p = dir / "cav.json";
  std::ofstream(p) << R"({ "name": "cav", "solver": "lbm",
    "lbm": { "domain_size": [1, 1], "resolution": )" << resolution << R"(, "reynolds": 100,
             "lattice_velocity": 0.1,
             "walls": {"y_max": {"type": "moving_wall", "velocity": [1, 0]}},
             "end_time": )" << endTime << R"(, "check_interval": 200 },
    "output": { "snapshots": )" << snapshots << R"(,
                "images": [{"field": "speed", "width": 200, "height": 170}] } })";
  return p;
}

/// SPH model B, two rollers in a closed box (particle_spacing dx), a picture.
inline std::filesystem::path writeSphScene(const std::filesystem::path& dir, double dx,
                                           double endTime, int snapshots) {
  const std::filesystem::path p = dir / "mill.json";
  std::ofstream(p) << R"({ "name": "mill", "solver": "sph",
    "sph": { "dimension": 2, "model": "B", "kernel": "wendland_c2", "particle_spacing": )" << dx
                   << R"(, "smoothing_length_ratio": 1.5, "speed_of_sound": 1.5, "viscosity": 0.01,
             "gravity": [0, 0, 0], "domain_upper": [1, 1, 0], "initial_pressure": "zero",
             "fluid_blocks": [{"lower": [0, 0, 0], "upper": [1, 1, 0]}],
             "rollers": [{"center": [0.3, 0.5], "radius": 0.15, "angular_velocity": 2},
                         {"center": [0.7, 0.5], "radius": 0.15, "angular_velocity": -2}],
             "end_time": )" << endTime << R"( },
    "output": { "snapshots": )" << snapshots << R"(,
                "images": [{"field": "speed", "width": 200, "height": 170}] } })";
  return p;
}

}  // namespace fluidviz::test
