"""Python results a scientist can trust and reproduce: sweetspot.__version__ is the program's;
every result of impacts(), impact() and certify() carries the resolved scene (defaults filled in),
the bat, program_version, git_commit and Conventions as a study dataset names them, in types netCDF
stores; a dataset saved with to_netcdf() and reopened with xarray.open_dataset computes the same
numbers bit for bit when its stored scene is fed back (impacts_like, scene_of, bat_of); a bat is
rebuilt from the stored text; every public function and class has a docstring.

    /usr/bin/python3 tests/check_python_provenance.py MODULE_DIR PROGRAM SOURCE_DIR WORK_DIR
"""
import inspect
import os
import pathlib
import shutil
import subprocess
import sys

module_dir, program, source, work = sys.argv[1:5]
sys.path.insert(0, module_dir)
import numpy as np  # noqa: E402
import xarray as xr  # noqa: E402

import sweetspot  # noqa: E402
from python_checks import check, finish  # noqa: E402

BAT = f"{source}/studies/bats/r161.toml"


def same_values(a, b):
    """Bitwise equality of two results of impact() or certify(), NaN equal to NaN."""
    if isinstance(a, dict):
        return isinstance(b, dict) and a.keys() == b.keys() and all(same_values(a[k], b[k]) for k in a)
    if isinstance(a, (list, np.ndarray)):
        return len(a) == len(b) and all(same_values(x, y) for x, y in zip(a, b))
    if isinstance(a, float):
        return isinstance(b, float) and (a == b or (np.isnan(a) and np.isnan(b)))
    return a == b


def same_numbers(a, b):
    """Every data variable and coordinate of two datasets equal bit for bit (NaN where NaN)."""
    names = sorted(set(a.variables) | set(b.variables))
    return all(name in a.variables and name in b.variables and a[name].dims == b[name].dims and
               np.array_equal(a[name].values, b[name].values, equal_nan=a[name].dtype.kind == "f")
               for name in names)


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

# 1. __version__ is `sweetspot --version`'s version; results record it and its commit.
version_line = subprocess.run([program, "--version"], capture_output=True, text=True, check=True).stdout.strip()
version, commit = version_line.split()[-2], version_line.split()[-1].strip("()")
check(sweetspot.__version__ == version, f"__version__ {sweetspot.__version__!r} != {version_line!r}")

bat = sweetspot.Bat.load(BAT)
z = np.array([0.5, 0.6, 0.7, 0.8])
speeds = np.array([30.0, 40.0])
ds = sweetspot.impacts(bat, z=z, ball_speed=speeds[:, None], cm_speed=10, omega=40, ball="ncaa")
a = ds.attrs
check(a["Conventions"] == "CF-1.8" and a["program"] == "sweetspot", f"Conventions {a.get('Conventions')}")
check(a["program_version"] == version and a["git_commit"] == commit, f"version {a['program_version']} {a['git_commit']}")
check(a["source"] == f"sweetspot {version} ({commit})", a["source"])

# 2. The resolved scene: every input that sets the numbers, defaults filled in, no argument left out.
ncaa = sweetspot.ball("ncaa")
expected = {"scene_ball": "ncaa", "scene_cm_speed": 10.0, "scene_omega": 40.0, "scene_e0": ncaa["e0"],
            "scene_ball_mass": ncaa["mass"], "scene_ball_radius": ncaa["radius"], "scene_k1": ncaa["k1"],
            "scene_a": ncaa["a"], "scene_cor_slope": ncaa["cor_slope"], "scene_cor_speed": ncaa["cor_speed"],
            "scene_curved_contact": int(ncaa["curved_contact"]), "scene_pivot": 0, "scene_modes": "auto",
            "scene_mode_tolerance": 1e-4, "scene_accuracy": 0.0, "scene_integrator": "exact", "scene_dt": 1e-5,
            "scene_tolerance": 1e-9, "scene_window": 5e-3, "scene_theory": "timoshenko"}
for name, value in expected.items():
    check(name in a and a[name] == value, f"{name} = {a.get(name)!r}, expected {value!r}")
