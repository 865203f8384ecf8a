// Reading an optimisation file (README "Design optimisation"): every key checked, with the
// study files' one-line messages (file:line: key 'free.density.min' = ...: expected ...). The
// bats, [free], [player], [model] and [optimizer] here; [objective] and [constraints] in files
// of their own.
#include <string>

#include "ball/ball_table.hpp"
#include "sweetspot/impact/equal_effort.hpp"
#include "problem_values.hpp"
#include "sweetspot/ball/ball_tests.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

namespace fs = std::filesystem;
using namespace optimize_detail;

// ---- The bats ------------------------------------------------------------------------------

BatDesign read_bat(const Where& at, const fs::path& file, const std::string& name, BatSource& source) {
  try {
    return load_bat_design((file.parent_path() / name).lexically_normal(), source);
  } catch (const InputError& e) {
    reject(at, quote(name), e.what());
  }
}

// ---- [free] --------------------------------------------------------------------------------

// A bound the design takes as its parameter's value (a hoop modulus or a wall of 0 is none).
void check_bound(const Where& at, const BatDesign& base, const std::string& name, double value) {
  BatDesign design = base;
  try {
    set_design_parameter(design, name, value);
  } catch (const InputError& e) {
    reject(at, format_number(value), e.what());
  }
}

FreeParameter read_free_parameter(const Where& at, const toml::node& node, const std::string& name,
                                  const BatDesign& base) {
  const std::vector<std::string> known = design_parameters(base);
  if (std::ranges::find(known, name) == known.end())
    reject(at, describe(node), "unknown parameter of the base bat; expected one of " + detail::join(known));
  if (!node.is_table()) reject(at, describe(node), "expected a table { min = ..., max = ... [, start = ...] }");
  const toml::table& t = *node.as_table();
  reject_unknown(at, t, {"min", "max", "start"});
  const std::optional<Dimension> dimension = design_parameter_dimension(name);  // "2.5 in" for a dimension
  FreeParameter p{name, required_number(at, t, "min", finite, "a finite lower bound", dimension),
                  required_number(at, t, "max", finite, "a finite upper bound", dimension), 0};
  if (!(p.lower < p.upper))
    reject(at.child("max", *t.get("max")), format_number(p.upper), "expected a bound above min = " + format_number(p.lower));
  check_bound(at.child("min", *t.get("min")), base, name, p.lower);
  check_bound(at.child("max", *t.get("max")), base, name, p.upper);
  const double base_value = design_parameter(base, name);
  const auto inside = [&](double v) { return v >= p.lower && v <= p.upper; };
  if (t.get("start"))
    p.start = number_key(at, t, "start", 0, inside, "a start within [min, max]", dimension);
  else if (!inside(base_value))
    reject(at, describe(node),
           "the base bat's " + name + " = " + format_number(base_value) +
               " lies outside [min, max]; expected bounds around it, or a start");
  else
    p.start = base_value;
  return p;
}

// Every corner of the box a possible bat: the rules are linear in the parameters, so then is
// every design inside it.
void check_box(const Where& at, const OptimizationProblem& problem) {
  const std::size_t n = problem.free.size();
  for (std::size_t corner = 0; corner < (std::size_t{1} << n); ++corner) {
    std::vector<double> x(n);
    std::string where;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = (corner >> i) & 1 ? problem.free[i].upper : problem.free[i].lower;
      where += (where.empty() ? "" : ", ") + problem.free[i].name + " = " + format_number(x[i]);
    }
    if (const auto broken = broken_rule(design_at(problem, x)))
      reject(at, "{...}", "the corner " + where + " of the bounds is an impossible bat (" + *broken +
                              "); expected bounds within which every design is a possible bat");
  }
}

std::vector<FreeParameter> read_free(const Where& top, const toml::table& doc, const BatDesign& base) {
  const toml::table& t = table_key(top, doc, "free", true);
  const Where at{top.file, "free", doc.get("free")->source().begin.line};
  if (t.empty()) reject(at, "{}", "expected at least one free parameter, e.g. barrel_diameter = { min = 0.06, max = 0.0667 }");
  if (t.size() > max_free_parameters)
    reject(at, "{...}", "has " + std::to_string(t.size()) + " parameters; expected at most " +
                            std::to_string(max_free_parameters));
  std::vector<FreeParameter> free;
  for (const auto& [key, node] : t) {
    // toml++ keeps keys sorted: the parameters' order is the alphabetical one, whatever the file's.
    free.push_back(read_free_parameter(at.child(key.str(), node), node, std::string(key.str()), base));
  }
  return free;
}

