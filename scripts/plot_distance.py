#!/usr/bin/python3
"""Draws the carry of studies/distance.toml (docs/flight.md): for each bat, the batted ball's
distance in feet against the undercut, one line per swing tilt, and the launch angle and backspin
of the longest drive. Run it with Debian's interpreter, which has xarray, h5netcdf and matplotlib.

Usage: /usr/bin/python3 scripts/plot_distance.py DISTANCE.h5 [OUT.png]
  DISTANCE.h5  sweetspot run studies/distance.toml -o DISTANCE.h5
  OUT.png      default studies/figures/distance.png
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import xarray as xr

ROOT = Path(__file__).resolve().parent.parent
FEET_PER_METRE = 1 / 0.3048
INCHES_PER_METRE = 1 / 0.0254

path = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else ROOT / "studies" / "figures" / "distance.png"
with xr.open_dataset(path, engine="h5netcdf") as ds:
    ds = ds.load()
names = [Path(str(name)).stem for name in ds["bat_file"].values]
fig, axes = plt.subplots(1, ds.sizes["bat"], figsize=(6 * ds.sizes["bat"], 4.8), sharey=True)
for ax, bat, name in zip(axes, range(ds.sizes["bat"]), names):
    one = ds.isel(bat=bat)
    for tilt in one.swing_tilt.values:
        curve = one.sel(swing_tilt=tilt)
        ax.plot(curve.undercut * INCHES_PER_METRE, curve.distance * FEET_PER_METRE, label=f"{tilt:g}°")
    best = one.distance.argmax(...)
    far = one.isel(best)
    ax.annotate(f"{float(far.distance) * FEET_PER_METRE:.0f} ft: {float(far.launch_angle):.0f}°, "
                f"{float(far.backspin):.0f} rpm", (float(far.undercut) * INCHES_PER_METRE,
                                                     float(far.distance) * FEET_PER_METRE),
                textcoords="offset points", xytext=(6, 6), fontsize=8)
    ax.set_title(name)
    ax.set_xlabel("undercut (in)")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("distance (ft)")
axes[-1].legend(title="swing tilt", fontsize=8)
fig.suptitle("Carry against undercut and swing tilt (equal effort, 85-mph pitch, friction 0.5, standard air)", fontsize=10)
fig.tight_layout()
fig.savefig(out, dpi=120)
print(f"wrote {out}")
