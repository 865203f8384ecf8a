#include "sweetspot/study/study_results.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "sweetspot/study/bat_properties.hpp"
#include "sweetspot/study/sweet_spot.hpp"

namespace sweetspot {

namespace {

constexpr double missing = std::numeric_limits<double>::quiet_NaN();

struct Description {
  const char* units;
  const char* long_name;
};

const std::map<std::string, Description>& descriptions() {
  static const std::map<std::string, Description> d = {
      {"vf", {"m/s", "exit speed of the ball, positive away from the bat"}},
      {"vf_rigid", {"m/s", "exit speed of the ball off a rigid bat at the same point (free or pivoted)"}},
      {"vf_van_zandt", {"m/s", "exit speed of the ball by Van Zandt's prescription (N2000 App. A)"}},
      {"bat_speed", {"m/s", "speed of the struck point of the bat toward the ball at first touch"}},
      {"bbs", {"m/s", "batted-ball speed: vf, the full flexible model's"}},
      {"bbs_linear", {"m/s", "batted-ball speed by the linear rule e_A v_pitch + (1 + e_A) v_bat, e_A at e_a_speed"}},
      {"swing_exponent", {"1", "exponent n of the equal-effort swing, speed ~ MOI^-n"}},
      {"e_a_speed", {"m/s", "ball speed at which e_A is taken for bbs_linear"}},
      {"e_eff", {"1", "effective coefficient of restitution"}},
      {"launch_angle", {"degree", "launch angle of the ball above the horizontal"}},
      {"distance", {"m", "the batted ball's carry: from home plate to where it lands (flight.md)"}},
      {"apex", {"m", "the batted ball's greatest height above the ground"}},
      {"hang_time", {"s", "the batted ball's time in the air"}},
      {"landing_angle", {"degree", "angle of the batted ball's path below the horizontal where it lands"}},
      {"temperature", {"K", "air temperature"}},
      {"pressure", {"Pa", "barometric pressure, reduced to sea level"}},
      {"altitude", {"m", "elevation of the field above sea level"}},
      {"humidity", {"percent", "relative humidity of the air"}},
      {"wind_speed", {"m/s", "wind speed, horizontal"}},
      {"wind_direction", {"degree", "where the wind blows toward: 0 out to centre field, positive toward right field"}},
      {"backspin", {"rpm", "backspin of the ball as it leaves the bat (negative: topspin)"}},
      {"sidespin", {"rpm", "sidespin of the ball as it leaves the bat (0 in the plane of the swing)"}},
      {"undercut", {"m", "offset of the ball's centre above the bat's axis (negative: below)"}},
      {"swing_tilt", {"degree", "angle of the bat's swing (and the pitch's line) above the horizontal"}},
      {"pitch_spin", {"rpm", "backspin of the pitch as it flies toward the bat (negative: topspin)"}},
      {"friction", {"1", "coefficient of sliding friction between ball and bat"}},
      {"energy_ball_spin", {"J", "final rotational energy of the ball"}},
      {"energy_bat_tangential", {"J", "final energy of the bat's rigid motion across the line of centres, its roll included"}},
      {"energy_friction", {"J", "energy friction took from ball and bat (sliding, and the grip's not returned)"}},
      {"e_a", {"1", "collision efficiency (vf - v_bat) / (ball_speed + v_bat)"}},
      {"bbcor", {"1", "ball-bat coefficient of restitution e_a (1 + r) + r, r = m d^2 / I_pivot"}},
      {"besr", {"1", "ball exit speed ratio e_a + 1/2"}},
      {"bpf", {"1", "bat performance factor bbcor / e0"}},
      {"z_max", {"m", "impact location from the knob where the standard's measure peaks"}},
      {"certified", {"", "whether the bat passes every rule of the standard"}},  // a flag
      {"rig_e0", {"1", "COR of the rig's ball"}},
      {"rig_ball_speed", {"m/s", "speed of the rig's ball"}},
      {"contact_time", {"s", "time the ball is in contact with the bat, summed over contacts"}},
      {"collision_time", {"s", "time from first touch until 99 % of the impulse is delivered"}},
      {"u_max", {"m", "largest compression of the ball"}},
      {"peak_force", {"N", "largest contact force"}},
      {"impulse", {"N s", "impulse delivered to the ball"}},
      {"contacts", {"1", "number of separate contacts"}},
      {"modes_kept", {"1", "vibrational modes kept (modes = auto)"}},
      {"modes_error", {"1", "estimated relative vf error of the dropped modes (modes = auto)"}},
      {"slicing_error", {"1", "estimated relative vf error of the slicing against the continuous bat (Richardson, N and 2N)"}},
      {"step_error", {"1", "estimated relative vf error of the time stepping (step doubling)"}},
      {"total_error", {"1", "estimated total relative vf error: slicing + modes + step"}},
      {"mode_tolerance", {"1", "relative vf error allowed the dropped modes (modes = auto)"}},
      {"accuracy", {"1", "total relative vf error allowed (sets slices, modes and step)"}},
      {"step_accuracy", {"1", "relative vf error the integration may add (sets the step)"}},
      {"slices_used", {"1", "slices the bat was cut into for the impact"}},
      {"step_used", {"s", "fixed time step the impact took (0: adaptive)"}},
      {"status", {"", "outcome of the impact"}},  // a flag, not a quantity: no units
      {"energy_initial", {"J", "initial kinetic energy of ball and bat"}},
      {"energy_ball", {"J", "final kinetic energy of the ball"}},
      {"energy_bat_translation", {"J", "final kinetic energy of the bat's centre of mass"}},
      {"energy_bat_rotation", {"J", "final rotational energy of the bat about its centre of mass"}},
      {"energy_vibration", {"J", "final vibrational energy of the bat"}},
      {"energy_ball_dissipated", {"J", "energy dissipated in the ball"}},
      {"energy_residual", {"J", "energy balance residual (integration error)"}},
      {"energy_barrel", {"J", "final energy of the barrel wall's ovaling (hollow barrels)"}},
      {"energy_damped", {"J", "energy dissipated by the bat's damping (its modes' and its barrel wall's loss factors)"}},
      {"hoop_frequency", {"Hz", "lowest hoop (ovaling) frequency of the struck section's wall; NaN where solid"}},
      {"barrel_compression",
       {"N", "force compressing the struck section's barrel by 0.04 in between opposite platens (ASTM F2844 style); "
             "NaN where solid"}},
      {"mode_energy", {"J", "final energy of each vibrational mode"}},
      {"mode_response", {"1", "response R_n = m psi_n^2 g(omega_n) of each kept vibrational mode"}},
      {"force_response", {"1", "g(omega tau) = |integral of F(t)/impulse exp(i omega t) dt|^2 of the force profile"}},
      {"displacement", {"m", "displacement of the probe point, in the frame where it is initially at rest"}},
      {"velocity", {"m/s", "velocity of the probe point, in the frame where it is initially at rest"}},
      {"acceleration", {"m/s^2", "acceleration of the probe point"}},
      {"vibration_displacement", {"m", "vibrational displacement of the probe point (rigid modes left out)"}},
      {"vibration_velocity", {"m/s", "vibrational velocity of the probe point (rigid modes left out)"}},
      {"vibration_acceleration", {"m/s^2", "vibrational acceleration of the probe point (rigid modes left out)"}},
      {"force", {"N", "contact force on the ball"}},
      {"compression", {"m", "compression of the ball"}},
      {"ball_position", {"m", "displacement of the ball from first touch, positive away from the bat"}},
      {"z", {"m", "impact location from the knob"}},
      {"sample", {"1", "sample of the uncertain inputs (their values: the variables named after them)"}},
      {"ball_speed", {"m/s", "ball speed toward the bat"}},
      {"e0", {"1", "coefficient of restitution of the ball on a rigid wall"}},
      {"ball_mass", {"kg", "ball mass"}},
      {"ball_radius", {"m", "ball radius"}},
      // N/m^a has no UDUNITS spelling (the exponent is the ball's a), which CF units need.
      {"k1", {"", "ball stiffness k1, in N m^-a (a the ball's compression exponent)"}},
      {"a", {"1", "ball compression exponent"}},
      {"cor_slope", {"s/m", "fall of the ball's flat-wall COR per m/s of impact speed"}},
      {"cor_speed", {"m/s", "impact speed at which the ball's flat-wall COR is e0"}},
      {"curved_contact", {"", "ball meets the barrel's curvature (1) or a flat surface (0)"}},
      {"cm_speed", {"m/s", "bat centre-of-mass speed toward the ball"}},
      {"center", {"m", "rotation centre of the swing from the knob"}},
      {"omega", {"rad/s", "bat angular velocity"}},
      {"pivot", {"", "bat held at the rotation centre or free"}},  // a flag
      {"modes", {"1", "vibrational modes kept, or all or auto (flag_values)"}},
      {"slices", {"1", "slices of the bat"}},
      {"dt", {"s", "integration step"}},
      {"window", {"s", "free flight followed after a separation"}},
      {"omega_tau", {"1", "toy model: bat spring frequency omega times collision time tau (N2000 App. A)"}},
      {"bat", {"", "bat"}},  // strings: no units
      {"theory", {"", "beam theory"}},
      {"mode", {"1", "vibrational mode number"}},
      {"frequency", {"Hz", "frequency of each vibrational mode of each bat"}},
      {"sweet_spot_z", {"m", "impact location of the largest vf along z, located between grid points"}},
      {"sweet_spot_vf", {"m/s", "largest vf along z, at sweet_spot_z"}},
      {"sweet_spot_width", {"m", "length along z where vf is within sweet_spot_fraction of its largest value"}},
  };
  return d;
}

// Each bat parameter's own long name and units (bat_design.hpp, dimensions.hpp): moduli in Pa, the
// density in kg/m^3, the shear coefficient and the loss factors ratios, a preset's name none,
// every dimension a length. `parameter` is without the "bat." prefix.
Description bat_parameter_description(std::string_view parameter) {
  static const std::map<std::string_view, Description> d = {
      {"material", {"", "bat material (wood preset)"}},
      {"length", {"m", "bat length"}},
      {"density", {"kg m-3", "bat density"}},
      {"youngs_modulus", {"Pa", "bat Young's modulus"}},
      {"shear_modulus", {"Pa", "bat shear modulus"}},
      {"shear_coefficient", {"1", "bat Timoshenko shear coefficient"}},
      {"hoop_modulus", {"Pa", "bat barrel wall hoop modulus"}},
      {"wall_loss_factor", {"1", "bat barrel wall loss factor"}},
      {"loss_factor", {"1", "bat loss factor"}},
      {"knob_diameter", {"m", "bat knob diameter"}},
      {"knob_length", {"m", "bat knob length"}},
      {"handle_diameter", {"m", "bat handle diameter"}},
      {"taper_start", {"m", "bat taper start from the knob"}},
      {"taper_end", {"m", "bat taper end from the knob"}},
      {"barrel_diameter", {"m", "bat barrel diameter"}},
      {"end_depth", {"m", "bat end depth"}},
      {"wall_thickness", {"m", "bat barrel wall thickness"}},
  };
  const auto it = d.find(parameter);
  // A parameter added to the designs without a line here would be unlabelled in every dataset.
  if (it == d.end()) throw std::logic_error("no description for the bat parameter '" + std::string(parameter) + "'");
  return it->second;
}

Description describe(const std::string& name) {
  if (is_bat_parameter(name)) return bat_parameter_description(std::string_view(name).substr(bat_parameter_prefix.size()));
  const auto it = descriptions().find(name);
  return it == descriptions().end() ? Description{"1", ""} : it->second;
}

double energy_value(const ImpactEnergy& e, const std::string& name) {
  if (name == "energy_initial") return e.initial;
  if (name == "energy_ball") return e.ball;
  if (name == "energy_bat_translation") return e.bat_translation;
  if (name == "energy_bat_rotation") return e.bat_rotation;
  if (name == "energy_vibration") return e.vibration;
  if (name == "energy_ball_dissipated") return e.ball_dissipated;
  if (name == "energy_barrel") return e.barrel;
  if (name == "energy_damped") return e.damped;
  if (name == "energy_ball_spin") return e.ball_spin;
  if (name == "energy_bat_tangential") return e.bat_tangential;
  if (name == "energy_friction") return e.friction;
  return e.residual;
}

double scalar_value(const ImpactResult& r, const std::string& name) {
  if (name == "status") return static_cast<double>(r.status);
  if (!stores_values(r.status)) return missing;
  if (name == "vf" || name == "bbs") return r.vf;  // the ball's exit speed is the batted-ball speed
  if (name == "bat_speed") return r.bat_speed;
  if (name == "hoop_frequency") return r.hoop_frequency;
  if (name == "barrel_compression") return r.barrel_compression;
  if (name == "bbs_linear") return r.bbs_linear;
  if (name == "vf_rigid") return r.vf_rigid;
  if (name == "vf_van_zandt") return r.vf_van_zandt;
  if (name == "e_eff") return r.e_eff;
  if (name == "launch_angle") return r.launch.angle;
  if (name == "distance") return r.distance;
  if (name == "apex") return r.apex;
  if (name == "hang_time") return r.hang_time;
  if (name == "landing_angle") return r.landing_angle;
  if (name == "backspin") return r.launch.backspin;
  if (name == "sidespin") return r.launch.sidespin;
  if (name == "e_a") return r.rig.e_a;
  if (name == "z_max") return r.z;
  if (name == "certified") return r.certified;
  if (name == "bbcor") return r.rig.bbcor;
  if (name == "besr") return r.rig.besr;
  if (name == "bpf") return r.rig.bpf;
  if (name == "contact_time") return r.contact_time;
  if (name == "collision_time") return r.collision_time;
  if (name == "u_max") return r.u_max;
  if (name == "peak_force") return r.peak_force;
  if (name == "impulse") return r.impulse;
  if (name == "contacts") return r.contacts;
  if (name == "modes_kept") return static_cast<double>(r.modes_kept.size());
  if (name == "modes_error") return r.modes_error;
  if (name == "slicing_error") return r.slicing_error;
  if (name == "step_error") return r.step_error;
  if (name == "total_error") return r.total_error;
  if (name == "slices_used") return r.slices_used;
  if (name == "step_used") return r.step_used;
  return energy_value(r.energy, name);
}

std::vector<std::int32_t> integers(const std::vector<double>& values) {
  return {values.begin(), values.end()};
}

// Counts are integers on disk; the words that stand for a count ("all", "auto") and the two
// states of pivot are CF flags, values named by flag_meanings.
Coordinate axis_coordinate(const Study& study, const Axis& axis) {
  const Description d = describe(axis.name);
  Coordinate c{dataset_name(axis.name), d.units, d.long_name, {}, {}};
  if (axis.name == "bat") {
    for (double index : axis.values) c.labels.push_back(study.bat_names[static_cast<std::size_t>(index)]);
  } else if (axis.name == "theory" || !axis.labels.empty()) {
    c.labels = axis.labels;
  } else if (axis.name == "slices" || axis.name == sample_axis) {
    c.integers = integers(axis.values);
  } else if (axis.name == "modes") {
    c.integers = integers(axis.values);
    c.int_attributes.push_back({"flag_values", {auto_modes, all_modes}});
    c.text_attributes.push_back({"flag_meanings", "auto all"});
  } else if (axis.name == "pivot") {
    c.integers = integers(axis.values);
    c.int_attributes.push_back({"flag_values", {0, 1}});
    c.text_attributes.push_back({"flag_meanings", "free pivoted"});
  } else {
    c.values = axis.values;
  }
  return c;
}

// `units` replaces the description's own when given.
Variable output_variable(const std::string& name, std::vector<std::string> dims, std::vector<double> values,
                         const char* units = nullptr) {
  Description d = describe(name);
  if (units && *d.units) d.units = units;  // a flag (status) has no units in any kind
  Variable v{name, d.units, d.long_name, std::move(dims), {}, {}, {}};
  if (name == "status" || name == "contacts" || name == "modes_kept" || name == "certified") {
    std::vector<std::int32_t> ints(values.size());
    std::transform(values.begin(), values.end(), ints.begin(),
                   [](double x) { return std::isfinite(x) ? static_cast<std::int32_t>(x) : -1; });
    v.values = std::move(ints);
  } else {
    v.values = std::move(values);
  }
  if (name == "certified") {
    v.int_attributes.push_back({"flag_values", {0, 1}});
    v.text_attributes.push_back({"flag_meanings", "fails passes"});
  }
  if (name == "status") {  // every CollisionStatus, by its value and name
    std::vector<std::int32_t> flags;
    std::string meanings;
    for (int k = 0; k <= static_cast<int>(last_collision_status); ++k) {
      flags.push_back(k);
      if (k) meanings += ' ';
      meanings += to_string(static_cast<CollisionStatus>(k));
    }
    v.int_attributes.push_back({"flag_values", flags});
    v.text_attributes.push_back({"flag_meanings", meanings});
  }
  return v;
}

bool is_sweet_spot(const std::string& name) { return name.starts_with("sweet_spot_"); }

bool is_scalar(const std::string& name) {
  return !(name == "mode_energy" || name == "mode_response" || name == "force_response" || is_history(name));
}

// The dimensions an output adds to the study's axes, slowest first.
std::vector<std::string> extra_dims(const Study& study, const std::string& name) {
  if (name == "mode_energy" || name == "mode_response") return {"mode"};
  if (name == "force_response") return {"omega_tau"};
  if (is_probe_history(name) && study.base.history.probes.size() > 1) return {"probe", "time"};
  if (is_history(name)) return {"time"};
  return {};
}

std::size_t dim_size(const Study& study, const std::string& dim) {
  if (dim == "mode") return static_cast<std::size_t>(study.base.vibrational_modes);  // a fixed count (load_study)
  if (dim == "omega_tau") return force_response_grid().size();
  if (dim == "probe") return study.base.history.probes.size();
  return study.base.history.samples();  // time
}

std::vector<double> ProbeHistory::*probe_member(const std::string& name) {
  if (name == "displacement") return &ProbeHistory::displacement;
  if (name == "velocity") return &ProbeHistory::velocity;
  if (name == "acceleration") return &ProbeHistory::acceleration;
  if (name == "vibration_displacement") return &ProbeHistory::vibration_displacement;
  if (name == "vibration_velocity") return &ProbeHistory::vibration_velocity;
  return &ProbeHistory::vibration_acceleration;
}

// A point's values of an output that has extra dimensions, row-major over them (probes, then time).
std::vector<double> array_value(const ImpactResult& r, const std::string& name) {
  if (name == "mode_energy") return r.mode_energy;
  if (name == "mode_response") return r.mode_response;
  if (name == "force_response") return r.force_response;
  if (name == "force") return r.histories.force;
  if (name == "compression") return r.histories.compression;
  if (name == "ball_position") return r.histories.ball_position;
  std::vector<double> values;
  for (const ProbeHistory& p : r.histories.probes) {
    const std::vector<double>& history = p.*probe_member(name);
    values.insert(values.end(), history.begin(), history.end());
  }
  return values;
}

}  // namespace

OutputDescription describe_output(const std::string& name) {
  const Description d = describe(name);
  return {d.units, d.long_name};
}

int dataset_mode_count(const Study& study) {
  const auto axis = std::ranges::find(study.axes, "modes", &Axis::name);
  const std::vector<double> counts = axis == study.axes.end() ? std::vector<double>{static_cast<double>(study.base.vibrational_modes)}
                                                              : axis->values;
  const int fixed = static_cast<int>(std::ranges::max(counts));
  int available = 0;  // as many as the bat with the most has
  for (const Bat& bat : study.designs)
    available = std::max(available, vibrational_mode_count(study.slices > 0 ? study.slices : bat.slices(), study.theory));
  if (std::ranges::count(counts, all_modes)) return available;
  if (std::ranges::count(counts, auto_modes)) return std::max(fixed, std::min(available, auto_frequency_modes));
  return fixed;
}

OutputLayout::OutputLayout(const Study& study) : names(study.outputs) {
  for (const std::string& name : names) {
    std::size_t values = is_sweet_spot(name) ? 0 : 1;  // a reduction over z, not a point's value
    for (const std::string& dim : extra_dims(study, name)) values *= dim_size(study, dim);
    offsets.push_back(width);
    widths.push_back(static_cast<int>(values));
    width += widths.back();
  }
}

void OutputLayout::extract(const ImpactResult& result, double* row) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (widths[i] == 0) continue;
    if (is_scalar(names[i])) {
      row[offsets[i]] = scalar_value(result, names[i]);
      continue;
    }
    // A failed point has none; a point keeping fewer modes than the dimension leaves NaN after them.
    const std::vector<double> values = stores_values(result.status) ? array_value(result, names[i])
                                                                     : std::vector<double>{};
    for (int n = 0; n < widths[i]; ++n) row[offsets[i] + n] = n < static_cast<int>(values.size()) ? values[n] : missing;
  }
}

