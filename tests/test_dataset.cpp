// Study datasets: what write_dataset writes reads back in xarray (engine h5netcdf) and h5py as it
// is (tests/check_dataset.py checks that side), a bad dataset is refused before any file is
// touched, and a failed write leaves an existing file as it was.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "program.hpp"
#include "temp_dir.hpp"
#include "sweetspot/study/dataset.hpp"

namespace fs = std::filesystem;
using sweetspot::Coordinate;
using sweetspot::Dataset;
using sweetspot::Variable;
using sweetspot::write_dataset;

namespace {

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// 2 bats x 5 z x 3 speeds, and 4 modes per bat; check_dataset.py expects exactly these values.
Dataset study_dataset() {
  Dataset dataset;
  dataset.coordinates = {
      {"bat", "", "bat profile", {}, {"R161", "torpedo"}},
      {"z", "m", "impact location from the knob", {0.1, 0.2, 0.3, 0.4, 0.5}, {}},
      {"ball_speed", "m/s", "ball speed before impact", {30.0, 40.0, 50.0}, {}},
      {"mode", "1", "mode number", {}, {}, {1, 2, 3, 4}, {{"flag_meanings", "all"}}, {{"flag_values", {-1}}}},
  };
  std::vector<double> vf;
  std::vector<std::int32_t> status;
  for (int b = 0; b < 2; ++b)
    for (int z = 0; z < 5; ++z)
      for (int s = 0; s < 3; ++s) {
        vf.push_back(100 * b + 10 * z + s + 0.5);
        status.push_back((100 * b + 10 * z + s) % 3);
      }
  std::vector<double> frequency;
  for (int b = 0; b < 2; ++b)
    for (int m = 1; m <= 4; ++m) frequency.push_back(100 * (b + 1) + m);
  dataset.variables = {
      {"vf", "m/s", "ball exit speed", {"bat", "z", "ball_speed"}, vf, {}, {}},
      {"status", "1", "integration status", {"bat", "z", "ball_speed"}, status,
       {{"flag_meanings", "ok max_steps no_contact"}}, {{"flag_values", {0, 1, 2}}}},
      {"frequency", "Hz", "natural frequency ω/2π", {"bat", "mode"}, frequency, {}, {}},
      {"bat_text", "", "text of the bat file", {"bat"}, std::vector<std::string>{"name = \"R161\"\n", "ω = 1\n"}, {}, {}},
  };
  dataset.text_attributes = {{"title", "dataset test"},
                             {"study", "name = \"test\"\n[axes]\nz = [0.1, 0.5]\n"}};
  dataset.number_attributes = {{"wall_time_s", 1.25}};
  dataset.int_attributes = {{"ranks", {4}}, {"flags", {1, 2}}};
  dataset.number_list_attributes = {{"probes", {0.06, 0.13}}};
  return dataset;
}

void require_python_reads(const fs::path& file) {
  const ProgramRun run = run_command(std::string(python) + " '" + source_path("tests/check_dataset.py") +
                                     "' '" + file.string() + "'");
  INFO("check_dataset.py output:\n" << run.output);
  REQUIRE(run.exit_code == 0);
  REQUIRE_THAT(run.output, Catch::Contains("dataset ok"));
}

// `dataset` must be refused with std::invalid_argument naming `object`, before any file exists.
void require_refused(const Dataset& dataset, const std::string& object, const std::string& why) {
  const TempDir temp;
  const fs::path path = temp.path / "study.h5";
  try {
    write_dataset(path, dataset);
    FAIL("write_dataset accepted a dataset with a bad " << object);
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains(object) && Catch::Contains(why));
  }
  CHECK(fs::is_empty(temp.path));
}

}  // namespace

TEST_CASE("a study dataset reads back in xarray, h5netcdf and h5py as it was written",
          "[dataset]") {
  const TempDir temp;
  const fs::path path = temp.path / "study.h5";
  write_dataset(path, study_dataset());
  CHECK(fs::exists(path));
  CHECK_FALSE(fs::exists(fs::path(path) += ".tmp"));
  require_python_reads(path);
}

TEST_CASE("dataset: writing replaces an existing file whole", "[dataset]") {
  const TempDir temp;
  const fs::path path = temp.path / "study.h5";
  std::ofstream(path) << "an older result";
  write_dataset(path, study_dataset());
  require_python_reads(path);
  CHECK(std::vector<fs::path>(fs::directory_iterator(temp.path), {}) == std::vector{path});
}

