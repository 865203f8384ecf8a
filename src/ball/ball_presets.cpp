#include "sweetspot/ball/ball_presets.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

constexpr double mph = metres_per_second_per_mph, inch = metres_per_inch;
constexpr double ounce = kilograms_per_ounce, pound_force = 4.4482216152605;

double radius_of_circumference(double inches) { return inches * inch / (2 * std::numbers::pi); }

// How a ball's COR falls with speed: about 0.001 per mph, the order of Nathan's fits to measured
// baseballs (recalled, not verified: the tables were not found in the project's reference search).
constexpr double recalled_cor_slope = -0.001 / mph;

BallTests baseball_of_the_league_spec() {
  BallTests t;
  t.mass = 5.125 * ounce;                    // 5 to 5.25 oz
  t.radius = radius_of_circumference(9.125);  // 9 to 9.25 in around
  t.cor = {{85 * 0.3048, 0.546}};             // 0.514 to 0.578 at 85 ft/s on a wall of ash
  t.cor_slope = recalled_cor_slope;
  t.k1 = Ball{}.k1;  // N2000's fit of a measured baseball's law
  t.exponent = Ball{}.a;
  return t;
}

// N2000's ball as tests: its own law, one COR at every speed, no curvature.
BallTests n2000_ball() {
  const Ball b;
  BallTests t;
  t.mass = b.mass, t.radius = b.radius, t.cor = {{60 * mph, b.e0}}, t.k1 = b.k1, t.exponent = b.a;
  t.curved_contact = false;
  return t;
}

BallTests rated_softball(double cor, double compression_lbf) {
  BallTests t;
  t.mass = 6.625 * ounce;                     // 6.25 to 7 oz
  t.radius = radius_of_circumference(11.9375);  // 11 7/8 to 12 in around
  t.cor = {{60 * mph, cor}};                  // the rating: COR at 60 mph (ASTM F1887)
  t.cor_slope = recalled_cor_slope;
  t.compression_force = compression_lbf * pound_force;  // at 0.25 in (ASTM F1888)
  return t;
}

std::vector<BallPreset> make_presets() {
  const std::string league =
      "COR 0.546 +- 0.032 at 85 ft/s on ash (MLB's specification, D. Ropeik, \"Squeezing the 'juice' out of "
      "baseballs\", msnbc.com); 5-5.25 oz, 9-9.25 in (Official Baseball Rules 3.01); k1 and a of N2000 Fig. 2; "
      "COR slope -0.001 per mph (recalled)";
  const std::string softball =
      "ASA/USA Softball 12-in ball ratings (COR at 60 mph, ASTM F1887; compression at 0.25 in, ASTM F1888); "
      "6.25-7 oz, 11 7/8-12 in; stiffness from the static compression (a lower bound of the dynamic one); COR "
      "slope -0.001 per mph (recalled)";
  return {
      {"n2000", "N2000's model ball (e0 = 0.5 at every speed, flat contact)",
       "A. M. Nathan, Am. J. Phys. 68, 979 (2000), Fig. 2", n2000_ball()},
      {"mlb", "a baseball of the MLB specification's centre", league, baseball_of_the_league_spec()},
      {"ncaa", "the BBCOR rig's baseball (the league specification's centre; the NCAA protocol's own ball "
               "specification was not found)",
       league, baseball_of_the_league_spec()},
      {"softball_44_375", "12-in softball, .44 COR / 375 lbf", softball, rated_softball(0.44, 375)},
      {"softball_47_525", "12-in softball, .47 COR / 525 lbf", softball, rated_softball(0.47, 525)},
  };
}

}  // namespace

const std::vector<BallPreset>& ball_presets() {
  static const std::vector<BallPreset> all = make_presets();
  return all;
}

const BallPreset& find_ball_preset(std::string_view name, const std::string& where) {
  const std::vector<BallPreset>& all = ball_presets();
  const auto it = std::ranges::find(all, name, &BallPreset::name);
  if (it != all.end()) return *it;
  std::vector<std::string> names;
  for (const BallPreset& p : all) names.push_back(p.name);
  throw InputError(where + ": preset = " + detail::quote(name) + ": expected one of " + detail::join(names));
}

BallFit preset_ball(const BallPreset& preset) {
  return fit_ball(preset.tests, "ball preset " + preset.name);
}

}  // namespace sweetspot
