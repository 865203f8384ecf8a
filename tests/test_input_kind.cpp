// A command given another command's input file (an optimisation file to `run`, a study to
// `optimize`, an uncertainty study to `convergence`) says what the file is and which command runs
// it, in one line with exit status 2, where each reader named the first key it did not know
// ("unknown key 'bat'"). The output is not touched.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "sweetspot/study/input_kind.hpp"
#include "temp_dir.hpp"

using sweetspot::InputKind;

TEST_CASE("An input file's kind is read from its top-level keys", "[study]") {
  CHECK(sweetspot::input_kind(source_path("studies/design_space.toml"), "study file") == InputKind::study);
  CHECK(sweetspot::input_kind(source_path("studies/uncertainty_bbcor.toml"), "study file") ==
        InputKind::uncertainty_study);
  CHECK(sweetspot::input_kind(source_path("studies/optimize_maple.toml"), "optimisation file") ==
        InputKind::optimisation);
}

TEST_CASE("A command given another command's file says what it is and which command runs it", "[study]") {
  TempDir dir;
  const std::string study = source_path("studies/design_space.toml");
  const std::string uncertainty = source_path("studies/uncertainty_bbcor.toml");
  const std::string optimisation = source_path("studies/optimize_maple.toml");
  const std::string earlier = "\x89HDF\r\n\x1a\nan earlier result";
  const std::filesystem::path out = dir.write("out.h5", earlier);
  require_refused(run_program("run " + optimisation + " -o " + out.string()),
                  {"optimize_maple.toml: run does not take an optimisation file", "`sweetspot optimize`"});
  require_refused(run_program("optimize " + study + " -o " + out.string()),
                  {"design_space.toml: optimize does not take a study", "`sweetspot run`"});
  require_refused(run_program("optimize " + uncertainty + " -o " + out.string()),
                  {"optimize does not take an uncertainty study", "`sweetspot run`"});
  require_refused(run_program("convergence " + uncertainty + " -o " + out.string()),
                  {"convergence does not take an uncertainty study"});
  require_refused(run_program("convergence " + optimisation + " -o " + out.string()),
                  {"convergence does not take an optimisation file"});
  require_refused(run_program("certify --uncertainty " + study), {"certify --uncertainty does not take a study"});
  std::ostringstream kept;
  kept << std::ifstream(out, std::ios::binary).rdbuf();
  CHECK(kept.str() == earlier);
  // A file that is not there is named as each command names its input.
  require_refused(run_program("optimize " + dir / "none.toml"), {"optimisation file not found"});
  require_refused(run_program("run " + dir / "none.toml"), {"study file not found"});
}
