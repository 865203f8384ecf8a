#pragma once
// A parameter study (design.md): a base scene and the axes it is swept over, read from a TOML
// study file and validated in full before a single collision is computed. The grid is the
// product of the axes in the order the file writes them (first axis slowest).
//
// Study file (keys are `sweetspot impact`'s option names with dashes turned into underscores):
//   title = "..."                      optional
//   kind = "impact" | "wall" | "toy"   optional, default "impact": what the ball strikes
//     impact: a bat (N2000 §4-5). wall: a rigid, immovable wall (Fig. 3). toy: the two-mass
//     model of App. A (Fig. 18). Each kind takes its own keys and outputs (below); any other is
//     an error that says it does not apply to the kind.
//   [scene]  impact: bat (path relative to the study file), theory ("timoshenko" |
//              "euler-bernoulli"), slices (4..4096; default the profile's own), z, ball_speed, e0,
//              ball_mass, ball_radius, k1, a, center | cm_speed (exactly one), omega, pivot
//              (bool), modes (count, "all" or "auto" (default)), probes (a list of points on the
//              bat, m from the knob), history_window (s, default 3e-3), history_step (s, default
//              5e-6; at most 1e5 samples), integrator ("exact" (default), "rk4", "dopri"), dt
//            (default: the integrator's own), tolerance (dopri), window, preset ("n2000": RK4 at
//            5 us with 18 modes wherever the study does not say otherwise; never an axis)
//            wall: ball_speed (> 0), e0, ball_mass, ball_radius, k1, a, integrator, dt, tolerance,
//            window, preset, history_window, history_step
//            toy: omega_tau (> 0)
//            impact also: "bat.PARAMETER" (quoted), a parameter of every bat (bat_design.hpp)
//   [axes]   any [scene] key of the kind but integrator, preset and the histories' keys, as a
//            list of values (bat: paths; theory: names; pivot: booleans; modes: counts, "all" or
//            "auto"; "bat.material": wood presets; "bat.PARAMETER": numbers, one bat per
//            combination), or for numbers as a range table
//            { start, stop, step } (stop included when it lands within 1e-9 step) or
//            { start, stop, count } (count points, both ends included), the latter with
//            spacing = "log" for points spaced evenly in the logarithm (start, stop > 0). An axis
//            overrides the same key in [scene]. Required in one of them: impact: bat, z,
//            ball_speed and the swing; wall: ball_speed; toy: omega_tau.
//   [output] variables = names of ImpactResult fields the kind gives (output_names(kind));
//            default default_outputs(kind). impact: vf, e_eff, contact_time, collision_time and
//            status by default; vf_rigid and vf_van_zandt (the rigid bat's and Van Zandt's exit
//            speeds at the same point) are computed only when named; e_a (the collision
//            efficiency) and, for studies whose every point is pivoted, bbcor, besr and bpf (the
//            bat-test rig's measures, rig_measures.hpp) likewise; wall: vf, e_eff (the
//            restitution), contact_time, collision_time, u_max, peak_force, impulse, status,
//            the energies of the ball (initial, ball, ball_dissipated, residual) and the
//            histories force, compression and ball_position; toy: vf
//            (v_f / v_i), vf_van_zandt, status and the energies initial, ball,
//            bat_translation, vibration, residual (model units, m = k = v_i = 1).
//            sweet_spot_z, sweet_spot_vf, sweet_spot_width: v_f reduced along a z axis of at least
//            3 points (sweet_spot.hpp), over the other axes; vf is then stored too.
//            sweet_spot_fraction (default 0.01): how near the peak v_f the sweet spot's zone is.
//            sweet_spot_of (default "vf"): "distance" reduces the flight's carry instead, which
//            is then stored too.
//            Always, over the bat dimensions: what a designer checks of each bat (bat_properties.hpp).
//            "mode_energy" adds a mode dimension of length base.vibrational_modes, so it needs
//            one mode count >= 1 for the whole study: modes a number in [scene] (or 18 under
//            preset = "n2000"), not "all", not "auto" and not an axis; so does "mode_response" (R_n per kept vibrational
//            mode, physics.md §5). Time histories, only when asked (histories.hpp):
//            displacement, velocity, acceleration and vibration_* of each of them at the points
//            `probes` (needed; with more than one a `probe` dimension), and force, compression,
//            ball_position, each over a `time` dimension from first touch to history_window
//            every history_step; force_response = g(omega tau) over an `omega_tau` dimension
//            (0 to 20 by 0.1, tau = the point's collision_time).
//            Failed points give NaN.
//   Every value is checked before any work: types, the rules of validate() in scene.cpp, z and
//   probes on every bat, modes within what every (bat, slices, theory) discretisation has, no repeated
//   axis values, bats with distinct names, at most 1e6 values per axis and 1e9 points, 5e-9 s <= dt <= 1e-3 s
//   (finest_step, coarsest_step), RK4 stable for every kept mode at every step unless accuracy is given, and
//   results that fit in the machine's memory (study_memory.hpp).
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "sweetspot/flight/air.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/equal_effort.hpp"
#include "sweetspot/impact/scene.hpp"

