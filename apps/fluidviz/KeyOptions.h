#pragma once
// Command-line options generated from the describe() declaration of a parameter struct, the
// same declaration that drives the scene keys and docs/scenes.md: one CLI11 option per key,
// named after the key ("noise_seed" -> "--noise-seed") unless ParamInfo::flag names it, with
// the docs row as help text (description, unit, default, allowed range). The values are read
// through the struct's own reader, so ranges, choices and messages are the scene file's; a bad
// value is a UsageError naming the flag ("--length is 0 px, outside the allowed range [1, 1000]").
//
// A bool key becomes a switch: "--KEY" when its default is false, "--no-KEY" when it is true.
#include <CLI/CLI.hpp>
#include <deque>
#include <string>
#include <vector>

#include "apps/fluidviz/Commands.h"
#include "fieldviz/scene/ParamVisitors.h"

namespace fluidviz::app {

/// A key and, where the command names it differently from the key and ParamInfo::flag, its flag.
struct KeyFlagName {
  std::string key;
  std::string flag = "";
};

/// The options of the keys of one struct, added to a CLI11 command.
class KeyOptions {
 public:
  /// Adds an option for each of `keys` (dotted for nested keys) of S to `app` under `group`.
  template <class S>
  void add(CLI::App& app, const std::vector<KeyFlagName>& keys, const std::string& group) {
    std::vector<scene::DocRow> rows;
    scene::documentParams<S>(rows, "");
    for (const KeyFlagName& k : keys) addRow(app, findRow(rows, k.key), k.flag, group);
  }

  /// The given values read into `params` (over the keys already in `json`). Throws UsageError
  /// naming the flag for a value that is not allowed.
  template <class S>
  void read(S& params, scene::json json = scene::json::object()) const {
    putGivenValues(json);
    checkWithFlagNames([&] { scene::readParams(json, params, ""); });
  }

  /// Runs `check` (a validate function of the struct) and turns its ParamError into a
  /// UsageError naming the flag of the key.
  template <class F>
  void checkWithFlagNames(F&& check) const {
    try {
      check();
    } catch (const ParamError& e) {
      throw UsageError(flagForKey(e.key()) + " " + e.what());
    }
  }

  /// "length" -> "--length", "line_color[1]" -> "--line-color[1]"; the key itself if no option
  /// sets it.
  std::string flagForKey(const std::string& key) const;

  /// True when the option of `key` was given.
  bool given(const std::string& key) const;

 private:
  struct Entry {
    scene::DocRow row;
    std::string flag;
    std::string value;
    bool on = false;  ///< a switch that was given
    CLI::Option* option = nullptr;
  };
  static const scene::DocRow& findRow(const std::vector<scene::DocRow>& rows,
                                      const std::string& key);
  void addRow(CLI::App& app, const scene::DocRow& row, const std::string& flag,
              const std::string& group);
  void putGivenValues(scene::json& json) const;

  std::deque<Entry> entries_;  // CLI11 keeps pointers to the values: no reallocation
};

/// The number `value` of option `flag`. Throws UsageError "--step is 'x'; expected a number".
double parseFlagNumber(const std::string& flag, const std::string& value);

/// Option name of a key: "--" + the key with '_' -> '-' ("noise_seed" -> "--noise-seed").
std::string flagFromKey(const std::string& key);

/// The option of a docs row: `flag` if given, else the row's ParamInfo::flag, else from the key;
/// a bool key whose default is true becomes "--no-..." (the switch turns it off).
std::string optionFlag(const scene::DocRow& row, const std::string& flag = "");

/// Help text of a key's option, from its docs row: "description (unit); default D; allowed R".
std::string keyHelp(const scene::DocRow& row);

/// Parses `args` (args[0] is the command's name) with `app`. Returns false after writing the
/// help to `out` for -h/--help; throws UsageError for anything CLI11 refuses and for unknown
/// options ("unknown option '--bogus' (see fluidviz lic --help)").
bool parseCommandLine(CLI::App& app, const std::vector<std::string>& args, std::ostream& out);

}  // namespace fluidviz::app
