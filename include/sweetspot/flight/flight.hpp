#pragma once
// The batted ball's flight from launch to landing: gravity, drag and Magnus lift that depend on
// the spin (aerodynamics.hpp), spin decay, the air's density and a uniform wind (air.hpp).
//
// Frame (the trajectory calculator's): origin at home plate on the ground, y toward centre field,
// x toward right field, z up. The ball leaves at height `height` above the plate with speed
// `speed`, `angle` above the horizontal, `direction` from the y axis toward right field. Backspin
// (the spin that lifts) and sidespin are the spin's components perpendicular to the launch
// velocity; positive sidespin curves the ball toward left field (toward -x), as in the
// calculator. The spin axis keeps its direction in space; only its rate decays.
//
// The equations are integrated by Boost.Odeint's Dormand-Prince 5(4) with error control and dense
// output; the apex (v_z = 0) and the landing (z = 0) are roots of the dense output found by
// Boost.Math's TOMS 748 to machine precision.
#include <optional>
#include <vector>

#include "sweetspot/flight/aerodynamics.hpp"
#include "sweetspot/flight/air.hpp"

namespace sweetspot {

struct Launch {
  double speed = 0;       // m/s
  double angle = 0;       // deg above the horizontal
  double direction = 0;   // deg from centre field toward right field
  double backspin = 0;    // rad/s
  double sidespin = 0;    // rad/s
  double height = 0.9144; // m above the ground (3 ft, the calculator's default)
};

struct FlightOptions {
  Aerodynamics aerodynamics;
  FlightBall ball;
  double gravity = 9.80665;          // m/s^2
  bool drag = true;                  // false: no drag (and no lift): the vacuum parabola
  bool lift = true;                  // false: no Magnus force
  double tolerance = 1e-10;          // the integrator's relative and absolute (m, m/s) tolerance
  double max_time = 60;              // s: a flight that has not landed by then is refused
  double sample_interval = 0;        // s: >= 1 ms records the trajectory at that interval (and landing)
};

struct FlightSample {
  double t, x, y, z, vx, vy, vz;
};

struct FlightResult {
  double distance = 0;        // m, horizontal, from home plate to the landing point
  double landing_x = 0;       // m, toward right field
  double landing_y = 0;       // m, toward centre field
  double bearing = 0;         // deg, of the landing point from centre field toward right field
  double apex = 0;            // m above the ground (the launch height if the ball never rises)
  double apex_time = 0;       // s
  double hang_time = 0;       // s, from launch to landing
  double landing_angle = 0;   // deg below the horizontal at landing
  double landing_speed = 0;   // m/s
  double landing_spin = 0;    // rad/s, what the spin has decayed to
  double air_density = 0;     // kg/m^3
  std::vector<FlightSample> samples;  // when asked (FlightOptions::sample_interval)
};

// The first thing unphysical about a launch, or nothing: speed >= 0, angle in [-90, 90] deg,
// direction in [-360, 360] deg, height in [0, 1000] m, everything finite (keys speed, angle,
// direction, backspin, sidespin, height). And about the options: positive ball mass and radius,
// gravity, tolerance, max_time and spin decay time, finite coefficients, sample_interval 0 (none)
// or at least 1 ms.
std::optional<InputProblem> launch_problem(const Launch& launch);
std::optional<InputProblem> flight_options_problem(const FlightOptions& options);

// The flight; checks the launch, the air and the options first (InputError from their
// problems). A launch at height 0 that does not rise lands at once (distance 0).
// std::runtime_error when the ball has not landed by max_time.
FlightResult simulate_flight(const Launch& launch, const Air& air, const FlightOptions& options = {});

}  // namespace sweetspot
