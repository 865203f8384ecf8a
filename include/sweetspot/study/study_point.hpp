#pragma once
// One grid point of a study computed, whatever its kind: the ball on a bat (simulate_impact),
// on the rigid wall (hit_wall) or in the toy model (toy_model). The engine calls this alone, so
// that the kinds differ in one place.
#include "sweetspot/impact/impact.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/study/study.hpp"

namespace sweetspot {

// The point's result. `basis` is the modal basis of the point's (bat, slices, theory) when the
// point strikes a bat (has_bat(point.kind)); wall and toy points need none: pass nullptr, so that
// the engine never solves for modes on their account. Throws std::invalid_argument for a point
// on a bat without its basis.
ImpactResult simulate_point(const GridPoint& point, const ModalBasis* basis);

// auto's estimate of the dropped modes' error stays near mode_tolerance (up to about 12 times it
// over repeated contacts, impact.cpp); this many times past it, the modal model is out of its
// depth (a wall of a nanometre once gave 1.1) and the point's vf is not to be trusted.
inline constexpr double untrusted_modes_error = 100;

// Marks an ok result of a scene with modes = auto whose modes_error exceeds untrusted_modes_error
// times the scene's mode_tolerance (at a stated accuracy, the modes' share of it) as failed,
// saying why; leaves any other result as it is.
void flag_untrusted_modes_error(const ImpactScene& scene, ImpactResult& r);

}  // namespace sweetspot
