#pragma once
// The distribution of one uncertain input of an uncertainty study: a scene, ball or bat key
// drawn from a normal, truncated normal, uniform or log-normal law (docs/uncertainty.md). Plain
// data: the sampler (sampling.hpp) turns it into OpenTURNS's distribution.
#include <cstddef>
#include <string>

namespace sweetspot {

enum class Shape { normal, truncated_normal, uniform, lognormal };
const char* to_string(Shape shape);

struct InputDistribution {
  std::string key;  // the study key it draws ("ball_speed", "bat.density")
  Shape shape = Shape::normal;
  // normal, truncated normal: the parent normal's mean and standard deviation; log-normal: the
  // variable's own mean and standard deviation (> 0); uniform: unused.
  double mean = 0, sd = 0;
  // truncated normal and uniform: the support [lower, upper]; unused otherwise.
  double lower = 0, upper = 0;
  std::size_t line = 0;  // where the study file gives it, for messages

  // The variable's own mean and variance (a truncated normal's differ from its parent's).
  double expected_value() const;
  double variance() const;
};

}  // namespace sweetspot
