// The design optimiser. With rigid bats swung with equal effort, the best density of a bat has a
// closed form the optimiser never sees: the rigid formulas of physics.md §5 and the power law of
// the swing, maximised by a 1-D root of their derivative. NLopt finds it to 1e-4; with a mass
// window below it, the optimum sits on the window's edge within its tolerance. A killed run
// resumes to the same best design; the best design's bat file reads back as the design; a bad
// optimisation file is refused before any work.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "program.hpp"
#include "refusal.hpp"
#include "sweetspot/bat/bat_design_text.hpp"
#include "sweetspot/impact/batted_flight.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/impact/equal_effort.hpp"
#include "sweetspot/impact/formulas.hpp"
#include "sweetspot/optimize/optimizer.hpp"
#include "sweetspot/study/journal.hpp"
#include "sweetspot/study/output_lock.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

const std::string maple = source_path("studies/bats/maple_271.toml");

// The rigid maple 271 at one impact point, its density free, swung with equal effort about a
// centre near the knob (the player's swing measured with the base bat itself).
constexpr double centre = 0.09, omega_ref = 51, pitch = 40, z0 = 0.7, exponent = 0.3;

std::string density_problem(const std::string& constraints = "", const std::string& free = "density = { min = 100, max = 3000 }") {
  return "bat = \"" + maple + "\"\n[free]\n" + free +
         "\n[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\nswing_exponent = 0.3\n"
         "[model]\nmodes = 0\n[objective]\nmaximize = \"mean_bbs\"\npoints = [0.7]\nweights = [1]\n"
         "[optimizer]\nxtol_rel = 1e-10\nmax_evaluations = 400\n" + constraints;
}

OptimizationHistory optimize(const OptimizationProblem& problem) {
  return optimize_design(problem, [&](const std::vector<double>& x) { return evaluate_design(problem, x, serial_map); });
}

// The rigid bat's exit speed at density s times the base's, from the formulas alone: mass and
// moment of inertia scale with s, the swing's speed with s^-n (equal effort against the base).
struct RigidFamily {
  double recoil0;  // R0 of the base bat at z0: (m/M)(1 + ((z0 - z_cm)/r_g)^2)
  double e0 = 0.5, ball_mass = 0.145;

