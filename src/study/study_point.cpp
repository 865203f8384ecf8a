#include "sweetspot/study/study_point.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sweetspot/impact/batted_flight.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/standards.hpp"
#include "sweetspot/impact/toy_model.hpp"
#include "sweetspot/impact/wall.hpp"

namespace sweetspot {

namespace {

// The point's bat certified: its result the rig's measures at their maximum over the barrel (at
// z), `certified` whether every rule of the standard holds.
ImpactResult certification_point(const GridPoint& point) {
  CertifyOptions options;
  if (point.rig_ball) options.ball = point.scene.ball;
  if (!std::isnan(point.rig_e0)) options.e0 = point.rig_e0;
  if (!std::isnan(point.rig_ball_speed)) options.ball_speed = point.rig_ball_speed;
  options.slices = point.slices;
  options.vibrational_modes = point.scene.vibrational_modes;
  options.theory = point.theory;
  if (point.scene.accuracy > 0) options.accuracy = point.scene.accuracy;
  const Certification c = certify(*point.design_spec, standards()[point.standard], options);
  ImpactResult r;
  r.z = c.z_max;
  r.rig = c.at_max;
  r.hoop_frequency = c.hoop_frequency;
  r.barrel_compression = c.barrel_compression;
  r.certified = c.pass ? 1 : 0;
  r.slices_used = c.slices_used;
  r.slicing_error = c.slicing_error, r.modes_error = c.modes_error, r.step_error = c.step_error;
  r.total_error = c.total_error;
  if (!c.accurate) r.status = CollisionStatus::inaccurate, r.message = "accuracy not met: " + c.unmet;
  if (!std::isfinite(c.measure)) r.status = CollisionStatus::non_finite, r.message = "the rig's measure is not finite";
  return r;
}

// The batted ball's flight from the impact's launch, in `air` (the study's keys: checked). A
// ball driven into the ground at once has no flight: distance 0.
void add_flight(const Air& air, ImpactResult& r) {
  const FlightResult f = batted_flight(r.launch, air);
  r.distance = f.distance, r.apex = f.apex, r.hang_time = f.hang_time, r.landing_angle = f.landing_angle;
}

}  // namespace

void flag_untrusted_modes_error(const ImpactScene& scene, ImpactResult& r) {
  if (r.status != CollisionStatus::ok || scene.vibrational_modes != auto_modes) return;
  const double tolerance = auto_mode_tolerance(scene);
  if (!(r.modes_error > untrusted_modes_error * tolerance) && !std::isnan(r.modes_error)) return;
  r.status = CollisionStatus::failed;
  std::ostringstream why;
  why << "modes = auto estimates a relative vf error of " << r.modes_error << " for the dropped modes, over "
      << untrusted_modes_error << " times "
      << (scene.accuracy > 0 ? "the accuracy's share for them, " : "mode_tolerance = ") << tolerance
      << ": the modal model does not hold for this bat";
  r.message = why.str();
}

ImpactResult simulate_point(const GridPoint& point, const ModalBasis* basis) {
  switch (point.kind) {
    case StudyKind::wall:
      return hit_wall(point.scene.ball, point.scene.ball_speed, point.scene.integrator,
                      point.scene.histories ? &point.scene.history : nullptr);
    case StudyKind::toy:
      return toy_model(point.omega_tau);
    case StudyKind::certification:
      return certification_point(point);
    case StudyKind::impact:
      break;
  }
  if (!basis) throw std::invalid_argument("simulate_point: an impact point needs its bat's modal basis");
  ImpactResult r = simulate_impact(*basis, point.scene);
  flag_untrusted_modes_error(point.scene, r);
  if (point.flight && r.status == CollisionStatus::ok) add_flight(point.air, r);
  return r;
}

}  // namespace sweetspot
