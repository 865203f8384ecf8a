"""The Python module against the program: impact equals `sweetspot impact --json` bit for bit,
impacts broadcasts and equals single impacts, bad input is ValueError with the program's message,
two Python threads run impacts at once (the GIL released), bats from knots and dimensions are the
bat files' bats, and certify equals `sweetspot certify --json`.

    /usr/bin/python3 tests/check_python.py MODULE_DIR PROGRAM SOURCE_DIR BUILD_DIR WORK_DIR
"""
import copy
import json
import pickle
import math
import os
import shutil
import signal
import subprocess
import sys
import threading
import time

module_dir, program, source, build, work = sys.argv[1:6]
sys.path.insert(0, module_dir)
import numpy as np  # noqa: E402
import sweetspot  # noqa: E402
from python_checks import check, finish, refused  # noqa: E402

BAT = f"{source}/studies/bats/r161.toml"


def same(a, b):
    """Bitwise equality of a JSON value (null for non-finite) and the module's."""
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if a is None:
        return isinstance(b, float) and not math.isfinite(b)
    if isinstance(a, str):
        return a == b
    return b is not None and float(a) == float(b)


def program_json(args):
    run = subprocess.run([program, "impact", "--bat", BAT, "--json", *args], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def program_error(args):
    run = subprocess.run([program, "impact", "--bat", BAT, *args], capture_output=True, text=True)
    assert run.returncode == 2, (run.returncode, run.stdout, run.stderr)
    return run.stderr.strip()


bat = sweetspot.Bat.load(BAT)
check(bat.name == "R161" and bat.slices == 84 and abs(bat.length - 0.84) < 1e-12, "bat properties")
modes = bat.modes(count=4)
check(modes["frequencies_hz"].shape == (4,) and modes["shapes"].shape == (4, 84), "modes shapes")
check(abs(modes["frequencies_hz"][0] - 174.6) < 0.5, f"f1 {modes['frequencies_hz'][0]}")
check(len(modes["nodes_m"][0]) == 2, "two nodes of mode 1")

# 1. impact == impact --json, bit for bit, key for key (arrays as lists).
scenes = [
    (["--z", "0.7", "--ball-speed", "40", "--cm-speed", "10", "--omega", "40"],
     dict(z=0.7, ball_speed=40, cm_speed=10, omega=40)),
    (["--z", "0.62", "--ball-speed", "31.3", "--center", "0.05", "--omega", "52", "--pivot", "--n2000", "--e0", "0.46"],
     dict(z=0.62, ball_speed=31.3, center=0.05, omega=52, pivot=True, n2000=True, e0=0.46)),
    (["--z", "0.8", "--ball-speed", "35", "--cm-speed", "5", "--modes", "12", "--integrator", "dopri"],
     dict(z=0.8, ball_speed=35, cm_speed=5, modes=12, integrator="dopri")),
]
for args, kwargs in scenes:
    expected = program_json(args)
    got = sweetspot.impact(bat, **kwargs)
    got = {k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in got.items()}
    check(list(expected) == list(got), f"keys {list(expected)} != {list(got)}")
    for key in expected:
        check(same(expected[key], got.get(key)), f"{' '.join(args)}: {key} {expected[key]!r} != {got.get(key)!r}")

# 1b. impact()'s error estimates are made when first read (they cost several impacts): every way
# of reading a dict's values gives the program's, whichever is first, and nothing else.
args, kwargs = scenes[0]
expected = program_json(args)
estimates = ("slicing_error", "step_error", "total_error")
readings = {"r[key]": lambda r: r["step_error"], "get": lambda r: r.get("total_error"), "items": lambda r: dict(r.items()),
            "values": lambda r: list(r.values()), "dict(r)": dict, "{**r}": lambda r: {**r}, "f(**r)": lambda r: (lambda **k: k)(**r),
            "update": lambda r: {}.update(r), "copy": lambda r: r.copy(), "json": lambda r: json.dumps(r, default=lambda v: v.tolist()),
            "repr": repr, "==": lambda r: r == {}, "|": lambda r: r | {}, "pop": lambda r: r.pop("contacts"),
            "copy.copy": copy.copy, "copy.deepcopy": copy.deepcopy, "pickle": lambda r: pickle.loads(pickle.dumps(r))}
for name, read in readings.items():
    got = sweetspot.impact(bat, **kwargs)
    read(got)
    check(all(same(expected[k], dict.__getitem__(got, k)) for k in estimates),
          f"estimates after {name}: {[dict.__getitem__(got, k) for k in estimates]}")
# A Result pickles (to a process pool, say) with its values and attrs as they read: the functions
# that make them when first read could not be pickled.
got = sweetspot.impact(bat, **kwargs)
back = pickle.loads(pickle.dumps(got))
check(type(back) is sweetspot.Result and repr(back) == repr(got) and back.attrs == got.attrs, "a Result through pickle")
got = sweetspot.impact(bat, **kwargs)
check(same(expected, json.loads(json.dumps({k: v for k, v in got.items() if k not in ("mode_energy", "modes_kept")}))
                       | {k: expected[k] for k in ("mode_energy", "modes_kept")}), "a Result through json")
# impact() reads plain floats and ints in C++ at once and has the package check anything else
# first (numpy numbers, units): the same scene either way, the same result and record, bit for bit.
plain = sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=10, omega=40, e0=0.5, dt=1e-5)
checked = sweetspot.impact(bat, z=np.float64(0.7), ball_speed="40 m/s", cm_speed=np.int64(10), omega=40.0,
                           e0=np.float64(0.5), dt=np.float64(1e-5))


