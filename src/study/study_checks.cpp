// The checks across a study's keys, before any work: what no single value shows wrong.
#include <algorithm>
#include <optional>

#include "study_settings.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/impact/n2000_settings.hpp"
#include "sweetspot/impact/standards.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot::study_detail {

using detail::format_number;
using detail::quote;

namespace {

constexpr double max_points = 1e9;

}  // namespace

// ---- Checks across keys ------------------------------------------------------------------------

// The mode count a study keeps unless it says: "auto", or N2000's 18 under preset = "n2000".
double default_mode_count(const Settings& s) { return s["preset"] ? n2000_modes : default_modes; }

void check_required(const Settings& s, const Where& top, StudyKind kind) {
  for (const KeySpec& key : scene_key_specs())
    if ((key.required & bit(kind)) && !s[key.name])
      reject(Where{top.file, "scene", 0}.missing(key.name), "",
             "expected " + std::string(key.expected) + ", in [scene] or as an axis in [axes]");
}

// The wall stands still, so only a ball moving toward it (speed > 0) ever touches it.
void check_wall_speeds(const Settings& s) {
  const Setting& speed = *s["ball_speed"];
  for (std::size_t i = 0; i < speed.values.size(); ++i)
    if (!(speed.values[i] > 0))
      reject(speed.where, speed.value_text(i), "expected a speed > 0 (m/s) toward the wall, which does not move");
}

// A key that only one setting reads, given where no point has that setting, would be silently
// ignored: dopri alone reads `tolerance`, and modes = "auto" alone reads `mode_tolerance`.
void check_unread_keys(const Settings& s) {
  const Setting *tolerance = s["tolerance"], *integrator = s["integrator"];
  const double default_method = static_cast<double>(s["preset"] ? Method::rk4 : Method::exact);
  if (tolerance && !std::ranges::count(s.values("integrator", default_method), static_cast<double>(Method::dopri)))
    reject(tolerance->where, tolerance->value_text(0),
           "expected integrator = \"dopri\" beside it, the one integrator that reads a tolerance (" +
               (integrator ? "key '" + integrator->where.key + "'" : std::string("the default")) +
               " steps at dt): give integrator = \"dopri\", or step_accuracy instead");
  const Setting *mode_tolerance = s["mode_tolerance"], *modes = s["modes"];
  if (mode_tolerance && !std::ranges::count(s.values("modes", default_mode_count(s)), static_cast<double>(auto_modes)))
    reject(mode_tolerance->where, mode_tolerance->value_text(0),
           "expected modes = \"auto\" beside it, the one choice of modes that reads a tolerance (" +
               (modes ? "key '" + modes->where.key + "'" : std::string("the n2000 preset")) +
               " keeps a fixed set): give modes = \"auto\", or no mode_tolerance");
}

