// sweetspot certify: a bat in the virtual test rig against a performance standard.
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "bat_argument.hpp"
#include "certify_uncertainty.hpp"
#include "commands.hpp"
#include "display_units.hpp"
#include "json.hpp"
#include "quantity_option.hpp"
#include "sweetspot/ball/ball_file.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot::app {

namespace {

struct CertifyCommand {
  std::string bat_file;
  std::string uncertainty;  // an uncertainty study of model "certification" in place of the bat
  std::string output;       // its dataset (default: none kept)
  std::string standard = "bbcor";
  std::string theory = "timoshenko";
  std::string modes = "auto";
  std::string ball = "ncaa";  // the standards' ball (standards.hpp)
  bool json = false;
  DisplayUnits units;
  std::optional<double> e0, ball_speed, pivot;
  CertifyOptions options;
};

Json checks_json(const std::vector<RuleCheck>& checks) {
  std::vector<Json> items;
  for (const RuleCheck& c : checks)
    items.push_back(Json::Object()
                        .add("rule", c.rule)
                        .add("value", c.value)
                        .add("limit", c.limit)
                        .add("pass", Json::boolean(c.pass)));
  return Json::array(items);
}

void print_json(const std::string& ball, double accuracy, const Certification& c) {
  Json::Object out;
  out.add("standard", c.standard.name)
      .add("z_max", c.z_max)
      .add("e_a", c.at_max.e_a)
      .add(to_string(c.standard.measure), c.measure)
      .add("moi_pivot", c.moi_pivot)
      .add("moi_pivot_model", c.moi_pivot_model)
      .add("mass", c.mass)
      .add("length", c.length)
      .add("drop", c.drop)
      .add("barrel_diameter", c.barrel_diameter)
      .add("hoop_frequency", c.hoop_frequency)          // these four null where z_max is solid
      .add("barrel_compression", c.barrel_compression)  // N at 0.04 in
      .add("barrel_phi", c.barrel_phi)
      .add("barrel_compliance", c.barrel_compliance)
      .add("pivot", c.standard.pivot)
      .add("ball_speed", c.standard.ball_speed)
      .add("ball", ball)
      .add("e0", c.standard.ball.e0)
      .add("cor_speed", c.standard.ball.cor_speed)
      .add("cor_slope", c.standard.ball.cor_slope)
      .add("checks", checks_json(c.checks))
      .add("pass", Json::boolean(c.pass));
  if (accuracy > 0)
    out.add("accuracy", accuracy)
        .add("slices_used", c.slices_used)
        .add("slicing_error", c.slicing_error)
        .add("modes_error", c.modes_error)
        .add("step_error", c.step_error)
        .add("total_error", c.total_error)
        .add("accurate", Json::boolean(c.accurate));
  if (accuracy > 0 && !c.accurate) out.add("unmet", c.unmet);
  if (c.hollow) out.add("barrel", barrel_json(c.barrel));
  std::printf("%s\n", Json(out).text().c_str());
}

// The swing weight as the rules give it, and the slices' own: one line in either system.
std::string moi_text(const Certification& c, const DisplayUnits& u) {
  const DisplayUnits si = DisplayUnits::si_units(), us = DisplayUnits::us_units();
  if (!u.us())
    return si.moment_of_inertia(c.moi_pivot, "%.6f") + " (" + us.moment_of_inertia(c.moi_pivot, "%.0f") +
           "; the model's slices: " + DisplayUnits::number(c.moi_pivot_model, "%.6f") + ")";
  return us.moment_of_inertia(c.moi_pivot, "%.0f") + " (" + si.moment_of_inertia(c.moi_pivot, "%.6f") +
         "; the model's slices: " + us.moment_of_inertia(c.moi_pivot_model, "%.0f") + ")";
}

void print_text(const std::string& bat_name, const std::string& ball, double accuracy, const Certification& c,
                const DisplayUnits& u) {
  const Standard& s = c.standard;
  const DisplayUnits si = DisplayUnits::si_units(), us = DisplayUnits::us_units();
  std::printf("%s against %s: %s\n", bat_name.c_str(), s.title.c_str(), c.pass ? "PASS" : "FAIL");
  std::printf("rig             pivot %s from the knob, ball %s\n", u.length(s.pivot, "%.4f").c_str(),
              u.both(si.speed(s.ball_speed, "%.4g"), us.speed(s.ball_speed, "%.4g")).c_str());
  std::printf("ball            %s: %s, COR %.4g at %s, %s; %.4g on a flat wall at the rig's speed\n", ball.c_str(),
              u.mass(s.ball.mass, "%.4g").c_str(), s.ball.e0, u.speed(s.ball.cor_speed, "%.4g").c_str(),
              u.per_speed(s.ball.cor_slope, "%.3g").c_str(), s.ball.cor_at(s.ball_speed));
  std::printf("maximum %-7s %.6f at z = %s from the knob (%.2f in from the barrel end)\n", to_string(s.measure),
              c.measure, u.length(c.z_max, "%.5f").c_str(), (c.length - c.z_max) / metres_per_inch);
  std::printf("e_a             %.6f there (bbcor %.6f, besr %.6f, bpf %.6f)\n", c.at_max.e_a, c.at_max.bbcor,
              c.at_max.besr, c.at_max.bpf);
  std::printf("MOI about pivot %s\n", moi_text(c, u).c_str());
  std::printf("length          %s, weight %s, drop %.2f\n",
              u.both(si.length(c.length, "%.4f"), us.length(c.length, "%.2f")).c_str(),
              u.both(si.mass(c.mass, "%.4f"), us.mass(c.mass, "%.2f")).c_str(), c.drop);
  std::printf("barrel diameter %s\n",
              u.both(si.length(c.barrel_diameter, "%.5f"), us.length(c.barrel_diameter, "%.4f")).c_str());
  if (std::isfinite(c.hoop_frequency)) {
    std::printf("barrel wall     hoop frequency %.5g Hz, compression %.5g N (%.4g lbf) at 0.04 in, there\n",
                c.hoop_frequency, c.barrel_compression, c.barrel_compression / newtons_per_pound_force);
    if (std::isfinite(c.barrel_phi))
      std::printf("wall's load     %s: phi_2 %.5g, other harmonics %.4g m/N at the peak\n",
                  c.barrel.load == WallLoad::point ? "point" : "patch", c.barrel_phi, c.barrel_compliance);
  }
  if (c.barrel.calibrated()) {
    std::printf("calibrated wall");
    if (c.barrel.hoop_frequency > 0) std::printf(" to hoop_frequency %.6g Hz", c.barrel.hoop_frequency);
    if (c.barrel.compression > 0)
      std::printf("%s compression %.6g N", c.barrel.hoop_frequency > 0 ? " and" : " to", c.barrel.compression);
    std::printf(" ([barrel], at its reference section)\n");
  }
  if (accuracy > 0)
    std::printf("accuracy        %.3g stated: %.3g estimated%s%s (slicing %.3g at %d slices, modes %.3g, step %.3g)\n",
                accuracy, c.total_error, c.accurate ? "" : ", NOT MET: ", c.unmet.c_str(), c.slicing_error,
                c.slices_used, c.modes_error, c.step_error);
  std::printf("%-16s %12s %12s  %s\n", "rule", "value", "limit", "result");
  for (const RuleCheck& r : c.checks)
    std::printf("%-16s %12.6g %12.6g  %s\n", r.rule.c_str(), r.value, r.limit, r.pass ? "pass" : "FAIL");
}

void run_certify(CertifyCommand& o) {
  if (o.bat_file.empty() == o.uncertainty.empty())
    throw InputError(o.uncertainty.empty() ? "certify: expected a bat, or --uncertainty with a study file"
                                           : "certify: a bat and --uncertainty " + o.uncertainty +
                                                 ": the study names its bat; give one or the other");
  if (!o.uncertainty.empty()) {
    certify_under_uncertainty(o.uncertainty, o.output, o.json);
    return;
  }
  if (!o.output.empty()) throw InputError("certify: --output " + o.output + " applies only with --uncertainty");
  BatSource source;
  const BatDesign design = load_bat_design(bat_argument(o.bat_file, "bat"), source);
  o.options.e0 = o.e0, o.options.ball_speed = o.ball_speed, o.options.pivot = o.pivot;
  o.options.ball = load_ball(o.ball).ball;
  o.options.vibrational_modes = parse_modes(o.modes);
  o.options.theory = parse_beam_theory(o.theory);
  const Certification c = certify(design, find_standard(o.standard), o.options);
  const double accuracy = o.options.accuracy.value_or(0);
  if (o.json) print_json(o.ball, accuracy, c);
  else print_text(design.name, o.ball, accuracy, c, o.units);
  if (!c.pass) exit_status = failed_check;
}

}  // namespace

