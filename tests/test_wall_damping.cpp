// The barrel wall's damping (README "Hollow barrels", barrel_wall.hpp): a loss factor eta makes
// the wall mode a viscously damped oscillator, zeta = eta / 2. Checked against a closed-form
// linear reference (a linear lossless ball on a damped wall over an immovable bat is a linear
// two-degree-of-freedom system, solved here by its eigen-decomposition), by every integrator;
// the dissipated energy against that reference's energy loss; the energy balance with damping;
// zero damping is the undamped path bit for bit; more damping dissipates more.
#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "barrel_scene.hpp"
#include "program.hpp"
#include "temp_dir.hpp"
#include "sweetspot/bat/bat_design_text.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/impact/bat_test_rig.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;

namespace {

// A linear ball (a = 1) with e0 = 1 is lossless: both branches are k1 u.
Ball lossless_linear_ball() {
  Ball ball;
  ball.a = 1;
  ball.k1 = 2e6;  // N/m
  ball.e0 = 1;
  return ball;
}

// The wall alone over an immovable bat: one damped mode of mass m_w at f Hz.
ModalContact damped_wall(double m_wall, double f, double zeta) {
  ModalContact wall;
  wall.omega = Eigen::VectorXd::Constant(1, 2 * std::numbers::pi * f);
  wall.psi = Eigen::VectorXd::Constant(1, 1 / std::sqrt(m_wall));
  wall.velocity0 = Eigen::VectorXd::Zero(1);
  wall.damping_ratio = Eigen::VectorXd::Constant(1, zeta);
  return wall;
}

// The closed-form collision of the linear ball with the damped wall: z = (s, s', x, x') with the
// wall's displacement x = psi a obeys z' = A z while x > s; the exit state is z at the first
// root of x - s after touch. Returns the ball's exit speed and what the damping took (the
// initial energy less the ball's and the wall's at separation: nothing else loses energy).
struct LinearReference {
  double exit_speed, dissipated;
};

LinearReference linear_reference(const Ball& ball, double m_wall, double omega, double zeta, double speed) {
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  const double k = ball.k1;
  a(0, 1) = 1;
  a(1, 0) = -k / ball.mass, a(1, 2) = k / ball.mass;
  a(2, 3) = 1;
  a(3, 0) = k / m_wall, a(3, 2) = -omega * omega - k / m_wall, a(3, 3) = -2 * zeta * omega;
  const Eigen::EigenSolver<Eigen::Matrix4d> eigen(a);
  const Eigen::Matrix4cd v = eigen.eigenvectors();
  const Eigen::Vector4cd lambda = eigen.eigenvalues();
  const Eigen::Vector4cd c = v.inverse() * Eigen::Vector4cd(0, -speed, 0, 0);
  const auto state = [&](double t) {
    return Eigen::Vector4d((v * (lambda.array() * t).exp().matrix().cwiseProduct(c)).real());
  };
  const auto compression = [&](double t) {
    const Eigen::Vector4d z = state(t);
    return z(2) - z(0);
  };
  double lo = 1e-9, hi = lo;  // scan for the sign change, then bisect
  while (compression(hi) > 0) lo = hi, hi += 1e-6;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) (compression((lo + hi) / 2) > 0 ? lo : hi) = (lo + hi) / 2;
  const Eigen::Vector4d z = state(hi);
  const double wall = 0.5 * m_wall * (z(3) * z(3) + omega * omega * z(2) * z(2));
  return {z(1), 0.5 * ball.mass * (speed * speed - z(1) * z(1)) - wall};
}

// Fine enough for 1e-8: exact stepping converges at second order here, where the linear ball's
// force leaves at a finite slope (k1 u'), with or without damping (1e-5 of 40 m/s at 1 us).
CollisionOptions options_for(Method method) {
  CollisionOptions options;
  options.method = method;
  options.dt = method == Method::exact ? 1e-8 : method == Method::rk4 ? 1e-6 : 1e-7;
  options.tolerance = 1e-12;
  return options;
}

// The alloy bat with its wall's loss factor eta and its beam undamped: the wall's damping alone.
BatDesign alloy_with_loss(double eta) {
  BatSource source;
  BatDesign design = load_bat_design(source_path("studies/bats/alloy_bbcor.toml"), source);
  set_design_parameter(design, "wall_loss_factor", eta);
  set_design_parameter(design, "loss_factor", 0);
  return design;
}

}  // namespace

