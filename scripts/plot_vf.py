#!/usr/bin/python3
"""Opens a sweetspot study result and plots the exit speed v_f against the impact point z, one
line per bat (other axes: their middle value, named in the title). A short example of reading
the dataset; run it with Debian's interpreter, which has xarray, h5netcdf and matplotlib.

Usage: /usr/bin/python3 scripts/plot_vf.py RESULT.h5 [OUT.png]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import xarray as xr

path = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else path.rsplit(".", 1)[0] + "_vf.png"

with xr.open_dataset(path, engine="h5netcdf") as ds:
    vf = ds.vf
    fixed = {d: vf[d].values[len(vf[d]) // 2] for d in vf.dims if d not in ("z", "bat")}
    vf = vf.sel(fixed)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for bat in vf.bat.values if "bat" in vf.dims else [None]:
        curve = vf.sel(bat=bat) if bat is not None else vf
        ax.plot(100 * curve.z, curve, marker="o", markersize=3, label=bat or str(ds.bat.item()))
    ax.set_xlabel("impact point z / cm from the knob")
    ax.set_ylabel("exit speed $v_f$ / (m/s)")
    title = ", ".join(f"{k} = {float(v):g}" for k, v in fixed.items()) or ds.attrs.get("title", "")
    if ds.attrs.get("scene_swing") == "equal_effort":  # say how the bats were swung
        title += f"\nswung with equal effort (reference {ds.attrs['scene_reference_bat']})"
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(title="bat")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
print(f"wrote {out}")
