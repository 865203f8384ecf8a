#include "sweetspot/impact/scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "sweetspot/ball/ball_tests.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/impact/mode_selection.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

[[noreturn]] void reject(const std::string& key, double value, const std::string& expected) {
  std::ostringstream text;
  text << "impact: " << key << " = " << value << ": " << expected;
  throw InputError(text.str());
}

// A point off the bat, with the digits that tell it from the bat's end.
[[noreturn]] void reject_off_bat(const std::string& key, double z, double length) {
  const auto [value, end] = detail::format_apart(z, z < 0 ? 0.0 : length);
  throw InputError("impact: " + key + " = " + value + ": must lie on the bat (0 to " +
                   (z < 0 ? detail::format_number(length) : end) + " m)");
}

void require_finite(const std::string& key, double value) {
  if (!std::isfinite(value)) reject(key, value, "must be a finite number");
}

void require_positive(const std::string& key, double value) {
  if (!(value > 0) || !std::isfinite(value)) reject(key, value, "must be a positive finite number");
}

// The modes an impact keeps: the rigid two, then the first N vibrational ones, all of them, or
// (auto) those the pulse can excite, the rest folded into a residual compliance.
std::vector<int> kept_modes(const ImpactScene& scene, const ModalBasis& basis, const Eigen::VectorXd& shapes,
                            SceneGeometry& g) {
  std::vector<int> kept;
  if (scene.vibrational_modes == auto_modes) {
    // A partial basis: the modes it did not solve are dropped, their compliance counted exactly.
    const UnsolvedModes unsolved =
        basis.complete() ? UnsolvedModes{} : UnsolvedModes{basis.unsolved_compliance_at(g.z), basis.solved_below};
    const ModeSelection selection =
        select_modes(basis.omega, shapes, scene.ball, scene.ball_speed, g.bat_speed, g.recoil,
                     scene.mode_tolerance, unsolved);
    kept.reserve(2 + selection.kept.size());  // the rigid two, then the kept ones, in one allocation
    kept = {0, 1};
    kept.insert(kept.end(), selection.kept.begin(), selection.kept.end());
    g.contact.residual_compliance = selection.residual_compliance;
    g.modes_error = selection.error_estimate;
    g.drops_solved = kept.size() < static_cast<std::size_t>(basis.count());
  } else {
    const int count = scene.vibrational_modes == all_modes ? basis.count() : 2 + scene.vibrational_modes;
    kept.reserve(std::max(count, 2));
    kept = {0, 1};
    for (int i = 2; i < count; ++i) kept.push_back(i);
  }
  g.modes_kept.reserve(kept.size());
  for (std::size_t i = 2; i < kept.size(); ++i) g.modes_kept.push_back(kept[i] - 1);
  return kept;
}

// A bat held at a point z_p. The pivot holds the bat's own point there, which lies between the
// discretisation's nodes: the nodes' interpolated displacement psi_p . a plus the segment's own
// yield c F under the pivot's force F (the compliance a point load there carries, beam_layout.hpp).
// So the constraint is a spring of stiffness 1/c on psi_p . a, and at a node (c = 0) psi_p . a = 0.
// Held rigidly between nodes instead, the bat is too stiff there by O(dz) and the held bat
// converges at first order in the slices, irregularly as the pivot moves among them (numerics.md).
// The constrained bat's own modes diagonalise the stiffness, so the collision integrates them like
// any free modal system, and free flight stays exact. The stiffness is decomposed in a basis whose
// first direction is psi_p: the spring then adds to one diagonal entry, and however stiff it is,
// the other modes keep the accuracy of the rigid constraint's.
// Its modes are columns over the free ones (omega, their shapes at the pivot psi_pivot), the first
// the rotation about the pivot.
struct HeldBasis {
  Eigen::MatrixXd modes;
  Eigen::VectorXd omega;
};

