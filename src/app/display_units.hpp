#pragma once
// --units: the units the text output writes physical values in. SI is the default and prints as
// it always has; "us" writes lengths in in, masses in oz, speeds in mph and moments of inertia
// (swing weights) in oz in^2, the unit beside each value. JSON output is always SI, so --units us
// with --json is refused rather than silently ignored.
#include <CLI/CLI.hpp>
#include <string>
#include <utility>

namespace sweetspot::app {

class DisplayUnits {
 public:
  // Adds --units si|us to the command.
  void add_option(CLI::App& cmd);
  // InputError when --units us meets --json: JSON keeps SI (its keys and the README say so).
  void check_text_output(const std::string& command, bool json) const;
  bool us() const { return system_ == "us"; }
  static DisplayUnits si_units() { return DisplayUnits("si"); }
  static DisplayUnits us_units() { return DisplayUnits("us"); }
  DisplayUnits() = default;

  // A plain number as printf's `format` writes it.
  static std::string number(double value, const char* format);

  // The value (given in SI) printed with `format` ("%.4f") and its unit: "0.7112 m" or "28.0000 in".
  std::string length(double metres, const char* format) const;
  // A compression or a displacement: mm in SI, in in US units.
  std::string small_length(double metres, const char* format) const;
  std::string mass(double kilograms, const char* format) const;
  std::string speed(double metres_per_second, const char* format) const;
  std::string moment_of_inertia(double kilogram_square_metres, const char* format) const;
  // A COR's fall with speed: "-0.002 per m/s" or "-0.00089 per mph".
  std::string per_speed(double per_metre_per_second, const char* format) const;
  // A value given in both systems: "0.8382 m (33.00 in)", or with --units us "33.00 in (0.8382 m)".
  std::string both(const std::string& si, const std::string& us) const;

 private:
  explicit DisplayUnits(std::string system) : system_(std::move(system)) {}
  std::string system_ = "si";
};

}  // namespace sweetspot::app
