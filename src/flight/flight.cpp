#include "sweetspot/flight/flight.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "flight/flight_equations.hpp"

namespace sweetspot {

namespace {

using detail::FlightState;
using detail::Vector3;
namespace odeint = boost::numeric::odeint;

double radians(double degrees) { return degrees * std::numbers::pi / 180; }
double degrees(double radians) { return radians * 180 / std::numbers::pi; }

// The launch as a state, and the spin's axis (unit, or zero without spin). Backspin is about the
// horizontal axis perpendicular to the velocity (lifting: w x v up), sidespin about the axis
// perpendicular to the velocity in its vertical plane, as in the trajectory calculator.
FlightState initial_state(const Launch& l, Vector3& axis) {
  const double th = radians(l.angle), ph = radians(l.direction);
  const Vector3 v{std::cos(th) * std::sin(ph), std::cos(th) * std::cos(ph), std::sin(th)};
  const Vector3 w{l.backspin * std::cos(ph) - l.sidespin * std::sin(th) * std::sin(ph),
                  -l.backspin * std::sin(ph) - l.sidespin * std::sin(th) * std::cos(ph),
                  l.sidespin * std::cos(th)};
  const double spin = detail::norm(w);
  axis = spin > 0 ? Vector3{w[0] / spin, w[1] / spin, w[2] / spin} : Vector3{0, 0, 0};
  return {0, 0, l.height, l.speed * v[0], l.speed * v[1], l.speed * v[2], spin};
}

// The time in [t0, t1] where component `i` of the dense output crosses zero (it changes sign
// there), to the last bits by TOMS 748.
template <class Stepper>
double crossing(const Stepper& stepper, int i, double t0, double t1, double f0, double f1) {
  FlightState s{};
  const auto f = [&](double t) {
    stepper.calc_state(t, s);
    return s[i];
  };
  if (f1 == 0) return t1;
  boost::uintmax_t iterations = 200;
  const auto [a, b] =
      boost::math::tools::toms748_solve(f, t0, t1, f0, f1, boost::math::tools::eps_tolerance<double>(), iterations);
  return 0.5 * (a + b);
}

void record(FlightResult& r, double t, const FlightState& s) {
  r.samples.push_back({t, s[0], s[1], s[2], s[3], s[4], s[5]});
}

void land(FlightResult& r, double t, const FlightState& s) {
  r.hang_time = t;
  r.landing_x = s[0];
  r.landing_y = s[1];
  r.distance = std::hypot(s[0], s[1]);
  r.bearing = r.distance > 0 ? degrees(std::atan2(s[0], s[1])) : 0;
  const double horizontal = std::hypot(s[3], s[4]);
  r.landing_angle = degrees(std::atan2(-s[5], horizontal));
  r.landing_speed = std::sqrt(horizontal * horizontal + s[5] * s[5]);
  r.landing_spin = s[6];
}

}  // namespace

FlightResult simulate_flight(const Launch& launch, const Air& air, const FlightOptions& options) {
  if (const auto problem = launch_problem(launch)) refuse(*problem, "");
  check_air(air);
  if (const auto problem = flight_options_problem(options)) refuse(*problem, "");

  FlightResult r;
  r.air_density = air_density(air);
  Vector3 axis;
  FlightState state = initial_state(launch, axis);
  const double to = radians(air.wind_direction);
  const Vector3 wind{air.wind_speed * std::sin(to), air.wind_speed * std::cos(to), 0};
  const detail::FlightEquations equations(axis, wind, r.air_density, options);

  r.apex = launch.height;
  const bool sampling = options.sample_interval > 0;
  if (sampling) record(r, 0, state);
  if (launch.height == 0 && !(state[5] > 0)) {
    // On the ground and not rising: it lands at once, unless launched level with a lift above
    // its weight (heavy backspin), which takes it up.
    FlightState rate{};
    equations(state, rate, 0.0);
    if (!(state[5] == 0 && rate[5] > 0)) {
      land(r, 0, state);
      return r;
    }
  }
  auto stepper =
      odeint::make_dense_output(options.tolerance, options.tolerance, odeint::runge_kutta_dopri5<FlightState>());
  // A first step of a thousandth of the time a vacuum flight would rise: the controller adapts it.
  stepper.initialize(state, 0.0, std::max(1e-3 * launch.speed / options.gravity, 1e-4));
  int next_sample = 1;
  while (true) {
    const auto [t0, t1] = stepper.do_step(equations);
    const FlightState& before = stepper.previous_state();
    const FlightState& after = stepper.current_state();
    if (before[5] > 0 && after[5] <= 0) {  // v_z passes zero: a top (the highest is the apex)
      const double t = crossing(stepper, 5, t0, t1, before[5], after[5]);
      FlightState top{};
      stepper.calc_state(t, top);
      if (top[2] > r.apex) r.apex = top[2], r.apex_time = t;
    }
    const bool landed = before[2] > 0 && after[2] <= 0;
    const double end = landed ? crossing(stepper, 2, t0, t1, before[2], after[2]) : t1;
    for (; sampling && next_sample * options.sample_interval < end; ++next_sample) {
      FlightState s{};
      stepper.calc_state(next_sample * options.sample_interval, s);
      record(r, next_sample * options.sample_interval, s);
    }
    if (landed) {
      FlightState s{};
      stepper.calc_state(end, s);
      s[2] = 0;  // on the ground by definition; the root leaves it within an ulp of the scale
      land(r, end, s);
      if (sampling) record(r, end, s);
      return r;
    }
    if (t1 > options.max_time)
      throw std::runtime_error("flight: the ball has not landed after " + std::to_string(options.max_time) + " s");
  }
}

}  // namespace sweetspot
