// The ball on a rigid wall (N2000 Fig. 3) and the two-mass toy model (App. A).
#include <catch2/catch.hpp>

#include "sweetspot/toy_model.hpp"
#include "sweetspot/wall.hpp"

using namespace sweetspot;

TEST_CASE("On a rigid wall the ball rebounds with exactly e0", "[wall]") {
  for (double e0 : {0.3, 0.5, 0.66, 1.0})
    for (double speed : {1.0, 40.0, 67.0}) {
      Ball ball;
      ball.e0 = e0;
      INFO("e0 " << e0 << ", speed " << speed);
      CHECK(hit_wall(ball, speed, {}).restitution == Approx(e0).epsilon(1e-6));
    }
}

TEST_CASE("Collision times on a rigid wall follow N2000 Fig. 3", "[wall]") {
  // physics.md §3: 99 %-impulse times 2.2, 1.0, 0.7, 0.6 ms; contact 1.1 ms at 67 m/s.
  const double speeds[] = {1, 11, 45, 67};
  const double paper_ms[] = {2.2, 1.0, 0.7, 0.6};
  Ball ball;
  for (int i = 0; i < 4; ++i) {
    const WallResult r = hit_wall(ball, speeds[i], {});
    INFO(speeds[i] << " m/s: " << 1e3 * r.collision_time << " ms");
    CHECK(1e3 * r.collision_time == Approx(paper_ms[i]).epsilon(0.05));
  }
  CHECK(1e3 * hit_wall(ball, 67, {}).contact_time == Approx(1.1).epsilon(0.05));
}

TEST_CASE("Toy model reaches its rigid and loose limits and conserves energy", "[toy]") {
  const ToyResult stiff = toy_model(20), loose = toy_model(0.05);
  CHECK(stiff.exit_ratio == Approx(5.0 / 7).epsilon(0.01));
  CHECK(loose.exit_ratio == Approx(1.0 / 3).epsilon(0.01));
  for (double omega_tau : {0.05, 0.5, 2.0, 20.0}) {
    const ToyResult r = toy_model(omega_tau);
    INFO("omega tau " << omega_tau);
    CHECK(r.ball_energy + r.bat_cm_energy + r.vibration_energy == Approx(1).epsilon(1e-8));
  }
  // Between the limits Van Zandt's prescription misses (N2000 Fig. 18).
  const ToyResult middle = toy_model(2);
  CHECK(std::abs(middle.van_zandt_ratio - middle.exit_ratio) > 0.05);
}
