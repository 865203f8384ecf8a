#include "sweetspot/wall.hpp"

namespace sweetspot {

WallResult hit_wall(const Ball& ball, double speed, const CollisionOptions& options) {
  const ModalContact wall;  // no modes: the contact point never moves
  const Collision c = collide(wall, ball, speed, options);
  WallResult r;
  r.status = c.status;
  r.restitution = c.ball_velocity / speed;
  r.collision_time = c.collision_time;
  r.contact_time = c.contact_time;
  r.u_max = c.u_max;
  r.peak_force = c.peak_force;
  return r;
}

}  // namespace sweetspot
