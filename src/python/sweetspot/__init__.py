"""sweetspot: the ball-bat collision (A. M. Nathan, Am. J. Phys. 68, 979 (2000)) from Python::

    import sweetspot
    bat = sweetspot.Bat.load("studies/bats/r161.toml")
    r = sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=10, omega=40)   # as `sweetspot impact --json`
    ds = sweetspot.impacts(bat, z=np.linspace(0.4, 0.84, 45), ball_speed=40, cm_speed=10, omega=40)

The physics is the C++ library's (the extension `_sweetspot`); this package gives the signatures,
numpy broadcasting and the xarray datasets. Bad input raises ValueError with the program's message.

Every result carries its provenance in `attrs` (a dataset's global attributes, or the `attrs` of the
dict impact() and certify() return): the resolved scene as `scene_*` (every input that determines
the numbers, defaults filled in, SI units as `scene_units` lists them), the bat (`bat`,
`bat_slices`, and its file's text `bat_toml` where known), `program_version`, `git_commit` and
`Conventions`, under the names a study dataset uses. `scene_of` and `bat_of` read them back, so
that a saved result can be computed again: `impacts_like(xr.open_dataset(path))`.
"""
import functools
import math
import os
import re
import shutil
import subprocess
import tempfile
import warnings
from collections.abc import Mapping
from pathlib import Path

import numpy as np

from ._sweetspot import (_LATER, Bat, __version__, _ball, _certify, _describe, _flight, _git_commit, _impact,
                         _impact_checked, _impacts, _installed_program, _max_slices, _max_threads, _min_slices,
                         _point_arguments, _scene_arguments, _scene_record, _si, _status_names)

__all__ = ["Bat", "Result", "ball", "impact", "impacts", "run_study", "certify", "flight", "scene_of", "bat_of",
           "impacts_like", "__version__"]

# ---- Arguments: every one checked here, so that a wrong type is a ValueError naming it (not
# pybind11's RuntimeError "Unable to cast" or TypeError "incompatible function arguments").

def _refuse(name, value, expected):
    shown = " ".join(repr(value).split())  # one line, an array's repr too
    raise ValueError(f"{name} {shown}: expected {expected}")


def _text(name, value, expected="a string", path=False):
    """A string (or, with path=True, a path-like object, as a string)."""
    if path and isinstance(value, os.PathLike):
        value = os.fspath(value)
    if not isinstance(value, str):
        _refuse(name, value, expected)
    return str(value)


def _whole(name, value, low, high, why=""):
    """A whole number from low to high (Python's or numpy's int; not a bool, a float or a string)."""
    if (isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer))
            or not low <= int(value) <= high):
        _refuse(name, value, f"a whole number from {low} to {high}{why}")
    return int(value)


def _real(name, value, dimension=None, arrays=False):
    """A real number as float (a string with its unit where the argument has a dimension, "28 in"),
    or with arrays=True also an array of real numbers as a float array. Complex numbers (their
    imaginary part would be lost), bools, other strings and objects are refused, and so are masked
    arrays (their masked values would be computed all the same)."""
    if value is None:
        return None
    if type(value) is float:  # the common cases, at once
        return value
    if type(value) is int and -2**53 <= value <= 2**53:  # exactly a float (bool is no int here)
        return float(value)
    expected = "a real number" + (" or an array of real numbers" if arrays else "")
    if isinstance(value, str):
        si = _si(name, value, dimension)  # ValueError naming the argument and the units if no quantity
        if isinstance(si, str):
            _refuse(name, value, expected)
        return float(si)
    if np.ma.isMaskedArray(value):
        _refuse(name, value, expected + " without a mask (its filled() or compressed() values)")
    try:
        array = np.asarray(value)
    except (TypeError, ValueError):  # ragged nested lists
        _refuse(name, value, expected)
    if array.dtype.kind == "O":  # Python ints beyond int64, or anything else
        if any(isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, float, np.integer, np.floating))
               for v in array.flat):
            _refuse(name, value, expected)
        try:
            array = array.astype(float)
        except OverflowError:  # an int past any float (10**400)
            _refuse(name, value, expected)
    if array.dtype.kind not in "iuf" or (array.ndim > 0 and not arrays):
        _refuse(name, value, expected)
    return float(array) if array.ndim == 0 else array.astype(float)


