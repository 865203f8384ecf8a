#pragma once
// One impact scene (physics.md §4, §6): where the ball hits, the ball, the bat's swing, whether the
// bat is pivoted, which modes are kept and how the collision is integrated.
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"
#include "sweetspot/bat/modes.hpp"

namespace sweetspot {

// The bat's rigid motion at first touch: v_bat(z) = V_cm + Omega (z - z_cm), +y toward the ball.
// Given either by the centre-of-mass speed or by the point at rest (the rotation centre).
struct Swing {
  double omega = 0;           // rad/s
  bool about_center = false;  // true: `center` is at rest; false: `cm_speed` is given
  double cm_speed = 0;        // m/s
  double center = 0;          // m from the knob
};

// What a stated accuracy must be, wherever it is given (a study's key, --accuracy, accuracy=):
// 0 or less would state no error at all, so it is refused rather than read as "not set".
inline constexpr const char* step_accuracy_expected =
    "a finite number > 0 (relative vf error the integration may add)";
// What a stated accuracy chooses itself, by key: given beside it, each would be silently
// overridden, so every surface (command line, study, Python) refuses the pair, in this order.
struct AccuracyExclusion {
  const char* given;
  const char* accuracy;
  const char* chooses;
};
inline constexpr AccuracyExclusion accuracy_exclusions[] = {
    {"dt", "accuracy", "the step"},          {"tolerance", "accuracy", "dopri's tolerance"},
    {"dt", "step_accuracy", "the step"},     {"tolerance", "step_accuracy", "dopri's tolerance"},
    {"step_accuracy", "accuracy", "the step"}, {"mode_tolerance", "accuracy", "the modes' tolerance"},
    {"slices", "accuracy", "the slices"}};
inline constexpr const char* accuracy_expected =
    "a number from 1e-7 to 0.1 (total relative vf error: slicing, modes and step)";
// auto's mode_tolerance, wherever it is given: past 0.1 of v_f a tolerance says nothing (1e300 kept
// no mode on the command line and failed every point of a study), and below round-off neither
// (1e-300 overflowed the finer slicings' requests: a slicing estimate of 0.23 where it is 1.5e-5).
inline constexpr const char* mode_tolerance_expected =
    "a number from 1e-15 to 0.1 (relative vf error allowed the dropped modes)";
inline bool valid_mode_tolerance(double x) { return x >= 1e-15 && x <= 0.1; }

// What a swing's omega must be, wherever it is given (--omega, a study's omega, omega=, an
// optimisation's [player]): v_bat(z) = V_cm + Omega (z - z_cm) with +y toward the ball, so a swing
// turns the barrel toward the ball at Omega >= 0 (N2000's 51 and 56 rad/s; 0 for a bat at rest or
// a push). A negative Omega swings it backwards, away from the pitch: no scene of a bat.
// Past 1000 rad/s (a barrel 1 m from the pivot at 1000 m/s) no swing is a batter's (N2000's 51).
inline constexpr double max_omega = 1000;  // rad/s
inline constexpr const char* omega_expected =
    "a finite angular speed >= 0 and at most 1000 rad/s (the swing turns the barrel toward the ball; a negative omega "
    "swings it backwards)";
inline bool valid_omega(double omega) { return omega >= 0 && omega <= max_omega; }  // NaN fails

// A ball's or a bat's speed, wherever it is given (ball_speed, cm_speed): at most 1000 m/s either
// way, as a flight's launch. Batted balls leave at about 50 m/s and the rules' cannons fire at
// about 60; far past them the ball's force law is no ball's (1e5 m/s returned it at -4 568 m/s).
inline constexpr double max_speed = 1000;  // m/s
inline constexpr const char* speed_expected = "a finite speed from -1000 to 1000 m/s";
inline bool valid_speed(double v) { return std::abs(v) <= max_speed; }  // NaN fails

// An impact in the plane of the swing (docs/oblique.md, oblique_impact.hpp). The plane is the one
// across the bat's axis at the struck point: the bat's point moves along the swing, tilted
// swing_tilt above the horizontal, and the pitch arrives along the same line, against it (a
// swing matched to the pitch's plane). All four zero is the head-on collision of N2000, bit for
// bit; the normal force along the line of centres is its ball law.
struct ObliqueImpact {
  // m: the ball's centre above the bat's axis, across the line of the swing (the bat passes under
  // the ball's centre: backspin and a higher launch); negative below. At or past the sum of the
  // radii the ball misses (status no_contact).
  double undercut = 0;
  double swing_tilt = 0;   // degrees above the horizontal of the bat's velocity (and the pitch's line)
  // rpm of the pitch about the bat's axis, positive for backspin as it flies toward the bat (a
  // fastball's, whose top turns back toward the pitcher): the same turning is topspin on the way out.
  double pitch_spin = 0;
  double friction = 0;     // coefficient of sliding friction between ball and bat, >= 0
  // The ball's tangential stiffness over its normal loading stiffness (tangential_contact.hpp):
  // 2/3 is Mindlin's for nu = 1/2; infinity grips rigidly (slide, then roll: the textbooks' model).
  double grip_stiffness = 2.0 / 3;
  double ball_inertia_factor = 0.4;  // the ball's moment of inertia over m R^2 (a uniform sphere)

