// Units users write ("33 in", "31 oz", "136 mph"): exact conversion, the same results as the SI
// numbers they stand for, and one-line refusals of anything else, in files, on the command line
// and in the text output of --units us.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "program.hpp"
#include "refusal.hpp"
#include "study_dir.hpp"
#include "sweetspot/ball/ball_file.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/optimize/problem.hpp"
#include "sweetspot/units/quantity.hpp"
#include "temp_dir.hpp"

using namespace sweetspot;

namespace {

double length(const char* text) { return parse_quantity(text, Dimension::length).value_or(-1); }

// A bat of named dimensions (alloy_bbcor.toml's), each dimension written as `given`.
std::string alloy_bat(const std::vector<std::string>& given) {
  const char* keys[] = {"knob_diameter", "knob_length", "handle_diameter", "taper_start",
                        "taper_end",     "barrel_diameter", "wall_thickness"};
  std::ostringstream s;
  s << "name = \"alloy\"\nlength = " << given[0] << "\n[material]\ndensity = 2800\nyoungs_modulus = 7.0e10\n"
    << "shear_modulus = 2.6e10\nshear_coefficient = 0.5\n[dimensions]\n";
  for (int i = 0; i < 7; ++i) s << keys[i] << " = " << given[i + 1] << "\n";
  return s.str();
}

// The numbers of a line of text output, in order.
std::vector<double> numbers_in(const std::string& line) {
  static const std::regex number(R"([-+]?\d+(\.\d+)?([eE][-+]?\d+)?)");
  std::vector<double> out;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), number); it != std::sregex_iterator(); ++it)
    out.push_back(std::stod(it->str()));
  return out;
}

// The line of `output` that starts with `label`.
std::string line_of(const std::string& output, const std::string& label) {
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(label, 0) == 0) return line;
  FAIL("no line '" << label << "' in\n" << output);
  return "";
}

}  // namespace

TEST_CASE("A quantity with a unit is the SI number of the same decimal digits, bitwise", "[units]") {
  CHECK(length("33 in") == 0.8382);
  CHECK(length("33 in") == 33 * metres_per_inch);
  CHECK(length("28.3 in") == 0.71882);  // exact in decimal, rounded once
  CHECK(length("2.625 in") == 0.066675);
  CHECK(length("84 cm") == 0.84);
  CHECK(length("4.5 mm") == 0.0045);
  CHECK(length("3 ft") == 0.9144);
  CHECK(length("0.84 m") == 0.84);
  CHECK(parse_quantity("136 mph", Dimension::speed) == 60.79744);
  CHECK(parse_quantity("88 ft/s", Dimension::speed) == 26.8224);
  CHECK(parse_quantity("36 km/h", Dimension::speed) == 10.0);
  CHECK(parse_quantity("31 oz", Dimension::mass) == 0.878835216875);
  CHECK(parse_quantity("1 lb", Dimension::mass) == 0.45359237);
  CHECK(parse_quantity("145 g", Dimension::mass) == 0.145);
  CHECK(parse_quantity("1.5 kHz", Dimension::frequency) == 1500.0);
  CHECK(parse_quantity("1561 Hz", Dimension::frequency) == 1561.0);
  CHECK(parse_quantity("30 rpm", Dimension::angular_speed) == std::numbers::pi);
  CHECK(parse_quantity("51 rad/s", Dimension::angular_speed) == 51.0);
}

TEST_CASE("A quantity may be written with or without a space, signed and in exponent form", "[units]") {
  CHECK(length("28in") == length("28 in"));
  CHECK(length("  28 in ") == length("28 in"));
  CHECK(length("+28 in") == length("28 in"));
  CHECK(length("2.8e1 in") == length("28 in"));
  CHECK(parse_quantity("-5 mph", Dimension::speed) == -2.2352);
}

