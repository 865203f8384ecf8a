// Study files: the shipped studies load, the grid runs row-major over the axes in the order
// written, defaults and overrides land where they should, and every kind of bad study fails
// before any work with one InputError line naming the file, the key and the value.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "program.hpp"
#include "temp_dir.hpp"
#include "text_edit.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/study.hpp"
#include "sweetspot/uncertainty/uncertainty_study.hpp"
#include "sweetspot/study/study_memory.hpp"

namespace fs = std::filesystem;
using namespace sweetspot;

namespace {

// A valid study; bad studies are this with one line changed.
constexpr std::string_view good_study = R"(title = "test"
[scene]
bat = "bats/r161.toml"
z = 0.7
ball_speed = 40
center = 0.09
omega = 51
e0 = 0.5
[axes]
z = [0.5, 0.6, 0.7]
[output]
variables = ["vf", "e_eff"]
)";

// Valid studies of the other kinds, for the same purpose.
constexpr std::string_view wall_study = R"(title = "wall"
kind = "wall"
[scene]
e0 = 0.5
[axes]
ball_speed = [1, 11, 45, 67]
[output]
variables = ["vf", "e_eff"]
)";

constexpr std::string_view toy_study = R"(title = "toy"
kind = "toy"
[scene]
omega_tau = 2
[output]
variables = ["vf", "status"]
)";

// A fresh directory with a copy of studies/bats, for study files that name bats relative to
// themselves; removed afterwards.
struct StudyDir : TempDir {
  const fs::path& dir = path;

  StudyDir() { fs::copy(source_path("studies/bats"), path / "bats", fs::copy_options::recursive); }
  Study load(std::string_view text) const { return load_study(write("study.toml", text)); }
};

// load_study must throw an InputError whose single line names the study file and contains every
// fragment (the key, the value, what was expected).
void require_error(std::string_view text, std::initializer_list<std::string_view> fragments) {
  const StudyDir dir;
  const fs::path file = dir.write("study.toml", text);
  try {
    load_study(file);
  } catch (const InputError& e) {
    const std::string message = e.what();
    INFO("message: " << message);
    CHECK(message.find('\n') == std::string::npos);
    CHECK_THAT(message, Catch::StartsWith(file.string()));
    for (const std::string_view fragment : fragments) CHECK_THAT(message, Catch::Contains(std::string(fragment)));
    return;
  }
  FAIL("load_study did not throw for:\n" << text);
}

void require_error(std::string_view from, std::string_view to, std::initializer_list<std::string_view> fragments) {
  require_error(with(good_study, from, to), fragments);
}

std::vector<double> axis_values(const Study& study, std::string_view name) {
  for (const Axis& axis : study.axes)
    if (axis.name == name) return axis.values;
  FAIL("no axis " << name);
  return {};
}

}  // namespace

TEST_CASE("every shipped study loads", "[study]") {
  const std::vector<std::pair<std::string, std::size_t>> expected = {
      {"low_impact.toml", 54},     {"high_impact.toml", 3 * 44}, {"high_impact_energy.toml", 44},
      {"e_eff_full.toml", 44},     {"e_eff_half.toml", 44},      {"pivot.toml", 2 * 2 * 54},
      {"design_space.toml", 2 * 44 * 21 * 21}, {"wall.toml", 18}, {"toy.toml", 61}};
  std::set<std::string> found;
  for (const auto& entry : fs::directory_iterator(source_path("studies"))) {
    if (entry.path().extension() != ".toml") continue;
    if (entry.path().filename().string().starts_with("optimize_")) continue;  // optimisations: test_optimize.cpp
    INFO(entry.path());
    // Uncertainty studies draw their samples first (test_uncertainty.cpp); then they are studies too.
    const Study study = entry.path().filename().string().starts_with("uncertainty_")
                            ? load_uncertainty_study(entry.path()).study
                            : load_study(entry.path());
    found.insert(entry.path().filename().string());
    CHECK(study.points() >= 1);
    CHECK(!study.title.empty());
    CHECK(study.text.starts_with('#'));  // each says what it reproduces
    CHECK(study.bats.size() == study.bat_names.size());
    std::vector<std::size_t> order = task_order(study);
    std::ranges::sort(order);
    for (std::size_t i = 0; i < order.size(); ++i) REQUIRE(order[i] == i);
    CHECK_NOTHROW(grid_point(study, study.points() - 1));
  }
  for (const auto& [name, points] : expected) {
    INFO(name);
    REQUIRE(found.count(name));
    CHECK(load_study(source_path("studies/" + name)).points() == points);
  }
}

