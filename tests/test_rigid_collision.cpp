// The closed-form collision with a body that only moves rigidly (src/contact/rigid_collision.*):
// its Beta integrals against arcsine and a quadrature, its collision against Dormand-Prince at a
// tight tolerance over the same body, and the rigid bat's exact identities.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/rigid_collision.hpp"
#include "sweetspot/contact/collision.hpp"

using namespace sweetspot;
using detail::branch_time;

namespace {

// int_0^x dx / sqrt(1 - x^q) by composite Simpson over 20000 intervals (x <= 0.95: smooth).
double simpson_branch_time(double x, double q) {
  constexpr int intervals = 20000;
  const double h = x / intervals;
  const auto f = [q](double t) { return 1 / std::sqrt(1 - std::pow(t, q)); };
  double sum = f(0) + f(x);
  for (int i = 1; i < intervals; ++i) sum += (i % 2 ? 4 : 2) * f(i * h);
  return sum * h / 3;
}

// A bat struck at its translation and rotation modes (mass-normalised: psi^2 = 1/M + d^2/I), or
// held at a pivot (the rotation alone), moving towards the ball.
ModalContact rigid_body(bool held) {
  ModalContact body;
  if (held) {
    body.omega = Eigen::VectorXd::Zero(1);
    body.psi = Eigen::VectorXd::Constant(1, 0.62 / std::sqrt(0.048));  // 62 cm from the pivot, I = 0.048 kg m^2
    body.velocity0 = Eigen::VectorXd::Constant(1, 40 * std::sqrt(0.048));  // the point at 24.8 m/s
  } else {
    body.omega = Eigen::VectorXd::Zero(2);
    body.psi = Eigen::Vector2d(1 / std::sqrt(0.885), 0.12 / std::sqrt(0.0459));
    body.velocity0 = Eigen::Vector2d(20 * std::sqrt(0.885), 15 * std::sqrt(0.0459));
  }
  return body;
}

}  // namespace

TEST_CASE("The branch times are the arcsine on a linear spring and a quadrature elsewhere", "[rigid_collision]") {
  // q = 2 (a linear ball): int_0^x dx / sqrt(1 - x^2) = asin x, over both series.
  for (double level : {0.0, 1e-6, 0.1, 0.5, 0.5000001, 0.9, 0.999999, 1.0})
    CHECK(branch_time(level, 2) == Approx(std::atan2(std::sqrt(level), std::sqrt(1 - level))).epsilon(1e-14));
  CHECK(branch_time(1, 2) == Approx(std::acos(-1.0) / 2).epsilon(1e-15));
  // Other exponents: the ball's compression (a + 1 = 2.84) and parting branches (b + 1 up to a
  // nearly dead ball's 1136), against a quadrature where the integrand is smooth.
  for (double q : {1.5, 2.84, 12.36, 1136.0})
    for (double x : {0.2, 0.6, 0.8, 0.95}) {
      if (std::pow(x, q) < 1e-300) continue;  // the level x^q underflows
      INFO("q " << q << ", x " << x);
      CHECK(branch_time(std::pow(x, q), q) == Approx(simpson_branch_time(x, q)).epsilon(1e-12));
    }
}

