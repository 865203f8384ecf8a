// sweetspot toy: the two-mass toy model of N2000 Appendix A (Figs. 17-18).
#include <cmath>
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "json.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/toy_model.hpp"

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
    const ToyResult r = toy_model(o->omega_tau);
    if (o->json) {
      const Json out = Json::Object()
                           .add("status", to_string(r.status))
                           .add("omega_tau", r.omega_tau)
                           .add("exit_ratio", r.exit_ratio)
                           .add("ball_energy", r.ball_energy)
                           .add("bat_cm_energy", r.bat_cm_energy)
                           .add("vibration_energy", r.vibration_energy)
                           .add("van_zandt_ratio", r.van_zandt_ratio);
      std::printf("%s\n", out.text().c_str());
      return;
    }
    std::printf("omega tau %.4g: v_f/v_i = %.6f (Van Zandt %.6f)\n", r.omega_tau, r.exit_ratio, r.van_zandt_ratio);
    std::printf("energy fractions: ball %.4f, bat CM %.4f, vibration %.4f\n", r.ball_energy, r.bat_cm_energy,
                r.vibration_energy);
  });
}

}  // namespace sweetspot::app