// ---- [player] ------------------------------------------------------------------------------

Player read_player(const Where& top, const toml::table& doc, OptimizationProblem& problem) {
  const toml::table& t = table_key(top, doc, "player", true);
  const Where at{top.file, "player", doc.get("player")->source().begin.line};
  reject_unknown(at, t, {"swing", "reference_bat", "swing_exponent", "center", "cm_speed", "omega", "ball_speed", "e0",
                         "undercut", "swing_tilt", "pitch_spin", "friction"});
  Player p;
  const std::string swing = string_key(at, t, "swing", "equal_effort", "\"equal_effort\" or \"given\"");
  if (swing != "equal_effort" && swing != "given")
    reject(at.child("swing", *t.get("swing")), quote(swing), "expected \"equal_effort\" or \"given\"");
  p.equal_effort = swing == "equal_effort";
  const bool center = t.get("center"), cm = t.get("cm_speed");
  if (center == cm)
    reject(center ? at.child("cm_speed", *t.get("cm_speed")) : at.missing("center"), center ? "given too" : "",
           "expected the swing's rotation centre `center` (m from the knob) or its `cm_speed` (m/s), one of them");
  p.swing.about_center = center;
  if (center)
    p.swing.center = number_key(at, t, "center", 0, finite, "a finite point from the knob", Dimension::length);
  if (cm) p.swing.cm_speed = number_key(at, t, "cm_speed", 0, valid_speed, speed_expected, Dimension::speed);
  // The swing turns the barrel toward the ball: v(z) = V_cm + omega (z - z_cm), + toward the ball
  // (scene.hpp), so a batter's omega is >= 0; a negative one would swing the barrel away from the pitch.
  p.swing.omega = required_number(at, t, "omega", valid_omega, omega_expected, Dimension::angular_speed);
  p.ball_speed = required_number(at, t, "ball_speed", [](double v) { return v >= 0 && valid_speed(v); },
                                 "the pitch's speed toward the bat, from 0 to 1000 m/s", Dimension::speed);
  // The pitched ball: the file's [ball] table (README "Balls"), N2000's without one; e0 sets its COR.
  if (const toml::node* ball = doc.get("ball")) {
    if (!ball->is_table()) reject(top.child("ball", *ball), describe(*ball), "expected a table [ball]");
    p.ball = detail::read_ball_table(*ball->as_table(), top.file->string()).ball;
  }
  p.ball.e0 = number_key(at, t, "e0", p.ball.e0, [](double v) { return in_range(ball_cor_range, v); },
                         range_text(ball_cor_range));
  // Where the bat meets the ball (docs/oblique.md): head-on unless given.
  p.oblique.undercut = number_key(at, t, "undercut", 0, valid_undercut, undercut_expected, Dimension::length);
  p.oblique.swing_tilt = number_key(at, t, "swing_tilt", 0, valid_swing_tilt, swing_tilt_expected);
  p.oblique.pitch_spin = number_key(at, t, "pitch_spin", 0, valid_pitch_spin, pitch_spin_expected);
  p.oblique.friction = number_key(at, t, "friction", 0, valid_friction, friction_expected);
  if (!p.equal_effort) {
    for (const char* key : {"reference_bat", "swing_exponent"})
      if (const toml::node* node = t.get(key))
        reject(at.child(key, *node), describe(*node), "applies only with swing = \"equal_effort\"");
    return p;
  }
  p.swing_exponent = number_key(at, t, "swing_exponent", default_swing_exponent, valid_swing_exponent,
                                "a power-law exponent in [0, 2] (n in swing speed ~ MOI^-n; 0.3 fits college hitters)");
  const toml::node* reference = t.get("reference_bat");
  if (reference) {
    const std::string name = string_key(at, t, "reference_bat", "", "a bat file (the player's swing was measured with it)");
    const BatDesign ref = read_bat(at.child("reference_bat", *reference), problem.file, name, problem.reference_source);
    p.reference_moi = design_mass_properties(ref).moment_of_inertia_about(0);
  } else {
    p.reference_moi = design_mass_properties(problem.base).moment_of_inertia_about(0);  // the base bat
  }
  return p;
}

