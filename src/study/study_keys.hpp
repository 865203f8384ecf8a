#pragma once
// Internal to the study code: the [scene] keys and the outputs of each kind of study, as tables
// that reading (study_reading.cpp), checking (study_checks.cpp) and the grid (study_grid.cpp)
// all look up, so that a key is described, validated and applied in one place.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sweetspot/study/study.hpp"
#include "sweetspot/units/quantity.hpp"

namespace sweetspot::study_detail {

// A set of study kinds, one bit each: which kinds a key or an output belongs to.
using KindSet = unsigned;
constexpr KindSet bit(StudyKind kind) { return 1u << static_cast<unsigned>(kind); }
constexpr KindSet impact = bit(StudyKind::impact), wall = bit(StudyKind::wall), toy = bit(StudyKind::toy),
                  certification = bit(StudyKind::certification);
constexpr KindSet ball_kinds = impact | wall;  // the kinds with the nonlinear ball and its integrator
constexpr KindSet bat_kinds = impact | certification;  // the kinds that strike bats
constexpr KindSet collision_kinds = impact | wall | toy;  // a point is one collision: vf, energies
constexpr KindSet every_kind = collision_kinds | certification;

// The kind as the study file writes it, quoted.
std::string kind_text(StudyKind kind);

// `numbers`: a list of numbers in [scene] (probes), never an axis; `set` takes each in turn.
// `material`: a wood preset's name (bat.material); `bat_parameter`: any other bat parameter.
// `swing`: "given" or "equal_effort"; `reference`: the equal-effort swing's reference bat file.
enum class Type {
  number, integer, boolean, bat, theory, modes, integrator, preset, numbers, material, bat_parameter, swing, reference,
  standard
};

// One key of [scene]: how its value is read, the rule validate() in scene.cpp applies to it, how
// it sets a grid point, and the kinds of study it belongs to and must be given in. Every value
// is a number here (see Axis in study.hpp). A key with a `dimension` also takes a string with a
// unit ("28 in"); its `expected` then names the dimension, and messages add the units.
struct KeySpec {
  std::string_view name;
  Type type;
  std::string_view expected;
  bool (*valid)(double);
  void (*set)(GridPoint&, double);
  KindSet kinds = impact;
  KindSet required = 0;
  bool axis = true;
  std::optional<Dimension> dimension = std::nullopt;
};

// Every [scene] key, in the order of the table of keys.
std::span<const KeySpec> scene_key_specs();
// The key of that name, or nullptr. Every "bat.NAME" finds the one spec of bat parameters (or of
// bat.material): which parameters a bat has is for its design to say (study_checks.cpp).
const KeySpec* find_key(std::string_view name);
// The dimension of the key `name` (spec's, or a bat parameter's from its name), if it has one.
std::optional<Dimension> key_dimension(const KeySpec& spec, std::string_view name);
// The keys of a kind (only those that may be axes, with axes_only), comma-separated for messages.
std::string key_list(StudyKind kind, bool axes_only);
// The keys an uncertainty study may draw: numbers (and bat parameters) a study of this kind takes
// as an axis; and their list, for a refusal.
bool drawable(const KeySpec& k, StudyKind kind);
std::string drawable_key_list(StudyKind kind);

// An output variable (an ImpactResult field), the kinds that give it and those that write it when
// [output] names none. The order of the table is the order of output_names() and default_outputs().
struct OutputSpec {
  std::string_view name;
  KindSet kinds;
  KindSet by_default;
};

std::span<const OutputSpec> output_specs();

}  // namespace sweetspot::study_detail