def identical(a, b):
    """The same keys in the same order, the same bits (NaN too)."""
    if isinstance(a, dict):
        return isinstance(b, dict) and list(a) == list(b) and all(identical(a[k], b[k]) for k in a)
    if isinstance(a, str):
        return a == b
    return np.asarray(a).dtype == np.asarray(b).dtype and np.asarray(a).tobytes() == np.asarray(b).tobytes()


check(identical(plain, checked), "plain numbers and checked ones give the same result")
check(plain.attrs == checked.attrs, "plain numbers and checked ones give the same record")
got = sweetspot.impact(bat, **kwargs)
got["total_error"] = -1.0
check(got["total_error"] == -1.0 and same(expected["slicing_error"], got["slicing_error"]), "a value set stays set")

# 2. impacts: broadcasting (ball_speed down, z across) and equality with single impacts.
z = np.array([0.5, 0.6, 0.7, 0.75, 0.8])
v = np.array([30.0, 40.0, 50.0])
ds = sweetspot.impacts(bat, z=z, ball_speed=v[:, None], cm_speed=10, omega=40, e0=0.5)
check(ds.vf.dims == ("ball_speed", "z") and ds.vf.shape == (3, 5), f"dims {ds.vf.dims} {ds.vf.shape}")
check(ds.vf.attrs.get("units") == "m/s" and "units" not in ds.status.attrs, "units as a study's")
check(ds.status.attrs["flag_meanings"].split()[0] == "ok" and list(ds.status.attrs["flag_values"][:2]) == [0, 1],
      "status flags")
for i, speed in enumerate(v):
    for j, zz in enumerate(z):
        one = sweetspot.impact(bat, z=zz, ball_speed=speed, cm_speed=10, omega=40, e0=0.5)
        for name in ("vf", "e_eff", "bat_speed", "e_a", "contact_time", "modes_error"):
            check(ds[name].values[i, j] == one[name], f"impacts {name}[{i},{j}] {ds[name].values[i, j]} != {one[name]}")
        check(ds.status.values[i, j] == 0 and ds.modes_kept.values[i, j] == len(one["modes_kept"]), "status, kept")
zipped = sweetspot.impacts(bat, z=z, e0=np.linspace(0.4, 0.6, 5), ball_speed=40, cm_speed=10, omega=40)
check(zipped.vf.dims == ("point",) and zipped.e0.dims == ("point",), f"zipped dims {zipped.vf.dims}")
one = sweetspot.impact(bat, z=z[2], e0=0.5, ball_speed=40, cm_speed=10, omega=40)
check(zipped.vf.values[2] == one["vf"], "zipped value")

# 3. Bad input: ValueError with the program's message, nothing crashes.
for args, kwargs in [(["--z", "2", "--ball-speed", "40", "--cm-speed", "10"], dict(z=2.0, ball_speed=40, cm_speed=10)),
                     (["--z", "0.7", "--ball-speed", "40", "--cm-speed", "10", "--e0", "2"],
                      dict(z=0.7, ball_speed=40, cm_speed=10, e0=2))]:
    message = program_error(args)
    try:
        sweetspot.impact(bat, **kwargs)
        check(False, f"no ValueError for {kwargs}")
    except ValueError as e:
        check(str(e) in message and "\n" not in str(e), f"message {e!r} not the program's {message!r}")
for call in [lambda: sweetspot.Bat.load(f"{source}/studies/bats/no_such_bat.toml"),
             lambda: sweetspot.impacts(bat, z=[0.7, 2.0], ball_speed=40, cm_speed=10),
             lambda: sweetspot.impacts(bat, z=0.7, ball_speed=40, cm_speed=10, e0=[0.5, 2]),
             lambda: sweetspot.impact(bat, z=0.7, ball_speed=40),
             lambda: sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=1, center=0.1),
             lambda: sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=1, modes="some"),
             lambda: sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=1, dt=1e-15),
             lambda: sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=1, integrator="euler"),
             lambda: sweetspot.impact(bat, z=math.nan, ball_speed=40, cm_speed=1),
             # its section read before the scene was checked killed the interpreter (segfault)
             lambda: sweetspot.impact(bat, z=math.nan, ball_speed=40, cm_speed=10, ball="ncaa"),
             lambda: sweetspot.impacts(bat, z=[0.5, math.nan], ball_speed=40, cm_speed=10, ball="ncaa"),
             lambda: sweetspot.impact(bat, z=0.7, ball_speed=40, center=-1000, omega=1000),
             lambda: bat.modes(theory="string")]:
    try:
        call()
        check(False, "no ValueError")
    except ValueError as e:
        print("ValueError:", e)