HeldBasis constrained_modes(const Eigen::VectorXd& omega, const Eigen::VectorXd& psi_pivot, double compliance) {
  const int n = static_cast<int>(omega.size());
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(psi_pivot);
  const int held_count = compliance > 0 ? n : n - 1;
  const Eigen::MatrixXd basis = (qr.householderQ() * Eigen::MatrixXd::Identity(n, n)).rightCols(held_count);
  Eigen::MatrixXd stiffness = basis.transpose() * omega.array().square().matrix().asDiagonal() * basis;
  if (compliance > 0) stiffness(0, 0) += psi_pivot.squaredNorm() / compliance;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(stiffness);
  HeldBasis held;
  held.modes = basis * eig.eigenvectors();
  held.omega = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  held.omega(0) = 0;  // rotation about the pivot; round-off otherwise
  return held;
}

// Held through its yield, a bat has as many modes as the free ones it is made of, the fastest at
// or above the fastest free one: a rank-one stiffening raises each eigenvalue at most to the next
// one's (Golub, SIAM Rev. 15, 318 (1973)). That mode is mostly the pivot's yield, faster than
// anything the kept free modes resolve, and without bound as the pivot nears a node. It follows
// the pulse quasi-statically: its compliance at the impact point goes in series with the ball,
// as the dropped modes' does. So a held bat keeps as many modes as the rigid constraint gives,
// none faster than the free ones, and RK4's and Dormand-Prince's steps stay bounded.
void fold_fastest_mode(ModalContact& held, Eigen::MatrixXd& modes) {
  const int n = held.count() - 1;
  held.residual_compliance += held.psi(n) * held.psi(n) / (held.omega(n) * held.omega(n));
  held.omega.conservativeResize(n);
  held.psi.conservativeResize(n);
  held.velocity0.conservativeResize(n);
  modes.conservativeResize(Eigen::NoChange, n);
}

// The bat's loss factor eta damps every vibrational mode of the struck body, free or held, at
// zeta = eta / 2: the viscous damping that dissipates a mode's 2 pi eta per cycle at resonance,
// as the wall's (barrel_wall.hpp; Cremer, Heckl & Petersson, "Structure-Borne Sound", ch. 3). A
// held bat's modes are damped as modes of their own (its damping in the free modes' coordinates,
// eta times their frequencies, is not diagonal in the held ones: taken so, the loss per cycle of
// each is the material's). Rigid motions (omega = 0) are not damped; eta = 0 changes nothing.
void damp_beam_modes(double loss_factor, ModalContact& c) {
  if (loss_factor == 0) return;
  c.damping_ratio = (c.omega.array() > 0).select(Eigen::VectorXd::Constant(c.count(), loss_factor / 2), 0.0);
}

// constrained_modes, the last one kept per thread (known by all it reads): the rig strikes one
// held bat at every point of its scan, a study every point of a held bat, and the decomposition
// costs more than an impact from a few tens of modes on.
const HeldBasis& held_modes(const Eigen::VectorXd& omega, const Eigen::VectorXd& at_pivot, double compliance) {
  struct Entry {
    Eigen::VectorXd omega, at_pivot;
    double compliance = 0;
    HeldBasis held;
  };
  thread_local Entry cache;
  const auto same = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return a.size() == b.size() && (a.array() == b.array()).all();
  };
  if (same(cache.omega, omega) && same(cache.at_pivot, at_pivot) && cache.compliance == compliance)
    return cache.held;
  cache.held = constrained_modes(omega, at_pivot, compliance);
  cache.omega = omega, cache.at_pivot = at_pivot, cache.compliance = compliance;
  return cache.held;
}

// The free modes `free` (their shapes at the struck point and their swing) held at the pivot.
ModalContact held_contact(const ModalContact& free, const Eigen::VectorXd& at_pivot, double compliance,
                          Eigen::MatrixXd& modes) {
  const HeldBasis& h = held_modes(free.omega, at_pivot, compliance);
  modes = h.modes;
  ModalContact held;
  held.omega = h.omega;
  held.psi = modes.transpose() * free.psi;
  held.velocity0 = modes.transpose() * free.velocity0;
  held.residual_compliance = free.residual_compliance;
  return held;
}

