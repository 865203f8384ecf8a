// The batted ball's flight (src/flight): exact limits (the vacuum parabola, quadratic drag's
// closed forms, symmetries), the trajectory calculator's own published case, and the command.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "sweetspot/flight/flight.hpp"
#include "study_dir.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/batted_flight.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/study/study_point.hpp"
#include "program.hpp"
#include "refusal.hpp"
#include "sweetspot/input_error.hpp"

using namespace sweetspot;

namespace {

constexpr double mph = 0.44704, ft = 0.3048, rpm = std::numbers::pi / 30;

FlightOptions vacuum() {
  FlightOptions o;
  o.drag = o.lift = false;
  return o;
}

// Drag alone with a constant C_D (no spin): the terminal speed v_t = sqrt(g / (K cd0)).
double terminal_speed(const Air& air, const FlightOptions& o) {
  const double k = air_density(air) * std::numbers::pi * o.ball.radius * o.ball.radius / (2 * o.ball.mass);
  return std::sqrt(o.gravity / (k * o.aerodynamics.cd0));
}

bool refused(const Launch& launch, const Air& air, const std::string& key) {
  try {
    simulate_flight(launch, air);
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK_THAT(e.what(), Catch::StartsWith(key + " = "));
    return true;
  }
  return false;
}

}  // namespace

TEST_CASE("Without air the flight is the parabola", "[flight]") {
  const double g = 9.80665;
  for (const double angle : {5.0, 27.5, 45.0, 80.0})
    for (const double height : {0.0, 0.9144}) {
      Launch l;
      l.speed = 45;
      l.angle = angle;
      l.direction = 17;
      l.backspin = 2000 * rpm;  // spin does nothing without air
      l.height = height;
      const FlightResult r = simulate_flight(l, Air{}, vacuum());
      const double th = angle * std::numbers::pi / 180;
      const double vx = l.speed * std::cos(th), vz = l.speed * std::sin(th);
      const double t = (vz + std::sqrt(vz * vz + 2 * g * height)) / g;
      INFO("angle " << angle << ", height " << height);
      CHECK(r.hang_time == Approx(t).epsilon(1e-9));
      CHECK(r.distance == Approx(vx * t).epsilon(1e-9));
      CHECK(r.apex == Approx(height + vz * vz / (2 * g)).epsilon(1e-9));
      CHECK(r.apex_time == Approx(vz / g).epsilon(1e-9));
      CHECK(r.bearing == Approx(17).epsilon(1e-9));
      CHECK(std::tan(r.landing_angle * std::numbers::pi / 180) == Approx((g * t - vz) / vx).epsilon(1e-9));
    }
}

TEST_CASE("A ball dropped through still air falls as quadratic drag's closed form says", "[flight]") {
  // z(t) = h - (v_t^2 / g) ln cosh(g t / v_t): the fall from h takes (v_t / g) arccosh(exp(g h / v_t^2))
  // and lands at v_t sqrt(1 - exp(-2 g h / v_t^2)).
  const Air air;
  const FlightOptions o;
  const double vt = terminal_speed(air, o), g = o.gravity;
  for (const double h : {2.0, 30.0, 300.0}) {
    Launch l;
    l.angle = -90;
    l.height = h;
    const FlightResult r = simulate_flight(l, air, o);
    INFO("h " << h << " m, v_t " << vt);
    CHECK(r.hang_time == Approx(vt / g * std::acosh(std::exp(g * h / (vt * vt)))).epsilon(1e-6));
    CHECK(r.landing_speed == Approx(vt * std::sqrt(1 - std::exp(-2 * g * h / (vt * vt)))).epsilon(1e-6));
    CHECK(r.apex == h);
  }
}

