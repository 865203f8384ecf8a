#include "sweetspot/units/quantity.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <system_error>
#include <vector>

namespace sweetspot {

namespace {

// The factors are exact: the inch is 0.0254 m, the pound 0.45359237 kg (and the ounce 1/16 of
// it), the mile 1609.344 m (so the mph 0.44704 m/s); inch_pound.hpp holds the same as doubles.
constexpr Unit unit_table[] = {
    {"m", Dimension::length, "1"},
    {"cm", Dimension::length, "0.01"},
    {"mm", Dimension::length, "0.001"},
    {"in", Dimension::length, "0.0254"},
    {"ft", Dimension::length, "0.3048"},
    {"kg", Dimension::mass, "1"},
    {"g", Dimension::mass, "0.001"},
    {"oz", Dimension::mass, "0.028349523125"},
    {"lb", Dimension::mass, "0.45359237"},
    {"m/s", Dimension::speed, "1"},
    {"km/h", Dimension::speed, "1", 1, 3.6},
    {"mph", Dimension::speed, "0.44704"},
    {"ft/s", Dimension::speed, "0.3048"},
    {"rad/s", Dimension::angular_speed, "1"},
    {"rpm", Dimension::angular_speed, "1", std::numbers::pi / 30},
    {"Hz", Dimension::frequency, "1"},
    {"kHz", Dimension::frequency, "1000"},
    {"rad", Dimension::angle, "1"},
    {"deg", Dimension::angle, "1", std::numbers::pi / 180},
    {"K", Dimension::temperature, "1"},
    {"C", Dimension::temperature, "1", 1, 1, 273.15},
    {"F", Dimension::temperature, "1", 5, 9, 459.67 * 5 / 9},
    {"Pa", Dimension::pressure, "1"},
    {"hPa", Dimension::pressure, "100"},
    {"kPa", Dimension::pressure, "1000"},
    {"mbar", Dimension::pressure, "100"},
    {"atm", Dimension::pressure, "101325"},
    {"mmHg", Dimension::pressure, "133.322387415"},   // 13.5951 g/cm^3 x 1 mm x 9.80665 m/s^2
    {"inHg", Dimension::pressure, "3386.388640341"},  // 25.4 mmHg
};

// A unit the users of that dimension write, for the example in messages.
std::string_view example(Dimension dimension) {
  switch (dimension) {
    case Dimension::length:
      return "28 in";
    case Dimension::mass:
      return "31 oz";
    case Dimension::speed:
      return "136 mph";
    case Dimension::angular_speed:
      return "600 rpm";
    case Dimension::frequency:
      return "1.5 kHz";
    case Dimension::angle:
      return "27.5 deg";
    case Dimension::temperature:
      return "70 F";
    case Dimension::pressure:
      return "29.92 inHg";
  }
  return "";
}

// A decimal number as its digits and a power of ten: -12.5e3 is {true, "125", 2}.
struct Decimal {
  bool negative = false;
  std::string digits;
  long exponent = 0;
};

// `text` is a number from_chars has read whole (so digits, at most one point, an exponent).
Decimal decimal(std::string_view text) {
  Decimal d;
  d.negative = text.starts_with('-');
  std::size_t i = d.negative ? 1 : 0;
  bool after_point = false;
  for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
    if (text[i] == '.') {
      after_point = true;
      continue;
    }
    d.digits += text[i];
    if (after_point) --d.exponent;
  }
  if (i < text.size()) {
    const std::string_view power = text.substr(i + 1 + (text[i + 1] == '+'));
    long e = 0;
    std::from_chars(power.data(), power.data() + power.size(), e);  // in range: the double was
    d.exponent += e;
  }
  return d;
}

// The product of two digit strings, schoolbook.
std::string multiply(const std::string& a, const std::string& b) {
  std::vector<int> sum(a.size() + b.size(), 0);
  for (std::size_t i = a.size(); i-- > 0;)
    for (std::size_t j = b.size(); j-- > 0;) sum[i + j + 1] += (a[i] - '0') * (b[j] - '0');
  for (std::size_t k = sum.size(); k-- > 1;) {
    sum[k - 1] += sum[k] / 10;
    sum[k] %= 10;
  }
  std::string digits;
  for (const int d : sum) digits += static_cast<char>('0' + d);
  return digits;
}

// `number` times the decimal `factor`, computed exactly and rounded once to a double.
double exact_product(std::string_view number, std::string_view factor) {
  const Decimal x = decimal(number), f = decimal(factor);
  std::string text = x.negative ? "-" : "";
  text.append(multiply(x.digits, f.digits)).append("e").append(std::to_string(x.exponent + f.exponent));
  double product = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), product);
  return ec == std::errc() ? product : std::nan("");  // out of a double's range
}

std::string_view trim(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::span<const Unit> units() { return unit_table; }

const Unit* find_unit(std::string_view name) {
  const auto it = std::ranges::find(unit_table, name, &Unit::name);
  return it == std::end(unit_table) ? nullptr : &*it;
}

std::string_view dimension_name(Dimension dimension) {
  switch (dimension) {
    case Dimension::length:
      return "length";
    case Dimension::mass:
      return "mass";
    case Dimension::speed:
      return "speed";
    case Dimension::angular_speed:
      return "angular speed";
    case Dimension::frequency:
      return "frequency";
    case Dimension::angle:
      return "angle";
    case Dimension::temperature:
      return "temperature";
    case Dimension::pressure:
      return "pressure";
  }
  return "";
}

std::string_view si_unit(Dimension dimension) {
  return std::ranges::find(unit_table, dimension, &Unit::dimension)->name;
}

std::string quantity_hint(Dimension dimension) {
  std::string names;
  for (const Unit& unit : unit_table)
    if (unit.dimension == dimension) names += (names.empty() ? "" : ", ") + std::string(unit.name);
  return "(a number in " + std::string(si_unit(dimension)) + ", or a string such as \"" +
         std::string(example(dimension)) + "\"; units " + names + ")";
}

std::string expected_quantity(Dimension dimension) {
  const std::string_view name = dimension_name(dimension);
  return std::string(name.starts_with('a') ? "an " : "a ") + std::string(name) + " " + quantity_hint(dimension);
}

std::optional<double> parse_quantity(std::string_view text, Dimension dimension) {
  text = trim(text);
  if (text.starts_with('+')) text.remove_prefix(1);
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || !std::isfinite(value)) return std::nullopt;
  const std::string_view number = text.substr(0, static_cast<std::size_t>(end - text.data()));
  const Unit* unit = find_unit(trim(text.substr(number.size())));
  if (!unit || unit->dimension != dimension) return std::nullopt;
  double si = exact_product(number, unit->si);
  if (unit->multiplier != 1 || unit->divisor != 1) si = si * unit->multiplier / unit->divisor;
  si += unit->offset;
  return std::isfinite(si) ? std::optional(si) : std::nullopt;
}

double in_unit(double si, const Unit& unit) {
  double factor = 0;
  std::from_chars(unit.si.data(), unit.si.data() + unit.si.size(), factor);
  return (si - unit.offset) * unit.divisor / unit.multiplier / factor;
}

}  // namespace sweetspot