  bool head_on() const { return undercut == 0 && swing_tilt == 0 && pitch_spin == 0 && friction == 0; }
};

// What the oblique keys must be, wherever they are given (study keys, impact options, Python).
inline constexpr const char* undercut_expected = "a finite length (the ball's centre above the bat's axis; negative below)";
inline constexpr const char* swing_tilt_expected = "a finite angle in degrees, above -90 and below 90";
// A pitch spins at most about 3500 rpm; 1e5 bounds what the tangential contact can follow (at
// 1e200 rpm the energy balance came out NaN).
inline constexpr double max_pitch_spin = 1e5;  // rpm
inline constexpr const char* pitch_spin_expected =
    "a spin from -1e5 to 1e5 rpm (positive: the pitch's backspin)";
// Ball-bat friction is measured at about 0.2-0.5; past 100 the grip hardly slides (R161's backspin
// within 0.2 % from 100 to 1e6: tests/test_oblique.cpp). 1e20 let the last sliding step before
// separation take mu times a vanishing force for a whole step: the ball left at 8 km/s.
inline constexpr double max_friction = 100;
inline constexpr const char* friction_expected = "a coefficient of friction from 0 to 100";
inline bool valid_undercut(double x) { return std::isfinite(x); }
inline bool valid_swing_tilt(double x) { return std::isfinite(x) && x > -90 && x < 90; }
inline bool valid_pitch_spin(double x) { return std::abs(x) <= max_pitch_spin; }
inline bool valid_friction(double x) { return x >= 0 && x <= max_friction; }  // NaN fails

inline constexpr int all_modes = -1;
// Keep the modes the collision can excite (see mode_selection.hpp), within mode_tolerance.
inline constexpr int auto_modes = -2;

// Points on the bat (z, probes) may lie this far past its ends, relative to its length: the
// length its slice centres give rounds (0.84 m in 5 slices comes to 0.8399999...), and a point
// given at the end must not fall off it. Such points are clamped onto the bat.
inline constexpr double bat_extent_tolerance = 1e-9;
inline bool lies_on_bat(double z, double length) {
  const double slack = bat_extent_tolerance * length;
  return z >= -slack && z <= length + slack;
}

// Bounds a history's steps (history_window / history_step, at most 1e5, i.e. 1e5 + 1 samples
// with both ends), so that a mistyped step cannot exhaust memory.
inline constexpr double max_history_samples = 1e5;

// Time histories of an impact (histories.hpp): where on the bat, and the uniform time grid.
struct HistoryRequest {
  std::vector<double> probes;  // points on the bat, m from the knob
  double window = 3e-3;        // s from first touch
  double step = 5e-6;          // s between samples

