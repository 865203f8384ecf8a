#include "sweetspot/flight/air.hpp"

#include <cmath>
#include <cstdio>

#include "sweetspot/input_error.hpp"

namespace sweetspot {

void refuse(const InputProblem& problem, const char* prefix) {
  char value[32];
  std::snprintf(value, sizeof value, "%.10g", problem.value);
  throw InputError(std::string(prefix) + problem.key + " = " + value + ": expected " + problem.expected);
}

double saturation_vapour_pressure(double temperature) {
  const double celsius = temperature - 273.15;
  return 611.21 * std::exp((18.678 - celsius / 234.5) * celsius / (257.14 + celsius));
}

double station_pressure(const Air& air) { return air.pressure * std::exp(-pressure_decay_per_metre * air.elevation); }

double air_density(const Air& air) {
  const double vapour = air.relative_humidity * saturation_vapour_pressure(air.temperature);
  return (station_pressure(air) - 0.378 * vapour) / (dry_air_gas_constant * air.temperature);
}

std::optional<InputProblem> air_problem(const Air& air) {
  if (!(air.temperature > min_air_temperature) || !(air.temperature < max_air_temperature))
    return InputProblem{"temperature", air.temperature, air_temperature_expected};
  if (!valid_air_pressure(air.pressure)) return InputProblem{"pressure", air.pressure, air_pressure_expected};
  if (!(air.elevation > -1000 && air.elevation < 10000))
    return InputProblem{"altitude", air.elevation, "an elevation between -1000 m and 10000 m"};
  if (!(air.relative_humidity >= 0 && air.relative_humidity <= 1))
    return InputProblem{"humidity", 100 * air.relative_humidity, "a relative humidity from 0 to 100 %"};
  if (!valid_wind_speed(air.wind_speed)) return InputProblem{"wind_speed", air.wind_speed, wind_speed_expected};
  if (!(std::abs(air.wind_direction) <= 360))  // as a launch's direction (flight_inputs.cpp)
    return InputProblem{"wind_direction", air.wind_direction, "an angle from -360 to 360 deg"};
  // Air so hot and humid that its vapour would exceed its pressure is not air.
  if (!(air_density(air) > 0))
    return InputProblem{"humidity", 100 * air.relative_humidity, "a humidity whose vapour pressure is below the air's"};
  return std::nullopt;
}

void check_air(const Air& air, const char* prefix) {
  if (const auto problem = air_problem(air)) refuse(*problem, prefix);
}

}  // namespace sweetspot
