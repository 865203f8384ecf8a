#!/usr/bin/python3
"""Reads the dataset tests/test_dataset.cpp writes, as users will: with xarray (engine h5netcdf),
with h5netcdf itself and with h5py, all as they are, and checks every part of it.

Usage: /usr/bin/python3 tests/check_dataset.py FILE. Prints "dataset ok" and exits 0 when all holds.
The values are those of the test: vf = 100 bat + 10 z + speed + 0.5 and status = (vf - 0.5) % 3
(by index), frequency = 100 (bat + 1) + mode.
"""
import sys

import h5netcdf
import h5py
import numpy as np
import xarray as xr

BATS = ["R161", "torpedo"]
Z = [0.1, 0.2, 0.3, 0.4, 0.5]
SPEEDS = [30.0, 40.0, 50.0]
MODES = [1, 2, 3, 4]
BAT_TEXTS = ['name = "R161"\n', "ω = 1\n"]
SAMPLES = [(0, 0, 0), (0, 4, 2), (1, 2, 1), (1, 4, 0), (0, 1, 2)]  # (bat, z, speed) indices


def vf(b, z, s):
    return 100 * b + 10 * z + s + 0.5


def check_xarray(path):
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert ds.vf.dims == ("bat", "z", "ball_speed"), ds.vf.dims
        assert ds.status.dims == ("bat", "z", "ball_speed"), ds.status.dims
        assert ds.frequency.dims == ("bat", "mode"), ds.frequency.dims
        assert dict(ds.sizes) == {"bat": 2, "z": 5, "ball_speed": 3, "mode": 4}, dict(ds.sizes)
        assert ds.mode.dtype == np.int32, ds.mode.dtype
        assert ds.mode.attrs["flag_meanings"] == "all" and ds.mode.attrs["flag_values"] == -1
        assert ds.bat_text.dims == ("bat",) and list(ds.bat_text.values) == BAT_TEXTS, ds.bat_text.values
        assert list(ds.bat.values) == BATS, ds.bat.values
        assert all(type(b) is str for b in ds.bat.values), ds.bat.values
        np.testing.assert_array_equal(ds.z.values, Z)
        np.testing.assert_array_equal(ds.ball_speed.values, SPEEDS)
        np.testing.assert_array_equal(ds.mode.values, MODES)
        for b, z, s in SAMPLES:
            assert ds.vf.values[b, z, s] == vf(b, z, s), (b, z, s)
            assert ds.status.values[b, z, s] == (vf(b, z, s) - 0.5) % 3, (b, z, s)
        # label and value selection go through the coordinates
        assert float(ds.vf.sel(bat="torpedo", z=0.3, ball_speed=40.0)) == vf(1, 2, 1)
        assert float(ds.frequency.sel(bat="R161", mode=3)) == 100 + 3
        assert ds.status.dtype == np.int32, ds.status.dtype
        np.testing.assert_array_equal(ds.status.attrs["flag_values"], [0, 1, 2])
        assert ds.status.attrs["flag_meanings"] == "ok max_steps no_contact"
        for name, units, long_name in [
            ("vf", "m/s", "ball exit speed"),
            ("status", "1", "integration status"),
            ("frequency", "Hz", "natural frequency ω/2π"),
            ("z", "m", "impact location from the knob"),
            ("ball_speed", "m/s", "ball speed before impact"),
            ("mode", "1", "mode number"),
        ]:
            attrs = ds[name].attrs
            assert attrs["units"] == units, (name, attrs)
            assert attrs["long_name"] == long_name, (name, attrs)
        for name in ("bat", "bat_text"):  # strings have no units
            assert "units" not in ds[name].attrs and ds[name].attrs["long_name"], ds[name].attrs
        assert ds.attrs["title"] == "dataset test", ds.attrs
        assert ds.attrs["study"] == 'name = "test"\n[axes]\nz = [0.1, 0.5]\n', ds.attrs
        assert ds.attrs["wall_time_s"] == 1.25, ds.attrs
        assert ds.attrs["ranks"] == 4 and ds.attrs["ranks"].dtype == np.int32, ds.attrs
        np.testing.assert_array_equal(ds.attrs["flags"], [1, 2])
        np.testing.assert_array_equal(ds.attrs["probes"], [0.06, 0.13])


def check_h5netcdf(path):
    """h5netcdf, under xarray, must itself decode every string attribute to str."""
    with h5netcdf.File(path, "r") as f:
        for name in ["vf", "status", "frequency", "bat", "z", "ball_speed", "mode", "bat_text"]:
            for key, value in f[name].attrs.items():
                if key != "flag_values":
                    assert type(value) is str, (name, key, value)
        assert all(type(value) is str for key, value in f.attrs.items() if key not in
                   ("wall_time_s", "ranks", "flags", "probes")), dict(f.attrs)
        assert f["status"].attrs["units"] == "1"


def check_h5py(path):
    with h5py.File(path, "r") as f:
        for name in ["bat", "z", "ball_speed", "mode"]:
            assert h5py.h5ds.is_scale(f[name].id), name
        assert [d[0].name for d in f["vf"].dims] == ["/bat", "/z", "/ball_speed"]
        assert [d[0].name for d in f["frequency"].dims] == ["/bat", "/mode"]
        assert f["vf"].shape == (2, 5, 3) and f["vf"].dtype == np.float64
        assert f["status"].dtype == np.int32, f["status"].dtype
        assert list(f["bat"][:]) == [b.encode() for b in BATS], f["bat"][:]
        for b, z, s in SAMPLES:
            assert f["vf"][b, z, s] == vf(b, z, s)
        assert f["vf"].attrs["units"] == b"m/s"
        assert f.attrs["wall_time_s"] == 1.25


def main():
    path = sys.argv[1]
    check_xarray(path)
    check_h5netcdf(path)
    check_h5py(path)
    print("dataset ok")


if __name__ == "__main__":
    main()
