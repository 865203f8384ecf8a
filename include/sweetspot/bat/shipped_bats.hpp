#pragma once
// The bat files shipped with sweetspot, found by name: `sweetspot impact --bat r161`,
// `sweetspot.Bat.load("r161")`. They are the checkout's studies/bats, installed as
// share/sweetspot/bats; the build tree links build/share/sweetspot to them, so that a program or
// module finds them at the same place relative to itself in both (shipped_bats_dir).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sweetspot {

// The shipped bats' folder seen from `origin`, the folder of the program or the Python module:
// origin/<data>/bats for the first of `data_dirs` (paths relative to origin, the installed
// layout's and the build tree's) where it is a folder; empty when there is none.
std::filesystem::path shipped_bats_dir(const std::filesystem::path& origin, const std::vector<std::string>& data_dirs);

// The names of the shipped bats in `dir` (r161, torpedo, ...): its .toml files, sorted.
std::vector<std::string> shipped_bat_names(const std::filesystem::path& dir);

// The bat file `argument` names: the argument itself when it is a file or looks like a path (it
// has a '/' or ends in .toml); otherwise the shipped bat of that name, dir/<argument>.toml. An
// unknown name throws InputError, "<option>: no bat file or shipped bat 'x' (shipped: ...)".
std::filesystem::path find_bat_file(const std::string& argument, const std::filesystem::path& dir,
                                    std::string_view option);

}  // namespace sweetspot
