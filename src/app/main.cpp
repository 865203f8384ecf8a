// sweetspot: the ball-bat collision engine's command line.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "commands.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"sweetspot: the ball-bat collision of Nathan, Am. J. Phys. 68, 979 (2000)"};
  app.set_version_flag("--version", std::string(sweetspot::version) + " (" + sweetspot::git_commit + ")");
  app.require_subcommand(1);
  sweetspot::app::add_modes_command(app);
  sweetspot::app::add_impact_command(app);
  sweetspot::app::add_wall_command(app);
  sweetspot::app::add_toy_command(app);
  sweetspot::app::add_run_command(app);
  sweetspot::app::add_convergence_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const sweetspot::InputError& e) {
    std::fprintf(stderr, "sweetspot: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweetspot: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