TEST_CASE("the grid is row-major over the axes in the order written", "[study]") {
  const StudyDir dir;
  const Study study = dir.load(with(good_study, "z = [0.5, 0.6, 0.7]\n",
                                    "z = [0.5, 0.6, 0.7]\nball_speed = [20.0, 40.0]\n"
                                    "bat = [\"bats/r161.toml\", \"bats/torpedo.toml\"]\n"));
  REQUIRE(study.axes.size() == 3);
  CHECK(study.axes[0].name == "z");
  CHECK(study.axes[1].name == "ball_speed");
  CHECK(study.axes[2].name == "bat");
  CHECK(study.axes[2].values == std::vector<double>{0, 1});
  CHECK(study.axes[2].labels == std::vector<std::string>{"bats/r161.toml", "bats/torpedo.toml"});
  CHECK(study.bat_names == std::vector<std::string>{"R161", "torpedo"});
  REQUIRE(study.bats.size() == 2);
  CHECK(study.bats[1] == (dir.dir / "bats" / "torpedo.toml").lexically_normal());
  REQUIRE(study.points() == 12);

  const GridPoint p = grid_point(study, 7);  // 7 = (1 * 2 + 1) * 2 + 1
  CHECK(p.coords == std::vector<std::size_t>{1, 1, 1});
  CHECK(p.scene.z == 0.6);
  CHECK(p.scene.ball_speed == 40.0);
  CHECK(p.bat == 1);
  const GridPoint q = grid_point(study, 4);  // (1, 0, 0)
  CHECK(q.coords == std::vector<std::size_t>{1, 0, 0});
  CHECK(q.scene.ball_speed == 20.0);
  CHECK(q.bat == 0);
  CHECK(grid_point(study, 11).coords == std::vector<std::size_t>{2, 1, 1});
  CHECK_THROWS_AS(grid_point(study, 12), std::out_of_range);
}

TEST_CASE("defaults fill what the study leaves out", "[study]") {
  const StudyDir dir;
  const Study study = dir.load("[scene]\nbat = \"bats/r161.toml\"\nz = 0.7\nball_speed = 40\ncenter = 0.09\n");
  const ImpactScene& s = study.base;
  CHECK(study.title.empty());
  CHECK(study.points() == 1);
  CHECK(study.axes.empty());
  CHECK(study.outputs == std::vector<std::string>{"vf", "e_eff", "contact_time", "collision_time", "status"});
  CHECK(study.outputs == default_outputs());
  CHECK(study.theory == BeamTheory::timoshenko);
  CHECK(study.slices == 0);
  CHECK(s.integrator.method == Method::exact);  // studies step exactly by default
  CHECK(s.z == 0.7);
  CHECK(s.ball_speed == 40);
  CHECK(s.ball.e0 == 0.5);
  CHECK(s.ball.mass == 0.145);
  CHECK(s.ball.radius == 0.0366);
  CHECK(s.ball.k1 == 6.53e7);
  CHECK(s.ball.a == 1.84);
  CHECK(s.swing.about_center);
  CHECK(s.swing.center == 0.09);
  CHECK(s.swing.omega == 0);
  CHECK_FALSE(s.pivoted);
  CHECK(s.vibrational_modes == auto_modes);  // the library's and the impact command's default too
  CHECK(s.integrator.dt == default_step(Method::exact));
  CHECK(s.integrator.window == 5e-3);
  const GridPoint p = grid_point(study, 0);
  CHECK(p.coords.empty());
  CHECK(p.scene.z == 0.7);
  CHECK(p.bat == 0);
  CHECK(study.bat_names == std::vector<std::string>{"R161"});
}

TEST_CASE("every scene key is read, and an axis overrides [scene]", "[study]") {
  const StudyDir dir;
  const Study study = dir.load(R"(
[scene]
bat = "bats/torpedo.toml"
theory = "euler-bernoulli"
slices = 40
z = 0.7
ball_speed = 30
e0 = 0.6
ball_mass = 0.15
ball_radius = 0.037
k1 = 7e7
a = 2
cm_speed = 20
omega = 40
pivot = false
modes = "all"
integrator = "rk4"
dt = 3e-7
window = 1e-3
[axes]
z = [0.6, 0.8]
omega = [10, 20]
)");
  const ImpactScene& s = study.base;
  CHECK(study.theory == BeamTheory::euler_bernoulli);
  CHECK(study.slices == 40);
  CHECK(study.bat_names == std::vector<std::string>{"torpedo"});
  CHECK(s.z == 0.7);  // the base keeps [scene]'s value; the points take the axis's
  CHECK(s.ball_speed == 30);
  CHECK(s.ball.e0 == 0.6);
  CHECK(s.ball.mass == 0.15);
  CHECK(s.ball.radius == 0.037);
  CHECK(s.ball.k1 == 7e7);
  CHECK(s.ball.a == 2);
  CHECK_FALSE(s.swing.about_center);
  CHECK(s.swing.cm_speed == 20);
  CHECK(s.vibrational_modes == all_modes);
  CHECK(s.integrator.dt == 3e-7);  // RK4 with all 80 modes of 40 EB slices needs dt < 3.3e-7
  CHECK(s.integrator.window == 1e-3);
  const GridPoint p = grid_point(study, 3);
  CHECK(p.scene.z == 0.8);
  CHECK(p.scene.swing.omega == 20);
  CHECK(p.slices == 40);
  CHECK(p.theory == BeamTheory::euler_bernoulli);
  CHECK(p.scene.ball.e0 == 0.6);
}

TEST_CASE("a key given only as an axis needs no [scene] entry", "[study]") {
  const StudyDir dir;
  const Study study = dir.load(R"(
[scene]
bat = "bats/r161.toml"
[axes]
center = [0.09, 0.15]
ball_speed = [40]
z = [0.7]
)");
  CHECK(study.points() == 2);
  CHECK(study.base.swing.about_center);
  const GridPoint p = grid_point(study, 1);
  CHECK(p.scene.swing.about_center);
  CHECK(p.scene.swing.center == 0.15);
}

