#include "sweetspot/study/input_kind.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "study/study_settings.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

// The top-level tables only an optimisation file has (problem_file.cpp).
constexpr std::array<std::string_view, 4> optimisation_tables = {"free", "objective", "constraints", "optimizer"};

// What the file is, in words a message can start with, and the command that runs it.
std::string described(InputKind kind) {
  switch (kind) {
    case InputKind::study: return "a study: run it with `sweetspot run`";
    case InputKind::uncertainty_study:
      return "an uncertainty study (kind = \"uncertainty\"): run it with `sweetspot run`";
    case InputKind::optimisation: return "an optimisation file (it has [free]): run it with `sweetspot optimize`";
  }
  return {};
}

}  // namespace

InputKind input_kind(const std::filesystem::path& file, const std::string& what) {
  const toml::table doc = study_detail::parse_toml(file, study_detail::read_text(file, what));
  if (const toml::node* kind = doc.get("kind"); kind && kind->value<std::string>() == std::string("uncertainty"))
    return InputKind::uncertainty_study;
  const auto has = [&doc](std::string_view key) { return doc.contains(key); };
  return std::ranges::any_of(optimisation_tables, has) ? InputKind::optimisation : InputKind::study;
}

InputKind require_input_kind(const std::filesystem::path& file, std::initializer_list<InputKind> accepted,
                             const std::string& command, const std::string& what) {
  const InputKind kind = input_kind(file, what);
  if (std::ranges::find(accepted, kind) == accepted.end())
    throw InputError(file.string() + ": " + command + " does not take " + described(kind));
  return kind;
}

}  // namespace sweetspot
