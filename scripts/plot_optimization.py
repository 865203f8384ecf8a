#!/usr/bin/python3
"""Plots a design optimisation (`sweetspot optimize`): the search history, and the best bat's
profile against the base bat's.

    /usr/bin/python3 scripts/plot_optimization.py RESULT.h5 [OUT.png]

Left: the objective of every evaluated design in the order the optimiser asked (filled: feasible,
every constraint met; hollow: infeasible; crosses at the bottom: failed) and the best feasible
design so far. Right: the outline (outer radius against z) of the base bat and of the best design,
both built from the dataset alone: the base bat's [dimensions] as the run read them (attribute
`bat_toml`) with the free parameters set to `best_design`, as the program's own bat file
OUT_best.toml holds them. Radii are stretched against the length so that they can be read.
"""
import pathlib
import sys
import tomllib

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import xarray as xr  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from draw_bat_dimensions import outline  # noqa: E402  the dimensions' outline, as dimensions.hpp makes it


def design(bat, values):
    """The bat's dimensions and length with the free parameters that shape it set."""
    dims, length = dict(bat["dimensions"]), bat["length"]
    for name, value in values.items():
        if name == "length":
            length = value
        elif name in dims or name in ("end_depth", "wall_thickness"):
            dims[name] = value
    return dims, length


def draw_outline(ax, dims, length, **style):
    z, r = zip(*outline(dims, length))
    z, r = 100 * np.array(z), 100 * np.array(r)
    ax.plot(z, r, **style)
    ax.plot(z, -r, color=ax.lines[-1].get_color(), lw=style.get("lw", 1.5), ls=style.get("ls", "-"))


def main(path, out):
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        objective = ds.objective.values
        feasible = ds.feasible.values == 1
        failed = ds.status.values != 0
        units = ds.objective.attrs.get("units", "")
        scale, shown = (100, "cm") if units == "m" else (1, "m/s")
        n = np.arange(len(objective))
        best_so_far = np.maximum.accumulate(np.where(feasible, objective, -np.inf))

        fig, (history, profile) = plt.subplots(2, 1, figsize=(10, 8.5), gridspec_kw={"height_ratios": [1.3, 1]})
        ok = ~failed
        history.plot(n[ok & feasible], scale * objective[ok & feasible], "o", ms=4, color="tab:blue", label="feasible")
        history.plot(n[ok & ~feasible], scale * objective[ok & ~feasible], "o", ms=4, mfc="none", color="tab:red",
                     label="infeasible")
        if failed.any():
            low = np.nanmin(scale * objective) if ok.any() else 0
            history.plot(n[failed], np.full(failed.sum(), low), "x", color="k", label="failed")
        shown_best = np.isfinite(best_so_far)
        history.step(n[shown_best], scale * best_so_far[shown_best], where="post", color="k", lw=1,
                     label="best feasible so far")
        history.set_xlabel("evaluation")
        history.set_ylabel(f"{ds.attrs['objective_kind']} / {shown}")
        history.set_title(f"{len(n)} designs ({ds.attrs['algorithm']}, {ds.attrs['stop_reason']}), "
                          f"{float(ds.attrs['wall_time_s']):.1f} s")
        history.legend(fontsize=8)

        bat = tomllib.loads(ds.attrs["bat_toml"])
        names = [str(p) for p in ds.parameter.values]
        base_dims, base_length = design(bat, {})
        draw_outline(profile, base_dims, base_length, color="tab:gray", ls="--", lw=1.2, label=f"base: {bat['name']}")
        best = int(ds.best_evaluation.values)
        if best >= 0:
            values = dict(zip(names, ds.best_design.values))
            best_dims, best_length = design(bat, values)
            draw_outline(profile, best_dims, best_length, color="tab:green", lw=1.8,
                         label=f"best: {ds.attrs['objective_kind']} = {scale * float(ds.best_objective):.4g} {shown}")
            changed = [f"{k} {float(ds.base_design.sel(parameter=k)):.4g} → {v:.4g}" for k, v in values.items()]
            half = (len(changed) + 1) // 2
            profile.set_title(", ".join(changed[:half]) + "\n" + ", ".join(changed[half:]), fontsize=9)
        profile.set_xlabel("z from the knob / cm")
        profile.set_ylabel("radius / cm")
        profile.legend(fontsize=8, loc="center right")
        fig.suptitle(ds.attrs["title"])
        fig.tight_layout()
        fig.savefig(out, dpi=100)


if __name__ == "__main__":
    result = sys.argv[1]
    main(result, sys.argv[2] if len(sys.argv) > 2 else result.rsplit(".", 1)[0] + "_optimization.png")