TEST_CASE("ranges, booleans, names and 'all' make axes", "[study]") {
  const StudyDir dir;
  const auto axis = [&](std::string_view line) {
    return axis_values(dir.load(with(good_study, "z = [0.5, 0.6, 0.7]", line)), line.substr(0, line.find(' ')));
  };
  SECTION("step: stop included when it lands on a point, values as a reader writes them") {
    const std::vector<double> z = axis("z = { start = 0.305, stop = 0.835, step = 0.01 }");
    REQUIRE(z.size() == 54);
    CHECK(z[3] == 0.335);
    CHECK(z.back() == 0.835);
    CHECK(axis("z = { start = 0.3, stop = 0.35, step = 0.02 }") == std::vector<double>{0.3, 0.32, 0.34});
    CHECK(axis("z = { start = 0.7, stop = 0.5, step = -0.1 }") == std::vector<double>{0.7, 0.6, 0.5});
    CHECK(axis("z = { start = 0.7, stop = 0.7, step = 0.1 }") == std::vector<double>{0.7});
  }
  SECTION("count: both ends included") {
    CHECK(axis("e0 = { start = 0.3, stop = 0.6, count = 4 }") == std::vector<double>{0.3, 0.4, 0.5, 0.6});
    CHECK(axis("e0 = { start = 0.3, stop = 0.6, count = 1 }") == std::vector<double>{0.3});
  }
  SECTION("count with spacing = \"log\": both ends exact, a constant ratio between") {
    const std::vector<double> e0 = axis("e0 = { start = 0.1, stop = 1, count = 3, spacing = \"log\" }");
    REQUIRE(e0.size() == 3);
    CHECK(e0[0] == 0.1);
    CHECK(e0[1] == Approx(std::sqrt(0.1)).epsilon(1e-14));
    CHECK(e0[2] == 1);
    CHECK(axis("e0 = { start = 0.3, stop = 0.6, count = 4, spacing = \"linear\" }") ==
          std::vector<double>{0.3, 0.4, 0.5, 0.6});
  }
  SECTION("integer axes") {
    CHECK(axis("slices = { start = 20, stop = 40, step = 10 }") == std::vector<double>{20, 30, 40});
    CHECK(axis("modes = [0, 1, 18, \"all\"]") == std::vector<double>{0, 1, 18, all_modes});
    CHECK(axis("modes = { start = 0, stop = 4, count = 5 }") == std::vector<double>{0, 1, 2, 3, 4});
  }
  SECTION("pivot: booleans as 0 and 1") {
    const Study study = dir.load(with(good_study, "z = [0.5, 0.6, 0.7]", "pivot = [false, true]"));
    CHECK(axis_values(study, "pivot") == std::vector<double>{0, 1});
    CHECK_FALSE(grid_point(study, 0).scene.pivoted);
    CHECK(grid_point(study, 1).scene.pivoted);
  }
  SECTION("theory: names as labels, BeamTheory as values") {
    const Study study =
        dir.load(with(good_study, "z = [0.5, 0.6, 0.7]", "theory = [\"euler-bernoulli\", \"timoshenko\"]"));
    CHECK(study.axes[0].labels == std::vector<std::string>{"euler-bernoulli", "timoshenko"});
    CHECK(grid_point(study, 0).theory == BeamTheory::euler_bernoulli);
    CHECK(grid_point(study, 1).theory == BeamTheory::timoshenko);
  }
}

TEST_CASE("tasks run model-major: each (bat, slices, theory) in one contiguous run", "[study]") {
  const StudyDir dir;
  const Study study = dir.load(with(good_study, "z = [0.5, 0.6, 0.7]\n",
                                    "z = [0.5, 0.6, 0.7]\nbat = [\"bats/r161.toml\", \"bats/torpedo.toml\"]\n"
                                    "e0 = [0.4, 0.5]\nslices = [42, 84]\n"));
  REQUIRE(study.points() == 24);
  REQUIRE(models(study) == 4);
  const std::vector<std::size_t> order = task_order(study);
  for (std::size_t model = 0; model < 4; ++model) {
    const GridPoint first = grid_point(study, order[model * 6]);
    CHECK(first.bat == model / 2);
    CHECK(first.slices == (model % 2 ? 84 : 42));
    for (std::size_t t = model * 6; t < model * 6 + 6; ++t) {
      const GridPoint p = grid_point(study, order[t]);
      CHECK(p.bat == first.bat);
      CHECK(p.slices == first.slices);
      CHECK(p.theory == first.theory);
    }
  }
  // Within a model the other axes stay row-major: z slowest, e0 fastest.
  CHECK(grid_point(study, order[1]).scene.ball.e0 == 0.5);
  CHECK(grid_point(study, order[2]).scene.z == 0.6);
  std::vector<std::size_t> sorted = order;
  std::ranges::sort(sorted);
  for (std::size_t i = 0; i < sorted.size(); ++i) CHECK(sorted[i] == i);
}

