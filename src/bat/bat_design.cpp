#include "sweetspot/bat/bat_design.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "sweetspot/bat/barrel_wall.hpp"
#include "sweetspot/bat/material_presets.hpp"
#include "sweetspot/bat/parameter_bounds.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

using detail::format_number;

struct MaterialField {
  std::string_view name, unit;
  double Material::*value;
};
constexpr std::array<MaterialField, 4> material_fields = {{
    {"density", "kg/m^3", &Material::density},
    {"youngs_modulus", "Pa", &Material::youngs_modulus},
    {"shear_modulus", "Pa", &Material::shear_modulus},
    {"shear_coefficient", "", &Material::shear_coefficient},
}};

// The wall's constants (barrel_wall.hpp) and the beam's loss factor, study axes like the others
// but with rules of their own: a hoop modulus of 0 stands for the isotropic wall (youngs_modulus),
// a loss factor lies in [0, 1).
constexpr std::array<MaterialField, 3> wall_fields = {{
    {"hoop_modulus", "Pa", &Material::hoop_modulus},
    {"wall_loss_factor", "", &Material::wall_loss_factor},
    {"loss_factor", "", &Material::loss_factor},
}};

std::string with_unit(double value, std::string_view unit) {
  std::string text = format_number(value);
  if (!unit.empty()) text.append(" ").append(unit);
  return text;
}

// Positive and finite, then within its range (parameter_bounds.hpp).
std::optional<RuleBreak> positive_rule_break(std::string_view name, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value > 0))
    return RuleBreak{std::string(name), std::string(name) + " " + with_unit(value, unit) + " is not a positive, finite number"};
  if (auto outside = bound_break(name, value)) return RuleBreak{std::string(name), std::move(*outside)};
  return std::nullopt;
}

// An isotropic G = E / 2(1 + nu) is E/3 to E/2 for nu from 0 to 0.5 (wood's is about E/16); a
// study may sweep E below a fixed G, but a shear modulus far above E (1e12 beside 1e6 Pa) makes
// the beam's stiffness singular at a thin handle.
constexpr double max_shear_to_youngs = 10;

std::optional<RuleBreak> shear_rule_break(const Material& m) {
  if (m.shear_modulus <= max_shear_to_youngs * m.youngs_modulus) return std::nullopt;
  return RuleBreak{"shear_modulus", "shear_modulus " + with_unit(m.shear_modulus, "Pa") + " exceeds 10 times youngs_modulus " +
                                        with_unit(m.youngs_modulus, "Pa") +
                                        "; expected at most 10 times youngs_modulus (G = E / 2(1 + nu) is E/3 to E/2 "
                                        "for nu from 0 to 0.5; wood's is about E/16)"};
}

std::optional<RuleBreak> wall_material_rule_break(const Material& m) {
  if (!(std::isfinite(m.hoop_modulus) && m.hoop_modulus >= 0))
    return RuleBreak{"hoop_modulus", "hoop_modulus " + with_unit(m.hoop_modulus, "Pa") +
                                         " is not a positive, finite number (or 0 for youngs_modulus)"};
  if (m.hoop_modulus > 0)
    if (auto outside = bound_break("hoop_modulus", m.hoop_modulus)) return RuleBreak{"hoop_modulus", std::move(*outside)};
  if (!(m.wall_loss_factor >= 0 && m.wall_loss_factor < 1))
    return RuleBreak{"wall_loss_factor", "wall_loss_factor " + format_number(m.wall_loss_factor) + " is not in [0, 1)"};
  if (!(m.loss_factor >= 0 && m.loss_factor < 1))
    return RuleBreak{"loss_factor", "loss_factor " + format_number(m.loss_factor) + " is not in [0, 1)"};
  return std::nullopt;
}

