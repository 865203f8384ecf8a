// sweetspot flight: the batted ball's flight from a launch through the air (src/flight).
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "json.hpp"
#include "sweetspot/flight/flight.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/units/quantity.hpp"

namespace sweetspot::app {

namespace {

// One option's text as the user wrote it, what it measures and how a plain number is read.
struct QuantityText {
  std::string text;
  std::optional<Dimension> dimension;  // nothing: a plain number only (humidity, in %)
  std::string_view plain_unit;         // "": SI
};

struct FlightCommandOptions {
  // The option names are the study keys with '-' for '_' (flight_inputs.cpp, air.cpp).
  std::map<std::string, QuantityText> values{
      {"speed", {"", Dimension::speed, ""}},
      {"angle", {"0", Dimension::angle, "deg"}},
      {"direction", {"0", Dimension::angle, "deg"}},
      {"backspin", {"0", Dimension::angular_speed, ""}},
      {"sidespin", {"0", Dimension::angular_speed, ""}},
      {"height", {"3 ft", Dimension::length, ""}},
      {"temperature", {"70 F", Dimension::temperature, ""}},
      {"pressure", {"29.92 inHg", Dimension::pressure, ""}},
      {"altitude", {"0", Dimension::length, ""}},
      {"humidity", {"50", std::nullopt, ""}},
      {"wind_speed", {"0", Dimension::speed, ""}},
      {"wind_direction", {"0", Dimension::angle, "deg"}},
  };
  double spin_decay_time = Aerodynamics{}.spin_decay_time;
  double samples = 0;
  bool vacuum = false;
  bool json = false;
};

std::string option_name(std::string key) {
  for (char& c : key)
    if (c == '_') c = '-';
  return "--" + key;
}

std::optional<double> plain_number(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  if (text.starts_with('+')) text.remove_prefix(1);
  double x = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return x;
}

// The option's value in SI, or in its plain unit where it has one (angles in deg: 27.5 stays
// 27.5), humidity as a fraction; InputError naming the option as written otherwise.
double read(const std::string& key, const QuantityText& q) {
  const std::string head = "flight: " + option_name(key) + " \"" + q.text + "\": expected ";
  if (!q.dimension) {  // humidity: a number of percent, "50" or "50%"
    std::string_view text = q.text;
    if (text.ends_with('%')) text.remove_suffix(1);
    while (text.ends_with(' ')) text.remove_suffix(1);  // "50 %" as "50%"
    const std::optional<double> percent = plain_number(text);
    if (!percent) throw InputError(head + "a relative humidity in % (a number from 0 to 100)");
    return *percent / 100;
  }
  const Unit* plain = q.plain_unit.empty() ? nullptr : find_unit(q.plain_unit);
  if (const std::optional<double> x = plain_number(q.text)) return *x;  // NaN reaches the physical checks
  if (const std::optional<double> si = parse_quantity(q.text, *q.dimension))
    return plain ? in_unit(*si, *plain) : *si;  // "0.48 rad" as deg
  std::string expected = expected_quantity(*q.dimension);
  if (plain) {
    const std::string si_text = "a number in " + std::string(si_unit(*q.dimension));
    expected.replace(expected.find(si_text), si_text.size(), "a number in " + std::string(q.plain_unit));
  }
  throw InputError(head + expected);
}

// A physical check's complaint, phrased with the option and its text as the user wrote them.
[[noreturn]] void refuse_option(const FlightCommandOptions& o, const InputProblem& problem) {
  const auto it = o.values.find(problem.key);
  if (it == o.values.end()) refuse(problem, "flight: ");
  throw InputError("flight: " + option_name(problem.key) + " \"" + it->second.text + "\": expected " +
                   problem.expected);
}

Json samples_json(const std::vector<FlightSample>& samples) {
  std::vector<double> t, x, y, z, vx, vy, vz;
  for (const FlightSample& s : samples) {
    t.push_back(s.t), x.push_back(s.x), y.push_back(s.y), z.push_back(s.z);
    vx.push_back(s.vx), vy.push_back(s.vy), vz.push_back(s.vz);
  }
  return Json::Object()
      .add("t", Json::numbers(t))
      .add("x", Json::numbers(x))
      .add("y", Json::numbers(y))
      .add("z", Json::numbers(z))
      .add("vx", Json::numbers(vx))
      .add("vy", Json::numbers(vy))
      .add("vz", Json::numbers(vz));
}

void print_json(const Launch& l, const Air& air, const FlightResult& r) {
  Json::Object out;
  out.add("speed", l.speed).add("angle", l.angle).add("direction", l.direction);
  out.add("backspin", l.backspin).add("sidespin", l.sidespin).add("height", l.height);
  out.add("temperature", air.temperature).add("pressure", air.pressure).add("altitude", air.elevation);
  out.add("humidity", 100 * air.relative_humidity).add("wind_speed", air.wind_speed);
  out.add("wind_direction", air.wind_direction).add("air_density", r.air_density);
  out.add("distance", r.distance).add("apex", r.apex).add("apex_time", r.apex_time);
  out.add("hang_time", r.hang_time).add("landing_angle", r.landing_angle).add("landing_speed", r.landing_speed);
  out.add("landing_spin", r.landing_spin);
  out.add("bearing", r.bearing).add("landing_x", r.landing_x).add("landing_y", r.landing_y);
  if (!r.samples.empty()) out.add("trajectory", samples_json(r.samples));
  std::printf("%s\n", Json(out).text().c_str());
}

void print_text(const FlightResult& r) {
  constexpr double ft = 0.3048, mph = 0.44704;
  std::printf("distance %.2f m (%.1f ft)\n", r.distance, r.distance / ft);
  std::printf("apex %.2f m (%.1f ft) at %.3f s\n", r.apex, r.apex / ft, r.apex_time);
  std::printf("hang time %.3f s\n", r.hang_time);
  std::printf("landing angle %.2f deg, speed %.2f m/s (%.1f mph)\n", r.landing_angle, r.landing_speed,
              r.landing_speed / mph);
  std::printf("bearing %.2f deg (x %.2f m toward right field, y %.2f m toward centre field)\n", r.bearing,
              r.landing_x, r.landing_y);
  std::printf("air density %.5f kg/m^3\n", r.air_density);
  if (r.samples.empty()) return;
  std::printf("%8s %10s %10s %10s\n", "t (s)", "x (m)", "y (m)", "z (m)");
  for (const FlightSample& s : r.samples) std::printf("%8.3f %10.3f %10.3f %10.3f\n", s.t, s.x, s.y, s.z);
}

void run_flight(const FlightCommandOptions& o) {
  std::map<std::string, double> v;
  for (const auto& [key, q] : o.values) v[key] = read(key, q);
  const Launch launch{v["speed"], v["angle"], v["direction"], v["backspin"], v["sidespin"], v["height"]};
  const Air air{v["temperature"], v["pressure"], v["altitude"], v["humidity"], v["wind_speed"], v["wind_direction"]};
  FlightOptions options;
  options.aerodynamics.spin_decay_time = o.spin_decay_time;
  options.sample_interval = o.samples;
  options.drag = options.lift = !o.vacuum;
  if (const auto problem = launch_problem(launch)) refuse_option(o, *problem);
  if (const auto problem = air_problem(air)) refuse_option(o, *problem);
  if (const auto problem = flight_options_problem(options)) {
    // The two options CLI11 reads as numbers: named as options, the value as the number read.
    InputProblem named = *problem;
    if (named.key == "spin_decay_time") named.key = "--spin-decay-time";
    if (named.key == "sample_interval") named.key = "--samples";
    refuse(named, "flight: ");
  }
  const FlightResult r = simulate_flight(launch, air, options);
  if (o.json)
    print_json(launch, air, r);
  else
    print_text(r);
}

}  // namespace

void add_flight_command(CLI::App& app) {
  auto o = std::make_shared<FlightCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "flight", "The batted ball's flight: distance, apex, hang time and landing angle (Nathan's trajectory model)");
  const auto add = [&](const std::string& key, const std::string& help) {
    return cmd->add_option(option_name(key), o->values.at(key).text, help)->default_str(o->values.at(key).text);
  };
  add("speed", "launch speed: m/s, or e.g. 103mph")->required();
  add("angle", "launch angle above the horizontal: deg, or e.g. 0.48rad");
  add("direction", "launch direction from centre field toward right field: deg");
  add("backspin", "backspin: rad/s, or e.g. 2500rpm");
  add("sidespin", "sidespin (positive curves toward left field): rad/s, or e.g. 500rpm");
  add("height", "launch height above the ground: m, or e.g. 3ft");
  add("temperature", "air temperature: K, or e.g. 70F, 21C");
  add("pressure", "barometric pressure reduced to sea level: Pa, or e.g. 29.92inHg, 1013hPa");
  add("altitude", "the field's elevation above sea level: m, or e.g. 5280ft");
  add("humidity", "relative humidity: % (0 to 100)");
  add("wind_speed", "wind speed: m/s, or e.g. 10mph");
  add("wind_direction", "the direction the wind blows toward, from centre field toward right field: deg (180: in)");
  cmd->add_option("--spin-decay-time", o->spin_decay_time, "spin decay time at 100 mph: s (the calculator's 1e4: none)")
      ->capture_default_str();
  cmd->add_option("--samples", o->samples, "print the trajectory every this many seconds (0: no; else >= 0.001)")
      ->capture_default_str();
  cmd->add_flag("--vacuum", o->vacuum, "no air: no drag and no lift (the parabola)");
  cmd->add_flag("--json", o->json, "print one JSON object (in SI units; angles in deg, humidity in %)");
  cmd->callback([o] { run_flight(*o); });
}

}  // namespace sweetspot::app
