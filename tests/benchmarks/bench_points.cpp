// What users run (issue 26): the cost of an impact over a study's unique points, every one a scene
// never met before (a study of 21 impact points x 100 ball speeds), and over repeated scenes (the
// same 31 points run again and again, as the other benchmarks do), each at
//   default: the library's defaults (exact stepping at 10 us, modes = auto, tolerance 1e-4),
//   all modes: every one of the bat's modes kept,
//   rigid: no vibrational mode (the two rigid ones alone),
// on R161 (or the bat file given) in N2000's high-impact swing (51 rad/s about 9 cm from the
// knob, e0 = 0.5). Prints us per impact and impacts per second per core (one thread, its CPU
// time: the median of repeats), and a checksum of each configuration's results over the unique
// points (the bits of vf, collision time, peak force and contact time), so that two builds run
// side by side (scripts/bench_compare) show whether their results are the same bit for bit.
//
// Usage: bench_points [BAT_FILE [default|all|rigid]]: the second argument runs that setting alone
// (for a profiler).
//
// Each repeat of the unique points shifts every ball speed by a fraction of the grid's spacing,
// so no scene of one repeat recurs in another: no per-thread memory of earlier impacts can help.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/impact/impact.hpp"

using namespace sweetspot;

namespace {

constexpr int z_count = 21, speed_count = 100, repeats = 5;

double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

ImpactScene high_impact(double z, double ball_speed, int modes) {
  ImpactScene s;  // the library's defaults
  s.z = z;
  s.ball_speed = ball_speed;
  s.ball.e0 = 0.5;
  s.swing = {51, true, 0, 0.09};
  s.vibrational_modes = modes;
  return s;
}

// The study's points: z over 50-80 cm, ball speed over 30-50 m/s, shifted by shift / repeats of a
// speed step (repeat r of `repeats` takes shift r).
std::vector<ImpactScene> unique_points(int modes, int shift) {
  std::vector<ImpactScene> scenes;
  for (int i = 0; i < z_count; ++i)
    for (int j = 0; j < speed_count; ++j)
      scenes.push_back(high_impact(0.50 + 0.30 * i / (z_count - 1),
                                   30 + 20.0 * (j + static_cast<double>(shift) / repeats) / speed_count, modes));
  return scenes;
}

// A bat's sweep: every cm from 50 to 80 cm at 40 m/s.
std::vector<ImpactScene> repeated_scenes(int modes) {
  std::vector<ImpactScene> scenes;
  for (int cm = 50; cm <= 80; ++cm) scenes.push_back(high_impact(cm / 100.0, 40, modes));
  return scenes;
}

// FNV-1a over the bits of the results that a study stores most often.
struct Checksum {
  std::uint64_t value = 1469598103934665603ull;
  void add(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    for (int byte = 0; byte < 8; ++byte) value = (value ^ ((bits >> (8 * byte)) & 0xff)) * 1099511628211ull;
  }
  void add(const ImpactResult& r) {
    for (double x : {r.vf, r.collision_time, r.peak_force, r.contact_time}) add(x);
  }
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Seconds per impact over the unique points: each repeat a new shift, its points all new.
double unique_seconds(const ModalBasis& basis, int modes, Checksum& checksum) {
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r) {
    const std::vector<ImpactScene> scenes = unique_points(modes, r);
    const double start = cpu_seconds();
    for (const ImpactScene& s : scenes) {
      const ImpactResult result = simulate_impact(basis, s);
      if (r == 0) checksum.add(result);
    }
    times.push_back((cpu_seconds() - start) / scenes.size());
  }
  return median(times);
}

// Seconds per impact over the repeated scenes: the median of 7 repeats, each of enough rounds
// over them to last about 0.2 s, after a round that lets whatever a thread remembers fill.
double repeated_seconds(const ModalBasis& basis, int modes) {
  const std::vector<ImpactScene> scenes = repeated_scenes(modes);
  const auto round = [&] {
    for (const ImpactScene& s : scenes) simulate_impact(basis, s);
  };
  double start = cpu_seconds();
  round();
  const int rounds = std::max(1, static_cast<int>(0.2 / std::max(cpu_seconds() - start, 1e-6)));
  std::vector<double> times;
  for (int r = 0; r < 7; ++r) {
    start = cpu_seconds();
    for (int k = 0; k < rounds; ++k) round();
    times.push_back((cpu_seconds() - start) / (rounds * scenes.size()));
  }
  return median(times);
}

// The whole benchmark on `bat_file`, or the setting whose name begins with `only` alone.
void run(const char* bat_file, const std::string& only) {
  const Bat bat = load_bat(bat_file);
  // The dense solve: every mode, from which modes = auto picks what each impact needs.
  const ModalBasis all = compute_modes(bat, BeamTheory::timoshenko);
  const ModalBasis rigid = compute_modes(bat, BeamTheory::timoshenko, ModeRequest::rigid_only());
  struct Setting {
    std::string name;
    const ModalBasis* basis;
    int modes;
  };
  const Setting settings[] = {{"default (modes auto)", &all, auto_modes},
                              {"all modes (" + std::to_string(all.count()) + ")", &all, all_modes},
                              {"rigid (no vibrational mode)", &rigid, 0}};
  std::printf("%d unique points (%d z x %d ball speeds, each repeat new), %zu repeated scenes; one thread\n",
              z_count * speed_count, z_count, speed_count, repeated_scenes(0).size());
  std::printf("%-28s %12s %16s %12s %16s  %s\n", "settings", "unique us", "unique /s/core", "repeated us",
              "repeated /s/core", "checksum (unique)");
  for (const Setting& s : settings) {
    if (!only.empty() && s.name.rfind(only, 0) != 0) continue;
    Checksum checksum;
    const double unique = unique_seconds(*s.basis, s.modes, checksum);
    const double repeated = repeated_seconds(*s.basis, s.modes);
    std::printf("%-28s %12.2f %16.0f %12.2f %16.0f  %016llx\n", s.name.c_str(), 1e6 * unique, 1 / unique,
                1e6 * repeated, 1 / repeated, static_cast<unsigned long long>(checksum.value));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string first = argc > 1 ? argv[1] : "", only = argc > 2 ? argv[2] : "";
  const bool known = only.empty() || only == "default" || only == "all" || only == "rigid";
  const bool wrong = argc > 3 || !known;
  if (wrong || first == "-h" || first == "--help") {
    std::fprintf(wrong ? stderr : stdout, "usage: bench_points [BAT_FILE [default|all|rigid]]\n");
    return wrong ? 2 : 0;
  }
  try {  // a bad bat file: one line and status 2, as the program says it
    run(argc > 1 ? argv[1] : SWEETSPOT_R161, only);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_points: %s\n", e.what());
    return 2;
  }
}
