#include "sweetspot/impact/ball_lab.hpp"

#include <stdexcept>

#include "sweetspot/impact/wall.hpp"

namespace sweetspot {

BallLabTest ball_lab_test(const Ball& ball, double speed, double section_radius, const CollisionOptions& options) {
  const ImpactResult r = hit_wall(ball.on_section(section_radius), speed, options);
  if (r.status != CollisionStatus::ok)
    throw std::runtime_error("the ball test at " + std::to_string(speed) + " m/s failed: " + r.message);
  const double f = r.peak_force / speed;
  return {speed, r.e_eff, r.peak_force, f * f / ball.mass, r.contact_time};
}

}  // namespace sweetspot