TEST_CASE("outputs: any ImpactResult field, mode_energy with a fixed mode count", "[study]") {
  const StudyDir dir;
  const Study study = dir.load(
      with(with(good_study, "e0 = 0.5", "e0 = 0.5\nmodes = 18"), "[\"vf\", \"e_eff\"]", "[\"status\", \"mode_energy\", \"u_max\"]"));
  CHECK(study.outputs == std::vector<std::string>{"status", "mode_energy", "u_max"});
  CHECK(study.base.vibrational_modes == 18);
  // The comparisons cost time: computed only for a study that names them.
  CHECK_FALSE(study.base.rigid_comparison);
  CHECK_FALSE(study.base.van_zandt_comparison);
  const Study compared = dir.load(with(good_study, "[\"vf\", \"e_eff\"]", "[\"vf\", \"vf_van_zandt\", \"vf_rigid\"]"));
  CHECK(compared.base.rigid_comparison);
  CHECK(compared.base.van_zandt_comparison);
  CHECK_FALSE(compared.base.integrator.record_force);  // simulate_impact records it for Van Zandt alone
  std::string all;
  for (const std::string& name : output_names()) all += (all.empty() ? "\"" : ", \"") + name + "\"";
  // The histories at the probes need probes.
  // The rig's measures need a pivoted bat.
  const std::string probed = with(good_study, "e0 = 0.5\n", "e0 = 0.5\nmodes = 18\nprobes = [0.13]\npivot = true\n");
  const Study every = dir.load(with(probed, "[\"vf\", \"e_eff\"]", "[" + all + "]"));
  CHECK(every.outputs == output_names());
  CHECK(every.base.histories);
  CHECK(every.base.force_response);
  CHECK(every.base.mode_response);
  CHECK(every.base.history.probes == std::vector<double>{0.13});
  CHECK_FALSE(study.base.histories);  // only when asked
  CHECK_FALSE(study.base.force_response);
}

TEST_CASE("each kind has its outputs and its defaults", "[study]") {
  using V = std::vector<std::string>;
  CHECK(output_names() == output_names(StudyKind::impact));
  CHECK(std::ranges::count(output_names(), "vf_rigid") == 1);
  CHECK(std::ranges::count(output_names(), "vf_van_zandt") == 1);
  CHECK(default_outputs(StudyKind::impact) == V{"vf", "e_eff", "contact_time", "collision_time", "status"});
  CHECK(output_names(StudyKind::wall) == V{"vf", "e_eff", "contact_time", "collision_time", "u_max", "peak_force",
                                           "impulse", "energy_initial", "energy_ball", "energy_ball_dissipated",
                                           "energy_residual", "force", "compression", "ball_position", "status"});
  CHECK(default_outputs(StudyKind::wall) == V{"vf", "e_eff", "contact_time", "collision_time", "status"});
  CHECK(output_names(StudyKind::toy) == V{"vf", "vf_van_zandt", "energy_initial", "energy_ball",
                                          "energy_bat_translation", "energy_vibration", "energy_residual", "status"});
  CHECK(default_outputs(StudyKind::toy) ==
        V{"vf", "vf_van_zandt", "energy_ball", "energy_bat_translation", "energy_vibration", "status"});
}

TEST_CASE("a wall study: the ball and its speed, no bat", "[study]") {
  const StudyDir dir;
  const Study study = dir.load(wall_study);
  CHECK(study.kind == StudyKind::wall);
  CHECK_FALSE(has_bat(study.kind));
  CHECK(study.bats.empty());
  CHECK(study.bat_names.empty());
  CHECK(study.outputs == std::vector<std::string>{"vf", "e_eff"});
  REQUIRE(study.points() == 4);
  CHECK(models(study) == 1);
  const GridPoint p = grid_point(study, 2);
  CHECK(p.kind == StudyKind::wall);
  CHECK(p.scene.ball_speed == 45);
  CHECK(p.scene.ball.e0 == 0.5);
  CHECK(p.scene.integrator.dt == default_step(Method::exact));
  CHECK(dir.load(with(wall_study, "[output]\nvariables = [\"vf\", \"e_eff\"]\n", "")).outputs ==
        default_outputs(StudyKind::wall));
}

TEST_CASE("a toy study: omega tau, alone or as a log axis", "[study]") {
  const StudyDir dir;
  const Study single = dir.load(toy_study);
  CHECK(single.kind == StudyKind::toy);
  CHECK(single.bats.empty());
  CHECK(single.omega_tau == 2);
  CHECK(single.points() == 1);
  CHECK(grid_point(single, 0).omega_tau == 2);
  CHECK(grid_point(single, 0).kind == StudyKind::toy);
  const Study swept = dir.load("kind = \"toy\"\n[axes]\nomega_tau = { start = 0.05, stop = 50, count = 61, "
                               "spacing = \"log\" }\n");
  CHECK(swept.outputs == default_outputs(StudyKind::toy));
  const std::vector<double> omega_tau = axis_values(swept, "omega_tau");
  REQUIRE(omega_tau.size() == 61);
  CHECK(omega_tau.front() == 0.05);
  CHECK(omega_tau[20] == Approx(0.5).epsilon(1e-14));  // 20 points a decade
  CHECK(omega_tau[40] == Approx(5).epsilon(1e-14));
  CHECK(omega_tau.back() == 50);
  CHECK(grid_point(swept, 60).omega_tau == 50);
}

