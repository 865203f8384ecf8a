#include "sweetspot/impact/wall.hpp"

#include "sweetspot/impact/histories.hpp"

namespace sweetspot {

ImpactResult hit_wall(const Ball& ball, double speed, const CollisionOptions& options, const HistoryRequest* history) {
  const SceneGeometry wall;  // no modes: the contact point never moves
  CollisionOptions recording = options;
  recording.record_force |= history != nullptr;
  const Collision c = collide(wall.contact, ball, speed, recording);
  ImpactResult r = collision_result(c);
  if (!options.record_force) r.force.clear();
  if (history && c.status == CollisionStatus::ok) {
    HistoryRequest ball_only = *history;
    ball_only.probes.clear();
    r.histories = impact_histories(ModalBasis{}, wall, ball, speed, c.force, ball_only);
  }
  r.e_eff = r.vf / speed;
  r.energy.initial = 0.5 * ball.mass * speed * speed;
  r.energy.ball = 0.5 * ball.mass * r.vf * r.vf;
  close_balance(r);
  require_finite(r, {options.find_collision_time});
  return r;
}

}  // namespace sweetspot