// ---- [model] -------------------------------------------------------------------------------

ModelSettings read_model(const Where& top, const toml::table& doc) {
  const toml::table& t = table_key(top, doc, "model", false);
  const Where at{top.file, "model", doc.get("model") ? doc.get("model")->source().begin.line : 0};
  reject_unknown(at, t, {"modes", "slices", "theory", "accuracy"});
  ModelSettings m;
  if (const toml::node* node = t.get("modes")) {
    const auto text = node->value<std::string_view>();
    if (node->is_integer() && node->as_integer()->get() >= 0 && node->as_integer()->get() <= max_slices * 2)
      m.vibrational_modes = static_cast<int>(node->as_integer()->get());
    else if (node->is_string() && (text == "all" || text == "auto"))
      m.vibrational_modes = text == "all" ? all_modes : auto_modes;
    else
      reject(at.child("modes", *node), describe(*node), "expected a count of vibrational modes (0: rigid bats), \"all\" or \"auto\"");
  }
  if (const toml::node* node = t.get("slices")) {
    if (!node->is_integer() || node->as_integer()->get() < min_slices || node->as_integer()->get() > max_slices)
      reject(at.child("slices", *node), describe(*node), "expected an integer from 4 to 4096");
    m.slices = static_cast<int>(node->as_integer()->get());
  }
  if (const toml::node* node = t.get("accuracy")) {
    const std::optional<double> a = node->value<double>();
    if (!node->is_number() || !(*a >= min_accuracy && *a <= max_accuracy))
      reject(at.child("accuracy", *node), describe(*node), std::string("expected ") + accuracy_expected);
    if (t.get("slices"))
      reject(at.child("accuracy", *node), describe(*node), "expected slices or accuracy, not both: the accuracy chooses the slices");
    if (m.vibrational_modes >= 0)
      reject(at.child("accuracy", *node), describe(*node),
             "expected modes \"auto\" or \"all\" beside it: a fixed number of modes cannot be held to an accuracy");
    m.accuracy = *a;
  }
  if (const toml::node* node = t.get("theory")) {
    try {
      m.theory = parse_beam_theory(node->value<std::string>().value_or(""));
    } catch (const InputError&) {
      reject(at.child("theory", *node), describe(*node), "expected \"timoshenko\" or \"euler-bernoulli\"");
    }
  }
  return m;
}

// The model must serve the shortest design (fewest slices when they are about 1 cm each): its
// slicing and theory, and a count of modes it has.
void check_model(const Where& top, const toml::table& doc, const OptimizationProblem& problem, double length) {
  const Where at{top.file, "model", doc.get("model") ? doc.get("model")->source().begin.line : 0};
  BatDesign shortest = problem.base;
  set_design_parameter(shortest, "length", length);
  int modes = 0, slices = 0;
  try {
    Bat bat = build_bat(shortest);
    if (problem.model.slices > 0) bat = resample(bat, problem.model.slices);
    modes = static_cast<int>(compute_modes(bat, problem.model.theory, ModeRequest::rigid_only()).vectors.rows()) - 2;
    slices = bat.slices();
  } catch (const InputError& e) {
    reject(at, "{...}", std::string("cannot model the shortest design: ") + e.what());
  }
  const int asked = problem.model.vibrational_modes;
  const auto modes_at = [&] { return at.child("modes", *doc["model"]["modes"].node()); };
  if (asked > modes)
    reject(modes_at(), std::to_string(asked),
           "expected at most the " + std::to_string(modes) + " vibrational modes of the shortest design, \"all\" or \"auto\"");
  // A solve that would take longer than is practical at the model's slices (every design's).
  if (asked != auto_modes && asked != 0)
    if (const auto why = impractical_solve(slices, problem.model.theory,
                                           asked == all_modes ? ModeRequest::all() : ModeRequest::lowest(asked)))
      reject(modes_at(), asked == all_modes ? "\"all\"" : std::to_string(asked),
             "at " + std::to_string(slices) + " slices: " + *why);
}

// ---- [optimizer] ---------------------------------------------------------------------------