  double numerator(double s) const {
    return (e0 * s - recoil0) * pitch + (1 + e0) * omega_ref * (z0 - centre) * std::pow(s, 1 - exponent);
  }
  double speed(double s) const { return numerator(s) / (s + recoil0); }
  // d speed / ds = (N' (s + R) - N) / (s + R)^2: its numerator.
  double slope(double s) const {
    const double dn = e0 * pitch + (1 - exponent) * (1 + e0) * omega_ref * (z0 - centre) * std::pow(s, -exponent);
    return dn * (s + recoil0) - numerator(s);
  }
  // The root of the slope by bisection, to 1e-12 relative.
  double best_scale(double lo, double hi) const {
    REQUIRE(slope(lo) > 0);
    REQUIRE(slope(hi) < 0);
    while (hi - lo > 1e-12 * hi) {
      const double mid = (lo + hi) / 2;
      (slope(mid) > 0 ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  }
};

RigidFamily rigid_family(const BatDesign& base) {
  const ModalBasis rigid = compute_modes(build_bat(base), BeamTheory::timoshenko, ModeRequest::rigid_only());
  const double m = RigidFamily{}.ball_mass;
  return {m / rigid.mass + m * (z0 - rigid.z_cm) * (z0 - rigid.z_cm) / rigid.moment_of_inertia_cm};
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// An optimisation's journal row: the design, its objective, its constraints, its status, then
// slices_used and four error estimates. forged_journal opens the journal a run of `p` into `out`
// would resume from, for a test to write rows a run did not.
std::size_t journal_width(const OptimizationProblem& p) { return p.free.size() + 1 + p.constraints.size() + 1 + 5; }

Journal forged_journal(const OptimizationProblem& p, const std::string& out) {
  return Journal(Journal::path_for(out),
                 journal_key(p.text, {p.base_source, p.reference_source},
                             static_cast<std::uint64_t>(p.optimizer.max_evaluations), journal_width(p)),
                 false, [](const double*) { return std::string(); });
}

}  // namespace

TEST_CASE("optimize finds the closed-form best density of a rigid bat swung with equal effort", "[optimize]") {
  TempDir dir;
  const std::string algorithm = GENERATE("cobyla", "bobyqa", "mlsl");
  INFO(algorithm);
  std::string text = density_problem();
  text.replace(text.find("xtol_rel"), 0, "algorithm = \"" + algorithm + "\"\n");
  const OptimizationProblem problem = load_optimization(dir.write("opt.toml", text));
  const double rho0 = problem.base.material.density;
  const RigidFamily family = rigid_family(problem.base);
  const double best = rho0 * family.best_scale(100 / rho0, 3000 / rho0);
  const OptimizationHistory history = optimize(problem);
  REQUIRE(history.best >= 0);
  const DesignEvaluation& found = history.evaluations[static_cast<std::size_t>(history.best)];
  CHECK(found.x[0] == Approx(best).epsilon(1e-4));
  // The collision reproduces the rigid formula (physics.md §5), so the best speed too.
  CHECK(found.objective == Approx(family.speed(best / rho0)).epsilon(1e-8));
  // And it is a maximum: the family is slower on both sides.
  CHECK(family.speed(best / rho0) > family.speed(0.9 * best / rho0));
  CHECK(family.speed(best / rho0) > family.speed(1.1 * best / rho0));
}

TEST_CASE("optimize meets an active mass window at its edge within the tolerance", "[optimize]") {
  TempDir dir;
  const BatDesign base = load_optimization(dir.write("free.toml", density_problem())).base;
  const double rho0 = base.material.density, mass0 = design_mass_properties(base).mass;
  const double best_free = rho0 * rigid_family(base).best_scale(100 / rho0, 3000 / rho0);
  // A window whose upper edge is the mass at 80 % of the free optimum's density: the speed still
  // rises there, so the constrained optimum is on the edge, mass proportional to density.
  const double limit = mass0 * 0.8 * best_free / rho0;
  std::ostringstream window;
  window.precision(17);
  window << "constraint_tolerance = 1e-7\n[constraints]\nmass = { min = 0.5, max = " << limit << " }\n";
  const OptimizationProblem problem = load_optimization(dir.write("opt.toml", density_problem(window.str())));
  const OptimizationHistory history = optimize(problem);
  REQUIRE(history.best >= 0);
  const DesignEvaluation& found = history.evaluations[static_cast<std::size_t>(history.best)];
  REQUIRE(problem.constraints.size() == 2);
  const double mass = found.constraints[1];
  CHECK(problem.constraints[1].label() == "mass_max");
  CHECK(mass == Approx(design_mass_properties(design_at(problem, found.x)).mass).epsilon(1e-15));
  CHECK(mass <= limit * (1 + 1e-7));  // met within its tolerance
  CHECK(found.x[0] == Approx(0.8 * best_free).epsilon(1e-4));
  CHECK(feasible(problem, found));
}

TEST_CASE("optimize's spread of impact points is the normal distribution's Gauss-Hermite rule", "[optimize]") {
  TempDir dir;
  std::string text = density_problem();
  const std::string one_point = "points = [0.7]\nweights = [1]";
  text.replace(text.find(one_point), one_point.size(), "spread = { mean = 0.7, sigma = 0.03, points = 6 }");
  const ObjectiveSpec o = load_optimization(dir.write("opt.toml", text)).objective;
  REQUIRE(o.z.size() == 6);
  // n points integrate polynomials to degree 2n - 1 exactly: the normal's moments up to the 11th
  // (odd ones 0, E[(z - mean)^(2k)] = sigma^(2k) (2k - 1)!!).
  double double_factorial = 1;
  for (int k = 0; k <= 11; ++k) {
    double moment = 0;
    for (std::size_t i = 0; i < o.z.size(); ++i) moment += o.weights[i] * std::pow((o.z[i] - 0.7) / 0.03, k);
    if (k >= 2 && k % 2 == 0) double_factorial *= k - 1;
    CHECK(moment == Approx(k % 2 ? 0.0 : double_factorial).margin(1e-9));
  }
}

TEST_CASE("optimize's best design is written as a bat file that reads back as the design", "[optimize]") {
  TempDir dir;
  const OptimizationProblem problem = load_optimization(dir.write(
      "opt.toml", density_problem("", "barrel_diameter = { min = 0.06, max = 0.0667 }\ndensity = { min = 500, max = 900 }")));
  BatDesign design = design_at(problem, {0.0612345678901234, 712.34567890123456});
  design.name = "a \"quoted\" name";
  const auto file = dir.write("best.toml", bat_design_text(design, "two\nlines"));
  BatSource source;
  const BatDesign back = load_bat_design(file, source);
  CHECK(back.name == design.name);
  CHECK(back.length == design.length);
  CHECK(back.material_name == design.material_name);
  for (const std::string& name : design_parameters(design)) CHECK(design_parameter(back, name) == design_parameter(design, name));
  CHECK(back.dimensions->end == design.dimensions->end);
  CHECK(design_mass_properties(back).mass == design_mass_properties(design).mass);
}

TEST_CASE("the best design's bat file reads back whatever control characters its name and comment hold", "[optimize]") {
  // A title, a path or a bat name may hold any character a TOML string can escape: written raw,
  // a \r or a NUL would make the file unreadable to every command. A name refuses a NUL, which a
  // dataset cannot store (bat_file.cpp); the comment, never stored, keeps it.
  TempDir dir;
  const OptimizationProblem problem = load_optimization(dir.write(
      "opt.toml", density_problem("", "barrel_diameter = { min = 0.06, max = 0.0667 }\ndensity = { min = 500, max = 900 }")));
  BatDesign design = design_at(problem, {0.0612345678901234, 712.34567890123456});
  design.name = "carriage\rreturn, delete \x7f, tab\t";
  const auto file = dir.write("best.toml", bat_design_text(design, std::string("title with \r and ") + '\0' + "\nsecond line"));
  BatSource source;
  const BatDesign back = load_bat_design(file, source);
  CHECK(back.name == design.name);
  CHECK(design_mass_properties(back).mass == design_mass_properties(design).mass);
  design.name += '\0';
  CHECK_THROWS_WITH(load_bat_design(dir.write("nul.toml", bat_design_text(design, "")), source),
                    Catch::Contains("without NUL characters") && Catch::Contains("\\u0000"));
}

TEST_CASE("optimize writes every evaluation and the best bat, which certify accepts, and refuses a bad file", "[optimize][program]") {
  TempDir dir;
  const auto opt = dir.write("opt.toml", density_problem("[constraints]\nmass = { max = 0.9 }\n"));
  const ProgramRun run = run_program("optimize " + opt.string() + " -o " + dir / "out.h5 --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun certified = run_program("certify " + dir / "out_best.toml --json");
  INFO(certified.output);
  CHECK(certified.exit_code == 0);
  const ProgramRun struck = run_program("impact --bat " + dir / "out_best.toml" + " --z 0.7 --ball-speed 40 --center 0.09 --omega 51");
  INFO(struck.output);
  CHECK(struck.exit_code == 0);
  const ProgramRun check = run_command(std::string(python) + " -c \"import h5py; f = h5py.File('" + dir / "out.h5" +
                                       "'); b = int(f['best_evaluation'][()]); print(f['design'].shape[0], b, "
                                       "f['feasible'][b], f['design'][b, 0] == f['best_design'][0], "
                                       "f['constraint_value'][b, 0] <= 0.9 * (1 + 1e-6))\"");
  INFO(check.output);
  CHECK(check.output.find(" 1 True True") != std::string::npos);

  // Bad files: one line naming the key, exit 2, nothing written.
  const auto refused = [&](const std::string& text, std::initializer_list<std::string> fragments) {
    const auto bad = dir.write("bad.toml", text);
    require_refused(run_program("optimize " + bad.string() + " -o " + dir / "bad.h5"), fragments);
    CHECK_FALSE(std::filesystem::exists(dir / "bad.h5"));
    CHECK_FALSE(std::filesystem::exists(dir / "bad.h5.journal"));
  };
  refused(density_problem("", "density = { min = 900, max = 800 }"), {"free.density.max", "800", "above min"});
  refused(density_problem("", "girth = { min = 1, max = 2 }"), {"free.girth", "unknown parameter", "barrel_diameter"});
  refused(density_problem("", "density = { min = 800, max = 900 }"), {"free.density", "705.6", "outside"});
  refused(density_problem("", "handle_diameter = { min = 0.02, max = 0.07 }"),
          {"free", "handle_diameter = 0.07", "impossible bat"});
  refused(density_problem("[constraints]\nstandard = \"bbcorr\"\n"), {"constraints.standard", "bbcorr", "bbcor"});
  // The dataset's title stopped at a NUL character.
  refused("title = \"a\\u0000b\"\n" + density_problem(), {"key 'title'", "\\u0000", "without NUL characters"});
  refused(density_problem("[constraints]\nmass = { max = \"heavy\" }\n"), {"constraints.mass.max", "heavy"});
  refused(density_problem("[constraints]\nweight = { max = 1 }\n"), {"constraints.weight", "unknown key"});
  std::string simplex = density_problem();
  simplex.replace(simplex.find("xtol_rel"), 0, "algorithm = \"simplex\"\n");
  refused(simplex, {"optimizer.algorithm", "simplex", "cobyla"});
  // BOBYQA's first step must fit twice in each range: NLopt's invalid argument, refused before any work.
  std::string wide_step = density_problem();
  wide_step.replace(wide_step.find("xtol_rel"), 0, "algorithm = \"bobyqa\"\ninitial_step = 0.8\n");
  refused(wide_step, {"optimizer.initial_step", "0.8", "0.5", "bobyqa"});
  refused(density_problem() + "[objective]\n", {"objective"});
  std::string too_many = density_problem();
  too_many.replace(too_many.find("modes = 0"), 9, "modes = 500");
  refused(too_many, {"model.modes", "500", "at most the"});
  refused("bat = \"" + source_path("studies/bats/r161.toml") + "\"\n[free]\ndensity = { min = 500, max = 900 }\n",
          {"bat", "profile", "[dimensions]"});
  std::string negative_weight = density_problem();
  negative_weight.replace(negative_weight.find("points = [0.7]\nweights = [1]"), 28,
                          "points = [0.6, 0.7]\nweights = [1, -1]");
  refused(negative_weight, {"objective.weights[1]", "-1", "weights >= 0"});  // named by its index
  std::string no_scan = density_problem();
  const std::string mean = "maximize = \"mean_bbs\"\npoints = [0.7]\nweights = [1]";
  no_scan.replace(no_scan.find(mean), mean.size(), "maximize = \"peak_bbs\"");
  refused(no_scan, {"objective.z", "z = {"});
  // A tolerance below the spacing of doubles near the bat would keep the golden section going forever.
  std::string fine_peak = no_scan;
  fine_peak.replace(fine_peak.find("[optimizer]"), 0, "z = { start = 0.5, stop = 0.8, step = 0.05 }\ntolerance = 1e-300\n");
  refused(fine_peak, {"objective.tolerance", "1e-300", "1e-12"});
  // An output that is the optimisation file itself is refused, and the file kept.
  require_refused(run_program("optimize " + opt.string() + " -o " + opt.string()), {opt.string()});
  CHECK(read(opt.string()).find("[free]") != std::string::npos);
}

TEST_CASE("optimize refuses a bound no design can take, naming the file and the key", "[optimize]") {
  // A hoop modulus or a wall of 0 is none (a bat file's 0 means "as youngs_modulus", "solid"):
  // refused at the bound, not as a bare "bat parameter" line without the file.
  TempDir dir;
  const auto hoop = dir.write("hoop.toml", density_problem("", "hoop_modulus = { min = 0, max = 1e11, start = 5e10 }"));
  REQUIRE_THROWS_WITH(load_optimization(hoop),
                      Catch::Contains("hoop.toml") && Catch::Contains("free.hoop_modulus.min") && Catch::Contains("positive"));
  const auto wall = dir.write("wall.toml", density_problem("", "wall_thickness = { min = -0.001, max = 0.004, start = 0.002 }"));
  REQUIRE_THROWS_WITH(load_optimization(wall),
                      Catch::Contains("wall.toml") && Catch::Contains("free.wall_thickness.min") && Catch::Contains("-0.001"));
  // So is a constraint no bat meets: the search ran every evaluation to find none feasible.
  for (const std::string window : {"mass = { max = -1 }", "mass = { max = 0 }", "moi_knob = { min = 0.1, max = 0 }"}) {
    INFO(window);
    const auto none = dir.write("none.toml", density_problem("[constraints]\n" + window + "\n"));
    REQUIRE_THROWS_WITH(load_optimization(none), Catch::Contains("none.toml") && Catch::Contains(".max") &&
                                                    Catch::Contains("expected a bound above"));
  }
}

TEST_CASE("optimize killed mid-run resumes to the same best design, and 2 ranks give the same bits", "[optimize][program]") {
  TempDir dir;
  // A flexible bat, two dimensions free, the sweet spot's width: about 55 evaluations of 5 ms.
  const auto opt = dir.write(
      "opt.toml", "bat = \"" + maple + "\"\n[free]\nbarrel_diameter = { min = 0.0603, max = 0.0667 }\n"
                  "taper_end = { min = 0.55, max = 0.70 }\n[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\n"
                  "[objective]\nmaximize = \"sweet_spot_width\"\n"
                  "z = { start = 0.50, stop = 0.82, step = 0.01 }\nfraction = 0.02\n"
                  "[constraints]\ndrop = { max = 3 }\n[optimizer]\nmax_evaluations = 80\nxtol_rel = 1e-10\n");
  const ProgramRun whole = run_program("optimize " + opt.string() + " -o " + dir / "whole.h5 --quiet");
  INFO(whole.output);
  REQUIRE(whole.exit_code == 0);
  const std::string best = read(dir / "whole_best.toml");
  REQUIRE_FALSE(best.empty());

  // Killed (SIGKILL) once its journal holds 10 evaluations (56-byte header, 64-byte records).
  const std::string out = dir / "killed.h5";
  const ProgramRun killed = run_command(
      "OMP_NUM_THREADS=1 " + std::string(SWEETSPOT_PROGRAM) + " optimize " + opt.string() + " -o " + out +
      " --quiet & pid=$!; while kill -0 $pid 2>/dev/null && [ $(stat -c %s " + out +
      ".journal 2>/dev/null || echo 0) -lt 696 ]; do sleep 0.002; done; kill -9 $pid 2>/dev/null; wait $pid; echo killed $?");
  INFO(killed.output);
  REQUIRE(killed.output.find("killed 137") != std::string::npos);
  REQUIRE(std::filesystem::exists(out + ".journal"));
  CHECK_FALSE(std::filesystem::exists(out));
  // Without --resume the journal is refused and kept.
  require_refused(run_program("optimize " + opt.string() + " -o " + out), {"journal", "--resume"});
  const ProgramRun resumed = run_program("optimize " + opt.string() + " -o " + out + " --resume");
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  CHECK(resumed.output.find("from the journal") != std::string::npos);
  // The same best design and comment (objective to 17 digits, its evaluation and the count).
  std::string resumed_best = read(dir / "killed_best.toml"), whole_best = best;
  CHECK(resumed_best == whole_best);

  const ProgramRun plot = run_command(std::string(python) + " " + source_path("scripts/plot_optimization.py") + " " +
                                      dir / "whole.h5" + " " + dir / "whole.png");
  INFO(plot.output);
  CHECK(plot.exit_code == 0);
  CHECK(std::filesystem::file_size(dir / "whole.png") > 10000);

  const ProgramRun two = run_program_mpi(2, 1, "optimize " + opt.string() + " -o " + dir / "two.h5 --quiet");
  INFO(two.output);
  REQUIRE(two.exit_code == 0);
  CHECK(read(dir / "two_best.toml") == best);
  const ProgramRun same = run_command(std::string(python) + " -c \"import h5py, numpy as n; a = h5py.File('" + dir / "whole.h5" +
                                      "'); b = h5py.File('" + dir / "two.h5" + "'); c = h5py.File('" + out +
                                      "'); print(all(n.array_equal(a[k][()], x[k][()], equal_nan=True) for x in (b, c) "
                                      "for k in ('design', 'objective', 'constraint_value', 'feasible')), "
                                      "c.attrs['resumed_evaluations'] > 0)\"");
  INFO(same.output);
  CHECK(same.output == "True True\n");
}

TEST_CASE("a journaled evaluation of another design is dropped with the later ones, and the run goes on", "[optimize][program]") {
  // A forged record, or a library changed between the kill and the resume: the optimiser asks
  // another design at that evaluation than the journal holds. The resume says so, computes it and
  // everything after it anew, and ends where an uninterrupted run ends.
  TempDir dir;
  const auto opt = dir.write("opt.toml", density_problem());
  const ProgramRun whole = run_program("optimize " + opt.string() + " -o " + dir / "whole.h5 --quiet");
  REQUIRE(whole.exit_code == 0);

  const OptimizationProblem p = load_optimization(opt);
  const std::size_t width = journal_width(p);
  const std::string out = dir / "forged.h5";
  {
    Journal journal = forged_journal(p, out);
    std::vector<double> row(width, 0.0);
    std::fill(row.end() - 4, row.end(), std::nan(""));  // no stated accuracy: no estimates
    row[0] = 2999.5;  // a density inside the bounds that the search does not start from
    row[p.free.size()] = 1.0;  // an objective; status ok
    journal.append({0}, row);
    journal.append({1}, row);
  }
  const ProgramRun resumed = run_program("optimize " + opt.string() + " -o " + out + " --resume");
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  CHECK(resumed.output.find("evaluation 0 is of another design") != std::string::npos);
  CHECK(resumed.output.find("2 in all") != std::string::npos);
  CHECK(read(dir / "forged_best.toml").substr(read(dir / "forged_best.toml").find("\nname")) ==
        read(dir / "whole_best.toml").substr(read(dir / "whole_best.toml").find("\nname")));
}

TEST_CASE("a resumed run's failed evaluation says why it failed, as an uninterrupted run's does", "[optimize][program]") {
  // A bat at rest and a ball at rest never approach: every evaluation fails, with a reason. The
  // journal keeps numbers only, so a failed row is evaluated again on resuming, for its reason.
  TempDir dir;
  std::string text = density_problem();
  text.replace(text.find("omega = 51"), 10, "omega = 0");
  text.replace(text.find("ball_speed = 40"), 15, "ball_speed = 0");
  text.replace(text.find("max_evaluations = 400"), 21, "max_evaluations = 3");
  const auto opt = dir.write("opt.toml", text);
  const ProgramRun whole = run_program("optimize " + opt.string() + " -o " + dir / "whole.h5 --quiet");
  INFO(whole.output);
  REQUIRE(whole.exit_code == 0);

  const OptimizationProblem p = load_optimization(opt);
  const std::size_t width = journal_width(p);
  const std::string out = dir / "resumed.h5";
  {
    Journal journal = forged_journal(p, out);
    std::vector<double> row(width, std::nan(""));  // no objective, no estimates
    row[0] = p.free[0].start;                       // the design the search asks first
    row[p.free.size() + 1] = 1;                     // status failed
    row[p.free.size() + 2] = 0;                     // slices_used: none stated
    journal.append({0}, row);
  }
  const ProgramRun resumed = run_program("optimize " + opt.string() + " -o " + out + " --resume --quiet");
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  const ProgramRun same = run_command(std::string(python) + " -c \"import h5py; a = h5py.File('" + dir / "whole.h5" +
                                      "'); b = h5py.File('" + out + "'); f = [x.decode() for x in b['failure'][()]]; "
                                      "print(f == [x.decode() for x in a['failure'][()]], f[0].startswith('the impact at z = 0.7 m ended no_contact'))\"");
  INFO(same.output);
  CHECK(same.output == "True True\n");
}

TEST_CASE("a journaled ok evaluation with a NaN constraint is dropped on reading", "[optimize][program]") {
  TempDir dir;
  const auto opt = dir.write("opt.toml", density_problem("[constraints]\nmass = { max = 2 }\n"));
  const OptimizationProblem p = load_optimization(opt);
  REQUIRE(p.constraints.size() == 1);
  const std::size_t width = journal_width(p);
  const std::string out = dir / "nan.h5";
  {
    Journal journal = forged_journal(p, out);
    std::vector<double> row(width, 0.0);
    std::fill(row.end() - 4, row.end(), std::nan(""));  // no stated accuracy: no estimates
    row[0] = 700;
    row[p.free.size()] = 30;
    row[p.free.size() + 1] = std::nan("");
    journal.append({0}, row);
  }
  const ProgramRun resumed = run_program("optimize " + opt.string() + " -o " + out + " --resume");
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  CHECK(resumed.output.find("an ok evaluation with a NaN constraint") != std::string::npos);
}

TEST_CASE("optimize at a stated accuracy holds a sweet spot's width, not only the speeds it is read from",
          "[optimize]") {
  // A 1 % zone's ends lie where v_f is flat: the speeds' errors move them some 99 times as much.
  // The width at 1e-2 must lie within the two estimates of the width at 1e-4.
  TempDir dir;
  const std::string text = "bat = \"" + maple + "\"\n[free]\nbarrel_diameter = { min = 0.060325, max = 0.066675 }\n"
                           "[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\n[objective]\n"
                           "maximize = \"sweet_spot_width\"\nz = { start = 0.50, stop = 0.82, step = 0.01 }\n"
                           "fraction = 0.01\n[model]\n";
  const auto scored = [&](const char* accuracy) {
    const DesignEvaluation e =
        evaluate_design(load_optimization(dir.write("opt.toml", text + "accuracy = " + accuracy + "\n")), {0.0635},
                        serial_map);
    INFO(e.message);
    REQUIRE(e.status == EvaluationStatus::ok);
    return e;
  };
  const DesignEvaluation coarse = scored("1e-2"), fine = scored("1e-4");
  INFO("width " << coarse.objective << " at 1e-2 (" << coarse.total_error << "), " << fine.objective << " at 1e-4 ("
                << fine.total_error << ")");
  CHECK(std::abs(coarse.objective / fine.objective - 1) <= coarse.total_error + fine.total_error);
  CHECK(coarse.total_error <= 1e-2);
  CHECK(fine.total_error <= 1e-4);
  // The speeds' modes and step estimates, scaled by the width's sensitivity, take about their quarters.
  CHECK(coarse.modes_error <= 0.25e-2);
  CHECK(coarse.modes_error >= 0.25e-2 / 10);
}

TEST_CASE("a journaled ok evaluation whose estimates cannot be true at the stated accuracy is dropped on reading",
          "[optimize][program]") {
  TempDir dir;
  const auto opt = dir.write(
      "opt.toml", "bat = \"" + maple + "\"\n[free]\nbarrel_diameter = { min = 0.0603, max = 0.0667 }\n"
                  "[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\n[objective]\nmaximize = \"peak_bbs\"\n"
                  "z = { start = 0.60, stop = 0.80, step = 0.02 }\n[model]\naccuracy = 1e-2\n"
                  "[optimizer]\nmax_evaluations = 1\n");
  const OptimizationProblem p = load_optimization(opt);
  // design, objective, status, then slices_used, the slicing's, modes', step's and total errors
  const std::size_t width = journal_width(p);
  const std::vector<std::pair<std::vector<double>, std::string>> forged = {
      {{336, 1e-4, 1e-4, 1e-4, 0.5}, "a total error that is not its estimates' sum"},
      {{336, 1e-2, 1e-2, 1e-2, 3e-2}, "total error passes the accuracy"},
      {{336, 1e-4, INFINITY, 1e-4, INFINITY}, "infinite error estimate"},
      {{336, 1e-4, std::nan(""), 1e-4, std::nan("")}, "without its error estimates"},
      {{0, 1e-4, 1e-4, 1e-4, 3e-4}, "fewer slices than three slicings give"}};
  for (const auto& [chosen, why] : forged) {
    INFO(why);
    const std::string out = dir / "forged.h5";
    {
      Journal journal = forged_journal(p, out);
      std::vector<double> row = {0.0635, 45.0, 0.0};  // a design, its objective, status ok
      row.insert(row.end(), chosen.begin(), chosen.end());
      REQUIRE(row.size() == width);
      journal.append({0}, row);
    }
    const ProgramRun resumed = run_program("optimize " + opt.string() + " -o " + out + " --resume");
    INFO(resumed.output);
    REQUIRE(resumed.exit_code == 0);
    CHECK(resumed.output.find(why) != std::string::npos);
    std::filesystem::remove(out);
  }
}

TEST_CASE("optimize refuses an output name too long for its journal or best bat file", "[optimize][program]") {
  TempDir dir;
  const auto opt = dir.write("opt.toml", density_problem());
  const ProgramRun run = run_program("optimize " + opt.string() + " -o " + dir / (std::string(242, 'o') + ".h5"));
  INFO(run.output);
  CHECK(run.exit_code == 2);
  CHECK(run.output.find("bytes long, over the 255 its file system allows") != std::string::npos);
}

TEST_CASE("every shipped optimisation loads, and its start design is feasible", "[optimize]") {
  int found = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_path("studies"))) {
    if (!entry.path().filename().string().starts_with("optimize_")) continue;
    INFO(entry.path());
    ++found;
    const OptimizationProblem problem = load_optimization(entry.path());
    CHECK(problem.text.starts_with('#'));  // each says what it searches for
    std::vector<double> start;
    for (const FreeParameter& p : problem.free) start.push_back(p.start);
    const DesignEvaluation e = evaluate_design(problem, start, serial_map);
    INFO(e.message);
    CHECK(e.status == EvaluationStatus::ok);
    CHECK(feasible(problem, e));
  }
  CHECK(found >= 1);
  // The README's study: five dimensions of a 33-in maple, BBCOR and drop constrained, the sweet
  // spot's width at equal effort.
  const OptimizationProblem maple = load_optimization(source_path("studies/optimize_maple.toml"));
  CHECK(maple.free.size() == 5);
  CHECK(maple.base.length == Approx(33 * 0.0254));
  CHECK(maple.base.material_name == "maple");
  CHECK(maple.player.equal_effort);
  CHECK(maple.objective.kind == ObjectiveKind::sweet_spot_width);
  std::vector<std::string> labels;
  for (const Constraint& c : maple.constraints) labels.push_back(c.label());
  CHECK(std::ranges::count(labels, "bbcor_max") == 1);
  CHECK(std::ranges::count(labels, "drop_max") == 1);
  CHECK(std::ranges::count(labels, "drop_min") == 1);
}

TEST_CASE("optimize's BBCOR constraint is certify's maximum over the barrel, and the rules are certify's", "[optimize]") {
  TempDir dir;
  const auto file = dir.write(
      "opt.toml", "bat = \"" + maple + "\"\n[free]\nbarrel_diameter = { min = 0.0603, max = 0.0667 }\n"
                  "[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\n[objective]\nmaximize = \"peak_bbs\"\n"
                  "z = { start = 0.55, stop = 0.80, step = 0.01 }\n[constraints]\nstandard = \"bbcor\"\n");
  const OptimizationProblem problem = load_optimization(file);
  const DesignEvaluation e = evaluate_design(problem, {0.0655}, serial_map);
  REQUIRE(e.status == EvaluationStatus::ok);
  const Certification c = certify(design_at(problem, {0.0655}), problem.standard, CertifyOptions{});
  std::vector<std::string> labels;
  for (const Constraint& k : problem.constraints) labels.push_back(k.label());
  CHECK(labels == std::vector<std::string>{"bbcor_max", "barrel_diameter_max", "drop_max", "length_max"});
  // The optimiser solves the modes its impacts ask (auto, a partial solve), certify all of them:
  // the measure agrees to the auto modes' stated error.
  CHECK(e.constraints[0] == Approx(c.measure).epsilon(1e-5));
  for (std::size_t i = 1; i < c.checks.size(); ++i) {
    INFO(c.checks[i].rule);
    CHECK(e.constraints[i] == c.checks[i].value);
    CHECK(problem.constraints[i].limit == c.checks[i].limit);
  }
  CHECK(feasible(problem, e) == c.pass);
}

TEST_CASE("optimize at a stated accuracy scores each design as certify --accuracy does, and refuses what excludes it",
          "[optimize]") {
  TempDir dir;
  const std::string problem_text =
      "bat = \"" + maple + "\"\n[free]\nbarrel_diameter = { min = 0.0603, max = 0.0667 }\n"
      "[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\n[objective]\nmaximize = \"peak_bbs\"\n"
      "z = { start = 0.55, stop = 0.80, step = 0.01 }\n[constraints]\nstandard = \"bbcor\"\n[model]\n";
  const OptimizationProblem problem = load_optimization(dir.write("opt.toml", problem_text + "accuracy = 1e-3\n"));
  const DesignEvaluation e = evaluate_design(problem, {0.0655}, serial_map);
  REQUIRE(e.status == EvaluationStatus::ok);
  // Three slicings at least; the step's estimate (the largest of the impacts') within its quarter,
  // the slicing's within what the step and the modes leave, the total within the accuracy. (auto
  // keeps each impact's modes within half their quarter against the rigid bat's v_f; against the
  // impact's own, lower off the sweet spot and in the rig, the largest takes more than the quarter.)
  CHECK(e.slices_used >= 4 * build_bat(design_at(problem, {0.0655})).slices());
  CHECK(e.modes_error > 0);
  CHECK(e.step_error > 0);
  CHECK(e.step_error <= 0.25e-3);
  CHECK(e.slicing_error <= 1e-3 - e.modes_error - e.step_error);
  CHECK(e.total_error == e.slicing_error + e.modes_error + e.step_error);
  CHECK(e.total_error <= 1e-3);
  // The measure is certify's at the same accuracy when both end on the same slices; both within
  // the accuracy of the converged value, so within twice it of each other.
  CertifyOptions stated;
  stated.accuracy = 1e-3;
  const Certification c = certify(design_at(problem, {0.0655}), problem.standard, stated);
  CHECK(std::abs(e.constraints[0] - c.measure) <= 2e-3 * c.measure);
  // The program writes what each design took and estimated.
  const auto opt = dir.write("few.toml", problem_text + "accuracy = 1e-2\n[optimizer]\nmax_evaluations = 2\n");
  const std::string out = dir / "few.h5";
  const ProgramRun run = run_program("optimize '" + opt.string() + "' -o '" + out + "' --quiet");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const ProgramRun read = run_command(std::string(python) + " -c \"import h5py; f = h5py.File('" + out +
                                     "'); s, m, t, a = (f[k][()] for k in ('slicing_error', 'modes_error', "
                                     "'step_error', 'total_error')); print(len(a), (a == s + m + t).all(), "
                                     "(a <= 1e-2).all(), (m > 0).all(), (t > 0).all(), (f['slices_used'][()] >= 4 * "
                                     + std::to_string(build_bat(problem.base).slices()) + ").all())\"");
  INFO(read.output);
  CHECK(read.output == "2 True True True True True\n");
  const auto refused = [&](const std::string& model) {
    const auto file = dir.write("bad.toml", problem_text + model + "\n");
    return run_program("optimize '" + file.string() + "' -o '" + (dir.path / "bad.h5").string() + "'");
  };
  require_refused(refused("accuracy = 0"), {"model.accuracy", "1e-7 to 0.1"});
  require_refused(refused("accuracy = 1e-3\nslices = 100"), {"model.accuracy", "slices or accuracy"});
  require_refused(refused("modes = 5\naccuracy = 1e-3"), {"model.accuracy", "fixed number of modes"});
}

TEST_CASE("optimize's peak_distance is the longest flight of the scan's impacts", "[optimize]") {
  TempDir dir;
  const std::string problem_text =
      "bat = \"" + maple + "\"\n[free]\nbarrel_diameter = { min = 0.0603, max = 0.0667 }\n"
      "[player]\ncenter = 0.09\nomega = 51\nball_speed = 40\nundercut = \"0.5 in\"\nswing_tilt = 10\n"
      "friction = 0.5\n[objective]\nmaximize = \"peak_distance\"\nz = { start = 0.60, stop = 0.80, step = 0.02 }\n";
  const OptimizationProblem problem = load_optimization(dir.write("opt.toml", problem_text));
  const DesignEvaluation e = evaluate_design(problem, {0.0655}, serial_map);
  REQUIRE(e.status == EvaluationStatus::ok);
  // Each scan point's impact flown in the calculator's air: the objective is their largest, or
  // more where the golden section finds the peak between them.
  const BatDesign design = design_at(problem, {0.0655});
  const Bat bat = build_bat(design);
  const ModalBasis basis = compute_modes(bat, BeamTheory::timoshenko);
  ImpactScene scene;
  scene.ball = problem.player.ball;
  scene.ball_speed = problem.player.ball_speed;
  scene.swing = equal_effort_swing(problem.player.swing, problem.player.reference_moi,
                                   design_mass_properties(design).moment_of_inertia_about(0), problem.player.swing_exponent);
  scene.oblique = problem.player.oblique;
  double longest = 0;
  for (double z = 0.60; z < 0.805; z += 0.02) {
    scene.z = z;
    const ImpactResult r = simulate_impact(basis, scene);
    REQUIRE(r.status == CollisionStatus::ok);
    CHECK(r.launch.angle > 10);  // the undercut lifts the ball above the swing's tilt
    longest = std::max(longest, batted_flight(r.launch, Air{}).distance);
  }
  CHECK(e.objective >= longest * (1 - 1e-4));  // auto modes' tolerance against all modes here
  CHECK(e.objective <= longest * 1.02);        // the peak between points lies near the best one
  const auto bad = dir.write("bad.toml", std::string(problem_text).replace(problem_text.find("friction = 0.5"), 14,
                                                                            "friction = -1"));
  require_refused(run_program("optimize '" + bad.string() + "' -o '" + (dir.path / "bad.h5").string() + "'"),
                  {"player.friction", "-1"});
}

TEST_CASE("optimize takes a lock on its best bat file, which outputs of one stem share", "[optimize][program]") {
  // r.h5 and r.nc both write r_best.toml: the second is refused while the first holds it.
  TempDir dir;
  const auto opt = dir.write("opt.toml", density_problem());
  int ready[2];
  REQUIRE(::pipe(ready) == 0);
  const pid_t holder = ::fork();
  REQUIRE(holder >= 0);
  if (holder == 0) {
    const sweetspot::OutputLock lock(dir / "r_best.toml");
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(1);
    ::pause();
  }
  char byte = 0;
  REQUIRE(::read(ready[0], &byte, 1) == 1);
  const ProgramRun run = run_program("optimize " + opt.string() + " -o " + dir / "r.nc --quiet");
  ::kill(holder, SIGKILL);
  ::waitpid(holder, nullptr, 0);
  INFO(run.output);
  CHECK(run.exit_code == 2);
  CHECK(run.output.find("r_best.toml") != std::string::npos);
  CHECK(run.output.find("another sweetspot run (process " + std::to_string(holder) + ")") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "r.nc"));
}