check("scene_z" not in a and "scene_ball_speed" not in a, "per-point arguments are coordinates, not attributes")
check("scene_center" not in a, "the swing given one way: no center")
units = dict(item.split(": ") for item in a["scene_units"].split("; "))
check(units.get("scene_dt") == "s" and units.get("scene_cm_speed") == "m/s" and units.get("scene_ball_mass") == "kg"
      and "scene_integrator" not in units, f"scene_units {a['scene_units']}")
check(a["bat"] == "R161" and a["bat_slices"] == 84, f"bat {a['bat']} {a['bat_slices']}")
check(a["bat_toml"] == pathlib.Path(BAT).read_text(), "bat_toml is the bat file's text")
check(a["bat_profile"] == (pathlib.Path(BAT).parent / "r161_profile.csv").read_text(), "bat_profile is the profile's text")
check(pathlib.Path(a["bat_file"]).resolve() == pathlib.Path(BAT).resolve(), a["bat_file"])
# netCDF has no booleans and no None: every attribute a string or a number.
for name, value in a.items():
    check(isinstance(value, (str, int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_)),
          f"attribute {name} of type {type(value)}")
check(ds.z.dims == ("z",) and ds.ball_speed.dims == ("ball_speed",), "coordinates as before")

# 3. to_netcdf, open_dataset, feed the scene back: the same numbers bit for bit, with the netCDF-3
# writer xarray picks by default here and with h5netcdf.
for engine in (None, "h5netcdf"):
    path = f"{work}/impacts_{engine}.nc"
    ds.to_netcdf(path, engine=engine)
    with xr.open_dataset(path, engine=engine) as back:
        back.load()
    again = sweetspot.impacts_like(back)
    check(same_numbers(again, ds), f"{engine}: impacts_like of the reopened dataset")
    check(np.array_equal(again.vf.values, back.vf.values), f"{engine}: vf bit for bit")
    explicit = sweetspot.impacts(sweetspot.bat_of(back), **sweetspot.scene_of(back))
    check(same_numbers(explicit, ds), f"{engine}: impacts(bat_of(ds), **scene_of(ds))")

# Other scenes: n2000 (RK4 at 5 us, 18 modes), pivoted about a centre, per-point e0 zipped with z
# (a `point` dimension), a dimension-made bat (its bat file written for it), accuracy given.
maple = sweetspot.Bat.from_dimensions("maple 271", 0.8382, knob_diameter=0.0505, knob_length=0.02,
                                      handle_diameter=0.0238125, taper_start=0.3048, taper_end=0.6604,
                                      barrel_diameter=0.0635, end="cupped", end_depth=0.0254, slices=60)
scenes = [(bat, dict(z=z, ball_speed=35, center=0.05, omega=52, pivot=True, n2000=True)),
          (bat, dict(z=z, e0=np.linspace(0.4, 0.55, 4), ball_speed=40, cm_speed=10, omega=40, modes=6)),
          (maple, dict(z=z, ball_speed=40, cm_speed=10, accuracy=1e-4, integrator="dopri"))]
for k, (which, kwargs) in enumerate(scenes):
    first = sweetspot.impacts(which, **kwargs)
    path = f"{work}/scene_{k}.nc"
    first.to_netcdf(path, engine="h5netcdf")
    with xr.open_dataset(path, engine="h5netcdf") as back:
        again = sweetspot.impacts_like(back.load())
    check(same_numbers(again, first), f"scene {k}: reproduced bit for bit")
    check(again.vf.dims == first.vf.dims, f"scene {k}: dims {again.vf.dims} {first.vf.dims}")
first = sweetspot.impacts(bat, z=z, ball_speed=35, center=0.05, omega=52, pivot=True, n2000=True)
check(first.attrs["scene_integrator"] == "rk4" and first.attrs["scene_dt"] == 5e-6 and first.attrs["scene_modes"] == 18
      and first.attrs["scene_pivot"] == 1 and first.attrs["scene_center"] == 0.05, "n2000 resolved")
check(sweetspot.bat_of(maple_ds := sweetspot.impacts(maple, z=0.7, ball_speed=40, cm_speed=10)).properties()
      == maple.properties() and maple_ds.attrs["bat_slices"] == 60, "a dimension-made bat rebuilt from its stored text")