TEST_CASE("The spin decays with the path through the air", "[flight]") {
  // d(omega)/dt = -omega |u| / (tau v_ref): omega = omega0 exp(-path / (tau v_ref)). A ball dropped
  // through still air without lift falls straight, so its path is the height it fell.
  FlightOptions o;
  o.lift = false;
  o.aerodynamics.spin_decay_time = 2;
  Launch l;
  l.angle = -90;
  l.height = 50;
  l.backspin = 3000 * rpm;
  const FlightResult r = simulate_flight(l, Air{}, o);
  CHECK(r.landing_spin == Approx(l.backspin * std::exp(-50 / (2 * spin_decay_reference_speed))).epsilon(1e-9));
}

TEST_CASE("A ball thrown straight up through still air rises and falls as quadratic drag's closed forms say",
          "[flight]") {
  // Up: apex (v_t^2 / 2g) ln(1 + v0^2 / v_t^2) at (v_t / g) atan(v0 / v_t); down from there it lands
  // at v0 v_t / sqrt(v0^2 + v_t^2).
  const Air air;
  const FlightOptions o;
  const double vt = terminal_speed(air, o), g = o.gravity;
  for (const double v0 : {10.0, 45.0}) {
    Launch l;
    l.speed = v0;
    l.angle = 90;
    l.height = 0;
    const FlightResult r = simulate_flight(l, air, o);
    const double apex = vt * vt / (2 * g) * std::log1p(v0 * v0 / (vt * vt));
    const double rise = vt / g * std::atan(v0 / vt), fall = vt / g * std::acosh(std::exp(g * apex / (vt * vt)));
    INFO("v0 " << v0);
    CHECK(r.apex == Approx(apex).epsilon(1e-6));
    CHECK(r.apex_time == Approx(rise).epsilon(1e-6));
    CHECK(r.hang_time == Approx(rise + fall).epsilon(1e-6));
    CHECK(r.landing_speed == Approx(v0 * vt / std::hypot(v0, vt)).epsilon(1e-6));
    CHECK(r.landing_angle == Approx(90).epsilon(1e-6));
  }
}

TEST_CASE("A ball moving with the wind falls straight through the air and drifts with the wind", "[flight]") {
  // Launched horizontally at the wind's velocity, the air's speed past the ball is vertical: it
  // falls as the closed form says and covers the wind speed times that time, toward the wind's
  // direction (the direction it blows to).
  Air air;
  air.wind_speed = 8;
  air.wind_direction = 30;
  const FlightOptions o;
  const double vt = terminal_speed(air, o), g = o.gravity, h = 20;
  Launch l;
  l.speed = air.wind_speed;
  l.direction = air.wind_direction;
  l.height = h;
  const FlightResult r = simulate_flight(l, air, o);
  const double t = vt / g * std::acosh(std::exp(g * h / (vt * vt)));
  CHECK(r.hang_time == Approx(t).epsilon(1e-6));
  CHECK(r.distance == Approx(air.wind_speed * t).epsilon(1e-6));
  CHECK(r.bearing == Approx(30).epsilon(1e-9));
}

TEST_CASE("Sidespin curves the ball to one side and its opposite to the mirror image", "[flight]") {
  Launch l;
  l.speed = 100 * mph;
  l.angle = 25;
  l.backspin = 2000 * rpm;
  l.sidespin = 800 * rpm;
  const FlightResult left = simulate_flight(l, Air{});
  l.sidespin = -l.sidespin;
  const FlightResult right = simulate_flight(l, Air{});
  CHECK(left.landing_x < -1);  // positive sidespin: toward left field, as in the calculator
  CHECK(right.landing_x == Approx(-left.landing_x).epsilon(1e-9));
  CHECK(right.landing_y == Approx(left.landing_y).epsilon(1e-9));
  CHECK(right.hang_time == Approx(left.hang_time).epsilon(1e-9));
}

TEST_CASE("In still air the flight does not depend on its direction", "[flight]") {
  Launch l;
  l.speed = 100 * mph;
  l.angle = 28;
  l.backspin = 2200 * rpm;
  const FlightResult centre = simulate_flight(l, Air{});
  l.direction = -35;
  const FlightResult pulled = simulate_flight(l, Air{});
  CHECK(pulled.distance == Approx(centre.distance).epsilon(1e-9));
  CHECK(pulled.apex == Approx(centre.apex).epsilon(1e-9));
  CHECK(pulled.bearing == Approx(-35).epsilon(1e-9));
}

