#pragma once
// What a study's dataset says about how it was made, so that it explains itself (design.md:
// provenance): the program and the commit it was built from (marked -dirty when the tree held
// changes), the base scene as the run used it with every default filled in, every bat's files and
// their texts byte for byte, and how the run went (ranks, threads, wall time, resumed or not).
#include <cstddef>
#include <filesystem>
#include <string>

#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot {

struct RunInfo {
  int ranks = 1;
  int threads = 1;
  double wall_time = 0;
  std::size_t resumed_points = 0;  // points taken from a killed run's journal (0: not resumed)
  std::filesystem::path journal;   // that journal
};

// Adds the global attributes (Conventions, title, the study text, the program, the scene_* keys,
// the run) and, for a study on bats, the per-bat variables bat_file, bat_toml, bat_profile_file,
// bat_profile and bat_slices over the `bat` axis, which `dataset` must already have; a study of
// one bat file has no bat axis, and they are scalars beside a scalar `bat` holding its name.
void add_provenance(const Study& study, const RunInfo& info, Dataset& dataset);

}  // namespace sweetspot