# 3b. Every argument of a wrong type or value is a ValueError naming it (issue 24): not
# pybind11's RuntimeError ("Unable to cast") or TypeError, no crash, no complex number read as its
# real part; threads bounded; dt and accuracy not both; an accuracy of 0 refused as a study's is.
swing = dict(z=0.7, ball_speed=40, cm_speed=10)
rod_args = ("rod", 0.84, [0, 0.84], [0.06, 0.06])
for call, fragments in [
        (lambda: sweetspot.impacts(bat, **swing, threads=100000), ["threads", "100000", "from 1 to"]),
        (lambda: sweetspot.impacts(bat, **swing, threads=sweetspot._max_threads() + 1),
         ["threads", str(sweetspot._max_threads() + 1), "4 per processor"]),
        (lambda: sweetspot.impacts(bat, **swing, threads=-1), ["threads", "-1"]),
        (lambda: sweetspot.impacts(bat, **swing, threads=0), ["threads", "0"]),
        (lambda: sweetspot.impacts(bat, **swing, threads=2.5), ["threads", "2.5"]),
        (lambda: sweetspot.impacts(bat, **swing, threads="4"), ["threads", "'4'"]),
        (lambda: sweetspot.impact(bat, **swing, dt=1e-5, accuracy=1e-4), ["dt", "accuracy"]),
        (lambda: sweetspot.impacts(bat, **swing, dt=1e-5, accuracy=1e-4), ["dt", "accuracy"]),
        (lambda: sweetspot.impact(bat, **swing, step_accuracy=0), ["step_accuracy", "0", "> 0"]),
        (lambda: sweetspot.impact(bat, **swing, step_accuracy=-1e-4), ["step_accuracy", "-0.0001", "> 0"]),
        (lambda: sweetspot.impact(bat, **swing, step_accuracy=math.nan), ["step_accuracy", "nan", "> 0"]),
        (lambda: sweetspot.impact(bat, **swing, dt=1e-5, step_accuracy=1e-4), ["dt", "step_accuracy"]),
        (lambda: sweetspot.impact(bat, **swing, accuracy=0), ["accuracy", "0", "from 1e-7 to 0.1"]),
        (lambda: sweetspot.impact(bat, **swing, accuracy=1e-9), ["accuracy", "1e-09", "from 1e-7 to 0.1"]),
        (lambda: sweetspot.impact(bat, **swing, accuracy=math.nan), ["accuracy", "nan", "from 1e-7 to 0.1"]),
        (lambda: sweetspot.impact(bat, **swing, accuracy=1e-4, mode_tolerance=1e-5), ["mode_tolerance", "accuracy"]),
        (lambda: sweetspot.impact(bat, **swing, accuracy=1e-4, step_accuracy=1e-5), ["step_accuracy", "accuracy"]),
        (lambda: sweetspot.impact(bat, **swing, accuracy=1e-4, tolerance=1e-8), ["tolerance", "accuracy"]),
        (lambda: sweetspot.impact(bat, **swing, accuracy=1e-4, modes=10), ["modes", "accuracy"]),
        # dopri alone reads a tolerance, modes="auto" alone a mode tolerance: elsewhere each was ignored.
        (lambda: sweetspot.impact(bat, **swing, tolerance=1e-8), ["tolerance", "1e-08", "integrator=\"dopri\"",
                                                                  "(exact steps at dt)"]),
        (lambda: sweetspot.impacts(bat, **swing, integrator="rk4", tolerance=1e-8), ["tolerance", "(rk4 steps"]),
        (lambda: sweetspot.impact(bat, **swing, modes=10, mode_tolerance=1e-5), ["mode_tolerance", "modes=\"auto\"",
                                                                               "(modes=10 keeps a fixed set)"]),
        (lambda: sweetspot.impacts(bat, **swing, n2000=True, mode_tolerance=1e-5), ["mode_tolerance", "(n2000 keeps"]),
        (lambda: sweetspot.impact(bat, **swing, pivot="yes"), ["pivot", "'yes'", "True or False"]),
        (lambda: sweetspot.impact(bat, **swing, n2000="no"), ["n2000", "'no'"]),
        (lambda: sweetspot.impact(bat, **swing, modes=10 ** 20), ["modes", "100000000000000000000"]),
        (lambda: sweetspot.impact(bat, **swing, theory=5), ["theory", "5"]),
        (lambda: sweetspot.impact(bat, **swing, integrator=["rk4"]), ["integrator"]),
        (lambda: sweetspot.impact(bat, z=0.7 + 1e-3j, ball_speed=40, cm_speed=10), ["z", "0.7"]),
        (lambda: sweetspot.impact(bat, **swing, e0=np.complex128(0.5 + 0.1j)), ["e0", "0.5"]),
        (lambda: sweetspot.impact(bat, **swing, e0=True), ["e0", "True"]),
        (lambda: sweetspot.impact(bat, **swing, dt="1e-5"), ["dt", "'1e-5'"]),
        (lambda: sweetspot.impact(bat, z=[0.6, 0.7], ball_speed=40, cm_speed=10), ["z", "[0.6, 0.7]"]),
        (lambda: sweetspot.impacts(bat, z=np.array([0.6, 0.7 + 1e-3j]), ball_speed=40, cm_speed=10), ["z"]),
        (lambda: sweetspot.impacts(bat, z=[0.6, "0.7"], ball_speed=40, cm_speed=10), ["z"]),
        (lambda: sweetspot.impacts(bat, z=[[0.6], [0.7, 0.8]], ball_speed=40, cm_speed=10), ["z"]),
        (lambda: sweetspot.impact("r161", **swing), ["bat", "'r161'", "sweetspot.Bat"]),
        (lambda: sweetspot.Bat.from_knots(*rod_args, density="700"), ["density", "'700'", "real number"]),
        (lambda: sweetspot.Bat.from_knots(*rod_args, density=700 + 1j), ["density"]),
        (lambda: sweetspot.Bat.from_knots("", *rod_args[1:]), ["name", "''", "non-empty"]),
        (lambda: sweetspot.Bat.from_knots(5, *rod_args[1:]), ["name", "5"]),
        (lambda: sweetspot.Bat.from_knots("rod", 0.84, [0, 0.84 + 1j], [0.06, 0.06]), ["z"]),
        (lambda: sweetspot.Bat.from_knots(*rod_args, slices="40"), ["slices", "'40'"]),
        (lambda: sweetspot.Bat.from_knots(*rod_args, slices=10 ** 20), ["slices", "100000000000000000000"]),
        (lambda: sweetspot.Bat.from_knots(*rod_args, interpolation=1), ["interpolation", "1"]),
        (lambda: sweetspot.Bat.from_dimensions("", 0.8382, knob_diameter=0.0505, knob_length=0.02,
                                               handle_diameter=0.0238125, taper_start=0.3048, taper_end=0.6604,
                                               barrel_diameter=0.0635), ["name", "''"]),
        (lambda: sweetspot.Bat.from_dimensions("b", 0.8382, knob_diameter=0.0505, knob_length=0.02,
                                               handle_diameter=0.0238125, taper_start=0.3048, taper_end=0.6604,
                                               barrel_diameter=0.0635j), ["barrel_diameter"]),
        (lambda: sweetspot.Bat.load(BAT, slices=3.5), ["slices", "3.5"]),
        (lambda: sweetspot.Bat.load(161), ["path", "161"]),
        (lambda: bat.modes(count="4"), ["count", "'4'"]),
        (lambda: bat.modes(count=10 ** 20), ["count"]),
        (lambda: bat.moment_of_inertia_about(1j), ["z", "1j"]),
        (lambda: bat.moment_of_inertia_about(float("nan")), ["z nan", "a finite point"]),  # returned nan
        (lambda: sweetspot.Bat.from_knots("rod\x00b", *rod_args[1:]), ["name", "without NUL"]),  # a dataset refused it late
        # A masked array's masked points were computed all the same.
        (lambda: sweetspot.impacts(bat, z=np.ma.array([0.6, 0.7], mask=[False, True]), ball_speed=40, cm_speed=10),
         ["z masked_array", "without a mask"]),
        (lambda: sweetspot.scene_of({"scene_pivot": 0.5, "scene_z": 0.7}), ["scene_pivot 0.5", "0 or 1"]),  # was True
        (lambda: sweetspot.certify(bat, e0="0.5"), ["e0", "'0.5'"]),
        (lambda: sweetspot.certify(bat, standard=None), ["standard", "None"]),
        (lambda: sweetspot.certify(bat, modes=10 ** 20), ["modes"]),
        (lambda: sweetspot.certify(bat, accuracy=0), ["accuracy 0", "1e-7 to 0.1"]),
        (lambda: sweetspot.ball(5), ["name", "5"]),
        # pybind11's many-line TypeError, an OverflowError naming nothing, the library's field name:
        (lambda: sweetspot.flight(40, None), ["angle None", "real number"]),
        (lambda: sweetspot.flight(40, 30, direction=None), ["direction None"]),
        (lambda: sweetspot.flight(40, 30, samples=-1), ["samples = -1", "0.001 s"]),
        (lambda: sweetspot.impact(bat, 10**400, 40, cm_speed=10), ["z 1000", "a real number"]),
        (lambda: sweetspot.scene_of(None), ["result None"]),
        (lambda: sweetspot.bat_of("abc"), ["result 'abc'"])]:
    try:
        call()
        check(False, f"no ValueError for {fragments}")
    except ValueError as e:
        check(all(f in str(e) for f in fragments) and "\n" not in str(e), f"{fragments} not all in {e!r}")
    except Exception as e:  # noqa: BLE001 (RuntimeError, TypeError: what this section refuses)
        check(False, f"{fragments}: {type(e).__name__}, not ValueError: {e}")
