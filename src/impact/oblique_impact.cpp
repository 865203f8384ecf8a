#include "sweetspot/impact/oblique_impact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "sweetspot/contact/tangential_contact.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

constexpr double rpm = 2 * std::numbers::pi / 60;  // rad/s per rpm
constexpr double degree = std::numbers::pi / 180;

// The direction of the line of centres against the swing's line.
struct LineOfCentres {
  double sin = 0;
  double cos = 1;
};

LineOfCentres line_of_centres(const ModalBasis& basis, const ImpactScene& scene) {
  const double s = scene.oblique.undercut / contact_reach(basis, scene);
  return {s, s == 0 ? 1.0 : std::sqrt((1 - s) * (1 + s))};
}

// The head-on scene along the line of centres: every speed of the swing's line times cos theta.
ImpactScene normal_scene(const ImpactScene& scene, const LineOfCentres& line) {
  ImpactScene normal = scene;
  normal.oblique = ObliqueImpact{};
  normal.oblique.grip_stiffness = scene.oblique.grip_stiffness;  // not read: head_on() ignores it
  if (line.sin != 0) {
    normal.ball_speed *= line.cos;
    normal.swing.omega *= line.cos;
    normal.swing.cm_speed *= line.cos;  // about a centre, the centre stays: omega alone scales
  }
  // Friction needs the normal force through the contact.
  if (scene.oblique.friction > 0) normal.integrator.record_force = true;
  return normal;
}

// The rigid bat's velocity at the struck point per unit impulse there (1/kg), free or pivoted: the
// same effective mass the normal collision's rigid modes give (scene.cpp, rigid_geometry).
double struck_point_mobility(const ModalBasis& basis, const ImpactScene& scene) {
  const double z = std::clamp(scene.z, 0.0, basis.length()), arm = z - basis.z_cm;
  if (scene.pivoted) {
    const double lever = z - scene.swing.center, pivot_arm = scene.swing.center - basis.z_cm;
    return lever * lever / (basis.moment_of_inertia_cm + basis.mass * pivot_arm * pivot_arm);
  }
  return 1 / basis.mass + arm * arm / basis.moment_of_inertia_cm;
}

// The swing's speed of the struck point along the swing's line, m/s.
double struck_point_speed(const ModalBasis& basis, const ImpactScene& scene) {
  const Swing& swing = scene.swing;
  const double cm_speed = swing.about_center ? swing.omega * (basis.z_cm - swing.center) : swing.cm_speed;
  return cm_speed + swing.omega * (std::clamp(scene.z, 0.0, basis.length()) - basis.z_cm);
}

TangentialBodies tangential_bodies(const ModalBasis& basis, const ImpactScene& scene) {
  TangentialBodies b;
  b.ball_mass = scene.ball.mass;
  b.ball_radius = scene.ball.radius;
  b.ball_inertia = scene.oblique.ball_inertia_factor * scene.ball.mass * scene.ball.radius * scene.ball.radius;
  b.bat_mobility = struck_point_mobility(basis, scene);
  b.bat_radius = basis.section_radius_at(scene.z);
  b.bat_axial_inertia =
      basis.axial_moment_of_inertia > 0 ? basis.axial_moment_of_inertia : std::numeric_limits<double>::infinity();
  return b;
}

ImpactResult missed(const ImpactScene& scene, std::string reason) {
  const double nan = std::nan("");
  ImpactResult r;
  r.status = CollisionStatus::no_contact;
  r.message = std::move(reason);
  r.z = scene.z;
  r.vf = r.e_eff = r.contact_time = r.collision_time = r.u_max = r.peak_force = r.impulse = r.bat_speed = nan;
  r.energy = {nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan};
  return r;
}

}  // namespace

BallLaunch head_on_launch(double vf) { return {vf, 0.0, 0.0, 0.0}; }

double contact_reach(const ModalBasis& basis, const ImpactScene& scene) {
  return scene.ball.radius + basis.section_radius_at(scene.z);
}

std::string miss_reason(const ModalBasis& basis, const ImpactScene& scene) {
  const double reach = contact_reach(basis, scene);
  if (!(std::abs(scene.oblique.undercut) >= reach)) return "";  // a miss for sure; a z off the bat is validate's
  return "the ball misses the bat: undercut " + detail::format_number(scene.oblique.undercut) +
         " m is not less than the ball's and the bat's radii together, " + detail::format_number(reach) + " m at z = " +
         detail::format_number(scene.z) + " m";
}