OptimizerSettings read_optimizer(const Where& top, const toml::table& doc) {
  const toml::table& t = table_key(top, doc, "optimizer", false);
  const Where at{top.file, "optimizer", doc.get("optimizer") ? doc.get("optimizer")->source().begin.line : 0};
  reject_unknown(at, t, {"algorithm", "max_evaluations", "xtol_rel", "initial_step", "constraint_tolerance", "seed"});
  OptimizerSettings o;
  const std::string algorithm = string_key(at, t, "algorithm", "cobyla", "\"cobyla\", \"bobyqa\" or \"mlsl\"");
  if (algorithm == "cobyla") o.algorithm = Algorithm::cobyla;
  else if (algorithm == "bobyqa") o.algorithm = Algorithm::bobyqa;
  else if (algorithm == "mlsl") o.algorithm = Algorithm::mlsl;
  else reject(at.child("algorithm", *t.get("algorithm")), quote(algorithm), "expected \"cobyla\", \"bobyqa\" or \"mlsl\"");
  const auto whole = [](double lo, double hi) { return [lo, hi](double v) { return v == std::floor(v) && v >= lo && v <= hi; }; };
  o.max_evaluations = static_cast<int>(number_key(at, t, "max_evaluations", o.max_evaluations,
                                                  whole(1, max_optimizer_evaluations), "an integer from 1 to 100000"));
  o.xtol_rel = number_key(at, t, "xtol_rel", o.xtol_rel, [](double v) { return v > 0 && v < 1; }, "a tolerance in (0, 1)");
  o.initial_step = number_key(at, t, "initial_step", o.initial_step, [](double v) { return v > 0 && v <= 1; },
                              "a fraction of each parameter's range in (0, 1]");
  // BOBYQA (alone, or MLSL's local search) needs its first trust region to fit twice in each range.
  if (o.algorithm != Algorithm::cobyla && o.initial_step > 0.5)
    reject(at.child("initial_step", *t.get("initial_step")), format_number(o.initial_step),
           "expected a fraction in (0, 0.5] with algorithm = \"" + algorithm + "\" (BOBYQA's first step must fit twice in each range)");
  o.constraint_tolerance = number_key(at, t, "constraint_tolerance", o.constraint_tolerance,
                                      [](double v) { return v >= 0 && v < 1; }, "a relative tolerance in [0, 1)");
  o.seed = static_cast<std::uint32_t>(number_key(at, t, "seed", o.seed, whole(0, 4294967295.0), "an integer from 0 to 2^32 - 1"));
  return o;
}

}  // namespace

OptimizationProblem load_optimization(const fs::path& file) {
  OptimizationProblem problem;
  problem.file = file;
  problem.text = study_detail::read_text(file, "optimisation file");
  const toml::table doc = study_detail::parse_toml(file, problem.text);
  const Where top{&problem.file, "", 0};
  reject_unknown(top, doc, {"title", "bat", "free", "player", "model", "objective", "constraints", "optimizer", "ball"});
  problem.title = string_key(top, doc, "title", file.stem().string(), "a title (string)");
  const std::string bat = string_key(top, doc, "bat", "", "the base bat file (its [dimensions] are what is optimised)");
  if (bat.empty()) reject(top.missing("bat"), "", "expected the base bat file (a bat of named [dimensions])");
  const Where bat_at = top.child("bat", *doc.get("bat"));
  problem.base = read_bat(bat_at, file, bat, problem.base_source);
  if (!problem.base.dimensions)
    reject(bat_at, quote(bat), "is a bat given by a profile; expected a bat of named [dimensions] (a parametric bat)");
  problem.free = read_free(top, doc, problem.base);
  check_box(Where{&problem.file, "free", doc.get("free")->source().begin.line}, problem);
  problem.player = read_player(top, doc, problem);
  problem.model = read_model(top, doc);
  const double length = shortest_length(problem);
  check_model(top, doc, problem, length);
  problem.objective = read_objective(top, doc, length);
  problem.rig.vibrational_modes = problem.model.vibrational_modes;
  problem.rig.slices = problem.model.slices;
  if (problem.model.accuracy > 0) problem.rig.accuracy = problem.model.accuracy;
  problem.rig.theory = problem.model.theory;
  read_constraints(top, doc, problem);
  check_rig(top, problem, length);
  problem.optimizer = read_optimizer(top, doc);
  return problem;
}

}  // namespace sweetspot