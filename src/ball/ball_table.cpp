#include "ball/ball_table.hpp"

#include <array>
#include <cmath>
#include <string_view>

#include "sweetspot/ball/ball_presets.hpp"
#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot::detail {

namespace {

constexpr std::array<std::string_view, 14> known_keys = {
    "preset", "mass", "radius", "cor", "cor_speed", "cor_slope", "dynamic_stiffness", "stiffness_speed",
    "stiffness_cylinder_diameter", "compression", "compression_displacement", "k1", "a", "curved_contact"};

// Where a message about `node` starts: "FILE:LINE: [ball]", its line as the file gives it.
std::string at(const std::string& file, const toml::node& node) {
  std::string where = file;
  if (const auto line = node.source().begin.line; line > 0) (where += ':') += std::to_string(line);
  return where + ": [ball]";
}

[[noreturn]] void reject(const std::string& file, std::string_view key, const toml::node& node,
                         const std::string& expected) {
  throw InputError(at(file, node) + ": " + std::string(key) + " = " + describe(node) + ": expected " + expected);
}

double number(const toml::table& t, std::string_view key, const std::string& file) {
  const toml::node& node = *t.get(key);
  if (!node.is_number()) reject(file, key, node, "a number");
  return *detail::number(node);
}

// A mass, length or speed: a number in SI or a string with its unit ("5.125 oz", "60 mph").
double quantity_at(const toml::node& node, std::string_view key, Dimension dimension, const std::string& file) {
  const std::optional<double> x = quantity(node, dimension);
  if (!x || !std::isfinite(*x))
    throw InputError(at(file, node) + ": " + std::string(key) + " = " + describe_quantity(node) + ": expected " +
                     expected_quantity(dimension));
  return *x;
}

double quantity_key(const toml::table& t, std::string_view key, Dimension dimension, const std::string& file) {
  return quantity_at(*t.get(key), key, dimension, file);
}

// A quantity with its range (ball_tests.hpp), refused with the value as written ("0.001 oz").
double ranged_quantity(const toml::table& t, std::string_view key, Dimension dimension, BallRange range,
                       const std::string& file) {
  const double x = quantity_key(t, key, dimension, file);
  if (!in_range(range, x))
    throw InputError(at(file, *t.get(key)) + ": " + std::string(key) + " = " + describe_quantity(*t.get(key)) +
                     ": expected " +
                     range_text(range));
  return x;
}

// A value at one speed (`value_key` a number, at `speed_key` or 60 mph) or at several
// (`value_key` = [[speed, value], ...]).
std::vector<SpeedValue> speed_values(const toml::table& t, std::string_view value_key, std::string_view speed_key,
                                     const std::string& file) {
  const toml::node& node = *t.get(value_key);
  if (node.is_number()) {
    const double speed =
        t.contains(speed_key) ? quantity_key(t, speed_key, Dimension::speed, file) : 60 * metres_per_second_per_mph;
    return {{speed, *detail::number(node)}};
  }
  const toml::array* rows = node.as_array();
  if (!rows || rows->empty()) reject(file, value_key, node, "a number, or [[speed, value], ...] pairs");
  if (t.contains(speed_key)) reject(file, speed_key, *t.get(speed_key), "no speed beside [[speed, value], ...] pairs");
  std::vector<SpeedValue> values;
  for (const toml::node& row : *rows) {
    const toml::array* pair = row.as_array();
    if (!pair || pair->size() != 2 || !((*pair)[0].is_number() || (*pair)[0].is_string()) || !(*pair)[1].is_number())
      reject(file, value_key, row, "[speed, value] pairs (the speed in m/s or as \"60 mph\", the value a number)");
    values.push_back({quantity_at((*pair)[0], value_key, Dimension::speed, file), *detail::number((*pair)[1])});
  }
  return values;
}

// A stiffness given replaces the preset's, and the exponent that went with it (refitted or given).
void clear_stiffness(BallTests& t) {
  t.dynamic_stiffness.clear();
  t.compression_force = 0;
  t.k1 = 0;
  t.exponent = 0;
}

// A value that 0 would mean "absent" to the fit must be given as a positive number.
double positive_number(const toml::table& t, std::string_view key, const std::string& file) {
  const double x = number(t, key, file);
  if (!(x > 0) || !std::isfinite(x)) reject(file, key, *t.get(key), "a positive, finite number");
  return x;
}

}  // namespace

