// The rig's measures as outputs of impact studies (README "Certification"): e_a at every point,
// bbcor, besr and bpf at pivoted ones, each what the rig gives at the same point; a study asking
// bbcor of a free bat is refused before any work.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "program.hpp"
#include "refusal.hpp"
#include "sweetspot/impact/bat_test_rig.hpp"
#include "sweetspot/study/study_point.hpp"
#include "sweetspot/study/study_results.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

std::string rig_study(const std::string& pivot) {
  return "[scene]\nbat = \"" + source_path("studies/bats/r161.toml") +
         "\"\ncenter = 0.1524\nomega = 0\nball_speed = 60.8\n" + pivot +
         "[axes]\nz = [0.6, 0.7, 0.8]\ne0 = [0.45, 0.5]\n[output]\nvariables = [\"vf\", \"e_a\", \"bbcor\", \"besr\", "
         "\"bpf\", \"status\"]\n";
}

}  // namespace

TEST_CASE("A pivoted study's e_a, bbcor, besr and bpf are the rig's at each point", "[certification][study]") {
  TempDir dir;
  const Study study = load_study(dir.write("rig.toml", rig_study("pivot = true\n")));
  const OutputLayout layout(study);
  const ModalBasis basis = compute_modes(study.designs[0], BeamTheory::timoshenko);
  for (std::size_t i = 0; i < study.points(); ++i) {
    const GridPoint p = grid_point(study, i);
    std::vector<double> row(layout.width);
    layout.extract(simulate_point(p, &basis), row.data());
    RigSettings rig;
    rig.ball = p.scene.ball, rig.ball_speed = p.scene.ball_speed;
    const RigMeasures m = rig_hit(basis, rig, p.scene.z);
    INFO("z " << p.scene.z << ", e0 " << p.scene.ball.e0);
    CHECK(row[1] == m.e_a);
    CHECK(row[1] == row[0] / 60.8);  // at rest, e_a is v_f / v_ball
    CHECK(row[2] == m.bbcor);
    CHECK(row[3] == row[1] + 0.5);
    CHECK(row[4] == row[2] / p.scene.ball.e0);
  }
}

TEST_CASE("A study asking bbcor, besr or bpf of a free bat is refused, e_a is not", "[certification][study]") {
  TempDir dir;
  for (const std::string pivot : {"", "pivot = false\n"}) {
    dir.write("out.h5", "\x89HDF\r\n\x1a\nan earlier result");
    const ProgramRun run = run_program("run " + dir.write("free.toml", rig_study(pivot)).string() + " -o " + dir / "out.h5");
    require_refused(run, {"key 'output.variables[2]' = \"bbcor\" (string): needs a pivoted bat"});
  }
  std::string axis = rig_study("");
  axis.replace(axis.find("e0 = [0.45, 0.5]"), 16, "pivot = [true, false]");
  const ProgramRun run = run_program("run " + dir.write("axis.toml", axis).string() + " -o " + dir / "out.h5");
  CHECK(run.exit_code == 2);
  std::string free_e_a = rig_study("");
  free_e_a.replace(free_e_a.find("\"bbcor\", \"besr\", \"bpf\", "), 24, "");
  const Study study = load_study(dir.write("e_a.toml", free_e_a));
  CHECK(std::ranges::count(study.outputs, "e_a") == 1);
}
