// The three integrators of the contact phase: RK4 (N2000), exact modal stepping and adaptive
// Dormand-Prince. Orders, agreement with a reference, and the exact identities for each.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "n2000_scenes.hpp"
#include "program.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/formulas.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;

namespace {

const ModalBasis& r161() {
  static const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko);
  return basis;
}

ImpactScene high_impact(double z, int modes, Method method, double dt, double tolerance = 1e-9) {
  ImpactScene s = n2000_high_impact(z, modes);
  s.integrator.method = method;
  s.integrator.dt = dt;
  s.integrator.tolerance = tolerance;
  return s;
}

double vf(const ImpactScene& s) {
  const ImpactResult r = simulate_impact(r161(), s);
  REQUIRE(r.status == CollisionStatus::ok);
  return r.vf;
}

// The reference: the tightest adaptive run (the explicit method needs steps below 2.5 us for
// all 168 modes anyway).
double reference_vf(double z, int modes) { return vf(high_impact(z, modes, Method::dopri, 1e-7, 1e-13)); }

}  // namespace

// Relative vf errors of exact stepping at the given steps, all modes, against the reference.
std::vector<double> exact_errors(const Ball& ball, const std::vector<double>& steps, std::vector<double>& vfs) {
  ImpactScene reference = high_impact(0.605, all_modes, Method::dopri, 1e-7, 1e-13);
  reference.ball = ball;
  const double v_ref = vf(reference);
  std::vector<double> errors;
  for (double dt : steps) {
    ImpactScene s = high_impact(0.605, all_modes, Method::exact, dt);
    s.ball = ball;
    vfs.push_back(vf(s));
    errors.push_back(std::abs(vfs.back() / v_ref - 1));
  }
  return errors;
}

TEST_CASE("Exact modal stepping is of sixth order on a smooth force pulse", "[integrators]") {
  // With a = 2 the force k u^2 is smooth from first touch, and with e0 = 0.5 it leaves as u^11:
  // the quintic interpolant's order shows.
  Ball ball;
  ball.a = 2;
  std::vector<double> vfs;
  const std::vector<double> errors = exact_errors(ball, {20e-6, 10e-6}, vfs);
  const double order = std::log2(errors[0] / errors[1]);
  WARN("a = 2: relative vf errors " << errors[0] << ", " << errors[1] << " at 20, 10 us: order " << order);
  CHECK(order > 5);
  CHECK(order < 7.5);
}

TEST_CASE("Exact modal stepping on the N2000 ball: order a + 1 from the t^a onset, checked against Richardson",
          "[integrators]") {
  // The force grows as t^a from first touch (a = 1.84), which no polynomial follows: at fine
  // steps that error, of order a + 1, outlasts the quintic's.
  const Ball ball;
  std::vector<double> vfs;
  const std::vector<double> errors = exact_errors(ball, {10e-6, 5e-6}, vfs);
  const double order = std::log2(errors[0] / errors[1]);
  WARN("a = " << ball.a << ": relative vf errors " << errors[0] << ", " << errors[1] << " at 10, 5 us: order "
              << order);
  CHECK(order == Approx(ball.a + 1).margin(0.3));
  // Richardson extrapolation at that order agrees with the adaptive reference.
  const double richardson = vfs[1] + (vfs[1] - vfs[0]) / (std::pow(2.0, ball.a + 1) - 1);
  ImpactScene reference = high_impact(0.605, all_modes, Method::dopri, 1e-7, 1e-13);
  CHECK(std::abs(richardson / vf(reference) - 1) < 0.2 * errors[1]);
}

TEST_CASE("A linear ball (a = 1) keeps exact stepping's high order: its force rises at touch as k1 u",
          "[integrators]") {
  // F'(0) = k1, not 0: taken as 0, the first step's force was wrong in slope, the energy balance
  // converged at second order and erred by 4e-4 at 10 us.
  std::vector<double> residuals;
  for (double dt : {10e-6, 5e-6}) {
    ImpactScene s = high_impact(0.605, 18, Method::exact, dt);
    s.ball.a = 1;
    const ImpactResult r = simulate_impact(r161(), s);
    REQUIRE(r.status == CollisionStatus::ok);
    residuals.push_back(std::abs(r.energy.residual) / r.energy.initial);
  }
  INFO("|residual| / initial " << residuals[0] << " at 10 us, " << residuals[1] << " at 5 us");
  CHECK(residuals[0] < 1e-5);
  CHECK(std::log2(residuals[0] / residuals[1]) > 4);
}

TEST_CASE("Every integrator agrees with the reference to 1e-8 at tight settings", "[integrators]") {
  for (double z : {0.305, 0.605, 0.705, 0.805}) {
    const double reference = reference_vf(z, all_modes);
    INFO("z " << z);
    CHECK(vf(high_impact(z, all_modes, Method::rk4, 1e-6)) == Approx(reference).epsilon(1e-8));
    CHECK(vf(high_impact(z, all_modes, Method::exact, 2e-6)) == Approx(reference).epsilon(1e-8));
    CHECK(vf(high_impact(z, all_modes, Method::dopri, 1e-6, 1e-11)) == Approx(reference).epsilon(1e-8));
  }
}

