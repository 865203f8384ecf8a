#pragma once
// A ball as the labs specify it, and the force law fitted to it (README "Balls").
//   COR (ASTM F1887): rebound over inbound speed on a massive, rigid, flat wall, at one or more
//     speeds; a real ball's falls as it is struck harder.
//   Dynamic stiffness (ASTM F2845): the peak force F of an impact at speed v, normalised by the
//     ball's mass and speed as a linear spring's would be, DS = (F / v)^2 / m (the form as
//     recalled: the standard's text was not found in the project's reference search).
//   Compression (ASTM F1888): the force that squeezes the ball 0.25 in between flat plates.
// The model's law F = k1 u^a takes k1 from the stiffness (or the compression) and a from how the
// stiffness grows with speed (or as given); its COR law e(v) = e0 + slope (v - v0) (Ball) is the
// least-squares line through the COR data, or one COR and the slope given.
#include <optional>
#include <string>
#include <vector>

#include "sweetspot/contact/ball.hpp"

namespace sweetspot {

struct SpeedValue {
  double speed = 0;  // m/s
  double value = 0;
};

struct BallTests {
  double mass = 0;    // kg
  double radius = 0;  // m
  std::vector<SpeedValue> cor;  // flat-wall COR at these speeds (at least one)
  double cor_slope = 0;         // per m/s, with a single COR: how it falls with speed
  // Stiffness, one of: dynamic stiffness (N/m) at these speeds, on a flat wall or, if
  // stiffness_cylinder_diameter > 0, on a rigid cylinder of that diameter (m); or the static
  // compression force (N) at compression_displacement (m between the plates, 0.25 in by F1888),
  // or the force law itself (k1, N/m^a).
  std::vector<SpeedValue> dynamic_stiffness;
  double stiffness_cylinder_diameter = 0;
  double compression_force = 0;
  double compression_displacement = 0.25 * 0.0254;
  double k1 = 0;
  double exponent = 0;  // a; 0: fitted from two or more stiffness speeds, else default_exponent
  bool curved_contact = true;
};

// N2000's exponent (Fig. 2), what a ball takes when its stiffness at one speed says nothing of a.
inline constexpr double default_ball_exponent = 1.84;

// The ranges of a ball's values, [low, high], the same wherever a ball is given: a [ball] table
// (ball files, a study's, a rig's, an optimisation's), a study's [scene] keys and axes, the
// commands' options (--ball-mass, --e0, ...) and Python's arguments. A baseball weighs 0.145 kg,
// is 0.0366 m in radius, has k1 about 1e8 N/m^a with a = 1.84 and a COR about 0.5; a table-tennis
// ball weighs 2.7 g, a medicine ball up to 10 kg. Below a COR of 0.05 the expansion branch's
// exponent b = (1 + a)/e0^2 - 1 passes 1100 and the force law is a wall, no ball; a compression
// of less than 0.1 mm (F1888 squeezes 0.25 in) would give k1 beyond its range.
struct BallRange {
  double low, high;
  const char* what;  // "a mass", "a COR", ...
  const char* unit;  // "kg", "" for a pure number
};
inline constexpr BallRange ball_mass_range{1e-3, 10, "a mass", "kg"};
inline constexpr BallRange ball_radius_range{1e-3, 1, "a radius", "m"};
inline constexpr BallRange ball_k1_range{1e3, 1e12, "a stiffness k1", "N/m^a"};
inline constexpr BallRange ball_exponent_range{0.5, 3, "an exponent a", ""};
inline constexpr BallRange ball_cor_range{0.05, 1, "a COR", ""};
inline constexpr BallRange ball_compression_range{10, 1e5, "a force", "N"};
inline constexpr BallRange ball_dynamic_stiffness_range{1e4, 1e9, "a stiffness", "N/m"};
inline constexpr BallRange ball_displacement_range{1e-4, 1, "a displacement", "m"};  // at most the radius
inline constexpr BallRange ball_cylinder_diameter_range{0.01, 1, "a diameter", "m"};
inline bool in_range(BallRange r, double x) { return x >= r.low && x <= r.high; }
// "a mass in [0.001, 10] kg"
std::string range_text(BallRange r);
// A ball's value outside its range: its key as a study names it (ball_mass, ball_radius, k1, a,
// e0), the value, and "expected ..." as text() says it.
struct OutOfRange {
  std::string key;
  double value;
  BallRange range;
  std::string expected() const { return "expected " + range_text(range); }
};
// The first of the ball's values (mass, radius, k1, a, e0) outside its range, or nothing.
std::optional<OutOfRange> ball_out_of_range(const Ball& ball);
// The speed (0 or max_cor_law_speed) at which the ball's COR law leaves ball_cor_range, or
// nothing: a line in COR against speed stays in range between its ends when both are.
std::optional<double> cor_law_leaves_range(const Ball& ball);
// Where a speed-dependent COR law leaves ball_cor_range: "with cor_slope = ... per m/s about ...
// m/s gives a COR of ... at ... m/s: not a physical ball (expected ...)", to follow the key that
// set the law (e0 where one was given). Nothing otherwise.
std::optional<std::string> cor_law_misfit(const Ball& ball);

struct BallFit {
  Ball ball;
  // Root-mean-square residuals of the fit: COR (absolute) and dynamic stiffness (relative); 0
  // where the data determine the parameters exactly (one COR, one stiffness).
  double cor_residual = 0;
  double stiffness_residual = 0;
  std::string stiffness_from;  // "dynamic stiffness", "compression" or "k1"
};

// Fits the model's ball to its tests. Throws InputError starting with `where` (the file and
// table, e.g. "study.toml: [ball]") naming the key, the value and what was expected.
BallFit fit_ball(const BallTests& tests, const std::string& where);

// The peak force and the dynamic stiffness (F / v)^2 / m of `ball` striking a rigid surface of
// curvature factor 1 at speed v, in closed form (the compression branch of its law).
double peak_force_on_rigid(const Ball& ball, double speed);
double dynamic_stiffness_on_rigid(const Ball& ball, double speed);

}  // namespace sweetspot
