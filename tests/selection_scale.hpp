#pragma once
// auto keeps its dropped modes within mode_tolerance of the rigid bat's exit speed, the one scale
// known before the impact (selection_error_scale); the result states the same estimate
// against its own exit speed (error_scale), as every other estimate. A test of the selection
// itself compares it on the selection's scale.
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/impact/mode_selection.hpp"
#include "sweetspot/impact/scene.hpp"

inline double selection_modes_error(const sweetspot::ImpactResult& r, const sweetspot::ModalBasis& basis,
                                    const sweetspot::ImpactScene& s) {
  const sweetspot::SceneGeometry g = sweetspot::scene_geometry(s, basis);
  return r.modes_error * sweetspot::error_scale(r.vf, s.ball_speed) /
         sweetspot::selection_error_scale(s.ball, s.ball_speed, g.bat_speed, g.recoil);
}