TEST_CASE("bad studies: the kind and what belongs to it", "[study]") {
  SECTION("unknown kind") {
    require_error("title = \"test\"", "kind = \"cannon\"",
                  {"study.toml:1:", "key 'kind' = \"cannon\" (string)", "\"impact\", \"wall\", \"toy\""});
  }
  SECTION("kind not a string") { require_error("title = \"test\"", "kind = 3", {"key 'kind' = 3", "\"wall\""}); }
  SECTION("a bat on the wall") {
    require_error(with(wall_study, "e0 = 0.5", "e0 = 0.5\nbat = \"bats/r161.toml\""),
                  {"study.toml:5:", "key 'scene.bat' = \"bats/r161.toml\"", "does not apply to kind \"wall\"",
                   "ball_speed"});
  }
  SECTION("an impact point on the wall") {
    require_error(with(wall_study, "[axes]", "[axes]\nz = [0.6, 0.7]"),
                  {"key 'axes.z' = [...]", "does not apply to kind \"wall\""});
  }
  SECTION("a swing on the wall") {
    require_error(with(wall_study, "e0 = 0.5", "center = 0.09"),
                  {"key 'scene.center' = 0.09", "does not apply to kind \"wall\""});
  }
  SECTION("the wall needs a speed toward it") {
    require_error(with(wall_study, "[1, 11, 45, 67]", "[1, 0]"), {"key 'axes.ball_speed' = 0", "> 0", "wall"});
    require_error(with(wall_study, "ball_speed = [1, 11, 45, 67]", "e0 = [0.5]"),
                  {"key 'scene.ball_speed' is missing"});
  }
  SECTION("bat outputs from the wall") {
    require_error(with(wall_study, "[\"vf\", \"e_eff\"]", "[\"vf\", \"energy_vibration\"]"),
                  {"key 'output.variables[1]' = \"energy_vibration\"", "does not apply to kind \"wall\"", "u_max"});
  }
  SECTION("omega tau not > 0") {
    require_error(with(toy_study, "omega_tau = 2", "omega_tau = 0"), {"key 'scene.omega_tau' = 0", "> 0"});
    require_error(with(toy_study, "omega_tau = 2", "omega_tau = -1.5"), {"key 'scene.omega_tau' = -1.5", "> 0"});
    require_error(with(toy_study, "[scene]\nomega_tau = 2", "[axes]\nomega_tau = [0.5, inf]"),
                  {"key 'axes.omega_tau[1]' = inf", "> 0"});
  }
  SECTION("the toy needs omega tau") {
    require_error(with(toy_study, "omega_tau = 2\n", ""), {"key 'scene.omega_tau' is missing"});
  }
  SECTION("ball keys in the toy") {
    require_error(with(toy_study, "omega_tau = 2", "omega_tau = 2\ne0 = 0.5"),
                  {"key 'scene.e0' = 0.5", "does not apply to kind \"toy\"", "omega_tau"});
  }
  SECTION("wall outputs from the toy") {
    require_error(with(toy_study, "[\"vf\", \"status\"]", "[\"vf\", \"peak_force\"]"),
                  {"key 'output.variables[1]' = \"peak_force\"", "does not apply to kind \"toy\"", "vf_van_zandt"});
  }
  SECTION("toy keys on a bat, bat outputs from the toy") {
    require_error("e0 = 0.5", "omega_tau = 2", {"key 'scene.omega_tau' = 2", "does not apply to kind \"impact\""});
    require_error(with(toy_study, "[\"vf\", \"status\"]", "[\"vf_rigid\"]"),
                  {"key 'output.variables[0]' = \"vf_rigid\"", "does not apply to kind \"toy\""});
  }
}

TEST_CASE("bad studies: the file and its syntax", "[study]") {
  SECTION("missing file") {
    const StudyDir dir;
    const fs::path file = dir.dir / "nowhere.toml";
    CHECK_THROWS_WITH(load_study(file), Catch::Contains(file.string()) && Catch::Contains("not found"));
  }
  SECTION("syntax error") { require_error("omega = 51", "omega = = 51", {"study.toml:7:", "TOML syntax error"}); }
  SECTION("title not a string") { require_error("title = \"test\"", "title = 3", {"key 'title' = 3", "string"}); }
  SECTION("title with a NUL character") {  // the dataset's title stopped at it: "a"
    require_error("title = \"test\"", "title = \"a\\u0000b\"", {"key 'title'", "without NUL characters"});
  }
  SECTION("section not a table") {
    require_error(
        with(with(good_study, "[output]\nvariables = [\"vf\", \"e_eff\"]", ""), "title = \"test\"", "output = 3"),
        {"key 'output' = 3", "table"});
  }
}

TEST_CASE("bad studies: unknown keys", "[study]") {
  SECTION("top level") {
    require_error("title = \"test\"", "colour = \"red\"", {"key 'colour' = \"red\"", "unknown key"});
  }
  SECTION("[scene]") {
    require_error("omega = 51", "omgea = 51", {"study.toml:7:", "key 'scene.omgea' = 51", "unknown key", "omega"});
  }
  SECTION("[axes]") {
    require_error("z = [0.5, 0.6, 0.7]", "height = [1]", {"key 'axes.height' = [...]", "unknown key"});
  }
  SECTION("not an axis") {
    require_error("z = [0.5, 0.6, 0.7]", "integrator = [\"rk4\"]", {"key 'axes.integrator'", "cannot be an axis"});
  }
  SECTION("axis table") {
    require_error("z = [0.5, 0.6, 0.7]", "z = { start = 0.5, stop = 0.7, stepp = 0.1 }",
                  {"key 'axes.z.stepp' = 0.1", "unknown key"});
  }
  SECTION("[output]") { require_error("variables =", "vars =", {"key 'output.vars' = [...]", "unknown key"}); }
}

