#include "sweetspot/wall.hpp"

namespace sweetspot {

ImpactResult hit_wall(const Ball& ball, double speed, const CollisionOptions& options) {
  const ModalContact wall;  // no modes: the contact point never moves
  ImpactResult r = collision_result(collide(wall, ball, speed, options));
  r.e_eff = r.vf / speed;
  r.energy.initial = 0.5 * ball.mass * speed * speed;
  r.energy.ball = 0.5 * ball.mass * r.vf * r.vf;
  close_balance(r);
  require_finite(r, {options.find_collision_time});
  return r;
}

}  // namespace sweetspot
