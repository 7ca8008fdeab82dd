#pragma once
// One plain struct per algorithm holds its parameters; the struct declares each member once, with
// its scene key, unit, valid range and description, in a static `describe` function:
//
//   struct LicParams {
//     double length = 30.0;  ///< kernel length L in output pixels, [1, 1000]
//     std::string kernel = "box";
//     template <class V> static void describe(V& v) {
//       v(&LicParams::length, {.key = "length", .unit = "px", .description = "kernel length L",
//                              .min = 1, .max = 1000});
//       v(&LicParams::kernel, {.key = "kernel", .description = "convolution kernel",
//                              .choices = {"box", "hann"}});
//     }
//   };
//
// Visitors (fieldviz/scene) use that one declaration to read scene JSON with range checks, to
// apply --set overrides, to write docs/scenes.md and to print the effective configuration.
// Supported member types: bool, int, double, std::string, std::optional<double>,
// std::array<double, N>, a nested struct with its own describe, std::vector of such structs.
// This header has no dependencies so that solvers and filter cores can declare parameters.
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluidviz {

struct ParamInfo {
  std::string key;          ///< scene key, snake_case
  std::string unit;         ///< physical unit ("m", "m/s", "1/s", "px"); empty if none
  std::string description;  ///< one line, shown in docs and errors
  double min = -std::numeric_limits<double>::infinity();  ///< smallest allowed value (inclusive)
  double max = std::numeric_limits<double>::infinity();   ///< largest allowed value (inclusive)
  bool minExclusive = false;         ///< true: value must be strictly greater than min
  std::vector<std::string> choices;  ///< allowed values of a string parameter; empty = any
  bool required = false;             ///< true: the scene must give it (no default)
};

/// A parameter value (or a combination of values) that is not allowed. `key` is the dotted path
/// relative to the struct being read; readers prefix the file and the enclosing path.
class ParamError : public std::runtime_error {
 public:
  ParamError(std::string key, const std::string& message)
      : std::runtime_error(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

/// Formats an allowed range for messages: "[8, 8192]", "(0, 0.4]", ">= 1".
std::string describeRange(const ParamInfo& info);

/// A number for messages, with `digits` significant digits ("0.0125", "1e+05").
std::string formatNumber(double value, int digits = 6);

}  // namespace fluidviz
