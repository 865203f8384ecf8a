#pragma once
// The rules' linear estimate of the batted-ball speed (A. M. Nathan, Am. J. Phys. 71, 134 (2003);
// physics.md §7): BBS = e_A v_pitch + (1 + e_A) v_bat, with e_A the collision efficiency, the
// ball's rebound over its inbound speed with the bat at rest, measured at one speed as a lab does.
// The collision depends only on the ball's speed relative to the struck point (the bat's initial
// motion is rigid and the modes start at rest), so the rule is exact when e_A is taken at that
// relative speed; taken at a lab's speed it errs as far as e_A depends on speed.
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/scene.hpp"

namespace sweetspot {

// e_A at the scene's point and constraint (free, or held at its centre), the bat at rest and the
// ball at `speed`: a collision of its own. NaN when that collision does not end ok.
double collision_efficiency(const ModalBasis& basis, const ImpactScene& scene, double speed);

double linear_batted_ball_speed(double e_a, double pitch_speed, double bat_speed);

}  // namespace sweetspot