  // Steps from 0 to the window: window / step, rounded down unless within 1e-9 of the next
  // whole number (3e-3 / 3e-8 comes to 100000.00000000001 and is 1e5 steps).
  double steps() const { return std::floor(window / step + 1e-9); }
  // Samples from 0 to the window, both ends included when the step divides it.
  std::size_t samples() const { return static_cast<std::size_t>(steps()) + 1; }
};

// The speed at which the rules measure the collision efficiency e_A (batted_ball.hpp): the BBCOR
// and BESR rig's 136 mph (70 mph pitch plus 66 mph bat; NCAA, ASTM F2219).
inline constexpr double lab_e_a_speed = 136 * metres_per_second_per_mph;

struct ImpactScene {
  double z = 0.7;             // impact location, m from the knob (anywhere on the bat)
  Ball ball;
  double ball_speed = 40;     // m/s toward the bat
  Swing swing;
  bool pivoted = false;       // held at swing.center by a constraint force (N2000 Fig. 16)
  int vibrational_modes = auto_modes; // kept vibrational modes, or all_modes, or auto_modes (the default)
  // auto_modes: relative exit-speed error allowed the dropped modes. 1e-4: the shipped bats' own
  // slicing errs 1e-4 to 1e-3, and modes held much tighter resolve the bat finer than its slicing
  // (docs/numerics.md, "Why the default tolerance is 1e-4").
  double mode_tolerance = 1e-4;
  // Relative exit-speed error the integration may add; > 0 chooses the step (or tolerance) from
  // the scene's pulse (step_selection.hpp) instead of integrator.dt. 0: integrator as given.
  double step_accuracy = 0;
  // With step_accuracy and exact stepping: a step already chosen and checked for that accuracy on
  // this scene with the bat cut coarser (SlicingLadder), taken as is, with no model and no check
  // run. 0: chosen here.
  double checked_step = 0;
  // With auto_modes at a stated accuracy: the modes' share is divided by this (>= 1). A rung whose
  // dropped modes took more than their share (a ball the bat's vibration catches again meets them
  // at every contact) runs again with it raised by as much (widened_scene): on a basis solved
  // further (auto_mode_request), keeping every solved mode.
  double mode_share_divisor = 1;
  // The total relative exit-speed error allowed (error_estimates.hpp), > 0 or 0 for none: it
  // shares itself among the sources (accuracy_budget): the modes' share is `auto`'s tolerance,
  // the step's chooses the step, and the slicing's is met by callers that hold the bat's design
  // (simulate_within_accuracy), which cut it finer until it is. Implies error_estimates.
  double accuracy = 0;
  CollisionOptions integrator;
  // The closed forms of physics.md §5 at the same point, computed beside the collision only when
  // asked (a study asks through its outputs), NaN otherwise: the rigid bat's exit speed
  // (vf_rigid) and Van Zandt's prescription (vf_van_zandt), which records the force profile.
  bool rigid_comparison = false;
  bool van_zandt_comparison = false;
  // The rules' linear estimate of the batted-ball speed (batted_ball.hpp), with e_A taken at
  // e_a_speed: another collision, so only when asked.
  bool linear_batted_ball = false;
  double e_a_speed = lab_e_a_speed;
  // Also only when asked, and each records the force profile: the time histories of `history`,
  // the force response g(omega tau) on force_response_grid() (impact.hpp) and R_n per kept
  // vibrational mode (physics.md §5).
  HistoryRequest history;
  bool histories = false;
  bool force_response = false;
  bool mode_response = false;
  // Also only when asked: the time stepping's error (ImpactResult::step_error), from a second
  // collisions at two and four times the step (dopri: 32 and 1024 times the tolerance), about
  // three quarters of an impact more.
  bool error_estimates = false;
  // The impact in the plane of the swing: undercut, tilt, pitch spin and friction.
  ObliqueImpact oblique;
};

// Throws InputError naming the offending scene value (z outside the bat, speeds not finite,
// e0 outside (0, 1], a <= 0, k1 <= 0, dt <= 0, too many modes, pivot without a centre).
void validate(const ImpactScene& scene, const ModalBasis& basis);
// The oblique keys alone (InputError naming undercut, swing_tilt, pitch_spin or friction); a
// miss (an undercut past the radii) is not an error here but the impact's status.
void validate_oblique(const ObliqueImpact& oblique);

// The scene as the collision sees it.
struct SceneGeometry {
  double z = 0;             // impact location, m from the knob
  double pivot = 0;         // held point (pivoted scenes), m from the knob
  double cm_speed = 0;      // V_cm, m/s
  double bat_speed = 0;     // v_bat at the impact point, m/s
  double recoil = 0;        // R0 of the rigid bat, free or pivoted (physics.md §5)
  ModalContact contact;     // kept modes; for a pivoted bat, the modes of the constrained bat
  std::vector<int> modes_kept;  // vibrational mode numbers kept (1 = the first vibrational mode)
  double modes_error = 0;       // auto_modes: estimated vf error of those dropped, over selection_error_scale
  bool drops_solved = false;    // auto_modes: a solved mode (a held one, for a pivoted bat) was dropped
  std::vector<int> kept;        // the basis's modes behind `contact` (0, 1 rigid)
  Eigen::MatrixXd held;         // pivoted: the held bat's modes in the kept ones; empty if free
  // A hollow struck slice's wall mode (barrel_wall.hpp), the contact's last mode; -1 for none.
  int wall = -1;
  double hoop_frequency = std::numeric_limits<double>::quiet_NaN();  // Hz of the struck slice's wall
  double barrel_compression = std::numeric_limits<double>::quiet_NaN();  // N at 0.04 in, the same wall's
  // The wall's point-load shape 1 / sqrt(m_w) and the contact's residual compliance without the
  // wall's other harmonics: what a patch-loaded wall (impact.cpp) scales and adds to.
  double wall_point_shape = 0;
  double beam_compliance = 0;
  // The patch the collision used (phi_2 and the harmonics' compliance) and the effective
  // compression it was taken at (NaN for a point load or no wall).
  PatchLoad wall_patch;
  double wall_compression = std::numeric_limits<double>::quiet_NaN();

