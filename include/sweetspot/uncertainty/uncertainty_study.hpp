#pragma once
// An uncertainty study (kind = "uncertainty", docs/uncertainty.md): a study of another kind (its
// `model`: impact, certification, wall, toy) whose [uncertain] keys are drawn from distributions,
// sampled as [sampling] says, and run over MPI ranks and OpenMP threads as any study, with its
// journal and --resume; its dataset adds, per output, the mean, standard deviation and quantiles
// with their confidence intervals, the probability of passing each rule of a certification, and
// with `sensitivity = true` the first-order and total Sobol' indices against every input.
//
//   kind = "uncertainty"
//   model = "impact"                  # what each sample computes (default "impact")
//   [scene] ... [axes] ... [output]   # as a study of that kind; no axis makes bats
//   [uncertain]                       # a key of the model = its distribution:
//   ball_speed = { distribution = "normal", mean = 40, sd = 0.5 }
//   "bat.density" = { distribution = "lognormal", mean = 649, sd = 30 }
//   e0 = { distribution = "truncated_normal", mean = 0.5, sd = 0.02, lower = 0.45, upper = 0.55 }
//   z = { distribution = "uniform", lower = 0.70, upper = 0.72 }
//   [sampling]
//   method = "latin_hypercube"        # or "monte_carlo", "low_discrepancy" (Sobol' sequence)
//   size = 200                        # N, at least 2
//   seed = 1
//   sensitivity = false               # true: Sobol' indices, N (d + 2) points
//   confidence = 0.95
//   quantiles = [0.05, 0.5, 0.95]
//   correlation = [["bat.density", "bat.youngs_modulus", 0.5]]   # a Gaussian copula's
#include <filesystem>
#include <vector>

#include "sweetspot/study/dataset.hpp"
#include "sweetspot/study/parallel.hpp"
#include "sweetspot/study/study.hpp"
#include "sweetspot/uncertainty/distribution.hpp"
#include "sweetspot/uncertainty/sampling.hpp"

namespace sweetspot {

struct UncertaintyStudy {
  Study study;  // the model's study over the sample axis (and its own [axes] after it)
  std::vector<InputDistribution> inputs;
  SamplingPlan plan;
};

// Reads, checks and draws an uncertainty study: every distribution, the plan, the memory the
// samples need (checked before they are drawn), then every drawn value as its key takes it.
// Throws InputError with one line naming the file, the key, the value and what was expected.
UncertaintyStudy load_uncertainty_study(const std::filesystem::path& file);

// The statistics of every output over the samples, added to the study's dataset.
void add_uncertainty_statistics(const UncertaintyStudy& u, Dataset& dataset);

// Runs the study as run_study does (every rank), its statistics added on rank 0.
void run_uncertainty_study(const UncertaintyStudy& u, RunOptions options);

}  // namespace sweetspot
