#pragma once
// A bat as a designer gives it, before it is cut into slices: a name, a length, a material and a
// shape, the shape a profile (a CSV of slices or knots) or named dimensions (dimensions.hpp).
// Studies sweep its parameters by name ("bat.barrel_diameter", "bat.density"); every set of
// values is checked against the rules of a possible bat before any work. No I/O here but
// load_bat_design; bat_file.hpp reads the files.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/dimensions.hpp"
#include "sweetspot/bat/profile.hpp"
#include "sweetspot/units/quantity.hpp"

namespace sweetspot {

struct BatDesign {
  std::string name;
  double length = 0;  // m
  Material material;
  std::string material_name;  // the preset's name ("maple", ...), or empty for constants as given
  // The shape: named dimensions when given, else the profile read from the CSV.
  std::optional<Dimensions> dimensions;
  Profile profile;
  bool slice_profile = false;  // the CSV listed one diameter per slice (z_center_m)
  std::optional<int> slices;   // the bat file's `slices`, if any
};

// Reads a bat file (README "Bat files"); throws InputError as load_bat does.
BatDesign load_bat_design(const std::filesystem::path& toml_path, BatSource& source);

// The same from texts already read (a dataset's bat_toml and bat_profile): source.toml_text is
// the bat file, source.profile_text the profile it names (unused for [dimensions]), and
// source.toml_file a name for the messages (the profile's path is taken relative to it, for the
// messages too). Sets source.profile_file. Throws InputError as load_bat_design does, and when
// the file names a profile but source.profile_text is empty.
BatDesign bat_design_from_texts(BatSource& source);

// The bat the design describes, cut into its slices (the design's own count, the profile's rows,
// or about 1 cm each). Throws InputError naming the rule broken, as broken_rule.
Bat build_bat(const BatDesign& design);

// The numeric parameters a study may sweep on this design ("length", "density",
// "youngs_modulus", "shear_modulus", "shear_coefficient", and for dimensions every dimension
// name), without the "bat." prefix.
std::vector<std::string> design_parameters(const BatDesign& design);

// Sets one; throws InputError naming the parameter, the value and what was expected when the
// design has no such parameter (e.g. a dimension of a bat given by a CSV profile).
void set_design_parameter(BatDesign& design, std::string_view name, double value);
// The value the bat takes for it: an absent hoop_modulus (stored as 0) is the Young's modulus.
double design_parameter(const BatDesign& design, std::string_view name);
// Length for the length and every dimension (which may then be written "2.625 in"); nothing for
// the material's constants, which are read in SI only.
std::optional<Dimension> design_parameter_dimension(std::string_view name);

// The wood presets, with their sources (README): names, and setting one as the material.
const std::vector<std::string>& material_presets();
void set_material_preset(BatDesign& design, std::string_view name);  // throws InputError

// The first rule the design breaks ("barrel_diameter 0.02 m is less than handle_diameter
// 0.025 m", "knot at z_m = 0.9 m lies beyond length 0.84 m", "wall_thickness ... is not less
// than the barrel's radius ..."), or nothing for a possible bat.
std::optional<std::string> broken_rule(const BatDesign& design);
// The same, with the parameter the rule is about: what a bat file's message names as its key.
std::optional<RuleBreak> rule_break(const BatDesign& design);

// The design's shape as knots: its dimensions' profile, or the profile read from the CSV.
Profile design_profile(const BatDesign& design);

// The exact mass properties of the designed shape (integrated over the profile, not the slices):
// what a designer weighs and swings. mass kg; balance point (CM) m from the knob; MOI about the CM.
MassProperties design_mass_properties(const BatDesign& design);

// The designed shape's largest outer diameter, m: the barrel diameter the rules bound.
double largest_outer_diameter(const BatDesign& design);

}  // namespace sweetspot
