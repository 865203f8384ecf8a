#pragma once
// The PointMap of an evaluation shared by every MPI rank: point i is computed by rank i mod
// ranks, a rank's points over its OpenMP threads, and the values summed over the ranks (each
// point is nonzero on one rank only, and x + 0 is x), so every rank gets every value, bitwise the
// same for any number of ranks and threads.
#include <cstddef>
#include <functional>
#include <vector>

#include "sweetspot/optimize/evaluation.hpp"

namespace sweetspot {

// Collective: every rank of MPI_COMM_WORLD calls it with the same count.
std::vector<PointValue> mpi_map(std::size_t count, const std::function<PointValue(std::size_t)>& value);

}  // namespace sweetspot
