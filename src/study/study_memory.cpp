#include "sweetspot/study/study_memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include <cmath>
#include <functional>

#include "sweetspot/study/parallel.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/study_results.hpp"

namespace sweetspot {

namespace {

constexpr double value_bytes = sizeof(double);
constexpr double largest_chunk = 4096;  // points a rank computes at once (parallel.cpp)
// Bytes per slice^2 of a modal basis (mode vectors and psi: 48) and of its eigen-solve at its
// peak (measured: about 120 in all for 512 to 1024 slices).
constexpr double basis_bytes_per_slice2 = 48, solve_bytes_per_slice2 = 120;

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

// The slice counts of the (design, slices, theory) models a rank may hold at once, largest
// first: its cache (cached_models) and the models of a chunk in flight.
std::vector<double> model_slices(const Study& study) {
  const auto axis = [&](const char* name) { return std::ranges::find(study.axes, name, &Axis::name); };
  const std::size_t theories = axis("theory") == study.axes.end() ? 1 : axis("theory")->size();
  std::vector<double> models;
  for (const Bat& bat : study.designs) {
    const std::vector<double> slices =
        axis("slices") != study.axes.end()
            ? axis("slices")->values
            : std::vector<double>{static_cast<double>(study.slices > 0 ? study.slices : bat.slices())};
    for (std::size_t t = 0; t < theories; ++t) models.insert(models.end(), slices.begin(), slices.end());
  }
  const double points_per_model = static_cast<double>(study.points()) / std::max<double>(1, models.size());
  const double held = cached_models + std::ceil(largest_chunk / points_per_model) + 1;
  std::ranges::sort(models, std::greater<>());
  models.resize(std::min(models.size(), static_cast<std::size_t>(held)));
  return models;
}

}  // namespace

double study_memory_bytes(const Study& study) {
  const double width = OutputLayout(study).width, points = static_cast<double>(study.points());
  double bytes = 2 * value_bytes * width * points + 2 * sizeof(std::uint64_t) * points +
                 2 * value_bytes * width * std::min(points, largest_chunk);
  if (!keeps_vibrations(study)) return bytes;
  double largest = 0;
  for (const double n : model_slices(study)) {
    bytes += basis_bytes_per_slice2 * n * n;
    largest = std::max(largest, n);
  }
  return bytes + solve_bytes_per_slice2 * largest * largest;
}

double machine_memory_bytes() {
  return static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

void check_study_memory(const Study& study, double available) {
  const double needed = study_memory_bytes(study);
  if (needed <= available) return;
  std::string grid;
  for (const Axis& axis : study.axes)
    grid += (grid.empty() ? "" : " x ") + axis.name + " (" + std::to_string(axis.size()) + ")";
  throw InputError(study.file.string() + ": the study needs about " + gigabytes(needed) + " of memory, more than the " +
                   gigabytes(available) + " this machine has: " + std::to_string(study.points()) + " points" +
                   (grid.empty() ? "" : " = " + grid) + ", " + std::to_string(OutputLayout(study).width) +
                   " values each; expected fewer points, outputs or history samples");
}

}  // namespace sweetspot
