// Large slice counts (up to max_slices = 4096): every path a user reaches with --slices or
// `slices =` stays banded (no dense 2N x 2N matrix unless every mode is asked), a certification
// past max_certify_full_slices takes the partial solve and agrees with the full one, and what
// would take longer than is practical (the full solve past max_full_solve_slices, a partial solve
// of too many modes) is refused with one line before any work.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "study_dir.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/input_error.hpp"

using namespace sweetspot;

namespace {

const std::string r161_file = source_path("studies/bats/r161.toml");
const std::string alloy_file = source_path("studies/bats/alloy_bbcor.toml");

double bbcor_at(int slices) {
  BatSource source;
  CertifyOptions options;
  options.slices = slices;
  return certify(load_bat_design(alloy_file, source), find_standard("bbcor"), options).measure;
}

}  // namespace

TEST_CASE("At 4096 slices the lowest modes come from the banded solve and converge to those at 336",
          "[large_slices]") {
  const ModalBasis fine = compute_modes(resample(load_bat(r161_file), 4096), BeamTheory::timoshenko,
                                        ModeRequest::lowest(4));
  const ModalBasis coarse = compute_modes(resample(load_bat(r161_file), 336), BeamTheory::timoshenko,
                                          ModeRequest::lowest(4));
  REQUIRE(fine.count() == 6);
  CHECK(fine.vectors.rows() == 2 * 4096);
  CHECK(!fine.complete());
  // Second-order convergence (beam_system.cpp): 336 slices are within 1e-4 of the limit in f1..f4.
  for (int n = 2; n < 6; ++n) CHECK(std::abs(fine.omega(n) / coarse.omega(n) - 1) < 1e-4);
  // The rigid modes stay exact: the mass of 4096 slices is the bat's.
  CHECK(std::abs(fine.mass / coarse.mass - 1) < 1e-12);
}

TEST_CASE("Every mode past 1024 slices and a partial solve of too many modes are refused before any work",
          "[large_slices][bounds]") {
  const Bat bat = resample(load_bat(r161_file), 2048);
  CHECK_THROWS_AS(compute_modes(bat, BeamTheory::timoshenko, ModeRequest::all()), InputError);
  CHECK_THROWS_WITH(compute_modes(bat, BeamTheory::timoshenko, ModeRequest::all()),
                    Catch::Contains("slices = 2048") && Catch::Contains("1024 slices"));
  // (2 * 1024)^3 / (2 * 4096) = 1024^2: 1024 modes at most, two of them rigid.
  CHECK(practical_mode_count(2 * 4096) == 1024);
  CHECK(practical_mode_count(2 * 1024) == 2 * 1024);
  CHECK(impractical_solve(4096, BeamTheory::timoshenko, ModeRequest::lowest(1023)).has_value());
  CHECK(!impractical_solve(4096, BeamTheory::timoshenko, ModeRequest::lowest(1022)).has_value());
  CHECK(!impractical_solve(1024, BeamTheory::timoshenko, ModeRequest::all()).has_value());
  CHECK(impractical_solve(1025, BeamTheory::timoshenko, ModeRequest::all()).has_value());
  // auto's request below a frequency is counted first: a tolerance so tight that it asks for
  // most of the 8192 modes is refused, not solved.
  CHECK_THROWS_WITH(compute_modes(resample(load_bat(r161_file), 4096), BeamTheory::timoshenko,
                                  ModeRequest::below(1e9)),
                    Catch::Contains("slices = 4096") && Catch::Contains("more than is practical"));
}

TEST_CASE("A certification past 512 slices takes the partial solve and agrees with the full one",
          "[large_slices][certification]") {
  // 512 slices: every mode, the whole beam held; 513 and 4096: the modes the scan asks. The
  // hollow alloy bat's held modes converge the slowest (certification.cpp, held_reach).
  const double full = bbcor_at(max_certify_full_slices);
  CHECK(std::abs(bbcor_at(max_certify_full_slices + 1) / full - 1) < 1e-5);
  CHECK(std::abs(bbcor_at(4096) / full - 1) < 1e-5);
}

TEST_CASE("The commands refuse an impractical solve with one line naming the option or key", "[large_slices][bounds]") {
  require_refused(run_program("impact --bat " + r161_file + " --slices 2048 --modes all --z 0.7 --ball-speed 40 "
                              "--cm-speed 10 --omega 40"),
                  {"slices = 2048", "every mode", "1024 slices", "auto"});
  require_refused(run_program("modes " + r161_file + " --slices 4096 --count 1100"),
                  {"--count 1100", "4096 slices", "at most 1022"});
  require_refused(run_program("certify " + r161_file + " --slices 2048 --modes all"), {"slices = 2048", "every mode"});
  StudyDir study(3, "slices = 2048\n");
  std::string text = file_text(study.study);
  text.replace(text.find("modes = 18"), 10, "modes = \"all\"");
  study.dir.write("study.toml", text);
  require_refused(run_program("run " + study.study.string()), {"key 'scene.modes' = \"all\"", "2048 slices", "1024"});
}

// Issue 24: "a length typed in mm (length = 838.2) is silently cut into 4096 slices". The bounds
// table (parameter_bounds.cpp) refuses it before any slice is cut.
TEST_CASE("A bat length typed in millimetres is refused, not cut into slices", "[large_slices][bounds]") {
  TempDir dir;
  std::string text = file_text(alloy_file);
  text.replace(text.find("length = 0.8382"), 15, "length = 838.2");
  require_refused(run_program("modes " + dir.write("mm.toml", text).string()),
                  {"mm.toml:8: key 'length': value 838.2", "0.001 to 2 m"});
}