TEST_CASE("optimize stops for max_evaluations only with that many evaluations recorded", "[optimize]") {
  // NLopt counts its calls, not the designs scored: a design asked twice in a row (the same point
  // after clamping to the bounds, or a local search starting where the global one sampled) is
  // scored once. The stop reason must agree with the evaluations a dataset records.
  TempDir dir;
  const std::string algorithm = GENERATE("cobyla", "bobyqa", "mlsl");
  const std::string constraints = GENERATE(std::string(), std::string("[constraints]\nmass = { max = 0.9 }\n"));
  for (const int budget : {3, 7, 12, 25}) {
    std::string text = density_problem(constraints);
    text.replace(text.find("max_evaluations = 400"), 21, "max_evaluations = " + std::to_string(budget));
    text.replace(text.find("xtol_rel"), 0, "algorithm = \"" + algorithm + "\"\n");
    const OptimizationProblem problem = load_optimization(dir.write("opt.toml", text));
    const OptimizationHistory history = optimize(problem);
    INFO(algorithm << ", " << constraints << "budget " << budget << ": " << history.evaluations.size()
                   << " evaluations, " << history.stop_reason);
    CHECK(history.evaluations.size() <= static_cast<std::size_t>(budget));
    if (history.stop_reason == "max_evaluations reached") CHECK(history.evaluations.size() == static_cast<std::size_t>(budget));
    else CHECK(history.stop_reason.find("max_evaluations") == std::string::npos);
  }
}

