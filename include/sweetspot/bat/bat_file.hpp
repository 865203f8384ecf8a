#pragma once
// Reading a bat from its TOML file and the profile CSV it names (README: "Bat files").
#include <filesystem>

#include "sweetspot/bat/bat.hpp"

namespace sweetspot {

// Loads and validates a bat file; throws InputError naming the file, key or CSV line, the value
// and what was expected.
Bat load_bat(const std::filesystem::path& toml_path);

}  // namespace sweetspot