# What stays accepted: units as strings, numpy numbers, 0/1 flags, threads up to the bound, a dt or
# an accuracy alone, a replay of a result with an accuracy (its record holds both).
one = sweetspot.impact(bat, z="27.56 in", ball_speed=np.float32(40), cm_speed=np.int64(10), pivot=0)
check(one["status"] == "ok", "units and numpy numbers")
check(sweetspot.impacts(bat, **swing, threads=1).vf.values[()] == sweetspot.impact(bat, **swing)["vf"], "threads=1")
for name in ("accuracy", "step_accuracy"):
    accurate = sweetspot.impact(bat, **swing, **{name: 1e-4})
    check(sweetspot.impact(bat, **sweetspot.scene_of(accurate))["vf"] == accurate["vf"], f"replay with {name}")
# A stated total accuracy is met, and impacts() computes what impact() does at it.
accurate = sweetspot.impact(bat, **swing, accuracy=1e-3)
check(accurate["status"] == "ok" and accurate["total_error"] <= 1e-3 and accurate["slices_used"] >= 2 * bat.slices,
      f"accuracy=1e-3 met: {accurate['total_error']} at {accurate['slices_used']} slices")
many = sweetspot.impacts(bat, z=[0.6, 0.7], ball_speed=40, cm_speed=10, accuracy=1e-3)
check(many.vf.values[1] == accurate["vf"] and many.slices_used.values[1] == accurate["slices_used"],
      "impacts at an accuracy as impact")