TEST_CASE("optimize refuses a player's negative omega: the swing turns the barrel toward the ball", "[optimize][program]") {
  TempDir dir;
  std::string text = density_problem();
  text.replace(text.find("omega = 51"), 10, "omega = -51");
  const auto opt = dir.write("opt.toml", text);
  require_refused(run_program("optimize " + opt.string() + " -o " + dir / "out.h5"),
                  {"opt.toml", "player.omega", "-51", ">= 0"});
  CHECK_FALSE(std::filesystem::exists(dir / "out.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "out.h5.journal"));
  text.replace(text.find("omega = -51"), 11, "omega = 0");  // a swing without rotation: a push, allowed
  CHECK(load_optimization(dir.write("zero.toml", text)).player.swing.omega == 0);
}

TEST_CASE("a failed evaluation's reason names the point and the collision's status", "[optimize]") {
  // A bat at rest (omega 0 about a centre) and a ball at rest: they never approach, and every
  // impact ends no_contact.
  TempDir dir;
  std::string text = density_problem();
  text.replace(text.find("omega = 51"), 10, "omega = 0");
  text.replace(text.find("ball_speed = 40"), 15, "ball_speed = 0");
  const OptimizationProblem problem = load_optimization(dir.write("opt.toml", text));
  const DesignEvaluation e = evaluate_design(problem, {problem.free[0].start}, serial_map);
  INFO(e.message);
  CHECK(e.status == EvaluationStatus::failed);
  CHECK_THAT(e.message, Catch::StartsWith("the impact at z = 0.7 m ended no_contact"));
}

TEST_CASE("a rerun into the same output that finds no feasible design removes the earlier best bat file",
          "[optimize][program]") {
  TempDir dir;
  const auto feasible = dir.write("feasible.toml", density_problem("[constraints]\nmass = { max = 0.9 }\n"));
  REQUIRE(run_program("optimize " + feasible.string() + " -o " + dir / "out.h5 --quiet").exit_code == 0);
  REQUIRE(std::filesystem::exists(dir / "out_best.toml"));
  // No density from 100 to 3000 makes the maple 271 lighter than 50 g.
  std::string text = density_problem("[constraints]\nmass = { max = 0.05 }\n");
  text.replace(text.find("max_evaluations = 400"), 21, "max_evaluations = 20");
  const auto infeasible = dir.write("infeasible.toml", text);
  const ProgramRun run = run_program("optimize " + infeasible.string() + " -o " + dir / "out.h5");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_FALSE(std::filesystem::exists(dir / "out_best.toml"));
  CHECK(run.output.find("no feasible design among") != std::string::npos);
  CHECK(run.output.find("removed " + dir / "out_best.toml" + ", an earlier run's best design") != std::string::npos);
  const ProgramRun check = run_command(std::string(python) + " -c \"import h5py; f = h5py.File('" + dir / "out.h5" +
                                       "'); print(int(f['best_evaluation'][()]))\"");
  INFO(check.output);
  CHECK(check.output == "-1\n");
  // A file of that name that no run wrote is the user's: refused before any work, and kept (a run
  // replaced it, or removed it as "an earlier run's best design").
  dir.write("out_best.toml", "name = \"my own bat\"\n");
  require_refused(run_program("optimize " + infeasible.string() + " -o " + dir / "out.h5"),
                  {"out_best.toml: exists and is not a best design an earlier run wrote"});
  CHECK(read(dir / "out_best.toml") == "name = \"my own bat\"\n");
}

TEST_CASE("A free hoop modulus starts from what the bat takes: absent, its Young's modulus", "[optimize]") {
  // alloy_bbcor gives no hoop_modulus: its wall's is youngs_modulus, 7e10 Pa, inside [1e10, 1e11].
  // It was read as 0 and the bounds refused as not around the base bat's value.
  TempDir dir;
  const auto opt = dir.write("hoop.toml", "bat = \"" + source_path("studies/bats/alloy_bbcor.toml") +
                                              "\"\n[free]\nhoop_modulus = { min = 1e10, max = 1e11 }\n[player]\n"
                                              "center = 0.09\nomega = 51\nball_speed = 40\n[model]\nmodes = 0\n"
                                              "[objective]\nmaximize = \"peak_bbs\"\nz = { start = 0.6, stop = 0.8, "
                                              "step = 0.05 }\n[optimizer]\nmax_evaluations = 5\n");
  const OptimizationProblem p = load_optimization(opt);
  REQUIRE(p.free.size() == 1);
  CHECK(p.free[0].start == p.base.material.youngs_modulus);
  CHECK(p.base.material.hoop_modulus == 0);  // the file's: absent
}
