// Studies that ask for time histories (study.hpp): the dataset's dimensions with one and with
// several probes, and the history keys refused, naming file, key and value, before any work.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "program.hpp"
#include "sweetspot/study/study_results.hpp"
#include "temp_dir.hpp"

namespace {

// The high-impact scene at two impact points, with 1 ms of history.
std::string history_study(const std::string& scene_extra, const std::string& outputs,
                          const std::string& axes_extra = "") {
  return "[scene]\nbat = \"" + source_path("studies/bats/r161.toml") +
         "\"\nball_speed = 40\ncenter = 0.09\nomega = 51\nhistory_window = 1e-3\n" + scene_extra +
         "[axes]\nz = [0.655, 0.705]\n" + axes_extra + "[output]\nvariables = " + outputs + "\n";
}

// Runs the study and checks the dims of its variables in Python (`checks`: asserts on `d`).
void check_dataset(const std::string& study_text, const std::string& checks) {
  TempDir dir;
  const auto study = dir.write("study.toml", study_text);
  const ProgramRun run = run_program("run " + study.string() + " -o " + dir / "out.h5 --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun check = run_command(std::string(python) + " -c \"import xarray as x, numpy as np; d = x.open_dataset('" +
                                       dir / "out.h5" + "', engine='h5netcdf'); " + checks + "; print('ok')\"");
  INFO(check.output);
  CHECK(check.exit_code == 0);
}

}  // namespace

TEST_CASE("A study with several probes stores histories over (axes, probe, time)", "[run][histories]") {
  check_dataset(history_study("probes = [0.06, 0.13, 0.20]\nmodes = 4\n",
                              "[\"displacement\", \"vibration_acceleration\", \"force\", \"compression\", "
                              "\"ball_position\", \"force_response\", \"mode_response\", \"status\"]"),
                "assert d.displacement.dims == ('z', 'probe', 'time'); "
                "assert d.vibration_acceleration.dims == ('z', 'probe', 'time'); "
                "assert list(d.probe.values) == [0.06, 0.13, 0.2] and d.probe.units == 'm'; "
                "assert d.sizes['time'] == 201 and abs(float(d.time[-1]) - 1e-3) < 1e-12 and d.time.units == 's'; "
                "assert d.force.dims == ('z', 'time') and d.force.units == 'N'; "
                "assert d.compression.dims == d.ball_position.dims == ('z', 'time'); "
                "assert d.force_response.dims == ('z', 'omega_tau') and d.sizes['omega_tau'] == 201; "
                "assert abs(float(d.force_response.isel(omega_tau=0).min()) - 1) < 1e-6; "
                "assert d.mode_response.dims == ('z', 'mode') and d.sizes['mode'] == 4; "
                "assert all(d[v].long_name for v in d.variables); "
                "assert np.isfinite(d.displacement).all() and float(abs(d.force).max()) > 1000");
}

TEST_CASE("A study with one probe stores histories over (axes, time) alone", "[run][histories]") {
  check_dataset(history_study("probes = [0.13]\n", "[\"velocity\", \"acceleration\", \"status\"]"),
                "assert d.velocity.dims == ('z', 'time') and d.acceleration.dims == ('z', 'time'); "
                "assert 'probe' not in d.dims and d.velocity.units == 'm/s'; "
                "assert d.acceleration.units == 'm/s^2' and 'omega_tau' not in d.dims");
}

TEST_CASE("Bad history keys are refused naming file, key and value", "[run][histories]") {
  TempDir dir;
  struct Case {
    std::string text, key, value;
  };
  const std::string displacement = "[\"displacement\"]";
  const Case cases[] = {
      {history_study("probes = [0.06, 2.5]\n", displacement), "scene.probes", "2.5"},
      {history_study("probes = [0.06, -0.1]\n", displacement), "scene.probes[1]", "-0.1"},
      {history_study("probes = [0.06, 0.06]\n", displacement), "scene.probes", "0.06"},
      {history_study("", displacement, "probes = [0.06, 0.13]\n"), "axes.probes", "[...]"},
      {history_study("", displacement), "output.variables[0]", "\"displacement\""},
      {history_study("probes = [0.06]\nhistory_step = 0\n", displacement), "scene.history_step", "0"},
      {history_study("probes = [0.06]\nhistory_step = -1e-6\n", displacement), "scene.history_step", "-1e-06"},
      {history_study("probes = [0.06]\nhistory_step = 1e-9\n", displacement), "scene.history_step", "1e-09"},
      {history_study("probes = 0.06\n", displacement), "scene.probes", "0.06"},
      {history_study("modes = \"all\"\n", "[\"mode_response\"]"), "output.variables[0]", "\"mode_response\""},
  };
  for (const Case& c : cases) {
    const auto study = dir.write("bad.toml", c.text);
    const ProgramRun run = run_program("run " + study.string() + " -o " + dir / "out.h5");
    INFO(c.text << "\n" << run.output);
    CHECK(run.exit_code != 0);
    CHECK_THAT(run.output, Catch::Contains("bad.toml") && Catch::Contains("'" + c.key + "'") &&
                               Catch::Contains("= " + c.value));
  }
}

TEST_CASE("A failed point gives NaN throughout its histories and responses", "[run][histories]") {
  TempDir dir;
  const auto file = dir.write("study.toml", history_study("probes = [0.06, 0.13]\nmodes = 4\n",
                                                          "[\"velocity\", \"force\", \"force_response\", "
                                                          "\"mode_response\", \"status\"]"));
  const sweetspot::OutputLayout layout(sweetspot::load_study(file));
  CHECK(layout.width == 2 * 201 + 201 + 201 + 4 + 1);
  sweetspot::ImpactResult failed;
  failed.status = sweetspot::CollisionStatus::no_separation;
  std::vector<double> row(layout.width, 0.0);
  layout.extract(failed, row.data());
  for (int i = 0; i + 1 < layout.width; ++i) CHECK(std::isnan(row[i]));
  CHECK(row.back() == static_cast<double>(sweetspot::CollisionStatus::no_separation));
}