# ... with every estimate and their sum, and the step chosen.
check(all(many[k].values[1] == accurate[k] for k in ("slicing_error", "modes_error", "step_error", "total_error")) and
      many.step_used.values[1] > 0 and
      (many.total_error == many.slicing_error + many.modes_error + many.step_error).all(),
      f"impacts' estimates at an accuracy as impact's: total {many.total_error.values}")
# A point of a failing status has no values, as in a study's dataset (Dormand-Prince at 1e-2 on a
# nearly dead ball at the tip ends unbalanced); the other point is ok.
statuses = sweetspot.impacts(sweetspot.Bat.load("torpedo"), z=np.array([0.83, 0.7]), ball_speed=150, center=0.09,
                             omega=51, e0=0.2, integrator="dopri", accuracy=1e-2)
check(list(statuses.status.values) == [4, 0] and np.isnan(statuses.vf.values[0]) and statuses.vf.values[1] > 0,
      f"impacts: an unbalanced point without values: {statuses.status.values} {statuses.vf.values}")
# Near the handle the ball is caught again and auto's unsolved modes pass their share: the rung
# runs again on a wider basis (docs/numerics.md), which Python solves as the program does.
handle = dict(z=0.405, ball_speed=30, e0=0.44, center=0.09, omega=51, accuracy=1e-3)
widened = sweetspot.impact(bat, **handle)
program_widened = program_json(["--z", "0.405", "--ball-speed", "30", "--e0", "0.44", "--center", "0.09",
                                "--omega", "51", "--accuracy", "1e-3"])
check(widened["status"] == "ok" and widened["contacts"] > 1 and widened["modes_error"] <= 2.5e-4 and
      widened["vf"] == program_widened["vf"], f"a widened rung as the program's: {widened['modes_error']}")
check(sweetspot.Bat.from_knots(*rod_args, density=np.float64(700), slices=np.int64(40)).slices == 40, "numpy args")
# Knots one per value: a 2-D array (read flattened), a masked array (its mask ignored) and bools
# among numbers are refused, naming the argument.
for bad in (np.array([[0, 0.3], [0.5, 0.84]]), np.ma.masked_array([0, 0.84], mask=[False, True]), [False, 0.84]):
    check(refused(lambda: sweetspot.Bat.from_knots("rod", 0.84, bad, [0.06, 0.06]), "z ", "1-D array"),
          f"from_knots refuses z = {bad!r}")
# A numpy integer is a mode count as an int is; numpy's bool is not.
check(len(sweetspot.impact(bat, **swing, modes=np.int64(18))["modes_kept"]) == 18 and
      sweetspot.certify(bat, modes=np.int32(18))["bbcor"] == sweetspot.certify(bat, modes=18)["bbcor"], "numpy modes")
check(refused(lambda: sweetspot.impact(bat, **swing, modes=np.bool_(True)), "modes True", "expected a number"),
      "numpy bool is no mode count")
# Empty strings are named, quoted, as the arguments Python was given (not as the command line's
# options, nor ": file not found").
check(refused(lambda: sweetspot.impact(bat, **swing, modes=""), "modes ''", "expected a number"), "modes ''")
check(refused(lambda: sweetspot.certify(bat, ""), "standard ''", "\"bbcor\", \"besr\" or \"bpf\"")
      and refused(lambda: sweetspot.certify(bat, "asa"), "standard 'asa'"), "certify's standard as written")
check(refused(lambda: sweetspot.Bat.load(""), "path ''", "a bat file's path"), "Bat.load('')")
check(refused(lambda: sweetspot.scene_of({"a": 1}), "without scene_* attributes"), "scene_of of no result")
# A key of 60 000 parts overflowed toml++'s stack and killed the interpreter (tests/test_toml_depth.cpp).
check(refused(lambda: sweetspot.Bat.from_text("x" + ".x" * 60000 + " = 1"), "<text>:1:", "more than 64 parts"),
      "Bat.from_text with a key of 60 000 parts")