TEST_CASE("Wrong dimensions, unknown units, missing numbers, garbage and NaN are no quantity", "[units]") {
  for (const char* text : {"31 oz", "136 mph", "28 furlongs", "28 inch", "28 IN", "in", "28", "", "garbage",
                           "nan m", "inf in", "1e400 m", "28 in in", "28 i n", "0x1p3 m", "--28 in"})
    CHECK_FALSE(parse_quantity(text, Dimension::length).has_value());
  CHECK_FALSE(parse_quantity("28 in", Dimension::mass).has_value());
  CHECK_FALSE(parse_quantity("1 Hz", Dimension::angular_speed).has_value());
}

TEST_CASE("What a quantity reader expects names the SI unit, an example and every unit", "[units]") {
  CHECK(expected_quantity(Dimension::length) ==
        "a length (a number in m, or a string such as \"28 in\"; units m, cm, mm, in, ft)");
  CHECK(expected_quantity(Dimension::speed) ==
        "a speed (a number in m/s, or a string such as \"136 mph\"; units m/s, km/h, mph, ft/s)");
  CHECK(expected_quantity(Dimension::angular_speed).starts_with("an angular speed (a number in rad/s"));
}

TEST_CASE("A bat file in inches and millimetres gives bitwise the modes of the same bat in metres", "[units]") {
  TempDir dir;
  const auto metres = dir.write("metres.toml", alloy_bat({"0.8382", "0.045", "0.01", "0.0238", "0.25", "0.55",
                                                          "0.066675", "0.0026"}));
  const auto inches = dir.write("inches.toml", alloy_bat({"\"33 in\"", "\"4.5 cm\"", "\"10 mm\"", "\"23.8mm\"",
                                                          "\"25 cm\"", "\"0.55 m\"", "\"2.625 in\"", "\"2.6 mm\""}));
  const Bat a = load_bat(metres), b = load_bat(inches);
  REQUIRE(a.slices() == b.slices());
  CHECK(a.length == b.length);
  CHECK(a.outer_diameter == b.outer_diameter);
  CHECK(a.inner_diameter == b.inner_diameter);
  const ModalBasis ma = compute_modes(a, BeamTheory::timoshenko), mb = compute_modes(b, BeamTheory::timoshenko);
  CHECK(ma.omega == mb.omega);
  CHECK(ma.psi == mb.psi);
}

TEST_CASE("A bat file's measured hoop frequency may be given in kHz", "[units]") {
  TempDir dir;
  std::string text = alloy_bat({"0.8382", "0.045", "0.01", "0.0238", "0.25", "0.55", "0.066675", "0.0026"});
  BatSource source;
  const auto hz = dir.write("hz.toml", text + "[barrel]\nhoop_frequency = 1561\n");
  const auto khz = dir.write("khz.toml", text + "[barrel]\nhoop_frequency = \"1.561 kHz\"\n");
  CHECK(load_bat_design(khz, source).material.barrel.hoop_frequency ==
        load_bat_design(hz, source).material.barrel.hoop_frequency);
}

TEST_CASE("A bat file refuses a dimension of the wrong kind with one line naming file, key and value", "[units]") {
  TempDir dir;
  const auto bat = dir.write("bat.toml", alloy_bat({"\"33 oz\"", "0.045", "0.01", "0.0238", "0.25", "0.55",
                                                    "0.066675", "0.0026"}));
  try {
    load_bat(bat);
    FAIL("not refused");
  } catch (const InputError& e) {
    const std::string message = e.what();
    CHECK(message == bat.string() + ":2: key 'length': value \"33 oz\" must be a positive, finite length (a number in "
                                    "m, or a string such as \"28 in\"; units m, cm, mm, in, ft)");
  }
  const auto hoop = dir.write("hoop.toml", alloy_bat({"0.8382", "0.045", "0.01", "0.0238", "0.25", "0.55",
                                                      "0.066675", "0.0026"}) + "[barrel]\nhoop_frequency = \"1.5 kg\"\n");
  CHECK_THROWS_WITH(load_bat(hoop), Catch::Contains("key 'barrel.hoop_frequency': value \"1.5 kg\" must be a measured "
                                                    "frequency from 100 to 20000 Hz (a number in Hz"));
}

