#pragma once
// The air a batted ball flies through: its density from temperature, pressure, field elevation
// and humidity, and the wind. Free of I/O; SI throughout.
//
// Density is moist air as an ideal gas, rho = (p - 0.378 e) / (R_d T) (dry air plus water vapour,
// R_d / R_v = 0.622), with the vapour pressure e = RH e_s(T) and e_s from Buck's formula over
// water (A. L. Buck, J. Appl. Meteor. 20, 1527 (1981), as updated in the Buck Research CR-1A
// manual (1996)): e_s = 611.21 Pa exp((18.678 - T/234.5) T / (257.14 + T)), T in deg C. This is
// the density of A. M. Nathan's trajectory calculator (baseball.physics.illinois.edu), which
// writes the same law with rounded constants (1.2929 kg/m^3 at 273 K and 760 mmHg, 0.3783).
//
// Pressure is the barometric pressure as weather services report it, reduced to sea level; the
// ball's own pressure is that times exp(-beta h) at the field's elevation h, beta = 1.217e-4 /m
// (a scale height of 8.2 km), as the calculator does. Give an elevation alone and the standard
// 101325 Pa is reduced; give a station pressure with elevation 0.

#include <optional>
#include <string>

namespace sweetspot {

// What is wrong with one input: its key (as a study or Python names it), its value in SI, and
// what was expected. The command line phrases it with the value as the user wrote it.
struct InputProblem {
  std::string key;
  double value = 0;
  std::string expected;
};

// "<prefix><key> = <value>: expected <expected>", thrown as InputError.
[[noreturn]] void refuse(const InputProblem& problem, const char* prefix);

struct Air {
  double temperature = 294.261111111111111;  // K (70 deg F, the calculator's default)
  // Pa, reduced to sea level: 29.92 inHg (the calculator's), 29.92 x 3386.388640341 rounded once,
  // as "29.92 inHg" reads (two roundings would give the next double up).
  double pressure = 101320.74811900272;
  double elevation = 0;                       // m above sea level
  double relative_humidity = 0.5;             // 0..1
  double wind_speed = 0;                      // m/s, horizontal, uniform
  // deg: the direction the wind blows TOWARD, from the line home plate -> centre field, positive
  // toward right field (the launch direction's convention): 0 blows out to centre, 180 blows in.
  double wind_direction = 0;
};

inline constexpr double standard_pressure = 101325;                // Pa
// The air's temperatures, K: the vapour pressure's formula (Buck's, the calculator's) holds down to
// about -80 C and has a pole at 16 K; colder air was refused later as too humid, naming humidity.
inline constexpr double min_air_temperature = 173.15, max_air_temperature = 373.15;  // -100 C, 100 C
inline constexpr const char* air_temperature_expected =
    "an absolute temperature above 173.15 K (-100 C) and below 373.15 K (100 C)";
// Sea-level pressures on record lie from 87 to 108 kPa, the strongest gusts at about 110 m/s; far
// outside, the ball never landed (1e300 of either) or the air had no density left beside its vapour
// (a pressure of 1e-300, which was then laid at the humidity's door).
inline constexpr const char* air_pressure_expected = "a sea-level pressure from 50 to 150 kPa (Pa)";
inline bool valid_air_pressure(double pa) { return pa >= 50e3 && pa <= 150e3; }
inline constexpr const char* wind_speed_expected = "a speed from 0 to 120 m/s";
inline bool valid_wind_speed(double v) { return v >= 0 && v <= 120; }
inline constexpr double pressure_decay_per_metre = 1.217e-4;       // beta, 1/m (the calculator's)
inline constexpr double dry_air_gas_constant = 287.058;            // R_d, J/(kg K)

// Buck's saturation vapour pressure over water (Pa) at `temperature` (K).
double saturation_vapour_pressure(double temperature);

// The pressure at the field (Pa): air.pressure exp(-beta elevation).
double station_pressure(const Air& air);

// Moist-air density (kg/m^3).
double air_density(const Air& air);

// The first thing unphysical about the air, or nothing: temperature > 0 K (and below 373.15 K,
// where Buck's formula and outdoor air end), pressure > 0, elevation in (-1 km, 10 km), humidity
// in [0, 1], wind speed >= 0, wind direction in [-360, 360] deg, everything finite (keys
// temperature, pressure, altitude, humidity, wind_speed, wind_direction).
std::optional<InputProblem> air_problem(const Air& air);

// InputError from air_problem; `prefix` starts the message ("flight: ").
void check_air(const Air& air, const char* prefix = "");

}  // namespace sweetspot
