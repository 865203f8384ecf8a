#!/usr/bin/python3
"""The Python module's cost (issue 15): `sweetspot.impacts` on one thread over 100 000 points of the
high-impact scene against the C++ benchmark's impacts per second per core (build/bench_numerics,
the same scene: modes auto at tolerance 5e-5, exact stepping at 60 us, z = 0.555..0.815 m; v_f alone
asked, and with the collision time too, as impacts() gives every output), and what one
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

# Reading a result's error estimates makes them (the impact at coarser steps and slicings).
estimate_calls = 200


def read_estimates():
    for _ in range(estimate_calls):
        sweetspot.impact(bat, **one)["total_error"]


read_estimates()  # the coarser slicings' modes solved once, outside the timing
per_read = [seconds(read_estimates) / estimate_calls for _ in range(7)]
print(f"impact() with its error estimates read: {1e6 * statistics.median(per_read):.0f} us per call, "
      f"{1e6 * (statistics.median(per_read) - call):.0f} us more (median of 7 rounds)")
