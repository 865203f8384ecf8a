#pragma once
// The bat-test rig (physics.md §7, README "Certification"): the bat at rest, held on a pivot 6 in
// from the knob and free to rotate about it, a ball fired at it. A scene like any other (the
// pivoted scene with omega = 0); what it measures are the rig's measures (rig_measures.hpp).
#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/rig_measures.hpp"
#include "sweetspot/impact/scene.hpp"

namespace sweetspot {

// The rig's pivot, 6 in from the knob: the point of the swing weight (ASTM F2398) and of the
// NCAA's BESR and BBCOR tests.
inline constexpr double rig_pivot = swing_weight_pivot;  // m

// What the rig is set to: the ball and its speed, where the bat is held, and how the collision
// is computed (the library's defaults: exact stepping, modes = auto).
struct RigSettings {
  Ball ball;
  double ball_speed = 0;  // m/s toward the bat
  double pivot = rig_pivot;
  int vibrational_modes = auto_modes;
  CollisionOptions integrator;
  double accuracy = 0;  // a stated total accuracy: its modes' and step's shares (ImpactScene::accuracy)
};

// The MOI about point z of the bat as the model discretises it: the inertia its rigid modes
// carry, I_cm + M (z - z_cm)^2 of the slices. With it, BBCOR = e_A (1 + r) + r holds to round-off.
double model_moi_about(const ModalBasis& basis, double z);

// The rig striking the bat at z: a pivoted scene at rest.
ImpactScene rig_scene(const RigSettings& rig, double z);

// The rig's hit at z, whole. Throws InputError for a bad scene (validate()), and
// std::runtime_error naming z and the status when the collision does not end ok.
ImpactResult rig_impact(const ModalBasis& basis, const RigSettings& rig, double z);
// Its measures alone.
inline RigMeasures rig_hit(const ModalBasis& basis, const RigSettings& rig, double z) {
  return rig_impact(basis, rig, z).rig;
}

}  // namespace sweetspot
