#pragma once
// Visitors over the `describe` declarations of parameter structs (fieldviz/core/Params.h):
// reading JSON with range checks, writing JSON, and writing the Markdown key reference.
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldviz/core/Params.h"

namespace fluidviz::scene {

using json = nlohmann::json;

template <class T>
struct IsStdArray : std::false_type {};
template <std::size_t N>
struct IsStdArray<std::array<double, N>> : std::true_type {};
template <class T>
struct IsStructVector : std::false_type {};
template <class T>
struct IsStructVector<std::vector<T>> : std::is_class<T> {};
/// A list of points, [[x, y], ...]: a list of numbers' arrays, not of objects.
template <std::size_t N>
struct IsStructVector<std::vector<std::array<double, N>>> : std::false_type {};
template <class T>
struct IsPointList : std::false_type {};
template <std::size_t N>
struct IsPointList<std::vector<std::array<double, N>>> : std::true_type {};

inline std::string joinKey(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

std::string jsonTypeName(const json& j);

// ---------------------------------------------------------------------------------------------
// Reading: fills a struct from a JSON object, rejecting unknown keys, wrong types and values
// outside the declared range. Errors are ParamError with the full dotted key path.
template <class S>
void readParams(const json& j, S& out, const std::string& path);

namespace detail {

[[noreturn]] void failType(const std::string& path, const char* expected, const json& got,
                           const ParamInfo& info);
void checkRange(double v, const std::string& path, const ParamInfo& info);
void checkChoice(const std::string& v, const std::string& path, const ParamInfo& info);

inline void readValue(const json& j, bool& v, const std::string& path, const ParamInfo& info) {
  if (!j.is_boolean()) failType(path, "true or false", j, info);
  v = j.get<bool>();
}
inline void readValue(const json& j, int& v, const std::string& path, const ParamInfo& info) {
  const bool whole = j.is_number_integer() ||
                     (j.is_number_float() && std::floor(j.get<double>()) == j.get<double>());
  if (!whole) failType(path, "a whole number", j, info);
  const double x = j.get<double>();
  checkRange(x, path, info);
  if (std::abs(x) > 2147483647.0) failType(path, "a whole number that fits in 32 bits", j, info);
  v = static_cast<int>(x);
}
inline void readValue(const json& j, double& v, const std::string& path, const ParamInfo& info) {
  if (!j.is_number()) failType(path, "a number", j, info);
  v = j.get<double>();
  checkRange(v, path, info);
}
inline void readValue(const json& j, std::string& v, const std::string& path,
                      const ParamInfo& info) {
  if (!j.is_string()) failType(path, "a string", j, info);
  v = j.get<std::string>();
  checkChoice(v, path, info);
}
/// A choice enum reads its name (or an alias); any other text gets the choice message.
template <ChoiceEnum E>
void readValue(const json& j, E& v, const std::string& path, const ParamInfo& info) {
  const ParamInfo withChoices = infoFor<E>(info);
  if (!j.is_string()) failType(path, "a string", j, withChoices);
  const std::string name = j.get<std::string>();
  const std::optional<E> value = choiceFromName<E>(name);
  if (!value) checkChoice(name, path, withChoices);  // throws the message of any other choice
  v = *value;
}
inline void readValue(const json& j, std::optional<double>& v, const std::string& path,
                      const ParamInfo& info) {
  if (j.is_null()) {
    v.reset();
    return;
  }
  double x = 0;
  readValue(j, x, path, info);
  v = x;
}
template <std::size_t N>
void readValue(const json& j, std::array<double, N>& v, const std::string& path,
               const ParamInfo& info) {
  if (!j.is_array() || j.size() != N)
    failType(path, (std::string("a list of ") + std::to_string(N) + " numbers").c_str(), j, info);
  for (std::size_t i = 0; i < N; ++i) readValue(j[i], v[i], path + "[" + std::to_string(i) + "]", info);
}
/// A list of points, each a list of N numbers inside the declared range.
template <std::size_t N>
void readValue(const json& j, std::vector<std::array<double, N>>& v, const std::string& path,
               const ParamInfo& info) {
  if (!j.is_array())
    failType(path, (std::string("a list of points [") + std::to_string(N) + " numbers]").c_str(), j,
             info);
  v.assign(j.size(), {});
  for (std::size_t i = 0; i < j.size(); ++i)
    readValue(j[i], v[i], path + "[" + std::to_string(i) + "]", info);
}
template <class T>
void readValue(const json& j, std::vector<T>& v, const std::string& path, const ParamInfo& info) {
  if (!j.is_array()) failType(path, "a list of objects", j, info);
  v.clear();
  for (std::size_t i = 0; i < j.size(); ++i) {
    T item{};
    readParams(j[i], item, path + "[" + std::to_string(i) + "]");
    v.push_back(std::move(item));
  }
}
template <class T>
  requires std::is_class_v<T>
void readValue(const json& j, T& v, const std::string& path, const ParamInfo&) {
  readParams(j, v, path);
}

template <class S>
class JsonReader {
 public:
  JsonReader(const json& j, S& s, std::string path) : j_(j), s_(s), path_(std::move(path)) {}

  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    known_.push_back(info.key);
    const std::string path = joinKey(path_, info.key);
    auto it = j_.find(info.key);
    if (it == j_.end()) {
      if (info.required)
        throw ParamError(path, "is required: " + info.description +
                                   (info.unit.empty() ? "" : " (" + info.unit + ")") +
                                   ", allowed " + describeRange(infoFor<T>(info)));
      return;
    }
    readValue(*it, s_.*member, path, info);
  }

  void rejectUnknownKeys() const;

 private:
  const json& j_;
  S& s_;
  std::string path_;
  std::vector<std::string> known_;
};

void rejectUnknownKeys(const json& j, const std::vector<std::string>& known,
                       const std::string& path);

template <class S>
void JsonReader<S>::rejectUnknownKeys() const {
  detail::rejectUnknownKeys(j_, known_, path_);
}

}  // namespace detail

template <class S>
void readParams(const json& j, S& out, const std::string& path) {
  if (!j.is_object())
    throw ParamError(path, "must be an object {...}, got " + jsonTypeName(j));
  if constexpr (requires { S::retiredKeys; })
    for (const RetiredKey& retired : S::retiredKeys)
      if (j.contains(retired.key))
        throw ParamError(joinKey(path, std::string(retired.key)), std::string(retired.message));
  detail::JsonReader<S> reader(j, out, path);
  S::describe(reader);
  reader.rejectUnknownKeys();
}

// ---------------------------------------------------------------------------------------------
// Writing: the struct's values as JSON (for the effective configuration and defaults in docs).
template <class S>
json writeParams(const S& s);

namespace detail {
inline json toJson(bool v) { return v; }
inline json toJson(int v) { return v; }
inline json toJson(double v) { return v; }
inline json toJson(const std::string& v) { return v; }
template <ChoiceEnum E>
json toJson(E v) {
  return choiceName(v);
}
inline json toJson(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }
template <std::size_t N>
json toJson(const std::array<double, N>& v) {
  return json(v);
}
template <std::size_t N>
json toJson(const std::vector<std::array<double, N>>& v) {
  json a = json::array();
  for (const std::array<double, N>& point : v) a.push_back(json(point));
  return a;
}
template <class T>
json toJson(const std::vector<T>& v) {
  json a = json::array();
  for (const T& item : v) a.push_back(writeParams(item));
  return a;
}
template <class T>
  requires std::is_class_v<T>
json toJson(const T& v) {
  return writeParams(v);
}

template <class S>
class JsonWriter {
 public:
  explicit JsonWriter(const S& s) : s_(s) {}
  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    j_[info.key] = toJson(s_.*member);
  }
  json result() const { return j_; }