TEST_CASE("Every integrator keeps the rigid-bat identity", "[integrators]") {
  // Exact stepping of a rigid bat is its closed form unless told to step (rigid_closed_form).
  for (auto [method, dt, closed_form] : {std::tuple{Method::exact, 4e-6, false}, {Method::exact, 4e-6, true},
                                         {Method::dopri, 5e-6, false}})
    for (bool pivoted : {false, true})
      for (double z : {0.305, 0.705, 0.805})
        for (double e0 : {0.5, 1.0}) {
          ImpactScene s = high_impact(z, 0, method, dt, 1e-10);
          s.integrator.rigid_closed_form = closed_form;
          s.pivoted = pivoted;
          s.ball.e0 = e0;
          const SceneGeometry g = scene_geometry(s, r161());
          INFO(to_string(method) << ", pivoted " << pivoted << ", z " << z << ", e0 " << e0);
          CHECK(vf(s) == Approx(rigid_exit_speed(e0, g.recoil, s.ball_speed, g.bat_speed)).epsilon(1e-7));
        }
}

TEST_CASE("A rigid bat's closed form and exact stepping at the default step differ by the step's error",
          "[integrators]") {
  // bench_points' unique points (50-80 cm, 30-50 m/s, N2000's swing) on the rigid bat: what the
  // closed form changes in a rigid impact's results against stepping it at 10 us.
  double worst_vf = 0, worst_time = 0;
  for (double z = 0.50; z <= 0.801; z += 0.05)
    for (double speed = 30; speed <= 50; speed += 5) {
      ImpactScene s = high_impact(z, 0, Method::exact, 1e-5);
      s.ball_speed = speed;
      const ImpactResult closed = simulate_impact(r161(), s);
      s.integrator.rigid_closed_form = false;
      const ImpactResult stepped = simulate_impact(r161(), s);
      REQUIRE(closed.status == CollisionStatus::ok);
      REQUIRE(stepped.status == CollisionStatus::ok);
      worst_vf = std::max(worst_vf, std::abs(stepped.vf / closed.vf - 1));
      worst_time = std::max({worst_time, std::abs(stepped.contact_time / closed.contact_time - 1),
                             std::abs(stepped.collision_time / closed.collision_time - 1)});
      CHECK(stepped.peak_force == Approx(closed.peak_force).epsilon(1e-6));
      CHECK(stepped.u_max == Approx(closed.u_max).epsilon(1e-6));
    }
  WARN("rigid bat, exact at 10 us against the closed form: vf " << worst_vf << ", times " << worst_time);
  CHECK(worst_vf <= 2e-8);  // 6.6e-9 measured
  CHECK(worst_time <= 1e-6);  // 2.6e-7
}

TEST_CASE("Every integrator keeps the lossless identity (e0 = 1)", "[integrators]") {
  for (auto [method, dt] : {std::pair{Method::exact, 2e-6}, {Method::dopri, 1e-6}}) {
    ImpactScene s = high_impact(0.605, 18, method, dt, 1e-11);
    s.ball.e0 = 1;
    s.integrator.record_force = true;
    const ImpactResult r = simulate_impact(r161(), s);
    REQUIRE(r.status == CollisionStatus::ok);
    const SceneGeometry g = scene_geometry(s, r161());
    const auto responses = mode_responses(g.contact, s.ball.mass, r.force);
    const double sum = std::accumulate(responses.begin(), responses.end(), 0.0);
    INFO(to_string(method));
    CHECK(r.vf == Approx(lossless_exit_speed(sum, s.ball_speed, g.bat_speed)).epsilon(1e-6));
  }
}

TEST_CASE("Exact stepping takes all modes at any step, RK4 is refused", "[integrators]") {
  const ImpactResult exact = simulate_impact(r161(), high_impact(0.705, all_modes, Method::exact, 40e-6));
  CHECK(exact.status == CollisionStatus::ok);
  CHECK(std::abs(exact.energy.residual) < 1e-3 * exact.energy.initial);
  CHECK(simulate_impact(r161(), high_impact(0.705, all_modes, Method::rk4, 5e-6)).status ==
        CollisionStatus::refused_step);
  const ProgramRun run = run_program("impact --bat " + source_path("studies/bats/r161.toml") +
                                     " --z 0.705 --ball-speed 40 --center 0.09 --omega 51 --modes all "
                                     "--integrator exact --dt 2e-5 --json");
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("\"status\": \"ok\""));
  CHECK(run_program("impact --bat " + source_path("studies/bats/r161.toml") +
                    " --z 0.7 --ball-speed 40 --center 0.09 --omega 51 --integrator leapfrog")
            .exit_code != 0);
}