TEST_CASE("Backspin lifts the ball, and thinner air and a tail wind carry it farther", "[flight]") {
  Launch l;
  l.speed = 100 * mph;
  l.angle = 28;
  const FlightResult plain = simulate_flight(l, Air{});
  l.backspin = 2500 * rpm;
  const FlightResult spun = simulate_flight(l, Air{});
  CHECK(spun.apex > plain.apex);
  CHECK(spun.hang_time > plain.hang_time);
  Air denver;
  denver.elevation = 5280 * ft;
  CHECK(simulate_flight(l, denver).distance > spun.distance + 5 * ft);
  Air out;
  out.wind_speed = 10 * mph;
  CHECK(simulate_flight(l, out).distance > spun.distance + 10 * ft);
}

TEST_CASE("Dry air is an ideal gas and humid air the trajectory calculator's density", "[flight]") {
  Air dry;
  dry.relative_humidity = 0;
  dry.temperature = 288.15;
  dry.pressure = 101325;
  CHECK(air_density(dry) == Approx(101325 / (287.058 * 288.15)).epsilon(1e-14));
  // The calculator's own formula (pybaseball's parameters.py): 70 F, 50 %, 29.92 inHg, 15 ft.
  Air ballpark;
  ballpark.pressure = 29.92 * 3386.388640341;
  ballpark.elevation = 15 * ft;
  const double c = 70.0 - 32, celsius = c * 5 / 9;
  const double svp = 4.5841 * std::exp((18.687 - celsius / 234.5) * celsius / (257.14 + celsius));
  const double calculator =
      1.2929 * (273 / (celsius + 273)) * (29.92 * 1000 / 39.37 * std::exp(-1.217e-4 * 15 * ft) - 0.3783 * 50 * svp / 100) / 760;
  CHECK(air_density(ballpark) == Approx(calculator).epsilon(1e-3));
  CHECK(air_density(ballpark) < air_density(Air{.relative_humidity = 0}));  // water vapour is lighter
}

TEST_CASE("The trajectory calculator's published fly ball: 103 mph, 27.5 deg, 2500 rpm at 70 F", "[flight]") {
  // The calculator's trajectory for this case (TrajectoryCalculator-new-3D.xlsx, as published in
  // the R package mosaicCalc, data set Fly_ball: 5.125 oz, 9.125 in, 70 F, 50 %, 29.92 inHg, 15 ft,
  // starting 2 ft in front of the plate and 3 ft up): apex 92.04 ft at 2.64 s, and the last point
  // y = 420.95 ft, z = 0.57 ft at 5.51 s, i.e. landing about 421.5 ft from the plate at 5.52 s.
  Launch l;
  l.speed = 103 * mph;
  l.angle = 27.5;
  l.backspin = 2500 * rpm;
  l.height = 3 * ft;
  Air air;
  air.pressure = 29.92 * 3386.388640341;
  air.elevation = 15 * ft;
  const FlightResult r = simulate_flight(l, air);
  CHECK((r.distance + 2 * ft) / ft == Approx(421.5).epsilon(0.005));
  CHECK(r.apex / ft == Approx(92.04).epsilon(0.005));
  CHECK(r.apex_time == Approx(2.64).epsilon(0.005));
  CHECK(r.hang_time == Approx(5.52).epsilon(0.005));
}