class Result(dict):
    """What impact() and certify() return: a dict with the keys of the program's --json, and
    `attrs`, a dict of the provenance an impacts() dataset carries as its attributes (the resolved
    scene as scene_*, the bat, program_version, git_commit, Conventions).

    impact()'s error estimates cost four to five times the impact: they are made when first read, by
    any way a dict's values are read (r[key], get, items, values, copies, dict(r), json, ==), and
    are the same values, bit for bit, whenever that is."""

    # impact() fills its Result in C++ and sets these: the provenance as a function that makes it
    # (when attrs is first read), and a function giving the values it stored as _LATER.
    _attrs = None
    _later = None

    def __init__(self, values, attrs):
        super().__init__(values)
        self._attrs = attrs  # the dict, or a function that makes it when first read

    def _complete(self):
        """The values made when first read, in their places (a key set or deleted since stays so)."""
        if self._later is not None:
            values = self._later()
            self._later = None
            for key, value in values.items():
                if dict.get(self, key) is _LATER:
                    dict.__setitem__(self, key, value)

    def __getitem__(self, key):
        value = dict.__getitem__(self, key)
        if value is _LATER:
            self._complete()
            value = dict.__getitem__(self, key)
        return value

    # Every other way of reading values completes them first. __iter__ is dict's own, but defined
    # here so that dict(r), {**r}, f(**r) and d.update(r) read through keys() and __getitem__
    # instead of the dict's storage.
    def __iter__(self):
        return dict.__iter__(self)

    def _completing(method):
        """dict's method, after completing this Result (and another one it is given)."""
        def read(self, *args, **kwargs):
            self._complete()
            for other in args:
                if isinstance(other, Result):
                    other._complete()
            return method(self, *args, **kwargs)
        read.__name__, read.__doc__ = method.__name__, method.__doc__
        return read

    get, items, values, copy = _completing(dict.get), _completing(dict.items), _completing(dict.values), _completing(dict.copy)
    pop, popitem, setdefault = _completing(dict.pop), _completing(dict.popitem), _completing(dict.setdefault)
    __repr__, __eq__, __ne__ = _completing(dict.__repr__), _completing(dict.__eq__), _completing(dict.__ne__)
    __or__, __ror__ = _completing(dict.__or__), _completing(dict.__ror__)
    del _completing

    def __reduce__(self):
        """Pickled (for a process pool, say) with its values made and its attrs read: the functions
        that make them when first read cannot be pickled."""
        return (Result, (dict(self.items()), self.attrs))

    @property
    def attrs(self):
        if callable(self._attrs):
            self._attrs = self._attrs()
        return self._attrs

    @attrs.setter
    def attrs(self, value):
        self._attrs = value


def _provenance(kind):
    """The global attributes a study dataset starts with (study_provenance.cpp), for a Python result."""
    return {"Conventions": "CF-1.8", "title": f"sweetspot.{'certify' if kind == 'certification' else 'impacts'}",
            "source": f"sweetspot {__version__} ({_git_commit})",
            "references": "A. M. Nathan, Am. J. Phys. 68, 979 (2000)", "kind": kind, "program": "sweetspot",
            "program_version": __version__, "git_commit": _git_commit}


@functools.lru_cache(maxsize=None)
def _units(name):
    """The units of an output or scene value of that name (fixed by the program)."""
    return _describe(name)[0]


def _with_units(scene):
    """`scene` and `scene_units`: each number's units as a dataset's variable of that name has them
    (netCDF attributes carry no attributes of their own)."""
    units = []
    for name, value in scene.items():
        unit = _units(name.removeprefix("scene_")) if not isinstance(value, str) else ""
        if name == "scene_pivot" and "scene_standard" in scene:
            unit = "m"  # the rig's pivot: a point, not the swing's flag
        if unit:
            units.append(f"{name}: {unit}")
    return scene | {"scene_units": "; ".join(units)}


def _record(bat, args, per_point=()):
    """The attributes of a result of impact() or impacts(): provenance, bat, resolved scene."""
    scene = _scene_record({k: v for k, v in args.items() if k not in per_point}, set(per_point))
    if args.get("ball") is not None:  # the ball's name gives what no argument does (its COR's speed law)
        scene = {"scene_ball": str(args["ball"])} | scene
    return _provenance("impact") | bat._source() | _with_units(scene)


def ball(name="n2000"):
    """The model's ball fitted to a preset or to the [ball] table of a TOML file (README "Balls").

    Parameters: name, a preset (n2000, mlb, ncaa, softball_44_375, softball_47_525) or a TOML file's path.
    Returns: a dict of mass (kg), radius (m), k1 (N m^-a) and a of the force law F = k1 u^a on a flat
    surface, e0 the flat-wall COR at cor_speed (m/s), cor_slope (per m/s), curved_contact, and the
    fit's stiffness_from, cor_residual and stiffness_residual."""
    return _ball(_text("name", name, "a ball preset's name or a TOML file's path", path=True))


def _knot_values(name, value):
    """One value per knot: a 1-D sequence of real numbers (not a 2-D array, which would be read
    flattened, nor a masked array, whose mask would be ignored, nor bools)."""
    if value is None:
        return None
    expected = "a 1-D array of real numbers, one per knot (m)"
    if np.ma.isMaskedArray(value) or (isinstance(value, (list, tuple)) and
                                      any(isinstance(x, (bool, np.bool_)) for x in value)):
        _refuse(name, value, expected)
    array = _real(name, value, arrays=True)
    if np.ndim(array) != 1:
        _refuse(name, value, expected)
    return [float(x) for x in array]


