#include "sweetspot/bat/material_presets.hpp"

#include <algorithm>

namespace sweetspot {

namespace {

// From the USDA Forest Products Laboratory, Wood Handbook: Wood as an Engineering Material,
// FPL-GTR-190 (2010), clear straight-grained wood at 12 % moisture content:
// - density: Table 5-3a's specific gravity G (oven-dry mass over volume at 12 %) times the mass
//   of water and the moisture the wood holds, rho = 1000 kg/m^3 * G * (1 + 0.12);
// - Young's modulus along the grain E_L: Table 5-3a's static-bending modulus raised by 10 %, which
//   the Handbook says removes the shear deflection it includes; the Timoshenko beam adds its own
//   shear compliance, which would otherwise count twice;
// - shear modulus G_LR (in the plane of the grain and the rays): Table 5-1's ratio G_LR/E_L times
//   E_L. A round bat shears in every plane across the grain; G_LT, the other modulus, is lower.
// - loss factor: the first bending mode of wood bats rings with a quality factor Q of about 100
//   (D. A. Russell, "Controlling vibration using a dynamic absorber", acs.psu.edu/drussell/bats,
//   2002), eta = 1/Q = 0.01, taken for every mode and every wood (no species' value was found).
constexpr double wood_loss_factor = 0.01;

MaterialPreset wood(std::string name, std::string species, double specific_gravity, double bending_modulus,
                    double shear_ratio) {
  const double youngs_modulus = 1.10 * bending_modulus;
  Material m{1000 * specific_gravity * 1.12, youngs_modulus, shear_ratio * youngs_modulus, 1};
  m.loss_factor = wood_loss_factor;
  return {std::move(name), std::move(species), m};
}

}  // namespace

const std::vector<MaterialPreset>& material_preset_list() {
  //                                                              G     MOE (Pa) G_LR/E_L
  static const std::vector<MaterialPreset> presets = {
      wood("maple", "sugar maple (Acer saccharum)", 0.63, 12.6e9, 0.111),
      wood("ash", "white ash (Fraxinus americana)", 0.60, 12.0e9, 0.109),
      wood("birch", "yellow birch (Betula alleghaniensis)", 0.62, 13.9e9, 0.074),
  };
  return presets;
}

const MaterialPreset* find_material_preset(std::string_view name) {
  const auto& presets = material_preset_list();
  const auto it = std::ranges::find(presets, name, &MaterialPreset::name);
  return it == presets.end() ? nullptr : &*it;
}

}  // namespace sweetspot