TEST_CASE("The trajectory is sampled from launch to landing on request", "[flight]") {
  Launch l;
  l.speed = 40;
  l.angle = 30;
  FlightOptions o;
  o.sample_interval = 0.1;
  const FlightResult r = simulate_flight(l, Air{}, o);
  REQUIRE(r.samples.size() >= 3);
  CHECK(r.samples.front().t == 0);
  CHECK(r.samples.front().z == l.height);
  CHECK(r.samples.back().t == r.hang_time);
  CHECK(r.samples.back().z == 0);
  CHECK(std::hypot(r.samples.back().x, r.samples.back().y) == r.distance);
  for (std::size_t i = 1; i + 1 < r.samples.size(); ++i) CHECK(r.samples[i].t == Approx(0.1 * i).epsilon(1e-12));
  CHECK(simulate_flight(l, Air{}).samples.empty());
}

TEST_CASE("A flight refuses unphysical air and launches before any work", "[flight]") {
  const double nan = std::nan("");
  const Launch ok{.speed = 40, .angle = 30};
  CHECK(refused(Launch{.speed = -1}, Air{}, "speed"));
  CHECK(refused(Launch{.speed = nan}, Air{}, "speed"));
  CHECK(refused(Launch{.speed = 40, .angle = 95}, Air{}, "angle"));
  CHECK(refused(Launch{.speed = 40, .height = -1}, Air{}, "height"));
  CHECK(refused(ok, Air{.temperature = 0}, "temperature"));
  CHECK(refused(ok, Air{.temperature = nan}, "temperature"));
  CHECK(refused(ok, Air{.pressure = -100}, "pressure"));
  CHECK(refused(ok, Air{.relative_humidity = 1.5}, "humidity"));
  CHECK(refused(ok, Air{.relative_humidity = -0.1}, "humidity"));
  CHECK(refused(ok, Air{.wind_speed = -3}, "wind_speed"));
  CHECK(refused(ok, Air{.wind_direction = nan}, "wind_direction"));
  FlightOptions tiny;
  tiny.sample_interval = 1e-9;  // billions of samples: refused, not a memory exhausted
  CHECK_THROWS_AS(simulate_flight(ok, Air{}, tiny), InputError);
}

// ---- The command: sweetspot flight.

TEST_CASE("sweetspot flight prints distance, apex, hang time and landing angle in m and ft", "[flight][program]") {
  const ProgramRun run = run_program("flight --speed 103mph --angle 27.5 --backspin 2500rpm");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  for (const char* line : {"distance ", " ft)", "apex ", "hang time ", "landing angle ", "air density "})
    CHECK_THAT(run.output, Catch::Contains(line));
}

TEST_CASE("sweetspot flight --vacuum --json is the parabola", "[flight][program]") {
  const ProgramRun run = run_program("flight --speed 40 --angle 30 --height 0 --vacuum --json");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const double g = 9.80665, th = std::numbers::pi / 6;
  const std::string key = "\"distance\": ";
  const std::size_t at = run.output.find(key);
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(run.output.substr(at + key.size())) == Approx(1600 * std::sin(2 * th) / g).epsilon(1e-9));
}

TEST_CASE("sweetspot flight refuses unphysical air and launches in one line, as written", "[flight][program]") {
  require_refused(run_program("flight --speed -3"), {"--speed \"-3\"", "a speed from 0 to 1000 m/s"});
  require_refused(run_program("flight --speed nan"), {"--speed \"nan\""});
  require_refused(run_program("flight --speed 40 --humidity 150"), {"--humidity \"150\"", "0 to 100"});
  require_refused(run_program("flight --speed 40 --humidity -1"), {"--humidity \"-1\""});
  require_refused(run_program("flight --speed 40 --pressure -1inHg"), {"--pressure \"-1inHg\"", "from 50 to 150 kPa"});
  require_refused(run_program("flight --speed 40 --temperature -500F"), {"--temperature \"-500F\"", "above 173.15 K"});
  // Down to 16 K the vapour pressure's formula ran, and the humidity was blamed.
  require_refused(run_program("flight --speed 40 --temperature 1K"), {"--temperature \"1K\"", "above 173.15 K"});
  require_refused(run_program("flight --speed 40 --temperature 0"), {"--temperature \"0\""});
  require_refused(run_program("flight --speed 40 --temperature 70mph"), {"--temperature \"70mph\"", "units K, C, F"});
  require_refused(run_program("flight --speed 40 --angle 100"), {"--angle \"100\"", "-90 to 90"});
  require_refused(run_program("flight --speed 40 --wind-direction nan"), {"--wind-direction \"nan\""});
  // 1e300 deg flew as some direction a sine made of it.
  require_refused(run_program("flight --speed 40 --direction 1e300"), {"--direction \"1e300\"", "-360 to 360 deg"});
  require_refused(run_program("flight --speed 40 --wind-direction -361"), {"--wind-direction \"-361\""});
  require_refused(run_program("flight --speed 40 --spin-decay-time 0"), {"--spin-decay-time"});
  // Past these no flight landed within its minute: refused before any work, not failed after it.
  require_refused(run_program("flight --speed 40 --spin-decay-time 1e-9"), {"--spin-decay-time", ">= 0.01 s"});
  require_refused(run_program("flight --speed 40 --backspin 1e30"), {"--backspin \"1e30\"", "-1e5 to 1e5 rpm"});
  require_refused(run_program("flight --speed 1e300"), {"--speed \"1e300\"", "from 0 to 1000 m/s"});
  require_refused(run_program("flight --angle 30"), {"--speed"});
}

