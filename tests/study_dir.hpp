#pragma once
// A study in a directory of its own for the tests that try to make a run overwrite or mix up
// files: the study and copies of both shipped bats with their profiles, so that a run refusing
// nothing would overwrite the copies, never the repository's files. With helpers to see that no
// file changed and that a refusal is the program's one line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "temp_dir.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/study.hpp"

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct StudyDir {
  TempDir dir;
  std::filesystem::path study;

  // 2 bats x `z_count` impact points x 2 speeds, 18 modes: the small study of test_run.cpp,
  // with `scene` added to its [scene].
  explicit StudyDir(int z_count = 3, const std::string& scene = "") {
    std::filesystem::create_directories(dir.path / "bats");
    for (const char* file : {"r161.toml", "r161_profile.csv", "torpedo.toml", "torpedo_profile.csv"})
      std::filesystem::copy_file(source_path(std::string("studies/bats/") + file), dir.path / "bats" / file);
    std::ostringstream s;
    s << "[scene]\nbat = \"bats/r161.toml\"\ncenter = 0.09\nomega = 51\nmodes = 18\n" << scene << "[axes]\n"
      << "bat = [\"bats/r161.toml\", \"bats/torpedo.toml\"]\nz = { start = 0.605, stop = 0.705, count = " << z_count
      << " }\nball_speed = [30.0, 40.0]\n";
    study = dir.write("study.toml", s.str());
  }

  std::string operator/(const std::string& name) const { return dir / name; }

  // Every file under the directory (directories too, as "<dir>") with its bytes.
  std::map<std::string, std::string> snapshot() const {
    std::map<std::string, std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir.path))
      files[entry.path().string()] = entry.is_directory() ? "<dir>" : file_text(entry.path());
    return files;
  }
};

// The one line load_study refuses `study` with, or "(not refused)".
inline std::string study_refusal(const std::filesystem::path& study) {
  try {
    sweetspot::load_study(study);
  } catch (const sweetspot::InputError& e) {
    return e.what();
  }
  return "(not refused)";
}

// The run was refused the program's way (refusal.hpp): exit status 2 and one line of sweetspot's
// own, "sweetspot: error: ...", holding `expected`, whatever MPI adds (mpirun's note on the exit
// status); no MPI_ABORT banner.
inline void require_refused(const ProgramRun& run, const std::string& expected) { require_refused(run, {expected}); }
