#pragma once
// Median wall time of repeated calls: benchmarks print it, tests never assert on it.
#include <algorithm>
#include <chrono>
#include <vector>

template <class Work>
double median_seconds(int repeats, Work work) {
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    work();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}
