#include "sweetspot/uncertainty/distribution.hpp"

#include <cmath>
#include <numbers>

namespace sweetspot {

const char* to_string(Shape shape) {
  switch (shape) {
    case Shape::normal:
      return "normal";
    case Shape::truncated_normal:
      return "truncated_normal";
    case Shape::uniform:
      return "uniform";
    case Shape::lognormal:
      return "lognormal";
  }
  return "?";
}

namespace {

double normal_density(double x) { return std::exp(-x * x / 2) / std::sqrt(2 * std::numbers::pi); }
double normal_cdf(double x) { return std::erfc(-x / std::numbers::sqrt2) / 2; }

// The moments of a normal truncated to [a, b] (Johnson, Kotz & Balakrishnan, Continuous
// Univariate Distributions 1, 2nd ed., eq. 13.134-13.135): the tests compare the sampler's with
// these, so they are written out here rather than asked of the library that samples.
struct Truncation {
  double alpha, beta, z;
};
Truncation truncation(const InputDistribution& d) {
  const double alpha = (d.lower - d.mean) / d.sd, beta = (d.upper - d.mean) / d.sd;
  return {alpha, beta, normal_cdf(beta) - normal_cdf(alpha)};
}

}  // namespace

double InputDistribution::expected_value() const {
  switch (shape) {
    case Shape::truncated_normal: {
      const Truncation t = truncation(*this);
      return mean + sd * (normal_density(t.alpha) - normal_density(t.beta)) / t.z;
    }
    case Shape::uniform:
      return (lower + upper) / 2;
    default:
      return mean;
  }
}

double InputDistribution::variance() const {
  switch (shape) {
    case Shape::truncated_normal: {
      const Truncation t = truncation(*this);
      const double shift = (normal_density(t.alpha) - normal_density(t.beta)) / t.z;
      return sd * sd * (1 + (t.alpha * normal_density(t.alpha) - t.beta * normal_density(t.beta)) / t.z - shift * shift);
    }
    case Shape::uniform:
      return (upper - lower) * (upper - lower) / 12;
    default:
      return sd * sd;
  }
}

}  // namespace sweetspot
