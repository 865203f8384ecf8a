#include "quantity_option.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <optional>
#include <string>
#include <system_error>

namespace sweetspot::app {

namespace {

// A number CLI11 reads as it always has: the option's meaning of a plain number is unchanged.
bool plain_number(const std::string& text) {
  const std::string_view digits = std::string_view(text).substr(text.starts_with('+') ? 1 : 0);
  double x = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
  return !digits.empty() && ec == std::errc() && end == digits.data() + digits.size();
}

// 17 significant digits: CLI11 reads back the very double.
std::string exact_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string expected(Dimension dimension, std::string_view plain_unit) {
  if (plain_unit.empty()) return expected_quantity(dimension);
  std::string hint = quantity_hint(dimension);
  const std::string si = "a number in " + std::string(si_unit(dimension));
  hint.replace(hint.find(si), si.size(), "a number in " + std::string(plain_unit));
  return "a " + std::string(dimension_name(dimension)) + " " + hint;
}

// The option's type in --help: "FLOAT:length", "FLOAT:angular_speed".
std::string type_name(Dimension dimension) {
  std::string name(dimension_name(dimension));
  std::ranges::replace(name, ' ', '_');
  return name;
}

}  // namespace

CLI::Validator quantity_option(Dimension dimension, std::string_view plain_unit) {
  const Unit* unit = plain_unit.empty() ? nullptr : find_unit(plain_unit);
  return CLI::Validator(
      [dimension, unit, plain_unit](std::string& value) -> std::string {
        if (plain_number(value)) return {};
        const std::optional<double> si = parse_quantity(value, dimension);
        if (!si) return "\"" + value + "\": expected " + expected(dimension, plain_unit);
        value = exact_text(unit ? in_unit(*si, *unit) : *si);
        return {};
      },
      type_name(dimension));
}

}  // namespace sweetspot::app