namespace {

void check_swing(const Settings& s, const Where& top) {
  const Setting *center = s["center"], *cm_speed = s["cm_speed"], *pivot = s["pivot"];
  if (center && cm_speed)
    reject(center->where, center->value_text(0),
           "expected exactly one of center and cm_speed, but key '" + cm_speed->where.key + "' is also given");
  if (!center && !cm_speed)
    reject(Where{top.file, "scene", 0}.missing("center"), "",
           "give the swing as center (the point at rest, m from the knob) or as cm_speed (m/s)");
  if (cm_speed && pivot && std::ranges::count(pivot->values, 1.0))
    reject(pivot->where, "true", "a pivoted bat is held at its rotation centre: give center, not cm_speed");
}

// A stated accuracy chooses the step (or dopri's tolerance) from the scene's pulse, and the total
// one also the modes' tolerance and the slices: what it chooses, given beside it, would be
// silently overridden, so each such pair is refused.
void check_step_or_accuracy(const Settings& s) {
  for (const AccuracyExclusion& pair : accuracy_exclusions) {
    const Setting *accuracy = s[pair.accuracy], *given = s[pair.given];
    if (accuracy && given)
      reject(given->where, given->values.size() == 1 ? given->value_text(0) : "[...]",
             std::string("expected ") + pair.given + " or " + pair.accuracy + ", not both: key '" +
                 accuracy->where.key + "' is also given, and chooses " + pair.chooses + " itself");
  }
  // A fixed mode count has no estimate of what its dropped modes cost: it cannot be held to one.
  const Setting *accuracy = s["accuracy"], *modes = s["modes"], *preset = s["preset"];
  if (accuracy && modes)
    for (const double count : modes->values)
      if (count >= 0)
        reject(modes->where, format_number(count),
               "a fixed number of modes cannot be held to key '" + accuracy->where.key +
                   "': expected \"auto\" (the default) or \"all\"");
  if (accuracy && preset && !modes)
    reject(preset->where, "\"n2000\"",
           "the preset keeps N2000's 18 modes, which cannot be held to key '" + accuracy->where.key +
               "': expected modes = \"auto\" or \"all\" beside it, or no preset");
}

// The bat files, each read once into its design.
void load_bat_files(Study& study, const Setting& bat) {
  for (const std::string& label : bat.labels) {
    study.bats.push_back((study.file.parent_path() / label).lexically_normal());
    try {
      study.bat_designs.push_back(load_bat_design(study.bats.back(), study.bat_sources.emplace_back()));
    } catch (const InputError& e) {
      reject(bat.where, quote(label), e.what());
    }
    // The dataset labels the bat coordinate by name: two bats of one name could not be told apart.
    const std::string& name = study.bat_designs.back().name;
    const auto same = std::ranges::find(study.bat_names, name);
    if (same != study.bat_names.end())
      reject(bat.where, quote(label),
             "its bat is named '" + *same + "' like the bat of " + quote(bat.labels[same - study.bat_names.begin()]) +
                 "; give each bat its own name");
    study.bat_names.push_back(name);
  }
}

// A bat parameter's value as written: a number, a quantity with its unit, or a preset's name.
std::string parameter_value(const Setting& setting, std::size_t i) { return setting.value_text(i); }

void set_parameter(BatDesign& design, const Setting& setting, std::size_t i, const std::string& bat) {
  try {
    if (setting.spec->type == Type::material)
      set_material_preset(design, setting.labels[i]);
    else
      set_design_parameter(design, std::string_view(setting.name).substr(bat_parameter_prefix.size()),
                           setting.values[i]);
  } catch (const InputError& e) {
    reject(setting.where, parameter_value(setting, i), std::string(e.what()) + " (bat " + bat + ")");
  }
}

// swing = "equal_effort" needs the bat the player's swing was measured with, whose MOI about the
// knob every bat's swing is scaled from; its keys mean nothing for a swing as given.
void read_equal_effort(Study& study, const Settings& s, const Where& top) {
  const Setting *swing = s["swing"], *reference = s["reference_bat"], *exponent = s["swing_exponent"];
  study.equal_effort = swing && swing->values[0] == 1;
  if (!study.equal_effort) {
    for (const Setting* key : {reference, exponent})
      if (key) reject(key->where, parameter_value(*key, 0), "applies only with swing = \"equal_effort\"");
    return;
  }
  if (!reference)
    reject(Where{top.file, "scene", 0}.missing("reference_bat"), "",
           "swing = \"equal_effort\" needs the bat file the given swing was measured with");
  const fs::path file = (study.file.parent_path() / reference->labels[0]).lexically_normal();
  try {
    study.reference_moi =
        design_mass_properties(load_bat_design(file, study.reference_source)).moment_of_inertia_about(0);
  } catch (const InputError& e) {
    reject(reference->where, quote(reference->labels[0]), e.what());
  }
}

// A study builds and checks every bat before any work, and each rank keeps them all.
constexpr double max_designs = 1e5;

// Refuses a design that breaks a rule of a possible bat, at the setting of the parameter the
// rule is about (or, when that parameter is not set by the study, the last bat-parameter axis or
// the bat file).
void check_possible(const BatDesign& design, const Settings& s, const std::vector<const Setting*>& axes,
                    const std::vector<std::size_t>& at, const Setting& bat, std::size_t file,
                    const std::string& label) {
  const std::optional<RuleBreak> broken = rule_break(design);
  if (!broken) return;
  const Setting* blamed = s[std::string(bat_parameter_prefix) + broken->parameter];
  if (!blamed) blamed = axes.empty() ? &bat : axes.back();
  const auto k = static_cast<std::size_t>(std::ranges::find(axes, blamed) - axes.begin());
  const std::string value = k < axes.size() ? parameter_value(*blamed, at[k])
                            : blamed == &bat ? quote(bat.labels[file])
                                             : parameter_value(*blamed, 0);
  reject(blamed->where, value, "makes an impossible bat: " + broken->message + " (" + label + ")");
}

// An uncertainty study's bats: the file's bat with each sample's drawn bat parameters, in
// sample order, each checked against the rules of a possible bat and built.
void build_sampled_designs(Study& study, const Settings& s, const Setting& bat, std::size_t file,
                           std::vector<std::string>& labels) {
  std::vector<const Setting*> drawn;
  for (const Setting& setting : s.samples)
    if (is_bat_parameter(setting.name)) drawn.push_back(&setting);
  const std::size_t samples = s.samples.front().values.size();
  if (static_cast<double>(samples) > max_designs)
    reject(drawn.front()->where, "[...]",
           "draws " + format_number(static_cast<double>(samples)) + " bats (one per sample); at most 1e5");
  const std::string name = study.bat_names[file] + " (" + bat.labels[file] + ")";
  for (std::size_t i = 0; i < samples; ++i) {
    BatDesign design = study.bat_designs[file];
    std::string label = name + " in sample " + std::to_string(i);
    for (const Setting* setting : drawn) {
      set_parameter(design, *setting, i, label);
      label += ", " + setting->name + " = " + parameter_value(*setting, i);
    }
    check_possible(design, s, drawn, std::vector<std::size_t>(drawn.size(), i), bat, file, label);
    study.designs.push_back(build_bat(design));
    study.design_mass.push_back(design_mass_properties(design));
    study.design_specs.push_back(std::move(design));
    labels.push_back(std::move(label));
  }
}

// Every design: each bat file with [scene]'s bat parameters, then each combination of the
// bat-parameter axes (row-major, in the order written), checked against the rules of a possible
// bat and built. Returns a label per design for messages:
// "R161 (bats/r161.toml) with bat.density = 700".
std::vector<std::string> build_designs(Study& study, const Settings& s, const Setting& bat) {
  std::vector<const Setting*> axes;
  double count = 1;
  for (const Setting& axis : s.axes)
    if (is_bat_parameter(axis.name)) axes.push_back(&axis), count *= static_cast<double>(axis.values.size());
  if (count * static_cast<double>(study.bat_designs.size()) > max_designs)
    reject(axes.empty() ? bat.where : axes.back()->where, "[...]",
           "the bat axes give " + format_number(count * static_cast<double>(study.bat_designs.size())) +
               " bats; at most 1e5");
  std::vector<std::string> labels;
  for (std::size_t f = 0; f < study.bat_designs.size(); ++f) {
    const std::string file = study.bat_names[f] + " (" + bat.labels[f] + ")";
    BatDesign& base = study.bat_designs[f];
    for (const Setting& setting : s.scene)
      if (is_bat_parameter(setting.name)) set_parameter(base, setting, 0, file);
    if (study.sampled_designs) {  // an uncertainty study: no bat axes, one bat per sample
      build_sampled_designs(study, s, bat, f, labels);
      continue;
    }
    std::vector<std::size_t> at(axes.size(), 0);
    for (std::size_t d = 0; d < static_cast<std::size_t>(count); ++d) {
      BatDesign design = base;
      std::string label = file;
      for (std::size_t k = 0; k < axes.size(); ++k) {
        set_parameter(design, *axes[k], at[k], file);
        label += (k ? ", " : " with ") + axes[k]->name + " = " + parameter_value(*axes[k], at[k]);
      }
      check_possible(design, s, axes, at, bat, f, label);
      study.designs.push_back(build_bat(design));
      study.design_mass.push_back(design_mass_properties(design));
      study.design_specs.push_back(std::move(design));
      labels.push_back(std::move(label));
      for (std::size_t k = axes.size(); k-- > 0 && ++at[k] == axes[k]->values.size();) at[k] = 0;
    }
  }
  return labels;
}

// Points on the bat (z, probes) must be on every bat.
void check_on_bats(const Setting& points, const std::vector<Bat>& bats, const std::vector<std::string>& labels) {
  for (std::size_t i = 0; i < points.values.size(); ++i)
    for (std::size_t b = 0; b < bats.size(); ++b)
      if (const double x = points.values[i]; !lies_on_bat(x, bats[b].length)) {
        const auto [value, end] = detail::format_apart(x, x < 0 ? 0.0 : bats[b].length);
        // A length with its unit as written, then in metres with the digits that part it from the end.
        const std::string written = points.value_text(i);
        reject(points.where, written.starts_with('"') ? written + " = " + value + " m" : value,
               "must lie on every bat of the study: 0 to " + (x < 0 ? format_number(bats[b].length) : end) +
                   " m for " + labels[b]);
      }
}

void check_mode_counts(const Settings& s, const Where& top, const std::vector<Bat>& bats,
                       const std::vector<std::string>& labels) {
  const Setting* modes = s["modes"];
  const Where where = modes ? modes->where : Where{top.file, "scene", 0}.missing("modes");
  for (std::size_t b = 0; b < bats.size(); ++b)
    for (const double slices : s.values("slices", bats[b].slices()))
      for (const double theory : s.values("theory", 0))
        for (const double m : s.values("modes", default_mode_count(s))) {
          const int available = vibrational_mode_count(static_cast<int>(slices), static_cast<BeamTheory>(theory));
          const std::string value =
              (m == all_modes ? "\"all\"" : format_number(m)) +
              (modes ? "" : s["preset"] ? " (the n2000 preset)" : " (the default)");
          if (m != all_modes && m != auto_modes && m > available)
            reject(where, value,
                   labels[b] + " in " + format_number(slices) + " slices has " + std::to_string(available) +
                       " vibrational modes (" + to_string(static_cast<BeamTheory>(theory)) +
                       "); expected at most that, or \"all\"");
          // A solve that would take longer than is practical (the full solve past 1024 slices).
          const ModeRequest request = m == all_modes ? ModeRequest::all() : ModeRequest::lowest(static_cast<int>(m));
          if (m != auto_modes && m != 0)
            if (const auto why = impractical_solve(static_cast<int>(slices), static_cast<BeamTheory>(theory), request))
              reject(where, value, labels[b] + " in " + format_number(slices) + " slices: " + *why);
        }
}

void check_euler_bernoulli_slices(const Settings& s, const Where& top, const std::vector<Bat>& bats,
                                  const std::vector<std::string>& labels) {
  const Setting* slices = s["slices"];
  const Where where = slices ? slices->where : Where{top.file, "scene", 0}.missing("slices");
  for (std::size_t b = 0; b < bats.size(); ++b)
    for (const double n : s.values("slices", bats[b].slices()))
      for (const double theory : s.values("theory", 0))
        if (static_cast<BeamTheory>(theory) == BeamTheory::euler_bernoulli && n > max_euler_bernoulli_slices)
          reject(where, format_number(n) + (slices ? "" : " (" + labels[b] + "'s own)"),
                 "at most " + std::to_string(max_euler_bernoulli_slices) +
                     " slices for theory euler-bernoulli (its dense solve loses the lowest frequencies to round-off)");
}

}  // namespace