TEST_CASE("dataset: bad shapes and names are refused before any file is touched", "[dataset]") {
  Dataset dataset = study_dataset();
  SECTION("a variable of the wrong size") {
    std::get<std::vector<double>>(dataset.variables[0].values).pop_back();
    require_refused(dataset, "variable 'vf'", "has 29 values, its dimensions make 30");
  }
  SECTION("a dimension that is not a coordinate") {
    dataset.variables[2].dims[1] = "modes";
    require_refused(dataset, "variable 'frequency'", "dimension 'modes'");
  }
  SECTION("a name used twice") {
    dataset.variables[1].name = "z";
    require_refused(dataset, "variable 'z'", "used twice");
  }
  SECTION("a name with a slash") {
    dataset.variables[0].name = "exit/speed";
    require_refused(dataset, "variable 'exit/speed'", "'/'");
  }
  SECTION("strings with units") {
    dataset.variables[0] = {"bat_note", "m", "text", {"bat"}, std::vector<std::string>{"a", "b"}, {}, {}};
    require_refused(dataset, "variable 'bat_note'", "take no units");
    dataset = study_dataset();
    dataset.coordinates[0].units = "1";
    require_refused(dataset, "coordinate 'bat'", "take no units");
  }
  SECTION("a coordinate with both values and integers") {
    dataset.coordinates[1].integers = {1, 2, 3, 4, 5};
    require_refused(dataset, "coordinate 'z'", "exactly one of");
  }
  SECTION("a coordinate with both values and labels") {
    dataset.coordinates[0].values = {1.0, 2.0};
    require_refused(dataset, "coordinate 'bat'", "exactly one of values, labels and integers");
  }
  SECTION("an empty coordinate") {
    dataset.coordinates[3].integers.clear();
    require_refused(dataset, "coordinate 'mode'", "exactly one of values, labels and integers");
  }
}

TEST_CASE("dataset: a refused dataset leaves an existing file byte for byte", "[dataset]") {
  const TempDir temp;
  const fs::path path = temp.path / "study.h5";
  write_dataset(path, study_dataset());
  const std::string before = read_bytes(path);
  Dataset bad = study_dataset();
  std::get<std::vector<std::int32_t>>(bad.variables[1].values).push_back(0);
  CHECK_THROWS_AS(write_dataset(path, bad), std::invalid_argument);
  CHECK(read_bytes(path) == before);
  CHECK_FALSE(fs::exists(fs::path(path) += ".tmp"));
}

TEST_CASE("dataset: an HDF5 failure midway names the file and leaves the old one", "[dataset]") {
  const TempDir temp;
  const fs::path path = temp.path / "study.h5";
  write_dataset(path, study_dataset());
  const std::string before = read_bytes(path);
  Dataset bad = study_dataset();
  // Valid in shape, but HDF5 refuses a second attribute of the same name after half the file.
  bad.variables[2].text_attributes.push_back({"units", "kHz"});
  CHECK_THROWS_WITH(write_dataset(path, bad),
                    Catch::StartsWith(path.string() + ": ") && Catch::Contains("'units'"));
  CHECK(read_bytes(path) == before);
  CHECK_FALSE(fs::exists(fs::path(path) += ".tmp"));
}

TEST_CASE("dataset: a directory that does not exist is an error naming the path", "[dataset]") {
  const TempDir temp;
  const fs::path path = temp.path / "missing" / "study.h5";
  CHECK_THROWS_WITH(write_dataset(path, study_dataset()),
                    Catch::StartsWith(path.string() + ": ") && Catch::Contains("creating the file"));
}

TEST_CASE("dataset: a million points write in well under a second", "[dataset]") {
  const TempDir temp;
  Dataset dataset;
  dataset.coordinates = {{"z", "m", "impact location", std::vector<double>(1000, 0.5), {}},
                         {"ball_speed", "m/s", "ball speed", std::vector<double>(1000, 40.0), {}}};
  dataset.variables = {
      {"vf", "m/s", "exit speed", {"z", "ball_speed"}, std::vector<double>(1'000'000, 1.0), {}, {}},
      {"status", "1", "status", {"z", "ball_speed"}, std::vector<std::int32_t>(1'000'000, 0), {},
       {}}};
  const auto start = std::chrono::steady_clock::now();
  write_dataset(temp.path / "big.h5", dataset);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  INFO("wrote 1e6 doubles and 1e6 int32 in " << elapsed.count() << " s");
  CHECK(elapsed.count() < 0.5);
}