  // The shapes of the contact's modes at any point z of the bat (ModalBasis::shapes_at).
  Eigen::VectorXd shapes_at(const ModalBasis& basis, double z) const;
};

// `basis` may be partial (ModeRequest): auto then counts the unsolved modes' compliance exactly
// and bounds what dropping them costs (mode_selection.hpp); fixed counts and "all" read the
// solved modes, so a study's cache solves at least as many as they ask.
SceneGeometry scene_geometry(const ImpactScene& scene, const ModalBasis& basis);

// The scene's ball as it meets the struck section (Ball): k1 on that section's curvature, e0 the
// COR of the energy a rigid bat of the same recoil would have it store. The scene's own ball when
// it has neither curved contact nor a speed-dependent COR (N2000's ball: no copy, no change).
Ball struck_ball(const ImpactScene& scene, const ModalBasis& basis);

// A bat held at a pivot is struck in its held modes, made from the free ones solved; they converge
// more slowly (the pivot's constraint force excites every free mode), so a held scene solves the
// free modes this many times as far. R161 on the rig (136 mph, N2000's ball, auto's default
// tolerance, the unsolved modes' compliance at the pivot counted: scene.cpp), against every mode
// from 20 to 80 cm: over auto's own reach v_f errs up to 24x its estimate at 168 slices; over twice
// it, 6.3x at 672 slices; over four times, within 2.1x (certify's partial basis: certification.cpp).
inline constexpr double held_reach = 4;

// The modes modes = "auto" needs solved at this scene: every one below
// auto_solve_factor(mode_tolerance) times the rigid-bat pulse's reach 4 pi / T (held_reach times
// that for a held bat), rounded up to a half-octave of 1000 rad/s. `basis` gives the mass
// properties only (a rigid-only basis will do).
ModeRequest auto_mode_request(const ImpactScene& scene, const ModalBasis& basis);

// What one impact solves for, by scene.vibrational_modes: the rigid modes alone for 0, every mode
// for all_modes, the lowest k for a count k, auto_mode_request for auto_modes. `rigid` gives the
// mass properties only (a rigid-only basis will do). The program's `impact` and the Python module
// both ask this, so that they solve the same basis and give the same result bit for bit.
ModeRequest impact_mode_request(const ImpactScene& scene, const ModalBasis& rigid);

}  // namespace sweetspot
