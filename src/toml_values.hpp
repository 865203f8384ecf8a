#pragma once
// Internal: how bat and study files quote the values they reject, the same in every message.
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include <toml++/toml.h>

#include "sweetspot/units/quantity.hpp"

namespace sweetspot::detail {

// A number as the user wrote it, without binary round-off.
inline std::string format_number(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

// A value and the bound it broke, with as many significant digits as tell them apart (at least 6,
// the same for both): z = 0.840000002 beside a bat of 0.84 m, not 0.84 beside 0.840000.
inline std::pair<std::string, std::string> format_apart(double value, double bound) {
  for (int digits = 6;; ++digits) {
    std::ostringstream a, b;
    a.precision(digits), b.precision(digits);
    a << value, b << bound;
    if (a.str() != b.str() || digits >= 17 || value == bound) return {a.str(), b.str()};
  }
}

// A string as TOML writes it in basic form.
inline std::string quote(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto code = static_cast<unsigned char>(c);
    if (code < 0x20 || code == 0x7f) {  // as TOML escapes it: the message stays one printable line
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04X", code);
      out += escaped;
    } else {
      out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
    }
  }
  return out + "\"";
}

// Names as a message lists them: "a, b, c".
template <class Names>
std::string join(const Names& names) {
  std::string list;
  for (const auto& name : names) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

// A number's value as a double: toml++ gives nothing for an integer a double cannot hold exactly
// (2^63 - 1), which is then taken as the nearest double.
inline std::optional<double> number(const toml::node& node) {
  if (node.is_integer()) return static_cast<double>(node.as_integer()->get());
  if (node.is_floating_point()) return node.as_floating_point()->get();
  return std::nullopt;
}

// A TOML value as written, with its type when that is not a plain number: an integer in all its
// digits (9223372036854775807, not the double it rounds to).
inline std::string describe(const toml::node& node) {
  if (node.is_integer()) return std::to_string(node.as_integer()->get());
  if (node.is_number()) return format_number(*node.value<double>());
  if (node.is_boolean()) return std::string(node.as_boolean()->get() ? "true" : "false") + " (boolean)";
  if (node.is_string()) return quote(node.as_string()->get()) + " (string)";
  std::ostringstream out;
  if (node.is_table())
    out << "{...}";
  else if (node.is_array())
    out << "[...]";
  else
    node.visit([&](const auto& value) { out << value; });
  out << " (" << node.type() << ")";
  return out.str();
}

// A length, mass, speed... as a file gives it: a number, in SI units as ever, or a string with
// its unit ("33 in", "136 mph": units/quantity.hpp). A number passes as it is (the caller's own
// checks refuse NaN, as before); a string that is not a finite quantity of that dimension, or any
// other type, gives nothing, for the caller to refuse with its own message.
inline std::optional<double> quantity(const toml::node& node, Dimension dimension) {
  if (node.is_number()) return number(node);
  if (node.is_string()) return parse_quantity(node.as_string()->get(), dimension);
  return std::nullopt;
}

// The value of a key that takes a quantity, where a string is one of the forms expected and so
// needs no "(string)" after it.
inline std::string describe_quantity(const toml::node& node) {
  return node.is_string() ? quote(node.as_string()->get()) : describe(node);
}

}  // namespace sweetspot::detail
