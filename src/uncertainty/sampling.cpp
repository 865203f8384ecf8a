// The draw of an uncertainty study's inputs, by OpenTURNS (design.md: a maintained library for
// sampling, kept out of the core).
#include "sweetspot/uncertainty/sampling.hpp"

#include <openturns/ComposedDistribution.hxx>
#include <openturns/CorrelationMatrix.hxx>
#include <openturns/LHSExperiment.hxx>
#include <openturns/LogNormal.hxx>
#include <openturns/LogNormalFactory.hxx>
#include <openturns/LowDiscrepancyExperiment.hxx>
#include <openturns/MonteCarloExperiment.hxx>
#include <openturns/Normal.hxx>
#include <openturns/NormalCopula.hxx>
#include <openturns/RandomGenerator.hxx>
#include <openturns/SobolIndicesExperiment.hxx>
#include <openturns/SobolSequence.hxx>
#include <openturns/TruncatedNormal.hxx>
#include <openturns/Uniform.hxx>

#include "sweetspot/input_error.hpp"
#include "openturns_setup.hpp"

namespace sweetspot {

const char* to_string(SamplingMethod method) {
  switch (method) {
    case SamplingMethod::monte_carlo:
      return "monte_carlo";
    case SamplingMethod::latin_hypercube:
      return "latin_hypercube";
    case SamplingMethod::low_discrepancy:
      return "low_discrepancy";
  }
  return "?";
}

namespace {

OT::Distribution marginal(const InputDistribution& d) {
  switch (d.shape) {
    case Shape::normal:
      return OT::Normal(d.mean, d.sd);
    case Shape::truncated_normal:
      return OT::TruncatedNormal(d.mean, d.sd, d.lower, d.upper);
    case Shape::uniform:
      return OT::Uniform(d.lower, d.upper);
    case Shape::lognormal: {
      // The variable's own mean m and standard deviation s: ln X is normal with
      // sigma^2 = ln(1 + s^2/m^2) and mu = ln m - sigma^2 / 2.
      const double sigma2 = std::log1p(d.sd * d.sd / (d.mean * d.mean));
      return OT::LogNormal(std::log(d.mean) - sigma2 / 2, std::sqrt(sigma2));
    }
  }
  return OT::Normal();
}

OT::Distribution joint(const std::vector<InputDistribution>& inputs, const SamplingPlan& plan,
                       const std::string& file) {
  OT::Collection<OT::Distribution> marginals;
  for (const InputDistribution& d : inputs) marginals.add(marginal(d));
  if (plan.correlations.empty()) return OT::ComposedDistribution(marginals);
  OT::CorrelationMatrix r(inputs.size());
  for (const InputCorrelation& c : plan.correlations) r(c.first, c.second) = c.value;
  if (!r.isPositiveDefinite())
    throw InputError(file + ": key 'sampling.correlation': the correlation matrix it makes is not positive "
                            "definite: expected correlations that some joint distribution can have");
  return OT::ComposedDistribution(marginals, OT::NormalCopula(r));
}

OT::WeightedExperiment experiment(const OT::Distribution& distribution, const SamplingPlan& plan) {
  const OT::UnsignedInteger n = plan.size;
  switch (plan.method) {
    case SamplingMethod::monte_carlo:
      return OT::MonteCarloExperiment(distribution, n);
    case SamplingMethod::latin_hypercube:
      return OT::LHSExperiment(distribution, n);
    case SamplingMethod::low_discrepancy:
      // The pick-freeze design takes A and B from one sequence of twice the dimension.
      return OT::LowDiscrepancyExperiment(
          OT::SobolSequence(), distribution, n, true);
  }
  return OT::MonteCarloExperiment(distribution, n);
}

}  // namespace

std::vector<std::vector<double>> draw_samples(const std::vector<InputDistribution>& inputs, const SamplingPlan& plan,
                                              const std::string& file) {
  configure_openturns();
  OT::RandomGenerator::SetSeed(plan.seed);
  const OT::Distribution distribution = joint(inputs, plan, file);
  OT::Sample sample;
  if (plan.sensitivity) {
    sample = OT::SobolIndicesExperiment(experiment(distribution, plan), false).generate();
  } else {
    OT::WeightedExperiment draw = experiment(distribution, plan);
    sample = draw.generate();
  }
  std::vector<std::vector<double>> columns(inputs.size(), std::vector<double>(sample.getSize()));
  for (OT::UnsignedInteger i = 0; i < sample.getSize(); ++i)
    for (std::size_t k = 0; k < inputs.size(); ++k) columns[k][i] = sample(i, k);
  return columns;
}

}  // namespace sweetspot