TEST_CASE("A ball table takes its mass, radius and speeds with units", "[units]") {
  TempDir dir;
  const auto si = dir.write("si.toml", "[ball]\nmass = 0.145291306015625\nradius = 0.03683\ncor = 0.5\n"
                                        "cor_speed = 26.8224\ncompression = 1800\n");
  const auto us = dir.write("us.toml", "[ball]\nmass = \"5.125 oz\"\nradius = \"1.45 in\"\ncor = 0.5\n"
                                        "cor_speed = \"60 mph\"\ncompression = 1800\n");
  const Ball a = load_ball(si.string()).ball, b = load_ball(us.string()).ball;
  CHECK(a.mass == b.mass);
  CHECK(a.radius == b.radius);
  CHECK(a.cor_speed == b.cor_speed);
  CHECK(a.k1 == b.k1);
  const auto wrong = dir.write("wrong.toml", "[ball]\nmass = \"5 in\"\n");
  CHECK_THROWS_WITH(load_ball(wrong.string()),
                    Catch::EndsWith(": [ball]: mass = \"5 in\": expected a mass (a number in kg, or a string such as "
                                    "\"31 oz\"; units kg, g, oz, lb)"));
}

// maple_271 under BBCOR with one free dimension; `free`, `player` and `scan` written as given.
std::string optimisation(const std::string& free, const std::string& player, const std::string& scan) {
  return "title = \"t\"\nbat = \"" + source_path("studies/bats/maple_271.toml") + "\"\n[free]\nbarrel_diameter = " +
         free + "\n[player]\nswing = \"equal_effort\"\ne0 = 0.5\nomega = 51\n" + player +
         "\n[objective]\nmaximize = \"sweet_spot_width\"\nfraction = 0.01\nz = " + scan +
         "\n[constraints]\nstandard = \"bbcor\"\n";
}

TEST_CASE("An optimisation file takes bounds, the swing and the scan with units", "[units]") {
  TempDir dir;
  const auto si = dir.write("si.toml", optimisation("{ min = 0.060325, max = 0.066675 }", "center = 0.09\nball_speed = 40",
                                                    "{ start = 0.5, stop = 0.82, step = 0.01 }"));
  const auto us = dir.write("us.toml", optimisation("{ min = \"2.375 in\", max = \"2.625 in\" }",
                                                    "center = \"9 cm\"\nball_speed = \"40 m/s\"",
                                                    "{ start = \"50 cm\", stop = \"820 mm\", step = \"1 cm\" }"));
  const OptimizationProblem a = load_optimization(si), b = load_optimization(us);
  CHECK(a.free[0].lower == b.free[0].lower);
  CHECK(a.free[0].upper == b.free[0].upper);
  CHECK(a.player.swing.center == b.player.swing.center);
  CHECK(a.player.ball_speed == b.player.ball_speed);
  CHECK(a.objective.z_from == b.objective.z_from);
  CHECK(a.objective.z_to == b.objective.z_to);
  CHECK(a.objective.z_step == b.objective.z_step);
  const auto wrong = dir.write("wrong.toml", optimisation("{ min = 0.060325, max = 0.066675 }",
                                                          "center = \"9 oz\"\nball_speed = 40",
                                                          "{ start = 0.5, stop = 0.82, step = 0.01 }"));
  CHECK_THROWS_WITH(load_optimization(wrong), Catch::Contains("key 'player.center' = \"9 oz\": expected a finite "
                                                              "point from the knob (a number in m, or a string"));
}

