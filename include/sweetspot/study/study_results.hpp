#pragma once
// What a study stores per grid point, and how the points become one dataset: one variable per
// requested output over the study's axes (mode_energy and mode_response add `mode`, the histories
// `time` and with several probes `probe` before it, force_response `omega_tau`), each axis a
// coordinate named as dataset_name names it (bat_length for the key "bat.length"), and for a
// study on a bat the modal frequencies of each bat over its bat dimensions and `mode`. Wall and
// toy studies have neither a bat nor a mode dimension.
#include <string>
#include <vector>

#include "sweetspot/impact/impact.hpp"
#include "sweetspot/study/bat_properties.hpp"
#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/study.hpp"
#include "sweetspot/study/study_provenance.hpp"

namespace sweetspot {

// Whether a point of this status stores its values: an ok one, and an inaccurate one (a stated
// accuracy not met: its result and estimates say how close it came). Any other gives NaN.
inline bool stores_values(CollisionStatus status) {
  return status == CollisionStatus::ok || status == CollisionStatus::inaccurate;
}

// Where each requested output sits in a point's row of values.
struct OutputLayout {
  std::vector<std::string> names;
  std::vector<int> offsets, widths;
  int width = 0;  // values per point

  explicit OutputLayout(const Study& study);
  // Fills one row from an impact result (NaN for what a failed point could not give).
  void extract(const ImpactResult& result, double* row) const;
};

// Rows of every point (row-major over the axes), the sweet spots along z when asked, what a
// designer checks of each bat (bat_properties.hpp; `modes` empty for the kinds without a bat or a
// study of rigid bats), with the provenance of study_provenance.hpp.
Dataset make_dataset(const Study& study, const OutputLayout& layout, const std::vector<double>& rows,
                     const DesignModes& modes, const RunInfo& info);

// The units (UDUNITS, empty for flags and strings) and long_name a dataset gives an output or an
// axis of this name: the Python module's datasets take theirs from here.
struct OutputDescription {
  std::string units, long_name;
};
OutputDescription describe_output(const std::string& name);

// Whether any point of the study keeps a vibrational mode (else no modes are computed at all).
bool keeps_vibrations(const Study& study);

// With modes = "auto", `frequency` holds each bat's lowest this many modes (`sweetspot modes`
// lists them all): auto keeps a point's modes as its pulse needs, rarely more than these.
inline constexpr int auto_frequency_modes = 10;

// How many modes the dataset's `mode` dimension has: the largest count the study keeps; with
// "all" anywhere, as many as the bat with the most has; with "auto", auto_frequency_modes.
int dataset_mode_count(const Study& study);

}  // namespace sweetspot
