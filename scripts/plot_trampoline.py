#!/usr/bin/python3
"""Draws the trampoline effect (README, "Hollow barrels"): BBCOR in the virtual rig and the peak exit
speed of an equal-effort swing against the lowest hoop frequency of the struck barrel, for the
wall-thickness sweeps of studies/trampoline_bbcor.toml and studies/trampoline_vf.toml. The plot
the literature shows (Nathan et al., Sports Eng. 13, 153 (2011); Russell, "Hoop frequency as a
predictor of performance for softball bats"): performance rises as the hoop frequency falls over
the 1-2.5 kHz of real bats. Run it with Debian's interpreter, which has xarray, h5netcdf and
matplotlib.

Usage: /usr/bin/python3 scripts/plot_trampoline.py BBCOR.h5 VF.h5 [OUT.png]
  BBCOR.h5  sweetspot run studies/trampoline_bbcor.toml -o BBCOR.h5
  VF.h5     sweetspot run studies/trampoline_vf.toml -o VF.h5
  OUT.png   default studies/figures/trampoline.png
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.ticker
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

ROOT = Path(__file__).resolve().parent.parent
WALL = "bat_wall_thickness"
BBCOR_LIMIT = 0.50  # NCAA/NFHS


def load(path):
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        ds = ds.load()
    failed = int((ds.status != 0).sum())
    if failed:
        sys.exit(f"{path}: {failed} points did not end ok")
    return ds


def peak_vf(vf_ds, bat):
    """Per wall thickness: the hoop frequency where v_f peaks along z, and that peak."""
    one = vf_ds.isel(bat=bat)
    at = one.vf.argmax("z")
    return one.hoop_frequency.isel(z=at).values, one.vf.isel(z=at).values


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    rig, swing = load(argv[0]), load(argv[1])
    out = Path(argv[2]) if len(argv) > 2 else ROOT / "studies" / "figures" / "trampoline.png"
    fig, (ax_cor, ax_vf) = plt.subplots(1, 2, figsize=(11, 4.3))
    for bat, (name, marker) in enumerate(zip(rig.bat.values, ("o", "s"))):
        hoop = rig.hoop_frequency.isel(bat=bat).values / 1000
        walls = rig[WALL].values * 1000
        ax_cor.plot(hoop, rig.bbcor.isel(bat=bat).values, marker=marker, label=str(name))
        for x, y, h in zip(hoop, rig.bbcor.isel(bat=bat).values, walls):
            ax_cor.annotate(f"{h:g}", (x, y), textcoords="offset points", xytext=(4, 3), fontsize=7)
        f, v = peak_vf(swing, bat)
        ax_vf.plot(f / 1000, v, marker=marker, label=str(name))
    for ax in (ax_cor, ax_vf):
        ax.axvspan(1.0, 2.5, color="0.9", zorder=0, label="real bats' hoop frequencies")
        ax.set_xscale("log")
        ax.set_xticks([0.7, 1, 1.5, 2, 3, 5, 8])
        ax.xaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("lowest hoop frequency of the struck barrel (kHz)")
        ax.grid(alpha=0.3)
    ax_cor.axhline(BBCOR_LIMIT, color="k", ls="--", lw=1, label="BBCOR limit 0.50")
    ax_cor.set_ylabel("BBCOR at its maximum over the barrel")
    ax_cor.set_title("Virtual rig (labels: wall thickness, mm)")
    ax_vf.set_ylabel("peak exit speed along the barrel (m/s)")
    ax_vf.set_title("Equal-effort swing, ball 40 m/s")
    ax_cor.legend(fontsize=8)
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