# 4. The GIL released: two Python threads each run impacts; both finish with the same numbers.
zs = np.linspace(0.45, 0.84, 3000)
# OpenMP's threads per call, then one each: two one-thread calls on two cores take about as long as
# one when the GIL is released, twice as long when it is not (printed, not asserted: shared machines).
for threads in (None, 1):
    start = time.perf_counter()
    alone = sweetspot.impacts(bat, z=zs, ball_speed=40, cm_speed=10, omega=40, threads=threads)
    t_one = time.perf_counter() - start
    results = [None, None]

    def run_in_thread(k):
        results[k] = sweetspot.impacts(bat, z=zs, ball_speed=40, cm_speed=10, omega=40, threads=threads)

    workers = [threading.Thread(target=run_in_thread, args=(k,)) for k in range(2)]
    start = time.perf_counter()
    for t in workers:
        t.start()
    for t in workers:
        t.join()
    t_two = time.perf_counter() - start
    for r in results:
        check(r is not None and np.array_equal(r.vf.values, alone.vf.values), "threaded impacts equal")
    print(f"impacts over {zs.size} points, threads={threads}: {t_one:.3f} s alone, two Python threads at once "
          f"{t_two:.3f} s ({t_two / t_one:.2f} x one call)")

# 5. run_study equals `sweetspot run`, and impacts equals the study's points (the same modes solved).
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
study = f"{source}/studies/high_impact.toml"
ds = sweetspot.run_study(study, output=f"{work}/module.h5")
subprocess.run([program, "run", study, "-o", f"{work}/program.h5", "--quiet"], check=True)
import xarray as xr  # noqa: E402
with xr.open_dataset(f"{work}/program.h5", engine="h5netcdf") as reference:
    for name in ("vf", "e_eff", "contact_time", "status", "frequency"):
        check(np.array_equal(ds[name].values, reference[name].values, equal_nan=True), f"run_study {name}")
points = sweetspot.impacts(bat, z=ds.z.values, ball_speed=40, center=0.09, omega=51, e0=0.5, modes=18)
check(refused(lambda: sweetspot.impacts_like(ds), "a dataset of `sweetspot run`", "run_study"),
      "impacts_like names a study's dataset as one")
check(np.array_equal(points.vf.values, ds.vf.sel(modes=18).squeeze().values), "impacts == the study's points")
# A study at a stated accuracy: each point climbs its own slicings, so the study (on any threads)
# equals impacts() point for point, and meets the accuracy.
accuracy_study = f"{work}/accuracy.toml"
with open(accuracy_study, "w") as f:
    f.write(f'[scene]\nbat = "{BAT}"\ncenter = 0.09\nomega = 51\nball_speed = 40\naccuracy = 1e-3\n'
            '[axes]\nz = [0.3, 0.6, 0.75]\n[output]\nvariables = ["vf", "total_error", "slices_used", "status"]\n')
for threads in ("1", "2"):
    run = subprocess.run([program, "run", accuracy_study, "-o", f"{work}/accuracy_{threads}.h5", "--quiet"],
                         env=os.environ | {"OMP_NUM_THREADS": threads}, capture_output=True, text=True)
    check(run.returncode == 0, f"accuracy study on {threads} thread(s): {run.stderr}")
with xr.open_dataset(f"{work}/accuracy_1.h5", engine="h5netcdf") as one, \
        xr.open_dataset(f"{work}/accuracy_2.h5", engine="h5netcdf") as two:
    check(np.array_equal(one.vf.values, two.vf.values), "accuracy study: the same on 1 and 2 threads")
    check(bool((one.total_error.values <= 1e-3).all()), f"accuracy study meets 1e-3: {one.total_error.values}")
    points = sweetspot.impacts(bat, z=one.z.values, ball_speed=40, center=0.09, omega=51, accuracy=1e-3)
    check(np.array_equal(points.vf.values, one.vf.values), "accuracy study == impacts(accuracy=1e-3)")
    check(np.array_equal(points.slices_used.values, one.slices_used.values), "the same slices chosen")
try:
    sweetspot.run_study(f"{source}/studies/no_such_study.toml")
    check(False, "run_study of a missing file")
except ValueError as e:
    print("ValueError:", e)

# 6. Bats as designs: from knots and from dimensions, their exact properties, and certify.
rod = sweetspot.Bat.from_knots("rod", 0.84, [0, 0.84], [0.06, 0.06], material="maple", density=700)
check(abs(rod.properties()["mass"] / (700 * math.pi * 0.03 ** 2 * 0.84) - 1) < 1e-12, "a 2-knot rod's mass")
check(abs(rod.properties()["moi_cm"] / (rod.properties()["mass"] * (0.84 ** 2 / 12 + 0.03 ** 2 / 4)) - 1) < 1e-12,
      "a 2-knot rod's MOI about its centre: M (L^2/12 + R^2/4)")