BallFit read_ball_table(const toml::table& table, const std::string& file) {
  for (const auto& [key, node] : table)
    if (std::ranges::find(known_keys, key.str()) == known_keys.end())
      throw InputError(at(file, node) + ": unknown key '" + std::string(key.str()) + "' (expected " +
                       join(known_keys) + ")");
  BallTests t;
  if (table.contains("preset")) {
    const toml::node& node = *table.get("preset");
    if (!node.is_string()) reject(file, "preset", node, "a preset's name");
    t = find_ball_preset(node.as_string()->get(), at(file, node)).tests;
  }
  if (table.empty())
    throw InputError(at(file, table) + ": is empty: expected a preset or the ball's test values (" + join(known_keys) +
                     ")");
  // One stiffness: two of them given would have one silently overrule the other.
  std::vector<std::string> stiffnesses;
  for (const char* key : {"dynamic_stiffness", "compression", "k1"})
    if (table.contains(key)) stiffnesses.emplace_back(key);
  if (stiffnesses.size() > 1)
    throw InputError(at(file, *table.get(stiffnesses.back())) + ": " + join(stiffnesses) +
                     " given together: expected one stiffness (dynamic_stiffness, compression or k1)");
  if (table.contains("mass")) t.mass = ranged_quantity(table, "mass", Dimension::mass, ball_mass_range, file);
  if (table.contains("radius"))
    t.radius = ranged_quantity(table, "radius", Dimension::length, ball_radius_range, file);
  if (table.contains("cor")) {
    // One COR beside a preset replaces the preset's at the preset's speed (unless cor_speed says
    // another) and keeps its slope, the ball's own fall with speed (unless cor_slope is given):
    // what is not given stays the preset's. CORs at several speeds are the whole law.
    const bool one = table.get("cor")->is_number(), from_preset = table.contains("preset") && t.cor.size() == 1;
    const double preset_speed = from_preset ? t.cor[0].speed : 0;
    t.cor = speed_values(table, "cor", "cor_speed", file);
    if (one && from_preset && !table.contains("cor_speed")) t.cor[0].speed = preset_speed;
    if (!(one && from_preset)) t.cor_slope = 0;
  } else if (table.contains("cor_speed")) {
    reject(file, "cor_speed", *table.get("cor_speed"), "cor beside it (the COR at that speed)");
  }
  if (table.contains("cor_slope")) t.cor_slope = number(table, "cor_slope", file);
  if (table.contains("dynamic_stiffness")) {
    clear_stiffness(t);
    t.dynamic_stiffness = speed_values(table, "dynamic_stiffness", "stiffness_speed", file);
  }
  if (table.contains("stiffness_cylinder_diameter"))
    t.stiffness_cylinder_diameter = ranged_quantity(table, "stiffness_cylinder_diameter", Dimension::length,
                                                    ball_cylinder_diameter_range, file);
  if (table.contains("compression")) {
    clear_stiffness(t);
    t.compression_force = positive_number(table, "compression", file);
  }
  if (table.contains("compression_displacement"))
    t.compression_displacement =  // at most the radius too: fit_ball
        ranged_quantity(table, "compression_displacement", Dimension::length, ball_displacement_range, file);
  if (table.contains("k1")) {
    clear_stiffness(t);
    t.k1 = positive_number(table, "k1", file);
  }
  if (table.contains("a")) t.exponent = positive_number(table, "a", file);
  if (table.contains("curved_contact")) {
    const toml::node& node = *table.get("curved_contact");
    if (!node.is_boolean()) reject(file, "curved_contact", node, "true or false");
    t.curved_contact = node.as_boolean()->get();
  }
  return fit_ball(t, file + ": [ball]");  // about the fit, not one line
}

}  // namespace sweetspot::detail
