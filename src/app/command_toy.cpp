// sweetspot toy: the two-mass toy model of N2000 Appendix A (Figs. 17-18).
#include <cmath>
#include <cstdio>
#include <memory>

#include <spdlog/fmt/fmt.h>

#include "commands.hpp"
#include "json.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/impact/toy_model.hpp"

namespace sweetspot::app {

void add_toy_command(CLI::App& app) {
  struct ToyOptions {
    double omega_tau = 0;
    bool json = false;
  };
  auto o = std::make_shared<ToyOptions>();
  CLI::App* cmd = app.add_subcommand("toy", "The toy model of N2000 App. A: v_f/v_i and energy split");
  cmd->add_option("--omega-tau", o->omega_tau, "omega tau: bat spring frequency times collision time")->required();
  cmd->add_flag("--json", o->json, "print one JSON object");
  cmd->callback([o] {
    if (!(o->omega_tau > 0) || !std::isfinite(o->omega_tau))
      throw InputError("toy: omega-tau = " + std::to_string(o->omega_tau) + ": must be a positive finite number");
    const ImpactResult r = toy_model(o->omega_tau);
    // Past the model's fixed step nothing was computed: the value given is what is wrong.
    if (r.status == CollisionStatus::refused_step)
      throw InputError(fmt::format("toy: --omega-tau {:g}: {}", o->omega_tau, r.message));
    // v_i = 1 in the model's units: vf is the ratio v_f / v_i; energies as fractions of the initial.
    const ImpactEnergy& e = r.energy;
    const double ball = e.ball / e.initial, bat_cm = e.bat_translation / e.initial;
    const double vibration = e.vibration / e.initial;
    if (o->json) {
      Json::Object out;
      out.add("status", to_string(r.status));
      if (!r.message.empty()) out.add("message", r.message);
      out.add("omega_tau", o->omega_tau)
          .add("exit_ratio", r.vf)
          .add("ball_energy", ball)
          .add("bat_cm_energy", bat_cm)
          .add("vibration_energy", vibration)
          .add("van_zandt_ratio", r.vf_van_zandt);
      std::printf("%s\n", Json(out).text().c_str());
      return;
    }
    if (r.status != CollisionStatus::ok) std::printf("status %s: %s\n", to_string(r.status), r.message.c_str());
    std::printf("omega tau %.4g: v_f/v_i = %.6f (Van Zandt %.6f)\n", o->omega_tau, r.vf, r.vf_van_zandt);
    std::printf("energy fractions: ball %.4f, bat CM %.4f, vibration %.4f\n", ball, bat_cm, vibration);
  });
}

}  // namespace sweetspot::app
