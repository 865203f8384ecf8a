// sweetspot: the ball-bat collision engine's command line.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/version.hpp"

namespace {

// An empty value reads as none: some options then kept their default silently (--swing-tilt ""),
// others said ": file not found" (--bat ""). Refused as any bad input, naming the option. An empty
// output path has its own refusal, with the output's other checks (output_paths.hpp).
std::string empty_argument(int argc, char** argv) {
  for (int i = 2; i < argc; ++i) {
    if (argv[i][0] != '\0') continue;
    const std::string before = argv[i - 1];
    if (before == "-o" || before == "--output") continue;
    const std::string what = before.starts_with("-") ? before + " \"\"" : std::string("an empty argument");
    return std::string(argv[1]) + ": " + what + ": expected a value, not an empty string";
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sweetspot: the ball-bat collision of Nathan, Am. J. Phys. 68, 979 (2000)"};
  app.set_version_flag("--version", std::string(sweetspot::version) + " (" + sweetspot::git_commit + ")");
  app.require_subcommand(1);
  sweetspot::app::add_modes_command(app);
  sweetspot::app::add_impact_command(app);
  sweetspot::app::add_wall_command(app);
  sweetspot::app::add_toy_command(app);
  sweetspot::app::add_ball_command(app);
  sweetspot::app::add_run_command(app);
  sweetspot::app::add_convergence_command(app);
  sweetspot::app::add_certify_command(app);
  sweetspot::app::add_optimize_command(app);
  sweetspot::app::add_flight_command(app);
  if (const std::string empty = empty_argument(argc, argv); !empty.empty()) {
    std::fprintf(stderr, "sweetspot: error: %s (see sweetspot %s --help)\n", sweetspot::app::printable(empty).c_str(),
                 argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help, --version
    // A usage error is a bad input like any other: one line, exit status 2.
    std::string text = e.what();
    std::replace(text.begin(), text.end(), '\n', ' ');
    // CLI11 names the option and its value, not what it should be: every option it converts is a number.
    if (const std::string unconverted = "Could not convert: "; text.starts_with(unconverted))
      text = text.substr(unconverted.size()) + ": expected a number";
    // CLI11's ranges say "Value abc not in range 4 to 4096" of a value that is no number at all.
    if (const std::size_t at = text.find("Value "), range = text.find(" not in range "); at != std::string::npos &&
        range != std::string::npos && range > at)
      text.replace(at, range + 14 - at, "'" + text.substr(at + 6, range - at - 6) + "': expected a whole number from ");
    for (const CLI::App* command : app.get_subcommands()) text = command->get_name() + ": " + text;
    if (app.get_subcommands().empty()) {  // CLI11 says only "A subcommand is required"
      text = "expected a command: modes, impact, wall, toy, ball, run, convergence, certify, optimize or flight";
      if (argc > 1) text += ", not '" + std::string(argv[1]) + "'";
    }
    std::fprintf(stderr, "sweetspot: error: %s (see sweetspot%s --help)\n", sweetspot::app::printable(text).c_str(),
                 app.get_subcommands().empty() ? "" : (" " + app.get_subcommands().front()->get_name()).c_str());
    return 2;
  } catch (const sweetspot::InputError& e) {
    std::fprintf(stderr, "sweetspot: error: %s\n", sweetspot::app::printable(e.what()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweetspot: error: %s\n", sweetspot::app::printable(e.what()).c_str());
    return 1;
  }
  return sweetspot::app::exit_status;
}
