#pragma once
// Time histories of one impact (physics.md §5, N2000 Figs. 2, 4, 9, 13-15): the motion of chosen
// points of the bat, the force, the ball and its compression, on a uniform time grid from first
// touch. The collision's own force profile drives the kept modes in closed form (the exact
// stepper's responses over each grid interval), so the histories are as accurate as the
// collision and cost O(modes) per sample.
#include <vector>

#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/scene.hpp"

namespace sweetspot {

// HistoryRequest (the probes and the time grid) is in scene.hpp, where a scene asks for histories.

// Per probe, per sample. "Total" motion is in the frame where the probe is initially at rest
// (its initial velocity taken out); "vibration" leaves out the rigid modes altogether.
struct ProbeHistory {
  std::vector<double> displacement, velocity, acceleration;
  std::vector<double> vibration_displacement, vibration_velocity, vibration_acceleration;
};

struct Histories {
  std::vector<double> time;          // s from first touch
  std::vector<ProbeHistory> probes;  // in the order asked
  std::vector<double> force;         // N on the ball
  std::vector<double> compression;   // m: the ball's compression u
  std::vector<double> ball_position; // m: the ball's displacement from first touch, +y away from the bat
};

// `force` is the collision's force profile (ImpactResult::force, CollisionOptions::record_force).
Histories impact_histories(const ModalBasis& basis, const SceneGeometry& geometry, const Ball& ball,
                           double ball_speed, const std::vector<ForceSample>& force, const HistoryRequest& request);

}  // namespace sweetspot