// A knot profile keeps its knots when the length changes: they must stay on the bat.
std::optional<RuleBreak> knot_rule_break(const BatDesign& d) {
  if (d.dimensions || d.slice_profile || d.profile.z.empty()) return std::nullopt;
  const double last = d.profile.z.back();
  if (last <= d.length * (1 + 1e-9)) return std::nullopt;  // a rounding's worth, as the file's check
  return RuleBreak{"length", "knot at z_m = " + format_number(last) + " m lies beyond length " + format_number(d.length) +
                                 " m; expected every knot on the bat (a length of at least " + format_number(last) + " m)"};
}

// A profile's diameters and, where it is hollow, its wall (thinnest anywhere, between knots too)
// within their ranges. "profile" is no parameter a study sets: the bat file is to blame.
std::optional<RuleBreak> profile_rule_break(const Profile& p) {
  for (std::size_t i = 0; i < p.z.size(); ++i)
    if (auto outside = bound_break(profile_outer_diameter, p.outer[i]))
      return RuleBreak{"profile", "at z = " + format_number(p.z[i]) + " m, " + *outside};
  if (p.inner.empty() || std::ranges::none_of(p.inner, [](double d) { return d > 0; })) return std::nullopt;
  // A solid stretch of a partly hollow profile is as thick as its diameter: the knots with a bore
  // and the intervals between them are what thinnest_wall weighs.
  const ThinnestWall thinnest = thinnest_wall(p);
  if (auto outside = bound_break(profile_wall, thinnest.wall / 2))
    return RuleBreak{"profile", "at z = " + format_number(thinnest.z) + " m, the " + *outside};
  return std::nullopt;
}

// A knot profile's default slices: about 1 cm thick, as N2000's.
int default_slices(double length) {
  return std::clamp(static_cast<int>(std::lround(length / 0.01)), min_slices, max_slices);
}

// The parameter's place in the design (const or not), or nullptr.
template <class Design>
auto find_parameter(Design& d, std::string_view name) -> decltype(&d.length) {
  if (name == "length") return &d.length;
  for (const MaterialField& f : material_fields)
    if (name == f.name) return &(d.material.*f.value);
  for (const MaterialField& f : wall_fields)
    if (name == f.name) return &(d.material.*f.value);
  if (d.dimensions)
    for (const DimensionField& f : dimension_fields)
      if (name == f.name) return &(*d.dimensions.*f.value);
  return nullptr;
}

bool positive_when_given(std::string_view name) {
  if (name == "hoop_modulus") return true;
  const auto f = std::ranges::find(dimension_fields, name, &DimensionField::name);
  return f != dimension_fields.end() && f->positive_when_given;
}

// The parameter the design lacks: unknown, or a dimension of a bat given by a profile CSV.
[[noreturn]] void no_parameter(const BatDesign& d, std::string_view name, const std::string& value) {
  const bool dimension = std::ranges::find(dimension_fields, name, &DimensionField::name) != dimension_fields.end();
  throw InputError("bat parameter '" + std::string(name) + "'" + value + ": " +
                   (dimension ? "bat '" + d.name + "' is given by a profile CSV, not [dimensions]"
                              : std::string("no such parameter")) +
                   "; expected one of " + detail::join(design_parameters(d)));
}

}  // namespace

Bat build_bat(const BatDesign& design) {
  if (const auto rule = broken_rule(design)) throw InputError(*rule);
  Bat bat;
  bat.name = design.name;
  bat.length = design.length;
  bat.material = design.material;
  if (design.slice_profile) {
    bat.set_slices(design.profile.outer, design.profile.inner);
    if (design.slices) bat = resample(bat, *design.slices);
    return bat;
  }
  cut_into_slices(design_profile(design), design.slices.value_or(default_slices(design.length)), bat);
  return bat;
}

std::vector<std::string> design_parameters(const BatDesign& design) {
  std::vector<std::string> names = {"length"};
  for (const MaterialField& f : material_fields) names.emplace_back(f.name);
  for (const MaterialField& f : wall_fields) names.emplace_back(f.name);
  if (design.dimensions)
    for (const DimensionField& f : dimension_fields) names.emplace_back(f.name);
  return names;
}