TEST_CASE("A study in inches and mph gives bitwise the dataset of the same study in SI", "[units]") {
  TempDir dir;
  const std::string bat = source_path("studies/bats/r161.toml");
  const std::string outputs = "[output]\nvariables = [\"vf\", \"e_eff\", \"displacement\"]\n";  // the probe's
  const auto si = dir.write("si.toml", "[scene]\nbat = \"" + bat + "\"\ncenter = 0.0889\nomega = 51\nmodes = 6\n"
                                        "probes = [0.6]\n[axes]\nz = { start = 0.6096, stop = 0.6858, step = 0.0254 }\n"
                                        "ball_speed = [60.79744, 30]\n" + outputs);
  const auto us = dir.write("us.toml", "[scene]\nbat = \"" + bat + "\"\ncenter = \"3.5 in\"\nomega = \"51 rad/s\"\n"
                                        "modes = 6\nprobes = [\"60 cm\"]\n[axes]\nz = { start = \"24 in\", stop = "
                                        "\"27 in\", step = \"1 in\" }\nball_speed = [\"136 mph\", \"30 m/s\"]\n" +
                                        outputs);
  for (const auto& study : {si, us}) {
    const ProgramRun run = run_program("run " + study.string() + " -o " + study.string() + ".h5 --quiet");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
  }
  const ProgramRun compare = run_command(std::string(python) + " " + source_path("tests/compare_datasets.py") + " " +
                                         si.string() + ".h5 " + us.string() + ".h5");
  INFO(compare.output);
  CHECK(compare.exit_code == 0);
  // The study text kept as provenance is the study as written, units and all.
  const ProgramRun text = run_command(std::string(python) + " -c \"import h5py; print(h5py.File('" + us.string() +
                                      ".h5', 'r').attrs['study'])\"");
  CHECK_THAT(text.output, Catch::Contains("ball_speed = [\"136 mph\", \"30 m/s\"]"));
}

TEST_CASE("A study refuses a quantity of the wrong dimension, an unknown unit, garbage or NaN before any work",
          "[units]") {
  const std::pair<std::string, std::string> cases[] = {
      {"z = \"31 oz\"", "key 'scene.z' = \"31 oz\": expected a length >= 0 from the knob (a number in m, or a string "
                        "such as \"28 in\"; units m, cm, mm, in, ft)"},
      {"z = \"28 furlongs\"", "key 'scene.z' = \"28 furlongs\": expected a length"},
      {"z = \"in\"", "key 'scene.z' = \"in\": expected a length"},
      {"z = \"nan in\"", "key 'scene.z' = \"nan in\": expected a length"},
      {"z = \"twenty-eight inches\"", "key 'scene.z' = \"twenty-eight inches\": expected a length"},
      {"ball_mass = \"5 in\"", "key 'scene.ball_mass' = \"5 in\": expected a mass in [0.001, 10] kg, as a [ball] table takes it (a number in kg"},
      {"e0 = \"0.5 m\"", "key 'scene.e0' = \"0.5 m\" (string): expected a COR, a number in [0.05, 1]"},
      {"e_a_speed = \"40 rad/s\"", "key 'scene.e_a_speed' = \"40 rad/s\": expected a speed > 0 (the speed e_A is "
                                   "taken at for bbs_linear) (a number in m/s"},
  };
  for (const auto& [line, message] : cases) {
    StudyDir s(3, line + "\n");  // the [scene] value is read (and refused) though an axis overrides it
    const auto before = s.snapshot();
    const ProgramRun run = run_program("run " + s.study.string() + " -o " + s / "out.h5");
    INFO(line);
    require_refused(run, message);
    CHECK(s.snapshot() == before);
  }
  StudyDir s(3);
  std::string text = file_text(s.study);
  text.replace(text.find("z = {"), text.find('\n', text.find("z = {")) - text.find("z = {"),
               "z = { start = \"24 in\", stop = \"27 oz\", step = \"1 in\" }");
  std::ofstream(s.study, std::ios::binary) << text;
  require_refused(run_program("run " + s.study.string() + " -o " + s / "out.h5"),
                  "key 'axes.z.stop' = \"27 oz\": expected a finite length (a number in m");
}

