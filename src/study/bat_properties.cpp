#include "sweetspot/study/bat_properties.hpp"

#include <omp.h>

#include <algorithm>
#include <limits>

#include "sweetspot/bat/modes.hpp"

namespace sweetspot {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// The modes whose nodes are stored, and the most nodes any of them has (mode k has k + 1).
constexpr int node_modes = 3, most_nodes = node_modes + 1;

Variable design_variable(const Study& study, const char* name, const char* units, const char* long_name,
                         std::vector<double> values, std::vector<std::string> extra_dims = {}) {
  std::vector<std::string> dims = design_dims(study);
  dims.insert(dims.end(), extra_dims.begin(), extra_dims.end());
  return {name, units, long_name, std::move(dims), std::move(values), {}, {}};
}

// One value per design.
template <class F>
std::vector<double> per_design(const Study& study, F value) {
  std::vector<double> values;
  for (std::size_t b = 0; b < study.designs.size(); ++b) values.push_back(value(study.designs[b], study.design_mass[b]));
  return values;
}

void add_mass_variables(const Study& study, Dataset& d) {
  d.variables.push_back(design_variable(study, "bat_mass", "kg", "mass of the bat",
                                        per_design(study, [](const Bat&, const MassProperties& m) { return m.mass; })));
  // A bat.length axis is the bat's length already: its coordinate bat_length takes the name.
  if (std::ranges::count(design_dims(study), "bat_length") == 0)
    d.variables.push_back(design_variable(study, "bat_length", "m", "length of the bat",
                                          per_design(study, [](const Bat& b, const MassProperties&) { return b.length; })));
  // In minus oz has no UDUNITS spelling: the long name says what it is.
  d.variables.push_back(design_variable(study, "drop", "", "drop: length in inches minus weight in ounces",
                                        per_design(study, [](const Bat& b, const MassProperties& m) {
                                          return bat_drop(b.length, m.mass);
                                        })));
  d.variables.push_back(design_variable(study, "balance_point", "m", "centre of mass of the bat from the knob",
                                        per_design(study, [](const Bat&, const MassProperties& m) { return m.z_cm; })));
  d.variables.push_back(design_variable(study, "moi_knob", "kg m^2", "moment of inertia about the knob",
                                        per_design(study, [](const Bat&, const MassProperties& m) {
                                          return m.moment_of_inertia_about(0);
                                        })));
  d.variables.push_back(design_variable(
      study, "moi_pivot", "kg m^2", "moment of inertia about the point 6 in (0.1524 m) from the knob (swing weight)",
      per_design(study,
                 [](const Bat&, const MassProperties& m) { return m.moment_of_inertia_about(swing_weight_pivot); })));
  d.variables.push_back(design_variable(
      study, "moi_cm", "kg m^2", "moment of inertia about the centre of mass",
      per_design(study, [](const Bat&, const MassProperties& m) { return m.moment_of_inertia_cm; })));
}

void add_mode_variables(const Study& study, const DesignModes& modes, int mode_count, Dataset& d) {
  std::vector<double> frequencies, nodes;
  for (std::size_t b = 0; b < study.designs.size(); ++b) {
    const std::vector<double>& f = modes.frequencies_hz[b];
    for (int n = 0; n < mode_count; ++n) frequencies.push_back(n < static_cast<int>(f.size()) ? f[n] : nan);
    for (int k = 0; k < node_modes; ++k) {
      const std::vector<double>* z = k < static_cast<int>(modes.nodes[b].size()) ? &modes.nodes[b][k] : nullptr;
      for (int j = 0; j < most_nodes; ++j) nodes.push_back(z && j < static_cast<int>(z->size()) ? (*z)[j] : nan);
    }
  }
  d.variables.push_back(design_variable(study, "frequency", "Hz", "frequency of each vibrational mode of each bat",
                                        std::move(frequencies), {"mode"}));
  Coordinate node_mode{"node_mode", "1", "vibrational mode whose nodes are given", {}, {}};
  Coordinate node{"node", "1", "node of the mode, counted from the knob", {}, {}};
  for (int k = 1; k <= node_modes; ++k) node_mode.integers.push_back(k);
  for (int j = 1; j <= most_nodes; ++j) node.integers.push_back(j);
  d.coordinates.push_back(std::move(node_mode));
  d.coordinates.push_back(std::move(node));
  d.variables.push_back(design_variable(study, "node_position", "m",
                                        "nodes (zeros of the mode shape) of the lowest vibrational modes, from the knob",
                                        std::move(nodes), {"node_mode", "node"}));
}

}  // namespace

std::vector<std::string> design_dims(const Study& study) {
  std::vector<std::string> dims;  // the bat axis comes first in design_axes
  for (const std::size_t k : design_axes(study)) dims.push_back(dataset_name(study.axes[k].name));
  return dims;
}

DesignModes design_modes(const Study& study, int modes, int share, int shares) {
  DesignModes out;
  const auto designs = static_cast<long>(study.designs.size());
  out.frequencies_hz.resize(study.designs.size());
  out.nodes.resize(study.designs.size());
#pragma omp parallel for schedule(dynamic)
  for (long b = share; b < designs; b += shares) {
    const Bat& bat = study.designs[b];
    // The lowest modes alone (a partial solve), enough for the nodes of the first three.
    const ModalBasis basis = compute_modes(study.slices > 0 ? resample(bat, study.slices) : bat, study.theory,
                                           ModeRequest::lowest(std::max(modes, node_modes)));
    std::vector<double> f = basis.vibrational_frequencies_hz();
    f.resize(std::min<std::size_t>(f.size(), static_cast<std::size_t>(modes)));
    out.frequencies_hz[b] = std::move(f);
    for (int k = 1; k <= node_modes && k + 1 < basis.count(); ++k) out.nodes[b].push_back(basis.nodes(k + 1));
  }
  return out;
}

std::vector<double> pack_design_modes(const DesignModes& modes, int share, int shares) {
  std::vector<double> packed;
  const auto add = [&packed](const std::vector<double>& values) {
    packed.push_back(static_cast<double>(values.size()));
    packed.insert(packed.end(), values.begin(), values.end());
  };
  for (std::size_t b = share; b < modes.frequencies_hz.size(); b += shares) {
    add(modes.frequencies_hz[b]);
    packed.push_back(static_cast<double>(modes.nodes[b].size()));
    for (const std::vector<double>& nodes : modes.nodes[b]) add(nodes);
  }
  return packed;
}

void unpack_design_modes(const std::vector<double>& packed, int share, int shares, DesignModes& into) {
  auto next = packed.begin();
  const auto take = [&next]() {
    const auto count = static_cast<std::ptrdiff_t>(*next++);
    std::vector<double> values(next, next + count);
    next += count;
    return values;
  };
  for (std::size_t b = share; b < into.frequencies_hz.size() && next != packed.end(); b += shares) {
    into.frequencies_hz[b] = take();
    into.nodes[b].resize(static_cast<std::size_t>(*next++));
    for (std::vector<double>& nodes : into.nodes[b]) nodes = take();
  }
}

void add_design_variables(const Study& study, const DesignModes& modes, int mode_count, Dataset& d) {
  add_mass_variables(study, d);
  if (!modes.frequencies_hz.empty()) add_mode_variables(study, modes, mode_count, d);
}

}  // namespace sweetspot