TEST_CASE("bad studies: wrong types", "[study]") {
  SECTION("string for a number") {
    require_error("e0 = 0.5", "e0 = \"0.5\"", {"key 'scene.e0' = \"0.5\" (string)", "number"});
  }
  SECTION("float for an integer") {
    require_error("e0 = 0.5", "slices = 84.5", {"key 'scene.slices' = 84.5", "integer"});
  }
  SECTION("list element") {
    require_error("z = [0.5, 0.6, 0.7]", "ball_speed = [20, \"fast\"]",
                  {"key 'axes.ball_speed[1]' = \"fast\"", "number"});
  }
  SECTION("scalar for an axis") {
    require_error("z = [0.5, 0.6, 0.7]", "z = 0.5", {"key 'axes.z' = 0.5", "a list of"});
  }
  SECTION("range for booleans") {
    require_error("z = [0.5, 0.6, 0.7]", "pivot = { start = 0, stop = 1, step = 1 }",
                  {"key 'axes.pivot' = {...}", "true or false"});
  }
  SECTION("pivot not a boolean") { require_error("e0 = 0.5", "pivot = 1", {"key 'scene.pivot' = 1", "true or false"}); }
  SECTION("modes") { require_error("e0 = 0.5", "modes = \"some\"", {"key 'scene.modes' = \"some\"", "\"all\""}); }
  SECTION("theory") {
    require_error("e0 = 0.5", "theory = \"bernoulli\"", {"key 'scene.theory' = \"bernoulli\"", "euler-bernoulli"});
  }
  SECTION("integrator") {
    require_error("e0 = 0.5", "integrator = \"euler\"", {"key 'scene.integrator' = \"euler\"", "rk4"});
  }
  SECTION("range bound") {
    require_error("z = [0.5, 0.6, 0.7]", "z = { start = \"a\", stop = 0.7, step = 0.1 }",
                  {"key 'axes.z.start' = \"a\"", "number"});
  }
  SECTION("range missing stop") {
    require_error("z = [0.5, 0.6, 0.7]", "z = { start = 0.5, step = 0.1 }",
                  {"key 'axes.z.stop' is missing", "start, stop"});
  }
}

TEST_CASE("bad studies: empty axes", "[study]") {
  const auto axis = [](std::string_view line, std::initializer_list<std::string_view> fragments) {
    require_error("z = [0.5, 0.6, 0.7]", line, fragments);
  };
  SECTION("empty list") { axis("z = []", {"key 'axes.z' = []", "at least one value"}); }
  SECTION("count 0") { axis("z = { start = 0.5, stop = 0.7, count = 0 }", {"key 'axes.z.count' = 0", "count"}); }
  SECTION("stop below start") {
    axis("z = { start = 0.7, stop = 0.5, step = 0.1 }", {"key 'axes.z.step' = 0.1", "sign"});
  }
  SECTION("step 0") { axis("z = { start = 0.5, stop = 0.7, step = 0 }", {"key 'axes.z.step' = 0", "not 0"}); }
  SECTION("step and count") {
    axis("z = { start = 0.5, stop = 0.7, step = 0.1, count = 3 }", {"key 'axes.z'", "exactly one of step and count"});
  }
  SECTION("too many values") {
    axis("z = { start = 0.5, stop = 0.7, step = 1e-9 }", {"key 'axes.z.step' = 1e-09", "at most"});
  }
  SECTION("repeated value") { axis("z = [0.5, 0.6, 0.5]", {"key 'axes.z' = 0.5", "twice"}); }
  // The first value met again in the order written, not the smallest one repeated.
  SECTION("first repeat") { axis("z = [0.5, 0.6, 0.7, 0.6, 0.5]", {"key 'axes.z' = 0.6", "twice"}); }
  SECTION("step of the wrong sign") {
    axis("z = { start = 0.7, stop = 0.5, step = 0.05 }",
         {"= 0.05: expected a step with the sign of stop - start = -0.2"});
  }
  SECTION("repeated bat") {
    axis("bat = [\"bats/r161.toml\", \"bats/../bats/r161.toml\"]", {"key 'axes.bat'", "r161.toml", "twice"});
  }
  SECTION("log range through 0") {
    axis("z = { start = 0, stop = 0.7, count = 3, spacing = \"log\" }",
         {"key 'axes.z.start' = 0", "log range", "> 0"});
  }
  SECTION("log range with a step") {
    axis("z = { start = 0.5, stop = 0.7, step = 0.1, spacing = \"log\" }",
         {"key 'axes.z.spacing' = \"log\"", "count, not step"});
  }
  SECTION("unknown spacing") {
    axis("z = { start = 0.5, stop = 0.7, count = 3, spacing = \"cubic\" }",
         {"key 'axes.z.spacing' = \"cubic\"", "\"linear\" or \"log\""});
  }
  SECTION("integer range off the integers") {
    axis("slices = { start = 20, stop = 30, count = 4 }", {"key 'axes.slices' = 23.3333", "integer"});
  }
}

