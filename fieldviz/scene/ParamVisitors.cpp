#include "fieldviz/scene/ParamVisitors.h"

#include "fieldviz/core/ParamRanges.h"

#include <algorithm>
#include <cmath>

namespace fluidviz::scene {

std::string jsonTypeName(const json& j) {
  switch (j.type()) {
    case json::value_t::null: return "null";
    case json::value_t::object: return "an object";
    case json::value_t::array: return "a list";
    case json::value_t::string: return "the string " + j.dump();
    case json::value_t::boolean: return j.dump();
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return "the number " + j.dump();
    default: return "an unsupported value";
  }
}

namespace detail {

[[noreturn]] void failType(const std::string& path, const char* expected, const json& got,
                           const ParamInfo& info) {
  std::string allowed = describeRange(info);
  throw ParamError(path, std::string("must be ") + expected + ", got " + jsonTypeName(got) +
                             (allowed == "any" ? "" : " (allowed " + allowed + ")"));
}

// Same rules and messages as a struct checked from code (fieldviz/core/ParamRanges.h).
void checkRange(double v, const std::string& path, const ParamInfo& info) {
  params::detail::checkNumber(v, path, info);
}

void checkChoice(const std::string& v, const std::string& path, const ParamInfo& info) {
  params::detail::check(v, path, info);
}

void rejectUnknownKeys(const json& j, const std::vector<std::string>& known,
                       const std::string& path) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw ParamError(joinKey(path, it.key()), "is not a known key; allowed keys here: " + list);
  }
}

std::string defaultText(const json& value, const ParamInfo& info) {
  if (info.required) return "(required)";
  if (value.is_null()) return "(none)";
  return "`" + value.dump() + "`";
}

}  // namespace detail

namespace {
// A '|' inside a cell would end it early.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}
}  // namespace

std::string markdownTable(const std::vector<DocRow>& rows) {
  std::ostringstream s;
  s << "| key | type | unit | default | allowed | description |\n";
  s << "|---|---|---|---|---|---|\n";
  for (const DocRow& r : rows)
    s << "| `" << r.key << "` | " << r.type << " | " << cell(r.unit) << " | "
      << cell(r.defaultValue) << " | " << cell(r.allowed) << " | " << cell(r.description) << " |\n";
  return s.str();
}

}  // namespace fluidviz::scene
