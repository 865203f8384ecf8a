#!/usr/bin/python3
"""Opens a dataset of `sweetspot run` with xarray (engine h5netcdf), as a user would, and checks
that it explains itself (README, "The dataset"): CF-1.8 attributes, integer axes with all/auto and
pivot as CF flags, the `frequency` dimension as long as the study keeps modes, no units on
strings, the bats' files byte for byte, the base scene as the run used it, the program's commit
with its -dirty mark as the source tree has it, and whether the run was resumed.

Usage: /usr/bin/python3 tests/check_provenance.py OUT.h5 SOURCE_DIR RESUMED BAT.toml...
  RESUMED: 0, or 1 for a run resumed from OUT.h5.journal.
  BAT.toml: the bat files of the study, in the order of its bat axis (their profiles beside them).
The study (tests/test_provenance.cpp) has the axes bat, slices = [20, 40],
modes = [0, 2, "all", "auto"], pivot = [false, true] and z; it sets e0 = 0.45, center = 0.09,
omega = 51 in [scene] and leaves the ball's mass, radius, k1 and a at N2000's values (the
defaults) and the theory Timoshenko. Prints "provenance ok" when all holds.
"""
import pathlib
import re
import subprocess
import sys

import numpy as np
import tomllib
import xarray as xr

path, source_dir, resumed = sys.argv[1], sys.argv[2], int(sys.argv[3])
bat_files = [pathlib.Path(p) for p in sys.argv[4:]]


def profile_path(bat_file):
    return bat_file.parent / tomllib.loads(bat_file.read_text())["profile"]


def profile_slices(bat_file):
    lines = profile_path(bat_file).read_text().splitlines()
    return len([line for line in lines if line.strip() and not line.startswith("#")]) - 1  # less the header


# With "all" among the modes, `mode` is as long as the bat with most modes has them: a Timoshenko
# beam of N slices has 2 N degrees of freedom, two of them rigid (at the profile's own slicing).
mode_count = max(2 * profile_slices(b) - 2 for b in bat_files)


def is_int(value):
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def expected_commit():
    """The commit of the source tree and its -dirty mark, as git sees it now."""
    try:
        commit = subprocess.run(["git", "-C", source_dir, "rev-parse", "--short", "HEAD"], capture_output=True,
                                text=True, check=True).stdout.strip()
        changes = subprocess.run(["git", "-C", source_dir, "status", "--porcelain", "--untracked-files=normal"],
                                 capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return None
    return commit + ("-dirty" if changes else "")


def check_conventions(ds):
    assert ds.attrs["Conventions"] == "CF-1.8", ds.attrs.get("Conventions")
    for name in ("title", "source", "references", "study", "program_version", "git_commit"):
        assert isinstance(ds.attrs[name], str), name
    # CF: names of letters, digits and underscores, starting with a letter
    for name in list(ds.variables) + list(ds.attrs):
        assert re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name), name
    for name, variable in ds.variables.items():
        assert variable.attrs.get("long_name"), name
        if variable.dtype.kind in "OUS":
            assert "units" not in variable.attrs, (name, variable.attrs)
        flags = variable.attrs.get("flag_values")
        if flags is not None:
            assert np.asarray(flags).dtype == variable.dtype, name  # CF: the variable's own type
            assert len(np.atleast_1d(flags)) == len(variable.attrs["flag_meanings"].split()), name


def check_axes(ds):
    for name in ("slices", "modes", "pivot", "mode"):
        assert ds[name].dtype == np.int32, (name, ds[name].dtype)
    assert list(ds.slices.values) == [20, 40], ds.slices.values
    modes = ds.modes
    meanings = dict(zip(np.atleast_1d(modes.attrs["flag_values"]).tolist(), modes.attrs["flag_meanings"].split()))
    assert [meanings.get(int(m), int(m)) for m in modes.values] == [0, 2, "all", "auto"], modes.values
    pivot = dict(zip(np.atleast_1d(ds.pivot.attrs["flag_values"]).tolist(), ds.pivot.attrs["flag_meanings"].split()))
    assert [pivot[int(p)] for p in ds.pivot.values] == ["free", "pivoted"], ds.pivot.values
    assert ds.frequency.dims == bat_dims(ds) + ("mode",), ds.frequency.dims
    assert ds.sizes["mode"] == mode_count, (ds.sizes["mode"], mode_count)
    assert list(ds.mode.values) == list(range(1, mode_count + 1))
    # every bat has at least as many modes as the dimension's first ones: no NaN in them
    assert np.isfinite(np.atleast_2d(ds.frequency.values)[:, :min(mode_count, 10)]).all()
    # the points that keep all modes, pivoted or not, are all computed
    assert (ds.status.sel(modes=-1) == 0).all()