// auto on a held bat: the modes are chosen among the held bat's own, whose shapes at the impact
// point are what the ball excites (choosing among the free bat's and holding those errs up to
// 80x the estimate on a hollow bat: README "Numerics"). Sets the contact's modes, the held map
// and the estimate; the dropped held modes' compliance goes into the residual.
//
// The bat is held over every solved mode. The free modes left unsolved follow the pivot's force
// quasi-statically, as they follow the ball's: their static flexibility over the two loaded
// points, [g_zz g_zp; g_zp g_pp], is the residual flexibility of component mode synthesis
// (MacNeal, Comput. Struct. 1, 581 (1971)). At the pivot g_pp, in series with the segment's
// yield, softens the constraint (without it the pivot holds the bat too stiffly, more so as the
// slices add modes above the solved ones: R161 on the rig at 672 slices, v_f erred up to 35x
// auto's estimate near the handle). The pivot's force F_p = -(psi_p . a + g_zp F) / c then also
// answers the ball's force F through g_zp: condensed out, the struck point reads the modes as
// psi_z - (g_zp / c) psi_p (and is forced so, symmetrically) and keeps g_zz - g_zp^2 / c of the
// unsolved compliance. Struck near the pivot, g_zp is as large as g_zz and g_pp, and the pivot
// holds the point as it should (counting g_zz alone there, aluminium on the rig 2.6 mm from its
// pivot erred 1.6x the total estimate).
void held_auto_geometry(const ImpactScene& scene, const ModalBasis& basis, SceneGeometry& g) {
  const Eigen::VectorXd at_pivot = basis.shapes_at(g.pivot);
  const double compliance = basis.layout.point(g.pivot).compliance + basis.unsolved_compliance_at(g.pivot);
  const HeldBasis& h = held_modes(basis.omega, at_pivot, compliance);
  const double shared = basis.unsolved_cross_compliance(g.z, g.pivot);
  const double condensed = shared != 0 ? shared / compliance : 0.0;
  const int n = static_cast<int>(h.omega.size());
  Eigen::VectorXd struck = basis.shapes_at(g.z);
  if (condensed != 0) struck -= condensed * at_pivot;
  const Eigen::VectorXd held_psi = h.modes.transpose() * struck;
  // select_modes takes two rigid modes first: the held bat has one, so a still one goes before it.
  Eigen::VectorXd omega(n + 1), psi(n + 1);
  omega << 0, h.omega;
  psi << 0, held_psi;
  const UnsolvedModes unsolved =
      basis.complete() ? UnsolvedModes{}
                       : UnsolvedModes{std::max(0.0, basis.unsolved_compliance_at(g.z) - condensed * shared),
                                       basis.solved_below};
  const ModeSelection selection = select_modes(omega, psi, scene.ball, scene.ball_speed, g.bat_speed, g.recoil,
                                               scene.mode_tolerance, unsolved);
  std::vector<int> held = {0};
  for (const int i : selection.kept) held.push_back(i - 1), g.modes_kept.push_back(i - 1);
  g.drops_solved = static_cast<int>(held.size()) < n;
  g.kept.resize(basis.count());
  for (int i = 0; i < basis.count(); ++i) g.kept[i] = i;
  g.held = h.modes(Eigen::all, held);
  const Eigen::VectorXd velocity0 = g.cm_speed * basis.translation + scene.swing.omega * basis.rotation;
  g.contact.omega = h.omega(held);
  g.contact.psi = held_psi(held);
  g.contact.velocity0 = g.held.transpose() * velocity0;
  g.contact.residual_compliance = selection.residual_compliance;
  g.modes_error = selection.error_estimate;
}

