#!/usr/bin/python3
"""Work-precision diagram of a `sweetspot convergence` dataset: the relative error of the exit
speed v_f against the wall time per impact, one line per integrator (markers at its settings,
coarsest first, labelled with the step or tolerance), and beside it the accuracy sweep: at each
stated total accuracy (and the default settings), the estimated total error, each source's
estimate (slicing, modes, step) and the actual error against the continuum, against the time per
impact. Lower left is better. Run it with Debian's interpreter, which has xarray, h5netcdf and
matplotlib.

Usage: /usr/bin/python3 scripts/plot_convergence.py RESULT.h5 [OUT.png]
"""
import math
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import xarray as xr

MARKERS = {"rk4": "o", "exact": "s", "dopri": "^"}


def setting_label(method, step, tolerance):
    return f"tol {tolerance:.0e}" if method == "dopri" else f"{1e6 * step:.3g} µs"


def scene_title(ds):
    """The study's own title and the scene's main keys, as its file gives them."""
    study = tomllib.loads(ds.attrs["study"])
    scene = study.get("scene", {})
    keys = ("z", "ball_speed", "e0", "modes")
    details = ", ".join(f"{key} = {scene[key]}" for key in keys if key in scene)
    if study.get("axes"):
        details += " (grid point 0 of the axes)"
    return f"Work-precision: {study.get('title', ds.attrs['study_file'])}\n{details}"


path = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else path.rsplit(".", 1)[0] + ".png"

SOURCES = (("total_error", "estimated total", "o", "-"), ("actual_error", "actual (continuum)", "*", "-"),
           ("slicing_error", "slicing", "s", "none"), ("modes_error", "modes", "^", "none"), ("step_error", "step", "v", "none"))


def accuracy_panel(ax, ds):
    """Each source's estimate, the total and the actual error of the accuracy sweep against the
    time per impact (the bat's modes solved beforehand), the stated accuracies labelled."""
    stated = np.arange(1, ds.sizes["accuracy_run"])  # run 0 is the default settings
    time = np.log10(ds.accuracy_time_per_impact.values * 1e6)
    for name, label, marker, style in SOURCES:
        error = np.log10(np.maximum(ds[name].values, 1e-16))
        ax.plot(time[stated], error[stated], marker=marker, linestyle=style, label=label)
        ax.plot(time[0], error[0], marker=marker, linestyle="none", color=ax.lines[-1].get_color(), fillstyle="none")
    for k in stated:
        ax.annotate(f"A = {float(ds.accuracy.values[k]):.0e}", (time[k], np.log10(ds.total_error.values[k])),
                    textcoords="offset points", xytext=(5, 4), fontsize=7)
    ax.annotate("default", (time[0], np.log10(ds.total_error.values[0])), textcoords="offset points",
                xytext=(5, 4), fontsize=7)
    ax.set_xlabel("log$_{10}$(wall time per impact / µs)")
    ax.set_ylabel("log$_{10}$(relative error of $v_f$)")
    ax.set_title(f"Stated accuracy: error sources against the continuum\n(v$_f$ = {ds.attrs['continuum_vf']:.8f} m/s, "
                 f"{int(ds.attrs['continuum_slices'])} slices; open markers: the default settings)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower left", fontsize=8)


with xr.open_dataset(path, engine="h5netcdf") as ds:
    sweep = "accuracy_run" in ds.dims
    fig, axes = plt.subplots(1, 2 if sweep else 1, figsize=(16, 6) if sweep else (8.5, 6), squeeze=False)
    ax = axes[0][0]
    for method in ds.integrator.values:
        run = ds.sel(integrator=method).dropna("setting", subset=["vf_error", "time_per_impact"])
        time = np.log10(run.time_per_impact.values * 1e6)
        error = np.log10(np.maximum(run.vf_error.values, 1e-16))  # an exact match would be -inf
        ax.plot(time, error, marker=MARKERS.get(method, "o"), label=method)
        # Labels alternate above right and below left, where a descending line leaves room.
        for i, (t, e, step, tolerance) in enumerate(zip(time, error, run.step.values, run.tolerance.values)):
            ax.annotate(setting_label(method, step, tolerance), (t, e), textcoords="offset points",
                        xytext=(5, 3) if i % 2 == 0 else (-5, -9), ha="left" if i % 2 == 0 else "right",
                        fontsize=7, color=ax.lines[-1].get_color())
    ax.axhline(-6, color="grey", linestyle=":", linewidth=1)
    ax.set_xlabel("log$_{10}$(wall time per impact / µs)")
    ax.set_ylabel("log$_{10}$(relative error of $v_f$)")
    ax.set_title(scene_title(ds), fontsize=10)
    disagreement = ds.attrs.get("reference_disagreement", math.nan)
    ax.text(0.99, 0.99, f"reference $v_f$ = {ds.attrs['reference_vf']:.10f} m/s (dopri, tol 1e-13)\n"
            f"Richardson of exact: relative difference {disagreement:.1e}",
            transform=ax.transAxes, ha="right", va="top", fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(title="integrator", loc="lower left")
    if sweep:
        accuracy_panel(axes[0][1], ds)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
print(f"wrote {out}")
