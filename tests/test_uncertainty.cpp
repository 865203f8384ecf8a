// Uncertainty studies: the sampler and the estimators against distributions and models whose
// answers are known in closed form, a rigid bat's exit speed (linear in the ball's and the bat's
// speeds) among them, the same bits on any ranks and threads, and the refusals.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "study_dir.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/formulas.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/study_point.hpp"
#include "sweetspot/uncertainty/statistics.hpp"
#include "sweetspot/uncertainty/uncertainty_study.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

bool within(double x, const Estimate& e) { return e.lower <= x && x <= e.upper; }

std::vector<double> draw_one(const InputDistribution& d, std::size_t size, SamplingMethod method) {
  SamplingPlan plan;
  plan.size = size;
  plan.method = method;
  plan.seed = 7;
  return draw_samples({d}, plan, "test").front();
}

}  // namespace

TEST_CASE("Sample means and standard deviations of known distributions lie within their intervals", "[uncertainty]") {
  const double z95 = 1.6448536269514722;  // the standard normal's 95 % quantile
  for (const SamplingMethod method :
       {SamplingMethod::monte_carlo, SamplingMethod::latin_hypercube, SamplingMethod::low_discrepancy}) {
    const InputDistribution normal{"ball_speed", Shape::normal, 40, 2};
    const InputDistribution truncated{"e0", Shape::truncated_normal, 0.5, 0.03, 0.47, 0.56};
    const InputDistribution uniform{"z", Shape::uniform, 0, 0, 0.70, 0.72};
    const InputDistribution lognormal{"bat.density", Shape::lognormal, 649, 30};
    for (const InputDistribution& d : {normal, truncated, uniform, lognormal}) {
      INFO(to_string(method) << " " << to_string(d.shape));
      const SampleSummary s = summarize(draw_one(d, 2000, method), 0.99, {0.05, 0.5, 0.95});
      CHECK(s.count == 2000);
      CHECK(within(d.expected_value(), s.mean));
      CHECK(within(std::sqrt(d.variance()), s.sd));
      if (d.shape == Shape::normal) {
        CHECK(within(d.mean - z95 * d.sd, s.quantiles[0]));
        CHECK(within(d.mean, s.quantiles[1]));
        CHECK(within(d.mean + z95 * d.sd, s.quantiles[2]));
      }
      if (d.shape == Shape::truncated_normal || d.shape == Shape::uniform) {  // never outside the bounds
        CHECK(s.quantiles[0].lower >= d.lower);
        CHECK(s.quantiles[2].upper <= d.upper);
      }
    }
  }
}

TEST_CASE("The mean's interval is Student's and shrinks as one over the root of the sample size", "[uncertainty]") {
  const InputDistribution normal{"ball_speed", Shape::normal, 40, 2};
  const SampleSummary small = summarize(draw_one(normal, 400, SamplingMethod::monte_carlo), 0.95, {0.5});
  const SampleSummary large = summarize(draw_one(normal, 6400, SamplingMethod::monte_carlo), 0.95, {0.5});
  // Half-width t s / sqrt(n): 16 times the samples, a quarter of the width (s and t vary slightly).
  const double ratio = (small.mean.upper - small.mean.lower) / (large.mean.upper - large.mean.lower);
  CHECK(ratio == Approx(4).epsilon(0.05));
  CHECK(small.mean.upper - small.mean.value == Approx(small.mean.value - small.mean.lower));
}

TEST_CASE("Correlated inputs have the Gaussian copula's correlation", "[uncertainty]") {
  // Normal marginals under a Gaussian copula are jointly normal: their Pearson correlation is r.
  // Its estimate from n pairs has atanh(r_hat) ~ N(atanh(r), 1/(n - 3)): 99.9 % within 3.29 sd.
  const std::vector<InputDistribution> inputs = {{"ball_speed", Shape::normal, 40, 2}, {"e0", Shape::normal, 0.5, 0.01}};
  for (const SamplingMethod method : {SamplingMethod::monte_carlo, SamplingMethod::low_discrepancy}) {
    SamplingPlan plan;
    plan.size = 4000, plan.method = method, plan.correlations = {{0, 1, 0.6}};
    const auto x = draw_samples(inputs, plan, "test");
    const SampleSummary a = summarize(x[0], 0.95, {0.5}), b = summarize(x[1], 0.95, {0.5});
    double covariance = 0;
    for (std::size_t i = 0; i < x[0].size(); ++i) covariance += (x[0][i] - a.mean.value) * (x[1][i] - b.mean.value);
    const double r = covariance / static_cast<double>(x[0].size() - 1) / (a.sd.value * b.sd.value);
    INFO(to_string(method) << ": r = " << r);
    CHECK(std::abs(std::atanh(r) - std::atanh(0.6)) < 3.29 / std::sqrt(4000.0 - 3));
  }
}