void add_certify_command(CLI::App& app) {
  auto o = std::make_shared<CertifyCommand>();
  CLI::App* cmd = app.add_subcommand("certify", "A bat in the virtual test rig against BBCOR, BESR or BPF");
  cmd->add_option("bat", o->bat_file, "bat file (TOML) or a shipped bat's name (r161, alloy_bbcor, ...)");
  cmd->add_option("--uncertainty", o->uncertainty,
                  "an uncertainty study (TOML) of model certification: the pass probability under its scatter");
  cmd->add_option("-o,--output", o->output, "with --uncertainty: keep its dataset here (HDF5)");
  cmd->add_option("--standard", o->standard, "bbcor (NCAA/NFHS), besr (NCAA 1999-2010) or bpf (USSSA)")
      ->capture_default_str();
  cmd->add_option("--ball", o->ball, "the rig's ball: a preset's name or a TOML file with a [ball] table")
      ->capture_default_str();
  cmd->add_option("--e0", o->e0, "the ball's COR on a rigid flat wall at its reference speed [default: the ball's]");
  cmd->add_option("--ball-speed", o->ball_speed, "the rig's ball speed, m/s, or e.g. 93mph [default: the standard's]")
      ->transform(quantity_option(Dimension::speed));
  cmd->add_option("--pivot-point", o->pivot, "the rig's pivot, m from the knob, or e.g. 6in [default: 0.1524, 6 in]")
      ->transform(quantity_option(Dimension::length));
  cmd->add_option("--theory", o->theory, "beam theory")
      ->check(CLI::IsMember({"timoshenko", "euler-bernoulli"}))
      ->capture_default_str();
  cmd->add_option("--slices", o->options.slices, "slice count N (default: the bat's own)")
      ->check(CLI::Range(min_slices, max_slices));
  cmd->add_option("--modes", o->modes, "vibrational modes kept: a number, 'all' or 'auto'")->capture_default_str();
  cmd->add_option("--accuracy", o->options.accuracy,
                  "total relative error of the measure (1e-7 to 0.1): chooses the slices, modes and step");
  cmd->add_flag("--json", o->json, "print one JSON object (in SI units)");
  o->units.add_option(*cmd);
  cmd->callback([o, cmd] {
    o->units.check_text_output("certify", o->json);
    if (cmd->count("--output") > 0 && o->output.empty())
      throw InputError("certify: --output \"\": the output path is empty; expected the name of a file to write");
    if (!o->uncertainty.empty() && o->units.us())
      throw InputError("certify: --units us with --uncertainty " + o->uncertainty +
                       ": its report is in SI units; expected no --units");
    // An uncertainty study sets the rig's settings itself: these would be silently ignored.
    if (!o->uncertainty.empty())
      for (const char* name : {"--standard", "--ball", "--e0", "--ball-speed", "--pivot-point", "--theory", "--slices",
                               "--modes", "--accuracy"})
        if (cmd->count(name) > 0) {
          // A quantity's value is kept converted to SI: its option is named alone.
          const bool quantity = std::string_view(name) == "--ball-speed" || std::string_view(name) == "--pivot-point";
          throw InputError(std::string("certify: ") + name +
                           (quantity ? "" : " " + cmd->get_option(name)->results().front()) + " with --uncertainty " +
                           o->uncertainty +
                           ": the study sets the rig's settings; give it in the study's [scene] instead");
        }
    run_certify(*o);
  });
}

}  // namespace sweetspot::app