TEST_CASE("A study's distance is the flight of each impact's launch, in the study's air", "[flight][study]") {
  // Each point's launch (speed, angle, backspin from the oblique impact) flown by the flight
  // module in the air the keys give: the same numbers but for the rounding of rpm and deg F.
  const StudyDir d(1, "friction = 0.5\nundercut = \"1 in\"\nswing_tilt = 10\ntemperature = \"90 F\"\n"
                      "altitude = 1600\nhumidity = 20\nwind_speed = 5\nwind_direction = 180\n");
  const auto file = d.dir.write("flight.toml", file_text(d.study) + "[output]\nvariables = [\"distance\", \"apex\", "
                                                                       "\"hang_time\", \"landing_angle\"]\n");
  const Study study = load_study(file);
  REQUIRE(study.flight);
  for (std::size_t i = 0; i < study.points(); ++i) {
    const GridPoint p = grid_point(study, i);
    const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/") + (p.bat == 0 ? "r161.toml" : "torpedo.toml")),
                                           BeamTheory::timoshenko, ModeRequest::lowest(18));
    const ImpactResult r = simulate_point(p, &basis);
    REQUIRE(r.status == CollisionStatus::ok);
    Launch launch;
    launch.speed = r.launch.speed;
    launch.angle = r.launch.angle;
    launch.backspin = r.launch.backspin * 2 * std::numbers::pi / 60;
    Air air;
    air.temperature = (90 - 32) / 1.8 + 273.15;
    air.elevation = 1600;
    air.relative_humidity = 0.2;
    air.wind_speed = 5;
    air.wind_direction = 180;
    const FlightResult f = simulate_flight(launch, air);
    CHECK(r.launch.angle > 10);  // the undercut lifts it above the swing's tilt
    CHECK(r.distance == Approx(f.distance).epsilon(1e-12));
    CHECK(r.apex == Approx(f.apex).epsilon(1e-12));
    CHECK(r.hang_time == Approx(f.hang_time).epsilon(1e-12));
    CHECK(r.landing_angle == Approx(f.landing_angle).epsilon(1e-12));
  }
}

TEST_CASE("A study's air defaults to the calculator's, and its wind direction is in degrees however written",
          "[flight][study]") {
  // `flight`'s defaults read "29.92 inHg" through the units table: a study's air is the same.
  const ProgramRun json = run_program("flight --speed 40 --angle 30 --json");
  REQUIRE(json.exit_code == 0);
  char pressure[40];
  std::snprintf(pressure, sizeof pressure, "\"pressure\": %.17g", Air{}.pressure);
  CHECK_THAT(json.output, Catch::Contains(pressure));
  // "180 deg", "3.141592653589793 rad" and 180 are one direction: degrees, not radians.
  for (const std::string written : {"180", "\"180 deg\"", "\"3.141592653589793 rad\""}) {
    INFO(written);
    const StudyDir d(1, "friction = 0.5\nundercut = \"1 in\"\nwind_speed = 5\nwind_direction = " + written + "\n");
    const auto file = d.dir.write("wind.toml", file_text(d.study) + "[output]\nvariables = [\"distance\"]\n");
    CHECK(grid_point(load_study(file), 0).air.wind_direction == Approx(180).epsilon(1e-15));
  }
}

