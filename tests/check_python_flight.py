"""The Python module's flight(): the same numbers as `sweetspot flight --json` bit for bit, units
as strings ("103 mph", "70 F"), the vacuum parabola, the trajectory on request, and ValueError
naming the argument for bad input.

    /usr/bin/python3 tests/check_python_flight.py MODULE_DIR PROGRAM
"""
import json
import math
import subprocess
import sys

module_dir, program = sys.argv[1:3]
sys.path.insert(0, module_dir)
import numpy as np  # noqa: E402
import sweetspot  # noqa: E402
from python_checks import check, finish, refused  # noqa: E402



# The program and the module compute the same flight from the same words.
r = sweetspot.flight("103 mph", 27.5, backspin="2500 rpm", altitude="15 ft", wind_speed="5 mph", wind_direction=30)
out = json.loads(subprocess.run([program, "flight", "--speed", "103mph", "--angle", "27.5", "--backspin", "2500rpm",
                                 "--altitude", "15ft", "--wind-speed", "5mph", "--wind-direction", "30", "--json"],
                                check=True, capture_output=True, text=True).stdout)
for key in ("distance", "apex", "apex_time", "hang_time", "landing_angle", "landing_speed", "bearing", "air_density"):
    check(r[key] == out[key], f"flight {key}: Python {r[key]!r}, program {out[key]!r}")

# No air: the parabola, in closed form.
g, v, th = 9.80665, 40.0, math.radians(30)
p = sweetspot.flight(v, 30, height=0, vacuum=True)
check(abs(p["distance"] - v * v * math.sin(2 * th) / g) < 1e-9 * p["distance"], f"vacuum distance {p['distance']}")
check(abs(p["apex"] - (v * math.sin(th)) ** 2 / (2 * g)) < 1e-9 * p["apex"], f"vacuum apex {p['apex']}")
# An angle with its unit is that angle.
check(abs(sweetspot.flight(v, f"{th!r} rad", height=0, vacuum=True)["distance"] - p["distance"]) < 1e-12 * p["distance"],
      "angle in rad")
r = sweetspot.flight("103 mph", "0.48 rad", wind_direction="-0.5 rad")
out = json.loads(subprocess.run([program, "flight", "--speed", "103mph", "--angle", "0.48rad", "--wind-direction", "-0.5rad",
                                 "--json"], check=True, capture_output=True, text=True).stdout)
check(r["distance"] == out["distance"], f"angles with units: Python {r['distance']!r}, program {out['distance']!r}")

t = sweetspot.flight(40, 30, samples=0.25)["trajectory"]
check(isinstance(t["z"], np.ndarray) and t["t"][0] == 0 and t["z"][-1] == 0, "trajectory from launch to landing")
check("trajectory" not in sweetspot.flight(40, 30), "no trajectory unless asked")

check(refused(lambda: sweetspot.flight(-1, 30), "speed"), "negative speed")
check(refused(lambda: sweetspot.flight(float("nan"), 30), "speed"), "NaN speed")
check(refused(lambda: sweetspot.flight(40, 30, humidity=150), "humidity"), "humidity above 100 %")
# Humidity as the command line takes it: a number of per cent, with or without "%".
for written in ("20%", "20 %", "20"):
    check(sweetspot.flight(40, 30, humidity=written) == sweetspot.flight(40, 30, humidity=20), f"humidity {written!r}")
check(refused(lambda: sweetspot.flight(40, 30, humidity="20 percent"), "humidity"), "humidity in words")
check(refused(lambda: sweetspot.flight(40, 30, humidity="150%"), "humidity"), "humidity above 100 % as text")
check(refused(lambda: sweetspot.flight(40, 30, direction=1e300), "direction", "-360 to 360"), "a direction past a turn")
check(refused(lambda: sweetspot.flight(40, 30, wind_direction=-400), "wind_direction"), "a wind past a turn")
check(refused(lambda: sweetspot.flight(40, 30, pressure=-5), "pressure"), "negative pressure")
# Far outside the records the ball never landed (1e300) or the fault was laid at the humidity (1e-300).
check(refused(lambda: sweetspot.flight(40, 30, pressure=1e-300), "pressure"), "a pressure of nothing")
check(refused(lambda: sweetspot.flight(40, 30, pressure=1e300), "pressure"), "a pressure past any air")
check(refused(lambda: sweetspot.flight(40, 30, temperature="-500 F"), "temperature"), "below absolute zero")
check(refused(lambda: sweetspot.flight(40, 30, temperature="70 mph"), "temperature", "units K, C, F"),
      "temperature of the wrong dimension")
check(refused(lambda: sweetspot.flight("40 ft", 30), "speed"), "speed of the wrong dimension")

finish("ok")
