#include "sweetspot/ball/ball_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "ball/ball_table.hpp"
#include "sweetspot/ball/ball_presets.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_parse.hpp"

namespace sweetspot {

BallFit load_ball(const std::string& preset_or_file, const std::string& option) {
  if (!preset_or_file.ends_with(".toml")) return preset_ball(find_ball_preset(preset_or_file, option));
  if (!std::filesystem::is_regular_file(preset_or_file))
    throw InputError(preset_or_file + ": no such ball file (expected a preset's name or a TOML file with a [ball] table)");
  toml::table file;
  try {
    std::ifstream in(preset_or_file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    file = detail::parse_toml_text(text.str(), preset_or_file);
  } catch (const toml::parse_error& e) {
    throw InputError(preset_or_file + ": line " + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description()));
  }
  const toml::table* table = file["ball"].as_table();
  if (!table) throw InputError(preset_or_file + ": [ball] is missing: expected a table stating the ball");
  return detail::read_ball_table(*table, preset_or_file);
}

}  // namespace sweetspot
