#!/usr/bin/python3
"""Draws what the two uncertainty studies of studies/ say (docs/uncertainty.md): left, R161's
BBCOR over the samples of studies/uncertainty_bbcor.toml against the 0.500 limit, with the pass
probability and its interval; right, the first-order and total Sobol indices of R161's sweet-spot
width (studies/uncertainty_sweet_spot.toml) against the wood's and the ball's properties, each
with its confidence interval. Run it with Debian's interpreter, which has xarray, h5netcdf and
matplotlib.

Usage: /usr/bin/python3 scripts/plot_uncertainty.py BBCOR.h5 SWEET_SPOT.h5 [OUT.png]
  BBCOR.h5       sweetspot run studies/uncertainty_bbcor.toml -o BBCOR.h5
  SWEET_SPOT.h5  sweetspot run studies/uncertainty_sweet_spot.toml -o SWEET_SPOT.h5
  OUT.png        default studies/figures/uncertainty.png
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

ROOT = Path(__file__).resolve().parent.parent
BBCOR_LIMIT = 0.50  # NCAA/NFHS
NAMES = {"bat_density": "wood density", "bat_youngs_modulus": "wood Young's modulus", "e0": "ball COR",
         "ball_mass": "ball mass"}


def load(path):
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        ds = ds.load()
    failed = int((ds.status != 0).sum())
    if failed:
        sys.exit(f"{path}: {failed} samples did not end ok")
    return ds


def interval(estimate):
    """(value, lower error, upper error) of an estimate over the `bound` dimension."""
    value = estimate.sel(bound="estimate").values
    return value, value - estimate.sel(bound="lower").values, estimate.sel(bound="upper").values - value


def draw_bbcor(ax, ds):
    p, low, high = (float(x) for x in interval(ds.pass_probability.sel(rule="bbcor")))
    level = ds.attrs["uncertainty_confidence"] * 100
    n = int(ds.attrs["uncertainty_statistics_samples"])
    ax.hist(ds.bbcor.values[:n], bins=20, color="C0", alpha=0.8)
    ax.axvline(BBCOR_LIMIT, color="k", ls="--", lw=1, label="BBCOR limit 0.500")
    mean, lo, hi = (float(x) for x in interval(ds.bbcor_mean))
    ax.axvline(mean, color="C1", lw=1.5, label=f"mean {mean:.4f} ({mean - lo:.4f} to {mean + hi:.4f})")
    ax.set_xlabel("BBCOR at its maximum over the barrel")
    ax.set_ylabel("samples")
    ax.set_title(f"R161 in the rig: passes with probability {p:.2f}\n({p - low:.2f} to {p + high:.2f}, "
                 f"{level:g} %; {n} samples of ball COR and cannon speed)", fontsize=9)
    ax.legend(fontsize=8)


def draw_sobol(ax, ds):
    inputs = [str(x) for x in ds.input.values]
    x = np.arange(len(inputs))
    for shift, (name, label) in zip((-0.18, 0.18), (("sweet_spot_width_sobol_first", "first order"),
                                                   ("sweet_spot_width_sobol_total", "total"))):
        value, low, high = interval(ds[name])
        ax.bar(x + shift, value, width=0.34, yerr=[low, high], capsize=3, label=label)
    ax.set_xticks(x, [NAMES.get(i, i) for i in inputs], rotation=15)
    ax.axhline(0, color="k", lw=0.5)
    ax.set_ylabel("Sobol index of the sweet-spot width")
    width = ds.sweet_spot_width_mean.sel(bound="estimate").item() * 100
    sd = ds.sweet_spot_width_std.sel(bound="estimate").item() * 100
    ax.set_title(f"R161's sweet-spot width {width:.2f} cm, sd {sd:.2f} cm:\nwhich input moves it "
                 f"({int(ds.attrs['uncertainty_size'])} x (d + 2) samples)", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(axis="y", alpha=0.3)


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    bbcor, sweet = load(argv[0]), load(argv[1])
    out = Path(argv[2]) if len(argv) > 2 else ROOT / "studies" / "figures" / "uncertainty.png"
    fig, (ax_bbcor, ax_sobol) = plt.subplots(1, 2, figsize=(11, 4.3))
    draw_bbcor(ax_bbcor, bbcor)
    draw_sobol(ax_sobol, sweet)
    fig.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1:])