def _from_knots(name, length, z, outer_diameter, inner_diameter=None, *, interpolation="linear", slices=None,
                material="maple", density=None, youngs_modulus=None, shear_modulus=None, shear_coefficient=None):
    """A bat from its diameters at knots, as a profile CSV with a z_m column gives them.

    Parameters: name; length (m); z, the knots (m from the knob, increasing); outer_diameter and
    inner_diameter (m, one per knot; no inner for a solid bat); interpolation "linear" (frustums),
    "pchip" or "stepped"; slices (default about 1 cm each); material, a wood preset, with density
    (kg/m^3), youngs_modulus, shear_modulus (Pa) and shear_coefficient overriding the preset's.
    length may be a string with a unit ("33 in"); the knot arrays are numbers in m.
    Returns: a Bat. Its results store its name and slices but no bat file (it has none)."""
    knots = {k: _knot_values(k, v) for k, v in (("z", z), ("outer_diameter", outer_diameter),
                                                ("inner_diameter", inner_diameter))}
    return Bat._from_knots(_text("name", name), _real("length", length, "length"), knots["z"], knots["outer_diameter"],
                           knots["inner_diameter"], _text("interpolation", interpolation, '"linear", "pchip" or "stepped"'),
                           _slices(slices), _text("material", material, "a wood preset's name"),
                           _constants(density, youngs_modulus, shear_modulus, shear_coefficient))


def _slices(slices):
    return None if slices is None else _whole("slices", slices, _min_slices, _max_slices)


def _constants(density, youngs_modulus, shear_modulus, shear_coefficient):
    """The material's constants given beside its preset, checked as real numbers."""
    given = dict(density=density, youngs_modulus=youngs_modulus, shear_modulus=shear_modulus,
                 shear_coefficient=shear_coefficient)
    return {k: _real(k, v) for k, v in given.items()}


def _length(name, value, zero=False):
    """A dimension in m, refused as given ("-33 in", not its metres) unless positive (or 0 with
    zero=True) and finite."""
    metres = _real(name, value, "length")
    if not (math.isfinite(metres) and (metres >= 0 if zero else metres > 0)):
        _refuse(name, value, "a length >= 0" if zero else "a positive length")
    return metres


def _from_dimensions(name, length, *, knob_diameter, knob_length, handle_diameter, taper_start, taper_end,
                     barrel_diameter, end="flat", end_depth=0.0, wall_thickness=None, slices=None, material="maple",
                     density=None, youngs_modulus=None, shear_modulus=None, shear_coefficient=None):
    """A bat from the named dimensions of a bat file's [dimensions] (README, "Bat files").

    Parameters: name; length (m, or a string with a unit, "33 in", as every dimension); knob_diameter, knob_length, handle_diameter, taper_start,
    taper_end, barrel_diameter, end_depth and wall_thickness (m; no wall for a solid bat); end
    "flat", "rounded" or "cupped"; slices (default about 1 cm each); material, a wood preset, with
    density (kg/m^3), youngs_modulus, shear_modulus (Pa) and shear_coefficient overriding the preset's.
    Returns: a Bat, whose results store a bat file's text (bat_toml) that Bat.from_text reads back."""
    length = _length("length", length)
    dimensions = dict(knob_diameter=knob_diameter, knob_length=knob_length, handle_diameter=handle_diameter,
                      taper_start=taper_start, taper_end=taper_end, barrel_diameter=barrel_diameter)
    if wall_thickness is not None:  # a hollow bat's wall; a solid bat has none (0 is refused)
        dimensions["wall_thickness"] = wall_thickness
    dimensions = {k: _length(k, v) for k, v in dimensions.items()}
    dimensions["end_depth"] = _length("end_depth", end_depth, zero=True)
    return Bat._from_dimensions(_text("name", name), length, dimensions,
                                _text("end", end, '"flat", "rounded" or "cupped"'), _slices(slices),
                                _text("material", material, "a wood preset's name"),
                                _constants(density, youngs_modulus, shear_modulus, shear_coefficient))


def _from_text(toml, profile=None, *, slices=None, name="<text>"):
    """A bat from the text of its bat file and of the profile CSV the file names, as results store
    them (bat_toml, bat_profile): the same bat, bit for bit, as Bat.load of the files.

    Parameters: toml, the bat file's text; profile, the profile's text (None for a bat of
    [dimensions]); slices, as Bat.load's; name, what error messages call the text.
    Returns: a Bat. Raises ValueError as Bat.load does."""
    profile = "" if profile is None else _text("profile", profile, "the profile's text (a string) or None")
    return Bat._from_text(_text("toml", toml, "the bat file's text (a string)"), profile,
                          _text("name", name, "a string"), _slices(slices))


def _load(path, slices=None):
    """Load a bat from its TOML file or a shipped bat's name ("r161"; docs/bats.md).

    Parameters: path, the bat file or a shipped bat's name; slices, the number of slices to cut it into (default: its own).
    Returns: a Bat. Raises ValueError naming the file, key and value that are wrong."""
    expected = "a bat file's path or a shipped bat's name"
    text = _text("path", path, expected, path=True)
    if not text:  # as the command line's --bat "": no file's name at all
        _refuse("path", path, expected)
    return Bat._load(text, _slices(slices))


