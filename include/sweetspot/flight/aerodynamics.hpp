#pragma once
// The batted ball's aerodynamic coefficients against its spin: A. M. Nathan's trajectory
// calculator (baseball.physics.illinois.edu/trajectory-calculator-new.html), whose constants are
// fitted to tracked batted balls; the values below are those its spreadsheet ships and its
// reimplementations use (pybaseball's analysis/trajectories/batted_balls/parameters.py):
//   C_D = cd0 + cd_spin (omega_perp / 1000 rpm)
//   C_L = cl2 S / (cl0 + cl1 S),   S = R omega_perp / v   (the spin factor)
// The spin decays as d(omega)/dt = -omega v / (tau v_ref), v_ref = 100 mph: the calculator's
// exp(-t / (tau 146.7 ft/s / v)) for a constant speed. The calculator ships tau = 10000 s
// (practically no decay); shorter times (tens of seconds) are what older studies assumed.
namespace sweetspot {

struct Aerodynamics {
  double cd0 = 0.3008;
  double cd_spin = 0.0292;        // per 1000 rpm of spin perpendicular to the air speed
  double cl0 = 0.583;
  double cl1 = 2.333;
  double cl2 = 1.120;
  double spin_decay_time = 1e4;   // tau, s, at 100 mph
};

// The calculator's ball: 5.125 oz and a 9.125-in circumference.
struct FlightBall {
  double mass = 0.145291306015625;        // kg (5.125 oz)
  double radius = 0.03688813693512404;     // m (9.125 in / 2 pi)
};

inline constexpr double spin_decay_reference_speed = 44.704;  // m/s (100 mph)

double drag_coefficient(const Aerodynamics& aero, double perpendicular_spin);  // rad/s
double lift_coefficient(const Aerodynamics& aero, double spin_factor);         // S = R omega / v

}  // namespace sweetspot
