#pragma once
// What a study stores per grid point, and how the points become one dataset: one variable per
// requested output over the study's axes (mode_energy and mode_response add `mode`, the histories
// `time` and with several probes `probe` before it, force_response `omega_tau`), each axis a
// coordinate, and for a study on a bat the modal frequencies of each bat over (bat, mode). Wall
// and toy studies have neither a bat nor a mode dimension.
#include <string>
#include <vector>

#include "sweetspot/study/dataset.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot {

// Where each requested output sits in a point's row of values.
struct OutputLayout {
  std::vector<std::string> names;
  std::vector<int> offsets, widths;
  int width = 0;  // values per point

  explicit OutputLayout(const Study& study);
  // Fills one row from an impact result (NaN for what a failed point could not give).
  void extract(const ImpactResult& result, double* row) const;
};

struct RunInfo {
  int ranks = 1;
  int threads = 1;
  double wall_time = 0;
};

// Rows of every point (row-major over the axes) and the vibrational frequencies (Hz) of each bat
// (none for the kinds without a bat).
Dataset make_dataset(const Study& study, const OutputLayout& layout, const std::vector<double>& rows,
                     const std::vector<std::vector<double>>& bat_frequencies_hz, const RunInfo& info);

// Whether any point of the study keeps a vibrational mode (else no modes are computed at all).
bool keeps_vibrations(const Study& study);

// How many modes the dataset's `mode` dimension has.
int dataset_mode_count(const Study& study);

}  // namespace sweetspot