def _modes(self, count=None, theory="timoshenko"):
    """The bat's normal modes.

    Parameters: count, the lowest vibrational modes to solve (default: all); theory, "timoshenko" or
    "euler-bernoulli".
    Returns: a dict of theory, frequencies_hz (Hz), shapes (count x slices, largest ``|psi|`` = 1, + at the barrel
    end), z_m (slice centres, m), nodes_m (each mode's nodes, m from the knob), omega (rad/s, the two rigid
    modes first), mass_kg, z_cm_m and moment_of_inertia_cm_kg_m2."""
    return self._modes(None if count is None else _whole("count", count, 1, 2 * _max_slices),
                       _text("theory", theory, '"timoshenko" or "euler-bernoulli"'))


def _moment_of_inertia_about(self, z):
    """kg m^2 about the point z (m from the knob, or a string with a unit, "6 in")"""
    point = _real("z", z, "length")
    if not math.isfinite(point):
        _refuse("z", z, "a finite point (m from the knob)")
    return self._moment_of_inertia_about(point)


Bat.from_knots = staticmethod(_from_knots)
Bat.from_dimensions = staticmethod(_from_dimensions)
Bat.from_text = staticmethod(_from_text)
Bat.load = staticmethod(_load)
Bat.modes = _modes
Bat.moment_of_inertia_about = _moment_of_inertia_about


def certify(bat, standard="bbcor", *, ball=None, e0=None, ball_speed=None, pivot=None, modes="auto",
            theory="timoshenko", accuracy=None):
    """The bat in the virtual test rig of a standard, as `sweetspot certify --json`.

    Parameters: bat, a Bat; standard "bbcor", "besr" or "bpf"; e0, ball_speed (m/s, or a string such
    as "93 mph") and pivot (m from the knob, or "6 in") override the standard's rig; ball (a preset's name or a TOML file with a [ball]
    table) replaces the standard's ball, the preset "ncaa"; modes (a count, "all" or "auto") and
    theory ("timoshenko" or "euler-bernoulli") of the bat's modes; accuracy (1e-7 to 0.1), the total
    relative error the measure may carry: the bat is then cut at its slices, twice and four times
    them and finer until the estimate meets it.
    Returns: a Result, a dict with standard, z_max (m), e_a, the measure by its name, moi_pivot
    (kg m^2), mass (kg), drop, barrel_diameter (m), checks (rule, value, limit, pass) and pass (with
    an accuracy also slices_used, slicing_error, modes_error, step_error, total_error, accurate), and
    `attrs`: the rig as run (scene_standard, scene_e0, scene_ball_speed, scene_pivot, scene_modes,
    scene_theory; scene_ball when given), the bat and the program's version and commit, so that
    ``certify(bat, **scene_of(result))`` certifies again the same way."""
    _check_bat(bat)
    ball = None if ball is None else _text("ball", ball, "a ball preset's name or a TOML file's path", path=True)
    result = _certify(bat, _text("standard", standard, '"bbcor", "besr" or "bpf"'), ball, _real("e0", e0),
                      _real("ball_speed", ball_speed, "speed"), _real("pivot", pivot, "length"), modes,
                      _text("theory", theory, '"timoshenko" or "euler-bernoulli"'), _real("accuracy", accuracy))
    scene = {"scene_standard": result["standard"]} | ({"scene_ball": str(ball)} if ball is not None else {})
    scene |= {"scene_accuracy": result["accuracy"]} if accuracy is not None else {}
    scene |= {"scene_e0": result["e0"], "scene_ball_speed": result["ball_speed"], "scene_pivot": result["pivot"],
              "scene_modes": modes if isinstance(modes, str) else int(modes), "scene_theory": theory}
    return Result(result, _provenance("certification") | bat._source() | _with_units(scene))

def _degrees(name, value):
    # An angle: a plain number in deg, or a string with its unit ("0.48 rad", "27.5 deg").
    # (rad / (pi / 180): the program's conversion, so that both give the same bits.)
    if value is None:
        _refuse(name, value, "a real number (deg)")
    return _real(name, value, "angle") / (math.pi / 180) if isinstance(value, str) else _real(name, value)