TEST_CASE("A batted ball launched past the vertical flies back, the mirror image of one short of it", "[flight]") {
  // Mirrored in the vertical plane across the heading, a launch at 90 + d deg with backspin b is
  // one at 90 - d deg with backspin -b (spin is an axial vector): the same distance, apex and time.
  for (const double backspin : {0.0, 2500.0, -1500.0}) {
    INFO("backspin " << backspin << " rpm");
    const FlightResult back = batted_flight(BallLaunch{35, 104, backspin, 0}, Air{});
    const FlightResult mirror = batted_flight(BallLaunch{35, 76, -backspin, 0}, Air{});
    CHECK(back.distance == Approx(mirror.distance).epsilon(1e-12));
    CHECK(back.apex == Approx(mirror.apex).epsilon(1e-12));
    CHECK(back.hang_time == Approx(mirror.hang_time).epsilon(1e-12));
  }
  // A study's pop-up undercut 6 cm below the ball's centre leaves at about 107 deg: it keeps its
  // impact and flies (it was refused as an angle past 90, and the point failed).
  const StudyDir d(1, "friction = 0.5\nswing_tilt = 8\nundercut = 0.06\n");
  const auto file = d.dir.write("popup.toml", file_text(d.study) + "[output]\nvariables = [\"distance\"]\n");
  const GridPoint p = grid_point(load_study(file), 0);
  const ModalBasis basis = compute_modes(load_bat(source_path("studies/bats/r161.toml")), BeamTheory::timoshenko,
                                         ModeRequest::lowest(18));
  const ImpactResult r = simulate_point(p, &basis);
  CHECK(r.status == CollisionStatus::ok);
  CHECK(r.launch.angle > 100);
  CHECK(r.distance > 0);
}

TEST_CASE("A ball launched level from the ground with a lift above its weight rises, as from a hair above it",
          "[flight]") {
  // 9000 rpm of backspin at 40 m/s: the Magnus lift beats gravity. From height 0 the flight
  // landed at once (distance 0); without the lift it still does.
  Launch l;
  l.speed = 40;
  l.angle = 0;
  l.backspin = 9000 * 2 * std::numbers::pi / 60;
  l.height = 0;
  const FlightResult ground = simulate_flight(l, Air{});
  l.height = 1e-9;
  const FlightResult above = simulate_flight(l, Air{});
  CHECK(ground.distance > 5);
  CHECK(ground.distance == Approx(above.distance).epsilon(1e-6));
  l.height = 0;
  l.backspin = 0;
  CHECK(simulate_flight(l, Air{}).distance == 0);
}

TEST_CASE("A study refuses air that is not air, naming the key", "[flight][study]") {
  for (const auto& [scene, words] : std::vector<std::pair<std::string, std::string>>{
           {"humidity = 150\n", "humidity"}, {"temperature = -5\n", "temperature"}, {"pressure = 0\n", "pressure"},
           {"pressure = 1e300\n", "pressure"}, {"altitude = 20000\n", "altitude"}, {"wind_speed = -1\n", "wind_speed"},
           {"wind_speed = 1e300\n", "wind_speed"},
           {"[output]\nsweet_spot_of = \"carry\"\n", "sweet_spot_of"}}) {
    const StudyDir d(1, scene);
    const std::string refusal = study_refusal(d.study);
    INFO(refusal);
    CHECK_THAT(refusal, Catch::Contains(words) && Catch::Contains("study.toml"));
  }
}
