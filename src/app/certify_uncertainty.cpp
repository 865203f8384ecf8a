#include "certify_uncertainty.hpp"

#include <mpi.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <variant>

#include "json.hpp"
#include "sweetspot/impact/standards.hpp"
#include "sweetspot/study/input_kind.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/uncertainty/uncertainty_study.hpp"

namespace sweetspot::app {

namespace {

const Variable& variable(const Dataset& d, const std::string& name) {
  const auto it = std::ranges::find(d.variables, name, &Variable::name);
  if (it == d.variables.end()) throw std::runtime_error("certify --uncertainty: no variable " + name + " in the dataset");
  return *it;
}

const std::vector<double>& numbers(const Dataset& d, const std::string& name) {
  return std::get<std::vector<double>>(variable(d, name).values);
}

const Coordinate& coordinate(const Dataset& d, const std::string& name) {
  return *std::ranges::find(d.coordinates, name, &Coordinate::name);
}

// A folder for the dataset when none is asked for, removed when the command ends.
struct ScratchFolder {
  std::filesystem::path path;
  ScratchFolder() {
    path = std::filesystem::temp_directory_path() / ("sweetspot_certify_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(path);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

Json interval_json(const std::vector<double>& v, std::size_t at) {
  return Json::numbers({v[at], v[at + 1], v[at + 2]});
}

void print_text(const UncertaintyStudy& u, const Dataset& d, const std::string& measure) {
  const Standard& standard = standards()[u.study.standard];
  const double percent = 100 * u.plan.confidence;
  const std::vector<double>& pass = numbers(d, "pass_probability");
  const std::vector<std::string>& rules = coordinate(d, "rule").labels;
  std::printf("%s under uncertainty: %zu samples (%s, seed %llu), %.4g %% intervals\n", standard.title.c_str(),
              u.plan.statistics_points(), to_string(u.plan.method), static_cast<unsigned long long>(u.plan.seed),
              percent);
  std::printf("pass probability %.4f (%.4f to %.4f)\n", pass[3 * (rules.size() - 1)], pass[3 * (rules.size() - 1) + 1],
              pass[3 * (rules.size() - 1) + 2]);
  const std::vector<double>&mean = numbers(d, measure + "_mean"), &sd = numbers(d, measure + "_std"),
  &quantiles = numbers(d, measure + "_quantile");
  std::printf("%-7s mean   %.6f (%.6f to %.6f)\n", measure.c_str(), mean[0], mean[1], mean[2]);
  std::printf("%-7s std    %.6f (%.6f to %.6f)\n", measure.c_str(), sd[0], sd[1], sd[2]);
  for (std::size_t q = 0; q < u.plan.quantiles.size(); ++q)
    std::printf("%-7s q%-5.4g %.6f (%.6f to %.6f)\n", measure.c_str(), u.plan.quantiles[q], quantiles[3 * q],
                quantiles[3 * q + 1], quantiles[3 * q + 2]);
  std::printf("%-16s %12s %12s %12s\n", "rule", "probability", "lower", "upper");
  for (std::size_t r = 0; r < rules.size(); ++r)
    std::printf("%-16s %12.6f %12.6f %12.6f\n", rules[r].c_str(), pass[3 * r], pass[3 * r + 1], pass[3 * r + 2]);
}

void print_json(const UncertaintyStudy& u, const Dataset& d, const std::string& measure) {
  const std::vector<double>& pass = numbers(d, "pass_probability");
  const std::vector<std::string>& rules = coordinate(d, "rule").labels;
  Json::Object probability, quantiles;
  for (std::size_t r = 0; r < rules.size(); ++r) probability.add(rules[r], interval_json(pass, 3 * r));
  const std::vector<double>& q = numbers(d, measure + "_quantile");
  for (std::size_t k = 0; k < u.plan.quantiles.size(); ++k) {
    char level[32];
    std::snprintf(level, sizeof level, "%g", u.plan.quantiles[k]);  // as the study writes it: "0.05"
    quantiles.add(level, interval_json(q, 3 * k));
  }
  Json::Object out;
  out.add("standard", standards()[u.study.standard].name)
      .add("samples", static_cast<double>(u.plan.statistics_points()))
      .add("confidence", u.plan.confidence)
      .add("pass_probability", Json(probability))
      .add(measure + "_mean", interval_json(numbers(d, measure + "_mean"), 0))
      .add(measure + "_std", interval_json(numbers(d, measure + "_std"), 0))
      .add(measure + "_quantiles", Json(quantiles));
  std::printf("%s\n", Json(out).text().c_str());
}

}  // namespace

void certify_under_uncertainty(const std::string& file, const std::string& output, bool json) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  }
  struct Finalize {
    ~Finalize() { MPI_Finalize(); }
  } finalize;
  require_input_kind(file, {InputKind::uncertainty_study}, "certify --uncertainty", "study file");
  const UncertaintyStudy u = load_uncertainty_study(file);
  if (u.study.kind != StudyKind::certification)
    throw InputError(file + ": key 'model' = \"" + to_string(u.study.kind) +
                     "\": certify --uncertainty takes model = \"certification\"");
  const std::string measure = to_string(standards()[u.study.standard].measure);
  if (std::ranges::count(u.study.outputs, measure) == 0)
    throw InputError(file + ": key 'output.variables': expected the standard's measure " + measure + " among them");
  spdlog::set_level(spdlog::level::warn);
  const ScratchFolder scratch;
  RunOptions options;
  options.output = output.empty() ? scratch.path / "certify.h5" : std::filesystem::path(output);
  options.verbosity = Verbosity::quiet;
  Dataset result;
  options.finish = [&](Dataset& d) {
    add_uncertainty_statistics(u, d);
    result = d;
  };
  run_study(u.study, options);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) return;  // rank 0 made the dataset, and says what it holds
  if (json) print_json(u, result, measure);
  else print_text(u, result, measure);
}

}  // namespace sweetspot::app
