#pragma once
// Woods a bat may be made of, by name ("maple", "ash", "birch"): density, Young's modulus along
// the grain and shear modulus, each from the USDA Forest Products Laboratory's Wood Handbook
// (README "Bat files"). A bat file names one in [material] preset = "maple".
#include <string>
#include <string_view>
#include <vector>

#include "sweetspot/bat/bat.hpp"

namespace sweetspot {

struct MaterialPreset {
  std::string name;      // "maple"
  std::string species;   // "sugar maple (Acer saccharum)"
  Material material;     // shear_coefficient left at 1, as N2000
};

const std::vector<MaterialPreset>& material_preset_list();

// The preset of that name, or nullptr.
const MaterialPreset* find_material_preset(std::string_view name);

}  // namespace sweetspot
