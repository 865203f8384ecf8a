#include "sweetspot/optimize/parallel_map.hpp"

#include <mpi.h>

#include <limits>

namespace sweetspot {

std::vector<double> mpi_map(std::size_t count, const std::function<double(std::size_t)>& value) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::vector<double> mine(count, 0.0);
  const long n = static_cast<long>(count);
#pragma omp parallel for schedule(dynamic)
  for (long i = rank; i < n; i += ranks) {
    try {
      mine[static_cast<std::size_t>(i)] = value(static_cast<std::size_t>(i));
    } catch (...) {  // no exception may leave an OpenMP region: the point fails instead
      mine[static_cast<std::size_t>(i)] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  std::vector<double> all(count);
  MPI_Allreduce(mine.data(), all.data(), static_cast<int>(count), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return all;
}

}  // namespace sweetspot
