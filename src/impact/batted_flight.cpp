#include "sweetspot/impact/batted_flight.hpp"

#include <numbers>

namespace sweetspot {

Launch flight_launch(const BallLaunch& ball) {
  constexpr double rad_per_s_per_rpm = 2 * std::numbers::pi / 60;
  Launch launch;
  launch.speed = ball.speed;
  launch.angle = ball.angle;
  launch.backspin = ball.backspin * rad_per_s_per_rpm;
  launch.sidespin = ball.sidespin * rad_per_s_per_rpm;
  return launch;
}

FlightResult batted_flight(const BallLaunch& ball, const Air& air) { return simulate_flight(flight_launch(ball), air); }

}  // namespace sweetspot
