#pragma once
// What a study stores per grid point, and how the points become one dataset: one variable per
// requested output over the study's axes (mode_energy and mode_response add `mode`, the histories
// `time` and with several probes `probe` before it, force_response `omega_tau`), each axis a
// coordinate, and for a study on a bat the modal frequencies of each bat over (bat, mode). Wall
// and toy studies have neither a bat nor a mode dimension.
#include <string>
#include <vector>

#include "sweetspot/impact/impact.hpp"
#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/study.hpp"
#include "sweetspot/study/study_provenance.hpp"

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

// Rows of every point (row-major over the axes) and the vibrational frequencies (Hz) of each bat
// (none for the kinds without a bat), with the provenance of study_provenance.hpp.
Dataset make_dataset(const Study& study, const OutputLayout& layout, const std::vector<double>& rows,
                     const std::vector<std::vector<double>>& bat_frequencies_hz, const RunInfo& info);

// Whether any point of the study keeps a vibrational mode (else no modes are computed at all).
bool keeps_vibrations(const Study& study);

// How many modes the dataset's `mode` dimension has: the largest count the study keeps, or with
// "all" or "auto" anywhere, as many as the bat with the most has.
int dataset_mode_count(const Study& study, const std::vector<std::vector<double>>& bat_frequencies_hz);

}  // namespace sweetspot
