#pragma once
// Internal to src/optimize: an optimisation file's values read with the study files' one-line
// refusals (study_settings.hpp: "file:line: key 'free.density.min' = ...: expected ..."), and the
// sections read in files of their own.
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "study/study_settings.hpp"
#include "sweetspot/optimize/problem.hpp"
#include "toml_values.hpp"

namespace sweetspot::optimize_detail {

using detail::describe;
using detail::format_number;
using detail::quote;
using study_detail::reject;
using study_detail::reject_unknown;
using study_detail::Where;

inline const toml::node* child(const toml::table& table, std::string_view key) { return table.get(key); }

// "expected ...", with the units a value of that dimension may be written in.
inline std::string expected_text(const std::string& expected, std::optional<Dimension> dimension) {
  std::string text = "expected " + expected;
  if (dimension) text.append(" ").append(quantity_hint(*dimension));
  return text;
}

// A value's refusal: with a dimension, the value may be a string with a unit ("28 in": toml_values.hpp).
[[noreturn]] inline void reject_value(const Where& at, const toml::node& node, const std::string& expected,
                                      std::optional<Dimension> dimension) {
  reject(at, dimension ? detail::describe_quantity(node) : describe(node), expected_text(expected, dimension));
}

// A finite number; with a dimension, also a string with a unit, read into SI.
inline double number(const Where& at, const toml::node& node, const std::string& expected,
                     std::optional<Dimension> dimension = std::nullopt) {
  const std::optional<double> x =
      dimension ? detail::quantity(node, *dimension) : detail::number(node);
  if (!x || !std::isfinite(*x)) reject_value(at, node, expected, dimension);
  return *x;
}

// A number that must satisfy `ok`; `fallback` when absent.
template <class Ok>
double number_key(const Where& table, const toml::table& t, std::string_view key, double fallback, Ok ok,
                  const std::string& expected, std::optional<Dimension> dimension = std::nullopt) {
  const toml::node* node = child(t, key);
  if (!node) return fallback;
  const Where at = table.child(key, *node);
  const double v = number(at, *node, expected, dimension);
  if (!ok(v)) reject_value(at, *node, expected, dimension);
  return v;
}

template <class Ok>
double required_number(const Where& table, const toml::table& t, std::string_view key, Ok ok,
                       const std::string& expected, std::optional<Dimension> dimension = std::nullopt) {
  if (!child(t, key)) reject(table.missing(key), "", expected_text(expected, dimension));
  return number_key(table, t, key, 0, ok, expected, dimension);
}

inline std::string string_key(const Where& table, const toml::table& t, std::string_view key, const std::string& fallback,
                       const std::string& expected) {
  const toml::node* node = child(t, key);
  if (!node) return fallback;
  // A NUL character would cut the text short where a dataset stores it (an HDF5 string ends there).
  const std::string* value = node->is_string() ? &node->as_string()->get() : nullptr;
  if (!value || value->empty()) reject(table.child(key, *node), describe(*node), "expected " + expected);
  if (value->find('\0') != std::string::npos)
    reject(table.child(key, *node), describe(*node), "expected " + expected + " without NUL characters");
  return *value;
}

inline const toml::table& table_key(const Where& parent, const toml::table& t, std::string_view key, bool required) {
  static const toml::table empty;
  const toml::node* node = child(t, key);
  if (!node) {
    if (required) reject(parent.missing(key), "", "expected a table [" + std::string(key) + "]");
    return empty;
  }
  if (!node->is_table()) reject(parent.child(key, *node), describe(*node), "expected a table [" + std::string(key) + "]");
  return *node->as_table();
}


inline constexpr auto finite = [](double) { return true; };
inline constexpr auto positive = [](double v) { return v > 0; };

// The shortest design the bounds allow: every impact point and the rig must fit it.
double shortest_length(const OptimizationProblem& problem);

// [objective] (problem_objective.cpp): what to maximise, its impact points on the shortest design.
ObjectiveSpec read_objective(const Where& top, const toml::table& doc, double length);

// [constraints] (problem_constraints.cpp): the standard's measure and rules, and the windows.
void read_constraints(const Where& top, const toml::table& doc, OptimizationProblem& problem);
// The rig must fit every design: its pivot before the scanned barrel of the shortest.
void check_rig(const Where& top, const OptimizationProblem& problem, double length);

}  // namespace sweetspot::optimize_detail