file_271 = sweetspot.Bat.load(f"{source}/studies/bats/maple_271.toml")
made_271 = sweetspot.Bat.from_dimensions("maple 271", 0.8382, knob_diameter=0.0505, knob_length=0.02,
                                         handle_diameter=0.0238125, taper_start=0.3048, taper_end=0.6604,
                                         barrel_diameter=0.0635, end="cupped", end_depth=0.0254)
check(made_271.properties() == file_271.properties(), "from_dimensions is the bat file's maple 271")
props = file_271.properties()
check(abs(props["drop"] - (props["length"] / 0.0254 - props["mass"] / 0.028349523125)) < 1e-12, "drop")
check(abs(props["moi_pivot"] - props["moi_cm"] - props["mass"] * (props["balance_point"] - 0.1524) ** 2) < 1e-15,
      "moi_pivot by the parallel-axis theorem")
for standard in ("bbcor", "besr"):
    mine = sweetspot.certify(sweetspot.Bat.load(BAT), standard)
    run = subprocess.run([program, "certify", BAT, "--standard", standard, "--json"], capture_output=True, text=True)
    check(same(json.loads(run.stdout), mine), f"certify({standard}) equals sweetspot certify --json")
mine = sweetspot.certify(sweetspot.Bat.load(BAT), accuracy=1e-2)
run = subprocess.run([program, "certify", BAT, "--accuracy", "1e-2", "--json"], capture_output=True, text=True)
check(same(json.loads(run.stdout), mine) and mine["total_error"] <= 1e-2,
      "certify(accuracy=1e-2) equals sweetspot certify --accuracy 1e-2 --json, within its accuracy")
for bad, what in ((lambda: sweetspot.Bat.from_knots("b", 0.84, [0, 0.9], [0.06, 0.06]), "beyond length"),
                  (lambda: sweetspot.Bat.from_knots("b", 0.84, [0.5, 0.2], [0.06, 0.06]), "increasing"),
                  (lambda: sweetspot.Bat.from_knots("b", 0.84, [0, 0.84], [0.06, 0.06], material="oak"), "oak"),
                  (lambda: sweetspot.Bat.from_dimensions("b", 0.84, knob_diameter=0.05, knob_length=0.02,
                                                         handle_diameter=0.024, taper_start=0.3, taper_end=0.6,
                                                         barrel_diameter=0.02), "handle_diameter"),
                  (lambda: sweetspot.certify(file_271, "asa"), "asa")):
    try:
        bad()
        check(False, f"{what}: no ValueError")
    except ValueError as e:
        check(what in str(e), f"{what}: {e}")

# 6a. Each bat parameter's range (parameter_bounds.hpp), as bat files and studies have it: just
# inside, a bat with finite modes; just outside, a ValueError naming the parameter and the range.
dims = dict(knob_diameter=0.0505, knob_length=0.02, handle_diameter=0.0238125, taper_start=0.3048,
            taper_end=0.6604, barrel_diameter=0.0635, end="cupped", end_depth=0.0254)
for key, inside, outside, expected in (("density", 25000, 25001, "10 to 25000 kg/m^3"),
                                       ("youngs_modulus", 1e6, 9.9e5, "1000000 to 1e+12 Pa"),
                                       ("shear_coefficient", 1, 1.01, "0.1 to 1"),
                                       ("barrel_diameter", 1, 1e300, "0.001 to 1 m")):
    material = {k: v for k, v in ((key, inside),) if key != "barrel_diameter"}
    if key == "youngs_modulus":  # the shear modulus stays at most Young's
        material["shear_modulus"] = inside
    shape = dict(dims, **({key: inside, "knob_diameter": 1} if key == "barrel_diameter" else {}))
    good = sweetspot.Bat.from_dimensions("b", 0.8382, material="maple", **material, **shape)
    hz = good.modes(count=3)["frequencies_hz"]
    check(all(math.isfinite(f) and f > 0 for f in hz) and math.isfinite(good.mass), f"{key} = {inside}: {hz}")
    try:
        material = {k: v for k, v in ((key, outside),) if key != "barrel_diameter"}
        if key == "youngs_modulus":
            material["shear_modulus"] = 1e6
        shape = dict(dims, **({key: outside, "knob_diameter": 1} if key == "barrel_diameter" else {}))
        sweetspot.Bat.from_dimensions("b", 0.8382, material="maple", **material, **shape)
        check(False, f"{key} = {outside}: no ValueError")
    except ValueError as e:
        check(key in str(e) and expected in str(e) and "\n" not in str(e), f"{key} = {outside}: {e}")
thin = sweetspot.Bat.from_knots("tube", 0.84, [0, 0.84], [0.06, 0.06], [0.0598, 0.0598], material="maple")
check(math.isfinite(thin.mass) and thin.modes(count=2)["frequencies_hz"][1] > 0, "a 0.1-mm wall from knots")
try:
    sweetspot.Bat.from_knots("tube", 0.84, [0, 0.84], [0.06, 0.06], [0.06 - 2e-9, 0.06 - 2e-9], material="maple")
    check(False, "a 1-nm wall from knots: no ValueError")
