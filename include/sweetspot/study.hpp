#pragma once
// A parameter study (design.md): a base impact scene and the axes it is swept over, read from a
// TOML study file and validated in full before a single impact is computed. The grid is the
// product of the axes in the order the file writes them (first axis slowest).
//
// Study file (keys are `sweetspot impact`'s option names with dashes turned into underscores):
//   title = "..."                      optional
//   [scene]  bat (path relative to the study file), theory ("timoshenko" | "euler-bernoulli"),
//            slices (4..4096; default the profile's own), z, ball_speed, e0, ball_mass,
//            ball_radius, k1, a, center | cm_speed (exactly one), omega, pivot (bool),
//            modes (count or "all"), integrator ("rk4"), dt, window
//   [axes]   any [scene] key but integrator, as a list of values (bat: paths; theory: names;
//            pivot: booleans; modes: counts or "all"), or for numbers as a range table
//            { start, stop, step } (stop included when it lands within 1e-9 step) or
//            { start, stop, count } (count points, both ends included). An axis overrides the
//            same key in [scene]; bat, z, ball_speed and the swing must be given in one of them.
//   [output] variables = names of ImpactResult fields (output_names()); default
//            default_outputs(). "mode_energy" adds a mode dimension of length
//            base.vibrational_modes, so it needs one mode count >= 1 for the whole study: modes
//            a number in [scene] (or the default 18), not "all" and not an axis.
//   Every value is checked before any work: types, the rules of validate() in scene.cpp, z on
//   every bat, modes within what every (bat, slices, theory) discretisation has, no repeated
//   axis values, bats with distinct names, at most 1e6 values per axis and 1e9 points.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "sweetspot/modes.hpp"
#include "sweetspot/scene.hpp"

namespace sweetspot {

// The collision integrator. Only classical RK4 (N2000) exists; an enum so that others can join.
enum class Integrator { rk4 };
const char* to_string(Integrator integrator);

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
  // Bat files resolved against the study file's directory, index = bat index (the bat axis's
  // values, or one entry), and the `name` each file gives its bat (the output coordinate).
  std::vector<std::filesystem::path> bats;
  std::vector<std::string> bat_names;
  // The [scene] values over the defaults; axes set their own keys per grid point.
  BeamTheory theory = BeamTheory::timoshenko;
  int slices = 0;  // 0: the profile's own slice count
  Integrator integrator = Integrator::rk4;
  ImpactScene base;
  std::vector<Axis> axes;            // in the order written
  std::vector<std::string> outputs;  // in the order written

  // Number of grid points: the product of the axis sizes (1 without axes).
  std::size_t points() const;
};

// Parses and validates a study file and loads each bat file once; throws InputError with one
// line naming the study file (and line), the key, the value and what was expected.
Study load_study(const std::filesystem::path& file);

// Everything one grid point needs: its scene, which bat, how it is sliced and which beam theory
// makes its modes, and its position on each axis.
struct GridPoint {
  ImpactScene scene;
  std::size_t bat = 0;  // index into Study::bats
  int slices = 0;       // 0: the profile's own
  BeamTheory theory = BeamTheory::timoshenko;
  std::vector<std::size_t> coords;  // one per axis
};

// Grid point `index` in row-major order over the axes (last axis fastest); throws
// std::out_of_range for index >= points().
GridPoint grid_point(const Study& study, std::size_t index);

// The order to compute points in. A point's modal basis depends only on its model, the triple
// (bat, slices, theory), so tasks run model-major: all points of one model in one contiguous
// run of points() / models() tasks, models in row-major order of their axes; within a model,
// row-major over the other axes. A worker's modal cache then meets each model once.
std::size_t models(const Study& study);
std::size_t task_point(const Study& study, std::size_t task);  // grid index of task `task`
std::vector<std::size_t> task_order(const Study& study);       // task_point for every task

// Output variables a study may ask for, and the list used when [output] gives none.
const std::vector<std::string>& output_names();
const std::vector<std::string>& default_outputs();

}  // namespace sweetspot
