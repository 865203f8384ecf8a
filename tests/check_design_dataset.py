#!/usr/bin/python3
"""Opens a design study's dataset (tests/test_bat_axes.cpp: the maple 271 over "bat.material" x
"bat.barrel_diameter" x z, 4 modes, sweet-spot outputs) with xarray and checks what a designer reads
there against the physics: the parameter axes named bat_material and bat_barrel_diameter, each with
its own long_name and units, selectable by keyword; no dimension of size 1 (one bat file: no bat
dimension); the designer's variables over (bat_material, bat_barrel_diameter); the drop from the mass and length; the swing weight from the MOI about the
CM by the parallel-axis theorem; a wider barrel weighs more; the sweet spot over the other axes,
between grid points, with vf stored beside it and equal to the reduction's own at its grid point.
Prints "design dataset ok".

Usage: /usr/bin/python3 tests/check_design_dataset.py OUT.h5
"""
import sys

import numpy as np
import xarray as xr

INCH, OUNCE = 0.0254, 0.028349523125
with xr.open_dataset(sys.argv[1], engine="h5netcdf") as ds:
    dims = ("bat_material", "bat_barrel_diameter")
    assert not any("." in name for name in ds.variables), list(ds.variables)
    assert ds.bat_material.attrs == {"long_name": "bat material (wood preset)"}, ds.bat_material.attrs
    assert ds.bat_barrel_diameter.attrs["long_name"] == "bat barrel diameter", ds.bat_barrel_diameter.attrs
    # One bat file: its name a scalar, and no variable carries a dimension of size 1.
    assert "bat" not in ds.dims and ds.bat.dims == () and ds.bat.item() == "maple 271", ds.bat
    for name, variable in ds.variables.items():
        assert all(ds.sizes[d] > 1 for d in variable.dims), (name, variable.dims)
    maple = ds.sel(bat_material="maple")
    assert maple.bat_mass.dims == ("bat_barrel_diameter",) and float(maple.bat_barrel_diameter[0]) == 0.0610
    for name, units in (("bat_mass", "kg"), ("bat_length", "m"), ("balance_point", "m"), ("moi_knob", "kg m^2"),
                        ("moi_pivot", "kg m^2"), ("moi_cm", "kg m^2")):
        assert ds[name].dims == dims, (name, ds[name].dims)
        assert ds[name].attrs["units"] == units, (name, ds[name].attrs)
    assert ds["drop"].dims == dims and "units" not in ds["drop"].attrs
    assert list(ds.bat_material.values) == ["maple", "ash", "birch"]
    assert ds.bat_barrel_diameter.attrs["units"] == "m"
    m, L, zc = ds.bat_mass.values, ds.bat_length.values, ds.balance_point.values
    np.testing.assert_allclose(ds["drop"].values, L / INCH - m / OUNCE, rtol=0, atol=1e-12)
    np.testing.assert_allclose(ds.moi_pivot.values, ds.moi_cm.values + m * (zc - 0.1524) ** 2, rtol=1e-13)
    np.testing.assert_allclose(ds.moi_knob.values, ds.moi_cm.values + m * zc ** 2, rtol=1e-13)
    assert (np.diff(m, axis=1) > 0).all(), "a wider barrel weighs more"
    assert (np.abs(m - 0.9) < 0.1).all(), m  # 33-in wood bats weigh 29 to 34 oz
    # Four modes kept: four frequencies, ascending; mode k has k + 1 nodes on the bat.
    assert ds.frequency.dims == dims + ("mode",) and ds.sizes["mode"] == 4
    assert (np.diff(ds.frequency.values, axis=-1) > 0).all()
    nodes = ds.node_position.values
    for k in range(3):
        count = np.isfinite(nodes[..., k, :]).sum(axis=-1)
        assert (count == k + 2).all(), (k, count)
        assert ((nodes[..., k, : k + 2] > 0) & (nodes[..., k, : k + 2] < L[..., None])).all()
    # The sweet spot keeps every axis but z, and lies between the z grid's points.
    for name in ("sweet_spot_z", "sweet_spot_vf", "sweet_spot_width"):
        assert ds[name].dims == dims, ds[name].dims
    z = ds.z.values
    best = ds.vf.values.argmax(axis=-1)
    spot = ds.sweet_spot_z.values
    assert (np.abs(spot - z[best]) <= np.diff(z)[0]).all(), (spot, z[best])
    assert (ds.sweet_spot_vf.values >= ds.vf.values.max(axis=-1) - 1e-12).all()
print("design dataset ok")
