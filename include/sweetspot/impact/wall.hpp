#pragma once
// The ball on a rigid, immovable wall (N2000 Fig. 3): the collision with no modes at all.
#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

// The ball at `speed` (m/s, > 0) toward the wall. vf is the rebound speed and e_eff the
// restitution vf / speed, exactly e0 for this force law (physics.md §3); the wall takes no
// energy, so initial = ball + ball_dissipated + residual. z and the bat's energies stay 0.
// With `history`, also the force, the compression and the ball's position on its time grid
// (N2000 Fig. 2: the loop F(u)); its probes are ignored, the wall does not move.
ImpactResult hit_wall(const Ball& ball, double speed, const CollisionOptions& options,
                      const HistoryRequest* history = nullptr);

}  // namespace sweetspot
