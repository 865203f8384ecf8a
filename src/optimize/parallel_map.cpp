#include "sweetspot/optimize/parallel_map.hpp"

#include <mpi.h>

namespace sweetspot {

namespace {

constexpr int fields = 3;  // a PointValue's numbers, in order

}  // namespace

std::vector<PointValue> mpi_map(std::size_t count, const std::function<PointValue(std::size_t)>& value) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::vector<double> mine(fields * count, 0.0);
  const long n = static_cast<long>(count);
#pragma omp parallel for schedule(dynamic)
  for (long i = rank; i < n; i += ranks) {
    PointValue v;  // no exception may leave an OpenMP region: a point that throws fails (NaN)
    try {
      v = value(static_cast<std::size_t>(i));
    } catch (...) {
      v = PointValue{};
    }
    double* at = &mine[fields * static_cast<std::size_t>(i)];
    at[0] = v.value, at[1] = v.modes_error, at[2] = v.step_error;
  }
  std::vector<double> all(fields * count);
  MPI_Allreduce(mine.data(), all.data(), fields * static_cast<int>(count), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  std::vector<PointValue> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = {all[fields * i], all[fields * i + 1], all[fields * i + 2]};
  return values;
}

}  // namespace sweetspot