TEST_CASE("A linear ball on a damped wall: every integrator gives the closed form's exit speed and loss",
          "[barrel][damping]") {
  const Ball ball = lossless_linear_ball();
  const double m_wall = 0.15, f = 1500, speed = 40;
  for (const double zeta : {0.0, 0.005, 0.05}) {
    const LinearReference reference = linear_reference(ball, m_wall, 2 * std::numbers::pi * f, zeta, speed);
    REQUIRE(reference.dissipated > -1e-9);
    for (const Method method : {Method::rk4, Method::exact, Method::dopri}) {
      INFO("zeta " << zeta << ", " << to_string(method));
      const Collision c = collide(damped_wall(m_wall, f, zeta), ball, speed, options_for(method));
      REQUIRE(c.status == CollisionStatus::ok);
      CHECK(c.dissipated == Approx(0).margin(1e-12));  // the lossless ball: only the wall loses
      CHECK(c.ball_velocity == Approx(reference.exit_speed).epsilon(1e-8));
      CHECK(c.damping_dissipated == Approx(reference.dissipated).epsilon(1e-6).margin(1e-12 * speed * speed));
    }
  }
}

TEST_CASE("A damped wall catches the ball again: the free flight's decay is counted, the balance closes",
          "[barrel][damping]") {
  // A slow, light wall (20 g, 100 Hz, zeta = 0.05) still moving outward meets the ball a second
  // time; between the contacts it decays in closed form, and what it loses there is added.
  const Ball ball;
  const double speed = 40, initial = 0.5 * ball.mass * speed * speed;
  const ModalContact wall = damped_wall(0.02, 100, 0.05);
  for (const Method method : {Method::rk4, Method::exact, Method::dopri}) {
    INFO(to_string(method));
    CollisionOptions options = options_for(method);
    options.dt = method == Method::dopri ? 1e-7 : 1e-6;
    options.tolerance = 1e-11;
    const Collision c = collide(wall, ball, speed, options);
    REQUIRE(c.status == CollisionStatus::ok);
    CHECK(c.contacts == 2);
    const double final = 0.5 * ball.mass * c.ball_velocity * c.ball_velocity + c.mode_energy(wall, 0);
    CHECK(final + c.dissipated + c.damping_dissipated == Approx(initial).epsilon(1e-8));
  }
}

TEST_CASE("Zero damping is the undamped path bit for bit, and vanishing damping tends to it", "[barrel][damping]") {
  const Ball ball;  // N2000's nonlinear, lossy ball
  for (const Method method : {Method::rk4, Method::exact, Method::dopri}) {
    INFO(to_string(method));
    CollisionOptions options;
    options.method = method;
    options.dt = default_step(method);
    ModalContact undamped = damped_wall(0.15, 1500, 0);
    undamped.damping_ratio.resize(0);
    const Collision a = collide(undamped, ball, 40, options);
    const Collision b = collide(damped_wall(0.15, 1500, 0), ball, 40, options);  // zeros spelt out
    CHECK(a.ball_velocity == b.ball_velocity);
    CHECK(a.a_dot(0) == b.a_dot(0));
    CHECK(b.damping_dissipated == 0);
    // The damped closed forms (exact stepping, free flight) at zeta = 1e-12 against the undamped;
    // Dormand-Prince, whose error norm now counts the dissipated energy too, steps differently
    // and agrees within its tolerance.
    const Collision c = collide(damped_wall(0.15, 1500, 1e-12), ball, 40, options);
    CHECK(c.ball_velocity == Approx(a.ball_velocity).epsilon(method == Method::dopri ? 1e-8 : 1e-11));
    CHECK(c.damping_dissipated == Approx(0).margin(1e-9));
  }
}

TEST_CASE("Exact stepping over steps of omega h > 4 (the damped closed form by recursion) matches dopri",
          "[barrel][damping]") {
  // A stiff wall (100 kHz) at 10 us steps: omega h = 1.6, 3.1 and 6.3 over the quarter, half and
  // whole steps, both branches of the damped monomial responses. N2000's ball, its smooth pulse.
  const Ball ball;
  for (const double zeta : {0.01, 0.2}) {
    INFO("zeta " << zeta);
    const ModalContact wall = damped_wall(0.05, 1e5, zeta);
    CollisionOptions exact;
    const Collision a = collide(wall, ball, 40, exact);
    const Collision b = collide(wall, ball, 40, options_for(Method::dopri));
    REQUIRE(a.status == CollisionStatus::ok);
    REQUIRE(b.status == CollisionStatus::ok);
    CHECK(a.ball_velocity == Approx(b.ball_velocity).epsilon(3e-7));  // undamped, the same step errs 1.8e-7
    CHECK(a.damping_dissipated == Approx(b.damping_dissipated).epsilon(1e-5));
    // And the same steps at vanishing damping against the undamped recursion.
    ModalContact undamped = wall;
    undamped.damping_ratio.resize(0);
    const Collision c = collide(damped_wall(0.05, 1e5, 1e-12), ball, 40, exact);
    CHECK(c.ball_velocity == Approx(collide(undamped, ball, 40, exact).ball_velocity).epsilon(1e-11));
  }
}

