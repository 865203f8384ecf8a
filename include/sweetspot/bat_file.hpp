#pragma once
// Reading a bat from its TOML file and the profile CSV it names (README: "Bat files").
#include <filesystem>

#include "sweetspot/bat.hpp"

namespace sweetspot {

// Loads and validates a bat file; throws InputError naming the file, key or CSV line, the value
// and what was expected.
Bat load_bat(const std::filesystem::path& toml_path);

// The profile CSV a bat file names, resolved against the bat file's directory as load_bat does
// (a run must know every file it reads: none may be its output, and all key its journal).
// Throws InputError as load_bat does when the bat file or its key 'profile' is unreadable.
std::filesystem::path profile_path(const std::filesystem::path& toml_path);

}  // namespace sweetspot