TEST_CASE("A rigid body's closed-form collision is Dormand-Prince's at a tight tolerance", "[rigid_collision]") {
  CollisionOptions reference;
  reference.method = Method::dopri;
  reference.dt = 1e-7;
  reference.tolerance = 1e-13;
  for (bool held : {false, true})
    for (double a : {1.0, 1.5, 1.84, 2.2})
      for (double e0 : {0.2, 0.5, 1.0})
        for (double cor_slope : {0.0, -0.002}) {
          const ModalContact body = rigid_body(held);
          Ball ball;
          ball.a = a, ball.e0 = e0, ball.k1 = 6.53e7 * std::pow(1e-3, a - 1.84);  // F(1 mm) as N2000's ball
          ball.cor_slope = cor_slope, ball.cor_speed = 40;
          const double speed = 40;
          INFO("held " << held << ", a " << a << ", e0 " << e0 << ", cor slope " << cor_slope);
          const auto closed = detail::rigid_collision(body, ball, speed, CollisionOptions{});
          REQUIRE(closed);
          const Collision stepped = collide(body, ball, speed, reference);
          REQUIRE(stepped.status == CollisionStatus::ok);
          CHECK(closed->status == CollisionStatus::ok);
          CHECK(closed->contacts == 1);
          CHECK(closed->ball_velocity == Approx(stepped.ball_velocity).epsilon(1e-10));
          CHECK(closed->impulse == Approx(stepped.impulse).epsilon(1e-10));
          CHECK(closed->u_max == Approx(stepped.u_max).epsilon(1e-10));
          CHECK(closed->peak_force == Approx(stepped.peak_force).epsilon(1e-9));
          CHECK(closed->dissipated == Approx(stepped.dissipated).epsilon(1e-9).margin(1e-12));
          CHECK(closed->contact_time == Approx(stepped.contact_time).epsilon(1e-9));
          // Dormand-Prince's collision time comes from its force samples' cubic interpolant.
          CHECK(closed->collision_time == Approx(stepped.collision_time).epsilon(1e-7));
          for (int n = 0; n < body.count(); ++n) {
            CHECK(closed->a_dot(n) == Approx(stepped.a_dot(n)).epsilon(1e-10));
            CHECK(closed->a(n) == Approx(stepped.a(n)).epsilon(1e-9));
          }
        }
}

TEST_CASE("A rigid body's closed-form collision keeps the rigid identities exactly", "[rigid_collision]") {
  for (bool held : {false, true})
    for (double e0 : {0.05, 0.5, 0.9}) {
      const ModalContact body = rigid_body(held);
      Ball ball;
      ball.e0 = e0;
      const double speed = 35, bat = body.psi.dot(body.velocity0), closing = speed + bat;
      const auto c = detail::rigid_collision(body, ball, speed, CollisionOptions{});
      REQUIRE(c);
      INFO("held " << held << ", e0 " << e0);
      // The struck point parts from the ball at e0 times the closing speed ...
      CHECK(c->ball_velocity - body.psi.dot(c->a_dot) == Approx(e0 * closing).epsilon(1e-14));
      // ... and the energy the ball's loop dissipates is all the kinetic energy lost.
      const double before = 0.5 * ball.mass * speed * speed + 0.5 * body.velocity0.squaredNorm();
      const double after = 0.5 * ball.mass * c->ball_velocity * c->ball_velocity + 0.5 * c->a_dot.squaredNorm();
      CHECK(after + c->dissipated == Approx(before).epsilon(1e-14));
    }
}

TEST_CASE("An elastic Hertzian ball's contact lasts 2.94 u_max over the closing speed", "[rigid_collision]") {
  // Hertz's impact of elastic spheres (F ~ u^1.5): duration 2.94 delta* / v (K. L. Johnson,
  // Contact Mechanics (1985), sec. 11.4), whatever the masses and the speed.
  for (bool held : {false, true})
    for (double speed : {1.0, 40.0}) {
      Ball ball;
      ball.a = 1.5, ball.e0 = 1;
      const ModalContact body = rigid_body(held);
      const auto c = detail::rigid_collision(body, ball, speed, CollisionOptions{});
      REQUIRE(c);
      const double closing = speed + body.psi.dot(body.velocity0);
      CHECK(c->contact_time * closing / c->u_max == Approx(2.94).margin(0.005));
    }
}

TEST_CASE("The closed form leaves to the stepper what it does not cover", "[rigid_collision]") {
  const Ball ball;
  ModalContact body = rigid_body(false);
  CollisionOptions options;
  CHECK(detail::rigid_collision(body, ball, 40, options));
  CHECK_FALSE(detail::rigid_collision(body, ball, -40, options));  // they never meet
  options.record_force = true;  // a force profile needs the steps
  CHECK_FALSE(detail::rigid_collision(body, ball, 40, options));
  options = {};
  options.max_contact_time = 1e-4;  // longer than that: the stepper reports no_separation
  CHECK_FALSE(detail::rigid_collision(body, ball, 40, options));
  body.residual_compliance = 1e-8;
  CHECK_FALSE(detail::rigid_collision(body, ball, 40, CollisionOptions{}));
  body = rigid_body(false);
  body.omega(1) = 1000;  // a vibrating mode
  CHECK_FALSE(detail::rigid_collision(body, ball, 40, CollisionOptions{}));
}