def flight(speed, angle=0.0, *, direction=0.0, backspin=0.0, sidespin=0.0, height="3 ft", temperature="70 F",
           pressure="29.92 inHg", altitude=0.0, humidity=50.0, wind_speed=0.0, wind_direction=0.0,
           spin_decay_time=1e4, vacuum=False, samples=0.0):
    """The batted ball's flight through the air, as `sweetspot flight --json` (docs/flight.md).

    Parameters (numbers in SI, or strings with a unit such as "103 mph", "2500 rpm", "70 F"):
    speed (m/s); angle above the horizontal and direction from centre field toward right field
    (plain numbers in deg); backspin and sidespin (rad/s; positive sidespin curves toward left
    field); height of the launch (m); temperature (K), pressure reduced to sea level (Pa),
    altitude of the field (m), humidity (%), wind_speed (m/s), wind_direction (deg, the direction
    the wind blows toward: 0 out to centre field, 180 in); spin_decay_time (s at 100 mph);
    vacuum=True for no air; samples > 0 records the trajectory every that many seconds.
    Returns: a dict with distance, apex (m), apex_time, hang_time (s), landing_angle (deg below the
    horizontal), landing_speed (m/s), landing_spin (rad/s), bearing (deg), landing_x, landing_y (m), air_density (kg/m^3)
    and, with samples, trajectory: numpy arrays t, x, y, z, vx, vy, vz."""
    if not isinstance(vacuum, (bool, np.bool_)):
        _refuse("vacuum", vacuum, "True or False")
    if isinstance(humidity, str):  # "50" or "50%", as on the command line
        number = re.fullmatch(r"([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?) *%?", humidity)
        if not number:
            _refuse("humidity", humidity, "a relative humidity in % (a number from 0 to 100, or such as \"50%\")")
        humidity = float(number.group(1))
    args = {name: _real(name, value, dimension) for name, value, dimension in (
        ("speed", speed, "speed"), ("backspin", backspin, "angular speed"), ("sidespin", sidespin, "angular speed"),
        ("height", height, "length"), ("temperature", temperature, "temperature"), ("pressure", pressure, "pressure"),
        ("altitude", altitude, "length"), ("humidity", humidity, None), ("wind_speed", wind_speed, "speed"),
        ("spin_decay_time", spin_decay_time, None), ("samples", samples, None))}
    for name, value in args.items():
        if value is None:
            _refuse(name, value, "a real number")
    return _flight(angle=_degrees("angle", angle), direction=_degrees("direction", direction),
                   wind_direction=_degrees("wind_direction", wind_direction), vacuum=bool(vacuum), **args)


_POINT = tuple(_point_arguments())  # z, ball_speed, cm_speed, center, omega, e0, ball_mass, ...
assert _scene_arguments() == [*_POINT, "ball", "pivot", "modes", "mode_tolerance", "accuracy", "step_accuracy",
                              "integrator", "dt", "tolerance", "window", "theory", "n2000"]  # impact()'s order


def _scene(z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a, pivot, modes,
           mode_tolerance, accuracy, step_accuracy, integrator, dt, tolerance, window, theory, n2000, ball=None, arrays=False,
           oblique=None):
    # Each point argument a real number (impacts: or an array of them); a length, mass or speed
    # given as a string with a unit ("28 in", "136 mph") is SI from here on.
    point = {name: _real(name, value, arrays=arrays)
             for name, value in (("z", z), ("ball_speed", ball_speed), ("cm_speed", cm_speed), ("center", center),
                                 ("omega", omega), ("e0", e0), ("ball_mass", ball_mass), ("ball_radius", ball_radius),
                                 ("k1", k1), ("a", a), *(oblique or {}).items())}
    numbers = {name: _real(name, value) for name, value in (("mode_tolerance", mode_tolerance), ("accuracy", accuracy),
                                                            ("step_accuracy", step_accuracy), ("dt", dt), ("tolerance", tolerance), ("window", window))}
    if ball is not None:
        ball = _text("ball", ball, "a ball preset's name or a TOML file with a [ball] table", path=True)
    return dict(ball=ball, **point, pivot=pivot, modes=modes, **numbers, integrator=integrator, theory=theory,
                n2000=n2000)


def _check_bat(bat):
    if not isinstance(bat, Bat):
        _refuse("bat", bat, "a sweetspot.Bat (Bat.load, Bat.from_knots, Bat.from_dimensions or Bat.from_text)")


def impact(bat, z, ball_speed, *, cm_speed=None, center=None, omega=0.0, ball=None, e0=None, ball_mass=None,
           ball_radius=None, k1=None, a=None, pivot=False, modes=None, mode_tolerance=None, accuracy=None, step_accuracy=None,
           integrator=None, dt=None, tolerance=None, window=None, theory="timoshenko", n2000=False,
           undercut=None, swing_tilt=None, pitch_spin=None, friction=None):
    """One ball on one bat, as `sweetspot impact --json`: a dict with the same keys (status, z, vf,
    e_eff, contact_time, collision_time, u_max, peak_force, impulse, bat_speed, e_a, bbcor, besr, bpf,
    energy, mode_energy, modes_kept, modes_error, slicing_error, step_error, total_error, contacts),
    NaN where the JSON has null. slicing_error, modes_error and step_error estimate each source of
    the relative vf error against the continuous bat (its slices, the dropped modes, the time step),
    total_error their sum. Without a stated accuracy they are made when first read (the same values):
    they cost the impact again at twice and four times the step and on the bat at twice and four
    times its slices, four to five times the impact itself. accuracy (the
    total relative vf error, 1e-7 to 0.1) chooses the slices, the modes and the step to meet it
    (slices_used, modes_kept, step_used say what it chose; status "inaccurate" where the bat
    cannot be cut finely enough); step_accuracy chooses the step alone.

    The swing is cm_speed (m/s) or center (m from the knob, the point at rest), with omega (rad/s).
    An oblique impact (docs/oblique.md): undercut (m, the ball's centre above the bat's axis),
    swing_tilt (degrees above the horizontal), pitch_spin (rpm, the pitch's backspin), friction
    (>= 0); the result then gives launch_angle (degrees), backspin and sidespin (rpm) beside vf.
    z, ball_speed, cm_speed, center, omega, ball_mass and ball_radius may be strings with a unit
    ("28 in", "136 mph", "480 rpm", "5.125 oz"); numbers are SI.
    `ball` names the ball (a preset's name or a TOML file with a [ball] table; default N2000's), and
    e0, ball_mass, ball_radius, k1 and a override its values.
    None means the program's default: e0 0.5, exact stepping at 10 us, modes "auto" (a count, "all"
    or "auto") at mode_tolerance 1e-4; n2000=True takes RK4 at 5 us with 18 modes unless integrator, dt or
    modes are given.
    The bat's modes are solved once per needed set and kept on the bat.

    Returns: a Result, the dict above with `attrs` (the resolved scene as scene_*, the bat, the
    program's version and commit); ``impact(bat, **scene_of(result))`` computes it again bit for bit."""
    # As given, in the order of _scene_arguments: plain numbers are read in C++ at once, anything
    # else (a unit, a numpy number, a path) checked and converted by _impact_scene first.
    given = (z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a, undercut, swing_tilt,
             pitch_spin, friction, ball, pivot, modes, mode_tolerance, accuracy, step_accuracy, integrator, dt,
             tolerance, window, theory, n2000)
    called = _impact(bat, given, Result) if isinstance(bat, Bat) else None
    if called is None:
        args = _impact_scene(given)
        _check_bat(bat)
        called = _impact_checked(bat, args, Result)
    result, u_max, radius = called
    if u_max > radius:
        warnings.warn(f"the ball compressed {1e3 * u_max:.3g} mm, past its radius "
                      f"{1e3 * radius:.3g} mm: the force law is not meant for that", RuntimeWarning, stacklevel=2)
    # The provenance costs more than the impact, the error estimates (result._later, without a
    # stated accuracy) four to five times it: each made when first read.
    result._attrs = lambda: _impact_record(bat, given)  # a closure, which copy.deepcopy leaves as it is
    return result