except ValueError as e:
    check("wall" in str(e) and "0.0001 to 0.5 m" in str(e), f"a 1-nm wall from knots: {e}")

# 6b. A shipped bat by name, found in the build tree (build/share/sweetspot links the checkout's
# studies/bats); an unknown name is a ValueError naming the shipped bats.
by_name = sweetspot.Bat.load("r161")
check(by_name.name == bat.name and by_name.mass == bat.mass and by_name.slices == bat.slices,
      f"Bat.load('r161'): {by_name.name} {by_name.mass}, not the file's {bat.name} {bat.mass}")
try:
    sweetspot.Bat.load("r16")
    check(False, "Bat.load('r16'): no ValueError")
except ValueError as e:
    check("'r16'" in str(e) and "r161 torpedo" in str(e) and "\n" not in str(e), f"Bat.load('r16'): {e}")

# 6c. A ball's ranges (ball_tests.hpp, docs/balls.md) and omega >= 0, as the program and studies
# have them: a tiny but positive value is a ValueError naming the argument and its range, before
# any impact runs.
os.makedirs(work, exist_ok=True)
tiny_mass = f"{work}/tiny_mass.toml"
with open(tiny_mass, "w") as f:
    f.write('[ball]\npreset = "mlb"\nmass = 1e-300\n')
tiny_squeeze = f"{work}/tiny_squeeze.toml"
with open(tiny_squeeze, "w") as f:
    f.write("[ball]\nmass = 0.145\nradius = 0.0366\ncor = 0.5\ncompression = 1500\ncompression_displacement = 1e-300\n")
for call, fragments in (
        (lambda: sweetspot.impact(bat, **swing, omega=40, ball_mass=1e-300), ["ball_mass", "[0.001, 10] kg"]),
        (lambda: sweetspot.impact(bat, **swing, omega=40, ball_radius=1e-300), ["ball_radius", "[0.001, 1] m"]),
        (lambda: sweetspot.impact(bat, **swing, omega=40, k1=1e-300), ["k1", "[1000, 1e12]"]),
        (lambda: sweetspot.impact(bat, **swing, omega=40, e0=1e-300), ["e0", "[0.05, 1]"]),
        (lambda: sweetspot.impacts(bat, **swing, omega=40, ball_mass=[0.145, 1e-300]), ["ball_mass", "1e-300"]),
        (lambda: sweetspot.impact(bat, **swing, omega=40, ball=tiny_mass), ["mass = 1e-300", "[0.001, 10] kg"]),
        (lambda: sweetspot.ball(tiny_squeeze), ["compression_displacement = 1e-300", "[0.0001, 1] m"]),
        # A negative omega swings the barrel away from the ball: refused as the program does (issue 24).
        (lambda: sweetspot.impact(bat, **swing, omega=-40), ["omega -40", ">= 0"]),
        (lambda: sweetspot.impacts(bat, **swing, omega=[40, -40]), ["omega -40", ">= 0"]),
        # A stated accuracy chooses dopri's tolerance: one given beside it is refused, as dt is.
        (lambda: sweetspot.impact(bat, **swing, omega=40, integrator="dopri", accuracy=1e-5, tolerance=1e-12),
         ["tolerance excludes accuracy"])):
    try:
        call()
        check(False, f"{fragments}: no ValueError")
    except ValueError as e:
        check(all(f in str(e) for f in fragments) and "\n" not in str(e), f"{fragments}: {e}")

# 7. cmake --install puts the package under the prefix, where the interpreter imports it.
prefix = f"{work}/prefix"
subprocess.run(["cmake", "--install", build, "--prefix", prefix], check=True, capture_output=True)
site = f"{prefix}/lib/python3/dist-packages"
run = subprocess.run([sys.executable, "-c", "import sweetspot; print(sweetspot.__file__)"],
                     env=os.environ | {"PYTHONPATH": site}, capture_output=True, text=True, cwd=work)
check(run.returncode == 0 and run.stdout.startswith(site), f"installed package: {run.stdout} {run.stderr}")

# 8. Ctrl-C stops a long impacts() within its tenth of a second of checks, with KeyboardInterrupt
# (it ran to the last of its points first: 150 000 points, interrupted at 2 s, raised at 11.5 s).
many = np.resize(np.linspace(0.5, 0.8, 31), 400_000)  # some seconds on any machine
for threads in (1, 2):
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        sweetspot.impacts(bat, z=many, ball_speed=40, cm_speed=10, threads=threads)
        check(False, f"impacts on {threads} thread(s) ran to the end through Ctrl-C")
    except KeyboardInterrupt:
        check(time.monotonic() - start < 2.5, f"KeyboardInterrupt after {time.monotonic() - start:.2f} s")
    timer.join()
check(sweetspot.impacts(bat, z=[0.7], ball_speed=40, cm_speed=10).vf.values[0] > 0, "impacts after an interrupt")

finish("python module: all checks passed")
