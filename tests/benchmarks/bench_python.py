#!/usr/bin/python3
"""The Python module's cost (issue 15): `sweetspot.impacts` on one thread over 100 000 points of the
high-impact scene against the C++ benchmark's impacts per second per core (build/bench_numerics,
the same scene: modes auto at tolerance 5e-5, exact stepping at 60 us, z = 0.555..0.815 m), and what
one `sweetspot.impact` call adds to the impact itself. Prints; asserts nothing.

Usage, from the repository's top after scripts/build: /usr/bin/python3 tests/benchmarks/bench_python.py
"""
import re
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, "build/python")
import sweetspot  # noqa: E402

bat = sweetspot.Bat.load("studies/bats/r161.toml")
scene = dict(ball_speed=40, center=0.09, omega=51, mode_tolerance=5e-5, dt=60e-6)
z = np.resize(np.arange(0.555, 0.83, 0.02), 100_000)

sweetspot.impacts(bat, z=z[:1000], threads=1, **scene)  # the bat's modes solved once, outside the timing
start = time.perf_counter()
sweetspot.impacts(bat, z=z, threads=1, **scene)
python_rate = len(z) / (time.perf_counter() - start)

cpp = subprocess.run(["build/bench_numerics"], capture_output=True, text=True, check=True).stdout
cpp_rate = float(re.search(r"(\d+) impacts per second per core", cpp).group(1))
print(f"impacts, 1 thread, 100 000 points: {python_rate:9.0f} impacts/s; C++ {cpp_rate:9.0f} impacts/s per core "
      f"({100 * python_rate / cpp_rate:.0f} %)")

# One call against the same impact inside impacts(): the difference is the call's own cost.
one = dict(z=0.705, **scene)
calls = 2000
start = time.perf_counter()
for _ in range(calls):
    sweetspot.impact(bat, **one)
per_call = (time.perf_counter() - start) / calls
start = time.perf_counter()
sweetspot.impacts(bat, z=np.full(calls, 0.705), threads=1, **scene)
per_point = (time.perf_counter() - start) / calls
print(f"impact(): {1e6 * per_call:.1f} us per call, of which the impact {1e6 * per_point:.1f} us: "
      f"{1e6 * (per_call - per_point):.1f} us added")
