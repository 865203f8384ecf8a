#pragma once
// What kind of input a TOML file is, read from its top-level keys: a command given another
// command's file then says what the file is and which command runs it, where its reader would
// name the first key it does not know ("unknown key 'bat'" for an optimisation file given to
// `run`).
#include <filesystem>
#include <initializer_list>
#include <string>

namespace sweetspot {

enum class InputKind {
  study,              // [scene] and [axes]: `sweetspot run`
  uncertainty_study,  // kind = "uncertainty": `sweetspot run`
  optimisation,       // [free], [objective], ...: `sweetspot optimize`
};

// The file's kind. Throws InputError when it cannot be read (naming it as `what`: "study file")
// or is no TOML, as its reader would.
InputKind input_kind(const std::filesystem::path& file, const std::string& what);

// The file's kind when it is among `accepted`; else throws InputError in one line: what the
// file is, that `command` does not take it, and which command does.
InputKind require_input_kind(const std::filesystem::path& file, std::initializer_list<InputKind> accepted,
                             const std::string& command, const std::string& what);

}  // namespace sweetspot
