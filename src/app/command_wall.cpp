// sweetspot wall: the ball on a rigid, immovable wall (N2000 Fig. 3).
#include <cmath>
#include <cstdio>
#include <memory>

#include "commands.hpp"
#include "display_units.hpp"
#include "json.hpp"
#include "quantity_option.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/impact/wall.hpp"

namespace sweetspot::app {

namespace {

struct WallOptions {
  Ball ball;
  std::string named_ball;
  double speed = 0;
  CollisionOptions integrator;
  bool json = false;
  DisplayUnits units;
};

void run_wall(const WallOptions& o) {
  if (!(o.speed > 0) || !std::isfinite(o.speed))
    throw InputError("wall: speed = " + std::to_string(o.speed) + ": must be a positive finite number (m/s)");
  if (!(o.integrator.dt > 0)) throw InputError("wall: dt must be positive");  // the ball: resolve_ball
  const ImpactResult r = hit_wall(o.ball, o.speed, o.integrator);
  if (o.json) {
    const Json out = Json::Object()
                         .add("status", to_string(r.status))
                         .add("speed", o.speed)
                         .add("restitution", r.e_eff)
                         .add("collision_time", r.collision_time)
                         .add("contact_time", r.contact_time)
                         .add("u_max", r.u_max)
                         .add("peak_force", r.peak_force);
    std::printf("%s\n", out.text().c_str());
    return;
  }
  std::printf("status %s\nrestitution %.9g\ncollision time %.4g ms (99 %% of the impulse)\n", to_string(r.status),
              r.e_eff, 1e3 * r.collision_time);
  std::printf("contact time %.4g ms\nmax compression %s\npeak force %.5g N\n", 1e3 * r.contact_time,
              o.units.small_length(r.u_max, "%.4g").c_str(), r.peak_force);
}

}  // namespace

void add_wall_command(CLI::App& app) {
  auto o = std::make_shared<WallOptions>();
  CLI::App* cmd = app.add_subcommand("wall", "The ball on a rigid, immovable wall (N2000 Fig. 3)");
  cmd->add_option("--speed", o->speed, "ball speed, m/s, or e.g. 60mph")
      ->transform(quantity_option(Dimension::speed))
      ->required();
  add_ball_options(*cmd, o->ball, o->named_ball);
  add_integrator_options(*cmd, o->integrator);
  cmd->add_flag("--json", o->json, "print one JSON object (in SI units)");
  o->units.add_option(*cmd);
  cmd->callback([o, cmd] {
    o->units.check_text_output("wall", o->json);
    resolve_integrator(*cmd, o->integrator);
    resolve_ball(*cmd, o->named_ball, o->ball);
    run_wall(*o);
  });
}

}  // namespace sweetspot::app
