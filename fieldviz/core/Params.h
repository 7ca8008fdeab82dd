#pragma once
// One plain struct per algorithm holds its parameters; the struct declares each member once, with
// its scene key, unit, valid range and description, in a static `describe` function:
//
//   enum class LicKernel { box, hann };
//   constexpr std::array<Choice<LicKernel>, 2> paramChoices(LicKernel) {
//     return {{{LicKernel::box, "box"}, {LicKernel::hann, "hann"}}};
//   }
//   struct LicParams {
//     double length = 30.0;  ///< half-length of the convolution kernel
//     LicKernel kernel = LicKernel::box;
//     template <class V> static void describe(V& v) {
//       v(&LicParams::length, {.key = "length", .unit = "px", .description = "kernel length L",
//                              .min = 1, .max = 1000});
//       v(&LicParams::kernel, {.key = "kernel", .description = "convolution kernel"});
//     }
//   };
//
// A choice is an `enum class` whose names are declared once, in a `paramChoices` function found
// next to the enum by argument-dependent lookup; the visitors read, write, check and document the
// member by those names, and the code compares enum values, never strings.
// Visitors (fieldviz/scene) use that one declaration to read scene JSON with range checks, to
// apply --set overrides, to write docs/scenes.md and to print the effective configuration.
// Supported member types: bool, int, double, std::string, a choice enum, std::optional<double>,
// std::array<double, N>, a nested struct with its own describe, std::vector of such structs.
// This header has no dependencies so that solvers and filter cores can declare parameters.
#include <array>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace fluidviz {

struct ParamInfo {
  std::string key;          ///< scene key, snake_case
  std::string unit;         ///< physical unit ("m", "m/s", "1/s", "px"); empty if none
  std::string description;  ///< one line, shown in docs and errors
  double min = -std::numeric_limits<double>::infinity();  ///< smallest allowed value (inclusive)
  double max = std::numeric_limits<double>::infinity();   ///< largest allowed value (inclusive)
  bool minExclusive = false;         ///< true: value must be strictly greater than min
  bool maxExclusive = false;         ///< true: value must be strictly less than max
  std::vector<std::string> choices;  ///< allowed values of a string parameter; empty = any
  bool required = false;             ///< true: the scene must give it (no default)
  std::string flag;  ///< command-line flag when it is not the key's ("--seed"); empty: from key
};

/// One allowed value of a choice enum E: its name in scene files and on the command line, and
/// an older spelling that is still read (never written) so that old scenes keep running.
template <class E>
struct Choice {
  E value;
  std::string_view name;
  std::string_view alias = {};
};

/// An enum class whose names are declared by `paramChoices(E)` (an array of Choice<E>).
template <class E>
concept ChoiceEnum = std::is_enum_v<E> && requires(E e) { paramChoices(e); };

/// The scene name of `value` ("rk4").
template <ChoiceEnum E>
std::string choiceName(E value) {
  for (const Choice<E>& c : paramChoices(E{}))
    if (c.value == value) return std::string(c.name);
  return "(invalid value " + std::to_string(static_cast<int>(value)) + ")";
}

/// The value called `name` or whose alias is `name`; empty for any other text.
template <ChoiceEnum E>
std::optional<E> choiceFromName(std::string_view name) {
  for (const Choice<E>& c : paramChoices(E{}))
    if (c.name == name || (!c.alias.empty() && c.alias == name)) return c.value;
  return std::nullopt;
}

/// The value called `name` (or whose alias is `name`); std::invalid_argument for any other text.
template <ChoiceEnum E>
E choiceNamed(std::string_view name) {
  if (const std::optional<E> value = choiceFromName<E>(name)) return *value;
  throw std::invalid_argument("\"" + std::string(name) + "\" is not a choice of this parameter");
}

/// "a, b, c".
std::string joinNames(const std::vector<std::string>& names);

/// The names of all values, in declaration order.
template <ChoiceEnum E>
std::vector<std::string> choiceNames() {
  std::vector<std::string> names;
  for (const Choice<E>& c : paramChoices(E{})) names.emplace_back(c.name);
  return names;
}

/// `info` as the visitors see a member of type T: for a choice enum, `choices` lists its names.
template <class T>
ParamInfo infoFor(const ParamInfo& info) {
  if constexpr (ChoiceEnum<T>) {
    ParamInfo withChoices = info;
    withChoices.choices = choiceNames<T>();
    return withChoices;
  } else {
    return info;
  }
}

/// A key that a struct no longer has, with the message that says what replaces it. A struct
/// lists them in `static constexpr std::array retiredKeys`; readers reject such a key with it.
struct RetiredKey {
  std::string_view key;
  std::string_view message;
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

/// Formats an allowed range for messages: "[8, 8192]", "(0, 0.4]", "[0, 1)", ">= 1".
std::string describeRange(const ParamInfo& info);

/// True when `v` lies in the declared range (finite, min/max exclusive where declared).
bool inRange(double v, const ParamInfo& info);

/// A number for messages, with `digits` significant digits ("0.0125", "1e+05").
std::string formatNumber(double value, int digits = 6);

/// `value` rounded to 15 significant digits: a time accumulated as n * dt (5.000000000000001)
/// becomes the 5 it means, for files people read (.pvd, CSV); non-finite values pass unchanged.
double withoutRoundOff(double value);

}  // namespace fluidviz
