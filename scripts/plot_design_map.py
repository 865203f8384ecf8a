#!/usr/bin/python3
"""Draws a design map from a study over bat parameters (docs/studies.md, "Bats as design spaces"): the
sweet spot's width and its peak exit speed against two bat dimensions, the other axes at a value
you choose (default: their middle one), with the designs that break a rule marked: a barrel over
2 5/8 in or a bat lighter than "drop -3" (the NCAA/BBCOR rules that `sweetspot certify` and
`sweetspot optimize` apply by default; drop = length in inches - weight in ounces). Run it with Debian's interpreter, which has xarray, h5netcdf and matplotlib.

Usage: /usr/bin/python3 scripts/plot_design_map.py RESULT.h5 [OUT.png] [--x DIM] [--y DIM] [DIM=VALUE ...]
  --x, --y   the dimensions of the map (default bat_barrel_diameter and bat_length)
  DIM=VALUE  where the other axes are held, e.g. bat_material=ash bat_taper_end=0.635
The dataset names a study's axis "bat.length" bat_length; the study's dotted key is taken too.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

INCH = 0.0254
BBCOR_BARREL = 2.625 * INCH  # NCAA rule 1-12: a non-wood bat's barrel at most 2 5/8 in (certify's bbcor)
args = [a for a in sys.argv[1:]]
x_dim, y_dim = "bat_barrel_diameter", "bat_length"


def dataset_name(key):
    """A study's axis key as the dataset names it: bat.length is bat_length."""
    return key.replace(".", "_")


for flag in ("--x", "--y"):
    if flag in args:
        i = args.index(flag)
        if flag == "--x":
            x_dim = dataset_name(args[i + 1])
        else:
            y_dim = dataset_name(args[i + 1])
        del args[i:i + 2]
held = {dataset_name(k): v for k, v in (a.split("=", 1) for a in args if "=" in a)}
files = [a for a in args if "=" not in a]
path = files[0]
out = files[1] if len(files) > 1 else path.rsplit(".", 1)[0] + "_design_map.png"


def at(ds, da):
    """`da` with every dimension but the two of the map held at its chosen (or middle) value."""
    chosen = {}
    for d in da.dims:
        if d in (x_dim, y_dim):
            continue
        values = ds[d].values
        if d in held and values.dtype.kind in "USO":  # names (bat_material): as given
            if held[d] not in list(values):
                sys.exit(f"{d}={held[d]}: expected one of {', '.join(map(str, values))}")
            chosen[d] = held[d]
        elif d in held:  # numbers: the nearest value of the axis
            chosen[d] = values[np.argmin(np.abs(values - float(held[d])))]
        else:
            chosen[d] = values[len(values) // 2]
    return da.sel(chosen).transpose(y_dim, x_dim), chosen


def scale(dim):
    """Lengths in inches, as designers give them."""
    return (1 / INCH, "in") if ds[dim].attrs.get("units") == "m" else (1, ds[dim].attrs.get("units", ""))


with xr.open_dataset(path, engine="h5netcdf") as ds:
    width, chosen = at(ds, ds.sweet_spot_width)
    peak, _ = at(ds, ds.sweet_spot_vf)
    drop, _ = at(ds, ds["drop"])  # ds.drop is a method of xarray's Dataset
    (xs, xu), (ys, yu) = scale(x_dim), scale(y_dim)
    x, y = ds[x_dim].values * xs, ds[y_dim].values * ys
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), sharey=True)
    for ax, field, label in ((axes[0], 100 * width, "sweet-spot width (v_f within {:g} %) / cm"),
                             (axes[1], peak, "peak exit speed $v_f$ / (m/s)")):
        fraction = 100 * float(ds.sweet_spot_width.attrs.get("sweet_spot_fraction", 0.01))
        mesh = ax.pcolormesh(x, y, field, shading="nearest", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=label.format(fraction))
        # Designs that break a rule: crossed out.
        illegal = np.asarray(drop) > 3  # drop = length - weight: "-3" bats are the lightest allowed
        if x_dim == "bat_barrel_diameter":
            illegal = illegal | (ds[x_dim].values[None, :] > BBCOR_BARREL * (1 + 1e-12))
        yy, xx = np.meshgrid(y, x, indexing="ij")
        ax.scatter(xx[illegal], yy[illegal], marker="x", color="white", s=18, label="breaks a rule")
        ax.scatter(xx[~illegal], yy[~illegal], marker=".", color="black", s=6, label="legal")
        ax.set_xlabel(f"{ds[x_dim].attrs.get('long_name', x_dim)} / {xu}")
        ax.grid(alpha=0.2)
    axes[0].set_ylabel(f"{ds[y_dim].attrs.get('long_name', y_dim)} / {yu}")
    axes[1].legend(loc="lower right", fontsize=8, framealpha=0.8)
    held_text = ", ".join(f"{k} = {v if isinstance(v, str) else f'{float(v):g}'}" for k, v in chosen.items())
    swing = "equal effort" if ds.attrs.get("scene_swing") == "equal_effort" else "the same swing for every bat"
    fig.suptitle(f"{ds.attrs.get('title', '')} ({swing})\n{held_text}; x: breaks NCAA/BBCOR (barrel > 2 5/8 in or lighter than drop -3)",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
print(out)