def _impact_scene(given):
    """impact()'s arguments (as it passes them to _impact) checked, as _scene gives them."""
    (z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a, undercut, swing_tilt, pitch_spin,
     friction, ball, pivot, modes, mode_tolerance, accuracy, step_accuracy, integrator, dt, tolerance, window, theory,
     n2000) = given
    return _scene(z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a, pivot, modes,
                  mode_tolerance, accuracy, step_accuracy, integrator, dt, tolerance, window, theory, n2000, ball,
                  oblique=dict(undercut=undercut, swing_tilt=swing_tilt, pitch_spin=pitch_spin, friction=friction))


def _impact_record(bat, given):
    return _record(bat, _impact_scene(given))


def _attrs(name):
    units, long_name = _describe(name)
    return ({"units": units} if units else {}) | {"long_name": long_name}


def _dims(arrays, shape):
    """Each array argument's own axis when every one is 1-D along a distinct axis, else None."""
    owner = {}
    for name, value in arrays.items():
        padded = (1,) * (len(shape) - value.ndim) + value.shape
        varying = [k for k, n in enumerate(padded) if n != 1]
        if len(varying) > 1:
            return None
        axis = varying[0] if varying else len(shape) - 1
        if axis in owner:
            return None
        owner[axis] = name
    return [owner[k] for k in range(len(shape))] if len(owner) == len(shape) else None


def impacts(bat, z, ball_speed, *, cm_speed=None, center=None, omega=0.0, ball=None, e0=None, ball_mass=None,
            ball_radius=None, k1=None, a=None, pivot=False, modes=None, mode_tolerance=None, accuracy=None, step_accuracy=None,
            integrator=None, dt=None, tolerance=None, window=None, theory="timoshenko", n2000=False, threads=None,
            undercut=None, swing_tilt=None, pitch_spin=None, friction=None):
    """Many impacts at once: z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1,
    a, undercut, swing_tilt, pitch_spin and friction may be arrays, broadcast together as numpy does. Runs in C++ over OpenMP threads with the
    GIL released (`threads` of them, 1 to 4 per processor; default OpenMP's: OMP_NUM_THREADS or every core), each needed set of modes solved once. Returns an xarray.Dataset with a study
    dataset's names, units and status flags: dims named after the array arguments when each is 1-D
    along its own axis (z=np.linspace(...), ball_speed=v[:, None] gives dims (ball_speed, z)), else
    one dim `point` with the arguments as coordinates over it.

    Units: z, center (m from the knob), ball_speed, cm_speed (m/s), omega (rad/s), ball_mass (kg),
    ball_radius (m), k1 (N m^-a), dt, window (s); e0, a, mode_tolerance, accuracy, step_accuracy,
    tolerance are ratios. accuracy (the total relative vf error, 1e-7 to 0.1) chooses the slices,
    the modes and the step: it excludes dt, tolerance, mode_tolerance and step_accuracy; step_accuracy
    chooses the step alone: it excludes dt and tolerance.
    Returns: an xarray.Dataset whose attributes record the resolved scene (scene_*, with
    scene_units), the bat (bat, bat_slices, bat_toml where known), program_version, git_commit and
    Conventions: impacts_like(ds) computes it again bit for bit, after ds.to_netcdf() and
    xarray.open_dataset too."""
    import xarray as xr

    args = _scene(z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a, pivot, modes,
                  mode_tolerance, accuracy, step_accuracy, integrator, dt, tolerance, window, theory, n2000, ball, arrays=True,
                  oblique=dict(undercut=undercut, swing_tilt=swing_tilt, pitch_spin=pitch_spin, friction=friction))
    _check_bat(bat)
    threads = 0 if threads is None else _whole("threads", threads, 1, _max_threads(),
                                                      " (4 per processor; more only contend for the same cores)")  # 0: OpenMP's default
    arrays = {k: v for k, v in args.items() if k in _POINT and isinstance(v, np.ndarray)}
    scalars = {k: v for k, v in args.items() if k not in arrays}
    try:
        shape = np.broadcast_shapes(*(v.shape for v in arrays.values())) if arrays else ()
    except ValueError as e:
        raise ValueError(f"impacts: arguments that do not broadcast together: {e}") from None
    flat = {k: np.ascontiguousarray(np.broadcast_to(v, shape)).ravel() for k, v in arrays.items()}
    out = _impacts(bat, scalars, flat, threads)

    dims = _dims(arrays, shape)
    if dims is not None:
        coords = {k: (k, arrays[k].ravel(), _attrs(k))
                  for k in dims}
        data_shape, data_dims = shape, tuple(dims)
    else:
        coords = {k: ("point", v, _attrs(k)) for k, v in flat.items()}
        data_shape, data_dims = (int(np.prod(shape)),), ("point",)
    data = {}
    for name, values in out.items():
        attrs = _attrs(name)
        if name == "status":
            names = _status_names()
            attrs |= {"flag_values": np.arange(len(names), dtype=np.int32), "flag_meanings": " ".join(names)}
        data[name] = (data_dims, values.reshape(data_shape), attrs)
    return xr.Dataset(data, coords=coords, attrs=_record(bat, args, per_point=list(arrays)))