def bat_dims(ds):
    """The dimensions of a per-bat-file variable: the bat axis, or none for a study of one bat."""
    return ("bat",) if "bat" in ds.dims else ()


def per_bat(ds, name):
    """A per-bat-file variable's values, one per bat file, after checking its dimensions."""
    assert ds[name].dims == bat_dims(ds), (name, ds[name].dims)
    return np.atleast_1d(ds[name].values)


def check_bats(ds):
    tomls, profiles = per_bat(ds, "bat_toml"), per_bat(ds, "bat_profile")
    files, profile_files, slices = per_bat(ds, "bat_file"), per_bat(ds, "bat_profile_file"), per_bat(ds, "bat_slices")
    assert len(tomls) == len(bat_files), (len(tomls), bat_files)
    for b, bat_file in enumerate(bat_files):
        toml_text = bat_file.read_bytes().decode()
        profile = profile_path(bat_file)
        assert tomls[b] == toml_text, b
        assert profiles[b] == profile.read_bytes().decode(), b
        assert pathlib.Path(files[b]).resolve() == bat_file.resolve(), files[b]
        assert pathlib.Path(profile_files[b]).resolve() == profile.resolve()
        assert int(slices[b]) == profile_slices(bat_file), slices[b]
        assert ds.bat_slices.dtype == np.int32


def check_scene(ds):
    a = ds.attrs
    given = {"scene_e0": 0.45, "scene_center": 0.09, "scene_omega": 51.0}
    n2000_ball = {"scene_ball_mass": 0.145, "scene_ball_radius": 0.0366, "scene_k1": 6.53e7, "scene_a": 1.84}
    for name, value in {**given, **n2000_ball}.items():
        assert a[name] == value, (name, a.get(name))
    assert a["scene_integrator"] in ("exact", "rk4", "dopri"), a["scene_integrator"]
    assert a["scene_theory"] in ("timoshenko", "euler-bernoulli")
    for name in ("scene_dt", "scene_tolerance", "scene_window", "scene_mode_tolerance", "scene_accuracy",
                 "scene_history_window", "scene_history_step"):
        assert isinstance(a[name], float) or a[name].dtype == np.float64, name
    # the swing is given by its centre: cm_speed has no value; axes are coordinates, not attributes
    for name in ("scene_cm_speed", "scene_modes", "scene_pivot", "scene_slices", "scene_z", "scene_bat"):
        assert name not in a, name
    assert is_int(a["mpi_ranks"]) and is_int(a["omp_threads"]) and a["mpi_ranks"] >= 1


def check_version(ds):
    commit = ds.attrs["git_commit"]
    assert re.fullmatch(r"([0-9a-f]{7,40}(-dirty)?|unknown)", commit), commit
    expected = expected_commit()
    if expected is not None:
        assert commit == expected, (commit, expected, "rebuild: the program is older than the tree")
    assert ds.attrs["source"] == f"sweetspot {ds.attrs['program_version']} ({commit})", ds.attrs["source"]


def check_resume(ds):
    a = ds.attrs
    assert is_int(a["resumed"]) and is_int(a["resumed_points"])
    assert a["resumed"] == resumed, a["resumed"]
    points = int(np.prod([ds.sizes[d] for d in ds.vf.dims]))
    if resumed:
        assert 0 < a["resumed_points"] < points, (a["resumed_points"], points)
        assert a["resumed_from"] == path + ".journal", a["resumed_from"]
    else:
        assert a["resumed_points"] == 0 and "resumed_from" not in a


with xr.open_dataset(path, engine="h5netcdf") as ds:
    check_conventions(ds)
    check_axes(ds)
    check_bats(ds)
    check_scene(ds)
    check_version(ds)
    check_resume(ds)
print("provenance ok")