TEST_CASE("bad studies: the swing", "[study]") {
  SECTION("both") {
    require_error("omega = 51", "omega = 51\ncm_speed = 24",
                  {"key 'scene.center' = 0.09", "exactly one", "scene.cm_speed"});
  }
  SECTION("both, one an axis") {
    require_error("z = [0.5, 0.6, 0.7]", "cm_speed = [20, 24]",
                  {"key 'scene.center' = 0.09", "exactly one", "axes.cm_speed"});
  }
  SECTION("neither") { require_error("center = 0.09\n", "", {"key 'scene.center' is missing", "cm_speed"}); }
  SECTION("pivot needs the centre") {
    require_error(
        with(with(good_study, "center = 0.09", "cm_speed = 24"), "z = [0.5, 0.6, 0.7]", "pivot = [false, true]"),
        {"key 'axes.pivot' = true", "rotation centre"});
  }
}

TEST_CASE("bad studies: values", "[study]") {
  SECTION("e0 above 1") { require_error("e0 = 0.5", "e0 = 1.5", {"study.toml:8:", "key 'scene.e0' = 1.5", "[0.05, 1]"}); }
  SECTION("e0 0 in an axis") {
    require_error("z = [0.5, 0.6, 0.7]", "e0 = [0.5, 0]", {"key 'axes.e0[1]' = 0", "[0.05, 1]"});
  }
  SECTION("e0 range leaving (0, 1]") {
    require_error("z = [0.5, 0.6, 0.7]", "e0 = { start = 0.8, stop = 1.2, step = 0.2 }",
                  {"key 'axes.e0' = 1.2", "[0.05, 1]"});
  }
  SECTION("a") { require_error("e0 = 0.5", "a = 0", {"key 'scene.a' = 0", "[0.5, 3]"}); }
  SECTION("k1") { require_error("e0 = 0.5", "k1 = -6.53e7", {"key 'scene.k1' = -65300000", "[1000, 1e12]"}); }
  SECTION("dt") { require_error("e0 = 0.5", "dt = 0", {"key 'scene.dt' = 0", "[5e-9, 1e-3]"}); }
  SECTION("window") { require_error("e0 = 0.5", "window = -1", {"key 'scene.window' = -1", "> 0"}); }
  SECTION("ball mass") { require_error("e0 = 0.5", "ball_mass = 0", {"key 'scene.ball_mass' = 0", "[0.001, 10] kg"}); }
  SECTION("nan") { require_error("ball_speed = 40", "ball_speed = nan", {"key 'scene.ball_speed' = nan", "finite"}); }
  SECTION("inf in an axis") {
    require_error("z = [0.5, 0.6, 0.7]", "omega = [51, inf]", {"key 'axes.omega[1]' = inf", "finite"});
  }
  SECTION("slices") { require_error("e0 = 0.5", "slices = 2", {"key 'scene.slices' = 2", "4 to 4096"}); }
  SECTION("negative modes") { require_error("e0 = 0.5", "modes = -1", {"key 'scene.modes' = -1", "modes"}); }
  SECTION("z negative") { require_error("z = [0.5, 0.6, 0.7]", "z = [-0.1]", {"key 'axes.z[0]' = -0.1", ">= 0"}); }
  SECTION("z beyond a bat") {
    require_error("z = [0.5, 0.6, 0.7]", "z = [0.7, 0.845]\nbat = [\"bats/torpedo.toml\", \"bats/r161.toml\"]",
                  {"key 'axes.z' = 0.845", "every bat", "R161", "0.84"});
  }
  SECTION("more modes than the slices give") {
    require_error("e0 = 0.5", "slices = 4\npreset = \"n2000\"", {"key 'scene.modes' = 18 (the n2000 preset)", "6 vibrational modes"});
    require_error("e0 = 0.5", "slices = 4\nmodes = 7", {"key 'scene.modes' = 7", "R161", "6 vibrational modes"});
  }
  SECTION("required keys") {
    require_error("ball_speed = 40\n", "", {"key 'scene.ball_speed' is missing", "[axes]"});
    require_error(with(with(good_study, "z = 0.7\n", ""), "z = [0.5, 0.6, 0.7]", "e0 = [0.5]"),
                  {"key 'scene.z' is missing"});
  }
}

TEST_CASE("bad studies: bats", "[study]") {
  SECTION("missing bat file") {
    require_error("bat = \"bats/r161.toml\"", "bat = \"bats/nope.toml\"",
                  {"study.toml:3:", "key 'scene.bat' = \"bats/nope.toml\"", "file not found"});
  }
  SECTION("missing bat in an axis") {
    require_error("z = [0.5, 0.6, 0.7]", "bat = [\"bats/r161.toml\", \"nope.toml\"]",
                  {"key 'axes.bat' = \"nope.toml\"", "file not found"});
  }
  SECTION("bad bat file") {
    const StudyDir dir;
    dir.write("bats/broken.toml", "name = \"broken\"\nlength = -1\n");
    const fs::path file = dir.write("study.toml", with(good_study, "bats/r161.toml", "bats/broken.toml"));
    CHECK_THROWS_WITH(load_study(file), Catch::Contains("key 'scene.bat' = \"bats/broken.toml\"") &&
                                            Catch::Contains("broken.toml:2: key 'length'"));
  }
  SECTION("two bats of one name") {
    const StudyDir dir;
    fs::copy_file(dir.dir / "bats" / "r161.toml", dir.dir / "bats" / "copy.toml");
    const fs::path file = dir.write(
        "study.toml", with(good_study, "z = [0.5, 0.6, 0.7]", "bat = [\"bats/r161.toml\", \"bats/copy.toml\"]"));
    CHECK_THROWS_WITH(load_study(file),
                      Catch::Contains("key 'axes.bat' = \"bats/copy.toml\"") && Catch::Contains("own name"));
  }
  SECTION("no bat") { require_error("bat = \"bats/r161.toml\"\n", "", {"key 'scene.bat' is missing"}); }
  SECTION("empty path") { require_error("bat = \"bats/r161.toml\"", "bat = \"\"", {"key 'scene.bat' = \"\"", "path"}); }
}

