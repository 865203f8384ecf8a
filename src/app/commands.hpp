#pragma once
// The program's subcommands. Each adds itself to the command line and runs when chosen.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

#include "json.hpp"
#include "sweetspot/bat/bat.hpp"
#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"

namespace sweetspot::app {

// The exit status of a command that ran to its end: 0, or `failed_check` when `certify` checked the
// bat and it breaks a rule. Bad input is 2 and an error 1 (main.cpp), so a script can tell a
// verdict from a failure to reach one.
inline constexpr int failed_check = 3;
inline int exit_status = 0;

// An error line as the terminal shows it: control characters from a file's contents (an escape
// sequence in a bat's name, say) written as \xHH, so that the one line stays one line and cannot
// clear or recolour the user's screen.
inline std::string printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}


void add_modes_command(CLI::App& app);
void add_impact_command(CLI::App& app);
void add_wall_command(CLI::App& app);
void add_toy_command(CLI::App& app);
void add_ball_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_convergence_command(CLI::App& app);
void add_certify_command(CLI::App& app);
void add_optimize_command(CLI::App& app);
void add_flight_command(CLI::App& app);

// A hollow bat's [barrel] table as the wall used it: its load, and what calibrated it (null: not
// given), in `impact --json` and `certify --json`.
Json barrel_json(const BarrelCalibration& barrel);

// --modes: a number of vibrational modes, "all" or "auto"; InputError naming --modes otherwise.
int parse_modes(const std::string& text);

// Options shared by the commands that run a collision: --ball (a preset or a ball file) and the
// force law's parameters, which override the named ball's once resolve_ball has run.
void add_ball_options(CLI::App& cmd, Ball& ball, std::string& named_ball);
void resolve_ball(const CLI::App& cmd, const std::string& named_ball, Ball& ball);
void add_integrator_options(CLI::App& cmd, CollisionOptions& options);
// N2000's integration (RK4) under --n2000 unless --integrator was given, then the chosen
// integrator's own step unless --dt was given.
void resolve_integrator(const CLI::App& cmd, CollisionOptions& options);

}  // namespace sweetspot::app
