#pragma once
// A bat on the command line: a bat file, or the name of a bat shipped with sweetspot (`--bat r161`),
// looked up beside the program (include/sweetspot/bat/shipped_bats.hpp).
#include <filesystem>
#include <string>
#include <string_view>

namespace sweetspot::app {

// The bat file `argument` names; InputError naming `option` and the shipped bats for an unknown name.
std::filesystem::path bat_argument(const std::string& argument, std::string_view option);

}  // namespace sweetspot::app
