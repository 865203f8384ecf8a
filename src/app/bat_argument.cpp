#include "bat_argument.hpp"

#include <system_error>

#include "sweetspot/bat/shipped_bats.hpp"

namespace sweetspot::app {

std::filesystem::path bat_argument(const std::string& argument, std::string_view option) {
  // The data folder relative to the program: installed (bin/ -> share/sweetspot) and in the build
  // tree (build/share/sweetspot, linked to the checkout's studies); CMakeLists.txt sets both.
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path dir =
      error ? std::filesystem::path() : shipped_bats_dir(program.parent_path(), {SWEETSPOT_DATA_INSTALLED, SWEETSPOT_DATA_BUILD});
  return find_bat_file(argument, dir, option);
}

}  // namespace sweetspot::app