void check_output_keys_read(const Settings& s, const Study& study) {
  const auto asks = [&study](const auto& output) { return std::ranges::any_of(study.outputs, output); };
  const struct {
    std::vector<const char*> keys;
    bool read;
    const char* readers;
  } groups[] = {
      {{"temperature", "pressure", "altitude", "humidity", "wind_speed", "wind_direction"},
       study.flight,
       "the flight's outputs (distance, apex, hang_time, landing_angle)"},
      {{"history_window", "history_step"}, asks(is_history),
       "the histories (force, compression, ball_position, displacement, velocity, ...)"},
      {{"probes"}, asks(is_probe_history), "the probes' histories (displacement, velocity, acceleration, ...)"},
      {{"e_a_speed"}, asks([](const std::string& o) { return o == "bbs_linear"; }), "bbs_linear"},
  };
  for (const auto& group : groups)
    for (const char* key : group.keys)
      if (const Setting* given = s[key]; given && !group.read)
        reject(given->where, given->values.size() == 1 ? given->value_text(0) : "[...]",
               std::string("is read by ") + group.readers + " alone, and the study asks none of them: add one to " +
                   "[output] variables, or leave the key out");
}

void check_grid_size(const Settings& s, const Where& top) {
  double points = s.samples.empty() ? 1 : static_cast<double>(s.samples.front().values.size());
  for (const Setting& axis : s.axes) points *= static_cast<double>(axis.values.size());
  if (points > max_points)
    reject(Where{top.file, "axes", 0}, "{...}", "the grid has " + format_number(points) + " points; at most 1e9");
}

