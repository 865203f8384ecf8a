#include "sweetspot/bat/shipped_bats.hpp"

#include <algorithm>
#include <system_error>

#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace fs = std::filesystem;

fs::path shipped_bats_dir(const fs::path& origin, const std::vector<std::string>& data_dirs) {
  for (const std::string& data : data_dirs) {
    std::error_code error;
    const fs::path dir = (origin / data / "bats").lexically_normal();
    if (fs::is_directory(dir, error)) return dir;
  }
  return {};
}

std::vector<std::string> shipped_bat_names(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code error;
  if (dir.empty() || !fs::is_directory(dir, error)) return names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

fs::path find_bat_file(const std::string& argument, const fs::path& dir, std::string_view option) {
  std::error_code error;
  const bool path_like = argument.find('/') != std::string::npos || fs::path(argument).extension() == ".toml";
  if (path_like || argument.empty() || fs::exists(argument, error)) return argument;  // load_bat says what is wrong
  const std::vector<std::string> names = shipped_bat_names(dir);
  if (std::find(names.begin(), names.end(), argument) != names.end()) return dir / (argument + ".toml");
  std::string message = std::string(option) + ": no bat file or shipped bat '" + argument + "'";
  if (names.empty()) throw InputError(message + " (and no shipped bats were found beside the program)");
  message += " (shipped:";
  for (const std::string& name : names) message += " " + name;
  throw InputError(message + ")");
}

}  // namespace sweetspot
