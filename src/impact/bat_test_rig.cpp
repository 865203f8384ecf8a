#include "sweetspot/impact/bat_test_rig.hpp"

#include <stdexcept>
#include <string>

#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

double model_moi_about(const ModalBasis& basis, double z) {
  const double arm = z - basis.z_cm;
  return basis.moment_of_inertia_cm + basis.mass * arm * arm;
}

ImpactScene rig_scene(const RigSettings& rig, double z) {
  ImpactScene scene;
  scene.z = z;
  scene.ball = rig.ball;
  scene.ball_speed = rig.ball_speed;
  scene.swing.about_center = true;  // at rest: omega = 0 about the pivot
  scene.swing.center = rig.pivot;
  scene.swing.omega = 0;
  scene.pivoted = true;
  scene.vibrational_modes = rig.vibrational_modes;
  scene.accuracy = rig.accuracy;
  scene.error_estimates = rig.accuracy > 0;  // the modes' and step's, free at a stated accuracy
  scene.integrator = rig.integrator;
  return scene;
}

ImpactResult rig_impact(const ModalBasis& basis, const RigSettings& rig, double z) {
  ImpactResult r = simulate_impact(basis, rig_scene(rig, z));
  if (r.status != CollisionStatus::ok)
    throw std::runtime_error("the rig's hit at z = " + std::to_string(z) + " m ended " + to_string(r.status) +
                             (r.message.empty() ? "" : ": " + r.message));
  return r;
}

}  // namespace sweetspot
