#pragma once
// The hollow-barrel tests' scene: a 40 m/s ball on a bat swung at 24 m/s (CM) and 51 rad/s, with
// sweetspot's default settings (exact stepping, auto modes), struck at z m from the knob.
#include "sweetspot/impact/scene.hpp"

inline sweetspot::ImpactScene barrel_scene(double z) {
  sweetspot::ImpactScene scene;
  scene.z = z;
  scene.ball_speed = 40;
  scene.swing.cm_speed = 24;
  scene.swing.omega = 51;
  return scene;
}