TEST_CASE("A probability's interval is Clopper-Pearson's", "[uncertainty]") {
  // No success in n trials: the upper bound solves (1 - p)^n = (1 - c) / 2.
  for (const std::size_t n : {10u, 200u})
    CHECK(proportion(0, n, 0.95).upper == Approx(1 - std::pow(0.025, 1.0 / static_cast<double>(n))).epsilon(1e-9));
  CHECK(proportion(200, 200, 0.95).lower == Approx(std::pow(0.025, 1.0 / 200)).epsilon(1e-9));
  const Estimate half = proportion(50, 100, 0.95);
  CHECK(half.value == 0.5);
  CHECK(half.lower + half.upper == Approx(1).epsilon(1e-12));  // symmetric at one half
}

TEST_CASE("Sobol indices of a linear model equal its variance shares and converge", "[uncertainty]") {
  // y = 3 x1 + x2 + 0 x3, x1 ~ N(0, 1), x2 ~ U(-3, 3) (variance 3), x3 ~ N(1, 1): shares 9/12, 3/12, 0.
  std::vector<InputDistribution> inputs = {{"a", Shape::normal, 0, 1}, {"b", Shape::uniform, 0, 0, -3, 3},
                                           {"c", Shape::normal, 1, 1}};
  const double shares[] = {0.75, 0.25, 0};
  double previous_width = 1;
  for (const std::size_t size : {500u, 8000u}) {
    SamplingPlan plan;
    plan.size = size, plan.sensitivity = true, plan.method = SamplingMethod::monte_carlo, plan.seed = 3;
    const auto x = draw_samples(inputs, plan, "test");
    REQUIRE(x.front().size() == size * 5);
    std::vector<double> y(x.front().size());
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = 3 * x[0][i] + x[1][i];
    const SobolIndices s = sobol_indices(x, y, size, 0.99);
    for (std::size_t k = 0; k < 3; ++k) {
      INFO(size << " samples, input " << k << ": " << s.first[k].value << " in [" << s.first[k].lower << ", "
                << s.first[k].upper << "]");
      CHECK(within(shares[k], s.first[k]));
      if (shares[k] > 0)
        CHECK(within(shares[k], s.total[k]));  // additive: no interaction
      else  // y does not read x3: A with x3 from B gives y(A) exactly, so the total index is 0
        CHECK(s.total[k].value == Approx(0).margin(1e-12));
    }
    const double width = s.first[0].upper - s.first[0].lower;
    CHECK(width < previous_width / 2);  // 16 times the samples: about a quarter
    previous_width = width;
  }
}

TEST_CASE("A rigid bat's first-order Sobol indices are the variance shares of its linear exit speed",
          "[uncertainty]") {
  // v_f = A v_ball + B v_bat (physics.md, rigid bat), with R0 = (m/M)(1 + ((z - z_cm)/r_g)^2) from
  // the bat's mass, balance and radius of gyration; the swing has omega = 0, so v_bat = cm_speed.
  TempDir dir;
  const std::string study = R"(kind = "uncertainty"
[scene]
bat = ")" + source_path("studies/bats/r161.toml") + R"("
z = 0.70
omega = 0
modes = 0
[uncertain]
ball_speed = { distribution = "normal", mean = 40, sd = 2 }
cm_speed = { distribution = "normal", mean = 25, sd = 1.5 }
[sampling]
method = "monte_carlo"
size = SIZE
sensitivity = true
confidence = 0.99
[output]
variables = ["vf"]
)";
  const MassProperties bat = mass_properties(load_bat(source_path("studies/bats/r161.toml")));
  const double m = 0.145, z = 0.70;
  const double recoil = m / bat.mass * (1 + std::pow((z - bat.z_cm) / bat.radius_of_gyration(), 2));
  const double a = rigid_exit_speed(0.5, recoil, 1, 0), b = rigid_exit_speed(0.5, recoil, 0, 1);
  const double ball_share = a * a * 4 / (a * a * 4 + b * b * 2.25);
  double previous_width = 1;
  for (const std::string size : {"300", "4800"}) {
    std::string text = study;
    text.replace(text.find("SIZE"), 4, size);
    const UncertaintyStudy u = load_uncertainty_study(dir.write("rigid_" + size + ".toml", text));
    const ModalBasis basis = compute_modes(u.study.designs.front(), BeamTheory::timoshenko);
    std::vector<double> vf(u.study.points());
    for (std::size_t i = 0; i < vf.size(); ++i) vf[i] = simulate_point(grid_point(u.study, i), &basis).vf;
    std::vector<std::vector<double>> inputs;
    for (const Axis& drawn : u.study.sampled) inputs.push_back(drawn.values);
    const SobolIndices s = sobol_indices(inputs, vf, u.plan.size, 0.99);
    INFO(size << " samples: ball " << s.first[0].value << " in [" << s.first[0].lower << ", " << s.first[0].upper
              << "], expected " << ball_share);
    CHECK(within(ball_share, s.first[0]));
    CHECK(within(1 - ball_share, s.first[1]));
    const double width = s.first[0].upper - s.first[0].lower;
    CHECK(width < previous_width / 2);
    previous_width = width;
  }
}

