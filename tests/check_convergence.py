#!/usr/bin/python3
"""Opens the dataset of `sweetspot convergence` with xarray (engine h5netcdf) as a user would and
checks its layout: dims (integrator x setting), the integrator labels, every variable with units
and long_name, NaN where a setting does not apply, the reference values as global attributes,
and that every integrator's finest setting agrees with the reference; and the accuracy sweep
(dim accuracy_run): each stated accuracy met, its estimate bounding the error against the
continuum.

Usage: /usr/bin/python3 tests/check_convergence.py OUT.h5 SETTINGS (the length of the setting
dimension). Prints "convergence ok" and exits 0 when all holds.
"""
import sys

import numpy as np
import xarray as xr

path, settings = sys.argv[1], int(sys.argv[2])
VARIABLES = {"step", "tolerance", "vf", "vf_error", "contact_time_error", "energy_error", "time_per_impact"}
SWEEP = {"accuracy", "accuracy_slices", "accuracy_modes", "accuracy_step", "slicing_error", "modes_error",
         "step_error", "total_error", "actual_error", "accuracy_time_per_impact"}

with xr.open_dataset(path, engine="h5netcdf") as ds:
    assert set(ds.sizes) == {"integrator", "setting", "accuracy_run"}, dict(ds.sizes)
    assert ds.sizes["integrator"] == 3 and ds.sizes["setting"] == settings, dict(ds.sizes)
    assert list(ds.integrator.values) == ["rk4", "exact", "dopri"], ds.integrator.values
    assert list(ds.setting.values) == list(range(settings)), ds.setting.values
    assert set(ds.data_vars) == VARIABLES | SWEEP, set(ds.data_vars)
    for name in VARIABLES | {"setting"}:
        assert ds[name].attrs["units"] and ds[name].attrs["long_name"], name
    # strings are no quantity: CF gives them no units
    assert "units" not in ds.integrator.attrs and ds.integrator.attrs["long_name"]
    assert ds.attrs["Conventions"] == "CF-1.8"
    for name in VARIABLES:
        assert ds[name].dims == ("integrator", "setting"), (name, ds[name].dims)
    assert ds.step.attrs["units"] == "s" and ds.time_per_impact.attrs["units"] == "s"
    # A step for rk4 and exact, a tolerance for dopri, never both.
    assert np.isnan(ds.step.sel(integrator="dopri")).all() and np.isnan(ds.tolerance.sel(integrator="rk4")).all()
    # NaN-padded where an integrator has fewer settings than the most.
    for method, setting in (("rk4", "step"), ("exact", "step"), ("dopri", "tolerance")):
        given = ds[setting].sel(integrator=method).dropna("setting")
        assert len(given) >= 2 and (given > 0).all(), (method, given.values)
        assert (np.diff(given.values) < 0).all(), (method, "coarsest first", given.values)
        finest = ds.vf_error.sel(integrator=method).dropna("setting")
        assert len(finest) == len(given) and float(finest[-1]) < 1e-8, (method, finest.values)
    assert (ds.time_per_impact.fillna(1) > 0).all()
    for key in ("reference_vf", "richardson_vf", "reference_disagreement", "study", "program_version", "git_commit"):
        assert key in ds.attrs, key
    assert ds.attrs["reference_disagreement"] < 1e-8, ds.attrs["reference_disagreement"]
    dopri_vf = ds.vf.sel(integrator="dopri").dropna("setting")
    assert abs(float(dopri_vf[-1]) / ds.attrs["reference_vf"] - 1) < 1e-8, (dopri_vf.values, ds.attrs["reference_vf"])
    # The sweep: the default settings first (no accuracy stated), then every accuracy met, each
    # estimate bounding the actual error against the continuum; the default's within 5x of it (a
    # stated accuracy's estimate counts the step's share, a quarter of it, for the step's error).
    sweep = ds[sorted(SWEEP)]
    assert np.isnan(sweep.accuracy[0]) and (sweep.accuracy[1:] > 0).all(), sweep.accuracy.values
    for name in SWEEP:
        assert ds[name].dims == ("accuracy_run",) and ds[name].attrs["long_name"], name
    stated = sweep.isel(accuracy_run=slice(1, None))
    assert (stated.total_error <= stated.accuracy).all(), (stated.total_error.values, stated.accuracy.values)
    assert (sweep.total_error >= sweep.actual_error).all(), (sweep.total_error.values, sweep.actual_error.values)
    default = sweep.isel(accuracy_run=0)
    assert default.total_error <= 5 * max(float(default.actual_error), 1e-7), float(default.total_error)
    assert (sweep.accuracy_slices[1:] >= 4 * sweep.accuracy_slices[0]).all(), sweep.accuracy_slices.values
    assert "continuum_vf" in ds.attrs
print("convergence ok")
