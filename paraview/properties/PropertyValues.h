#pragma once
// The values a ParaView proxy has set on a fluidviz filter, kept as scene-file JSON and read into
// the filter's parameter struct by the scene reader itself (fieldviz/scene/ParamVisitors.h): the
// same range checks and the same error text as a scene key or a CLI flag. VTK-free; the plugin's
// VTK classes (paraview/plugin) forward their Set*Parameter methods here.
//
//   PropertyValues values(scene::paramTable<lic::LicParams>());
//   values.setNumber("length", 30);        // DoubleVectorProperty Length, initial_string "length"
//   values.setChoice("kernel", 1);         // EnumerationDomain entry 1: "hann"
//   lic::LicParams p = values.read<lic::LicParams>();  // ParamError naming the key if not allowed
//
// A setter given a key the struct does not declare, or a value of the wrong kind, records the
// error; read() then throws it (a VTK Set method must not throw through ParaView's interpreter).
#include <map>
#include <set>
#include <string>
#include <vector>

#include "fieldviz/scene/ParamTable.h"

namespace fluidviz::paraview {

class PropertyValues {
 public:
  explicit PropertyValues(std::vector<scene::ParamRow> rows) : rows_(std::move(rows)) {}

  void setNumber(const std::string& key, double value);
  void setInteger(const std::string& key, int value);
  void setFlag(const std::string& key, int on);
  /// `index` into the row's info.choices (the EnumerationDomain's entry values).
  void setChoice(const std::string& key, int index);
  void setText(const std::string& key, const std::string& value);
  /// An array of numbers (ParamKind::numbers), as many as its declaration's default has.
  void setNumbers(const std::string& key, const std::vector<double>& values);
  /// An optional number counts only while given; its value may be set before or after.
  void setGiven(const std::string& key, bool given);

  /// The scene JSON of every value set so far (keys nested as in a scene file).
  scene::json sceneJson() const;

  /// The struct with the values set; throws ParamError (key, allowed range) for a value the
  /// declaration does not allow, or the first setter error.
  template <class S>
  S read() const {
    if (!error_.key().empty()) throw error_;
    S params{};
    scene::readParams(sceneJson(), params, "");
    return params;
  }

  /// read() without exceptions: false, and `error` says which property and why, if not allowed.
  template <class S>
  bool tryRead(S& out, std::string& error) const {
    try {
      out = read<S>();
      return true;
    } catch (const ParamError& e) {
      error = propertyMessage(e);
      return false;
    }
  }

  /// "property Length (scene key length) must be in [1, 1000], got 5000".
  static std::string propertyMessage(const ParamError& e);

  const std::vector<scene::ParamRow>& rows() const { return rows_; }

 private:
  const scene::ParamRow* rowFor(const std::string& key, scene::ParamKind kind,
                                scene::ParamKind alternative);
  void record(const std::string& key, const std::string& message);

  std::vector<scene::ParamRow> rows_;
  std::map<std::string, scene::json> values_;  ///< by dotted key
  std::set<std::string> given_;                ///< optional numbers currently given
  ParamError error_{"", ""};
};

}  // namespace fluidviz::paraview