TEST_CASE("An uncertainty study gives the same dataset bit for bit on any ranks and threads", "[uncertainty][mpi]") {
  TempDir dir;
  const auto study = dir.write("scatter.toml", R"(kind = "uncertainty"
[scene]
bat = ")" + source_path("studies/bats/r161.toml") + R"("
z = 0.70
center = 0.09
omega = 51
ball_speed = 40
[uncertain]
"bat.density" = { distribution = "lognormal", mean = 649, sd = 30 }
e0 = { distribution = "truncated_normal", mean = 0.5, sd = 0.02, lower = 0.46, upper = 0.54 }
[sampling]
method = "latin_hypercube"
size = 64
sensitivity = true
seed = 11
[output]
variables = ["vf", "e_eff", "status"]
)");
  const ProgramRun serial = run_program("run " + study.string() + " -o " + dir / "serial.h5 --quiet");
  INFO(serial.output);
  REQUIRE(serial.exit_code == 0);
  for (const auto& [ranks, threads] : {std::pair{1, 2}, {2, 1}}) {
    const std::string out = dir / std::to_string(10 * ranks + threads).append(".h5");
    const ProgramRun run = run_program_mpi(ranks, threads, "run " + study.string() + " -o " + out + " --quiet");
    INFO(ranks << " ranks x " << threads << " threads\n" << run.output);
    REQUIRE(run.exit_code == 0);
    const ProgramRun compare = run_command(std::string(python) + " " + source_path("tests/compare_datasets.py") + " " +
                                           dir / "serial.h5" + " " + out);
    INFO(compare.output);
    CHECK(compare.exit_code == 0);
  }
}