# A replay on another bat is refused, naming what differs.
try:
    sweetspot.impacts_like(ds, sweetspot.Bat.load(f"{source}/studies/bats/torpedo.toml"))
    check(False, "impacts_like on another bat: no ValueError")
except ValueError as e:
    check("bat" in str(e), f"impacts_like on another bat: {e}")
# A stored result that lacks a scene attribute is refused, naming it: its value would be taken at
# the default (e0 0.5 for the stored 0.6), and the numbers would differ with no word said.
for lost in ("scene_e0", "scene_omega", "scene_integrator", "scene_modes"):
    tampered = ds.copy()
    del tampered.attrs[lost]
    try:
        sweetspot.impacts_like(tampered)
        check(False, f"impacts_like without {lost}: no ValueError")
    except ValueError as e:
        check(f"lacks {lost}" in str(e), f"impacts_like without {lost}: {e}")
rod = sweetspot.Bat.from_knots("rod", 0.84, [0, 0.84], [0.06, 0.06])
rod_ds = sweetspot.impacts(rod, z=0.7, ball_speed=40, cm_speed=10)
check("bat_toml" not in rod_ds.attrs and rod_ds.attrs["bat"] == "rod", "a knot bat stores its name, no text")
try:
    sweetspot.bat_of(rod_ds)
    check(False, "bat_of a knot bat: no ValueError")
except ValueError as e:
    check("path=" in str(e), str(e))

# 4. Bat.from_text: the bat file's bat, bit for bit; a missing profile text is refused.
text_bat = sweetspot.Bat.from_text(a["bat_toml"], a["bat_profile"])
check(text_bat.properties() == bat.properties() and np.array_equal(text_bat.outer_diameter, bat.outer_diameter),
      "Bat.from_text is Bat.load")
try:
    sweetspot.Bat.from_text(a["bat_toml"])
    check(False, "from_text without the profile: no ValueError")
except ValueError as e:
    check("profile" in str(e), str(e))

# 5. impact() and certify(): the program's keys, and attrs that compute them again.
one = sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=10, omega=40, ball="ncaa", modes="all")
check(isinstance(one, dict) and "attrs" not in one and one.attrs["scene_z"] == 0.7 and one.attrs["scene_modes"] == "all",
      "impact's attrs")
check(one.attrs["program_version"] == version and one.attrs["Conventions"] == "CF-1.8", "impact's provenance")
replay = sweetspot.impact(bat, **sweetspot.scene_of(one))
check(same_values(replay, one) and replay.attrs == one.attrs, "impact replayed")
rig = sweetspot.certify(bat, "bbcor")
check(rig.attrs["kind"] == "certification" and rig.attrs["scene_standard"] == "bbcor", f"certify's attrs {rig.attrs}")
check(rig.attrs["scene_pivot"] == rig["pivot"] and rig.attrs["scene_ball_speed"] == rig["ball_speed"]
      and rig.attrs["git_commit"] == commit and "scene_ball" not in rig.attrs, f"certify's attrs {rig.attrs}")
again = sweetspot.certify(bat, **sweetspot.scene_of(rig))
check(same_values(again, rig) and again.attrs == rig.attrs, "certify replayed")

# 6. Docstrings on every public function and class (Sphinx autodoc renders them).
for name in sweetspot.__all__:
    thing = getattr(sweetspot, name)
    if callable(thing):
        check(bool(inspect.getdoc(thing)) and len(inspect.getdoc(thing)) > 40, f"docstring of {name}")
for name in ("load", "from_text", "from_knots", "from_dimensions", "modes", "properties"):
    check(len(inspect.getdoc(getattr(sweetspot.Bat, name)) or "") > 40, f"docstring of Bat.{name}")
for name in ("impacts", "impact", "certify", "scene_of", "bat_of", "impacts_like", "run_study"):
    doc = inspect.getdoc(getattr(sweetspot, name))
    check("Returns" in doc or "Returns:" in doc, f"{name}'s docstring says what it returns")

finish("python provenance: all checks passed")
