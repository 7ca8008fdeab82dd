#pragma once
// Checks a parameter struct against its own describe() declaration (fieldviz/core/Params.h):
// numbers inside [min, max] (minExclusive, maxExclusive honoured), strings among `choices`
// (a choice enum must hold one of its declared values), recursing into
// nested structs and vectors of structs. The scene reader applies the same rules while it reads
// JSON; this lets a filter core reject values that were set from C++ with the same message.
// Header-only and free of dependencies beyond Params.h so that every solver and filter core can
// use it.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "fieldviz/core/Params.h"

namespace fluidviz::params {

template <class S>
void checkRanges(const S& s, const std::string& prefix = "");

namespace detail {

inline std::string joinKey(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

inline void checkNumber(double v, const std::string& key, const ParamInfo& info) {
  if (inRange(v, info)) return;
  throw ParamError(key, "is " + formatNumber(v, 10) + (info.unit.empty() ? "" : " " + info.unit) +
                            ", outside the allowed range " + describeRange(info) + " (" +
                            info.description + ")");
}

inline void check(bool, const std::string&, const ParamInfo&) {}
inline void check(int v, const std::string& key, const ParamInfo& info) {
  checkNumber(v, key, info);
}
inline void check(double v, const std::string& key, const ParamInfo& info) {
  checkNumber(v, key, info);
}
inline void check(const std::optional<double>& v, const std::string& key, const ParamInfo& info) {
  if (v) checkNumber(*v, key, info);
}
inline void check(const std::string& v, const std::string& key, const ParamInfo& info) {
  if (info.choices.empty()) return;
  for (const auto& c : info.choices)
    if (c == v) return;
  throw ParamError(key, "is \"" + v + "\", allowed " + describeRange(info));
}
/// A value that is none of the declared ones can only come from a cast or corrupt memory.
template <ChoiceEnum E>
void check(E v, const std::string& key, const ParamInfo& info) {
  for (const Choice<E>& c : paramChoices(E{}))
    if (c.value == v) return;
  throw ParamError(key, "is the value " + std::to_string(static_cast<int>(v)) +
                            ", allowed " + describeRange(infoFor<E>(info)));
}
template <std::size_t N>
void check(const std::array<double, N>& v, const std::string& key, const ParamInfo& info) {
  for (std::size_t i = 0; i < N; ++i) checkNumber(v[i], key + "[" + std::to_string(i) + "]", info);
}
template <std::size_t N>
void check(const std::vector<std::array<double, N>>& v, const std::string& key,
           const ParamInfo& info) {
  for (std::size_t i = 0; i < v.size(); ++i) check(v[i], key + "[" + std::to_string(i) + "]", info);
}
template <class T>
void check(const std::vector<T>& v, const std::string& key, const ParamInfo&) {
  for (std::size_t i = 0; i < v.size(); ++i) checkRanges(v[i], key + "[" + std::to_string(i) + "]");
}
template <class T>
  requires std::is_class_v<T>
void check(const T& v, const std::string& key, const ParamInfo&) {
  checkRanges(v, key);
}

template <class S>
struct RangeChecker {
  const S& s;
  std::string prefix;
  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    check(s.*member, joinKey(prefix, info.key), info);
  }
};

}  // namespace detail

/// Throws ParamError(key, "is <v>, outside the allowed range [a, b] (<description>)") for the
/// first member of `s` outside its declared range or choices.
template <class S>
void checkRanges(const S& s, const std::string& prefix) {
  detail::RangeChecker<S> checker{s, prefix};
  S::describe(checker);
}

}  // namespace fluidviz::params
