#pragma once
// How an uncertainty study draws its inputs, and the draw itself (OpenTURNS's experiments): Monte
// Carlo, Latin hypercube or a Sobol' low-discrepancy sequence, with an optional Gaussian copula
// for correlated inputs, and Saltelli's pick-freeze design when Sobol' indices are asked for.
// The draw depends on the plan and the distributions alone, never on ranks or threads: every rank
// draws the same samples, bit for bit.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sweetspot/uncertainty/distribution.hpp"

namespace sweetspot {

enum class SamplingMethod { monte_carlo, latin_hypercube, low_discrepancy };
const char* to_string(SamplingMethod method);

// The Gaussian copula's correlation between two inputs (indices into the distributions).
struct InputCorrelation {
  std::size_t first = 0, second = 0;
  double value = 0;
};

struct SamplingPlan {
  SamplingMethod method = SamplingMethod::latin_hypercube;
  std::size_t size = 0;  // N: samples of the inputs (each of the pick-freeze blocks A and B)
  std::uint64_t seed = 1;
  bool sensitivity = false;  // Sobol' indices: N (d + 2) points (A, B and d mixed blocks)
  std::vector<InputCorrelation> correlations;
  double confidence = 0.95;  // of every interval
  std::vector<double> quantiles = {0.05, 0.5, 0.95};

  // The points the study computes: N, or N (d + 2) with sensitivity.
  std::size_t points(std::size_t inputs) const { return sensitivity ? size * (inputs + 2) : size; }
  // The points the moments and quantiles are taken over: N, or 2N (the blocks A and B, two
  // independent samples of the inputs) with sensitivity.
  std::size_t statistics_points() const { return sensitivity ? 2 * size : size; }
};

// Every input's value in every point, one column per distribution (column-major: column k holds
// points(d) values). Points run as OpenTURNS's SobolIndicesExperiment lays them out: A, B, then
// A with column i from B for each i. Throws InputError naming the study file when the copula's
// correlation matrix is not positive definite.
std::vector<std::vector<double>> draw_samples(const std::vector<InputDistribution>& inputs, const SamplingPlan& plan,
                                              const std::string& file);

}  // namespace sweetspot