namespace {

// Friction only takes energy, and the tangential contact's balance closes to rounding whatever it
// takes, so the balance cannot show it giving some. The grip could: its stiffness follows the
// normal force (GripLaw), and a stretch stiffened as the force grew gave back more than the bodies
// put in. The grip now loads incrementally (tangential_contact.cpp), and friction took energy at
// every point of scripts/friction_energy (R161's barrel, mu 0.2 to 5) and of 3 840 oblique impacts
// on four bats (mu 0.2 to 100, both spins, undercuts -2 to 3.5 cm). A result that gave energy all
// the same is not ok: this guard has no known case.
constexpr double friction_gain_limit = 1e-6;  // of the initial energy: the balance's rounding

void refuse_energy_from_friction(ImpactResult& r) {
  const ImpactEnergy& e = r.energy;
  if (r.status != CollisionStatus::ok || !(e.friction < -friction_gain_limit * e.initial)) return;
  char text[240];
  std::snprintf(text, sizeof text,
                "friction gave the bodies %.2g of the initial energy, which friction cannot: the grip's stepping "
                "failed to hold its energy (please report the scene)",
                -e.friction / e.initial);
  r.status = CollisionStatus::unbalanced;
  r.message = text;
}

// The oblique impact at the scene's settings, without the step's estimate.
ImpactResult oblique_impact(const ModalBasis& basis, const ImpactScene& scene) {
  if (std::string reason = miss_reason(basis, scene); !reason.empty()) return missed(scene, std::move(reason));
  const ObliqueImpact& o = scene.oblique;
  const LineOfCentres line = line_of_centres(basis, scene);
  ImpactResult r = simulate_impact(basis, normal_scene(scene, line));
  std::vector<ForceSample> force = std::move(r.force);
  if (scene.integrator.record_force) r.force = force;
  if (!has_values(r.status)) return r;

  // Across the line of centres, t = the swing's line turned a quarter up (toward the ball's side
  // for D > 0): the pitch's velocity -v s has +v sin(theta) along t, the bat's +V s has -V sin(theta).
  const TangentialBodies bodies = tangential_bodies(basis, scene);
  TangentialMotion initial;
  initial.ball_velocity = scene.ball_speed * line.sin;
  initial.ball_spin = 0.0 - o.pitch_spin * rpm;  // the pitch's backspin turns as topspin leaving
  initial.bat_velocity = -struck_point_speed(basis, scene) * line.sin;
  GripLaw grip;
  grip.friction = o.friction;
  grip.grip_stiffness = o.grip_stiffness;
  const Ball struck = scene.ball.curved_contact ? scene.ball.on_section(bodies.bat_radius) : scene.ball;
  grip.k1 = struck.k1;
  grip.a = struck.a;
  // The stretch as lossy as the ball's normal law at this collision's closing speed.
  grip.damping_ratio = damping_ratio_for(scene.ball.cor_at((scene.ball_speed + struck_point_speed(basis, scene)) * line.cos));
  const TangentialResult t = tangential_contact(force, bodies, initial, grip);

  // Energies: the normal collision's balance plus the motion across the line.
  ImpactEnergy& e = r.energy;
  const double m = bodies.ball_mass, normal_ball = 0.5 * m * r.vf * r.vf;
  const double v_t0 = initial.ball_velocity, v_t = t.final.ball_velocity;
  const double ball_normal_initial = 0.5 * m * (scene.ball_speed * line.cos) * (scene.ball_speed * line.cos);
  // The bat's swing across the line carries sin^2 / cos^2 of what it carries along it.
  const double bat_across_initial =
      line.sin == 0 ? 0.0 : (e.initial - ball_normal_initial) * (line.sin * line.sin) / (line.cos * line.cos);
  const double j = t.impulse;
  e.initial += 0.5 * m * v_t0 * v_t0 + 0.5 * bodies.ball_inertia * initial.ball_spin * initial.ball_spin +
               bat_across_initial;
  e.ball = normal_ball + 0.5 * m * v_t * v_t;
  e.ball_spin = 0.5 * bodies.ball_inertia * t.final.ball_spin * t.final.ball_spin;
  e.bat_tangential = bat_across_initial - j * 0.5 * (initial.bat_velocity + t.final.bat_velocity) -
                     j * bodies.bat_radius * 0.5 * (initial.bat_roll + t.final.bat_roll);
  e.friction = t.friction_loss;

  // The launch: the exit velocity (normal r.vf along the line of centres, v_t across it) in the
  // vertical plane; the line of centres leans swing_tilt + theta above the horizontal.
  BallLaunch& launch = r.launch;
  launch.speed = std::hypot(r.vf, v_t);
  launch.angle = o.swing_tilt + std::asin(line.sin) / degree + std::atan2(v_t, r.vf) / degree;
  launch.backspin = t.final.ball_spin / rpm;
  launch.sidespin = 0;
  r.vf = launch.speed;
  close_balance(r);
  refuse_energy_from_friction(r);
  require_finite(r, {scene.integrator.find_collision_time || scene.force_response, scene.rigid_comparison, scene.van_zandt_comparison,
                     scene.linear_batted_ball, true, !std::isnan(e.damped)});
  return r;
}

// The estimate of the error of `fine`'s exit speed from a run at twice its step, `coarse`: their
// difference over 2^2 - 1 (the tangential contact's second order, as Richardson's), divided by
// `further` (4 for a run at twice and four times the step), times 2 (the convergence is not clean
// at the coarser steps: measured within 0.7x of the actual error without it; the slicing estimate's
// factor), relative as every estimate. Infinite where a run failed.
double doubling_estimate(const ImpactResult& fine, const ImpactResult& coarse, double ball_speed, double further = 1) {
  if (fine.status != CollisionStatus::ok || coarse.status != CollisionStatus::ok)
    return std::numeric_limits<double>::infinity();
  return 2 * std::abs(fine.vf - coarse.vf) / (3 * further) / error_scale(fine.vf, ball_speed);
}

// The estimate of `r`'s error from runs of its scene at twice and four times its step (`at`
// makes them): the larger of the two doublings, since two runs can agree by chance. Infinite where
// the run at twice the step fails.
template <class RunAt>
double doubling_pair(const ImpactResult& r, const RunAt& at, double ball_speed) {
  const ImpactResult twice = at(2.0);
  const double estimate = doubling_estimate(r, twice, ball_speed);
  return std::isfinite(estimate) ? std::max(estimate, doubling_estimate(twice, at(4.0), ball_speed, 4)) : estimate;
}

// An oblique impact's exit speed takes the motion across the line of centres, which friction
// moves at the tangential contact's second order in the step: the normal collision's estimates
// and its model of the step do not see it. Without a stated accuracy, step doubling of the whole
// impact (doubling_pair), never below the normal collision's own estimate; Dormand-Prince at 32
// and 1024 times its tolerance, which double and quadruple its steps (its step goes as the fifth
// root of the tolerance). Where the coarser run fails (RK4 past its stability), from a run at half
// the step.
double oblique_step_error(const ModalBasis& basis, const ImpactScene& scene, const ImpactResult& r) {
  if (!std::isfinite(r.step_error)) return r.step_error;
  const auto at = [&](double factor) {
    ImpactScene other = scene;
    other.error_estimates = false;
    if (other.integrator.method == Method::dopri) other.integrator.tolerance *= std::pow(32.0, std::log2(factor));
    else other.integrator.dt *= factor;
    return oblique_impact(basis, other);
  };
  double estimate = doubling_pair(r, at, scene.ball_speed);
  // The error at h from a run at h / 2: 4 times its own.
  if (!std::isfinite(estimate)) estimate = 4 * doubling_estimate(at(0.5), r, scene.ball_speed);
  return std::max(r.step_error, estimate);
}

// The step's share of a stated accuracy, where the normal collision's model chooses the step with
// exact stepping (the step not already checked on a coarser slicing): 0 otherwise.
double step_share(const ImpactScene& scene) {
  if (scene.integrator.method != Method::exact || scene.checked_step > 0) return 0;
  return scene.step_accuracy > 0 ? scene.step_accuracy : scene.accuracy > 0 ? accuracy_budget(scene.accuracy).step : 0;
}

// Under a stated accuracy the normal collision's model chooses the step for the normal collision
// alone (at 1e-5 the tangential contact erred up to 25x its share there): the step is halved
// until the runs at twice and four times it agree within the share (doubling_pair), and the
// result states the larger of the share and the estimate.
constexpr int max_oblique_halvings = 8;

ImpactResult within_step_share(const ModalBasis& basis, const ImpactScene& scene, ImpactResult r, double share) {
  for (int halvings = 0;; ++halvings) {
    const double h = r.step_used;
    const auto at = [&](double factor) {
      ImpactScene coarser = scene;
      coarser.error_estimates = false;
      coarser.checked_step = factor * h;
      return oblique_impact(basis, coarser);
    };
    const double estimate = doubling_pair(r, at, scene.ball_speed);
    if (estimate <= share || halvings == max_oblique_halvings) {
      if (scene.error_estimates || scene.accuracy > 0) {
        r.step_error = std::max(std::isnan(r.step_error) ? share : r.step_error, estimate);
        r.total_error = r.modes_error + r.step_error + r.slicing_error;
      }
      return r;
    }
    ImpactScene finer = scene;
    finer.checked_step = h / 2;
    ImpactResult next = oblique_impact(basis, finer);
    if (next.status != CollisionStatus::ok) return next;
    r = std::move(next);
  }
}

}  // namespace

ImpactResult simulate_oblique_impact(const ModalBasis& basis, const ImpactScene& scene) {
  ImpactResult r = oblique_impact(basis, scene);
  if (r.status != CollisionStatus::ok || !(scene.oblique.friction > 0)) return r;
  if (const double share = step_share(scene); share > 0) return within_step_share(basis, scene, std::move(r), share);
  if (scene.error_estimates && scene.step_accuracy == 0 && scene.accuracy == 0) {
    r.step_error = oblique_step_error(basis, scene, r);
    r.total_error = r.modes_error + r.step_error + r.slicing_error;  // NaN until the caller adds the slicing's
  }
  return r;
}

}  // namespace sweetspot
