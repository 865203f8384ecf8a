#include "sweetspot/optimize/evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "sweetspot/impact/bat_test_rig.hpp"
#include "sweetspot/impact/batted_flight.hpp"
#include "sweetspot/impact/equal_effort.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/scan_maximum.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/sweet_spot.hpp"

namespace sweetspot {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Thrown inside an evaluation for a design that cannot be scored; becomes its status.
struct Unscorable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// "the impact at z = 0.7 m", as a failure names the point.
std::string point_name(const char* what, double z) {
  char text[96];
  std::snprintf(text, sizeof text, "%s at z = %.6g m", what, z);
  return text;
}

// A point's function: its value and its impact's error estimates.
using PointFunction = std::function<PointValue(double)>;

// Why f failed at z, f computed again on this worker alone (the map returns numbers only, and a
// failure is rare): its exception's message, which names the collision's status ("the rig's hit at
// z = 0.7 m ended no_separation"), or the value it gave.
std::string failure_at(const PointFunction& f, double z, const char* what) {
  try {
    const double v = f(z).value;
    return point_name(what, z) + " gave " + std::to_string(v);
  } catch (const std::exception& e) {
    return e.what();
  }
}

// A value made from points carries the largest of their impacts' estimates: a maximum or a
// weighted mean (weights summing to 1) of relative errors at most e errs by at most e relative to
// the maximum, or the mean, itself. fmax: an estimate not made (NaN) adds nothing.
void include_estimates(PointValue& scored, const PointValue& p) {
  scored.modes_error = std::fmax(scored.modes_error, p.modes_error);
  scored.step_error = std::fmax(scored.step_error, p.step_error);
}

// Values at `points` through the map, their estimates included in `scored`; a point that throws
// or fails gives NaN, and any NaN makes the evaluation unscorable, saying what was computed there
// and how it ended.
std::vector<double> values_at(const std::vector<double>& points, const PointFunction& f, const PointMap& map,
                              const char* what, PointValue& scored) {
  const std::vector<PointValue> mapped = map(points.size(), [&](std::size_t i) {
    try {
      return f(points[i]);
    } catch (const std::exception&) {
      return PointValue{};
    }
  });
  std::vector<double> values;
  for (std::size_t i = 0; i < mapped.size(); ++i) {
    if (!std::isfinite(mapped[i].value)) throw Unscorable(failure_at(f, points[i], what));
    values.push_back(mapped[i].value);
    include_estimates(scored, mapped[i]);
  }
  return values;
}

// The maximum of f between from and to as scan_maximum finds it, its uniform samples computed
// through the map (bitwise the values scan_maximum would compute itself), the golden section
// after them on every worker alike; with the largest estimates of every point computed.
PointValue mapped_scan_maximum(const PointFunction& f, double from, double to, double step, double tolerance,
                           const PointMap& map, const char* what) {
  PointValue scored;
  const std::vector<double> points = scan_points(from, to, step);
  const std::vector<double> values = values_at(points, f, map, what, scored);
  const auto sampled_or_computed = [&](double x) {
    const auto at = std::ranges::find(points, x);
    if (at != points.end()) return values[static_cast<std::size_t>(at - points.begin())];
    const PointValue v = f(x);
    if (!std::isfinite(v.value)) throw Unscorable(failure_at(f, x, what));
    include_estimates(scored, v);
    return v.value;
  };
  scored.value = scan_maximum(sampled_or_computed, from, to, step, tolerance).value;
  return scored;
}

// The player's swing with this design: scaled from the reference bat's by equal effort.
Swing design_swing(const Player& player, const MassProperties& exact) {
  if (!player.equal_effort) return player.swing;
  return equal_effort_swing(player.swing, player.reference_moi, exact.moment_of_inertia_about(0),
                            player.swing_exponent);
}

// The impact at z; throws naming the status unless it ends ok.
ImpactResult impact_at(const ModalBasis& basis, ImpactScene scene, double z) {
  scene.z = z;
  ImpactResult r = simulate_impact(basis, scene);
  if (r.status != CollisionStatus::ok)
    throw std::runtime_error(point_name("the impact", z) + " ended " + to_string(r.status) +
                             (r.message.empty() ? "" : ": " + r.message));
  return r;
}

// The batted-ball speed (the flexible model's v_f) at z.
PointValue batted_ball_speed(const ModalBasis& basis, const ImpactScene& scene, double z) {
  const ImpactResult r = impact_at(basis, scene, z);
  return {r.vf, r.modes_error, r.step_error};
}

// A carry's relative error over its exit speed's: a carry in vacuum goes as the launch speed
// squared, and air makes it less sensitive (d ln carry / d ln speed 1.0-1.8 over 20-50 m/s launches).
constexpr double carry_sensitivity = 2;

// The batted ball's carry from the impact at z, in the trajectory calculator's air (flight.hpp),
// with the impact's estimates times carry_sensitivity.
PointValue carry(const ModalBasis& basis, const ImpactScene& scene, double z) {
  const ImpactResult r = impact_at(basis, scene, z);
  return {batted_flight(r.launch, Air{}).distance, carry_sensitivity * r.modes_error,
          carry_sensitivity * r.step_error};
}

// How many times its speeds' relative error the objective's may be, as its impacts are held to
// it: a carry's carry_sensitivity; a sweet spot's width (1 - f) / f on a parabolic peak, and up to
// 1.25 times that read between the points of an even scan (SweetSpot::width_sensitivity); a peak
// speed's or a mean's once.
double assumed_sensitivity(const ObjectiveSpec& o) {
  switch (o.kind) {
    case ObjectiveKind::peak_distance: return carry_sensitivity;
    case ObjectiveKind::sweet_spot_width: return 1.25 * (1 - o.fraction) / o.fraction;
    case ObjectiveKind::peak_bbs:
    case ObjectiveKind::mean_bbs: break;
  }
  return 1;
}

PointValue objective_value(const OptimizationProblem& problem, const ModalBasis& basis, const ImpactScene& scene,
                       const PointMap& map) {
  const ObjectiveSpec& o = problem.objective;
  const auto bbs = [&](double z) { return batted_ball_speed(basis, scene, z); };
  switch (o.kind) {
    case ObjectiveKind::peak_bbs:
      return mapped_scan_maximum(bbs, o.z_from, o.z_to, o.z_step, o.tolerance, map, "the impact");
    case ObjectiveKind::peak_distance: {
      const auto distance = [&](double z) { return carry(basis, scene, z); };
      return mapped_scan_maximum(distance, o.z_from, o.z_to, o.z_step, o.tolerance, map, "the impact");
    }
    case ObjectiveKind::sweet_spot_width: {
      PointValue scored;
      const std::vector<double> z = scan_points(o.z_from, o.z_to, o.z_step);
      const SweetSpot spot = sweet_spot(z, values_at(z, bbs, map, "the impact", scored), o.fraction);
      if (!std::isfinite(spot.width))
        throw Unscorable("the sweet spot is not inside the z scan (its peak at an end, or its zone running off it)");
      scored.value = spot.width;
      scored.modes_error *= spot.width_sensitivity, scored.step_error *= spot.width_sensitivity;
      return scored;
    }
    case ObjectiveKind::mean_bbs: {
      PointValue scored;
      const std::vector<double> vf = values_at(o.z, bbs, map, "the impact", scored);
      scored.value = 0;
      for (std::size_t i = 0; i < vf.size(); ++i) scored.value += o.weights[i] * vf[i];
      return scored;
    }
  }
  throw std::logic_error("objective_value: unknown objective");
}

// The standard's measure at its maximum over the barrel, as certify finds it. A measure's
// relative error is at most its hit's exit speed's (certification.hpp).
PointValue rig_maximum(const OptimizationProblem& problem, const ModalBasis& basis, double length, const PointMap& map) {
  const RigSettings rig = certification_rig(problem.standard, problem.rig, length);
  const BarrelScan& scan = problem.rig.scan;
  const auto measure = [&](double z) {
    const ImpactResult r = rig_impact(basis, rig, z);
    return PointValue{measure_value(r.rig, problem.standard.measure), r.modes_error, r.step_error};
  };
  return mapped_scan_maximum(measure, length - scan.far_from_end, length - scan.near_end, scan.step, scan.tolerance,
                             map, "the rig's hit");
}

double shape_quantity(Quantity q, const BatDesign& design, const MassProperties& exact) {
  switch (q) {
    case Quantity::barrel_diameter: return largest_outer_diameter(design);
    case Quantity::drop: return bat_drop(design.length, exact.mass);
    case Quantity::mass: return exact.mass;
    case Quantity::moi_knob: return exact.moment_of_inertia_about(0);
    case Quantity::moi_pivot: return exact.moment_of_inertia_about(swing_weight_pivot);
    case Quantity::length: return design.length;
    case Quantity::measure: break;
  }
  throw std::logic_error("shape_quantity: the rig's measure is no number of the shape");
}

// Whether a constraint asks the rig's measure.
bool asks_measure(const OptimizationProblem& problem) {
  return std::ranges::any_of(problem.constraints, [](const Constraint& c) { return c.quantity == Quantity::measure; });
}

// The impact points an evaluation strikes at its scan's samples (the golden section's points
// lie between them), and the rig's hits when a constraint asks for its measure.
std::vector<ImpactScene> sampled_scenes(const OptimizationProblem& problem, const ImpactScene& scene, double length) {
  const ObjectiveSpec& o = problem.objective;
  std::vector<ImpactScene> scenes;
  for (const double z : o.kind == ObjectiveKind::mean_bbs ? o.z : scan_points(o.z_from, o.z_to, o.z_step)) {
    scenes.push_back(scene);
    scenes.back().z = z;
  }
  if (asks_measure(problem)) {
    const RigSettings rig = certification_rig(problem.standard, problem.rig, length);
    const BarrelScan& scan = problem.rig.scan;
    for (const double z : scan_points(length - scan.far_from_end, length - scan.near_end, scan.step))
      scenes.push_back(rig_scene(rig, z));
  }
  return scenes;
}

// One basis for every impact and rig hit of the design: the rigid modes alone, a fixed count, all
// modes, or (auto) every mode below the largest reach any sampled scene asks, as a study's cache
// solves it (a partial solve: most of an evaluation's cost is this eigen-solve).
ModalBasis design_modes(const OptimizationProblem& problem, const Bat& bat, const std::vector<ImpactScene>& scenes) {
  const int modes = problem.model.vibrational_modes;
  if (modes == 0) return compute_modes(bat, problem.model.theory, ModeRequest::rigid_only());
  if (modes == all_modes) return compute_modes(bat, problem.model.theory, ModeRequest::all());
  if (modes != auto_modes) return compute_modes(bat, problem.model.theory, ModeRequest::lowest(modes));
  const ModalBasis rigid = compute_modes(bat, problem.model.theory, ModeRequest::rigid_only());
  ModeRequest request = ModeRequest::below(0);
  for (const ImpactScene& s : scenes) {
    const ModeRequest asked = auto_mode_request(scene_for_accuracy(s), rigid);
    if (asked.is_all()) return compute_modes(bat, problem.model.theory, ModeRequest::all());
    request.below_omega = std::max(request.below_omega, asked.below_omega);
  }
  return compute_modes(bat, problem.model.theory, request);
}

// The design's objective and (NaN when no constraint asks it) the rig's measure, on the design cut
// into `slices` slices (0: its own, or the model's).
struct Scores {
  PointValue objective, measure;

