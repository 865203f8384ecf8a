#include "study_keys.hpp"

#include <algorithm>
#include <cmath>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/ball/ball_tests.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/impact/equal_effort.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/histories.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace study_detail {

namespace {

bool any(double) { return true; }
bool finite(double x) { return std::isfinite(x); }
bool positive(double x) { return std::isfinite(x) && x > 0; }
bool on_bat(double x) { return std::isfinite(x) && x >= 0; }  // the bats' lengths: check_on_bats
bool non_positive(double x) { return std::isfinite(x) && x <= 0; }
bool cor_speed(double x) { return x >= 0 && x <= max_cor_law_speed; }
bool slice_count(double x) { return x >= min_slices && x <= max_slices; }  // as `impact --slices`
// The ball's values as a [ball] table takes them (ball_tests.hpp).
bool ball_mass(double x) { return in_range(ball_mass_range, x); }
bool ball_radius(double x) { return in_range(ball_radius_range, x); }
bool ball_k1(double x) { return in_range(ball_k1_range, x); }
bool ball_exponent(double x) { return in_range(ball_exponent_range, x); }
bool ball_cor(double x) { return in_range(ball_cor_range, x); }
bool swing_exponent(double x) { return valid_swing_exponent(x); }
bool mode_count(double x) { return x >= 0 && x <= 1e6; }    // "all" and "auto" are not checked
bool total_accuracy(double x) { return x >= min_accuracy && x <= max_accuracy; }
bool air_temperature(double x) { return x > min_air_temperature && x < max_air_temperature; }
bool elevation(double x) { return x > -1000 && x < 10000; }
bool humidity(double x) { return x >= 0 && x <= 100; }

constexpr KeySpec keys[] = {
    {"bat", Type::bat, "a bat file path (relative to the study file)", any,
     [](GridPoint& p, double x) { p.bat = static_cast<std::size_t>(x); }, bat_kinds, bat_kinds},
    {"theory", Type::theory, "\"timoshenko\" or \"euler-bernoulli\"", any,
     [](GridPoint& p, double x) { p.theory = static_cast<BeamTheory>(x); }, bat_kinds},
    {"slices", Type::integer, "an integer slice count from 4 to 4096", slice_count,
     [](GridPoint& p, double x) { p.slices = static_cast<int>(x); }, bat_kinds},
    // The rig of a certification study: the standard, and its ball where the study overrides it.
    {"standard", Type::standard, "\"bbcor\", \"besr\" or \"bpf\"", any,
     [](GridPoint& p, double x) { p.standard = static_cast<std::size_t>(x); }, certification, 0, false},
    {"rig_e0", Type::number, "a COR, a number in [0.05, 1] (the rig ball's; default the standard's)", ball_cor,
     [](GridPoint& p, double x) { p.rig_e0 = x; }, certification},
    {"rig_ball_speed", Type::number, "a finite speed > 0 (default the standard's)", positive,
     [](GridPoint& p, double x) { p.rig_ball_speed = x; }, certification, 0, true, Dimension::speed},
    {"z", Type::number, "a length >= 0 from the knob", on_bat,
     [](GridPoint& p, double x) { p.scene.z = x; }, impact, impact, true, Dimension::length},
    // The wall takes only speeds > 0: check_wall_speeds.
    {"ball_speed", Type::number, speed_expected, valid_speed,
     [](GridPoint& p, double x) { p.scene.ball_speed = x; }, ball_kinds, ball_kinds, true, Dimension::speed},
    {"e0", Type::number, "a COR, a number in [0.05, 1], as a [ball] table takes it", ball_cor,
     [](GridPoint& p, double x) { p.scene.ball.e0 = x; },
     ball_kinds},
    {"ball_mass", Type::number, "a mass in [0.001, 10] kg, as a [ball] table takes it", ball_mass,
     [](GridPoint& p, double x) { p.scene.ball.mass = x; }, ball_kinds, 0, true, Dimension::mass},
    {"ball_radius", Type::number, "a radius in [0.001, 1] m, as a [ball] table takes it", ball_radius,
     [](GridPoint& p, double x) { p.scene.ball.radius = x; }, ball_kinds, 0, true, Dimension::length},
    {"k1", Type::number, "a stiffness k1 in [1000, 1e12] N/m^a, as a [ball] table takes it", ball_k1, [](GridPoint& p, double x) { p.scene.ball.k1 = x; },
     ball_kinds},
    {"a", Type::number, "an exponent a in [0.5, 3], as a [ball] table takes it", ball_exponent, [](GridPoint& p, double x) { p.scene.ball.a = x; },
     ball_kinds},
    // The ball's COR law (contact/ball.hpp): its fall with speed and the speed where the COR is e0.
    {"cor_slope", Type::number, "a finite number <= 0 (per m/s: how the COR falls with speed)", non_positive,
     [](GridPoint& p, double x) { p.scene.ball.cor_slope = x; }, ball_kinds},
    {"cor_speed", Type::number, "a speed from 0 to 100 m/s (where the COR is e0)", cor_speed,
     [](GridPoint& p, double x) { p.scene.ball.cor_speed = x; }, ball_kinds, 0, true, Dimension::speed},
    {"curved_contact", Type::boolean, "true or false (the ball meets the barrel's curvature)", any,
     [](GridPoint& p, double x) { p.scene.ball.curved_contact = x != 0; }, ball_kinds},
    {"center", Type::number, "a finite length from the knob", finite,
     [](GridPoint& p, double x) {
       p.scene.swing.center = x;
       p.scene.swing.about_center = true;
     },
     impact, 0, true, Dimension::length},
    {"cm_speed", Type::number, speed_expected, valid_speed,
     [](GridPoint& p, double x) {
       p.scene.swing.cm_speed = x;
       p.scene.swing.about_center = false;
     },
     impact, 0, true, Dimension::speed},
    {"omega", Type::number, omega_expected, valid_omega, [](GridPoint& p, double x) { p.scene.swing.omega = x; },
     impact, 0, true, Dimension::angular_speed},
    {"pivot", Type::boolean, "true or false", any, [](GridPoint& p, double x) { p.scene.pivoted = x != 0; }},
    // Equal effort scales each bat's swing from the reference bat's by their MOIs (grid_point).
    {"swing", Type::swing, "\"given\" or \"equal_effort\" (the swing scaled by the bat's MOI)", any,
     [](GridPoint&, double) {}, impact, 0, false},
    {"reference_bat", Type::reference, "the bat file the swing was measured with (relative to the study file)", any,
     [](GridPoint&, double) {}, impact, 0, false},
    {"swing_exponent", Type::number,
     "a power-law exponent in [0, 2] (n in swing speed ~ MOI^-n; 0.3 fits college hitters)", swing_exponent,
     [](GridPoint& p, double x) { p.swing_exponent = x; }},
    {"e_a_speed", Type::number, "a speed > 0 (the speed e_A is taken at for bbs_linear)", positive,
     [](GridPoint& p, double x) { p.scene.e_a_speed = x; }, impact, 0, true, Dimension::speed},
    // The impact in the plane of the swing (oblique_impact.hpp); a miss is a point's status.
    {"undercut", Type::number, undercut_expected, valid_undercut,
     [](GridPoint& p, double x) { p.scene.oblique.undercut = x; }, impact, 0, true, Dimension::length},
    // The air the batted ball flies through (flight/air.hpp), for the flight's outputs.
    {"temperature", Type::number, air_temperature_expected, air_temperature,
     [](GridPoint& p, double x) { p.air.temperature = x; }, impact, 0, true, Dimension::temperature},
    {"pressure", Type::number, air_pressure_expected, valid_air_pressure,
     [](GridPoint& p, double x) { p.air.pressure = x; }, impact, 0, true, Dimension::pressure},
    {"altitude", Type::number, "an elevation between -1000 m and 10000 m", elevation,
     [](GridPoint& p, double x) { p.air.elevation = x; }, impact, 0, true, Dimension::length},
    {"humidity", Type::number, "a relative humidity from 0 to 100 (%)", humidity,
     [](GridPoint& p, double x) { p.air.relative_humidity = x / 100; }, impact},
    {"wind_speed", Type::number, wind_speed_expected, valid_wind_speed,
     [](GridPoint& p, double x) { p.air.wind_speed = x; }, impact, 0, true, Dimension::speed},
    {"wind_direction", Type::number,
     "an angle from -360 to 360 deg (where the wind blows toward; 0 out to centre field)",
     [](double x) { return std::abs(x) <= 360; },
     [](GridPoint& p, double x) { p.air.wind_direction = x; }, impact, 0, true, Dimension::angle},
    {"swing_tilt", Type::number, swing_tilt_expected, valid_swing_tilt,
     [](GridPoint& p, double x) { p.scene.oblique.swing_tilt = x; }, impact},
    {"pitch_spin", Type::number, pitch_spin_expected, valid_pitch_spin,
     [](GridPoint& p, double x) { p.scene.oblique.pitch_spin = x; }, impact},
    {"friction", Type::number, friction_expected, valid_friction,
     [](GridPoint& p, double x) { p.scene.oblique.friction = x; }, impact},
    {"modes", Type::modes, "a number of vibrational modes >= 0, \"all\" or \"auto\"", mode_count,
     [](GridPoint& p, double x) { p.scene.vibrational_modes = static_cast<int>(x); }, bat_kinds},
    {"mode_tolerance", Type::number, mode_tolerance_expected, valid_mode_tolerance,
     [](GridPoint& p, double x) { p.scene.mode_tolerance = x; }},
    {"accuracy", Type::number, accuracy_expected, total_accuracy,
     [](GridPoint& p, double x) { p.scene.accuracy = x; }, bat_kinds},
    {"step_accuracy", Type::number, step_accuracy_expected, positive,
     [](GridPoint& p, double x) { p.scene.step_accuracy = x; }},
    // N2000's settings (RK4 at 5 us, 18 modes) under the keys the study leaves out: load_study.
    {"preset", Type::preset, "\"n2000\" (RK4 at 5 us with 18 vibrational modes)", any, [](GridPoint&, double) {},
     ball_kinds, 0, false},
    {"integrator", Type::integrator, "\"exact\", \"rk4\" or \"dopri\"", any,
     [](GridPoint& p, double x) { p.scene.integrator.method = static_cast<Method>(x); }, ball_kinds, 0, false},
    {"tolerance", Type::number, "a finite number > 0 (relative error per step, dopri)", positive,
     [](GridPoint& p, double x) { p.scene.integrator.tolerance = x; }, ball_kinds},
    {"dt", Type::number,
     "a number in [5e-9, 1e-3] (s; a finer step could take over 1e7 steps per contact, a coarser one steps over it)",
     valid_step,  // as the commands' --dt
     [](GridPoint& p, double x) { p.scene.integrator.dt = x; }, ball_kinds},
    {"window", Type::number, "a finite number > 0 (s)", positive,
     [](GridPoint& p, double x) { p.scene.integrator.window = x; }, ball_kinds},
    // Histories shape the dataset's dimensions (probe, time), so they are never axes.
    {"probes", Type::numbers, "a list of points on the bat, each a length >= 0 from the knob", on_bat,
     [](GridPoint& p, double x) { p.scene.history.probes.push_back(x); }, impact, 0, false, Dimension::length},
    {"history_window", Type::number, "a finite number > 0 (s of history from first touch)", positive,
     [](GridPoint& p, double x) { p.scene.history.window = x; }, ball_kinds, 0, false},
    {"history_step", Type::number, "a finite number > 0 (s between history samples)", positive,
     [](GridPoint& p, double x) { p.scene.history.step = x; }, ball_kinds, 0, false},
    {"omega_tau", Type::number, "a finite number > 0 (omega tau of the toy model)", positive,
     [](GridPoint& p, double x) { p.omega_tau = x; }, toy, toy},
};
constexpr OutputSpec outputs[] = {
    {"vf", collision_kinds, collision_kinds},
    {"vf_rigid", impact, 0},
    {"vf_van_zandt", impact | toy, toy},
    {"bat_speed", impact, 0},
    {"hoop_frequency", bat_kinds, 0},
    {"barrel_compression", bat_kinds, 0},
    {"bbs", impact, 0},
    {"bbs_linear", impact, 0},
    {"e_eff", ball_kinds, ball_kinds},
    {"launch_angle", impact, 0},
    {"distance", impact, 0},
    {"apex", impact, 0},
    {"hang_time", impact, 0},
    {"landing_angle", impact, 0},
    {"backspin", impact, 0},
    {"sidespin", impact, 0},
    {"e_a", bat_kinds, 0},
    {"bbcor", bat_kinds, certification},  // these three only for pivoted bats (read_outputs)
    {"besr", bat_kinds, 0},
    {"bpf", bat_kinds, 0},
    {"z_max", certification, certification},
    {"certified", certification, certification},
    {"contact_time", ball_kinds, ball_kinds},
    {"collision_time", ball_kinds, ball_kinds},
    {"u_max", ball_kinds, 0},
    {"peak_force", ball_kinds, 0},
    {"impulse", ball_kinds, 0},
    {"contacts", impact, 0},
    {"energy_initial", collision_kinds, 0},
    {"energy_ball", collision_kinds, toy},
    {"energy_bat_translation", impact | toy, toy},
    {"energy_bat_rotation", impact, 0},
    {"energy_vibration", impact | toy, toy},
    {"energy_ball_dissipated", ball_kinds, 0},
    {"energy_barrel", impact, 0},
    {"energy_damped", impact, 0},
    {"energy_ball_spin", impact, 0},
    {"energy_bat_tangential", impact, 0},
    {"energy_friction", impact, 0},
    {"energy_residual", collision_kinds, 0},
    {"mode_energy", impact, 0},
    {"sweet_spot_z", impact, 0},
    {"sweet_spot_vf", impact, 0},
    {"sweet_spot_width", impact, 0},
    {"displacement", impact, 0},
    {"velocity", impact, 0},
    {"acceleration", impact, 0},
    {"vibration_displacement", impact, 0},
    {"vibration_velocity", impact, 0},
    {"vibration_acceleration", impact, 0},
    {"force", ball_kinds, 0},
    {"compression", ball_kinds, 0},
    {"ball_position", ball_kinds, 0},
    {"force_response", impact, 0},
    {"mode_response", impact, 0},
    {"modes_kept", impact, 0},
    {"modes_error", bat_kinds, 0},
    {"slicing_error", bat_kinds, 0},
    {"step_error", bat_kinds, 0},
    {"total_error", bat_kinds, 0},
    {"slices_used", bat_kinds, 0},
    {"step_used", impact, 0},
    {"status", every_kind, every_kind},
};

std::vector<std::string> output_list(StudyKind kind, KindSet OutputSpec::*member) {
  std::vector<std::string> names;
  for (const OutputSpec& o : outputs)
    if (o.*member & bit(kind)) names.emplace_back(o.name);
  return names;
}

// A bat's own parameters set the point's design (design_index), not its scene.
constexpr KeySpec bat_parameter{"bat.", Type::bat_parameter,
                                "a finite number, the bat parameter in SI units (m, kg/m^3, Pa), or a dimension "
                                "with its unit (\"2.625 in\")",
                                finite,
                                [](GridPoint&, double) {}, bat_kinds};
constexpr KeySpec bat_material{"bat.material", Type::material, "the name of a wood preset", any,
                               [](GridPoint&, double) {}, bat_kinds};

}  // namespace

