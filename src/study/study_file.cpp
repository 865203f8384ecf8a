// load_study: a study file read, checked across keys and resolved into a Study.
#include <algorithm>
#include <numeric>

#include "ball/ball_table.hpp"
#include "study_settings.hpp"
#include "sweetspot/impact/n2000_settings.hpp"
#include "sweetspot/study/study_memory.hpp"
#include "toml_values.hpp"

namespace sweetspot {

using namespace study_detail;
using detail::describe;
using detail::format_number;

namespace {

Axis make_axis(const Setting& s) {
  Axis axis{s.name, s.values, s.labels};
  if (s.spec->type == Type::bat)
    for (std::size_t i = 0; i < axis.size(); ++i) axis.values[i] = static_cast<double>(i);
  return axis;
}

// An uncertainty study's drawn keys as settings, each value checked as the key's own values are
// (a normal distribution reaches any value: one outside what the key takes is refused, naming
// the sample, so that the user truncates the distribution).
std::vector<Setting> drawn_settings(const Where& top, const SampledKeys& sampled, const Settings& given) {
  std::vector<Setting> settings;
  for (std::size_t k = 0; k < sampled.keys.size(); ++k) {
    const Axis& key = sampled.keys[k];
    const KeySpec* spec = find_key(key.name);
    const Where where{top.file, "uncertain." + key.name, sampled.lines[k]};
    if (!spec || !drawable(*spec, sampled.model))
      reject(where, "{...}", "expected a numeric key of kind " + kind_text(sampled.model) + " that may be an axis: " +
                                 drawable_key_list(sampled.model) + ", or \"bat.PARAMETER\"");
    if (find(given.scene, key.name))
      reject(where, "{...}", "is drawn here and set in [scene]: give it in one place");
    if (find(given.axes, key.name)) reject(where, "{...}", "is drawn here and is an axis: give it in one place");
    for (std::size_t i = 0; i < key.values.size(); ++i)
      if (!spec->valid(key.values[i]))
        reject(where, format_number(key.values[i]) + " (sample " + std::to_string(i) + ")",
               std::string(spec->expected) + "; truncate the distribution to the values the key takes");
    settings.push_back(Setting{spec, where, key.values, {}, key.name});
  }
  return settings;
}

// An uncertainty study's axes sweep its scene for every sample; the bats are the samples'.
void reject_model_axes(const Settings& s) {
  for (const Setting& axis : s.axes)
    if (axis.name == "bat" || axis.name == "slices" || axis.name == "theory" || is_bat_parameter(axis.name))
      reject(axis.where, "[...]",
             "an uncertainty study's bats are one file's (its [scene] bat and the drawn bat parameters): not an axis");
}

Study load(const fs::path& file, std::string text, const SampledKeys* sampled) {
  Study study;
  study.file = file;
  study.text = std::move(text);
  const toml::table doc = parse_toml(file, study.text);
  const Where top{&study.file, "", 0};
  if (sampled)
    reject_unknown(top, doc, {"title", "kind", "model", "scene", "axes", "output", "ball", "uncertain", "sampling"});
  else
    reject_unknown(top, doc, {"title", "kind", "scene", "axes", "output", "ball"});
  if (const toml::node* title = doc.get("title")) {
    // A NUL character would cut the title short in the dataset (an HDF5 string ends there).
    if (!title->is_string() || title->as_string()->get().find('\0') != std::string::npos)
      reject(top.child("title", *title), describe(*title), "expected a string without NUL characters");
    study.title = title->as_string()->get();
  }
  study.kind = sampled ? sampled->model : read_kind(top, doc);
  Settings s{read_settings(top, doc, "scene", study.kind), read_settings(top, doc, "axes", study.kind)};
  if (sampled) {
    reject_model_axes(s);
    s.samples = drawn_settings(top, *sampled, s);
    study.sampled = sampled->keys;
    study.sampled_designs = std::ranges::any_of(s.samples, [](const Setting& d) { return is_bat_parameter(d.name); });
  }
  check_grid_size(s, top);
  check_required(s, top, study.kind);
  if (has_bat(study.kind)) check_bat_scene(study, s, top);
  if (study.kind == StudyKind::wall) check_wall_speeds(s), check_unread_keys(s), check_history_samples(s);
  study.outputs = read_outputs(top, doc, s, study.kind);
  study.sweet_spot_fraction = read_sweet_spot_fraction(top, doc);
  study.sweet_spot_of = read_sweet_spot_of(top, doc);
  check_sweet_spot_keys_read(top, doc, study.outputs);
  // The sweet spot of the carry needs the carry at every point.
  if (study.sweet_spot_of == "distance" && !std::ranges::count(study.outputs, "distance") &&
      std::ranges::any_of(study.outputs, [](const std::string& o) { return o.starts_with("sweet_spot_"); }))
    study.outputs.push_back("distance");

  GridPoint base;
  // The library's defaults (exact modal stepping, modes = auto: README, "Numerics"), or N2000's
  // settings under preset = "n2000"; what the study gives overrides either. Each method has its
  // own default step.
  if (s["preset"]) base.scene = with_n2000_settings(base.scene);
  // [ball]: a preset or the ball's test values (README "Balls"); [scene] and axes keys override it.
  if (const toml::node* ball = doc.get("ball")) {
    if (!ball->is_table()) reject(top.child("ball", *ball), describe(*ball), "expected a table [ball]");
    base.scene.ball = detail::read_ball_table(*ball->as_table(), file.string()).ball;
    study.rig_ball = true;
  }
  for (const Setting& setting : s.scene)
    for (const double x : setting.values) setting.spec->set(base, x);  // one value, or each of a list
  if (!s["dt"]) base.scene.integrator.dt = default_step(base.scene.integrator.method);
  // The comparisons cost time (Van Zandt records and integrates the force profile): only when asked.
  base.scene.rigid_comparison = std::ranges::count(study.outputs, "vf_rigid") > 0;
  base.scene.van_zandt_comparison = std::ranges::count(study.outputs, "vf_van_zandt") > 0;
  base.scene.linear_batted_ball = std::ranges::count(study.outputs, "bbs_linear") > 0;
  base.scene.histories = std::ranges::any_of(study.outputs, is_history);
  base.scene.force_response = std::ranges::count(study.outputs, "force_response") > 0;
  base.scene.mode_response = std::ranges::count(study.outputs, "mode_response") > 0;
  // The error estimates cost half an impact (step) and an impact on the bat at twice its slices
  // (slicing, its modes solved once per bat): only when asked (error_estimates.hpp).
  base.scene.error_estimates = std::ranges::any_of(study.outputs, [](const std::string& name) {
    return name == "slicing_error" || name == "step_error" || name == "total_error";
  });
  base.scene.integrator.find_collision_time = std::ranges::count(study.outputs, "collision_time") > 0;
  // A damped bat's loss is integrated only for a study that stores energies.
  base.scene.integrator.damping_loss =
      std::ranges::any_of(study.outputs, [](const std::string& name) { return name.starts_with("energy_"); });
  base.scene.swing.about_center = s["center"] != nullptr;
  study.base = base.scene;
  study.omega_tau = base.omega_tau;
  study.swing_exponent = base.swing_exponent;
  study.air = base.air;
  // The flight costs about an impact: only when one of its outputs is asked.
  study.flight = std::ranges::any_of(study.outputs, [](const std::string& name) {
    return name == "distance" || name == "apex" || name == "hang_time" || name == "landing_angle";
  });
  check_output_keys_read(s, study);
  study.standard = base.standard;
  study.rig_e0 = base.rig_e0;
  study.rig_ball_speed = base.rig_ball_speed;
  study.theory = base.theory;
  study.slices = base.slices;
  if (sampled) {
    Axis samples{std::string(sample_axis), std::vector<double>(sampled->samples), {}};
    std::iota(samples.values.begin(), samples.values.end(), 0.0);
    study.axes.push_back(std::move(samples));
  }
  for (const Setting& axis : s.axes) study.axes.push_back(make_axis(axis));
  check_study_memory(study, machine_memory_bytes());
  return study;
}

}  // namespace

Study load_study(const fs::path& file) { return load(file, read_text(file), nullptr); }

Study load_sampled_study(const fs::path& file, std::string text, const SampledKeys& sampled) {
  return load(file, std::move(text), &sampled);
}

}  // namespace sweetspot
