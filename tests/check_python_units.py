"""The Python module takes lengths, masses and speeds as strings with a unit ("28 in", "136 mph"),
bitwise as the SI numbers they stand for, and refuses the wrong dimension, an unknown unit,
garbage and NaN with ValueError naming the argument.

    /usr/bin/python3 tests/check_python_units.py MODULE_DIR SOURCE_DIR
"""
import sys

module_dir, source = sys.argv[1:3]
sys.path.insert(0, module_dir)
import numpy as np  # noqa: E402
import sweetspot  # noqa: E402
from python_checks import check, finish, refused  # noqa: E402

BAT = f"{source}/studies/bats/r161.toml"


def same_dict(a, b):
    """Bitwise equality of two results (NaN equal to NaN)."""
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same_dict(a[k], b[k]) for k in a)
    if isinstance(a, str):
        return a == b
    return np.array_equal(np.asarray(a, dtype=float), np.asarray(b, dtype=float), equal_nan=True)


bat = sweetspot.Bat.load(BAT)

# impact: every quantity argument with a unit, against the SI numbers they stand for.
si = sweetspot.impact(bat, z=0.7112, ball_speed=60.79744, center=0.0889, omega=51, ball_mass=0.145291306015625,
                      ball_radius=0.03683, modes=6)
us = sweetspot.impact(bat, z="28 in", ball_speed="136 mph", center="3.5in", omega="51 rad/s",
                      ball_mass="5.125 oz", ball_radius="1.45 in", modes=6)
check(same_dict(si, us), "impact with units differs from impact in SI")
swing = sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed="10 m/s", omega="30 rpm", modes=6)
check(same_dict(swing, sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=10.0, omega=np.pi, modes=6)),
      "cm_speed and omega in rpm")

# impacts: scalars with units beside arrays of numbers (SI).
a = sweetspot.impacts(bat, z=np.array([0.6096, 0.635]), ball_speed=60.79744, center=0.0889, omega=51, modes=6)
b = sweetspot.impacts(bat, z=np.array([0.6096, 0.635]), ball_speed="136 mph", center="3.5 in", omega=51, modes=6)
check(np.array_equal(a["vf"].values, b["vf"].values), "impacts with units differs from impacts in SI")
check(a.attrs["scene_ball_speed"] == b.attrs["scene_ball_speed"] == 60.79744, "impacts' scene_ball_speed in SI")

# Refusals: one line naming the argument, the value and the dimension expected.
check(refused(lambda: sweetspot.impact(bat, z="31 oz", ball_speed=40, center=0.09, omega=51),
              "z '31 oz': expected a length (a number in m"), "z in oz")
check(refused(lambda: sweetspot.impact(bat, z=0.7, ball_speed="40 furlongs", center=0.09, omega=51),
              "ball_speed '40 furlongs': expected a speed"), "unknown unit")
check(refused(lambda: sweetspot.impact(bat, z="nan in", ball_speed=40, center=0.09, omega=51), "z 'nan in'"), "NaN")
check(refused(lambda: sweetspot.impact(bat, z="garbage", ball_speed=40, center=0.09, omega=51), "z 'garbage'"),
      "garbage")
check(refused(lambda: sweetspot.impact(bat, z=0.7, ball_speed=40, center=0.09, omega=51, e0="0.5 m"), "e0"),
      "a unit on e0")

# Bats from dimensions and knots: lengths with units are the bat of the same numbers in m.
dims_si = dict(knob_diameter=0.045, knob_length=0.01, handle_diameter=0.0238, taper_start=0.25, taper_end=0.55,
               barrel_diameter=0.066675, wall_thickness=0.0026)
dims_us = dict(knob_diameter="4.5 cm", knob_length="10 mm", handle_diameter="23.8 mm", taper_start="25 cm",
               taper_end="0.55 m", barrel_diameter="2.625 in", wall_thickness="2.6 mm")
materials = dict(material="maple", density=2800, youngs_modulus=7.0e10, shear_modulus=2.6e10, shear_coefficient=0.5)
x = sweetspot.Bat.from_dimensions("a", 0.8382, **dims_si, **materials)
y = sweetspot.Bat.from_dimensions("a", "33 in", **dims_us, **materials)
check(x.length == y.length and np.array_equal(x.outer_diameter, y.outer_diameter)
      and np.array_equal(x.modes(3)["frequencies_hz"], y.modes(3)["frequencies_hz"]), "from_dimensions with units")
check(refused(lambda: sweetspot.Bat.from_dimensions("a", "33 oz", **dims_us, **materials), "length '33 oz'"),
      "from_dimensions length in oz")
# A length refused as given, not as its metres: "-33 in", not -0.8382 m.
check(refused(lambda: sweetspot.Bat.from_dimensions("a", "-33 in", **dims_us, **materials),
              "length '-33 in': expected a positive length"), "from_dimensions negative length with a unit")
check(refused(lambda: sweetspot.Bat.from_dimensions("a", "33 in", **dict(dims_us, handle_diameter="-1 in"),
                                                    **materials), "handle_diameter '-1 in'"),
      "from_dimensions negative dimension with a unit")
k = sweetspot.Bat.from_knots("k", "33 in", [0, 0.8382], [0.025, 0.066])
check(k.length == 0.8382, "from_knots length in inches")

# certify: the rig's ball speed and pivot with units.
alloy = sweetspot.Bat.load(f"{source}/studies/bats/alloy_bbcor.toml")
c_si = sweetspot.certify(alloy, ball_speed=60.79744, pivot=0.1524, modes=6)
c_us = sweetspot.certify(alloy, ball_speed="136 mph", pivot="6 in", modes=6)
check(c_si["bbcor"] == c_us["bbcor"] and c_si["z_max"] == c_us["z_max"], "certify with units")
check(refused(lambda: sweetspot.certify(alloy, pivot="6 oz"), "pivot '6 oz': expected a length"), "pivot in oz")

finish("ok")