TEST_CASE("A study's bat parameter axis takes lengths with units, its material constants only numbers", "[units]") {
  TempDir dir;
  const std::string bat = source_path("studies/bats/alloy_bbcor.toml");
  const auto study = dir.write("study.toml", "[scene]\nbat = \"" + bat + "\"\nz = 0.7\nball_speed = 40\ncenter = 0.09\n"
                                             "omega = 51\n[axes]\n\"bat.barrel_diameter\" = [\"2.5 in\", \"2.625 in\"]\n");
  const Study s = load_study(study);
  const auto axis = std::ranges::find(s.axes, "bat.barrel_diameter", &Axis::name);
  REQUIRE(axis != s.axes.end());
  CHECK(axis->values == std::vector<double>{0.0635, 0.066675});
  const auto density = dir.write("density.toml", "[scene]\nbat = \"" + bat + "\"\nz = 0.7\nball_speed = 40\n"
                                                 "center = 0.09\nomega = 51\n[axes]\n\"bat.density\" = [\"2800 kg\"]\n");
  CHECK_THAT(study_refusal(density), Catch::Contains("key 'axes.bat.density[0]' = \"2800 kg\" (string): expected a "
                                                     "finite number, the bat parameter in SI units"));
}

TEST_CASE("impact takes --z, --ball-speed and the swing with units and prints the same as in SI", "[units]") {
  const std::string bat = source_path("studies/bats/r161.toml");
  const ProgramRun si = run_program("impact --bat " + bat + " --z 0.7112 --ball-speed 60.79744 --center 0.0889 "
                                    "--omega 51 --modes 6 --json");
  const ProgramRun us = run_program("impact --bat " + bat + " --z 28in --ball-speed \"136 mph\" --center 3.5in "
                                    "--omega 51rad/s --modes 6 --json");
  INFO(si.output << us.output);
  REQUIRE(si.exit_code == 0);
  CHECK(us.output == si.output);
}

TEST_CASE("The command line refuses a quantity of the wrong dimension, an unknown unit or garbage", "[units]") {
  const std::string bat = source_path("studies/bats/r161.toml");
  const std::string swing = " --ball-speed 40 --center 0.09 --omega 51";
  require_refused(run_program("impact --bat " + bat + " --z 31oz" + swing),
                  {"impact: --z: \"31oz\": expected a length (a number in m, or a string such as \"28 in\"; units m, "
                   "cm, mm, in, ft)"});
  require_refused(run_program("impact --bat " + bat + " --z \"28 furlongs\"" + swing), {"--z", "\"28 furlongs\""});
  require_refused(run_program("impact --bat " + bat + " --z garbage" + swing), {"--z", "\"garbage\"", "a length"});
  require_refused(run_program("impact --bat " + bat + " --z 0.7 --ball-speed 40kg --center 0.09"),
                  {"--ball-speed", "\"40kg\"", "expected a speed"});
  require_refused(run_program("wall --speed \"nan mph\""), {"--speed", "\"nan mph\"", "expected a speed"});
  require_refused(run_program("certify " + bat + " --pivot-point 6oz"), {"--pivot-point", "\"6oz\"", "a length"});
  require_refused(run_program("ball --speeds 60 40kg"), {"--speeds", "\"40kg\"", "a number in mph"});
}

TEST_CASE("ball --speeds takes plain mph as before and other speeds with their unit", "[units]") {
  const ProgramRun mph = run_program("ball n2000 --speeds 60 --json");
  const ProgramRun metres = run_program("ball n2000 --speeds 26.8224m/s --json");
  INFO(mph.output << metres.output);
  REQUIRE(mph.exit_code == 0);
  CHECK(metres.output == mph.output);
}