void validate_history(const HistoryRequest& h, double length) {
  require_positive("history_window", h.window);
  require_positive("history_step", h.step);
  if (!(h.steps() <= max_history_samples))
    reject("history_step", h.step, "gives more than 1e5 samples over the history window");
  for (const double z : h.probes)
    if (!lies_on_bat(z, length)) reject_off_bat("probes", z, length);
}

// The wall's ovaling as one more mode of the contact (barrel_wall.hpp): mass-normalised, its
// shape at the contact point is 1 / sqrt(m_w) under a point load; it starts at rest, whatever the
// bat's swing. A patch-loaded wall scales that shape by phi_2 and adds its other harmonics to the
// residual compliance (impact.cpp, at the impact's effective compression). A bat kept rigid (no
// vibrational mode) has no wall either, though its section has a hoop frequency.
void add_wall_mode(const ImpactScene& scene, const ModalBasis& basis, SceneGeometry& g) {
  const std::optional<WallMode> wall = basis.wall_at(g.z);
  if (!wall) return;
  g.hoop_frequency = wall->frequency_hz();
  g.barrel_compression = barrel_compression(*wall);
  if (scene.vibrational_modes == 0) return;
  ModalContact& c = g.contact;
  const int n = c.count();
  c.omega.conservativeResize(n + 1);
  c.psi.conservativeResize(n + 1);
  c.velocity0.conservativeResize(n + 1);
  c.omega(n) = wall->omega;
  c.psi(n) = 1 / std::sqrt(wall->mass);
  c.velocity0(n) = 0;
  g.wall_point_shape = c.psi(n);
  g.beam_compliance = c.residual_compliance;
  // Its loss factor eta as viscous damping, zeta = eta / 2 (equal loss per cycle at resonance,
  // barrel_wall.hpp); a lossless wall on an undamped beam leaves every mode undamped, the
  // undamped code paths. The beam's own damping (damp_beam_modes) is kept.
  if (wall->loss_factor > 0 || c.damping_ratio.size()) {
    c.damping_ratio.conservativeResizeLike(Eigen::VectorXd::Zero(n + 1));
    c.damping_ratio(n) = wall->loss_factor / 2;
  }
  g.wall = n;
}

}  // namespace

Eigen::VectorXd SceneGeometry::shapes_at(const ModalBasis& basis, double z) const {
  const Eigen::VectorXd free = basis.shapes_at(z)(kept);
  Eigen::VectorXd shapes = held.size() ? Eigen::VectorXd(held.transpose() * free) : free;
  // The wall's ovaling is local: it moves no other point of the bat's axis.
  if (wall >= 0) shapes.conservativeResizeLike(Eigen::VectorXd::Zero(wall + 1));
  return shapes;
}

void validate_oblique(const ObliqueImpact& o) {
  if (!valid_undercut(o.undercut)) reject("undercut", o.undercut, std::string("expected ") + undercut_expected);
  if (!valid_swing_tilt(o.swing_tilt)) reject("swing_tilt", o.swing_tilt, std::string("expected ") + swing_tilt_expected);
  if (!valid_pitch_spin(o.pitch_spin)) reject("pitch_spin", o.pitch_spin, std::string("expected ") + pitch_spin_expected);
  if (!valid_friction(o.friction)) reject("friction", o.friction, std::string("expected ") + friction_expected);
  if (!(o.grip_stiffness > 0)) reject("grip_stiffness", o.grip_stiffness, "expected a number > 0 or infinity");
  if (!(o.ball_inertia_factor > 0 && o.ball_inertia_factor <= 2.0 / 3))
    reject("ball_inertia_factor", o.ball_inertia_factor, "expected a number in (0, 2/3] (I / m R^2 of a ball)");
}

