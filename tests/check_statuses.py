#!/usr/bin/python3
"""Checks a dataset's per-point statuses: the points whose coordinate AXIS is one of VALUES have
status STATUS (by its flag meaning) and NaN in every other output; every other point is ok with
finite values. With no AXIS, every point must be ok.

Usage: /usr/bin/python3 tests/check_statuses.py FILE [AXIS VALUES STATUS]   (VALUES: 13,17)
"""
import sys

import numpy as np
import xarray as xr

file = sys.argv[1]
with xr.open_dataset(file, engine="h5netcdf") as ds:
    status = ds.status
    assert status.dtype == np.int32, status.dtype
    meanings = status.attrs["flag_meanings"].split()
    flags = list(status.attrs["flag_values"])
    assert flags == list(range(len(meanings))), (flags, meanings)
    bad = xr.zeros_like(status, dtype=bool)
    expected = 0
    if len(sys.argv) > 2:
        axis, values, name = sys.argv[2], [float(v) for v in sys.argv[3].split(",")], sys.argv[4]
        bad = ds[axis].isin(values).broadcast_like(status)
        expected = meanings.index(name)
        assert int(bad.sum()) > 0, "no point on those values"
    assert (status.where(bad, expected) == expected).all(), status.values
    assert (status.where(~bad, 0) == 0).all(), status.values
    for name, v in ds.data_vars.items():
        if name == "status" or v.dims != status.dims or not np.issubdtype(v.dtype, np.floating):
            continue  # the per-point scalars: histories may end early, mode_energy has NaN past the kept modes
        assert bool(np.isnan(v.where(bad, np.nan)).all()), f"{name}: a failed point has a value"
        assert bool(np.isfinite(v.where(~bad, 0.0)).all()), f"{name}: an ok point has no value"
print("statuses as expected")
