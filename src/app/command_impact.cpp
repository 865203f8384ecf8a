// sweetspot impact: one ball on one bat, everything N2000 derives from a collision.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

#include "bat_argument.hpp"
#include "commands.hpp"
#include "display_units.hpp"
#include "json.hpp"
#include "quantity_option.hpp"
#include "sweetspot/ball/ball_file.hpp"
#include "sweetspot/ball/ball_tests.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/oblique_impact.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/impact/n2000_settings.hpp"

namespace sweetspot::app {

namespace {

struct ImpactOptions {
  std::string bat_file;
  std::string theory = "timoshenko";
  int slices = 0;
  std::optional<double> cm_speed, center;
  std::string modes = "auto";
  bool json = false;
  DisplayUnits units;
  ImpactScene scene;
  std::string named_ball;
};

Json energy_json(const ImpactEnergy& e) {
  return Json::Object()
      .add("initial", e.initial)
      .add("ball", e.ball)
      .add("bat_translation", e.bat_translation)
      .add("bat_rotation", e.bat_rotation)
      .add("vibration", e.vibration)
      .add("ball_dissipated", e.ball_dissipated)
      .add("barrel", e.barrel)
      .add("damped", e.damped)
      .add("ball_spin", e.ball_spin)
      .add("bat_tangential", e.bat_tangential)
      .add("friction", e.friction)
      .add("residual", e.residual);
}

void print_json(const ImpactResult& r, const Bat& bat) {
  Json::Object out;
  out.add("status", to_string(r.status));
  if (!r.message.empty()) out.add("message", r.message);
  out.add("z", r.z)
      .add("vf", r.vf)
      .add("e_eff", r.e_eff)
      .add("contact_time", r.contact_time)
      .add("collision_time", r.collision_time)
      .add("u_max", r.u_max)
      .add("peak_force", r.peak_force)
      .add("impulse", r.impulse)
      .add("bat_speed", r.bat_speed)
      .add("hoop_frequency", r.hoop_frequency)  // null where the struck section is solid
      .add("barrel_compression", r.barrel_compression)  // N at 0.04 in; null where solid
      .add("barrel_phi", r.barrel_phi)            // these three null where no wall takes the ball
      .add("barrel_compliance", r.barrel_compliance)
      .add("barrel_compression_eff", r.barrel_compression_eff)
      .add("e_a", r.rig.e_a)
      .add("bbcor", r.rig.bbcor)  // these three null for a free bat: no rig holds it
      .add("besr", r.rig.besr)
      .add("bpf", r.rig.bpf)
      .add("energy", energy_json(r.energy))
      .add("launch_angle", r.launch.angle)  // degrees; these three null where nothing collided
      .add("backspin", r.launch.backspin)   // rpm
      .add("sidespin", r.launch.sidespin)
      .add("mode_energy", Json::numbers(r.mode_energy))
      .add("modes_kept", Json::numbers({r.modes_kept.begin(), r.modes_kept.end()}))
      .add("modes_error", r.modes_error)
      .add("slicing_error", r.slicing_error)  // error_estimates.hpp; null where not estimated
      .add("step_error", r.step_error)
      .add("total_error", r.total_error)
      .add("slices_used", Json::integer(r.slices_used))
      .add("step_used", r.step_used)
      .add("contacts", Json::integer(r.contacts));
  if (bat.hollow()) out.add("barrel", barrel_json(bat.material.barrel));
  std::printf("%s\n", Json(out).text().c_str());
}

void print_text(const ImpactResult& r, const DisplayUnits& u, bool oblique) {
  std::printf("status          %s%s%s\n", to_string(r.status), r.message.empty() ? "" : ": ", r.message.c_str());
  std::printf("impact at z     %s from the knob\n", u.length(r.z, "%.4f").c_str());
  std::printf("exit speed vf   %s\n", u.speed(r.vf, "%.6g").c_str());
  if (oblique)  // docs/oblique.md
    std::printf("launch          %.4g deg above the horizontal, backspin %.5g rpm, sidespin %.3g rpm\n", r.launch.angle,
                r.launch.backspin, r.launch.sidespin);
  std::printf("e_eff           %.6g\n", r.e_eff);
  // Along the line of centres: in an oblique impact, the struck point's speed toward the ball.
  std::printf("bat speed       %s toward the ball at the impact point; e_a %.6g\n",
              u.speed(r.bat_speed, "%.6g").c_str(), r.rig.e_a);
  if (std::isfinite(r.rig.bbcor))
    std::printf("held at the pivot: bbcor %.6g, besr %.6g, bpf %.6g\n", r.rig.bbcor, r.rig.besr, r.rig.bpf);
  std::printf("contact time    %.4g ms (%d contact%s)\n", 1e3 * r.contact_time, r.contacts, r.contacts == 1 ? "" : "s");
  std::printf("collision time  %.4g ms (99 %% of the impulse)\n", 1e3 * r.collision_time);
  std::printf("max compression %s, peak force %.5g N, impulse %.5g N s\n", u.small_length(r.u_max, "%.4g").c_str(),
              r.peak_force, r.impulse);
  const ImpactEnergy& e = r.energy;
  std::printf("energy/J        initial %.6g = ball %.6g + bat translation %.6g + rotation %.6g\n", e.initial, e.ball,
              e.bat_translation, e.bat_rotation);
  if (std::isfinite(r.hoop_frequency)) {  // a hollow struck section: its wall takes a share
    std::printf("                + vibration %.6g + dissipated in the ball %.6g + barrel wall %.6g\n", e.vibration,
                e.ball_dissipated, e.barrel);
    std::printf("                + dissipated by the bat's damping %.6g\n", e.damped);
    std::printf("                + residual %.3g; the wall's hoop frequency %.5g Hz\n", e.residual, r.hoop_frequency);
    if (std::isfinite(r.barrel_compression_eff))
      std::printf("wall's load     phi_2 %.5g, other harmonics %.4g m/N, at compression %s\n", r.barrel_phi,
                  r.barrel_compliance, u.small_length(r.barrel_compression_eff, "%.4g").c_str());
  } else if (e.damped != 0) {  // a damped beam
    std::printf("                + vibration %.6g + dissipated in the ball %.6g + by the bat's damping %.6g\n",
                e.vibration, e.ball_dissipated, e.damped);
    std::printf("                + residual %.3g\n", e.residual);
  } else if (oblique) {
    std::printf("                + vibration %.6g + dissipated in the ball %.6g\n", e.vibration, e.ball_dissipated);
    std::printf("                + ball's spin %.6g + bat across the line of centres %.6g + friction %.6g\n",
                e.ball_spin, e.bat_tangential, e.friction);
    std::printf("                + residual %.3g\n", e.residual);
  } else {
    std::printf("                + vibration %.6g + dissipated in the ball %.6g + residual %.3g\n", e.vibration,
                e.ball_dissipated, e.residual);
  }
  std::printf("vibration/J by mode:");
  for (std::size_t n = 0; n < r.mode_energy.size(); ++n)
    std::printf("%s%d: %.4g", n % 6 ? ", " : "\n  ", r.modes_kept[n], r.mode_energy[n]);
  std::printf("\n");
  if (r.modes_error > 0)
    std::printf("modes kept: %zu; estimated relative vf error of the dropped ones %.2g\n", r.modes_kept.size(),
                r.modes_error);
  std::printf("estimated error total %.2g (relative vf): slicing %.2g, modes %.2g, time step %.2g\n", r.total_error,
              r.slicing_error, r.modes_error, r.step_error);
  std::printf("computed at %d slices, %zu vibrational modes, ", r.slices_used, r.modes_kept.size());
  if (r.step_used > 0) std::printf("step %.3g us\n", 1e6 * r.step_used);
  else std::printf("adaptive steps\n");
}

// The bat's basis for the scene, as a study's point solves it (study/parallel.cpp), so that both
// give the same result.
ModalBasis scene_basis(const Bat& bat, BeamTheory theory, const ImpactScene& scene) {
  return compute_modes(bat, theory, impact_mode_request(scene, compute_modes(bat, theory, ModeRequest::rigid_only())));
}

// The impact with every estimate (error_estimates.hpp): at a stated accuracy, the design cut as
// finely as it needs; otherwise at the bat's slices, the slicing error from the design at twice
// and four times them.
ImpactResult impact_with_estimates(const BatDesign& design, const Bat& bat, BeamTheory theory, ImpactScene scene) {
  scene.error_estimates = true;
  if (scene.accuracy > 0) {
    std::map<std::pair<int, double>, ModalBasis> bases;  // by slice count and mode_share_divisor, each solved once
    const auto basis_at = [&](int slices, const ImpactScene& rung) -> const ModalBasis& {
      const std::pair key(slices, rung.mode_share_divisor);
      auto found = bases.find(key);
      if (found == bases.end())
        found = bases.emplace(key, scene_basis(bat_with_slices(design, slices), theory, rung)).first;
      return found->second;
    };
    return simulate_within_accuracy(basis_at, bat.slices(), theory, scene);
  }
  const ModalBasis basis = scene_basis(bat, theory, scene);  // first: its refusals are the user's
  // The design at twice and four times the slices, as far as it can be cut and solved in
  // practice; where not, the slicing error stays unestimated (NaN).
  std::vector<ModalBasis> finer;
  try {
    for (int times = 1, slices = bat.slices(); times <= 2 && can_refine(bat.slices(), theory, times); ++times)
      finer.push_back(scene_basis(bat_with_slices(design, slices *= slicing_refinement), theory, scene));
  } catch (const InputError&) {
    finer.clear();
  }
  std::vector<const ModalBasis*> finer_bases;
  for (const ModalBasis& b : finer) finer_bases.push_back(&b);
  return simulate_impact_with_errors(basis, finer_bases, scene);
}

// The oblique options, before any work: "impact: --friction -0.1: expected ...".
void check_oblique_options(const ObliqueImpact& o) {
  const std::tuple<const char*, double, bool, const char*> options[] = {
      {"--undercut", o.undercut, valid_undercut(o.undercut), undercut_expected},
      {"--swing-tilt", o.swing_tilt, valid_swing_tilt(o.swing_tilt), swing_tilt_expected},
      {"--pitch-spin", o.pitch_spin, valid_pitch_spin(o.pitch_spin), pitch_spin_expected},
      {"--friction", o.friction, valid_friction(o.friction), friction_expected}};
  for (const auto& [name, x, valid, expected] : options)
    if (!valid) {
      char value[32];
      std::snprintf(value, sizeof value, "%.10g", x);
      throw InputError(std::string("impact: ") + name + " " + value + ": expected " + expected);
    }
}

void run_impact(ImpactOptions& o) {
  BatSource source;
  const BatDesign design = load_bat_design(bat_argument(o.bat_file, "--bat"), source);
  Bat bat = build_bat(design);
  if (o.slices > 0) bat = resample(bat, o.slices);
  o.scene.vibrational_modes = parse_modes(o.modes);
  if (o.scene.accuracy > 0 && o.scene.vibrational_modes >= 0)
    throw InputError("impact: --modes " + o.modes + " excludes --accuracy (a fixed number of modes cannot be held to "
                     "an accuracy): give --modes auto or all, or no --modes");
  o.scene.swing.about_center = o.center.has_value();
  o.scene.swing.center = o.center.value_or(0);
  o.scene.swing.cm_speed = o.cm_speed.value_or(0);
  const BeamTheory theory = parse_beam_theory(o.theory);
  // A ball that misses the bat is no impact to compute (a study's point records it as a status).
  if (o.scene.oblique.undercut != 0) {
    const std::string miss = miss_reason(compute_modes(bat, theory, ModeRequest::rigid_only()), o.scene);
    if (!miss.empty()) throw InputError("impact: --undercut: " + miss);
  }
  const ImpactResult r = impact_with_estimates(design, bat, theory, o.scene);
  if (r.status == CollisionStatus::refused_step) throw InputError("--dt: " + r.message);
  if (o.json) print_json(r, bat);
  else print_text(r, o.units, !o.scene.oblique.head_on());
  if (r.u_max > o.scene.ball.radius)
    std::fprintf(stderr, "sweetspot: warning: the ball compressed %.3g mm, past its radius %.3g mm: the force law is "
                         "not meant for that\n",
                 1e3 * r.u_max, 1e3 * o.scene.ball.radius);
}

}  // namespace

int parse_modes(const std::string& text) {
  if (text == "all") return all_modes;
  if (text == "auto") return auto_modes;
  try {
    std::size_t used = 0;
    const int n = std::stoi(text, &used);
    if (used == text.size() && n >= 0) return n;
  } catch (const std::exception&) {
  }
  throw InputError("--modes " + text + ": expected a number of vibrational modes (0, 1, 2, ...), 'all' or 'auto'");
}

// A hollow bat's [barrel] table as the wall used it: its load, and what calibrated it (null: not given).
Json barrel_json(const BarrelCalibration& b) {
  const double nan = std::nan("");
  return Json::Object()
      .add("load", std::string(b.load == WallLoad::point ? "point" : "patch"))
      .add("calibrated", Json::boolean(b.calibrated()))
      .add("hoop_frequency_measured", b.hoop_frequency > 0 ? b.hoop_frequency : nan)
      .add("compression_measured", b.compression > 0 ? b.compression : nan);
}

void add_ball_options(CLI::App& cmd, Ball& ball, std::string& named_ball) {
  cmd.add_option("--ball", named_ball, "the ball: a preset's name or a TOML file with a [ball] table [default: n2000]");
  cmd.add_option("--e0", ball.e0, "coefficient of restitution on a rigid wall, in (0, 1]")->capture_default_str();
  cmd.add_option("--ball-mass", ball.mass, "ball mass, kg, or e.g. 5.125oz")
      ->transform(quantity_option(Dimension::mass))
      ->capture_default_str();
  cmd.add_option("--ball-radius", ball.radius, "ball radius, m, or e.g. 1.45in")
      ->transform(quantity_option(Dimension::length))
      ->capture_default_str();
  cmd.add_option("--k1", ball.k1, "ball stiffness k1, N/m^a")->capture_default_str();
  cmd.add_option("--a", ball.a, "ball compression exponent a")->capture_default_str();
}

void resolve_ball(const CLI::App& cmd, const std::string& named_ball, Ball& ball) {
  if (!named_ball.empty()) {
    Ball named = load_ball(named_ball).ball;
    if (cmd.count("--e0")) named.e0 = ball.e0;
    if (cmd.count("--ball-mass")) named.mass = ball.mass;
    if (cmd.count("--ball-radius")) named.radius = ball.radius;
    if (cmd.count("--k1")) named.k1 = ball.k1;
    if (cmd.count("--a")) named.a = ball.a;
    ball = named;
  }
  // The ball's ranges, as a [ball] table and a study take them (ball_tests.hpp), before any work.
  // A named ball is in range (load_ball): what is not came from an option.
  if (const auto outside = ball_out_of_range(ball)) {
    // Each option's SI unit: a value given with another ("9oz") reaches here in SI.
    const std::map<std::string, std::pair<std::string, std::string>> options = {
        {"ball_mass", {"--ball-mass", " kg"}}, {"ball_radius", {"--ball-radius", " m"}}, {"k1", {"--k1", ""}},
        {"a", {"--a", ""}}, {"e0", {"--e0", ""}}};
    const auto& [option, unit] = options.at(outside->key);
    char value[32];
    std::snprintf(value, sizeof value, "%.10g", outside->value);
    throw InputError(cmd.get_name() + ": " + option + " " + value + unit + ": " + outside->expected());
  }
}

void resolve_integrator(const CLI::App& cmd, CollisionOptions& options) {
  if (cmd.count("--n2000") && cmd.count("--integrator") == 0) options = with_n2000_settings(options);
  if (cmd.count("--dt") == 0) options.dt = default_step(options.method);
  // dopri alone reads a tolerance: beside another integrator it would be silently ignored.
  if (cmd.count("--tolerance") && options.method != Method::dopri)
    throw InputError(cmd.get_name() + ": --tolerance " + cmd.get_option("--tolerance")->results().front() +
                     ": expected --integrator dopri beside it, the one integrator that reads a tolerance (" +
                     to_string(options.method) + " steps at --dt): give --integrator dopri" +
                     (cmd.get_option_no_throw("--step-accuracy") ? ", or --step-accuracy instead" : ""));
  // As history_step is bounded: a mistyped step would take billions of steps and their memory.
  if (!valid_step(options.dt)) {
    char text[200];
    std::snprintf(text, sizeof text, ": --dt %g: expected a step in [%g, %g] s (a finer one could take more than 1e7 "
                  "steps per contact, a coarser one steps over it)", options.dt, finest_step, coarsest_step);
    throw InputError(cmd.get_name() + text);
  }
}

// --accuracy (the total) and --step-accuracy, as a study's keys: each in its range, and neither
// beside what it chooses itself (it would be silently overridden).
void check_accuracy(const CLI::App& cmd, const ImpactScene& scene) {
  // The value as written (an empty one is refused before: main.cpp).
  const auto value = [&cmd](const char* name) { return "'" + cmd.get_option(name)->results().front() + "'"; };
  if (cmd.count("--accuracy") && !(scene.accuracy >= min_accuracy && scene.accuracy <= max_accuracy))
    throw InputError(cmd.get_name() + ": --accuracy " + value("--accuracy") + ": expected " + accuracy_expected);
  if (cmd.count("--step-accuracy") && !(std::isfinite(scene.step_accuracy) && scene.step_accuracy > 0))
    throw InputError(cmd.get_name() + ": --step-accuracy " + value("--step-accuracy") + ": expected " +
                     step_accuracy_expected);
  const auto option = [](std::string key) {
    std::ranges::replace(key, '_', '-');
    return "--" + key;
  };
  for (const AccuracyExclusion& pair : accuracy_exclusions) {
    const std::string given = option(pair.given), accuracy = option(pair.accuracy);
    if (cmd.count(given) && cmd.count(accuracy))
      throw InputError(cmd.get_name() + ": " + given + " excludes " + accuracy + " (which chooses " + pair.chooses +
                       "): give one of them");
  }
}

void add_integrator_options(CLI::App& cmd, CollisionOptions& options) {
  cmd.add_option("--integrator", options.method, "rk4 (N2000), exact (modal, any step) or dopri (adaptive)")
      ->transform(CLI::Validator(
          [](std::string& value) -> std::string {
            for (const Method m : {Method::rk4, Method::exact, Method::dopri})
              if (value == to_string(m)) return value = std::to_string(static_cast<int>(m)), std::string();
            return "'" + value + "': expected rk4, exact or dopri";
          },
          "rk4|exact|dopri"))
      ->default_str("exact");
  cmd.add_option("--dt", options.dt, "step (rk4, exact) or first step (dopri), s [default: 5e-6 for rk4, "
                                     "1e-5 for exact, 1e-6 for dopri]");
  cmd.add_flag("--n2000")->description(
      "N2000's settings: RK4 at 5 us (and 18 vibrational modes for impact) unless --integrator, --dt or "
      "--modes say otherwise");
  cmd.add_option("--tolerance", options.tolerance, "relative local error per step (dopri)")->capture_default_str();
  cmd.add_option("--window", options.window, "free flight followed after a separation, s")->capture_default_str();
}

void add_impact_command(CLI::App& app) {
  auto o = std::make_shared<ImpactOptions>();
  CLI::App* cmd = app.add_subcommand("impact", "One ball on one bat: exit speed, times, energies");
  cmd->add_option("--bat", o->bat_file, "bat file (TOML) or a shipped bat's name (r161, torpedo, ...)")->required();
  cmd->add_option("--theory", o->theory, "beam theory")
      ->check(CLI::IsMember({"timoshenko", "euler-bernoulli"}))
      ->capture_default_str();
  cmd->add_option("--slices", o->slices, "slice count N (default: the profile's own)")->check(CLI::Range(min_slices, max_slices));
  cmd->add_option("--z", o->scene.z, "impact location, m from the knob (anywhere on the bat), or e.g. 28in")
      ->transform(quantity_option(Dimension::length))
      ->required();
  cmd->add_option("--ball-speed", o->scene.ball_speed, "ball speed toward the bat, m/s, or e.g. 85mph")
      ->transform(quantity_option(Dimension::speed))
      ->required();
  auto* cm = cmd->add_option("--cm-speed", o->cm_speed, "bat centre-of-mass speed toward the ball, m/s, or e.g. 50mph")
                 ->transform(quantity_option(Dimension::speed));
  auto* center =
      cmd->add_option("--center", o->center, "rotation centre (the point at rest), m from the knob, or e.g. 3.5in")
          ->transform(quantity_option(Dimension::length));
  cm->excludes(center);
  center->excludes(cm);
  cmd->add_option("--omega", o->scene.swing.omega, "bat angular velocity, rad/s, or e.g. 480rpm")
      ->transform(quantity_option(Dimension::angular_speed))
      ->capture_default_str();
  cmd->add_flag("--pivot", o->scene.pivoted, "hold the bat at the rotation centre (N2000 Fig. 16)");
  // The impact in the plane of the swing (docs/oblique.md).
  cmd->add_option("--undercut", o->scene.oblique.undercut,
                  "the ball's centre above the bat's axis (negative: below), m, or e.g. 0.5in [default: 0]")
      ->transform(quantity_option(Dimension::length));
  cmd->add_option("--swing-tilt", o->scene.oblique.swing_tilt,
                  "the swing's (and the pitch's line's) angle above the horizontal, degrees [default: 0]");
  cmd->add_option("--pitch-spin", o->scene.oblique.pitch_spin,
                  "the pitch's backspin, rpm (negative: topspin) [default: 0]");
  cmd->add_option("--friction", o->scene.oblique.friction,
                  "coefficient of sliding friction between ball and bat, >= 0 [default: 0]");
  cmd->add_flag_function(
      "--rigid-grip", [o](std::int64_t) { o->scene.oblique.grip_stiffness = std::numeric_limits<double>::infinity(); },
      "the textbooks' rigid ball across the line of centres: slide, then roll (no tangential stretch)");
  cmd->add_option("--modes", o->modes, "vibrational modes kept: a number, 'all' or 'auto' [default: auto; 18 with "
                                       "--n2000]");
  cmd->add_option("--mode-tolerance", o->scene.mode_tolerance,
                  "with --modes auto: relative vf error allowed the dropped modes")
      ->capture_default_str();
  cmd->add_option("--accuracy", o->scene.accuracy,
                  "total relative vf error allowed (slicing, modes and step): chooses the slices, the modes and "
                  "the step");
  cmd->add_option("--step-accuracy", o->scene.step_accuracy,
                  "relative vf error the integration may add: chooses the step (or tolerance) instead of --dt");
  add_ball_options(*cmd, o->scene.ball, o->named_ball);
  add_integrator_options(*cmd, o->scene.integrator);
  cmd->add_flag("--json", o->json, "print one JSON object (in SI units)");
  o->units.add_option(*cmd);
  cmd->callback([o, cmd] {
    o->units.check_text_output("impact", o->json);
    check_accuracy(*cmd, o->scene);
    if (!valid_omega(o->scene.swing.omega)) {
      char value[40];  // in rad/s, with its unit: "-480rpm" reaches here as -50.27 rad/s
      std::snprintf(value, sizeof value, "%.10g rad/s", o->scene.swing.omega);
      throw InputError(std::string("impact: --omega ") + value + ": expected " + omega_expected);
    }
    check_oblique_options(o->scene.oblique);
    resolve_integrator(*cmd, o->scene.integrator);
    resolve_ball(*cmd, o->named_ball, o->scene.ball);
    if (cmd->count("--n2000") && cmd->count("--modes") == 0) {
      if (cmd->count("--accuracy"))
        throw InputError("impact: --n2000 keeps N2000's 18 modes, which cannot be held to --accuracy: give --modes "
                         "auto or all beside it, or no --n2000");
      o->modes = std::to_string(n2000_modes);
    }
    // auto alone reads a mode tolerance: beside a fixed set it would be silently ignored.
    if (cmd->count("--mode-tolerance") && parse_modes(o->modes) != auto_modes)
      throw InputError("impact: --mode-tolerance " + cmd->get_option("--mode-tolerance")->results().front() +
                       ": expected --modes auto beside it, the one choice of modes that reads a tolerance (" +
                       (cmd->count("--modes") ? "--modes " + o->modes : std::string("--n2000")) +
                       " keeps a fixed set): give --modes auto, or no --mode-tolerance");
    if (!o->cm_speed && !o->center) throw InputError("impact: give the swing as --cm-speed or as --center");
    run_impact(*o);
  });
}

}  // namespace sweetspot::app
