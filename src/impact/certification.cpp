#include "sweetspot/impact/certification.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sweetspot/ball/ball_tests.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/scan_maximum.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

[[noreturn]] void reject(const std::string& what, double value, const std::string& expected) {
  std::ostringstream text;
  text << "certify: " << what << " " << value << ": expected " << expected;
  throw InputError(text.str());
}

// The scanned stretch of the barrel, m from the knob.
double scan_start(const BarrelScan& scan, double length) { return length - scan.far_from_end; }
double scan_end(const BarrelScan& scan, double length) { return length - scan.near_end; }

// The modes the scan's hits ask with `auto`: the widest auto_mode_request over its points (as an
// optimisation's design_modes asks; held_reach times the free reach, scene.hpp); or the lowest
// `count`. BBCOR at 513 slices, over that basis, is within 5.5e-6 of BBCOR at 512 over every mode
// (alloy_bbcor 5.0e-6, aluminium 5.5e-6, the torpedo 2.1e-6, r161 4.9e-7).
ModeRequest partial_scan_request(const ModalBasis& rigid, const RigSettings& rig, const BarrelScan& scan, int modes) {
  if (modes != auto_modes) return ModeRequest::lowest(modes);
  ModeRequest widest = ModeRequest::below(0);
  for (const double z : scan_points(scan_start(scan, rigid.length()), scan_end(scan, rigid.length()), scan.step)) {
    const ModeRequest asked = auto_mode_request(scene_for_accuracy(rig_scene(rig, z)), rigid);
    if (asked.is_all()) return asked;
    widest.below_omega = std::max(widest.below_omega, asked.below_omega);
  }
  return widest;
}

ModalBasis certification_modes(const BatDesign& design, const CertifyOptions& options, const RigSettings& rig) {
  Bat bat = build_bat(design);
  if (options.slices > 0) bat = resample(bat, options.slices);
  const int modes = options.vibrational_modes, most = vibrational_mode_count(bat.slices(), options.theory);
  if (modes != all_modes && modes != auto_modes && (modes < 0 || modes > most))
    throw InputError("certify: modes " + std::to_string(modes) + ": expected 'all', 'auto' or 0 to " +
                     std::to_string(most) + " (the vibrational modes of " + design.name + " in " +
                     std::to_string(bat.slices()) + " slices)");
  if (modes == 0) return compute_modes(bat, options.theory, ModeRequest::rigid_only());
  // One basis serves every point of the scan: all modes up to max_certify_full_slices (the held
  // bat's modes are then those of the whole beam); past that, what the scan's hits ask, by the
  // partial solve (as `impact --pivot` and an optimisation's rig take them at any slice count).
  if (modes == all_modes || bat.slices() <= max_certify_full_slices)
    return compute_modes(bat, options.theory, ModeRequest::all());
  const ModalBasis rigid = compute_modes(bat, options.theory, ModeRequest::rigid_only());
  return compute_modes(bat, options.theory, partial_scan_request(rigid, rig, options.scan, modes));
}

}  // namespace

std::optional<std::string> rig_misfit(const Standard& standard, double pivot, double length, const BarrelScan& scan) {
  if (pivot < scan_start(scan, length)) return std::nullopt;
  using detail::format_number;
  return "expected a bat longer than " + format_number(pivot + scan.far_from_end) + " m: the " + standard.name +
         " rig's pivot, " + format_number(pivot) + " m from the knob, must lie before the scanned barrel, which starts " +
         format_number(scan.far_from_end) + " m from the end";
}

RigSettings certification_rig(const Standard& standard, const CertifyOptions& options, double length) {
  RigSettings rig;
  rig.ball = options.ball.value_or(standard.ball);
  rig.ball.e0 = options.e0.value_or(rig.ball.e0);
  rig.ball_speed = options.ball_speed.value_or(standard.ball_speed);
  rig.pivot = options.pivot.value_or(standard.pivot);
  rig.vibrational_modes = options.vibrational_modes;
  rig.accuracy = options.accuracy.value_or(0);
  rig.integrator.damping_loss = false;  // the measures need no energy balance
  if (!in_range(ball_cor_range, rig.ball.e0)) reject("e0", rig.ball.e0, range_text(ball_cor_range));
  if (const auto misfit = cor_law_misfit(rig.ball))
    throw InputError("certify: e0 " + detail::format_number(rig.ball.e0) + ": " + *misfit);
  if (!(rig.ball_speed > 0) || !std::isfinite(rig.ball_speed))
    reject("ball speed", rig.ball_speed, "a finite speed > 0 (m/s) toward the bat at rest");
  const double start = scan_start(options.scan, length);
  // A bat too short for the rig (the standard's pivot, or any pivot when the scan starts before
  // the knob) is the bat's fault, not the option's.
  if (!options.pivot || !(start > 0))
    if (const auto misfit = rig_misfit(standard, rig.pivot, length, options.scan))
      throw InputError("certify: bat of length " + detail::format_number(length) + " m: " + *misfit);
  if (!(rig.pivot >= 0 && rig.pivot < start)) {
    std::ostringstream range;
    range << "a point on the bat before the scanned barrel (0 to " << start << " m from the knob of this "
          << length << "-m bat)";
    reject("pivot point", rig.pivot, range.str());
  }
  return rig;
}

ScanMaximum barrel_maximum(const ModalBasis& basis, const RigSettings& rig, Measure measure, const BarrelScan& scan) {
  const auto value = [&](double z) { return measure_value(rig_hit(basis, rig, z), measure); };
  return scan_maximum(value, scan_start(scan, basis.length()), scan_end(scan, basis.length()), scan.step,
                      scan.tolerance);
}