TEST_CASE("bad studies: outputs", "[study]") {
  const auto outputs = [](std::string_view list, std::initializer_list<std::string_view> fragments) {
    require_error("[\"vf\", \"e_eff\"]", list, fragments);
  };
  SECTION("unknown name") {
    outputs("[\"vf\", \"speed\"]", {"key 'output.variables[1]' = \"speed\"", "expected one of", "e_eff"});
  }
  SECTION("duplicate") { outputs("[\"vf\", \"e_eff\", \"vf\"]", {"key 'output.variables[2]' = \"vf\"", "twice"}); }
  SECTION("empty") { outputs("[]", {"key 'output.variables' = [...]", "non-empty"}); }
  SECTION("not a string") { outputs("[\"vf\", 3]", {"key 'output.variables[1]' = 3", "expected one of"}); }
  SECTION("mode_energy with a modes axis") {
    require_error(
        with(with(good_study, "z = [0.5, 0.6, 0.7]", "modes = [0, 18]"), "[\"vf\", \"e_eff\"]", "[\"mode_energy\"]"),
        {"key 'output.variables[0]' = \"mode_energy\"", "fixed number of modes"});
  }
  SECTION("mode_energy with all modes") {
    require_error(with(with(good_study, "e0 = 0.5", "modes = \"all\""), "[\"vf\", \"e_eff\"]", "[\"mode_energy\"]"),
                  {"key 'output.variables[0]' = \"mode_energy\"", "fixed number of modes"});
  }
  // A key only some outputs read, in a study that asks none of them, ran and was recorded as if it
  // had counted: the air without a flight, a history's window without a history, the sweet
  // spot's keys without its outputs, e_a_speed without bbs_linear.
  SECTION("the air without the flight") {
    require_error("e0 = 0.5", "e0 = 0.5\ntemperature = 300",
                  {"key 'scene.temperature' = 300", "read by the flight's outputs", "asks none of them"});
    require_error("z = [0.5, 0.6, 0.7]", "wind_speed = [0, 5]", {"key 'axes.wind_speed' = [...]", "flight's"});
  }
  SECTION("a history's window without a history") {
    require_error("e0 = 0.5", "e0 = 0.5\nhistory_window = 0.002", {"key 'scene.history_window'", "histories"});
  }
  SECTION("the sweet spot's keys without its outputs") {
    require_error("[\"vf\", \"e_eff\"]", "[\"vf\", \"e_eff\"]\nsweet_spot_of = \"vf\"",
                  {"key 'output.sweet_spot_of' = \"vf\"", "sweet_spot_z, sweet_spot_vf, sweet_spot_width"});
    require_error("[\"vf\", \"e_eff\"]", "[\"vf\", \"sweet_spot_z\"]\nsweet_spot_fraction = 0.02",
                  {"key 'output.sweet_spot_fraction' = 0.02", "read by sweet_spot_width alone"});
  }
  SECTION("e_a_speed without bbs_linear") {
    require_error("e0 = 0.5", "e0 = 0.5\ne_a_speed = 30", {"key 'scene.e_a_speed' = 30", "bbs_linear"});
  }
}

TEST_CASE("A key some outputs read is taken beside one of them", "[study]") {
  const StudyDir dir;
  CHECK(dir.load(with(with(good_study, "e0 = 0.5", "e0 = 0.5\ntemperature = 300\ne_a_speed = 30"),
                      "[\"vf\", \"e_eff\"]", "[\"vf\", \"distance\", \"bbs_linear\"]"))
            .air.temperature == 300);
}

TEST_CASE("the memory a study needs grows with its points, outputs and bats, and a bound names the axes",
          "[study][bounds]") {
  const StudyDir dir;
  const std::string axes = "[axes]\nz = [0.6, 0.7, 0.8]\nball_speed = [30.0, 40.0]\n";
  const std::string scene = "[scene]\nbat = \"bats/r161.toml\"\ncenter = 0.09\nomega = 51\nmodes = 0\n";
  const Study small = dir.load(scene + axes + "[output]\nvariables = [\"vf\"]\n");
  const Study wide = dir.load(scene + axes + "[output]\nvariables = [\"vf\", \"status\", \"force\"]\n");
  // No modes: 8 bytes a value, twice (results, dataset), the task order and a chunk in flight.
  CHECK(sweetspot::study_memory_bytes(small) == 6 * (2 * 8 * 1 + 16) + 2 * 8 * 1 * 6);
  CHECK(sweetspot::study_memory_bytes(wide) == 6 * (2 * 8 * 603 + 16) + 2 * 8 * 603 * 6);  // force: 601 samples
  CHECK_NOTHROW(sweetspot::check_study_memory(wide, sweetspot::study_memory_bytes(wide)));
  try {
    sweetspot::check_study_memory(wide, sweetspot::study_memory_bytes(wide) - 1);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("6 points = z (3) x ball_speed (2), 603 values each"));
  }
}
