#pragma once
// Flow around a cylinder in a channel: the 2D benchmarks of Schaefer & Turek (1996), against
// which the drag and lift coefficients of the cylinder example are validated
// (tests/pipeline/ProbesTimeSeries_test.cpp; examples/cylinder_channel.json is test 2D-2).
//
// Geometry (all tests): channel H = 0.41 m high, 2.2 m long, no-slip walls at y = 0 and H; a
// cylinder of diameter D = 0.1 m centred at (0.2, 0.2), 0.005 m below the centre line; inflow
// U(y) = 4 U_m y (H - y) / H^2 (parabolic), outflow free; nu = 1e-3 m^2/s, rho = 1 kg/m^3.
// Re = U_mean D / nu with U_mean = 2 U_m / 3. C_D = 2 F_x / (rho U_mean^2 D), C_L = 2 F_y /
// (rho U_mean^2 D); St = D f / U_mean, f the frequency of the lift.
//   2D-1: U_m = 0.3 m/s, Re 20, steady.
//   2D-2: U_m = 1.5 m/s, Re 100, periodic vortex shedding.
// The intervals are the lower and upper bounds the benchmark's authors drew from the
// participating groups' most accurate results.
//
// Reference: M. Schaefer, S. Turek, "Benchmark computations of laminar flow around a cylinder",
// in E. H. Hirschel (ed.), Flow Simulation with High-Performance Computers II, Notes on Numerical
// Fluid Mechanics, Vieweg 1996, pp. 547-566.

namespace fluidviz::lbm {

struct BenchmarkInterval {
  double lower, upper;
  double centre() const { return 0.5 * (lower + upper); }
};

/// Test 2D-1 (steady, Re 20).
inline constexpr BenchmarkInterval kSchaeferTurek2D1Drag{5.57, 5.59};
inline constexpr BenchmarkInterval kSchaeferTurek2D1Lift{0.0104, 0.0110};

/// Test 2D-2 (periodic, Re 100): maxima over a period and the Strouhal number.
inline constexpr BenchmarkInterval kSchaeferTurek2D2MaxDrag{3.22, 3.24};
inline constexpr BenchmarkInterval kSchaeferTurek2D2MaxLift{0.99, 1.01};
inline constexpr BenchmarkInterval kSchaeferTurek2D2Strouhal{0.295, 0.305};

}  // namespace fluidviz::lbm