# Attributes that record the scene but are no argument: the ball's name (scene_ball) sets them.
_RECORD_ONLY = {"cor_slope", "cor_speed", "curved_contact"}


def _attrs_of(result):
    """The attributes of a dataset, a Result or a dict of attributes."""
    attrs = result.attrs if hasattr(result, "attrs") else result
    if not isinstance(attrs, Mapping):
        _refuse("result", result, "what impacts(), impact() or certify() returned, their dataset, or its attributes")
    return dict(attrs)


def scene_of(result):
    """The keyword arguments that compute a stored result again.

    Parameters: result, what impacts(), impact() or certify() returned, or that dataset read back
    with xarray.open_dataset after to_netcdf(), or its attributes as a dict.
    Returns: a dict of keyword arguments, for ``impacts(bat, **...)`` (the per-point arguments as
    arrays shaped as the dataset's dimensions), ``impact(bat, **...)`` or ``certify(bat, **...)`` (kind
    "certification"). Every value is the resolved one, so the defaults of a later version do not
    change what is computed."""
    attrs = _attrs_of(result)
    if not any(str(name).startswith("scene_") for name in attrs):  # nothing to compute again from
        raise ValueError(f"result (a {type(result).__name__} without scene_* attributes): expected what impacts(), "
                         "impact() or certify() returned, their dataset, or its attributes")
    certification = attrs.get("kind") == "certification"
    kwargs = {}
    for name, value in attrs.items():
        key = name.removeprefix("scene_")
        if key == name or key == "units" or key in _RECORD_ONLY:
            continue
        if isinstance(value, (str, bytes)):
            kwargs[key] = value.decode() if isinstance(value, bytes) else value
        elif key == "modes":
            kwargs[key] = int(value)  # a count (netCDF gives numpy integers back)
        elif key == "pivot" and not certification:  # the swing's flag; the rig's pivot is a point (m)
            if value not in (0, 1):
                _refuse(name, value, "0 or 1 (the swing held at its centre or not)")
            kwargs[key] = bool(value)
        else:
            kwargs[key] = float(value)
    # An accuracy of 0 records none stated. A stated one chose what it excludes: the step (scene_dt,
    # scene_tolerance) and, the total accuracy, the modes' tolerance.
    for key in ("accuracy", "step_accuracy"):
        if kwargs.get(key) == 0:
            del kwargs[key]
    if "accuracy" in kwargs or "step_accuracy" in kwargs:
        kwargs.pop("dt", None)
        kwargs.pop("tolerance", None)
    if "accuracy" in kwargs:
        kwargs.pop("mode_tolerance", None)
    # What the scene's integrator or modes do not read is no argument (impact() refuses it).
    if kwargs.get("integrator") != "dopri":
        kwargs.pop("tolerance", None)
    if kwargs.get("modes", "auto") != "auto":
        kwargs.pop("mode_tolerance", None)
    if hasattr(result, "dims") and "status" in result:  # a dataset: its per-point arguments
        dims = result["status"].dims
        for key in _POINT:
            if key in result.coords and key not in kwargs:
                values = np.asarray(result[key].values, dtype=float)
                (dim,) = result[key].dims
                if dim == "point":
                    kwargs[key] = values
                else:  # along its own axis of the dataset, as impacts broadcast it
                    shape = [1] * len(dims)
                    shape[dims.index(dim)] = values.size
                    kwargs[key] = values.reshape(shape)
    return kwargs


