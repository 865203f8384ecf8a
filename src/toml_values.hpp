#pragma once
// Internal: how bat and study files quote the values they reject, the same in every message.
#include <sstream>
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace sweetspot::detail {

// A number as the user wrote it, without binary round-off.
inline std::string format_number(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

// A string as TOML writes it in basic form.
inline std::string quote(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

// Names as a message lists them: "a, b, c".
template <class Names>
std::string join(const Names& names) {
  std::string list;
  for (const auto& name : names) list += (list.empty() ? "" : ", ") + std::string(name);
  return list;
}

// A TOML value as written, with its type when that is not a plain number.
inline std::string describe(const toml::node& node) {
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

}  // namespace sweetspot::detail
