#pragma once
// Internal to the study code: a study file's settings as read (each [scene] key and axis with
// where it was written), the one-line messages that name that place, and the steps of
// load_study: reading (study_reading.cpp) and the checks across keys (study_checks.cpp).
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "study_keys.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot::study_detail {

namespace fs = std::filesystem;

constexpr int default_modes = ImpactScene{}.vibrational_modes;

// Where a value sits in the study file; line 0 when it has none to show.
struct Where {
  const fs::path* file;
  std::string key;
  std::size_t line = 0;

  Where child(std::string_view name, const toml::node& node) const {
    return {file, key.empty() ? std::string(name) : key + "." + std::string(name), node.source().begin.line};
  }
  Where item(std::size_t i, const toml::node& node) const {
    return {file, key + "[" + std::to_string(i) + "]", node.source().begin.line};
  }
  // A key that is not there: shown at its table's line, if that has one.
  Where missing(std::string_view name) const {
    return {file, key.empty() ? std::string(name) : key + "." + std::string(name), line};
  }
};

// Throws InputError "file:line: key 'axes.z.step' = 0: expected ..."; `value` empty: the key is
// missing. Every message is one line, so the program prints it as is.
[[noreturn]] void reject(const Where& at, const std::string& value, const std::string& expected);

// A scene key as the study gives it: the one value in [scene] or the values of its axis.
struct Setting {
  const KeySpec* spec;
  Where where;
  std::vector<double> values;
  std::vector<std::string> labels;  // bat, theory and bat.material only
  std::string name = std::string(spec->name);  // the key as written ("z", "bat.barrel_diameter")
  // Each value as the file wrote it ("71.12 cm" for z = 0.7112; a range's values as numbers), for
  // messages: a user finds "71.12 cm" in the file, not the SI value it stands for.
  std::vector<std::string> written = {};

  // Value i as a message shows it: the name quoted, else as written.
  std::string value_text(std::size_t i) const;
};

const Setting* find(const std::vector<Setting>& settings, std::string_view name);

// The settings in force: an axis overrides the same key in [scene]. An uncertainty study's
// drawn keys (`samples`, each with a value per sample, all moving together along the sample
// axis) are neither, and no key is both drawn and set.
struct Settings {
  std::vector<Setting> scene, axes, samples = {};
  const Setting* operator[](std::string_view name) const {
    if (const Setting* drawn = find(samples, name)) return drawn;
    const Setting* axis = find(axes, name);
    return axis ? axis : find(scene, name);
  }
  std::vector<double> values(std::string_view name, double fallback) const {
    const Setting* s = (*this)[name];
    return s ? s->values : std::vector<double>{fallback};
  }
};

// The mode count a study keeps unless it says: "auto", or N2000's 18 under preset = "n2000".
double default_mode_count(const Settings& s);

// ---- Reading (study_reading.cpp) ----
// The text of a study (or, `what`, an optimisation) file; InputError when it cannot be read.
std::string read_text(const fs::path& file, std::string_view what = "study file");
toml::table parse_toml(const fs::path& file, const std::string& text);
// Unknown keys are errors: a misspelt optional key would otherwise be silently ignored.
void reject_unknown(const Where& at, const toml::table& table, std::initializer_list<std::string_view> known);
StudyKind read_kind(const Where& top, const toml::table& doc);
// The keys of [scene] or [axes] (`section`), in the order written.
std::vector<Setting> read_settings(const Where& top, const toml::table& doc, std::string_view section, StudyKind kind);
std::vector<std::string> read_outputs(const Where& top, const toml::table& doc, const Settings& s, StudyKind kind);
// [output]'s sweet_spot_fraction and sweet_spot_of beside no sweet_spot_* output: refused, not ignored.
void check_sweet_spot_keys_read(const Where& top, const toml::table& doc, const std::vector<std::string>& outputs);
double read_sweet_spot_fraction(const Where& top, const toml::table& doc);
// [output] sweet_spot_of: "vf" (the default) or "distance".
std::string read_sweet_spot_of(const Where& top, const toml::table& doc);

// ---- Checks across keys (study_checks.cpp) ----
// Keys that only some outputs read (the air: the flight's; probes: the histories'; e_a_speed:
// bbs_linear's), given in a study that asks none of those outputs: refused, not ignored.
void check_output_keys_read(const Settings& s, const Study& study);
void check_grid_size(const Settings& s, const Where& top);
void check_required(const Settings& s, const Where& top, StudyKind kind);
// The wall stands still, so only a ball moving toward it (speed > 0) ever touches it.
void check_wall_speeds(const Settings& s);
// dopri alone reads `tolerance`, modes = "auto" alone `mode_tolerance`: beside no point that reads
// it, either is refused.
void check_unread_keys(const Settings& s);
void check_history_samples(const Settings& s);
// The impact kind's checks across keys: the swing, the bat files (loaded into `study`), z on
// every bat, mode counts, Euler-Bernoulli's slices, RK4's stability.
void check_bat_scene(Study& study, const Settings& s, const Where& top);

}  // namespace sweetspot::study_detail
