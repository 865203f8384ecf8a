#include "sweetspot/study/study_point.hpp"

#include <stdexcept>

#include "sweetspot/impact/toy_model.hpp"
#include "sweetspot/impact/wall.hpp"

namespace sweetspot {

ImpactResult simulate_point(const GridPoint& point, const ModalBasis* basis) {
  switch (point.kind) {
    case StudyKind::wall:
      return hit_wall(point.scene.ball, point.scene.ball_speed, point.scene.integrator,
                      point.scene.histories ? &point.scene.history : nullptr);
    case StudyKind::toy:
      return toy_model(point.omega_tau);
    case StudyKind::impact:
      break;
  }
  if (!basis) throw std::invalid_argument("simulate_point: an impact point needs its bat's modal basis");
  return simulate_impact(*basis, point.scene);
}

}  // namespace sweetspot