def bat_of(result, *, path=None):
    """The bat a stored result was computed on, rebuilt from its attributes.

    Parameters: result, as scene_of takes it; path, a bat file to load instead when the result
    stores no bat file's text (a bat made with Bat.from_knots).
    Returns: a Bat with the stored slices: from the stored text (bat_toml, with bat_profile) if
    there is one, else from `path`. Raises ValueError when neither is there."""
    attrs = _attrs_of(result)
    slices = _whole("bat_slices", attrs["bat_slices"], _min_slices, _max_slices) if "bat_slices" in attrs else None
    if "bat_toml" in attrs:
        return Bat.from_text(attrs["bat_toml"], attrs.get("bat_profile"), slices=slices,
                             name=str(attrs.get("bat_file", "bat_toml")))
    if path is not None:
        return Bat.load(path, slices=slices)
    if "study" in attrs:  # a study's dataset keeps its study, not one bat's scene
        raise ValueError("result: a dataset of `sweetspot run` (its study is attrs['study']): expected what impacts() "
                         "returned; run a study again with sweetspot.run_study")
    raise ValueError(f"bat {attrs.get('bat', '?')!r}: the result stores no bat file's text (a bat made from knots); "
                     "expected path=, the bat's file")


def impacts_like(result, bat=None, *, threads=None):
    """Computes a stored impacts() result again: ``impacts(bat, **scene_of(result))``.

    Parameters: result, an impacts() dataset (or one read back with xarray.open_dataset); bat,
    the Bat (default: bat_of(result), rebuilt from the stored bat file's text); threads as impacts'.
    Returns: the new dataset, bit for bit the stored one's numbers when the program and bat are the
    same. Raises ValueError when the new run's resolved scene or bat differs from the stored one
    (a ball file changed since, another bat), naming the attributes that differ."""
    if bat is None:
        bat = bat_of(result)
    again = impacts(bat, threads=threads, **scene_of(result))
    stored = _attrs_of(result)
    recorded = [k for k in again.attrs
                if k.startswith("scene_") or k in ("bat", "bat_slices", "bat_toml", "bat_profile")]
    # An attribute the stored result lacks was computed at its default, which may not be what it
    # was computed at (scene_e0 deleted: v_f 4.5 m/s off, and no word said).
    missing = [k for k in recorded if k not in stored]
    if missing:
        raise ValueError("impacts_like: the stored result lacks " + ", ".join(missing) +
                         ": expected every attribute impacts() records, to compute the same scene")
    differ = [k for k in recorded if not _same_attribute(stored[k], again.attrs[k])]
    if differ:
        raise ValueError("impacts_like: not the stored scene: " +
                         ", ".join(f"{k} = {again.attrs[k]!r}, stored {stored[k]!r}" for k in differ))
    return again


def _same_attribute(a, b):
    """Attributes equal as netCDF gives them back (numpy scalars for numbers)."""
    if isinstance(a, (str, bytes)) or isinstance(b, (str, bytes)):
        return str(a) == str(b)
    return bool(np.array_equal(np.asarray(a), np.asarray(b)))


def _program():
    """The program run_study runs: SWEETSPOT_PROGRAM when set, else the one built or installed with
    this module (the build tree's, or the prefix's bin), else the first on PATH."""
    named = os.environ.get("SWEETSPOT_PROGRAM")
    if named:
        if Path(named).is_file() and os.access(named, os.X_OK):
            return named
        raise RuntimeError(f"run_study: SWEETSPOT_PROGRAM={named!r}: not an executable file")
    here = Path(__file__).resolve().parent
    for candidate in (here.parent.parent / "sweetspot", here / _installed_program):
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return str(candidate.resolve())
    found = shutil.which("sweetspot")
    if not found:
        raise RuntimeError("run_study: the sweetspot program was not found (set SWEETSPOT_PROGRAM)")
    return found


def run_study(path, output=None):
    """Runs a study file with the program (`sweetspot run PATH -o OUTPUT --quiet`).

    Parameters: path, the study file; output, where the dataset is written (None: a temporary
    file, removed afterwards).
    Returns: the study's dataset (xarray.Dataset, read into memory), with the program's provenance.
    Raises ValueError with the program's message when it refuses the study."""
    import xarray as xr

    path = _text("path", path, "a study file's path", path=True)
    output = None if output is None else _text("output", output, "a dataset's path (or None)", path=True)
    with tempfile.TemporaryDirectory() as scratch:
        out = output if output is not None else os.path.join(scratch, "study.h5")
        # "--" ends the options: a study whose name starts with "-" is a file, not an option.
        run = subprocess.run([_program(), "run", "-o", out, "--quiet", "--", path], capture_output=True, text=True)
        if run.returncode != 0:
            lines = (run.stderr or run.stdout).strip().splitlines()
            message = lines[-1] if lines else f"exit status {run.returncode}"
            raise ValueError(message.removeprefix("sweetspot: error: ").removeprefix("sweetspot: "))
        with xr.open_dataset(out, engine="h5netcdf") as ds:
            return ds.load()