  double modes_error() const { return std::fmax(objective.modes_error, measure.modes_error); }
  double step_error() const { return std::fmax(objective.step_error, measure.step_error); }
};

Scores scores_at(const OptimizationProblem& problem, const BatDesign& design, const ImpactScene& scene, int slices,
                 const PointMap& map) {
  const Bat bat = slices > 0 ? bat_with_slices(design, slices)
                             : problem.model.slices > 0 ? resample(build_bat(design), problem.model.slices)
                                                        : build_bat(design);
  const ModalBasis basis = design_modes(problem, bat, sampled_scenes(problem, scene, design.length));
  Scores s;
  s.objective = objective_value(problem, basis, scene, map);
  if (asks_measure(problem)) s.measure = rig_maximum(problem, basis, design.length, map);
  return s;
}

// The relative slicing estimate of the finest of `values` (error_estimates.hpp); 0 for a quantity
// not computed (all NaN).
double relative_slicing_error(const std::vector<double>& values) {
  if (std::isnan(values.back())) return 0;
  return slicing_error(values, values.size() - 1) / std::abs(values.back());
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// The scores at a stated accuracy: the design cut at its own slices N, 2N, 4N ..., at least three
// slicings and then one more while the objective's or the measure's Richardson estimate exceeds
// what the modes and the step leave of the accuracy (slicing_allowance, as certify --accuracy and
// an impact's ladder); the finest are the answer. A design the slices cannot meet it for is
// unscorable.
Scores scores_within_accuracy(const OptimizationProblem& problem, const BatDesign& design, const ImpactScene& scene,
                              const PointMap& map, DesignEvaluation& e) {
  const double accuracy = problem.model.accuracy;
  std::vector<double> objectives, measures;
  for (int slices = build_bat(design).slices();; slices *= slicing_refinement) {
    Scores s;
    try {
      s = scores_at(problem, design, scene, slices, map);
    } catch (const InputError& refused) {  // a finer slicing whose modes cannot be solved
      if (objectives.empty()) throw;
      throw Unscorable("accuracy " + number(accuracy) + " needs the design cut finer than " +
                       std::to_string(slices / slicing_refinement) + " slices, and the next slicing cannot be solved: " +
                       refused.what());
    }
    objectives.push_back(s.objective.value);
    measures.push_back(s.measure.value);
    const bool can_double = can_refine(slices, problem.model.theory);
    if (objectives.size() < 3 && can_double) continue;
    e.slices_used = slices;
    e.slicing_error = std::max(relative_slicing_error(objectives), relative_slicing_error(measures));
    e.modes_error = s.modes_error();
    e.step_error = s.step_error();
    e.total_error = e.slicing_error + e.modes_error + e.step_error;
    const double allowance = slicing_allowance(accuracy, e.modes_error, e.step_error);
    if (e.slicing_error <= allowance) return s;
    if (!(allowance > 0))
      throw Unscorable("accuracy " + number(accuracy) + ": the modes' and the step's estimated errors (" +
                       number(e.modes_error) + " and " + number(e.step_error) + ") leave nothing of it for the slicing");
    if (!can_double)
      throw Unscorable("accuracy " + number(accuracy) + " needs the design cut finer than " + std::to_string(slices) +
                       " slices (its slicing estimate there " + number(e.slicing_error) +
                       ", where the modes and the step leave it " + number(allowance) + ")");
  }
}

}  // namespace

std::vector<PointValue> serial_map(std::size_t count, const std::function<PointValue(std::size_t)>& value) {
  std::vector<PointValue> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = value(i);
  return values;
}

const char* to_string(EvaluationStatus status) { return status == EvaluationStatus::ok ? "ok" : "failed"; }

DesignEvaluation evaluate_design(const OptimizationProblem& problem, const std::vector<double>& x, const PointMap& map) {
  DesignEvaluation e;
  e.x = x;
  e.constraints.assign(problem.constraints.size(), nan);
  try {
    const BatDesign design = design_at(problem, x);
    if (const auto broken = broken_rule(design)) throw Unscorable(*broken);
    const MassProperties exact = design_mass_properties(design);
    for (std::size_t i = 0; i < problem.constraints.size(); ++i)
      if (problem.constraints[i].quantity != Quantity::measure)
        e.constraints[i] = shape_quantity(problem.constraints[i].quantity, design, exact);
    ImpactScene scene;
    scene.ball = problem.player.ball;
    scene.integrator.damping_loss = false;  // the objective is a speed: no energy balance
    scene.ball_speed = problem.player.ball_speed;
    scene.swing = design_swing(problem.player, exact);
    scene.oblique = problem.player.oblique;
    scene.vibrational_modes = problem.model.vibrational_modes;
    // The impacts are held to the accuracy over the objective's sensitivity to them, so that their
    // estimates, multiplied by it, take the modes' and step's quarters and leave the slicing its half.
    if (problem.model.accuracy > 0)
      scene.accuracy = std::max(problem.model.accuracy / assumed_sensitivity(problem.objective), min_accuracy);
    scene.error_estimates = scene.accuracy > 0;  // the modes' and step's, free at a stated accuracy
    const Scores s = problem.model.accuracy > 0 ? scores_within_accuracy(problem, design, scene, map, e)
                                                : scores_at(problem, design, scene, 0, map);
    e.objective = s.objective.value;
    const auto measure = std::ranges::find(problem.constraints, Quantity::measure, &Constraint::quantity);
    if (measure != problem.constraints.end())
      e.constraints[static_cast<std::size_t>(measure - problem.constraints.begin())] = s.measure.value;
  } catch (const std::exception& failure) {  // Unscorable, or an InputError of a rig off this bat
    e.status = EvaluationStatus::failed;
    e.message = failure.what();
    e.objective = nan;
  }
  return e;
}

double constraint_violation(const OptimizationProblem& problem, const DesignEvaluation& e, std::size_t i) {
  const Constraint& c = problem.constraints[i];
  const double value = e.constraints[i];
  if (e.status != EvaluationStatus::ok || !std::isfinite(value)) return 1;
  const double scale = std::abs(c.limit) > 0 ? std::abs(c.limit) : 1;
  return (c.upper ? value - c.limit : c.limit - value) / scale;
}

bool feasible(const OptimizationProblem& problem, const DesignEvaluation& e) {
  if (e.status != EvaluationStatus::ok) return false;
  for (std::size_t i = 0; i < problem.constraints.size(); ++i)
    if (constraint_violation(problem, e, i) > problem.optimizer.constraint_tolerance) return false;
  return true;
}

}  // namespace sweetspot
