#pragma once
// What a bat designer checks of every bat of a study, stored over the study's bat dimensions (the
// bat axis and the bat-parameter axes, design_axes): mass, length, drop, balance point, moments of
// inertia about the knob, the 6-in pivot and the centre of mass (exact, from the design's shape),
// and the lowest vibrational frequencies and their nodes (from the bat's modes as the study cuts it).
#include <vector>

#include "sweetspot/bat/inch_pound.hpp"  // swing_weight_pivot, bat_drop
#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot {

// Frequencies (Hz) of each design's vibrational modes, the first `modes`, and the nodes (m from
// the knob) of its first three; empty for a study that keeps no vibrational mode (no eigen-solve).
struct DesignModes {
  std::vector<std::vector<double>> frequencies_hz;
  std::vector<std::vector<std::vector<double>>> nodes;  // [design][mode 1..3][node]
};

// Solves each design's modes (as the study's base slices and theory cut it), spread over the
// OpenMP threads: every design, or those of one share of `shares` (the designs whose index is
// `share` modulo `shares`: a study's ranks solve one share each), the others left empty.
DesignModes design_modes(const Study& study, int modes, int share = 0, int shares = 1);
// One share's designs as numbers, for a message between ranks (per design: the frequencies' count
// and values, then the node lists' count and each list's count and values), and back into `into`,
// whose other designs are kept.
std::vector<double> pack_design_modes(const DesignModes& modes, int share, int shares);
void unpack_design_modes(const std::vector<double>& packed, int share, int shares, DesignModes& into);

// The dimensions the designer's variables run over, as the dataset names them: "bat" if the study
// has a bat axis, then each bat-parameter axis ("bat_barrel_diameter", ...). No bat axis, no
// bat dimension: a study of one bat file stores its bat's values over the parameter axes alone.
std::vector<std::string> design_dims(const Study& study);

// Adds bat_mass, bat_length (unless a bat.length axis is its coordinate), drop, balance_point, moi_knob, moi_pivot, moi_cm over design_dims,
// and (with modes) frequency over design_dims + mode and node_position over design_dims +
// node_mode + node, with the coordinates node_mode and node.
void add_design_variables(const Study& study, const DesignModes& modes, int mode_count, Dataset& d);

}  // namespace sweetspot
