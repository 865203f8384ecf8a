// The ball on a rigid wall (N2000 Fig. 3) and the two-mass toy model (App. A).
#include <catch2/catch.hpp>
#include <cmath>

#include "sweetspot/impact/toy_model.hpp"
#include "sweetspot/impact/wall.hpp"

using namespace sweetspot;

TEST_CASE("On a rigid wall the ball rebounds with exactly e0", "[wall]") {
  for (double e0 : {0.3, 0.5, 0.66, 1.0})
    for (double speed : {1.0, 40.0, 67.0}) {
      Ball ball;
      ball.e0 = e0;
      INFO("e0 " << e0 << ", speed " << speed);
      const ImpactResult r = hit_wall(ball, speed, {});
      CHECK(r.status == CollisionStatus::ok);
      CHECK(r.e_eff == Approx(e0).epsilon(1e-6));
      CHECK(r.vf == Approx(e0 * speed).epsilon(1e-6));
    }
}

TEST_CASE("On a rigid wall the ball's energy is all there is", "[wall]") {
  // physics.md §3: the loop loses 1 - e0^2 of the energy; the wall takes nothing.
  Ball ball;
  const ImpactResult r = hit_wall(ball, 40, {});
  const ImpactEnergy& e = r.energy;
  CHECK(e.initial == Approx(0.5 * ball.mass * 40 * 40));
  CHECK(e.ball == Approx(ball.e0 * ball.e0 * e.initial).epsilon(1e-6));
  CHECK(e.ball_dissipated == Approx((1 - ball.e0 * ball.e0) * e.initial).epsilon(1e-6));
  CHECK(e.bat_translation == 0);
  CHECK(e.bat_rotation == 0);
  CHECK(e.vibration == 0);
  CHECK(std::abs(e.residual) < 1e-6 * e.initial);
  CHECK(e.residual == e.initial - (e.ball + e.ball_dissipated));
  CHECK(r.impulse == Approx(ball.mass * (1 + ball.e0) * 40).epsilon(1e-6));
  CHECK(r.contacts == 1);
  CHECK(std::isnan(r.vf_van_zandt));
}

TEST_CASE("Collision times on a rigid wall follow N2000 Fig. 3", "[wall]") {
  // physics.md §3: 99 %-impulse times 2.2, 1.0, 0.7, 0.6 ms; contact 1.1 ms at 67 m/s.
  const double speeds[] = {1, 11, 45, 67};
  const double paper_ms[] = {2.2, 1.0, 0.7, 0.6};
  Ball ball;
  for (int i = 0; i < 4; ++i) {
    const ImpactResult r = hit_wall(ball, speeds[i], {});
    INFO(speeds[i] << " m/s: " << 1e3 * r.collision_time << " ms");
    CHECK(1e3 * r.collision_time == Approx(paper_ms[i]).epsilon(0.05));
  }
  CHECK(1e3 * hit_wall(ball, 67, {}).contact_time == Approx(1.1).epsilon(0.05));
}

TEST_CASE("Toy model reaches its rigid and loose limits and conserves energy", "[toy]") {
  // v_i = 1 and m = 1: vf is v_f / v_i and the initial energy 1/2.
  const ImpactResult stiff = toy_model(20), loose = toy_model(0.05);
  CHECK(stiff.vf == Approx(5.0 / 7).epsilon(0.01));
  CHECK(loose.vf == Approx(1.0 / 3).epsilon(0.01));
  for (double omega_tau : {0.05, 0.5, 2.0, 20.0}) {
    const ImpactResult r = toy_model(omega_tau);
    const ImpactEnergy& e = r.energy;
    INFO("omega tau " << omega_tau);
    CHECK(r.status == CollisionStatus::ok);
    CHECK(e.initial == 0.5);
    CHECK(e.ball == 0.5 * r.vf * r.vf);
    CHECK((e.ball + e.bat_translation + e.vibration) / e.initial == Approx(1).epsilon(1e-8));
    CHECK(e.bat_rotation == 0);
    CHECK(std::abs(e.ball_dissipated) < 1e-12);  // e0 = 1: the ball's loop encloses no area
    CHECK(e.residual == e.initial - (e.ball + e.bat_translation + e.bat_rotation + e.vibration + e.ball_dissipated));
  }
  // Between the limits Van Zandt's prescription misses (N2000 Fig. 18).
  const ImpactResult middle = toy_model(2);
  CHECK(std::abs(middle.vf_van_zandt - middle.vf) > 0.05);
}
