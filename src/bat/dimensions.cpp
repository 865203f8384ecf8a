#include "sweetspot/bat/dimensions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "sweetspot/bat/parameter_bounds.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

using detail::format_number;

// Frustums through the rounded end's arc: its volume within 0.3 % of the half-ellipsoid's (0.24 %), i.e.
// a few hundredths of a gram on a wood bat.
constexpr int rounded_end_pieces = 16;

std::string metres(std::string_view name, double value) {
  return std::string(name) + " " + format_number(value) + " m";
}

RuleBreak broken(std::string_view name, std::string message) { return {std::string(name), std::move(message)}; }

// Every dimension finite; those that make the bat positive, the optional ones at least 0; and any
// given within its range (parameter_bounds.hpp).
std::optional<RuleBreak> value_rule_break(const Dimensions& d) {
  for (const DimensionField& f : dimension_fields) {
    const double x = d.*f.value;
    if (!std::isfinite(x)) return broken(f.name, metres(f.name, x) + " is not a finite number");
    if (f.optional ? x < 0 : x <= 0)
      return broken(f.name, metres(f.name, x) + (f.optional ? " is negative; expected 0 (none) or more"
                                                            : " is not positive; expected a positive length"));
    if (x > 0)
      if (auto outside = bound_break(f.name, x)) return broken(f.name, std::move(*outside));
  }
  return std::nullopt;
}

std::optional<RuleBreak> diameter_rule_break(const Dimensions& d) {
  const std::string handle = metres("handle_diameter", d.handle_diameter);
  if (d.barrel_diameter < d.handle_diameter)
    return broken("barrel_diameter", metres("barrel_diameter", d.barrel_diameter) + " is less than " + handle +
                                         "; expected a barrel at least as thick as the handle");
  if (d.knob_diameter < d.handle_diameter)
    return broken("knob_diameter", metres("knob_diameter", d.knob_diameter) + " is less than " + handle +
                                       "; expected a knob at least as thick as the handle");
  return std::nullopt;
}

// Along the bat: knob, handle, taper and barrel in that order, each of some length, then the end.
std::optional<RuleBreak> order_rule_break(const Dimensions& d, double length) {
  const double barrel_end = length - d.end_depth;
  const std::string order = "; expected knob_length < taper_start < taper_end < length - end_depth (" +
                            format_number(barrel_end) + " m)";
  if (d.taper_start <= d.knob_length)
    return broken("taper_start", metres("taper_start", d.taper_start) + " is not beyond " +
                                     metres("knob_length", d.knob_length) + order);
  if (d.taper_end <= d.taper_start)
    return broken("taper_end", metres("taper_end", d.taper_end) + " is not beyond " +
                                   metres("taper_start", d.taper_start) + order);
  if (d.taper_end >= barrel_end)
    return broken("taper_end", metres("taper_end", d.taper_end) + " is not short of length " + format_number(length) +
                                   " m less end_depth " + format_number(d.end_depth) + " m" + order);
  return std::nullopt;
}

std::optional<RuleBreak> end_rule_break(const Dimensions& d) {
  const std::string end = std::string(" with end '") + to_string(d.end) + "'";
  if (d.end == EndShape::flat && d.end_depth > 0)
    return broken("end_depth", metres("end_depth", d.end_depth) + end +
                                   "; expected 0 (a flat end has no depth), or end 'rounded' or 'cupped'");
  if (d.end != EndShape::flat && d.end_depth == 0)
    return broken("end_depth", metres("end_depth", d.end_depth) + end + "; expected the end's depth, positive");
  if (d.end == EndShape::cupped && d.wall_thickness > 0)
    return broken("wall_thickness", metres("wall_thickness", d.wall_thickness) + end +
                                        "; expected a solid bat (wall_thickness 0) to cup, or end 'flat' or "
                                        "'rounded'");
  return std::nullopt;
}

// The handle is the thinnest part of the tube (knob and barrel are at least as thick).
std::optional<RuleBreak> wall_rule_break(const Dimensions& d) {
  if (d.wall_thickness < d.handle_diameter / 2) return std::nullopt;
  return broken("wall_thickness", metres("wall_thickness", d.wall_thickness) + " is not less than the handle's radius " +
                                      format_number(d.handle_diameter / 2) + " m (handle_diameter " +
                                      format_number(d.handle_diameter) + " m); expected a wall thinner than the radius");
}

}  // namespace

double cup_diameter(const Dimensions& d) { return d.barrel_diameter / 2; }

Profile dimensions_profile(const Dimensions& d, double length) {
  const bool hollow = d.wall_thickness > 0;
  const double wall = 2 * d.wall_thickness;
  const double handle_bore = hollow ? d.handle_diameter - wall : 0.0;
  const double barrel_bore = hollow ? d.barrel_diameter - wall : 0.0;
  Profile p;
  p.interpolation = Interpolation::linear;
  const auto knot = [&](double z, double outer, double inner) {
    p.z.push_back(z);
    p.outer.push_back(outer);
    p.inner.push_back(inner);
  };
  knot(0, d.knob_diameter, handle_bore);
  knot(d.knob_length, d.knob_diameter, handle_bore);
  knot(d.knob_length, d.handle_diameter, handle_bore);
  knot(d.taper_start, d.handle_diameter, handle_bore);
  knot(d.taper_end, d.barrel_diameter, barrel_bore);
  const double barrel_end = length - d.end_depth;
  switch (d.end) {
    case EndShape::flat: knot(length, d.barrel_diameter, barrel_bore); break;
    case EndShape::cupped:
      knot(barrel_end, d.barrel_diameter, 0);
      knot(barrel_end, d.barrel_diameter, cup_diameter(d));
      knot(length, d.barrel_diameter, cup_diameter(d));
      break;
    case EndShape::rounded:
      for (int k = 0; k <= rounded_end_pieces; ++k) {
        const double theta = std::numbers::pi / 2 * k / rounded_end_pieces;
        // The tip exactly at the length, of diameter exactly 0.
        const double z = k == rounded_end_pieces ? length : barrel_end + d.end_depth * std::sin(theta);
        const double outer = k == rounded_end_pieces ? 0.0 : d.barrel_diameter * std::cos(theta);
        knot(z, outer, hollow ? std::max(outer - wall, 0.0) : 0.0);
      }
      break;
  }
  // A solid bat without a cup has no bore at all: a solid Bat, as a profile without inner diameters.
  if (!hollow && d.end != EndShape::cupped) p.inner.clear();
  return p;
}

std::optional<RuleBreak> dimensions_rule_break(const Dimensions& d, double length) {
  if (auto rule = value_rule_break(d)) return rule;
  if (auto rule = diameter_rule_break(d)) return rule;
  if (auto rule = order_rule_break(d, length)) return rule;
  if (auto rule = end_rule_break(d)) return rule;
  return wall_rule_break(d);
}

// The end shapes' names, in the enum's order.
constexpr std::array<const char*, 3> end_names = {"flat", "rounded", "cupped"};

const char* to_string(EndShape end) { return end_names[static_cast<std::size_t>(end)]; }

EndShape parse_end_shape(std::string_view text) {
  for (std::size_t i = 0; i < end_names.size(); ++i)
    if (text == end_names[i]) return static_cast<EndShape>(i);
  throw InputError("end '" + std::string(text) + "': expected 'flat', 'rounded' or 'cupped'");
}

}  // namespace sweetspot
