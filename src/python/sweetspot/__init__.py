"""sweetspot: the ball-bat collision (A. M. Nathan, Am. J. Phys. 68, 979 (2000)) from Python.

    import sweetspot
    bat = sweetspot.Bat.load("studies/bats/r161.toml")
    r = sweetspot.impact(bat, z=0.7, ball_speed=40, cm_speed=10, omega=40)   # as `sweetspot impact --json`
    ds = sweetspot.impacts(bat, z=np.linspace(0.4, 0.84, 45), ball_speed=40, cm_speed=10, omega=40)

The physics is the C++ library's (the extension `_sweetspot`); this package gives the signatures,
numpy broadcasting and the xarray datasets. Bad input raises ValueError with the program's message.
"""
import os
import shutil
import subprocess
import tempfile
import warnings
from pathlib import Path

import numpy as np

from ._sweetspot import Bat, _ball, _certify, _describe, _impact, _impacts, _point_arguments, _si, _status_names

__all__ = ["Bat", "ball", "impact", "impacts", "run_study", "certify"]


def ball(name="n2000"):
    """The model's ball fitted to a preset (n2000, mlb, ncaa, softball_44_375, softball_47_525) or to
    the [ball] table of a TOML file: a dict of mass (kg), radius (m), k1 and a of the force law F =
    k1 u^a on a flat surface, e0 the flat-wall COR at cor_speed (m/s), cor_slope (per m/s),
    curved_contact, and the fit's residuals (README "Balls")."""
    return _ball(name)


def _from_knots(name, length, z, outer_diameter, inner_diameter=None, *, interpolation="linear", slices=None,
                material="maple", density=None, youngs_modulus=None, shear_modulus=None, shear_coefficient=None):
    """A bat from its diameters at knots (m from the knob), as a profile CSV with a z_m column gives
    them: interpolation "linear" (frustums), "pchip" or "stepped"; `material` a wood preset, any
    constant given beside it overriding the preset's; cut into `slices` (default about 1 cm each).
    length may be a string with a unit ("33 in"); the knot arrays are numbers in m."""
    length = _si("length", length, "length")
    inner = None if inner_diameter is None else [float(d) for d in np.ravel(inner_diameter)]
    return Bat._from_knots(name, float(length), [float(v) for v in np.ravel(z)],
                           [float(d) for d in np.ravel(outer_diameter)], inner, interpolation, slices, material,
                           dict(density=density, youngs_modulus=youngs_modulus, shear_modulus=shear_modulus,
                                shear_coefficient=shear_coefficient))


def _from_dimensions(name, length, *, knob_diameter, knob_length, handle_diameter, taper_start, taper_end,
                     barrel_diameter, end="flat", end_depth=0.0, wall_thickness=None, slices=None, material="maple",
                     density=None, youngs_modulus=None, shear_modulus=None, shear_coefficient=None):
    """A bat from the named dimensions of a bat file's [dimensions] (README, "Bat files"), m, each
    (and length) a number in m or a string with a unit ("2.625 in")."""
    length = _si("length", length, "length")
    dimensions = dict(knob_diameter=knob_diameter, knob_length=knob_length, handle_diameter=handle_diameter,
                      taper_start=taper_start, taper_end=taper_end, barrel_diameter=barrel_diameter,
                      end_depth=end_depth)
    if wall_thickness is not None:  # a hollow bat's wall; a solid bat has none (0 is refused)
        dimensions["wall_thickness"] = wall_thickness
    dimensions = {k: _si(k, v, "length") for k, v in dimensions.items()}
    return Bat._from_dimensions(name, float(length), {k: float(v) for k, v in dimensions.items()}, end, slices,
                                material, dict(density=density, youngs_modulus=youngs_modulus,
                                               shear_modulus=shear_modulus, shear_coefficient=shear_coefficient))


Bat.from_knots = staticmethod(_from_knots)
Bat.from_dimensions = staticmethod(_from_dimensions)


def certify(bat, standard="bbcor", *, ball=None, e0=None, ball_speed=None, pivot=None, modes="auto",
            theory="timoshenko"):
    """The bat in the virtual test rig of a standard ("bbcor", "besr" or "bpf"), as `sweetspot
    certify --json`: a dict with standard, z_max, e_a, the measure by its name, moi_pivot, mass,
    drop, barrel_diameter, checks (rule, value, limit, pass) and pass. e0, ball_speed (m/s, or a
    string such as "93 mph") and pivot (m from the knob, or "6 in") override the standard's rig; ball
    (a preset's name or a TOML file with a [ball] table) replaces the standard's ball, the preset
    "ncaa"."""
    return _certify(bat, standard, ball, e0, _si("ball_speed", ball_speed, "speed"), _si("pivot", pivot, "length"),
                    modes, theory)

_POINT = tuple(_point_arguments())  # z, ball_speed, cm_speed, center, omega, e0, ball_mass, ...


def _scene(z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a, pivot, modes,
           mode_tolerance, accuracy, integrator, dt, tolerance, window, theory, n2000, ball=None):
    # A length, mass or speed given as a string with a unit ("28 in", "136 mph") is SI from here on.
    z, ball_speed, cm_speed, center, omega, ball_mass, ball_radius = (
        _si(name, value) for name, value in (("z", z), ("ball_speed", ball_speed), ("cm_speed", cm_speed),
                                             ("center", center), ("omega", omega), ("ball_mass", ball_mass),
                                             ("ball_radius", ball_radius)))
    return dict(ball=ball, z=z, ball_speed=ball_speed, cm_speed=cm_speed, center=center, omega=omega, e0=e0,
                ball_mass=ball_mass, ball_radius=ball_radius, k1=k1, a=a, pivot=pivot, modes=modes,
                mode_tolerance=mode_tolerance, accuracy=accuracy, integrator=integrator, dt=dt,
                tolerance=tolerance, window=window, theory=theory, n2000=n2000)


