#!/usr/bin/python3
"""Opens the dataset of studies/wall.toml or studies/toy.toml with xarray (engine h5netcdf) as a
user would and checks the physics it must show (physics.md §3, §6), and that a study without a
bat has no bat, mode or frequency in it.

wall (N2000 Fig. 3): e_eff = e0 at every speed within 1e-6, vf = e_eff * ball_speed, the
collision time falls as the speed rises and is near the paper's at 1, 11, 45 and 67 m/s, the
contact time is longer than the collision time.
toy (N2000 Fig. 18): v_f / v_i within 1 % of 1/3 at the smallest omega tau and of 5/7 at the
largest, the energy fractions sum to 1 within 1e-6, Van Zandt's prescription misses in between.

Usage: /usr/bin/python3 tests/check_kinds.py wall|toy OUT.h5. Prints "KIND ok" and exits 0 when
all holds.
"""
import sys
import tomllib

import numpy as np
import xarray as xr


def check_no_bat(ds, kind, axis):
    assert ds.attrs["kind"] == kind, ds.attrs["kind"]
    assert set(ds.dims) == {axis}, dict(ds.sizes)
    assert "frequency" not in ds.data_vars and "bat" not in ds.coords and "mode" not in ds.coords
    assert ds.status.dtype == np.int32 and int(abs(ds.status).max()) == 0, ds.status.values


def check_wall(ds):
    check_no_bat(ds, "wall", "ball_speed")
    e0 = tomllib.loads(ds.attrs["study"])["scene"]["e0"]
    assert float(abs(ds.e_eff - e0).max()) < 1e-6, ds.e_eff.values
    assert np.allclose(ds.vf, ds.e_eff * ds.ball_speed, rtol=1e-12, atol=0)
    time = ds.collision_time.sortby("ball_speed").values
    assert np.all(np.diff(time) < 0), time
    assert bool((ds.contact_time > ds.collision_time).all())
    for speed, paper_ms in ((1, 2.2), (11, 1.0), (45, 0.7), (67, 0.6)):  # physics.md §3
        got_ms = 1e3 * float(ds.collision_time.sel(ball_speed=speed))
        assert abs(got_ms / paper_ms - 1) < 0.05, (speed, got_ms, paper_ms)
    assert ds.collision_time.attrs["units"] == "s" and ds.vf.attrs["units"] == "m/s"


def check_toy(ds):
    check_no_bat(ds, "toy", "omega_tau")
    vf = ds.vf.sortby("omega_tau")
    assert abs(float(vf[0]) * 3 - 1) < 0.01, float(vf[0])          # Ma alone
    assert abs(float(vf[-1]) * 7 / 5 - 1) < 0.01, float(vf[-1])    # one rigid mass of 6
    # Model units m = v_i = 1: the initial energy is 1/2.
    initial = ds.energy_initial if "energy_initial" in ds.data_vars else 0.5
    total = (ds.energy_ball + ds.energy_bat_translation + ds.energy_vibration) / initial
    assert float(abs(total - 1).max()) < 1e-6, total.values
    assert float(abs(ds.vf_van_zandt - ds.vf).max()) > 0.05
    # status is a flag, no quantity: CF gives it no units
    assert all(ds[name].attrs["units"] == "1" for name in ds.data_vars if name != "status"), "dimensionless"
    assert "units" not in ds.status.attrs and "flag_values" in ds.status.attrs
    assert ds.omega_tau.attrs["long_name"] and ds.vf_van_zandt.attrs["long_name"]


if __name__ == "__main__":  # tests/check_figures.py imports the checks
    kind, path = sys.argv[1], sys.argv[2]
    with xr.open_dataset(path, engine="h5netcdf") as dataset:
        {"wall": check_wall, "toy": check_toy}[kind](dataset)
    print(kind, "ok")
