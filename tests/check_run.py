#!/usr/bin/python3
"""Opens a sweetspot dataset with xarray (engine h5netcdf) as a user would and checks the small
study of tests/test_run.cpp: dims, coordinates, attributes, and vf at one point against the value
`sweetspot impact --json` printed for it.

Usage: /usr/bin/python3 tests/check_run.py OUT.h5 BAT Z SPEED VF
"""
import sys

import numpy as np
import xarray as xr

path, bat, z, speed, vf = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
with xr.open_dataset(path, engine="h5netcdf") as ds:
    assert ds.vf.dims == ("bat", "z", "ball_speed"), ds.vf.dims
    assert list(ds.bat.values) == ["R161", "torpedo"], ds.bat.values
    assert np.allclose(ds.z.values, [0.605, 0.655, 0.705]), ds.z.values
    assert list(ds.ball_speed.values) == [30.0, 40.0], ds.ball_speed.values
    assert ds.status.dtype == np.int32 and int(ds.status.max()) == 0
    assert ds.vf.attrs["units"] == "m/s" and ds.vf.attrs["long_name"]
    assert ds.frequency.dims == ("bat", "mode") and 150 < float(ds.frequency[0, 0]) < 200
    assert list(ds.mode.values) == list(range(1, 19)), ds.mode.values  # the study's 18 modes, no more
    for key in ("study", "program_version", "git_commit", "mpi_ranks", "omp_threads", "wall_time_s"):
        assert key in ds.attrs, key
    got = float(ds.vf.sel(bat=bat).sel(z=z, ball_speed=speed, method="nearest"))
    assert got == vf, (got, vf)
    provenance = {"bat_file", "bat_toml", "bat_profile_file", "bat_profile", "bat_slices"}  # check_provenance.py
    # what a designer checks of each bat (tests/check_design_dataset.py)
    designer = {"bat_mass", "bat_length", "drop", "balance_point", "moi_knob", "moi_pivot", "moi_cm", "frequency",
                "node_position"}
    assert set(ds.data_vars) == {"vf", "e_eff", "contact_time", "collision_time", "status"} | designer | provenance
    # R161's of physics.md §2: M = 0.869 kg, z_cm = 0.561 m; its first mode's nodes near 17 and 68 cm
    assert abs(float(ds.bat_mass.sel(bat="R161")) - 0.869) < 1e-3 and abs(float(ds.balance_point.sel(bat="R161")) - 0.561) < 1e-3
    nodes = ds.node_position.sel(bat="R161", node_mode=1).values
    assert abs(nodes[0] - 0.17) < 0.01 and abs(nodes[1] - 0.68) < 0.01 and np.isnan(nodes[2:]).all(), nodes
print("dataset ok")