TEST_CASE("The energy balance closes with a damped wall, free and pivoted", "[barrel][damping]") {
  for (const double eta : {1e-4, 1e-2}) {
    const ModalBasis alloy = compute_modes(build_bat(alloy_with_loss(eta)), BeamTheory::timoshenko);
    for (const double z : {0.62, 0.7, 0.78}) {
      for (const bool pivoted : {false, true}) {
        INFO("eta " << eta << ", z " << z << (pivoted ? ", pivoted" : ", free"));
        const ImpactScene scene = pivoted ? rig_scene(RigSettings{Ball{}, 60, rig_pivot, auto_modes, {}}, z)
                                          : barrel_scene(z);
        const ImpactResult r = simulate_impact(alloy, scene);
        REQUIRE(r.status == CollisionStatus::ok);
        CHECK(r.energy.damped > 0);
        CHECK(std::abs(r.energy.residual) <= 1e-6 * r.energy.initial);
      }
    }
  }
}

TEST_CASE("rk4, exact and dopri agree on a damped wall's exit speed and loss", "[barrel][damping]") {
  const ModalBasis alloy = compute_modes(build_bat(alloy_with_loss(1e-2)), BeamTheory::timoshenko);
  ImpactScene scene = barrel_scene(0.68);
  scene.step_accuracy = 1e-7;
  ImpactResult r[3];
  int i = 0;
  for (const Method method : {Method::rk4, Method::exact, Method::dopri}) {
    scene.integrator.method = method;
    r[i] = simulate_impact(alloy, scene);
    REQUIRE(r[i].status == CollisionStatus::ok);
    ++i;
  }
  CHECK(r[0].vf == Approx(r[1].vf).epsilon(1e-6));
  CHECK(r[2].vf == Approx(r[1].vf).epsilon(1e-6));
  CHECK(r[0].energy.damped == Approx(r[1].energy.damped).epsilon(1e-5));
  CHECK(r[2].energy.damped == Approx(r[1].energy.damped).epsilon(1e-5));
}

TEST_CASE("More wall damping dissipates more and lowers the rig's BBCOR, slightly", "[barrel][damping]") {
  double previous_bbcor = 0, previous_loss = -1;
  for (const double eta : {0.0, 1e-4, 1e-3, 1e-2}) {
    INFO("eta " << eta);
    const ModalBasis alloy = compute_modes(build_bat(alloy_with_loss(eta)), BeamTheory::timoshenko);
    // At the rig's peak (z_max 0.64 m): off it, at 0.7 m, the patch-loaded wall's trampoline no
    // longer outweighs the beam's vibration at eta = 0.01 (BBCOR 0.499), as the point load's did.
    const ImpactResult r = simulate_impact(alloy, rig_scene(RigSettings{Ball{}, 60, rig_pivot, auto_modes, {}}, 0.64));
    REQUIRE(r.status == CollisionStatus::ok);
    if (eta == 0) CHECK(r.energy.damped == 0);
    if (eta > 0) {
      CHECK(r.energy.damped > previous_loss);
      CHECK(r.rig.bbcor < previous_bbcor);
      // Bounded: the wall never holds more than the initial energy, so a'^2 <= 2 E_initial and
      // int 2 zeta w a'^2 dt <= 2 eta w T E_initial over the contact time T. And the trampoline stays.
      const double omega = 2 * std::numbers::pi * r.hoop_frequency;
      CHECK(r.energy.damped <= 2 * eta * omega * r.contact_time * r.energy.initial);
      CHECK(r.rig.bbcor > Ball{}.e0);
    }
    previous_bbcor = r.rig.bbcor, previous_loss = r.energy.damped;
  }
}

TEST_CASE("A hollow design written back as a bat file keeps its wall's hoop modulus and loss factor",
          "[barrel][damping]") {
  BatSource source;
  const BatDesign composite = load_bat_design(source_path("studies/bats/composite_bbcor.toml"), source);
  REQUIRE(composite.material.wall_loss_factor != default_wall_loss_factor);
  const TempDir dir;
  const auto file = dir.write("best.toml", bat_design_text(composite, "written back"));
  BatSource again;
  const BatDesign read = load_bat_design(file, again);
  CHECK(read.material.hoop_modulus == composite.material.hoop_modulus);
  CHECK(read.material.wall_loss_factor == composite.material.wall_loss_factor);
}