TEST_CASE("A bad uncertainty study is refused with one line before any work", "[uncertainty]") {
  TempDir dir;
  const std::string head = "kind = \"uncertainty\"\n[scene]\nbat = \"" + source_path("studies/bats/r161.toml") +
                           "\"\nz = 0.7\ncenter = 0.09\nomega = 51\nball_speed = 40\n";
  const std::string sampling = "[sampling]\nsize = 10\n";
  const std::pair<std::string, std::string> cases[] = {
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = -0.02 }\n" + sampling,
       "key 'uncertain.e0.sd' = -0.02: expected a standard deviation > 0"},
      {"[uncertain]\ne0 = { distribution = \"truncated_normal\", mean = 0.5, sd = 0.02, lower = 0.52, upper = 0.6 }\n" +
           sampling,
       "key 'uncertain.e0.mean' = 0.5: expected a mean within the bounds [0.52, 0.6]"},
      {"[uncertain]\nball_sped = { distribution = \"normal\", mean = 40, sd = 1 }\n" + sampling,
       "key 'uncertain.ball_sped' = {...}: expected a numeric key of kind \"impact\""},
      {"[uncertain]\n\"bat.densty\" = { distribution = \"normal\", mean = 649, sd = 10 }\n" + sampling,
       "bat.densty"},
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.02 }\n[sampling]\nsize = 0\n",
       "key 'sampling.size' = 0: expected a whole number of samples >= 2"},
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.02 }\n[sampling]\nsize = 1e14\n",
       "key 'sampling.size' = 1e+14"},
      // Under 1e9 points, but 9.5e8 points of 3 inputs need some 84 GB before a value is drawn.
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.02 }\nk1 = { distribution = \"normal\", "
       "mean = 6.53e7, sd = 1e6 }\na = { distribution = \"uniform\", lower = 1.8, upper = 1.9 }\n[sampling]\n"
       "size = 190000000\nsensitivity = true\n",
       "GB, more than half the"},
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.9, sd = 0.2 }\n[sampling]\nsize = 200\n",
       "truncate the distribution"},
      {"[uncertain]\ne0 = { distribution = \"gauss\", mean = 0.5, sd = 0.02 }\n" + sampling,
       "key 'uncertain.e0.distribution' = \"gauss\""},
      // Three correlations no joint distribution has: x1 ~ x2 and x2 ~ x3 strongly, x1 ~ x3 against both.
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.01 }\nk1 = { distribution = \"normal\", "
       "mean = 6.53e7, sd = 1e6 }\na = { distribution = \"uniform\", lower = 1.8, upper = 1.9 }\n[sampling]\n"
       "size = 10\nmethod = \"monte_carlo\"\ncorrelation = [[\"e0\", \"k1\", 0.9], [\"k1\", \"a\", 0.9], "
       "[\"e0\", \"a\", -0.9]]\n",
       "key 'sampling.correlation': the correlation matrix it makes is not positive definite"},
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.01 }\nk1 = { distribution = \"normal\", "
       "mean = 6.53e7, sd = 1e6 }\n[sampling]\nsize = 10\ncorrelation = [[\"e0\", \"k1\", 1.5]]\n",
       "key 'sampling.correlation[0]'"},
      // A pair twice (the later overruled the earlier), a seed past OpenTURNS's 32 bits (it aliased
      // a smaller one), Sobol' indices from too few samples, a quantile level twice.
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.01 }\nk1 = { distribution = \"normal\", "
       "mean = 6.53e7, sd = 1e6 }\n[sampling]\nsize = 10\nmethod = \"monte_carlo\"\n"
       "correlation = [[\"e0\", \"k1\", 0.5], [\"k1\", \"e0\", -0.5]]\n",
       "key 'sampling.correlation[1]' = [...] (array): expected each pair of keys once"},
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.01 }\n[sampling]\nsize = 10\n"
       "seed = 4294967296\n",
       "key 'sampling.seed' = 4294967296: expected a whole number from 0 to 4294967295"},
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.01 }\n[sampling]\nsize = 16\n"
       "sensitivity = true\n",
       "key 'sampling.size' = 16: expected at least 64 samples with sensitivity = true"},
      {"[uncertain]\ne0 = { distribution = \"normal\", mean = 0.5, sd = 0.01 }\n[sampling]\nsize = 10\n"
       "quantiles = [0.5, 0.5]\n",
       "expected each level once"},
      // Parameters OpenTURNS cannot take (its own error left with exit 1), and a truncated normal
      // so wide that its draws left their window.
      {"[uncertain]\npitch_spin = { distribution = \"uniform\", lower = -1e308, upper = 1e308 }\n" + sampling,
       "key 'uncertain.pitch_spin.upper' = 1e+308: expected bounds whose difference is a finite number"},
      {"[uncertain]\n\"bat.density\" = { distribution = \"lognormal\", mean = 649, sd = 1e-300 }\n" + sampling,
       "key 'uncertain.bat.density.sd' = 1e-300: expected sd / mean from 1e-100 to 1e100"},
      {"[uncertain]\ne0 = { distribution = \"truncated_normal\", mean = 0.5, sd = 1e15, lower = 0.4, upper = 0.6 }\n" +
           sampling,
       "key 'uncertain.e0.sd' = 1e+15: expected sd at most 1e6 times upper - lower"},
  };
  for (const auto& [tail, expected] : cases) {
    const auto file = dir.write("bad.toml", head + tail);
    const std::string out = dir / "out.h5";
    const ProgramRun run = run_program("run " + file.string() + " -o " + out);
    INFO(head + tail);
    require_refused(run, expected);
    CHECK(!std::filesystem::exists(out));
    CHECK(!std::filesystem::exists(out + ".journal"));
  }
  // A key that may be an axis but is no number cannot be drawn, and the keys the refusal offers
  // are those that can (it offered slices, theory and pivot too).
  const auto file =
      dir.write("bad.toml", head + "[uncertain]\nslices = { distribution = \"uniform\", lower = 10, upper = 100 }\n" +
                                sampling);
  const ProgramRun run = run_program("run " + file.string() + " -o " + dir / "out.h5");
  require_refused(run, "key 'uncertain.slices' = {...}: expected a numeric key of kind \"impact\"");
  for (const char* not_drawable : {" slices,", " theory,", " pivot,", " modes,", " curved_contact,"})
    CHECK(run.output.find(not_drawable) == std::string::npos);
}

