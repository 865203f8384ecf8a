#include "sweetspot/bat/bat_design_text.hpp"

#include "sweetspot/bat/material_presets.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace sweetspot {

namespace {

// 17 significant digits: the double itself comes back when the file is read.
std::string exact(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

// A control character as TOML writes it in a basic string: TOML allows none of them raw (tab
// aside), so a name or title holding a \r or a NUL would make the whole file unreadable.
bool is_control(char c) { return (static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f; }

std::string escaped_control(char c) {
  char text[8];
  std::snprintf(text, sizeof text, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
  return text;
}

// A TOML basic string.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (c == '\n')
      out += "\\n";
    else
      out += is_control(c) ? escaped_control(c) : std::string(1, c);
  }
  return out + "\"";
}

// A comment line: its control characters shown as escapes, which a comment may hold.
std::string comment_line(const std::string& line) {
  std::string out;
  for (const char c : line) out += is_control(c) ? escaped_control(c) : std::string(1, c);
  return out;
}

}  // namespace

std::string bat_design_text(const BatDesign& design, const std::string& comment) {
  if (!design.dimensions) throw std::invalid_argument("bat_design_text: the design has no [dimensions] to write");
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << comment_line(line) << "\n";
  out << "name = " << quoted(design.name) << "\n";
  out << "length = " << exact(design.length) << "  # m\n";
  if (design.slices) out << "slices = " << *design.slices << "\n";
  out << "\n[material]\n";
  if (!design.material_name.empty()) out << "preset = " << quoted(design.material_name) << "\n";
  const Material& m = design.material;
  out << "density = " << exact(m.density) << "  # kg/m^3\n"
      << "youngs_modulus = " << exact(m.youngs_modulus) << "  # Pa\n"
      << "shear_modulus = " << exact(m.shear_modulus) << "  # Pa\n"
      << "shear_coefficient = " << exact(m.shear_coefficient) << "\n";
  // A hollow wall's constants, where they are not what an absent key reads as (0: the axial
  // modulus; the default loss factor), so that a wooden bat's text is what it always was.
  if (m.hoop_modulus > 0) out << "hoop_modulus = " << exact(m.hoop_modulus) << "  # Pa\n";
  if (m.wall_loss_factor != default_wall_loss_factor) out << "wall_loss_factor = " << exact(m.wall_loss_factor) << "\n";
  // The beam's loss factor where it is not what an absent key reads as (a preset's, else 0).
  const MaterialPreset* preset = find_material_preset(design.material_name);
  if (m.loss_factor != (preset ? preset->material.loss_factor : 0.0))
    out << "loss_factor = " << exact(m.loss_factor) << "\n";
  out << "\n[dimensions]  # m\n";
  const Dimensions& d = *design.dimensions;
  for (const DimensionField& f : dimension_fields)
    if (!f.optional || d.*f.value > 0) out << f.name << " = " << exact(d.*f.value) << "\n";
  out << "end = " << quoted(to_string(d.end)) << "\n";
  // The [barrel] table, only where the bat file had one that says something.
  const BarrelCalibration& b = m.barrel;
  if (b.load != WallLoad::patch || b.calibrated()) {
    out << "\n[barrel]\n";
    if (b.load != WallLoad::patch) out << "load = \"point\"\n";
    if (b.hoop_frequency > 0) out << "hoop_frequency = " << exact(b.hoop_frequency) << "  # Hz\n";
    if (b.compression > 0) out << "compression = " << exact(b.compression) << "  # N at 0.04 in\n";
  }
  return out.str();
}

}  // namespace sweetspot