std::vector<RuleCheck> rule_checks(const Standard& standard, double measure, double barrel_diameter, double drop,
                                   double length) {
  std::vector<RuleCheck> checks{{to_string(standard.measure), measure, standard.limit, false},
                                {"barrel_diameter", barrel_diameter, standard.max_barrel_diameter, false}};
  if (standard.max_drop) checks.push_back({"drop", drop, *standard.max_drop, false});
  if (standard.max_length) checks.push_back({"length", length, *standard.max_length, false});
  for (RuleCheck& c : checks) c.pass = c.value <= c.limit;
  return checks;
}

namespace {

// The certification at the options' slices.
Certification certify_at_slices(const BatDesign& design, const Standard& standard, const CertifyOptions& options) {
  const RigSettings rig = certification_rig(standard, options, design.length);
  const ModalBasis basis = certification_modes(design, options, rig);
  const ScanMaximum peak = barrel_maximum(basis, rig, standard.measure, options.scan);

  Certification c;
  c.standard = standard;
  c.standard.ball = rig.ball, c.standard.ball_speed = rig.ball_speed, c.standard.pivot = rig.pivot;
  c.z_max = peak.x;
  c.measure = peak.value;
  // The hit at the peak, whole: its measures, the wall's load, and at a stated accuracy its
  // modes' and step's error estimates.
  const ImpactResult hit = rig_impact(basis, rig, peak.x);
  c.at_max = hit.rig;
  if (const std::optional<WallMode> wall = basis.wall_at(peak.x)) {
    c.hoop_frequency = wall->frequency_hz();
    c.barrel_compression = barrel_compression(*wall);
  }
  c.barrel_phi = hit.barrel_phi;
  c.barrel_compliance = hit.barrel_compliance;
  c.slices_used = basis.slices();
  if (rig.accuracy > 0) c.modes_error = hit.modes_error, c.step_error = hit.step_error;
  c.hollow = !design_profile(design).inner.empty();
  c.barrel = design.material.barrel;
  c.evaluations = peak.evaluations + 1;
  const MassProperties exact = design_mass_properties(design);
  c.mass = exact.mass;
  c.moi_pivot = exact.moment_of_inertia_about(rig.pivot);
  c.moi_pivot_model = model_moi_about(basis, rig.pivot);
  c.length = design.length;
  c.drop = bat_drop(design.length, exact.mass);
  c.barrel_diameter = largest_outer_diameter(design);
  c.checks = rule_checks(standard, c.measure, c.barrel_diameter, c.drop, c.length);
  c.pass = std::ranges::all_of(c.checks, &RuleCheck::pass);
  return c;
}

// What a stated accuracy cannot be given with, refused before any work.
void check_accuracy_options(const CertifyOptions& options) {
  if (!(*options.accuracy >= min_accuracy && *options.accuracy <= max_accuracy)) {
    // With the digits that tell it from the bound it broke: 0.10000001, not 0.1.
    const double bound = *options.accuracy > max_accuracy ? max_accuracy : min_accuracy;
    throw InputError("certify: accuracy " + detail::format_apart(*options.accuracy, bound).first + ": expected " +
                     accuracy_expected);
  }
  if (options.slices > 0)
    throw InputError("certify: slices " + std::to_string(options.slices) +
                     " with accuracy: the accuracy chooses the slices; give one of them");
  if (options.vibrational_modes >= 0)
    throw InputError("certify: modes " + std::to_string(options.vibrational_modes) +
                     " with accuracy: a fixed number of modes cannot be held to an accuracy; expected 'auto' or 'all'");
}

// The certification on the design cut at its own slices N, then 2N, 4N ...: at least three
// slicings, then one more while the measure's Richardson estimate (error_estimates.hpp) exceeds
// what the modes and the step leave of the accuracy (as impact's SlicingLadder). The finest is
// the answer; where the next slicing cannot be made (4096 slices, or its modes too many to solve)
// the finest so far, not accurate, says why.
Certification certify_within_accuracy(const BatDesign& design, const Standard& standard, CertifyOptions options) {
  check_accuracy_options(options);
  const double accuracy = *options.accuracy;
  std::vector<double> measures;
  int evaluations = 0;
  Certification c;
  const auto finish = [&](const std::string& unmet) {
    c.slicing_error = measures.size() >= 2 ? slicing_error(measures, measures.size() - 1) / std::abs(c.measure)
                                           : std::numeric_limits<double>::quiet_NaN();
    c.total_error = c.slicing_error + c.modes_error + c.step_error;
    c.accurate = unmet.empty();
    c.unmet = unmet;
    c.evaluations = evaluations;
    return c;
  };
  for (options.slices = build_bat(design).slices();; options.slices *= slicing_refinement) {
    try {
      c = certify_at_slices(design, standard, options);
    } catch (const InputError& refused) {
      if (measures.empty()) throw;  // the design's own slices: the input's fault, not the accuracy's
      return finish(std::string("the next slicing cannot be solved: ") + refused.what());
    }
    evaluations += c.evaluations;
    measures.push_back(c.measure);
    const bool can_double = can_refine(options.slices, options.theory);
    if (measures.size() < 3 && can_double) continue;
    const double allowance = slicing_allowance(accuracy, c.modes_error, c.step_error);
    const double estimate = slicing_error(measures, measures.size() - 1) / std::abs(c.measure);
    if (estimate > allowance && allowance > 0 && can_double) continue;
    if (estimate <= allowance) return finish("");
    return finish(allowance > 0 ? "the slices cannot double again" : "the modes and the step leave nothing for the slicing");
  }
}

}  // namespace

Certification certify(const BatDesign& design, const Standard& standard, const CertifyOptions& options) {
  if (options.accuracy) return certify_within_accuracy(design, standard, options);
  return certify_at_slices(design, standard, options);
}

}  // namespace sweetspot