std::optional<Dimension> design_parameter_dimension(std::string_view name) {
  if (name == "length" || std::ranges::find(dimension_fields, name, &DimensionField::name) != dimension_fields.end())
    return Dimension::length;
  return std::nullopt;
}

void set_design_parameter(BatDesign& design, std::string_view name, double value) {
  double* parameter = find_parameter(design, name);
  if (!parameter) no_parameter(design, name, " = " + format_number(value));
  // One diameter per slice fixes the slices' thickness and so the length.
  if (name == "length" && design.slice_profile && value != design.length)
    throw InputError("bat parameter 'length' = " + format_number(value) + ": bat '" + design.name +
                     "' lists one diameter per slice (z_center_m), which fixes its length at " +
                     format_number(design.length) + " m; expected " + format_number(design.length) +
                     ", or a bat of knots (z_m) or [dimensions] to vary the length");
  // 0 stands for "absent" (a hoop modulus as youngs_modulus, a solid bat's wall) only where a bat
  // file leaves the key out: a value set must be positive.
  if (positive_when_given(name) && !(value > 0 && std::isfinite(value)))
    throw InputError("bat parameter '" + std::string(name) + "' = " + format_number(value) +
                     ": expected a positive, finite value (0 stands for none only by leaving the key out of a bat file)");
  // A positive value outside its range is refused here, naming the range; 0, negatives and NaN
  // are left to the design's rules, which say what they stand for (a flat end's depth of 0).
  const ParameterBound* bound = parameter_bound(name);
  if (bound && value > 0 && std::isfinite(value) && !within(*bound, value))
    throw InputError("bat parameter '" + std::string(name) + "' = " + format_number(value) + ": expected " +
                     expected_range(*bound));
  *parameter = value;
}

double design_parameter(const BatDesign& design, std::string_view name) {
  const double* parameter = find_parameter(design, name);
  if (!parameter) no_parameter(design, name, "");
  return name == "hoop_modulus" ? design.material.wall_hoop_modulus() : *parameter;
}

const std::vector<std::string>& material_presets() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const MaterialPreset& p : material_preset_list()) out.push_back(p.name);
    return out;
  }();
  return names;
}

void set_material_preset(BatDesign& design, std::string_view name) {
  const MaterialPreset* preset = find_material_preset(name);
  if (!preset)
    throw InputError("material preset '" + std::string(name) + "': expected one of " + detail::join(material_presets()));
  // The shear coefficient is the beam's, not the wood's: it stays as the design has it.
  const double shear_coefficient = design.material.shear_coefficient;
  design.material = preset->material;
  design.material.shear_coefficient = shear_coefficient;
  design.material_name = preset->name;
}

std::optional<RuleBreak> rule_break(const BatDesign& design) {
  if (auto rule = positive_rule_break("length", design.length, "m")) return rule;
  for (const MaterialField& f : material_fields)
    if (auto rule = positive_rule_break(f.name, design.material.*f.value, f.unit)) return rule;
  if (auto rule = shear_rule_break(design.material)) return rule;
  if (auto rule = wall_material_rule_break(design.material)) return rule;
  if (design.dimensions) return dimensions_rule_break(*design.dimensions, design.length);
  if (auto rule = profile_rule_break(design.profile)) return rule;
  return knot_rule_break(design);
}

std::optional<std::string> broken_rule(const BatDesign& design) {
  const auto rule = rule_break(design);
  return rule ? std::optional(rule->message) : std::nullopt;
}

Profile design_profile(const BatDesign& design) {
  return design.dimensions ? dimensions_profile(*design.dimensions, design.length) : design.profile;
}

MassProperties design_mass_properties(const BatDesign& design) {
  return mass_properties(design_profile(design), design.length, design.material.density);
}

double largest_outer_diameter(const BatDesign& design) { return std::ranges::max(design_profile(design).outer); }

}  // namespace sweetspot
