// What a flight refuses before any work: the launch and the options (the air: air.cpp).
#include <cmath>
#include <numbers>

#include "sweetspot/flight/flight.hpp"

namespace sweetspot {

std::optional<InputProblem> launch_problem(const Launch& launch) {
  // Past these the flight is no ball's: it did not land within max_time, and the run failed after
  // its work instead of refusing before it.
  constexpr double max_speed = 1000, max_spin = 1e5 * 2 * std::numbers::pi / 60;  // m/s; 1e5 rpm in rad/s
  if (!(launch.speed >= 0 && launch.speed <= max_speed))
    return InputProblem{"speed", launch.speed, "a speed from 0 to 1000 m/s"};
  if (!(launch.angle >= -90 && launch.angle <= 90))
    return InputProblem{"angle", launch.angle, "an angle from -90 to 90 deg above the horizontal"};
  // Past a turn either way a direction says nothing more (1e300 deg is no direction a sine can read).
  if (!(std::abs(launch.direction) <= 360))
    return InputProblem{"direction", launch.direction, "an angle from -360 to 360 deg"};
  if (!(std::abs(launch.backspin) <= max_spin))
    return InputProblem{"backspin", launch.backspin, "a spin from -1e5 to 1e5 rpm (-10472 to 10472 rad/s)"};
  if (!(std::abs(launch.sidespin) <= max_spin))
    return InputProblem{"sidespin", launch.sidespin, "a spin from -1e5 to 1e5 rpm (-10472 to 10472 rad/s)"};
  if (!(launch.height >= 0 && launch.height <= 1000))
    return InputProblem{"height", launch.height, "a launch height from 0 to 1000 m"};
  return std::nullopt;
}

std::optional<InputProblem> flight_options_problem(const FlightOptions& o) {
  const auto positive = [](double x) { return x > 0 && std::isfinite(x); };
  if (!positive(o.ball.mass)) return InputProblem{"ball_mass", o.ball.mass, "a finite mass > 0"};
  if (!positive(o.ball.radius)) return InputProblem{"ball_radius", o.ball.radius, "a finite radius > 0"};
  if (!positive(o.gravity)) return InputProblem{"gravity", o.gravity, "a finite acceleration > 0"};
  if (!positive(o.tolerance)) return InputProblem{"tolerance", o.tolerance, "a finite tolerance > 0"};
  if (!positive(o.max_time)) return InputProblem{"max_time", o.max_time, "a finite time > 0"};
  if (!(o.sample_interval == 0 || (o.sample_interval >= 1e-3 && std::isfinite(o.sample_interval))))
    return InputProblem{"sample_interval", o.sample_interval, "0 (no samples) or a finite time >= 0.001 s"};
  const Aerodynamics& a = o.aerodynamics;
  for (const auto& [key, value] : {std::pair{"cd0", a.cd0}, std::pair{"cd_spin", a.cd_spin},
                                   std::pair{"cl0", a.cl0}, std::pair{"cl1", a.cl1}, std::pair{"cl2", a.cl2}})
    if (!std::isfinite(value)) return InputProblem{key, value, "a finite coefficient"};
  if (!(a.cl0 > 0) || !(a.cl1 >= 0)) return InputProblem{"cl0", a.cl0, "cl0 > 0 and cl1 >= 0 (a finite C_L)"};
  // Shorter, the spin's decay is too stiff for the integrator (1e-9 s never landed); the spin is
  // then gone within the first centimetres anyway.
  if (!(a.spin_decay_time >= 0.01))
    return InputProblem{"spin_decay_time", a.spin_decay_time, "a time >= 0.01 s"};
  return std::nullopt;
}

}  // namespace sweetspot
