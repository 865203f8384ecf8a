#pragma once
// A bat given by named dimensions, as bats are specified and turned (README "Bat files"): a knob,
// a straight handle, a linear taper (a frustum) to a straight barrel, and an end cap; for a hollow
// bat, a wall thickness. The shape becomes a Profile of knots, cut into slices like any other.
// No I/O here: bat_file.hpp reads the [dimensions] table.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "sweetspot/bat/profile.hpp"

namespace sweetspot {

// The barrel's end:
//   flat     cut square at the bat's length
//   rounded  a half-ellipsoid of depth end_depth: the radius falls as R cos(theta) while z rises as
//            end_depth sin(theta) (16 frustums through points of that arc)
//   cupped   a cylindrical bore end_depth deep into the end, of cup_diameter (half the barrel's)
enum class EndShape { flat, rounded, cupped };

struct Dimensions {
  double knob_diameter = 0;    // m
  double knob_length = 0;      // m, the knob's thickness along the bat
  double handle_diameter = 0;  // m, straight from the knob to taper_start
  double taper_start = 0;      // m from the knob, where the handle starts to widen
  double taper_end = 0;        // m from the knob, where the barrel reaches barrel_diameter
  double barrel_diameter = 0;  // m, straight from taper_end to the end cap
  EndShape end = EndShape::flat;
  double end_depth = 0;       // m: the rounded end's or the cup's depth; 0 for a flat end
  double wall_thickness = 0;  // m: a hollow bat's wall; 0 for a solid one
};

// The numeric dimensions by name, in the order a bat file lists them: how files and studies
// (set_design_parameter) address them. An optional one is 0 when absent, the others are positive;
// a wall, once given, is positive too (0 is a solid bat's, which leaves the key out).
struct DimensionField {
  std::string_view name;
  double Dimensions::*value;
  bool optional = false;
  bool positive_when_given = false;
};
inline constexpr std::array<DimensionField, 8> dimension_fields = {{
    {"knob_diameter", &Dimensions::knob_diameter},
    {"knob_length", &Dimensions::knob_length},
    {"handle_diameter", &Dimensions::handle_diameter},
    {"taper_start", &Dimensions::taper_start},
    {"taper_end", &Dimensions::taper_end},
    {"barrel_diameter", &Dimensions::barrel_diameter},
    {"end_depth", &Dimensions::end_depth, true},
    {"wall_thickness", &Dimensions::wall_thickness, true, true},
}};

// The cup's bore: half the barrel's diameter, the middle of the 1 to 2 in the major-league rule
// allows for any barrel from 2 to 2 3/4 in (README).
double cup_diameter(const Dimensions& d);

// The bat's shape for a length (m), linear between knots: steps at the knob's shoulder and the
// cup's bore are repeated knots. A hollow bat's bore is the handle's along knob and handle, then
// follows the outer surface wall_thickness in (a rounded end's shell stops at the axis).
Profile dimensions_profile(const Dimensions& d, double length);

// The first rule of a possible bat that the dimensions break, with the parameter it is about.
struct RuleBreak {
  std::string parameter;  // "barrel_diameter", "length", "density", ... (no "bat." prefix)
  std::string message;    // one line naming the parameter(s), the value(s) and the rule
};
std::optional<RuleBreak> dimensions_rule_break(const Dimensions& d, double length);

const char* to_string(EndShape end);
// Throws InputError for anything but "flat", "rounded" or "cupped".
EndShape parse_end_shape(std::string_view text);

}  // namespace sweetspot
