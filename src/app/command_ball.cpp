// sweetspot ball: the standard ball tests run on the model's ball (README "Balls"), so that a lab
// can enter its own ball and check it: the fit, the COR on a flat wall against speed, and the COR
// and dynamic stiffness on a rigid cylinder.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "display_units.hpp"
#include "json.hpp"
#include "quantity_option.hpp"
#include "sweetspot/ball/ball_file.hpp"
#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/impact/ball_lab.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot::app {

namespace {

constexpr double mph = metres_per_second_per_mph, inch = metres_per_inch;
constexpr double pound_force_per_inch = 4.4482216152605 / metres_per_inch;

struct BallCommand {
  std::string ball = "n2000";
  std::vector<double> speeds_mph = {40, 60, 80, 100, 120, 136};
  double cylinder_diameter = 2.625 * inch;  // a BBCOR barrel
  double cylinder_speed_mph = 60;
  bool json = false;
  DisplayUnits units;
};

Json test_json(const BallLabTest& t) {
  return Json::Object()
      .add("speed", t.speed)
      .add("cor", t.cor)
      .add("peak_force", t.peak_force)
      .add("dynamic_stiffness", t.dynamic_stiffness)
      .add("contact_time", t.contact_time);
}

void print_test(const char* surface, const BallLabTest& t) {
  std::printf("%-9s %6.1f %7.2f  %.4f  %9.0f  %8.0f %8.0f  %.3f\n", surface, t.speed / mph, t.speed, t.cor,
              t.peak_force, t.dynamic_stiffness / pound_force_per_inch, t.dynamic_stiffness / 1e3,
              1e3 * t.contact_time);
}

// A number as short as it reads (0, not 0.000000).
std::string shown(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", x);
  return text;
}

// The slowest test speed, mph: a preset's ball leaves a flat wall after about 18 ms at 0.01 mph,
// within the collision's 50 ms, and never left it at 1e-300 mph (the test failed after the work).
constexpr double slowest_test_mph = 0.01;

bool valid_test_speed(double mph_value) {
  return mph_value >= slowest_test_mph && mph_value * mph <= max_cor_law_speed;
}

void run_ball(const BallCommand& o) {
  for (const double v : o.speeds_mph)
    if (!valid_test_speed(v))
      throw InputError("ball: --speeds " + shown(v) + ": expected speeds from 0.01 to 223.7 mph");
  if (!(o.cylinder_diameter > 0 && o.cylinder_diameter < 1))
    throw InputError("ball: --cylinder-diameter " + shown(o.cylinder_diameter) + ": expected (0, 1) m");
  if (!valid_test_speed(o.cylinder_speed_mph))
    throw InputError("ball: --cylinder-speed " + shown(o.cylinder_speed_mph) + ": expected 0.01 to 223.7 mph");
  const BallFit fit = load_ball(o.ball);
  const Ball& b = fit.ball;
  std::vector<BallLabTest> flat;
  for (const double v : o.speeds_mph) flat.push_back(ball_lab_test(b, v * mph, 0));
  const BallLabTest cylinder = ball_lab_test(b, o.cylinder_speed_mph * mph, o.cylinder_diameter / 2);
  if (o.json) {
    std::vector<Json> rows;
    for (const BallLabTest& t : flat) rows.push_back(test_json(t));
    const Json out = Json::Object()
                         .add("ball", o.ball)
                         .add("mass", b.mass)
                         .add("radius", b.radius)
                         .add("k1", b.k1)
                         .add("a", b.a)
                         .add("e0", b.e0)
                         .add("cor_speed", b.cor_speed)
                         .add("cor_slope", b.cor_slope)
                         .add("curved_contact", Json::boolean(b.curved_contact))
                         .add("stiffness_from", fit.stiffness_from)
                         .add("cor_residual", fit.cor_residual)
                         .add("stiffness_residual", fit.stiffness_residual)
                         .add("flat_wall", Json::array(rows))
                         .add("cylinder_diameter", o.cylinder_diameter)
                         .add("cylinder", test_json(cylinder));
    std::printf("%s\n", out.text().c_str());
    return;
  }
  const DisplayUnits& u = o.units;
  const DisplayUnits si = DisplayUnits::si_units(), us = DisplayUnits::us_units();
  std::printf("ball %s: %s, radius %s; F = %.4g u^%.4g (from %s, residual %.2g)\n", o.ball.c_str(),
              u.mass(b.mass, "%.4g").c_str(), u.length(b.radius, "%.4g").c_str(), b.k1, b.a,
              fit.stiffness_from.c_str(), fit.stiffness_residual);
  std::printf("COR %.4f at %s, %s; fit residual %.2g; %s contact\n", b.e0,
              u.both(si.speed(b.cor_speed, "%.4g"), us.speed(b.cor_speed, "%.4g")).c_str(),
              u.both(si.per_speed(b.cor_slope, "%.4g"), us.per_speed(b.cor_slope, "%.4g")).c_str(), fit.cor_residual,
              b.curved_contact ? "curved" : "flat");
  std::printf("%-9s %6s %7s  %-6s  %9s  %8s %8s  %s\n", "surface", "mph", "m/s", "COR", "F_peak/N", "DS lbf/in",
              "kN/m", "contact/ms");
  for (const BallLabTest& t : flat) print_test("flat", t);
  char cylinder_name[32];
  std::snprintf(cylinder_name, sizeof cylinder_name, "cyl %.3gin", o.cylinder_diameter / inch);
  print_test(cylinder_name, cylinder);
}

}  // namespace

void add_ball_command(CLI::App& app) {
  auto o = std::make_shared<BallCommand>();
  CLI::App* cmd = app.add_subcommand("ball", "The standard ball tests (COR against speed, cylinder COR, dynamic "
                                             "stiffness) run on a ball of the model");
  cmd->add_option("ball", o->ball, "a preset's name or a TOML file with a [ball] table")->capture_default_str();
  cmd->add_option("--speeds", o->speeds_mph, "flat-wall test speeds, mph (plain numbers), or e.g. 40m/s")
      ->transform(quantity_option(Dimension::speed, "mph"))
      ->capture_default_str();
  cmd->add_option("--cylinder-diameter", o->cylinder_diameter, "the rigid cylinder's diameter, m, or e.g. 2.625in")
      ->transform(quantity_option(Dimension::length))
      ->capture_default_str();
  cmd->add_option("--cylinder-speed", o->cylinder_speed_mph,
                  "the cylinder test's speed, mph (plain numbers), or e.g. 27m/s")
      ->transform(quantity_option(Dimension::speed, "mph"))
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "print one JSON object (in SI units)");
  o->units.add_option(*cmd);
  cmd->callback([o] {
    o->units.check_text_output("ball", o->json);
    run_ball(*o);
  });
}

}  // namespace sweetspot::app