namespace {

// The mode dimension of the frequencies and mode_energy. A study of one bat has no bat dimension:
// its bat's variables run over the bat-parameter axes alone (a scalar `bat` names it).
void add_mode_coordinate(const Study& study, Dataset& d) {
  if (!keeps_vibrations(study)) return;
  Coordinate mode{"mode", "1", describe("mode").long_name, {}, {}};
  for (int n = 1; n <= dataset_mode_count(study); ++n) mode.integers.push_back(n);
  d.coordinates.push_back(mode);
}

Coordinate history_coordinate(const Study& study, const std::string& dim) {
  const HistoryRequest& h = study.base.history;
  if (dim == "probe") return {"probe", "m", "probe point on the bat, from the knob", h.probes, {}};
  if (dim == "omega_tau")
    return {"omega_tau", "1", "angular frequency omega times the point's collision time tau", force_response_grid(), {}};
  Coordinate time{"time", "s", "time since the ball first touches the bat", {}, {}};
  for (std::size_t j = 0; j < h.samples(); ++j) time.values.push_back(static_cast<double>(j) * h.step);
  return time;
}

// The dimensions of the histories and the force response that the outputs use, once each.
void add_history_coordinates(const Study& study, Dataset& d) {
  for (const std::string dim : {"probe", "time", "omega_tau"})
    if (std::ranges::any_of(study.outputs,
                            [&](const std::string& name) { return std::ranges::count(extra_dims(study, name), dim) > 0; }))
      d.coordinates.push_back(history_coordinate(study, dim));
}

// A history at one probe has no probe dimension: the attribute says where it was taken.
void add_probe_attribute(const Study& study, Variable& v) {
  if (!is_probe_history(v.name) || study.base.history.probes.size() != 1) return;
  std::ostringstream where;
  where << study.base.history.probes[0] << " m from the knob";
  v.text_attributes.push_back({"probe", where.str()});
}

void add_outputs(const Study& study, const OutputLayout& layout, const std::vector<double>& rows,
                 const std::vector<std::string>& dims, Dataset& d) {
  const std::size_t points = study.points();
  for (std::size_t i = 0; i < layout.names.size(); ++i) {
    if (layout.widths[i] == 0) continue;  // reductions: add_sweet_spots
    std::vector<double> values(points * layout.widths[i]);
    for (std::size_t p = 0; p < points; ++p)
      std::copy_n(rows.begin() + p * layout.width + layout.offsets[i], layout.widths[i],
                  values.begin() + p * layout.widths[i]);
    std::vector<std::string> variable_dims = dims;
    for (std::string& dim : extra_dims(study, layout.names[i])) variable_dims.push_back(std::move(dim));
    // The toy model is dimensionless (m = k = v_i = 1): speeds are ratios to v_i and energies
    // are in units of m v_i^2 (the initial energy is 1/2).
    const char* units = study.kind == StudyKind::toy ? "1" : nullptr;
    d.variables.push_back(output_variable(layout.names[i], variable_dims, std::move(values), units));
    add_probe_attribute(study, d.variables.back());
  }
}

// The sweet spot of every line of vf along z: the outputs over the other axes.
void add_sweet_spots(const Study& study, const OutputLayout& layout, const std::vector<double>& rows, Dataset& d) {
  const auto asked = [&](const char* name) { return std::ranges::count(study.outputs, name) > 0; };
  if (!asked("sweet_spot_z") && !asked("sweet_spot_vf") && !asked("sweet_spot_width")) return;
  const std::size_t zk = static_cast<std::size_t>(std::ranges::find(study.axes, "z", &Axis::name) - study.axes.begin());
  const Axis& z = study.axes[zk];
  const int vf = layout.offsets[std::ranges::find(layout.names, study.sweet_spot_of) - layout.names.begin()];
  std::size_t inner = 1;  // points between neighbours along z: the axes after it
  for (std::size_t k = zk + 1; k < study.axes.size(); ++k) inner *= study.axes[k].size();
  const std::size_t lines = study.points() / z.size();
  // The axis's values in ascending order, whatever order the study wrote them in.
  std::vector<std::size_t> order(z.size());
  std::iota(order.begin(), order.end(), 0);
  std::ranges::sort(order, {}, [&](std::size_t j) { return z.values[j]; });
  std::vector<double> ascending(z.size());
  for (std::size_t j = 0; j < z.size(); ++j) ascending[j] = z.values[order[j]];
  std::vector<double> at(lines), peak(lines), width(lines), line(z.size());
  for (std::size_t l = 0; l < lines; ++l) {
    const std::size_t first = (l / inner) * inner * z.size() + l % inner;
    for (std::size_t j = 0; j < z.size(); ++j) line[j] = rows[(first + order[j] * inner) * layout.width + vf];
    const SweetSpot spot = sweet_spot(ascending, line, study.sweet_spot_fraction);
    at[l] = spot.z, peak[l] = spot.vf, width[l] = spot.width;
  }
  std::vector<std::string> dims;
  for (const Axis& axis : study.axes)
    if (axis.name != "z") dims.push_back(dataset_name(axis.name));
  for (auto [name, values] : {std::pair{"sweet_spot_z", &at}, {"sweet_spot_vf", &peak}, {"sweet_spot_width", &width}})
    if (asked(name))  // the carry's peak is a distance
      d.variables.push_back(output_variable(name, dims, std::move(*values),
                                            study.sweet_spot_of == "distance" && values == &peak ? "m" : nullptr));
  std::ostringstream fraction;
  fraction << study.sweet_spot_fraction;
  d.variables.back().text_attributes.push_back({"sweet_spot_fraction", fraction.str()});
  d.variables.back().text_attributes.push_back({"sweet_spot_of", study.sweet_spot_of});
}

}  // namespace

