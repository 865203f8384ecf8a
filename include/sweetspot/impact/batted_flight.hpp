#pragma once
// The batted ball's flight from an impact's launch (flight.hpp): the exit velocity in the plane of
// the swing, toward centre field, from the trajectory calculator's 3 ft above the plate, with the
// impact's spins. What a study's `distance` and an optimisation's `peak_distance` fly.
#include "sweetspot/flight/flight.hpp"
#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

// The flight's launch of an impact's ball (spins from rpm to rad/s).
Launch flight_launch(const BallLaunch& ball);

// The ball's flight from that launch in `air`.
FlightResult batted_flight(const BallLaunch& ball, const Air& air);

}  // namespace sweetspot
