#include "sweetspot/uncertainty/statistics.hpp"

#include <openturns/Binomial.hxx>
#include <openturns/DistFunc.hxx>
#include <openturns/Exception.hxx>
#include <openturns/MartinezSensitivityAlgorithm.hxx>
#include <openturns/Sample.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "openturns_setup.hpp"

namespace sweetspot {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The order-statistic interval of the level-p quantile: [x_(l), x_(u)] (1-based) with l and u the
// binomial(n, p) quantiles that leave (1 - confidence) / 2 out on each side; NaN on a side the
// sample is too small to reach.
Estimate quantile(const std::vector<double>& sorted, const OT::Sample& sample, double level, double confidence) {
  const std::size_t n = sorted.size();
  const double tail = (1 - confidence) / 2;
  const OT::Binomial order(n, level);
  const auto l = static_cast<std::size_t>(order.computeQuantile(tail)[0]);
  const auto u = static_cast<std::size_t>(order.computeQuantile(1 - tail)[0]) + 1;
  Estimate e{sample.computeQuantile(level)[0], nan, nan};
  if (l >= 1) e.lower = sorted[l - 1];
  if (u <= n) e.upper = sorted[u - 1];
  return e;
}

}  // namespace

SampleSummary summarize(std::span<const double> values, double confidence, const std::vector<double>& levels) {
  configure_openturns();
  std::vector<double> finite;
  for (const double x : values)
    if (std::isfinite(x)) finite.push_back(x);
  SampleSummary s;
  s.count = finite.size();
  s.mean = s.sd = {nan, nan, nan};
  s.quantiles.assign(levels.size(), {nan, nan, nan});
  if (finite.size() < 2) return s;
  const auto n = static_cast<double>(finite.size());
  OT::Sample sample(finite.size(), 1);
  for (std::size_t i = 0; i < finite.size(); ++i) sample(i, 0) = finite[i];
  const double mean = sample.computeMean()[0];
  const double sd = std::sqrt(sample.computeVariance()[0]);  // the unbiased variance's root
  const double tail = (1 - confidence) / 2;
  const double t = OT::DistFunc::qStudent(n - 1, 1 - tail);
  s.mean = {mean, mean - t * sd / std::sqrt(n), mean + t * sd / std::sqrt(n)};
  // (n - 1) s^2 / sigma^2 is chi-square with n - 1 degrees of freedom: 2 Gamma((n - 1) / 2).
  const double chi_low = 2 * OT::DistFunc::qGamma((n - 1) / 2, tail),
               chi_high = 2 * OT::DistFunc::qGamma((n - 1) / 2, 1 - tail);
  s.sd = {sd, sd * std::sqrt((n - 1) / chi_high), sd * std::sqrt((n - 1) / chi_low)};
  std::ranges::sort(finite);
  for (std::size_t q = 0; q < levels.size(); ++q) s.quantiles[q] = quantile(finite, sample, levels[q], confidence);
  return s;
}

Estimate proportion(std::size_t passes, std::size_t count, double confidence) {
  if (count == 0) return {nan, nan, nan};
  const double k = static_cast<double>(passes), n = static_cast<double>(count), tail = (1 - confidence) / 2;
  const double lower = passes == 0 ? 0 : OT::DistFunc::qBeta(k, n - k + 1, tail);
  const double upper = passes == count ? 1 : OT::DistFunc::qBeta(k + 1, n - k, 1 - tail);
  return {k / n, lower, upper};
}

SobolIndices sobol_indices(const std::vector<std::vector<double>>& inputs, std::span<const double> outputs,
                           std::size_t size, double confidence) {
  configure_openturns();
  const std::size_t d = inputs.size();
  SobolIndices indices{std::vector<Estimate>(d, {nan, nan, nan}), std::vector<Estimate>(d, {nan, nan, nan})};
  if (std::ranges::any_of(outputs, [](double y) { return !std::isfinite(y); })) return indices;
  OT::Sample x(outputs.size(), d), y(outputs.size(), 1);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    for (std::size_t k = 0; k < d; ++k) x(i, k) = inputs[k][i];
    y(i, 0) = outputs[i];
  }
  // An output that does not vary (a bat's length when no input moves it) has no shares to give.
  const auto [lowest, highest] = std::ranges::minmax(outputs);
  if (lowest == highest) return indices;
  try {
    OT::MartinezSensitivityAlgorithm martinez(x, y, size);
    martinez.setUseAsymptoticDistribution(true);  // Fisher-transformed normal intervals: no resampling
    martinez.setConfidenceLevel(confidence);
    const OT::Point first = martinez.getFirstOrderIndices(), total = martinez.getTotalOrderIndices();
    const OT::Interval first_interval = martinez.getFirstOrderIndicesInterval(),
                       total_interval = martinez.getTotalOrderIndicesInterval();
    for (std::size_t k = 0; k < d; ++k) {
      indices.first[k] = {first[k], first_interval.getLowerBound()[k], first_interval.getUpperBound()[k]};
      indices.total[k] = {total[k], total_interval.getLowerBound()[k], total_interval.getUpperBound()[k]};
    }
  } catch (const OT::Exception&) {
    // OpenTURNS refuses a block whose output does not vary (e.g. a flag every sample shares):
    // no shares, as above.
  }
  return indices;
}

}  // namespace sweetspot