TEST_CASE("certify --uncertainty: a rigid bat's BBCOR is the drawn e0, so it passes as often as e0 <= 0.5",
          "[uncertainty][certification]") {
  // With N2000's ball (one COR at every speed) a rigid bat returns BBCOR = e0 (test_certification_study.cpp):
  // e0 uniform on [0.44, 0.54] passes the 0.500 limit with probability 0.6, and BBCOR's mean is 0.49.
  TempDir dir;
  const auto study = dir.write("rigid_certify.toml", R"(kind = "uncertainty"
model = "certification"
[ball]
preset = "n2000"
[scene]
bat = ")" + source_path("studies/bats/r161.toml") + R"("
modes = 0
[uncertain]
rig_e0 = { distribution = "uniform", lower = 0.44, upper = 0.54 }
[sampling]
method = "monte_carlo"
size = 40
[output]
variables = ["bbcor", "status"]
)");
  const ProgramRun run = run_program("certify --uncertainty " + study.string() + " --json");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const auto triple = [&](const std::string& key) {
    const std::size_t at = run.output.find("\"" + key + "\": [");
    REQUIRE(at != std::string::npos);
    double v[3];
    REQUIRE(std::sscanf(run.output.c_str() + at + key.size() + 4, "[%lf, %lf, %lf]", &v[0], &v[1], &v[2]) == 3);
    return Estimate{v[0], v[1], v[2]};
  };
  CHECK(within(0.6, triple("all")));
  CHECK(within(0.6, triple("bbcor")));
  CHECK(within(0.49, triple("bbcor_mean")));
  CHECK(within(0.1 / std::sqrt(12.0), triple("bbcor_std")));
  // Under mpirun, rank 0 alone prints, the same numbers (the other rank failed reading its empty dataset).
  const ProgramRun ranks = run_program_mpi(2, 1, "certify --uncertainty " + study.string() + " --json");
  INFO(ranks.output);
  CHECK(ranks.exit_code == 0);
  CHECK(ranks.output.find(run.output) != std::string::npos);
  // A bat given as well is refused: the study names its bat. So is any of the rig's settings,
  // which the study sets (ignored, it would certify what was not asked).
  require_refused(run_program("certify r161 --uncertainty " + study.string()), "give one or the other");
  // An empty output kept no dataset with exit status 0, and US units were taken and not used.
  require_refused(run_program("certify --uncertainty " + study.string() + " -o \"\""),
                  {"certify: --output \"\"", "the output path is empty"});
  require_refused(run_program("certify --uncertainty " + study.string() + " --units us"),
                  {"--units us with --uncertainty", "its report is in SI units"});
  for (const std::string option :
       {"--accuracy 5", "--accuracy 1e-3", "--modes 18", "--standard besr", "--ball-speed 93mph"}) {
    INFO(option);
    require_refused(run_program("certify --uncertainty " + study.string() + " " + option),
                    {"certify: " + option.substr(0, option.find(' ')), "with --uncertainty",
                     "the study sets the rig's settings"});
  }
}

TEST_CASE("A killed uncertainty study resumes to the file of an uninterrupted run", "[uncertainty]") {
  TempDir dir;
  const auto study = dir.write("resume.toml", R"(kind = "uncertainty"
[scene]
bat = ")" + source_path("studies/bats/r161.toml") + R"("
center = 0.09
omega = 51
ball_speed = 40
[axes]
z = { start = 0.60, stop = 0.80, step = 0.01 }
[uncertain]
"bat.youngs_modulus" = { distribution = "lognormal", mean = 1.814e10, sd = 2e9 }
[sampling]
size = 150
[output]
variables = ["vf", "sweet_spot_width", "status"]
)");
  const std::string whole = dir / "whole.h5", resumed = dir / "resumed.h5";
  REQUIRE(run_program("run " + study.string() + " -o " + whole + " --quiet").exit_code == 0);
  const ProgramRun killed =
      run_and_kill(SWEETSPOT_PROGRAM, "run " + study.string() + " -o " + resumed + " --quiet", resumed);
  INFO(killed.output);
  REQUIRE_THAT(killed.output, Catch::Contains("killed 137"));
  REQUIRE(std::filesystem::exists(resumed + ".journal"));
  const ProgramRun resume = run_program("run " + study.string() + " -o " + resumed + " --resume");
  INFO(resume.output);
  REQUIRE(resume.exit_code == 0);
  CHECK_THAT(resume.output, Catch::Contains("resuming:"));
  const ProgramRun compare =
      run_command(std::string(python) + " " + source_path("tests/compare_datasets.py") + " " + whole + " " + resumed);
  INFO(compare.output);
  CHECK(compare.exit_code == 0);
}
