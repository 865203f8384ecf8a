#pragma once
// The range each of a bat's numeric parameters may take, wherever it is given: a bat file (its
// keys and its profile's rows), a study's "bat.*" keys and axes, an optimisation's [free] bounds,
// Python's Bat.from_knots and from_dimensions. Every one of them reaches the model through
// BatDesign (set_design_parameter, rule_break), which consults this one table.
//
// The ranges are wide enough for any real or exploratory bat and material, and narrow enough that
// the model's numbers hold: a stiffness (E d^4) or a mass (rho d^2) that overflows or underflows,
// or a wall of a nanometre beside a beam of centimetres, makes the mode solve lose every digit.
#include <optional>
#include <string>
#include <string_view>

namespace sweetspot {

struct ParameterBound {
  std::string_view name;  // as design_parameters names it; "outer_diameter" and "wall" for a profile's rows
  double low = 0, high = 0;  // inclusive, in SI units
  std::string_view unit;     // "m", "kg/m^3", "Pa", or "" for a pure number
  std::string_view why;      // the reason for the range, for messages and the docs
};

// The parameter's range, or nullptr for one without a range of its own here (the loss factors,
// whose [0, 1) the design's own rules keep).
const ParameterBound* parameter_bound(std::string_view name);

// What a message expects: "0.001 to 1 m (why)".
std::string expected_range(const ParameterBound& bound);

bool within(const ParameterBound& bound, double value);

// "barrel_diameter 1e+300 m: expected 0.001 to 1 m (why)", or nothing when the value lies within
// its range (or the parameter has none).
std::optional<std::string> bound_break(std::string_view name, double value);

// A hollow profile's wall (half of outer less inner diameter) and its rows' outer diameters take
// these ranges: named here for the readers that check a profile row by row.
inline constexpr std::string_view profile_wall = "wall";
inline constexpr std::string_view profile_outer_diameter = "outer_diameter";

}  // namespace sweetspot
