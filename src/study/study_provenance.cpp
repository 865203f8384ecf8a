#include "sweetspot/study/study_provenance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sweetspot/impact/standards.hpp"
#include "sweetspot/version.hpp"

namespace sweetspot {

namespace {

// An axis's values, and an uncertainty study's drawn values, are variables of their own: such a
// key has no one value to state as an attribute.
bool is_axis(const Study& study, const std::string& key) {
  const auto named = [&](const Axis& axis) { return axis.name == key; };
  return std::ranges::any_of(study.axes, named) || std::ranges::any_of(study.sampled, named);
}

// Global attributes named scene_KEY, typed as the key is: numbers as doubles, counts and
// booleans as integers, names as text.
struct SceneAttributes {
  Dataset& d;
  void number(const std::string& key, double x) { d.number_attributes.push_back({"scene_" + key, x}); }
  void integer(const std::string& key, int x) { d.int_attributes.push_back({"scene_" + key, {x}}); }
  void text(const std::string& key, const std::string& x) { d.text_attributes.push_back({"scene_" + key, x}); }
};

// A count of modes, or the word that stands for the count ("all", "auto").
void add_modes(SceneAttributes& out, int modes) {
  if (modes == all_modes) return out.text("modes", "all");
  if (modes == auto_modes) return out.text("modes", "auto");
  out.integer("modes", modes);
}

// One key of [scene] with the value the run used for it (the study's, else the default). Keys
// that only the other kinds of study read are never asked of an impact study, and so on.
void add_scene_key(const Study& study, const std::string& key, SceneAttributes& out) {
  const ImpactScene& s = study.base;
  if (key == "bat" || key == "slices") return;  // the bat_* variables: files and slices per bat
  if (key == "preset") return;  // what it sets is in the scene_* keys (integrator, dt, modes)
  if (key == "theory") return out.text(key, to_string(study.theory));
  if (key == "z") return out.number(key, s.z);
  if (key == "ball_speed") return out.number(key, s.ball_speed);
  if (key == "e0") return out.number(key, s.ball.e0);
  if (key == "ball_mass") return out.number(key, s.ball.mass);
  if (key == "ball_radius") return out.number(key, s.ball.radius);
  if (key == "k1") return out.number(key, s.ball.k1);
  if (key == "a") return out.number(key, s.ball.a);
  if (key == "cor_slope") return out.number(key, s.ball.cor_slope);
  if (key == "cor_speed") return out.number(key, s.ball.cor_speed);
  if (key == "curved_contact") return out.integer(key, s.ball.curved_contact ? 1 : 0);
  // The swing is given one way: the other key has no value to show.
  if (key == "center") return s.swing.about_center ? out.number(key, s.swing.center) : void();
  if (key == "cm_speed") return s.swing.about_center ? void() : out.number(key, s.swing.cm_speed);
  if (key == "omega") return out.number(key, s.swing.omega);
  if (key == "pivot") return out.integer(key, s.pivoted ? 1 : 0);
  if (key == "swing") return out.text(key, study.equal_effort ? "equal_effort" : "given");
  // The swing's reference: its file (its text is reference_bat_toml) and the exponent, with equal effort.
  if (key == "reference_bat")
    return study.equal_effort ? out.text(key, study.reference_source.toml_file.string()) : void();
  if (key == "swing_exponent") return study.equal_effort ? out.number(key, study.swing_exponent) : void();
  if (key == "e_a_speed") return out.number(key, s.e_a_speed);
  if (key == "undercut") return out.number(key, s.oblique.undercut);
  if (key == "swing_tilt") return out.number(key, s.oblique.swing_tilt);
  if (key == "temperature") return out.number(key, study.air.temperature);
  if (key == "pressure") return out.number(key, study.air.pressure);
  if (key == "altitude") return out.number(key, study.air.elevation);
  if (key == "humidity") return out.number(key, 100 * study.air.relative_humidity);
  if (key == "wind_speed") return out.number(key, study.air.wind_speed);
  if (key == "wind_direction") return out.number(key, study.air.wind_direction);
  if (key == "pitch_spin") return out.number(key, s.oblique.pitch_spin);
  if (key == "friction") return out.number(key, s.oblique.friction);
  if (key == "standard") return out.text(key, standards()[study.standard].name);
  // The rig's ball: the standard's, unless the study gives its own.
  if (key == "rig_e0") return std::isnan(study.rig_e0) ? void() : out.number(key, study.rig_e0);
  if (key == "rig_ball_speed") return std::isnan(study.rig_ball_speed) ? void() : out.number(key, study.rig_ball_speed);
  if (key == "modes") return add_modes(out, s.vibrational_modes);
  if (key == "mode_tolerance") return out.number(key, s.mode_tolerance);
  if (key == "accuracy") return out.number(key, s.accuracy);  // 0: none stated
  if (key == "step_accuracy") return out.number(key, s.step_accuracy);  // 0: the step as given (dt)
  if (key == "integrator") return out.text(key, to_string(s.integrator.method));
  if (key == "tolerance") return out.number(key, s.integrator.tolerance);
  if (key == "dt") return out.number(key, s.integrator.dt);
  if (key == "window") return out.number(key, s.integrator.window);
  if (key == "probes") {
    if (!s.history.probes.empty()) out.d.number_list_attributes.push_back({"scene_probes", s.history.probes});
    return;
  }
  if (key == "history_window") return out.number(key, s.history.window);
  if (key == "history_step") return out.number(key, s.history.step);
  if (key == "omega_tau") return out.number(key, study.omega_tau);
  // A key added to the study without a line here would silently go missing from every dataset.
  throw std::logic_error("no dataset attribute for the scene key '" + key + "'");
}

// An axis's values are its coordinate: only the keys that are not axes are attributes.
void add_scene(const Study& study, Dataset& d) {
  SceneAttributes out{d};
  for (const std::string& key : scene_keys(study.kind))
    if (!is_axis(study, key)) add_scene_key(study, key, out);
}

// Per bat file: over the bat axis, or scalars when the study has one bat file (and no bat axis).
std::vector<std::string> bat_dims(const Study& study) {
  if (is_axis(study, "bat")) return {"bat"};
  return {};
}

Variable bat_texts(const Study& study, const std::string& name, const std::string& long_name,
                   std::vector<std::string> texts) {
  return {name, "", long_name, bat_dims(study), std::move(texts), {}, {}};
}

void add_bats(const Study& study, Dataset& d) {
  std::vector<std::string> files, tomls, profile_files, profiles;
  std::vector<std::int32_t> slices;
  for (std::size_t b = 0; b < study.bat_sources.size(); ++b) {
    const BatSource& source = study.bat_sources[b];
    files.push_back(source.toml_file.string());
    tomls.push_back(source.toml_text);
    profile_files.push_back(source.profile_file.string());
    profiles.push_back(source.profile_text);
    // The file's first design: bat parameters do not change how a profile is cut.
    const Bat& first = study.designs[b * (study.designs.size() / study.bat_sources.size())];
    slices.push_back(study.slices > 0 ? study.slices : first.slices());
  }
  // The bat's name: the bat axis's coordinate, or this scalar beside a study's one bat.
  if (!is_axis(study, "bat")) d.variables.push_back(bat_texts(study, "bat", "bat", study.bat_names));
  d.variables.push_back(bat_texts(study, "bat_file", "bat file, as the run read it", std::move(files)));
  d.variables.push_back(bat_texts(study, "bat_toml", "text of the bat file", std::move(tomls)));
  d.variables.push_back(bat_texts(study, "bat_profile_file", "profile of the bat, as the run read it",
                                  std::move(profile_files)));
  d.variables.push_back(bat_texts(study, "bat_profile", "text of the bat's profile", std::move(profiles)));
  // With a slices axis, the points take the axis's counts; the frequencies still take these.
  d.variables.push_back({"bat_slices", "1", "slices the bat is cut into (the profile's own unless the study sets slices)",
                         bat_dims(study), std::move(slices), {}, {}});
}

void add_run(const RunInfo& info, Dataset& d) {
  d.int_attributes.push_back({"mpi_ranks", {info.ranks}});
  d.int_attributes.push_back({"omp_threads", {info.threads}});
  d.number_attributes.push_back({"wall_time_s", info.wall_time});
  d.int_attributes.push_back({"resumed", {info.resumed_points > 0 ? 1 : 0}});
  d.int_attributes.push_back({"resumed_points", {static_cast<std::int32_t>(info.resumed_points)}});
  if (info.resumed_points > 0) d.text_attributes.push_back({"resumed_from", info.journal.string()});
}

}  // namespace

void add_provenance(const Study& study, const RunInfo& info, Dataset& d) {
  d.text_attributes = {{"Conventions", "CF-1.8"},
                       {"title", study.title},
                       {"source", std::string("sweetspot ") + version + " (" + git_commit + ")"},
                       {"references", "A. M. Nathan, Am. J. Phys. 68, 979 (2000)"},
                       {"study_file", study.file.string()},
                       {"kind", to_string(study.kind)},
                       {"study", study.text},
                       {"program", "sweetspot"},
                       {"program_version", version},
                       {"git_commit", git_commit}};
  add_scene(study, d);
  if (has_bat(study.kind)) add_bats(study, d);
  add_run(info, d);
}

}  // namespace sweetspot