void validate(const ImpactScene& scene, const ModalBasis& basis) {
  const double length = basis.length();
  if (!lies_on_bat(scene.z, length)) reject_off_bat("z", scene.z, length);
  if (!valid_speed(scene.ball_speed)) reject("ball_speed", scene.ball_speed, std::string("expected ") + speed_expected);
  if (!valid_omega(scene.swing.omega)) reject("omega", scene.swing.omega, std::string("expected ") + omega_expected);
  if (scene.swing.about_center) {
    require_finite("center", scene.swing.center);
    // A centre far off the bat moves the struck point past any batter's speed (-1000 m at
    // 1000 rad/s: 1e6 m/s), which the speeds' own bound would not see.
    if (const double point_speed = scene.swing.omega * (scene.z - scene.swing.center); !valid_speed(point_speed))
      reject("center", scene.swing.center,
             "the swing moves the struck point at " + detail::format_number(point_speed) + " m/s; expected " +
                 speed_expected);
  } else if (!valid_speed(scene.swing.cm_speed))
    reject("cm_speed", scene.swing.cm_speed, std::string("expected ") + speed_expected);
  // The ball's ranges, as a [ball] table and a study's keys take them (ball_tests.hpp).
  if (const auto outside = ball_out_of_range(scene.ball)) reject(outside->key, outside->value, outside->expected());
  if (scene.ball.speed_dependent()) {
    require_finite("cor_slope", scene.ball.cor_slope);
    if (!(scene.ball.cor_speed >= 0 && scene.ball.cor_speed <= max_cor_law_speed))
      reject("cor_speed", scene.ball.cor_speed, "must lie in [0, 100] m/s");
    // The law is e0 and the slope together: an e0 given (--e0 1.0 on mlb's ball) is named too.
    if (const auto misfit = cor_law_misfit(scene.ball)) reject("e0", scene.ball.e0, *misfit);
  }
  require_positive("dt", scene.integrator.dt);
  require_positive("tolerance", scene.integrator.tolerance);
  if (!valid_mode_tolerance(scene.mode_tolerance))
    reject("mode_tolerance", scene.mode_tolerance, std::string("expected ") + mode_tolerance_expected);
  if (scene.step_accuracy != 0) require_positive("step_accuracy", scene.step_accuracy);
  if (scene.checked_step != 0) require_positive("checked_step", scene.checked_step);
  if (!(scene.mode_share_divisor >= 1)) reject("mode_share_divisor", scene.mode_share_divisor, "must be at least 1");
  if (scene.accuracy != 0 && !(scene.accuracy >= min_accuracy && scene.accuracy <= max_accuracy))
    reject("accuracy", scene.accuracy, std::string("must be ") + accuracy_expected);
  require_positive("window", scene.integrator.window);
  if (scene.histories) validate_history(scene.history, length);
  if (scene.pivoted && !scene.swing.about_center)
    reject("pivot", 1, "a pivoted bat is held at its rotation centre: give the centre, not the CM speed");
  if (scene.vibrational_modes != all_modes && scene.vibrational_modes != auto_modes &&
      (scene.vibrational_modes < 0 || scene.vibrational_modes > basis.count() - 2))
    reject("modes", scene.vibrational_modes,
           "must be 'all' or between 0 and " + std::to_string(basis.count() - 2) + " at this slice count");
  validate_oblique(scene.oblique);
}

namespace {

// The rigid bat's part of the geometry: speeds and recoil, from the mass properties alone.
SceneGeometry rigid_geometry(const ImpactScene& scene, const ModalBasis& basis) {
  SceneGeometry g;
  g.z = std::clamp(scene.z, 0.0, basis.length());
  const Swing& swing = scene.swing;
  g.pivot = swing.center;
  g.cm_speed = swing.about_center ? swing.omega * (basis.z_cm - swing.center) : swing.cm_speed;
  g.bat_speed = g.cm_speed + swing.omega * (g.z - basis.z_cm);

  const double m = scene.ball.mass, arm = g.z - basis.z_cm;
  if (scene.pivoted) {
    const double lever = g.z - g.pivot, pivot_arm = g.pivot - basis.z_cm;
    g.recoil = m * lever * lever / (basis.moment_of_inertia_cm + basis.mass * pivot_arm * pivot_arm);
  } else {
    g.recoil = m * (1 / basis.mass + arm * arm / basis.moment_of_inertia_cm);
  }
  return g;
}

}  // namespace

