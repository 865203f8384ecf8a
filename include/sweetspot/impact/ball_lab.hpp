#pragma once
// The standard ball tests, run on the model (`sweetspot ball`, README "Balls"): the COR on a
// rigid flat wall against speed (ASTM F1887's test at any speed), and the COR and dynamic
// stiffness on a rigid cylinder (ASTM F2845's kind of test), each a collision integrated as any
// other, so that a lab can check that the model's ball is the ball it measured.
#include <vector>

#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"

namespace sweetspot {

struct BallLabTest {
  double speed = 0;              // m/s
  double cor = 0;                // rebound over inbound speed
  double peak_force = 0;         // N
  double dynamic_stiffness = 0;  // (F / v)^2 / m, N/m
  double contact_time = 0;       // s
};

// The ball fired at `speed` at a rigid surface: flat (section_radius 0) or a cylinder of that
// radius, which the ball meets as on a barrel (Ball::on_section).
BallLabTest ball_lab_test(const Ball& ball, double speed, double section_radius, const CollisionOptions& options = {});

}  // namespace sweetspot
