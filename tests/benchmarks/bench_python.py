#!/usr/bin/python3
"""The Python module's cost (issue 15): `sweetspot.impacts` on one thread over 100 000 points of the
high-impact scene against the C++ benchmark's impacts per second per core (build/bench_numerics,
the same scene: modes auto at tolerance 5e-5, exact stepping at 60 us, z = 0.555..0.815 m; v_f alone
asked, and with the collision time too, as impacts() gives every output); over 2 100 points each
new at the defaults against build/bench_points' rate over the same grid; and what one
`sweetspot.impact` call adds to the impact itself, and what reading its error estimates adds.
Prints; asserts nothing.

Each figure is the median of rounds taken in turns with what it is compared to (a Python round,
then a C++ run; a round of impact() calls, then the same impacts inside impacts()), so that the
load of a shared machine falls on both sides alike instead of on whichever ran during a spike.

Usage, from the repository's top after scripts/build: /usr/bin/python3 tests/benchmarks/bench_python.py
"""
import re
import statistics
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, "build/python")
import sweetspot  # noqa: E402

bat = sweetspot.Bat.load("studies/bats/r161.toml")
scene = dict(ball_speed=40, center=0.09, omega=51, mode_tolerance=5e-5, dt=60e-6)
z = np.resize(np.arange(0.555, 0.83, 0.02), 100_000)


def seconds(work):
    start = time.perf_counter()
    work()
    return time.perf_counter() - start


def cpp_rates():
    """bench_numerics' rates: v_f alone asked, and with the collision time as impacts() finds it."""
    out = subprocess.run(["build/bench_numerics"], capture_output=True, text=True, check=True).stdout
    return [float(m) for m in re.findall(r"(\d+) impacts per second per core", out)[:2]]


sweetspot.impacts(bat, z=z[:1000], threads=1, **scene)  # the bat's modes solved once, outside the timing
python_rates, cpp_runs = [], []
for _ in range(3):
    python_rates.append(len(z) / seconds(lambda: sweetspot.impacts(bat, z=z, threads=1, **scene)))
    cpp_runs.append(cpp_rates())
python_rate = statistics.median(python_rates)
cpp = statistics.median(run[0] for run in cpp_runs)
like = ""
if all(len(run) == 2 for run in cpp_runs):  # builds before this script's change print the first alone
    cpp_like = statistics.median(run[1] for run in cpp_runs)
    like = f", {cpp_like:9.0f} with the collision time, as impacts() gives it ({100 * python_rate / cpp_like:.0f} %)"
print(f"impacts, 1 thread, 100 000 points: {python_rate:9.0f} impacts/s; C++ {cpp:9.0f} impacts/s per core "
      f"({100 * python_rate / cpp:.0f} %){like}; medians of 3 rounds in turns")

# The same on points each new, as a study's are: bench_points' grid (21 z from 50 to 80 cm x 100
# ball speeds from 30 to 50 m/s, the defaults, N2000's high-impact swing), each round shifted by a
# fraction of a speed step so that no point recurs, against bench_points' rate over its own rounds
# of that grid at the defaults (CPU time on both sides).
unique_z, unique_speed = (a.ravel() for a in np.meshgrid(0.50 + 0.30 * np.arange(21) / 20, np.arange(100),
                                                         indexing="ij"))


def unique_rate(shift):
    speeds = 30 + 20.0 * (unique_speed + shift) / 100
    start = time.process_time()
    sweetspot.impacts(bat, z=unique_z, ball_speed=speeds, e0=0.5, omega=51, center=0.09, threads=1)
    return len(unique_z) / (time.process_time() - start)


def cpp_unique_rate():
    out = subprocess.run(["build/bench_points", "studies/bats/r161.toml", "default"], capture_output=True, text=True,
                         check=True).stdout
    return float(next(line for line in out.splitlines() if line.startswith("default")).split()[-4])


unique_rate(0.05)  # the modes the defaults need, solved once outside the timing
unique_python, unique_cpp = [], []
for r in range(3):
    unique_python.append(unique_rate(0.1 + 0.25 * r))
    unique_cpp.append(cpp_unique_rate())
python_unique, cpp_unique = statistics.median(unique_python), statistics.median(unique_cpp)
print(f"impacts, 1 thread, 2 100 unique points at the defaults: {python_unique:9.0f} impacts/s; C++ (bench_points) "
      f"{cpp_unique:9.0f} impacts/s per core ({100 * python_unique / cpp_unique:.0f} %); medians of 3 rounds in turns")

# One call against the same impact inside impacts(): the difference is the call's own cost.
one = dict(z=0.705, **scene)
calls = 2000


def impact_calls():
    for _ in range(calls):
        sweetspot.impact(bat, **one)


sweetspot.impact(bat, **one)  # the first call's one-time work (its names and layouts) outside the timing
per_call, per_point = [], []
for _ in range(7):
    per_call.append(seconds(impact_calls) / calls)
    per_point.append(seconds(lambda: sweetspot.impacts(bat, z=np.full(calls, 0.705), threads=1, **scene)) / calls)
call, point = statistics.median(per_call), statistics.median(per_point)
print(f"impact(): {1e6 * call:.1f} us per call, of which the impact {1e6 * point:.1f} us: "
      f"{1e6 * (call - point):.1f} us added (medians of 7 rounds in turns)")

# Reading a result's error estimates makes them (the impact at coarser steps and slicings). Each
# round's points are new (ball speeds shifted apart), as a study's are, so no per-thread memory of
# an earlier impact helps either side: a round of calls that read v_f alone, then one that reads
# the estimates too.
estimate_calls = 200


def estimate_round(r, read):
    for speed in 40 + 1e-3 * (2 * r + read + np.arange(estimate_calls) / estimate_calls):
        result = sweetspot.impact(bat, z=0.705, **dict(scene, ball_speed=speed))
        result["total_error" if read else "vf"]


estimate_round(-1, True)  # the coarser slicings' modes solved once, outside the timing
plain, read = [], []
for r in range(7):  # in turns
    plain.append(seconds(lambda: estimate_round(r, False)) / estimate_calls)
    read.append(seconds(lambda: estimate_round(r, True)) / estimate_calls)
plain_us, read_us = 1e6 * statistics.median(plain), 1e6 * statistics.median(read)
print(f"impact() on new points: {plain_us:.0f} us per call reading v_f, {read_us:.0f} us reading its error "
      f"estimates: {read_us - plain_us:.0f} us more (medians of 7 rounds in turns)")