Ball struck_ball(const ImpactScene& scene, const ModalBasis& basis) {
  if (!scene.ball.curved_contact && !scene.ball.speed_dependent()) return scene.ball;
  const SceneGeometry g = rigid_geometry(scene, basis);
  return scene.ball.on_section(basis.section_radius_at(g.z)).anchored_at(scene.ball_speed + g.bat_speed, g.recoil);
}

ModeRequest auto_mode_request(const ImpactScene& scene, const ModalBasis& basis) {
  // Asked before the scene is validated (a caller solves the bat first): a point off the bat (z
  // NaN) has no section to meet, and validation refuses it.
  if (!lies_on_bat(scene.z, basis.length())) return ModeRequest::all();
  const SceneGeometry g = rigid_geometry(scene, basis);
  const double pulse = pulse_duration(struck_ball(scene, basis), scene.ball_speed + g.bat_speed, g.recoil);
  const double reach = scene.pivoted ? held_reach : 1;
  const double omega = reach * auto_solve_factor(auto_mode_tolerance(scene)) * 4 * std::numbers::pi / pulse;
  if (!std::isfinite(omega) || !(omega > 0)) return ModeRequest::all();  // a scene validation will refuse
  // Half-octaves of 1000 rad/s: nearby pulses share one basis.
  return ModeRequest::below(1000 * std::exp2(std::ceil(2 * std::log2(std::max(omega, 1000.0) / 1000)) / 2));
}

ModeRequest impact_mode_request(const ImpactScene& scene, const ModalBasis& rigid) {
  const int modes = scene.vibrational_modes;
  if (modes == auto_modes) return auto_mode_request(scene, rigid);
  if (modes == 0) return ModeRequest::rigid_only();
  if (modes == all_modes) return ModeRequest::all();
  return ModeRequest::lowest(modes);
}

SceneGeometry scene_geometry(const ImpactScene& scene, const ModalBasis& basis) {
  SceneGeometry g = rigid_geometry(scene, basis);
  if (scene.pivoted && scene.vibrational_modes == auto_modes && basis.count() > 2) {
    held_auto_geometry(scene, basis, g);
  } else {
    const Eigen::VectorXd shapes = basis.shapes_at(g.z);
    g.kept = kept_modes(scene, basis, shapes, g);
    const std::vector<int>& kept = g.kept;
    ModalContact free;
    free.omega = basis.omega(kept);
    free.psi = shapes(kept);
    free.velocity0 = g.cm_speed * basis.translation(kept) + scene.swing.omega * basis.rotation(kept);
    free.residual_compliance = g.contact.residual_compliance;
    if (scene.pivoted) {
      // A bat kept rigid is held rigidly, as it is struck (below).
      const double yield = scene.vibrational_modes != 0 ? basis.layout.point(g.pivot).compliance : 0;
      g.contact = held_contact(free, basis.shapes_at(g.pivot)(kept), yield, g.held);
      if (yield > 0) fold_fastest_mode(g.contact, g.held);
    } else {
      g.contact = std::move(free);
    }
  }
  // A flexible bat also yields locally where the ball strikes between the discretisation's nodes
  // (beam_layout.hpp), in series with the ball like the dropped modes; a rigid bat does not.
  if (scene.vibrational_modes != 0) g.contact.residual_compliance += basis.layout.point(g.z).compliance;
  damp_beam_modes(basis.loss_factor, g.contact);
  add_wall_mode(scene, basis, g);
  return g;
}

}  // namespace sweetspot
