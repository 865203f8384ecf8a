#pragma once
// A design of named dimensions written back as a bat file (README "Bat files"), so that a bat
// made by a program (the optimiser's best design) is read by every command as any other bat.
#include <string>

#include "sweetspot/bat/bat_design.hpp"

namespace sweetspot {

// The TOML text of a bat file that load_bat_design reads back as `design`, bit for bit: every
// number with 17 significant digits, every material constant written out (beside the preset's
// name, which they override), every dimension. `comment` (lines without '#') heads the file.
// Throws std::invalid_argument for a design given by a profile, which has no dimensions to write.
std::string bat_design_text(const BatDesign& design, const std::string& comment);

}  // namespace sweetspot