// Rounded as the time grid rounds (HistoryRequest::steps): 3e-3 / 3e-8 is 1e5, not 1e5 + 1e-11.
void check_history_samples(const Settings& s) {
  const HistoryRequest h{{}, s.values("history_window", HistoryRequest{}.window)[0],
                         s.values("history_step", HistoryRequest{}.step)[0]};
  if (h.steps() > max_history_samples) {
    const Setting* at = s["history_step"] ? s["history_step"] : s["history_window"];
    reject(at->where, at->value_text(0),
           "history_window / history_step = " + format_number(h.steps()) + " samples; at most 1e5");
  }
}

namespace {

// The fastest mode a point keeps (rad/s): the free bat's, or with `pivot_center` the held bat's,
// whose modes the constraint makes (scene.cpp), never faster than the free ones.
double fastest_kept_mode(const ModalBasis& basis, double modes, const double* pivot_center) {
  if (!pivot_center) return basis.omega(modes == all_modes ? basis.count() - 1 : static_cast<int>(modes) + 1);
  ImpactScene scene;
  scene.vibrational_modes = static_cast<int>(modes);
  scene.pivoted = scene.swing.about_center = true;
  scene.swing.center = *pivot_center;
  scene.z = basis.z.front();  // the held bat's frequencies do not depend on where it is struck
  return scene_geometry(scene, basis).contact.omega.maxCoeff();
}

// RK4 at a fixed step is unstable once omega dt > 2.8 for a kept mode, and `impact` refuses such a
// scene: so does the study, before any work, naming the combination of values that makes it.
// ("auto" keeps modes per point and is left to the point; a stated accuracy keeps the step stable.)
void check_rk4_stability(const Settings& s, const Where& top, const std::vector<Bat>& bats,
                         const std::vector<std::string>& labels) {
  const Setting* integrator = s["integrator"];
  if (!integrator || static_cast<Method>(integrator->values[0]) != Method::rk4 || s["accuracy"] || s["step_accuracy"])
    return;
  const std::vector<double> steps = s.values("dt", default_step(Method::rk4));
  const double dt = *std::ranges::max_element(steps);
  const std::vector<double> pivots = s.values("pivot", 0), centers = s.values("center", 0);
  const bool all_pivoted = std::ranges::count(pivots, 0.0) == 0;
  const Setting* modes_setting = s["modes"];
  const Where where = modes_setting ? modes_setting->where : Where{top.file, "scene", 0}.missing("modes");
  for (std::size_t b = 0; b < bats.size(); ++b)
    for (const double slices : s.values("slices", bats[b].slices()))
      for (const double theory : s.values("theory", 0)) {
        std::optional<ModalBasis> basis;  // solved only when some point keeps a vibrational mode
        const std::vector<double> counts = s.values("modes", default_modes);
        // The modes the points keep, and no more: every one, or the lowest of the largest count.
        const ModeRequest request = std::ranges::count(counts, all_modes)
                                        ? ModeRequest::all()
                                        : ModeRequest::lowest(static_cast<int>(std::ranges::max(counts)));
        for (const double m : counts) {
          if (m == 0 || m == auto_modes) continue;
          if (!basis)
            basis = compute_modes(resample(bats[b], static_cast<int>(slices)), static_cast<BeamTheory>(theory), request);
          double omega = fastest_kept_mode(*basis, m, nullptr), center = 0;
          if (omega * dt <= rk4_stability_limit) continue;
          if (all_pivoted) {  // held, the fastest mode may be slow enough
            omega = 0;
            for (const double c : centers)
              if (const double w = fastest_kept_mode(*basis, m, &c); w > omega) omega = w, center = c;
            if (omega * dt <= rk4_stability_limit) continue;
          }
          const std::string value = m == all_modes ? "\"all\"" : format_number(m);
          reject(where, value + (modes_setting ? "" : " (the default)"),
                 "with integrator = \"rk4\" and dt = " + format_number(dt) + " s, " + labels[b] + " in " +
                     format_number(slices) + " slices (" + to_string(static_cast<BeamTheory>(theory)) + ")" +
                     (all_pivoted ? ", pivoted at center = " + format_number(center) + " m," : "") +
                     " keeps a mode of omega = " + format_number(omega) + " rad/s: omega dt = " +
                     format_number(omega * dt) + " > 2.8 is unstable; expected fewer modes, dt <= " +
                     format_number(rk4_stability_limit / omega) + " s, accuracy, or integrator = \"exact\"");
        }
      }
}

// The rig holds every bat at its standard's pivot, before the scanned barrel: a bat too short for
// that is refused before any work, as certify and optimize refuse it, not failed at its point.
void check_rig_fits(const Settings& s, const std::vector<Bat>& bats, const std::vector<std::string>& labels) {
  const Standard& standard = standards()[static_cast<std::size_t>(s.values("standard", 0).front())];
  const BarrelScan scan;
  for (std::size_t b = 0; b < bats.size(); ++b)
    if (const auto misfit = rig_misfit(standard, standard.pivot, bats[b].length, scan))
      reject(s["bat"]->where, labels[b] + " (" + format_number(bats[b].length) + " m)", *misfit);
}

}  // namespace

// The impact kind's checks across keys: the swing, the bat files, z on every bat, mode counts.
void check_bat_scene(Study& study, const Settings& s, const Where& top) {
  const Setting& bat = *s["bat"];
  check_step_or_accuracy(s);
  check_unread_keys(s);
  if (study.kind == StudyKind::certification) {  // the rig holds each bat at rest: no swing, no point
    load_bat_files(study, bat);
    const std::vector<std::string> labels = build_designs(study, s, bat);
    check_mode_counts(s, top, study.designs, labels);
    check_euler_bernoulli_slices(s, top, study.designs, labels);
    check_rig_fits(s, study.designs, labels);
    return;
  }
  check_swing(s, top);
  read_equal_effort(study, s, top);
  load_bat_files(study, bat);
  const std::vector<std::string> labels = build_designs(study, s, bat);
  const std::vector<Bat>& bats = study.designs;
  check_on_bats(*s["z"], bats, labels);
  if (const Setting* probes = s["probes"]) check_on_bats(*probes, bats, labels);
  check_mode_counts(s, top, bats, labels);
  check_euler_bernoulli_slices(s, top, bats, labels);
  check_history_samples(s);
  check_rk4_stability(s, top, bats, labels);
}

}  // namespace sweetspot::study_detail
