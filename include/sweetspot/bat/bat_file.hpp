#pragma once
// Reading a bat from its TOML file and the profile CSV it names, or its [dimensions] (README:
// "Bat files"). The file becomes a BatDesign (bat_design.hpp, load_bat_design), which becomes the
// Bat: one path for every bat.
#include <filesystem>
#include <string>

#include "sweetspot/bat/bat.hpp"

namespace sweetspot {

// Loads and validates a bat file; throws InputError naming the file, key or CSV line, the value
// and what was expected.
Bat load_bat(const std::filesystem::path& toml_path);

// The files a bat was read from and their texts byte for byte, as load_bat parsed them: what a
// dataset stores so that its bats can be told apart and rebuilt. A bat of named dimensions reads
// no profile: its profile file and text are empty.
struct BatSource {
  std::filesystem::path toml_file, profile_file;
  std::string toml_text, profile_text;
};

// As load_bat, and fills `source` with the texts the bat was built from.
Bat load_bat(const std::filesystem::path& toml_path, BatSource& source);

}  // namespace sweetspot