TEST_CASE("impact --units us prints the SI output's values in in, mph and in of compression", "[units]") {
  const std::string args = "impact --bat " + source_path("studies/bats/r161.toml") +
                           " --z 0.7 --ball-speed 40 --center 0.09 --omega 51 --modes 6";
  const ProgramRun si = run_program(args), us = run_program(args + " --units us");
  INFO(si.output << us.output);
  REQUIRE(si.exit_code == 0);
  REQUIRE(us.exit_code == 0);
  CHECK(run_program(args + " --units si").output == si.output);
  CHECK_THAT(line_of(us.output, "impact at z"), Catch::EndsWith(" in from the knob"));
  CHECK(numbers_in(line_of(us.output, "impact at z"))[0] == Approx(0.7 / metres_per_inch).epsilon(1e-5));
  const double vf = numbers_in(line_of(si.output, "exit speed vf"))[0];
  CHECK_THAT(line_of(us.output, "exit speed vf"), Catch::EndsWith(" mph"));
  CHECK(numbers_in(line_of(us.output, "exit speed vf"))[0] == Approx(vf / metres_per_second_per_mph).epsilon(1e-5));
  const double bat_speed = numbers_in(line_of(si.output, "bat speed"))[0];
  CHECK(numbers_in(line_of(us.output, "bat speed"))[0] ==
        Approx(bat_speed / metres_per_second_per_mph).epsilon(1e-5));
  const double u_max_mm = numbers_in(line_of(si.output, "max compression"))[0];
  CHECK_THAT(line_of(us.output, "max compression"), Catch::Contains(" in, peak force"));
  CHECK(numbers_in(line_of(us.output, "max compression"))[0] == Approx(u_max_mm / 25.4).epsilon(1e-3));
  // What has no US unit (times, forces, energies) is printed as in SI.
  CHECK(line_of(us.output, "contact time") == line_of(si.output, "contact time"));
  CHECK(line_of(us.output, "energy/J") == line_of(si.output, "energy/J"));
}

TEST_CASE("modes --units us prints length, mass, MOI in oz in^2 and nodes in inches", "[units]") {
  const std::string args = "modes " + source_path("studies/bats/r161.toml") + " --count 3";
  const ProgramRun si = run_program(args), us = run_program(args + " --units us");
  INFO(si.output << us.output);
  REQUIRE(us.exit_code == 0);
  const std::vector<double> mass_si = numbers_in(line_of(si.output, "mass")), mass_us = numbers_in(line_of(us.output, "mass"));
  CHECK_THAT(line_of(us.output, "mass"), Catch::Contains(" oz, centre of mass ") && Catch::EndsWith(" in"));
  CHECK(mass_us[0] == Approx(mass_si[0] / kilograms_per_ounce).epsilon(1e-4));
  CHECK(mass_us[1] == Approx(mass_si[1] / metres_per_inch).epsilon(1e-4));
  CHECK(mass_us[2] == Approx(mass_si[2] / metres_per_inch).epsilon(5e-4));  // SI printed to 0.1 mm
  const double oz_in2 = kilograms_per_ounce * metres_per_inch * metres_per_inch;
  const std::vector<double> moi_si = numbers_in(line_of(si.output, "moment of inertia"));
  const std::vector<double> moi_us = numbers_in(line_of(us.output, "moment of inertia"));
  CHECK_THAT(line_of(us.output, "moment of inertia"), Catch::Contains(" oz in^2 about the CM"));
  CHECK(moi_us[0] == Approx(moi_si[0] / oz_in2).epsilon(1e-3));
  CHECK(moi_us[2] == Approx(moi_si[2] / oz_in2).epsilon(1e-3));  // [1] is the 2 of "in^2"
  CHECK_THAT(us.output, Catch::Contains("nodes/in from the knob"));
  const std::vector<double> mode_si = numbers_in(line_of(si.output, "    1")), mode_us = numbers_in(line_of(us.output, "    1"));
  CHECK(mode_us[1] == mode_si[1]);  // the frequency
  CHECK(mode_us[2] == Approx(mode_si[2] / 2.54).margin(0.06));  // a node, cm to in at one decimal
}

