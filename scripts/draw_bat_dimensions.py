#!/usr/bin/python3
"""Draws a parametric bat's outline with each of its [dimensions] annotated (README "Bat files").

    scripts/draw_bat_dimensions.py [OUT.png [BAT.toml ...]]

Defaults: studies/bats/maple_271.toml (cupped) above studies/bats/alloy_bbcor.toml (hollow), written
to studies/figures/bat_dimensions.png. The outline
follows dimensions.hpp: a knob, a straight handle, a linear taper (a frustum), a straight barrel
and the end (flat, rounded as a half-ellipsoid, or cupped with a bore half the barrel wide); a
hollow bat's bore is drawn dashed and left white. Diameters are drawn 3 times their scale so that they can be read.
"""
import math
import pathlib
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
STRETCH = 3  # diameters drawn this many times their scale
CM = 100  # the axes in cm


def outline(d, length):
    """(z, outer radius) along the bat, z from the knob, as dimensions_profile makes it."""
    kl, ts, te = d["knob_length"], d["taper_start"], d["taper_end"]
    rk, rh, rb = d["knob_diameter"] / 2, d["handle_diameter"] / 2, d["barrel_diameter"] / 2
    end, depth = d.get("end", "flat"), d.get("end_depth", 0.0)
    points = [(0, rk), (kl, rk), (kl, rh), (ts, rh), (te, rb)]
    if end == "rounded":
        points += [(length - depth + depth * math.sin(t), rb * math.cos(t))
                   for t in (math.pi / 2 * k / 16 for k in range(17))]
    else:
        points += [(length, rb)]
    return points


def dimension_line(ax, z0, z1, y, label, above=True):
    """A horizontal dimension from z0 to z1 at height y, labelled."""
    ax.annotate("", xy=(z0 * CM, y), xytext=(z1 * CM, y),
                arrowprops=dict(arrowstyle="<->", color="tab:blue", lw=1))
    ax.text((z0 + z1) / 2 * CM, y + (0.35 if above else -0.35), label, ha="center",
            va="bottom" if above else "top", color="tab:blue", fontsize=9)


def diameter_line(ax, z, radius, label, side="right"):
    """A vertical dimension across the bat at z, labelled beside it."""
    r = radius * STRETCH * CM
    ax.annotate("", xy=(z * CM, -r), xytext=(z * CM, r),
                arrowprops=dict(arrowstyle="<->", color="tab:red", lw=1))
    ax.text(z * CM + (0.6 if side == "right" else -0.6), 0, label, rotation=90, ha="left" if side == "right" else "right",
            va="center", color="tab:red", fontsize=9)


def draw(ax, bat_file):
    bat = tomllib.loads(pathlib.Path(bat_file).read_text())
    d, length = bat["dimensions"], bat["length"]
    points = outline(d, length)
    z = [p[0] * CM for p in points]
    r = [p[1] * STRETCH * CM for p in points]
    ax.fill_between(z, [-x for x in r], r, color="burlywood", alpha=0.6, lw=0)
    ax.plot(z, r, "k", lw=1.2)
    ax.plot(z, [-x for x in r], "k", lw=1.2)
    ax.plot([0, 0], [-r[0], r[0]], "k", lw=1.2)
    end, depth = d.get("end", "flat"), d.get("end_depth", 0.0)
    rb = d["barrel_diameter"] / 2
    if end == "flat":
        ax.plot([length * CM] * 2, [-r[-1], r[-1]], "k", lw=1.2)
    if end == "cupped":
        cup = rb / 2 * STRETCH * CM  # the cup is half the barrel wide
        ax.plot([length * CM] * 2, [-r[-1], r[-1]], "k", lw=1.2)
        ax.fill_between([(length - depth) * CM, length * CM], -cup, cup, color="white", lw=0)
        ax.plot([length * CM, (length - depth) * CM, (length - depth) * CM, length * CM], [cup, cup, -cup, -cup],
                "k", lw=1)
    wall = d.get("wall_thickness", 0.0)
    if wall > 0:
        bore = [max(p[1] - wall, 0) if p[0] >= d["taper_start"] else d["handle_diameter"] / 2 - wall for p in points]
        inner = [b * STRETCH * CM for b in bore]
        ax.fill_between(z, [-x for x in inner], inner, color="white", lw=0)
        for sign in (1, -1):
            ax.plot(z, [sign * x for x in inner], "k--", lw=0.8)

    top = rb * STRETCH * CM
    dimension_line(ax, 0, d["knob_length"], top + 1.2, "knob_length")
    dimension_line(ax, 0, d["taper_start"], top + 3.4, "taper_start")
    dimension_line(ax, d["taper_start"], d["taper_end"], top + 5.6, "taper_end (from the knob)")
    ax.plot([0, d["taper_start"] * CM], [top + 5.6] * 2, color="tab:blue", lw=1)
    dimension_line(ax, 0, length, -top - 2.0, f"length = {length * CM:.2f} cm", above=False)
    if depth > 0:
        dimension_line(ax, length - depth, length, top + 1.2, "end_depth")
    for zz in (d["taper_start"], d["taper_end"]):
        ax.plot([zz * CM] * 2, [-top * 0.2, top + 5.6], color="tab:blue", lw=0.5, ls=":")
    diameter_line(ax, d["knob_length"] / 2, d["knob_diameter"] / 2, "knob_diameter", side="left")
    diameter_line(ax, (d["knob_length"] + d["taper_start"]) / 2, d["handle_diameter"] / 2, "handle_diameter")
    diameter_line(ax, (d["taper_end"] + length - depth) / 2, rb, "barrel_diameter")
    if end == "cupped":
        ax.text((length - depth / 2) * CM, -top - 0.4, "cup: ½ barrel_diameter", ha="center", va="top", fontsize=8)
    if wall > 0:
        ax.text((d["taper_end"] + length) / 2 * CM + 8, 0, "wall_thickness\n(bore dashed)", ha="center",
                va="center", fontsize=9)

    ax.set_xlabel("z from the knob (cm)")
    ax.set_ylabel(f"diameter (cm, drawn ×{STRETCH})")
    ax.set_xlim(-4, length * CM + 4)
    ax.set_ylim(-top - 5, top + 8)
    ax.set_yticks([])
    ax.set_title(f"{pathlib.Path(bat_file).name}: {bat['name']}, end = \"{end}\"" +
                 (f", wall_thickness = {wall * 1000:g} mm" if wall > 0 else ", solid"))
    ax.spines[["top", "right", "left"]].set_visible(False)


if __name__ == "__main__":
    out_file = sys.argv[1] if len(sys.argv) > 1 else ROOT / "studies/figures/bat_dimensions.png"
    bats = sys.argv[2:] or [ROOT / "studies/bats/maple_271.toml", ROOT / "studies/bats/alloy_bbcor.toml"]
    fig, axes = plt.subplots(len(bats), 1, figsize=(12, 5 * len(bats)), squeeze=False)
    for ax, bat_file in zip(axes[:, 0], bats):
        draw(ax, bat_file)
    fig.tight_layout()
    fig.savefig(out_file, dpi=100)
