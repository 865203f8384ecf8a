#pragma once
// The ball on a rigid, immovable wall (N2000 Fig. 3): the collision with no modes at all.
#include "sweetspot/ball.hpp"
#include "sweetspot/collision.hpp"

namespace sweetspot {

struct WallResult {
  CollisionStatus status = CollisionStatus::ok;
  double restitution = 0;     // rebound speed / incoming speed; exactly e0 for this force law
  double collision_time = 0;  // s, 99 % of the impulse
  double contact_time = 0;    // s, first touch to separation
  double u_max = 0;           // m
  double peak_force = 0;      // N
};

WallResult hit_wall(const Ball& ball, double speed, const CollisionOptions& options);

}  // namespace sweetspot
