#pragma once
// A parameter struct's declarations (fieldviz/core/Params.h) as a flat table: one row per leaf
// key, nested structs flattened to dotted keys ("separatrix_integration.step"), with its kind,
// declared info (unit, range, choices, description) and default value. Other front ends than
// scene files and the CLI read it: the ParaView plugin's property XML and its setters
// (paraview/), so that a property has the same name, default, range and text as the scene key.
#include <string>
#include <type_traits>
#include <vector>

#include "fieldviz/scene/ParamVisitors.h"

namespace fluidviz::scene {

/// How a front end presents a parameter. Numbers: a fixed-size array of numbers
/// (std::array<double, N>: a point, counts along axes), N = defaultValue.size(), the range
/// applying to each. List: a list of objects (output.images[]), which a single property cannot
/// hold; front ends say that they do not offer it.
enum class ParamKind { flag, integer, number, optional_number, text, choice, numbers, list };

struct ParamRow {
  std::string key;  ///< dotted path from the struct
  ParamKind kind = ParamKind::number;
  ParamInfo info;        ///< as declared; for a choice, info.choices lists the names
  json defaultValue;     ///< the default-constructed struct's value (null: optional, unset)
};

/// Appends the rows of `values`' struct; keys start with `prefix`, defaults are `values`' own
/// (a nested struct's defaults are those its parent gives it).
template <class S>
void tabulateParams(std::vector<ParamRow>& rows, const std::string& prefix, const S& values);

namespace detail {
template <class T>
constexpr ParamKind paramKindOf() {
  if constexpr (std::is_same_v<T, bool>) return ParamKind::flag;
  else if constexpr (std::is_same_v<T, int>) return ParamKind::integer;
  else if constexpr (std::is_same_v<T, double>) return ParamKind::number;
  else if constexpr (std::is_same_v<T, std::optional<double>>) return ParamKind::optional_number;
  else if constexpr (std::is_same_v<T, std::string>) return ParamKind::text;
  else if constexpr (ChoiceEnum<T>) return ParamKind::choice;
  else if constexpr (IsStdArray<T>::value) return ParamKind::numbers;
  else return ParamKind::list;  // lists of points and of objects
}

template <class S>
class TableWriter {
 public:
  TableWriter(std::vector<ParamRow>& rows, std::string prefix, const S& defaults)
      : rows_(rows), prefix_(std::move(prefix)), defaults_(defaults) {}

  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    const std::string key = joinKey(prefix_, info.key);
    if constexpr (std::is_class_v<T> && !IsStdArray<T>::value && !IsStructVector<T>::value &&
                  !IsPointList<T>::value && !std::is_same_v<T, std::string> && !std::is_same_v<T, std::optional<double>>)
      tabulateParams(rows_, key, defaults_.*member);
    else
      rows_.push_back({key, paramKindOf<T>(), infoFor<T>(info), toJson(defaults_.*member)});
  }

 private:
  std::vector<ParamRow>& rows_;
  std::string prefix_;
  const S& defaults_;
};
}  // namespace detail

template <class S>
void tabulateParams(std::vector<ParamRow>& rows, const std::string& prefix, const S& values) {
  detail::TableWriter<S> writer(rows, prefix, values);
  S::describe(writer);
}

/// The rows of S, keys from its top level, defaults those of S{}.
template <class S>
std::vector<ParamRow> paramTable() {
  std::vector<ParamRow> rows;
  tabulateParams(rows, "", S{});
  return rows;
}

/// The row called `key`; nullptr if there is none.
const ParamRow* findParamRow(const std::vector<ParamRow>& rows, const std::string& key);

}  // namespace fluidviz::scene
