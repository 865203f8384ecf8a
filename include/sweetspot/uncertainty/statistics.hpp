#pragma once
// What an uncertainty study says of each output from its samples, each estimate with its
// confidence interval (docs/uncertainty.md):
//   mean: Student's t interval; standard deviation: the chi-square interval (both exact for a
//   normal output, asymptotically right for any with finite moments); quantiles: the
//   distribution-free interval between two order statistics (binomial); a probability (the
//   share of samples passing a rule): Clopper-Pearson's exact binomial interval; first-order and
//   total Sobol' indices: Martinez's estimators with their asymptotic intervals (OpenTURNS).
// The intervals treat the samples as independent draws, which Monte Carlo samples are; for a
// Latin hypercube or a low-discrepancy sequence, whose estimates vary less, they are conservative.
#include <cstddef>
#include <span>
#include <vector>

namespace sweetspot {

struct Estimate {
  double value = 0, lower = 0, upper = 0;  // NaN where the samples cannot give it
};

struct SampleSummary {
  std::size_t count = 0;  // finite samples (a failed point's NaN is left out)
  Estimate mean, sd;
  std::vector<Estimate> quantiles;  // one per level asked, in that order
};

// `values` with NaN left out; levels in (0, 1), confidence in (0, 1).
SampleSummary summarize(std::span<const double> values, double confidence, const std::vector<double>& levels);

// The probability of `passes` successes out of `count` trials (Clopper-Pearson).
Estimate proportion(std::size_t passes, std::size_t count, double confidence);

struct SobolIndices {
  std::vector<Estimate> first, total;  // one per input
};

// The indices of `outputs` (the pick-freeze design's N (d + 2) values, as draw_samples lays
// them out) against the d inputs (`inputs`, one column each). NaN throughout when an output is
// not finite (a failed point).
SobolIndices sobol_indices(const std::vector<std::vector<double>>& inputs, std::span<const double> outputs,
                           std::size_t size, double confidence);

}  // namespace sweetspot