 private:
  const S& s_;
  json j_ = json::object();
};
}  // namespace detail

template <class S>
json writeParams(const S& s) {
  detail::JsonWriter<S> writer(s);
  S::describe(writer);
  return writer.result();
}

// ---------------------------------------------------------------------------------------------
// Documentation: one Markdown table row per key, with type, unit, default and allowed range.
struct DocRow {
  std::string key, type, unit, defaultValue, allowed, description;
  std::string flag;  ///< ParamInfo::flag: the command-line flag when it is not the key's
};

template <class S>
void documentParams(std::vector<DocRow>& rows, const std::string& prefix);

namespace detail {
inline std::string typeName(const bool*) { return "bool"; }
inline std::string typeName(const int*) { return "integer"; }
inline std::string typeName(const double*) { return "number"; }
inline std::string typeName(const std::string*) { return "string"; }
template <ChoiceEnum E>
std::string typeName(const E*) {
  return "string";
}
inline std::string typeName(const std::optional<double>*) { return "number (optional)"; }
template <std::size_t N>
std::string typeName(const std::array<double, N>*) {
  return "[" + std::to_string(N) + " numbers]";
}
template <std::size_t N>
std::string typeName(const std::vector<std::array<double, N>>*) {
  return "list of [" + std::to_string(N) + " numbers]";
}

std::string defaultText(const json& value, const ParamInfo& info);

template <class S>
class DocWriter {
 public:
  DocWriter(std::vector<DocRow>& rows, std::string prefix, const S& defaults)
      : rows_(rows), prefix_(std::move(prefix)), defaults_(defaults) {}

  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    const std::string key = joinKey(prefix_, info.key);
    if constexpr (IsStructVector<T>::value) {
      rows_.push_back({key, "list of objects", "", defaultText(toJson(defaults_.*member), info),
                       "see " + key + "[].*", info.description});
      documentParams<typename T::value_type>(rows_, key + "[]");
    } else if constexpr (std::is_class_v<T> && !IsStdArray<T>::value && !IsPointList<T>::value &&
                         !std::is_same_v<T, std::string> &&
                         !std::is_same_v<T, std::optional<double>>) {
      rows_.push_back({key, "object", "", "", "see " + key + ".*", info.description});
      documentParams<T>(rows_, key);
    } else {
      rows_.push_back({key, typeName(static_cast<const T*>(nullptr)), info.unit,
                       defaultText(toJson(defaults_.*member), info),
                       describeRange(infoFor<T>(info)), info.description, info.flag});
    }
  }

 private:
  std::vector<DocRow>& rows_;
  std::string prefix_;
  const S& defaults_;
};
}  // namespace detail

template <class S>
void documentParams(std::vector<DocRow>& rows, const std::string& prefix) {
  const S defaults{};
  detail::DocWriter<S> writer(rows, prefix, defaults);
  S::describe(writer);
}

/// Markdown table of rows.
std::string markdownTable(const std::vector<DocRow>& rows);

}  // namespace fluidviz::scene