def impact(bat, z, ball_speed, *, cm_speed=None, center=None, omega=0.0, ball=None, e0=None, ball_mass=None,
           ball_radius=None, k1=None, a=None, pivot=False, modes=None, mode_tolerance=None, accuracy=None,
           integrator=None, dt=None, tolerance=None, window=None, theory="timoshenko", n2000=False):
    """One ball on one bat, as `sweetspot impact --json`: a dict with the same keys (status, z, vf,
    e_eff, contact_time, collision_time, u_max, peak_force, impulse, bat_speed, e_a, bbcor, besr, bpf,
    energy, mode_energy, modes_kept, modes_error, contacts), NaN where the JSON has null.

    The swing is cm_speed (m/s) or center (m from the knob, the point at rest), with omega (rad/s).
    z, ball_speed, cm_speed, center, omega, ball_mass and ball_radius may be strings with a unit
    ("28 in", "136 mph", "480 rpm", "5.125 oz"); numbers are SI.
    `ball` names the ball (a preset's name or a TOML file with a [ball] table; default N2000's), and
    e0, ball_mass, ball_radius, k1 and a override its values.
    None means the program's default: e0 0.5, exact stepping at 10 us, modes "auto" (a count, "all"
    or "auto"); n2000=True takes RK4 at 5 us with 18 modes unless integrator, dt or modes are given.
    The bat's modes are solved once per needed set and kept on the bat."""
    result = _impact(bat, _scene(z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a,
                                 pivot, modes, mode_tolerance, accuracy, integrator, dt, tolerance, window,
                                 theory, n2000, ball))
    radius = _si("ball_radius", ball_radius) if ball_radius is not None else _ball(ball or "n2000")["radius"]
    if result["u_max"] > radius:
        warnings.warn(f"the ball compressed {1e3 * result['u_max']:.3g} mm, past its radius "
                      f"{1e3 * radius:.3g} mm: the force law is not meant for that", RuntimeWarning, stacklevel=2)
    return result


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
            ball_radius=None, k1=None, a=None, pivot=False, modes=None, mode_tolerance=None, accuracy=None,
            integrator=None, dt=None, tolerance=None, window=None, theory="timoshenko", n2000=False, threads=None):
    """Many impacts at once: z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1
    and a may be arrays, broadcast together as numpy does. Runs in C++ over OpenMP threads with the
    GIL released (`threads` of them, default OpenMP's: OMP_NUM_THREADS or every core), each needed set of modes solved once. Returns an xarray.Dataset with a study
    dataset's names, units and status flags: dims named after the array arguments when each is 1-D
    along its own axis (z=np.linspace(...), ball_speed=v[:, None] gives dims (ball_speed, z)), else
    one dim `point` with the arguments as coordinates over it."""
    import xarray as xr

    args = _scene(z, ball_speed, cm_speed, center, omega, e0, ball_mass, ball_radius, k1, a, pivot, modes,
                  mode_tolerance, accuracy, integrator, dt, tolerance, window, theory, n2000, ball)
    arrays = {k: np.asarray(v, dtype=float) for k, v in args.items()
              if k in _POINT and v is not None and np.ndim(v) > 0}
    scalars = {k: v for k, v in args.items() if k not in arrays}
    try:
        shape = np.broadcast_shapes(*(v.shape for v in arrays.values())) if arrays else ()
    except ValueError as e:
        raise ValueError(f"impacts: arguments that do not broadcast together: {e}") from None
    flat = {k: np.ascontiguousarray(np.broadcast_to(v, shape)).ravel() for k, v in arrays.items()}
    out = _impacts(bat, scalars, flat, 0 if threads is None else int(threads))

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
    attrs = {"bat": bat.name, "bat_slices": bat.slices}
    attrs |= {f"scene_{k}": (v if not isinstance(v, bool) else int(v)) for k, v in scalars.items()
              if v is not None and k not in _POINT}
    attrs |= {f"scene_{k}": float(v) for k, v in scalars.items() if v is not None and k in _POINT}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _program():
    here = Path(__file__).resolve().parent
    for candidate in (here.parent.parent / "sweetspot", Path(os.environ.get("SWEETSPOT_PROGRAM", ""))):
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return str(candidate)
    found = shutil.which("sweetspot")
    if not found:
        raise RuntimeError("run_study: the sweetspot program was not found (set SWEETSPOT_PROGRAM)")
    return found


def run_study(path, output=None):
    """Runs a study file with the program (`sweetspot run PATH -o OUTPUT --quiet`) and returns its
    dataset, read into memory. output None: a temporary file, removed afterwards."""
    import xarray as xr

    with tempfile.TemporaryDirectory() as scratch:
        out = output if output is not None else os.path.join(scratch, "study.h5")
        run = subprocess.run([_program(), "run", str(path), "-o", str(out), "--quiet"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            lines = (run.stderr or run.stdout).strip().splitlines()
            message = lines[-1] if lines else f"exit status {run.returncode}"
            raise ValueError(message.removeprefix("sweetspot: error: ").removeprefix("sweetspot: "))
        with xr.open_dataset(out, engine="h5netcdf") as ds:
            return ds.load()
