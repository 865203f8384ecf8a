#include "sweetspot/impact/rig_measures.hpp"

namespace sweetspot {

double collision_efficiency(double vf, double ball_speed, double bat_speed) {
  return (vf - bat_speed) / (ball_speed + bat_speed);
}

double pivot_recoil(double ball_mass, double distance, double moi_pivot) {
  return ball_mass * distance * distance / moi_pivot;
}

double bbcor_from(double e_a, double recoil) { return e_a * (1 + recoil) + recoil; }

RigMeasures rig_measures(double e_a, double recoil, double e0) {
  RigMeasures m;
  m.e_a = e_a;
  m.bbcor = bbcor_from(e_a, recoil);
  // BESR = [v_out + (v_pitch - v_bat)/2] / (v_pitch + v_bat) with v_out = e_A v_pitch +
  // (1 + e_A) v_bat is e_A + 1/2 exactly (literature notes §1.4, Falcon Sports' test sheet).
  m.besr = e_a + 0.5;
  m.bpf = m.bbcor / e0;  // BPF = BBCOR over the ball's own COR (WSU glossary, Eq. 10.2)
  return m;
}

}  // namespace sweetspot