std::string kind_text(StudyKind kind) { return detail::quote(to_string(kind)); }

std::span<const KeySpec> scene_key_specs() { return keys; }

std::span<const OutputSpec> output_specs() { return outputs; }

const KeySpec* find_key(std::string_view name) {
  if (name == bat_material.name) return &bat_material;
  if (is_bat_parameter(name)) return &bat_parameter;
  const auto it = std::ranges::find(keys, name, &KeySpec::name);
  return it == std::end(keys) ? nullptr : &*it;
}

std::optional<Dimension> key_dimension(const KeySpec& spec, std::string_view name) {
  if (spec.type == Type::bat_parameter) return design_parameter_dimension(name.substr(bat_parameter_prefix.size()));
  return spec.dimension;
}

std::string key_list(StudyKind kind, bool axes_only) {
  std::string list;
  for (const KeySpec& k : keys)
    if ((k.kinds & bit(kind)) && (k.axis || !axes_only)) list += (list.empty() ? "" : ", ") + std::string(k.name);
  return list;
}

bool drawable(const KeySpec& k, StudyKind kind) {
  return (k.kinds & bit(kind)) && k.axis && (k.type == Type::number || k.type == Type::bat_parameter);
}

std::string drawable_key_list(StudyKind kind) {
  std::string list;
  for (const KeySpec& k : keys)
    if (drawable(k, kind)) list += (list.empty() ? "" : ", ") + std::string(k.name);
  return list;
}

}  // namespace study_detail

