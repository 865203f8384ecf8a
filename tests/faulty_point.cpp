// Test-only: the program with a simulate_point that throws at chosen points, linked into the
// sweetspot_faulty test binary in place of src/study_point.cpp (never into the program). After
// the bounds that keep every valid input inside the physics, no real input reaches a throw in
// a point, yet a worker must survive one: ball_speed = 13 m/s throws std::runtime_error,
// 17 m/s throws an int (not a std::exception). Any other point is computed as the program does.
#include <stdexcept>

#include "sweetspot/study/study_point.hpp"
#include "sweetspot/impact/toy_model.hpp"
#include "sweetspot/impact/wall.hpp"

namespace sweetspot {

ImpactResult simulate_point(const GridPoint& point, const ModalBasis* basis) {
  if (point.scene.ball_speed == 13) throw std::runtime_error("test fault at ball_speed = 13");
  if (point.scene.ball_speed == 17) throw 17;
  switch (point.kind) {
    case StudyKind::wall: return hit_wall(point.scene.ball, point.scene.ball_speed, point.scene.integrator);
    case StudyKind::toy: return toy_model(point.omega_tau);
    case StudyKind::impact: break;
  }
  return simulate_impact(*basis, point.scene);
}

}  // namespace sweetspot