namespace sweetspot {

// What the ball strikes: a bat, a rigid immovable wall, the toy model's two masses, or each bat
// in the virtual test rig of a certification standard (certification.hpp).
enum class StudyKind { impact, wall, toy, certification };
const char* to_string(StudyKind kind);

// Impact and certification studies strike bats; the others have no bats, no modes and no bat
// dimension.
constexpr bool has_bat(StudyKind kind) { return kind == StudyKind::impact || kind == StudyKind::certification; }
// Only an impact point strikes the bat once with the study's modes: a certification point scans
// its bat in the rig and solves its own.
constexpr bool needs_modal_basis(StudyKind kind) { return kind == StudyKind::impact; }


// One swept scene key. `values` holds a number for every kind of axis: the value itself, 0/1 for
// pivot, the count for modes (all_modes for "all"), and for the named keys an index: bat into
// Study::bats, theory in BeamTheory's order. `labels` holds those names as written (bat, theory)
// and is empty for the other axes.
struct Axis {
  std::string name;  // the scene key: "z", "ball_speed", "bat", ...
  std::vector<double> values;
  std::vector<std::string> labels;

  std::size_t size() const { return values.size(); }
};

struct Study {
  std::filesystem::path file;  // the study file, as given
  std::string text;            // its full text, for the dataset's attributes
  std::string title;           // empty when the file has none
  StudyKind kind = StudyKind::impact;
  // Bat files resolved against the study file's directory, index = bat index (the bat axis's
  // values, or one entry), and the `name` each file gives its bat (the output coordinate). Both
  // empty for the kinds without a bat.
  std::vector<std::filesystem::path> bats;
  std::vector<std::string> bat_names;
  // Each bat file's design as read when the study was loaded, with [scene]'s bat parameters set,
  // and the texts it was read from: the dataset stores the texts.
  std::vector<BatDesign> bat_designs;
  std::vector<BatSource> bat_sources;
  // Every bat the points strike, built and checked when the study was loaded: one per
  // combination of the bat dimensions (design_axes), row-major over them, so every rank computes
  // with these. Without bat-parameter axes, one per bat file.
  std::vector<Bat> designs;
  std::vector<MassProperties> design_mass;  // the exact mass properties of each design
  std::vector<BatDesign> design_specs;      // each design as parameters: what certification takes
  // swing = "equal_effort": every bat's swing scales from the base scene's, the player's swing
  // with the reference bat, by its MOI about the knob (equal_effort.hpp).
  bool equal_effort = false;
  BatSource reference_source;  // the reference bat's files and texts (a run's inputs too)
  double reference_moi = 0;    // kg m^2 about the knob, exact for its design
  // The [scene] values over the defaults; axes set their own keys per grid point.
  BeamTheory theory = BeamTheory::timoshenko;
  int slices = 0;  // 0: the profile's own slice count
  ImpactScene base;                  // impact; wall: its ball, ball_speed and integrator
  double omega_tau = 0;              // toy
  double swing_exponent = default_swing_exponent;  // equal effort, unless an axis
  Air air;                                         // the batted ball's, unless an axis
  bool flight = false;                             // a flight output is asked
  std::size_t standard = 0;                        // certification: its standard, and the rig's
  double rig_e0 = std::numeric_limits<double>::quiet_NaN();          // e0 and ball speed where
  double rig_ball_speed = std::numeric_limits<double>::quiet_NaN();  // the study overrides them
  bool rig_ball = false;  // a [ball] table: certification fires base.ball, not the standard's
  std::vector<Axis> axes;            // in the order written
  std::vector<std::string> outputs;  // in the order written
  double sweet_spot_fraction = 0.01;  // [output]: the sweet spot's zone is within this of the peak vf
  std::string sweet_spot_of = "vf";   // [output]: what the sweet spot reduces: "vf" or "distance"
  // An uncertainty study (sweetspot/uncertainty/): the keys drawn from distributions, each with
  // its value in every sample (labels empty). The study's first axis is then `sample` (0, 1, ...),
  // along which they all move together; empty for any other study.
  std::vector<Axis> sampled;
  bool sampled_designs = false;  // a sampled key is a bat parameter: one bat per sample