using namespace study_detail;

bool is_bat_parameter(std::string_view axis_name) {
  return axis_name.starts_with(bat_parameter_prefix) && axis_name.size() > bat_parameter_prefix.size();
}

std::string dataset_name(std::string_view axis_name) {
  std::string name(axis_name);
  std::ranges::replace(name, '.', '_');
  return name;
}

const char* to_string(StudyKind kind) {
  switch (kind) {
    case StudyKind::impact:
      return "impact";
    case StudyKind::wall:
      return "wall";
    case StudyKind::toy:
      return "toy";
    case StudyKind::certification:
      return "certification";
  }
  return "?";
}


bool is_probe_history(std::string_view name) {
  static constexpr std::string_view names[] = {"displacement",           "velocity",           "acceleration",
                                               "vibration_displacement", "vibration_velocity", "vibration_acceleration"};
  return std::ranges::count(names, name) > 0;
}

bool is_history(std::string_view name) {
  return is_probe_history(name) || name == "force" || name == "compression" || name == "ball_position";
}

std::vector<std::string> scene_keys(StudyKind kind) {
  std::vector<std::string> names;
  for (const KeySpec& k : keys)
    if (k.kinds & bit(kind)) names.emplace_back(k.name);
  return names;
}

const std::vector<std::string>& output_names(StudyKind kind) {
  static const std::vector<std::string> names[] = {output_list(StudyKind::impact, &OutputSpec::kinds),
                                                   output_list(StudyKind::wall, &OutputSpec::kinds),
                                                   output_list(StudyKind::toy, &OutputSpec::kinds),
                                                   output_list(StudyKind::certification, &OutputSpec::kinds)};
  return names[static_cast<std::size_t>(kind)];
}

const std::vector<std::string>& default_outputs(StudyKind kind) {
  static const std::vector<std::string> names[] = {output_list(StudyKind::impact, &OutputSpec::by_default),
                                                   output_list(StudyKind::wall, &OutputSpec::by_default),
                                                   output_list(StudyKind::toy, &OutputSpec::by_default),
                                                   output_list(StudyKind::certification, &OutputSpec::by_default)};
  return names[static_cast<std::size_t>(kind)];
}
}  // namespace sweetspot
