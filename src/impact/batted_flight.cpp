#include "sweetspot/impact/batted_flight.hpp"

#include <cmath>
#include <numbers>

namespace sweetspot {

Launch flight_launch(const BallLaunch& ball) {
  constexpr double rad_per_s_per_rpm = 2 * std::numbers::pi / 60;
  Launch launch;
  launch.speed = ball.speed;
  launch.angle = ball.angle;
  launch.backspin = ball.backspin * rad_per_s_per_rpm;
  launch.sidespin = ball.sidespin * rad_per_s_per_rpm;
  // A ball the bat sends back past the vertical (a pop-up undercut far below its centre leaves at
  // up to 107 deg) is the same flight seen from behind: elevation 180 deg - angle, heading turned
  // half round, and both spins' signs with it, their axes being tied to the heading (flight.cpp's
  // initial_state gives the same velocity and spin vector).
  if (std::abs(launch.angle) > 90) {
    launch.angle = std::copysign(180.0, launch.angle) - launch.angle;
    launch.direction += 180;
    launch.backspin = -launch.backspin;
    launch.sidespin = -launch.sidespin;
  }
  return launch;
}

FlightResult batted_flight(const BallLaunch& ball, const Air& air) { return simulate_flight(flight_launch(ball), air); }

}  // namespace sweetspot
