#pragma once
// N2000's numerical settings, one option away from sweetspot's defaults (exact modal stepping at
// 10 us with modes = auto, README "Numerics"): classical RK4 at 5 us with 18 vibrational modes,
// the choice RK4's stability forced on the paper. `impact --n2000` and `preset = "n2000"` in a
// study's [scene] take them; options given beside them still apply.
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/scene.hpp"

namespace sweetspot {

inline constexpr int n2000_modes = 18;
inline constexpr double n2000_step = 5e-6;  // s

// RK4 at N2000's step.
inline CollisionOptions with_n2000_settings(CollisionOptions options) {
  options.method = Method::rk4;
  options.dt = n2000_step;
  return options;
}

// The scene integrated as N2000 did: RK4 at 5 us, 18 vibrational modes.
inline ImpactScene with_n2000_settings(ImpactScene scene) {
  scene.integrator = with_n2000_settings(scene.integrator);
  scene.vibrational_modes = n2000_modes;
  return scene;
}

}  // namespace sweetspot
