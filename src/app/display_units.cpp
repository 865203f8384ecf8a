#include "display_units.hpp"

#include <cstdio>

#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot::app {

namespace {

std::string with_unit(double value, const char* format, const char* unit) {
  return DisplayUnits::number(value, format) + " " + unit;
}

constexpr double ounce_square_inch = kilograms_per_ounce * metres_per_inch * metres_per_inch;

}  // namespace

std::string DisplayUnits::number(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void DisplayUnits::add_option(CLI::App& cmd) {
  cmd.add_option("--units", system_, "units of the text output: si (m, kg, m/s) or us (in, oz, mph, oz in^2)")
      ->check(CLI::IsMember({"si", "us"}))
      ->capture_default_str();
}

void DisplayUnits::check_text_output(const std::string& command, bool json) const {
  if (json && us())
    throw InputError(command + ": --units us applies to the text output; --json is always in SI units (m, kg, m/s, "
                               "kg m^2): expected one of --units us and --json");
}

std::string DisplayUnits::length(double metres, const char* format) const {
  return us() ? with_unit(metres / metres_per_inch, format, "in") : with_unit(metres, format, "m");
}

std::string DisplayUnits::small_length(double metres, const char* format) const {
  return us() ? with_unit(metres / metres_per_inch, format, "in") : with_unit(1e3 * metres, format, "mm");
}

std::string DisplayUnits::mass(double kilograms, const char* format) const {
  return us() ? with_unit(kilograms / kilograms_per_ounce, format, "oz") : with_unit(kilograms, format, "kg");
}

std::string DisplayUnits::speed(double metres_per_second, const char* format) const {
  return us() ? with_unit(metres_per_second / metres_per_second_per_mph, format, "mph")
              : with_unit(metres_per_second, format, "m/s");
}

std::string DisplayUnits::moment_of_inertia(double kilogram_square_metres, const char* format) const {
  return us() ? with_unit(kilogram_square_metres / ounce_square_inch, format, "oz in^2")
              : with_unit(kilogram_square_metres, format, "kg m^2");
}

std::string DisplayUnits::per_speed(double per_metre_per_second, const char* format) const {
  return us() ? with_unit(per_metre_per_second * metres_per_second_per_mph, format, "per mph")
              : with_unit(per_metre_per_second, format, "per m/s");
}

std::string DisplayUnits::both(const std::string& si, const std::string& us) const {
  return this->us() ? us + " (" + si + ")" : si + " (" + us + ")";
}

}  // namespace sweetspot::app
