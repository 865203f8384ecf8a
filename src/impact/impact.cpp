#include "sweetspot/impact/impact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "sweetspot/impact/batted_ball.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/formulas.hpp"
#include "sweetspot/impact/mode_selection.hpp"
#include "sweetspot/impact/oblique_impact.hpp"
#include "sweetspot/impact/step_selection.hpp"

namespace sweetspot {

namespace {

// Rigid modes at the front of the contact's: rotation about the pivot, or translation and rotation.
int rigid_modes(const ImpactScene& scene) { return scene.pivoted ? 1 : 2; }

// Splits the final energy of the bat among rigid translation, rotation and vibration. A pivoted
// bat has one rigid mode, rotation about the pivot: its energy 1/2 I_p W^2 splits into the CM's
// translation 1/2 M (W d)^2 and rotation 1/2 I_cm W^2 in the ratio M d^2 : I_cm.
void bat_energies(const ImpactScene& scene, const SceneGeometry& g, const ModalBasis& basis, const Collision& c,
                  ImpactResult& r) {
  const int rigid = rigid_modes(scene);
  const int beam = g.wall >= 0 ? g.wall : g.contact.count();  // the wall mode is last
  r.mode_energy.reserve(std::max(0, beam - rigid));
  for (int n = rigid; n < beam; ++n) {
    r.mode_energy.push_back(c.mode_energy(g.contact, n));
    r.energy.vibration += r.mode_energy.back();
  }
  if (g.wall >= 0) r.energy.barrel = c.mode_energy(g.contact, g.wall);
  r.energy.damped = c.damping_dissipated;  // the beam's modes' and the wall's damping
  if (scene.pivoted) {
    const double arm = basis.z_cm - g.pivot;
    const double translation_share = basis.mass * arm * arm / (basis.moment_of_inertia_cm + basis.mass * arm * arm);
    r.energy.bat_translation = translation_share * c.mode_energy(g.contact, 0);
    r.energy.bat_rotation = (1 - translation_share) * c.mode_energy(g.contact, 0);
  } else {
    r.energy.bat_translation = c.mode_energy(g.contact, 0);
    r.energy.bat_rotation = c.mode_energy(g.contact, 1);
  }
}

// The rig's measures at this point. A pivoted bat swinging about its pivot gives the rig's
// numbers at the relative speed v_ball + v_bat: rotation about the pivot is its free rigid mode.
RigMeasures impact_rig_measures(const ImpactScene& scene, const SceneGeometry& g, double vf) {
  const double e_a = collision_efficiency(vf, scene.ball_speed, g.bat_speed);
  // g.recoil = m d^2 / I_pivot; BPF divides by the ball's own COR on a flat wall at the rig's speed.
  if (scene.pivoted) return rig_measures(e_a, g.recoil, scene.ball.cor_at(scene.ball_speed));
  RigMeasures free;
  free.e_a = e_a;
  return free;
}

// What a scene asks beside the collision that needs its whole force profile.
void add_force_analyses(const ImpactScene& scene, const ModalBasis& basis, const SceneGeometry& g, const Collision& c,
                        ImpactResult& r) {
  if (scene.histories)
    r.histories = impact_histories(basis, g, scene.ball, scene.ball_speed, c.force, scene.history);
  if (scene.force_response) {
    std::vector<double> omegas;
    for (const double omega_tau : force_response_grid()) omegas.push_back(omega_tau / c.collision_time);
    r.force_response = force_responses(c.force, omegas);
  }
  if (scene.mode_response) {
    const std::vector<double> all = mode_responses(g.contact, scene.ball.mass, c.force);
    r.mode_response.assign(all.begin() + rigid_modes(scene), g.wall >= 0 ? all.begin() + g.wall : all.end());
  }
}

}  // namespace

std::vector<double> force_response_grid() {
  std::vector<double> grid;
  for (int i = 0; i <= 200; ++i) grid.push_back(i / 10.0);
  return grid;
}

bool has_values(CollisionStatus status) {
  return status != CollisionStatus::no_contact && status != CollisionStatus::no_separation &&
         status != CollisionStatus::non_finite && status != CollisionStatus::failed &&
         status != CollisionStatus::refused_step;
}

void close_balance(ImpactResult& r) {
  ImpactEnergy& e = r.energy;
  // The barrel's terms last: 0 for a solid section, so a wooden bat's sum is what it always was.
  // The oblique terms after them: 0 for a head-on impact, whose sum is again what it always was.
  e.residual = e.initial - (e.ball + e.bat_translation + e.bat_rotation + e.vibration + e.ball_dissipated + e.barrel +
                            e.damped + e.ball_spin + e.bat_tangential + e.friction);
  if (r.status != CollisionStatus::ok) return;
  // A damped bat's loss not integrated (CollisionOptions::damping_loss): the damping can only take
  // energy away, so what is left unaccounted for must not be negative (a step that blew up makes
  // energy). Otherwise the whole balance.
  const bool loss_known = !std::isnan(e.damped);
  const double off = loss_known ? std::abs(e.residual)
                                : e.ball + e.bat_translation + e.bat_rotation + e.vibration + e.ball_dissipated +
                                      e.barrel + e.ball_spin + e.bat_tangential + e.friction - e.initial;
  if (off <= balance_limit * e.initial) return;  // NaN (a term that is not finite) is not balanced
  char text[200];
  std::snprintf(text, sizeof text,
                "the energy balance is off by %.2g of the initial energy: the step is too coarse for this pulse "
                "(take a smaller dt or tolerance, or a tighter accuracy or step_accuracy)",
                off / e.initial);
  r.status = CollisionStatus::unbalanced;
  r.message = text;
}

namespace {

bool finite(const std::vector<double>& values) {
  return std::ranges::all_of(values, [](double x) { return std::isfinite(x); });
}

// The first value of an ok result that is NaN or infinite, or nullptr.
const char* first_non_finite(const ImpactResult& r, const AskedValues& asked) {
  const ImpactEnergy& e = r.energy;
  const std::pair<const char*, double> scalars[] = {
      {"vf", r.vf},
      {"e_eff", r.e_eff},
      {"e_a", asked.e_a ? r.rig.e_a : 0.0},
      {"contact_time", r.contact_time},
      {"collision_time", asked.collision_time ? r.collision_time : 0.0},
      {"u_max", r.u_max},
      {"peak_force", r.peak_force},
      {"impulse", r.impulse},
      {"vf_rigid", asked.vf_rigid ? r.vf_rigid : 0.0},
      {"vf_van_zandt", asked.vf_van_zandt ? r.vf_van_zandt : 0.0},
      {"bbs_linear", asked.bbs_linear ? r.bbs_linear : 0.0},
      {"energy", asked.energy ? e.initial + e.ball + e.bat_translation + e.bat_rotation + e.vibration +
                                    e.ball_dissipated + e.residual + e.barrel + e.damped + e.ball_spin +
                                    e.bat_tangential + e.friction
                              : 0.0},
      {"launch_angle", std::isnan(r.launch.speed) ? 0.0 : r.launch.angle},  // the wall and toy give none
      {"backspin", std::isnan(r.launch.speed) ? 0.0 : r.launch.backspin},
  };
  for (const auto& [name, value] : scalars)
    if (!std::isfinite(value)) return name;
  if (!finite(r.mode_energy)) return "mode_energy";
  if (!finite(r.force_response)) return "force_response";
  if (!finite(r.mode_response)) return "mode_response";
  const Histories& h = r.histories;
  if (!finite(h.force) || !finite(h.compression) || !finite(h.ball_position)) return "the force history";
  for (const ProbeHistory& p : h.probes)
    for (const auto* v : {&p.displacement, &p.velocity, &p.acceleration, &p.vibration_displacement,
                          &p.vibration_velocity, &p.vibration_acceleration})
      if (!finite(*v)) return "a probe's history";
  return nullptr;
}

}  // namespace

void require_finite(ImpactResult& r, const AskedValues& asked) {
  if (r.status != CollisionStatus::ok) return;
  if (const char* name = first_non_finite(r, asked)) {
    r.status = CollisionStatus::non_finite;
    r.message = std::string(name) + " is not finite";
  }
}

ImpactResult collision_result(const Collision& c) {
  ImpactResult r;
  r.status = c.status;
  r.message = c.message;
  if (c.status == CollisionStatus::refused_step) return r;
  r.vf = c.ball_velocity;
  r.contact_time = c.contact_time;
  r.collision_time = c.collision_time;
  r.u_max = c.u_max;
  r.peak_force = c.peak_force;
  r.impulse = c.impulse;
  r.contacts = c.contacts;
  r.force = c.force;
  r.energy.ball_dissipated = c.dissipated;
  return r;
}

namespace {

// The collision of the scene's ball with the struck body as `g` sees it: at the scene's step, at
// the step its accuracy asks, or at the step a coarser slicing checked for it.
Collision collide_scene(const ImpactScene& scene, const SceneGeometry& g, CaughtAgain caught_again) {
  CollisionOptions options = scene.integrator;
  const bool checked = scene.step_accuracy > 0 && scene.checked_step > 0 && options.method == Method::exact;
  // The accuracy's other settings (the contact phase's bound) hold for a checked step too.
  if (scene.step_accuracy > 0)
    options = options_for_accuracy(options, scene.step_accuracy, scene.ball, scene.ball_speed + g.bat_speed, g.recoil,
                                   g.contact.count() ? g.contact.omega.maxCoeff() : 0.0,
                                   g.wall >= 0 ? g.contact.omega(g.wall) : 0.0);
  if (checked) options.dt = scene.checked_step;
  options.stop_when_caught_again = caught_again == CaughtAgain::stop;
  // Van Zandt and the force analyses drive the modes with the force profile.
  options.record_force |= scene.van_zandt_comparison || scene.histories || scene.force_response || scene.mode_response;
  options.find_collision_time |= scene.force_response;  // its omega grid is in units of 1/tau
  return scene.step_accuracy > 0 && !checked
             ? collide_within(g.contact, scene.ball, scene.ball_speed, options, scene.step_accuracy, caught_again)
             : collide(g.contact, scene.ball, scene.ball_speed, options);
}

}  // namespace

double mean_compression_fraction(const Ball& ball) {
  // On one branch F ~ u^p, from rest at u_m (or to it), the ball's energy gives
  // u' ~ sqrt(1 - (u/u_m)^(p+1)), so int F u dt / int F dt = u_m B(1 + 1/(p+1), 1/2) / 2.
  const auto branch = [](double p) {
    const double q = 1 / (p + 1);
    return std::tgamma(1 + q) * std::tgamma(0.5) / (2 * std::tgamma(1.5 + q));
  };
  // The branches' impulses are mu v (compression) and e0 mu v (expansion).
  return (branch(ball.a) + ball.e0 * branch(ball.expansion_exponent())) / (1 + ball.e0);
}

namespace {

// A patch-loaded wall (barrel_wall.hpp): phi_2 and the other harmonics' compliance depend on the
// ball's compression, which the collision decides. Within one impact they are held at the values
// of one effective compression, so the integrators see a fixed modal system (energy exactly
// conserved); that compression is made self-consistent: delta_eff = mean_compression_fraction
// times the collision's largest ball compression, starting from the rigid wall's u_m at the
// rigid bat's reduced mass, rerun until phi_2 moves by less than patch_phi_tolerance (at most
// max_patch_runs collisions). A point-loaded wall, or no wall, collides once as before.
constexpr double patch_phi_tolerance = 1e-4;
constexpr int max_patch_runs = 6;

Collision collide_with_patch(const ImpactScene& scene, const ModalBasis& basis, SceneGeometry& g,
                             CaughtAgain caught_again = CaughtAgain::check) {
  const std::optional<WallMode> wall = g.wall >= 0 ? basis.wall_at(g.z) : std::nullopt;
  if (!wall || wall->load == WallLoad::point) return collide_scene(scene, g, caught_again);
  // Each run's largest compression, over all its contacts, sets the next run's patch.
  if (caught_again == CaughtAgain::stop) caught_again = CaughtAgain::return_unchecked;
  const Ball& ball = scene.ball;
  const double fraction = mean_compression_fraction(ball);
  const double v = scene.ball_speed + g.bat_speed, mu = ball.mass / (1 + g.recoil);
  double compression = fraction * std::pow((ball.a + 1) * mu * v * v / (2 * ball.k1), 1 / (ball.a + 1));
  PatchLoad load = patch_load(*wall, ball.radius, compression);
  for (int run = 1;; ++run) {
    g.contact.psi(g.wall) = load.phi * g.wall_point_shape;
    g.contact.residual_compliance = g.beam_compliance + load.compliance;
    g.wall_patch = load;
    g.wall_compression = compression;
    Collision c = collide_scene(scene, g, caught_again);
    if (run == max_patch_runs || !(c.u_max > 0) || !std::isfinite(c.u_max)) return c;
    const double next_compression = fraction * c.u_max;
    const PatchLoad next = patch_load(*wall, ball.radius, next_compression);
    if (std::abs(next.phi - load.phi) < patch_phi_tolerance) return c;
    load = next;
    compression = next_compression;
  }
}

// The time stepping's error of `fine` by step doubling (error_estimates.hpp): the same collision
// at twice and four times the step (dopri: 32x and 1024x the tolerance); the error at h is
// estimated as |v(h) - v(2h)| / (2^p - 1), p = min(a + 1, 4) (the order the ball's t^a onset
// leaves RK4 and exact stepping at fine steps), or |v(2h) - v(4h)| / (2^p (2^p - 1)) if larger:
// two runs can agree by chance where the error changes sign between their steps (measured on the
// rigid bat: exact at 40 us agreed with 80 us to 7e-8 while erring 8e-6). Where a coarser step is
// refused (RK4's stability), the runs at h / 2 and h / 4 instead. Where a step accuracy chose
// the step, that accuracy. Infinite where no second run succeeds: no estimate.
double step_error_estimate(const ImpactScene& scene, const ModalBasis& basis, const SceneGeometry& g,
                           const Collision& fine) {
  const Method method = scene.integrator.method;
  const bool dopri = method == Method::dopri;
  if (scene.step_accuracy > 0) return scene.step_accuracy;
  const double order = dopri ? 1 : std::min(scene.ball.a + 1, 4.0);
  const double factor = dopri ? 32 : 2, ratio = dopri ? 32 : std::pow(2.0, order);
  const auto run = [&](double multiple) {
    ImpactScene other = scene;
    if (dopri) other.integrator.tolerance *= multiple;
    else other.integrator.dt *= multiple;
    SceneGeometry copy = g;
    return collide_with_patch(other, basis, copy);
  };
  const double v = fine.ball_velocity;
  double estimate = 0;
  Collision c1 = run(factor);
  if (c1.status == CollisionStatus::ok) {
    estimate = std::abs(v - c1.ball_velocity) / (ratio - 1);
    const Collision c2 = run(factor * factor);
    if (c2.status == CollisionStatus::ok)
      estimate = std::max(estimate, std::abs(c1.ball_velocity - c2.ball_velocity) / (ratio * (ratio - 1)));
  } else if (!dopri) {  // refused: finer runs, the error at h from theirs
    c1 = run(0.5);
    if (c1.status != CollisionStatus::ok) return std::numeric_limits<double>::infinity();
    estimate = std::abs(v - c1.ball_velocity) * ratio / (ratio - 1);
  } else {
    return std::numeric_limits<double>::infinity();
  }
  return estimate / error_scale(v, scene.ball_speed);
}

// auto's estimate, made against the rigid bat's exit speed before the impact, against this one's
// error_scale as every other estimate is: where the flexible bat returns the ball slower than the
// rigid one the same error in m/s is a larger share of it (1-1.5x over R161's barrel, about 2x
// toward its handle, up to 7x on maple_271 at 30 cm, 2.4x on the low-impact scene).
double restated_modes_error(const SceneGeometry& g, const ImpactScene& scene, double vf) {
  if (!(g.modes_error > 0) || !std::isfinite(vf)) return g.modes_error;
  return g.modes_error * selection_error_scale(scene.ball, scene.ball_speed, g.bat_speed, g.recoil) /
         error_scale(vf, scene.ball_speed);
}

// validate() lets points lie a rounding error past the bat's ends (bat_extent_tolerance): the
// scene with them put on it, or nullptr when all are on it already (the usual case: no copy).
std::unique_ptr<ImpactScene> clamped_onto_bat(const ImpactScene& scene, double length) {
  const auto off = [length](double z) { return z < 0 || z > length; };
  if (!off(scene.z) && !(scene.histories && std::ranges::any_of(scene.history.probes, off))) return nullptr;
  auto clamped = std::make_unique<ImpactScene>(scene);
  clamped->z = std::clamp(scene.z, 0.0, length);
  for (double& z : clamped->history.probes) z = std::clamp(z, 0.0, length);
  return clamped;
}

}  // namespace

ImpactResult simulate_impact(const ModalBasis& basis, const ImpactScene& stated) {
  validate(stated, basis);
  // Off the line of the swing, or with spin or friction: the head-on collision along the line of
  // centres, then the motion across it (oblique_impact.cpp).
  if (!stated.oblique.head_on()) return simulate_oblique_impact(basis, stated);
  // A stated accuracy sets the modes' tolerance and the step (error_estimates.hpp); the slicing
  // is the caller's, who holds the bat's design (simulate_within_accuracy).
  const std::unique_ptr<ImpactScene> budgeted =
      stated.accuracy > 0 ? std::make_unique<ImpactScene>(scene_for_accuracy(stated)) : nullptr;
  const ImpactScene& given = budgeted ? *budgeted : stated;
  std::unique_ptr<ImpactScene> adjusted = clamped_onto_bat(given, basis.length());
  // The ball as it meets this section (struck_ball): the collision and the closed forms take it.
  if (given.ball.curved_contact || given.ball.speed_dependent()) {
    if (!adjusted) adjusted = std::make_unique<ImpactScene>(given);
    adjusted->ball = struck_ball(*adjusted, basis);
  }
  const ImpactScene& scene = adjusted ? *adjusted : given;
  SceneGeometry g = scene_geometry(scene, basis);
  // Without a stated accuracy (whose modes' share widens the basis itself: widened_scene), a
  // tolerance looser than caught_again_mode_tolerance solved fewer modes than a ball caught again
  // needs.
  const bool widens = scene.vibrational_modes == auto_modes && !(scene.accuracy > 0) && basis.widening &&
                      scene.mode_tolerance > caught_again_mode_tolerance;
  const bool reruns_if_caught_again = scene.vibrational_modes == auto_modes && (g.drops_solved || widens);
  // A scene whose modes' share was divided took its dropped modes past their share before (a
  // coarser rung, or this one on a narrower basis: widened_scene), mostly by a ball caught again:
  // every solved mode at once.
  const bool over_share_before = reruns_if_caught_again && scene.mode_share_divisor > 1;
  Collision c;
  if (!over_share_before)
    c = collide_with_patch(scene, basis, g, reruns_if_caught_again ? CaughtAgain::stop : CaughtAgain::check);
  // auto's estimate bounds what the dropped modes change over one pulse. A ball the bat's
  // vibration strikes again (a handle impact) sums their errors over the contacts, and the timing
  // of each later one can magnify them past it (up to 12x the tolerance on R161 and the torpedo):
  // the impact is then run again with every solved mode kept, the unsolved ones alone dropped,
  // and their estimate counted once per contact (README "Numerics").
  const ModalBasis* solved = &basis;
  if (over_share_before || (reruns_if_caught_again && c.contacts > 1)) {
    if (widens && !over_share_before) {
      ImpactScene tighter = scene;
      tighter.ball = given.ball;  // as the caller asked its basis: struck_ball follows
      tighter.mode_tolerance = caught_again_mode_tolerance;
      solved = &basis.widened(auto_mode_request(tighter, basis));
    }
    ImpactScene every_solved = scene;
    every_solved.mode_tolerance = 0;  // nothing solved is dropped
    g = scene_geometry(every_solved, *solved);
    c = collide_with_patch(scene, *solved, g);
    g.modes_error *= c.contacts;
  }

  ImpactResult r = collision_result(c);
  if (!scene.integrator.record_force) r.force.clear();  // recorded for this function's use alone
  r.z = g.z;
  r.bat_speed = g.bat_speed;
  r.hoop_frequency = g.hoop_frequency;
  r.barrel_compression = g.barrel_compression;
  if (g.wall >= 0) {
    r.barrel_phi = g.wall_patch.phi;
    r.barrel_compliance = g.wall_patch.compliance;
    r.barrel_compression_eff = g.wall_compression;
  }
  r.modes_kept = g.modes_kept;
  r.modes_error = restated_modes_error(g, scene, r.vf);
  r.slices_used = basis.slices();
  r.step_used = c.step;
  if (scene.error_estimates && c.status == CollisionStatus::ok) {
    r.step_error = step_error_estimate(scene, *solved, g, c);
    r.total_error = r.modes_error + r.step_error + r.slicing_error;  // NaN until the caller adds the slicing's
  }
  if (!has_values(c.status)) {  // nothing happened, nothing to report, or a step refused
    const double nan = std::nan("");
    r.vf = r.contact_time = r.collision_time = r.u_max = r.peak_force = r.impulse = nan;
    r.e_eff = nan;
    r.energy = {nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan};
    return r;
  }
  if (scene.rigid_comparison) r.vf_rigid = rigid_exit_speed(scene.ball.e0, g.recoil, scene.ball_speed, g.bat_speed);
  if (scene.linear_batted_ball)
    r.bbs_linear = linear_batted_ball_speed(collision_efficiency(*solved, scene, scene.e_a_speed), scene.ball_speed,
                                            g.bat_speed);
  r.e_eff = effective_cor(r.vf, g.recoil, scene.ball_speed, g.bat_speed);
  r.rig = impact_rig_measures(scene, g, r.vf);
  // Only a whole force profile can drive the modes (the toy model does the same).
  if (scene.van_zandt_comparison && c.status == CollisionStatus::ok)
    r.vf_van_zandt = van_zandt_exit_speed(g.contact, scene.ball, g.recoil, scene.ball_speed, g.bat_speed, c.force);
  if (c.status == CollisionStatus::ok) add_force_analyses(scene, *solved, g, c, r);

  ImpactEnergy& e = r.energy;
  e.initial = 0.5 * scene.ball.mass * scene.ball_speed * scene.ball_speed + 0.5 * g.contact.velocity0.squaredNorm();
  e.ball = 0.5 * scene.ball.mass * r.vf * r.vf;
  bat_energies(scene, g, *solved, c, r);
  r.launch = head_on_launch(r.vf);
  close_balance(r);
  const bool collision_time = scene.integrator.find_collision_time || scene.force_response;
  require_finite(r, {collision_time, scene.rigid_comparison, scene.van_zandt_comparison, scene.linear_batted_ball, true,
                     !std::isnan(r.energy.damped)});
  return r;
}

}  // namespace sweetspot