bool keeps_vibrations(const Study& study) {
  const auto axis = std::ranges::find(study.axes, "modes", &Axis::name);
  if (axis == study.axes.end()) return has_bat(study.kind) && study.base.vibrational_modes != 0;
  return std::ranges::any_of(axis->values, [](double modes) { return modes != 0; });
}

Dataset make_dataset(const Study& study, const OutputLayout& layout, const std::vector<double>& rows,
                     const DesignModes& modes, const RunInfo& info) {
  Dataset d;
  std::vector<std::string> dims;
  for (const Axis& axis : study.axes) {
    d.coordinates.push_back(axis_coordinate(study, axis));
    dims.push_back(d.coordinates.back().name);
  }
  // Wall and toy studies have no bat: no bat or mode dimension and no frequencies; a study of
  // rigid bats alone computed no modes, so it stores no frequencies either.
  if (has_bat(study.kind)) add_mode_coordinate(study, d);
  add_history_coordinates(study, d);
  add_outputs(study, layout, rows, dims, d);
  add_sweet_spots(study, layout, rows, d);
  if (has_bat(study.kind)) add_design_variables(study, modes, dataset_mode_count(study), d);
  // An uncertainty study's inputs: each drawn key's value in every sample (a drawn bat.length is
  // already there: the bats' bat_length over the sample dimension).
  for (const Axis& drawn : study.sampled) {
    if (std::ranges::count(d.variables, dataset_name(drawn.name), &Variable::name)) continue;
    const Description description = describe(drawn.name);
    d.variables.push_back({dataset_name(drawn.name), description.units, description.long_name,
                           {std::string(sample_axis)}, drawn.values, {}, {}});
  }

  add_provenance(study, info, d);
  return d;
}

}  // namespace sweetspot
