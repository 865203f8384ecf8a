#pragma once
// A design optimisation (README "Design optimisation"): a base bat of named dimensions, the
// parameters left free with their bounds, the player who swings it, what to maximise and the
// rules' constraints. Read from an optimisation file by load_optimization, every value checked
// before any work; no I/O beyond that reading.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/impact/scene.hpp"
#include "sweetspot/impact/standards.hpp"

namespace sweetspot {

// One dimension (or material constant) of the base bat that the optimiser may change.
struct FreeParameter {
  std::string name;  // a design parameter ("barrel_diameter", "density", ...), no "bat." prefix
  double lower = 0, upper = 0;  // bounds, lower < upper
  double start = 0;             // where the search starts: the base bat's value unless given
};

// Who swings the bat and at what: the swing measured with the reference bat, scaled to each
// design by equal effort (equal_effort.hpp) unless the swing is taken as given.
struct Player {
  Swing swing;
  bool equal_effort = true;
  double reference_moi = 0;  // kg m^2, the reference bat's exact MOI about the knob
  double swing_exponent = 0;
  double ball_speed = 0;     // m/s, the pitch
  Ball ball;                 // the pitched ball: the file's [ball] (N2000's by default), [player] e0 over it
  ObliqueImpact oblique;     // undercut, swing tilt, pitch spin and friction (head-on by default)
};

enum class ObjectiveKind {
  peak_bbs,          // the largest batted-ball speed over the z scan, located between scan points
  sweet_spot_width,  // the length of the zone where the speed stays within `fraction` of its peak
  mean_bbs,          // the speed averaged over the player's spread of impact points
  peak_distance      // the longest carry of the batted ball over the z scan (the calculator's air)
};
const char* to_string(ObjectiveKind kind);

struct ObjectiveSpec {
  ObjectiveKind kind = ObjectiveKind::peak_bbs;
  double z_from = 0, z_to = 0, z_step = 0;  // the scan (peak_bbs, sweet_spot_width), m from the knob
  double fraction = 0.01;                   // sweet_spot_width
  double tolerance = 1e-5;                  // peak_bbs: where the peak is, m
  std::vector<double> z, weights;           // mean_bbs: impact points and their weights (sum 1)
};

// What a constraint bounds: the standard's measure at its maximum over the barrel, or a number
// of the designed shape (exact, design_mass_properties).
enum class Quantity { measure, barrel_diameter, drop, mass, moi_knob, moi_pivot, length };
const char* to_string(Quantity quantity);

// value <= limit (upper) or value >= limit (lower). The optimiser sees it scaled by |limit|, and
// a design meets it when it errs by at most `tolerance` of |limit|.
struct Constraint {
  Quantity quantity = Quantity::mass;
  std::string name;  // the quantity's name, the measure's own for the rig's ("bbcor")
  bool upper = true;
  double limit = 0;
  std::string label() const;  // "bbcor_max", "mass_min", ...
};

enum class Algorithm {
  cobyla,  // NLopt's COBYLA: constraints handled directly
  bobyqa,  // NLopt's augmented Lagrangian around BOBYQA
  mlsl     // global: the augmented Lagrangian around MLSL (low-discrepancy starts) with BOBYQA
};
const char* to_string(Algorithm algorithm);

struct OptimizerSettings {
  Algorithm algorithm = Algorithm::cobyla;
  int max_evaluations = 200;
  double xtol_rel = 1e-6;             // of the free parameters scaled to [0, 1]
  double initial_step = 0.1;          // of each parameter's range
  double constraint_tolerance = 1e-6; // relative to each limit
  std::uint32_t seed = 1;             // NLopt's random numbers (mlsl), fixed so that runs repeat
};

// How every design is cut and solved, and its impacts integrated.
struct ModelSettings {
  int vibrational_modes = auto_modes;  // 0 makes every design a rigid bat
  int slices = 0;                      // 0: the design's own
  BeamTheory theory = BeamTheory::timoshenko;
  // A stated total accuracy (error_estimates.hpp), 0 for none: every impact and rig hit takes its
  // modes' and step's shares, and each design is cut at its slices N, 2N, 4N ... until the
  // objective's and the measure's Richardson estimates meet the slicing's. Excludes `slices`
  // and a fixed mode count.
  double accuracy = 0;
};

struct OptimizationProblem {
  std::filesystem::path file;  // the optimisation file
  std::string text;            // its text byte for byte
  std::string title;
  BatDesign base;
  BatSource base_source, reference_source;
  std::vector<FreeParameter> free;
  Player player;
  ObjectiveSpec objective;
  std::vector<Constraint> constraints;
  // The standard whose measure a `measure` constraint bounds, and its rig.
  Standard standard;
  CertifyOptions rig;
  ModelSettings model;
  OptimizerSettings optimizer;
};

// At most this many free parameters: every corner of their box is checked to be a possible bat.
inline constexpr std::size_t max_free_parameters = 12;
inline constexpr int max_optimizer_evaluations = 100000;

// Reads and checks an optimisation file; throws InputError (one line: the file, the key, the
// value and what was expected) for anything wrong, including bounds whose box holds an
// impossible bat (every corner is built and checked: the rules are linear in the dimensions, so
// a box whose corners are possible bats holds only possible bats).
OptimizationProblem load_optimization(const std::filesystem::path& file);

// The base design with the free parameters set to x (in the order of problem.free).
BatDesign design_at(const OptimizationProblem& problem, const std::vector<double>& x);

}  // namespace sweetspot
