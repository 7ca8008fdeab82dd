#include "paraview/properties/PropertyValues.h"

#include <cmath>

#include "paraview/properties/ServerManagerXml.h"

namespace fluidviz::paraview {

using scene::json;
using scene::ParamKind;

namespace {
// "separatrix_integration.step" -> /separatrix_integration/step: nested as in a scene file.
json::json_pointer pointerOf(std::string key) {
  for (char& c : key)
    if (c == '.') c = '/';
  return json::json_pointer("/" + key);
}
}  // namespace

void PropertyValues::record(const std::string& key, const std::string& message) {
  if (error_.key().empty()) error_ = ParamError(key, message);
}

const scene::ParamRow* PropertyValues::rowFor(const std::string& key, ParamKind kind,
                                              ParamKind alternative) {
  const scene::ParamRow* row = scene::findParamRow(rows_, key);
  if (!row) {
    record(key, "is not a parameter of this filter");
    return nullptr;
  }
  if (row->kind != kind && row->kind != alternative) {
    record(key, "was set through the wrong kind of property (ParaView XML and declaration "
                "disagree)");
    return nullptr;
  }
  return row;
}

void PropertyValues::setNumber(const std::string& key, double value) {
  if (!rowFor(key, ParamKind::number, ParamKind::optional_number)) return;
  // JSON has no NaN: keep it as null, which the reader refuses with the allowed range.
  values_[key] = std::isfinite(value) ? json(value) : json("nan");
}

void PropertyValues::setInteger(const std::string& key, int value) {
  if (rowFor(key, ParamKind::integer, ParamKind::integer)) values_[key] = value;
}

void PropertyValues::setFlag(const std::string& key, int on) {
  if (rowFor(key, ParamKind::flag, ParamKind::flag)) values_[key] = on != 0;
}

void PropertyValues::setChoice(const std::string& key, int index) {
  const scene::ParamRow* row = rowFor(key, ParamKind::choice, ParamKind::choice);
  if (!row) return;
  if (index < 0 || index >= int(row->info.choices.size())) {
    record(key, "choice number " + std::to_string(index) + " does not exist; allowed: 0 to " +
                    std::to_string(row->info.choices.size() - 1) + " (" +
                    joinNames(row->info.choices) + ")");
    return;
  }
  values_[key] = row->info.choices[index];
}

void PropertyValues::setText(const std::string& key, const std::string& value) {
  if (rowFor(key, ParamKind::text, ParamKind::text)) values_[key] = value;
}

void PropertyValues::setNumbers(const std::string& key, const std::vector<double>& values) {
  const scene::ParamRow* row = rowFor(key, ParamKind::numbers, ParamKind::numbers);
  if (!row) return;
  if (values.size() != row->defaultValue.size()) {
    record(key, "has " + std::to_string(row->defaultValue.size()) + " numbers, got " +
                    std::to_string(values.size()));
    return;
  }
  json list = json::array();
  for (double v : values) list.push_back(std::isfinite(v) ? json(v) : json("nan"));
  values_[key] = list;
}

void PropertyValues::setGiven(const std::string& key, bool given) {
  if (!rowFor(key, ParamKind::optional_number, ParamKind::optional_number)) return;
  if (given)
    given_.insert(key);
  else
    given_.erase(key);
}

std::string PropertyValues::propertyMessage(const ParamError& e) {
  return "property " + propertyName(e.key()) + " (scene key " + e.key() + ") " + e.what();
}

json PropertyValues::sceneJson() const {
  json j = json::object();
  for (const auto& [key, value] : values_) {
    const scene::ParamRow* row = scene::findParamRow(rows_, key);
    if (row->kind == ParamKind::optional_number && !given_.count(key)) continue;
    j[pointerOf(key)] = value;
  }
  return j;
}

}  // namespace fluidviz::paraview