  // Number of grid points: the product of the axis sizes (1 without axes).
  std::size_t points() const;
};

// Parses and validates a study file and loads each bat file once; throws InputError with one
// line naming the study file (and line), the key, the value and what was expected.
Study load_study(const std::filesystem::path& file);

// The draws of an uncertainty study, made by its sampler (sweetspot/uncertainty/) from the
// file's [uncertain] and [sampling] tables: what each sample computes (`model`), and per drawn
// key its value in every sample and the line of the file that gives its distribution.
struct SampledKeys {
  StudyKind model = StudyKind::impact;
  std::size_t samples = 0;
  std::vector<Axis> keys;
  std::vector<std::size_t> lines;
};
// The name of the axis the samples run along.
inline constexpr std::string_view sample_axis = "sample";
// Loads the study `text` (read from `file`) with the drawn keys set per sample: its scene and
// [axes] as any study of kind `sampled.model` (no axis may make bats: bat, bat.PARAMETER, slices,
// theory), every drawn value checked as the key's own values are (InputError naming the key, the
// sample and the value), a bat built and checked per sample when a bat parameter is drawn.
Study load_sampled_study(const std::filesystem::path& file, std::string text, const SampledKeys& sampled);

// Everything one grid point needs: its kind and scene (the ball, speed and integrator serve the
// wall too), for a bat which one, how it is sliced and which beam theory makes its modes, for the
// toy omega tau, and its position on each axis.
struct GridPoint {
  StudyKind kind = StudyKind::impact;
  ImpactScene scene;
  double omega_tau = 0;
  std::size_t bat = 0;     // index into Study::bats
  std::size_t design = 0;  // index into Study::designs
  double swing_exponent = default_swing_exponent;  // equal-effort swings: n in v ~ I^-n
  // certification: the standard (index into standards()) and the rig's e0 and ball speed where
  // the study overrides the standard's (NaN: the standard's); the design certified.
  std::size_t standard = 0;
  double rig_e0 = std::numeric_limits<double>::quiet_NaN();
  double rig_ball_speed = std::numeric_limits<double>::quiet_NaN();
  bool rig_ball = false;  // the study's [ball] (scene.ball) in place of the standard's
  const BatDesign* design_spec = nullptr;
  int slices = 0;       // 0: the profile's own
  BeamTheory theory = BeamTheory::timoshenko;
  // The batted ball's flight from the impact's launch (flight.hpp), computed only when a flight
  // output is asked, in this air.
  bool flight = false;
  Air air;
  std::vector<std::size_t> coords;  // one per axis
};

// Bat-parameter axes are named "bat." followed by the parameter ("bat.barrel_diameter",
// "bat.density"; "bat.material" takes preset names): bat_design.hpp.
inline constexpr std::string_view bat_parameter_prefix = "bat.";
bool is_bat_parameter(std::string_view axis_name);

// The name an axis has in the dataset: its key with every '.' an '_' ("bat.length" is
// `bat_length`), since CF names are letters, digits and underscores and a dotted name cannot be a
// keyword (ds.sel(bat_length=0.84)). The study file keeps the key as written.
std::string dataset_name(std::string_view axis_name);

// The dimensions over which bats differ, as indices into Study::axes: the bat axis (if any)
// first, then every bat-parameter axis in the order written. Study::designs is row-major over
// them; the dataset stores what a designer checks of each bat (mass, balance, MOI, frequencies)
// over them.
std::vector<std::size_t> design_axes(const Study& study);
// The design of a point with these coordinates (one per axis).
std::size_t design_index(const Study& study, const std::vector<std::size_t>& coords);


// Grid point `index` in row-major order over the axes (last axis fastest); throws
// std::out_of_range for index >= points().
GridPoint grid_point(const Study& study, std::size_t index);

// The order to compute points in. A point's modal basis depends only on its model, the triple
// (design, slices, theory), so tasks run model-major: all points of one model in one contiguous
// run of points() / models() tasks, models in row-major order of their axes; within a model,
// row-major over the other axes. A worker's modal cache then meets each model once.
std::size_t models(const Study& study);
std::size_t task_point(const Study& study, std::size_t task);  // grid index of task `task`
std::vector<std::size_t> task_order(const Study& study);       // task_point for every task

// Outputs that are time histories at the probes (displacement, velocity, acceleration and their
// vibration parts), and those plus the histories of the impact itself (force, compression,
// ball_position): all add a `time` dimension.
bool is_probe_history(std::string_view name);
bool is_history(std::string_view name);

// The [scene] keys of a kind, in the order of the table of keys (the study file's names).
std::vector<std::string> scene_keys(StudyKind kind);

// Output variables a study of a kind may ask for, and the list used when [output] gives none.
const std::vector<std::string>& output_names(StudyKind kind = StudyKind::impact);
const std::vector<std::string>& default_outputs(StudyKind kind = StudyKind::impact);

}  // namespace sweetspot