TEST_CASE("certify --units us puts US values first and SI in parentheses", "[units]") {
  const std::string args = "certify " + source_path("studies/bats/alloy_bbcor.toml") + " --modes 6";
  const ProgramRun si = run_program(args), us = run_program(args + " --units us");
  INFO(si.output << us.output);
  REQUIRE(us.exit_code == 3);  // this alloy bat fails BBCOR: a verdict, not an error
  REQUIRE(si.exit_code == 3);
  const std::vector<double> length_si = numbers_in(line_of(si.output, "length"));
  const std::vector<double> length_us = numbers_in(line_of(us.output, "length"));
  // SI: "0.8382 m (33.00 in), weight 0.8800 kg (31.04 oz), drop 1.96"; US the pairs swapped.
  CHECK(length_us[0] == length_si[1]);
  CHECK(length_us[1] == length_si[0]);
  CHECK(length_us[2] == length_si[3]);
  CHECK(length_us[3] == length_si[2]);
  CHECK(length_us[4] == length_si[4]);
  CHECK_THAT(line_of(us.output, "MOI about pivot"), Catch::Contains(" oz in^2 ("));
  CHECK(line_of(us.output, "maximum") != line_of(si.output, "maximum"));
  CHECK(numbers_in(line_of(us.output, "maximum"))[1] ==
        Approx(numbers_in(line_of(si.output, "maximum"))[1] / metres_per_inch).epsilon(1e-5));
}

TEST_CASE("JSON is always SI: --units us with --json is refused", "[units]") {
  for (const std::string& args : {"impact --bat " + source_path("studies/bats/r161.toml") +
                                      " --z 0.7 --ball-speed 40 --center 0.09",
                                  "modes " + source_path("studies/bats/r161.toml"), std::string("wall --speed 40"),
                                  std::string("ball n2000"),
                                  "certify " + source_path("studies/bats/alloy_bbcor.toml")})
    require_refused(run_program(args + " --units us --json"), {"--units us applies to the text output; --json is always in SI"});
  CHECK(run_program("wall --speed 40 --units si --json").exit_code == 0);
  require_refused(run_program("wall --speed 40 --units imperial"), {"--units"});
}

// Issue 24: a study's messages named the SI value a unit stood for (z = 0.7112 for "71.12 cm",
// bat.barrel_diameter = 0.00254 for "0.1 in"), which the user cannot find in the file.
TEST_CASE("A study's refusals show each value as written, units and all", "[units]") {
  TempDir dir;
  const std::string bat = source_path("studies/bats/alloy_bbcor.toml");
  const auto refusal = [&](const std::string& scene, const std::string& axes) {
    return study_refusal(dir.write("s.toml", "[scene]\nbat = \"" + bat + "\"\ncenter = 0.09\nomega = 51\n"
                                             "ball_speed = 40\n" + scene + "[axes]\n" + axes));
  };
  CHECK_THAT(refusal("", "z = [\"28 in\", \"71.12 cm\"]\n"),
             Catch::Contains("key 'axes.z' = \"71.12 cm\" (the same as \"28 in\"): appears twice"));
  CHECK_THAT(refusal("z = 0.7\n", "\"bat.barrel_diameter\" = [\"0.1 in\"]\n"),
             Catch::Contains("key 'axes.bat.barrel_diameter' = \"0.1 in\": makes an impossible bat") &&
                 Catch::Contains("with bat.barrel_diameter = \"0.1 in\")"));
  CHECK_THAT(refusal("z = 0.7\n", "\"bat.material\" = [\"maple\", \"maple\"]\n"),
             Catch::Contains("key 'axes.bat.material' = \"maple\": appears twice"));
  CHECK_THAT(refusal("z = 0.7\n", "\"bat.length\" = [\"838.2 in\"]\n"),
             Catch::Contains("key 'axes.bat.length' = \"838.2 in\": bat parameter 'length'"));
  CHECK_THAT(refusal("", "z = [\"28 in\", \"40 in\"]\n"), Catch::Contains("key 'axes.z' = \"40 in\" = 1.016 m: must lie"));
  CHECK_THAT(refusal("z = 0.7\nprobes = [\"5 in\", \"12.7 cm\"]\n", "ball_speed = [30, 40]\n"),
             Catch::Contains("key 'scene.probes' = \"12.7 cm\" (the same as \"5 in\"): appears twice in the list"));
  // A range's values are numbers the range made: shown as numbers.
  CHECK_THAT(refusal("", "z = { start = \"1 in\", stop = \"1 in\", count = 2 }\n"),
             Catch::Contains("key 'axes.z' = 0.0254: appears twice"));
}
