"""Writes the validation page: each published measurement of docs/validation/published.toml beside
sweetspot's prediction for the same bat and ball, with the residual and what had to be assumed.
Run by scripts/validation; every number comes from build/sweetspot as it is."""
import json
import os
import re
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROGRAM = Path(os.environ.get("SWEETSPOT_PROGRAM", ROOT / "build" / "sweetspot"))
BATS = ROOT / "studies" / "bats"
INCH, MPH, LBF = 0.0254, 0.44704, 4.4482216152605


def sweetspot(*args, verdicts=(0,)):
    """The program's JSON; `verdicts` the exit statuses that are answers (certify: 3, it fails a rule)."""
    run = subprocess.run([str(PROGRAM), *map(str, args)], capture_output=True, text=True)
    if run.returncode not in verdicts:
        raise RuntimeError(f"sweetspot {' '.join(map(str, args))}: exit status {run.returncode}: {run.stderr.strip()}")
    return json.loads(run.stdout)


def certify(bat, standard="bbcor"):
    return sweetspot("certify", bat, "--standard", standard, "--json", verdicts=(0, 3))


def stretched_wood(folder, wood, inches):
    """The maple 271 of studies/bats in another wood preset and length, taper and barrel at the
    same shares of the length."""
    text = (BATS / "maple_271.toml").read_text()
    scale = inches / 33
    text = text.replace('preset = "maple"', f'preset = "{wood}"')
    text = re.sub(r"^length = .*$", f"length = {inches * INCH!r}", text, flags=re.M)
    for key in ("taper_start", "taper_end"):
        value = float(re.search(rf"^{key} = ([0-9.]+)", text, flags=re.M).group(1))
        text = re.sub(rf"^{key} = .*$", f"{key} = {value * scale!r}", text, flags=re.M)
    path = Path(folder) / f"{wood}_{inches:g}.toml"
    path.write_text(text)
    return path


def calibrated_alloy(folder, hoop_hz):
    text = (BATS / "alloy_bbcor.toml").read_text() + f"\n[barrel]\nhoop_frequency = {hoop_hz}\n"
    path = Path(folder) / f"alloy_{hoop_hz}.toml"
    path.write_text(text)
    return path


def alloy_of_wall(folder, thickness_mm):
    text = (BATS / "alloy_bbcor.toml").read_text()
    text = re.sub(r"^wall_thickness = .*$", f"wall_thickness = {thickness_mm / 1000!r}", text, flags=re.M)
    path = Path(folder) / f"alloy_{thickness_mm}mm.toml"
    path.write_text(text)
    return path


def fit_slope(xs, ys):
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def row(*cells):
    return "| " + " | ".join(str(c) for c in cells) + " |"


def ball_inputs():
    lines = ["| ball | specification | its source | virtual test on the model | residual |", "|---|---|---|---|---|"]
    presets = {"mlb": (0.546, 85 * 0.3048, "0.546 +- 0.032 at 85 ft/s (MLB)"),
               "softball_44_375": (0.44, 60 * MPH, ".44 at 60 mph (ASA/USA Softball)"),
               "softball_47_525": (0.47, 60 * MPH, ".47 at 60 mph (ASA/USA Softball)")}
    for name, (cor, speed, spec) in presets.items():
        ball = sweetspot("ball", name, "--speeds", f"{speed / MPH!r}", "--json")
        model = ball["flat_wall"][0]["cor"]
        lines.append(row(f"`{name}`", f"COR {spec}", "ASTM F1887-style rating", f"{model:.4f}", f"{model - cor:+.1e}"))
    return lines


def adair_rows(data):
    ball = sweetspot("ball", "mlb", "--json")
    barrel = 2.625 * INCH / 2
    curvature = (barrel / (ball["radius"] + barrel)) ** 0.25
    lines = []
    for label, u_in, force in zip(data["labels"], data["compression_in"], data["force_lbf"]):
        predicted = ball["k1"] * curvature * (u_in * INCH) ** ball["a"] / LBF
        lines.append(row(f"peak force at {u_in} in of ball compression ({label})", "Adair", f"{force} lbf",
                         f"{predicted:.0f} lbf", f"{(predicted - force) / force:+.0%}",
                         "the `mlb` ball's law (N2000's k1, a) on a 2 5/8-in barrel; the bat's compression "
                         "neglected"))
    return lines


def wood_rows(data, folder):
    shipped = {f"`{name}`": BATS / f"{name}.toml" for name in ("r161", "torpedo", "maple_271")}
    stretched = {(wood, inches): stretched_wood(folder, wood, inches)
                 for wood in ("maple", "ash", "birch") for inches in (32, 33, 34)}
    bats = dict(shipped) | {f"{wood} 271 at {inches} in": path for (wood, inches), path in stretched.items()}
    bbcor = {name: certify(path)["bbcor"] for name, path in bats.items()}
    besr = {name: certify(path, "besr")["besr"] for name, path in bats.items()}
    best = max(bbcor, key=bbcor.get)
    spreads = {wood: max(bbcor[f"{wood} 271 at {i} in"] for i in (32, 33, 34)) -
               min(bbcor[f"{wood} 271 at {i} in"] for i in (32, 33, 34)) for wood in ("maple", "ash", "birch")}
    ncaa, nathan = data["ncaa_wood"], data["nathan_besr_wood"]
    best_besr = max(besr, key=besr.get)
    e_a = besr[best_besr] - 0.5
    exit_mph = e_a * nathan["pitch_mph"] + (1 + e_a) * nathan["bat_mph"]
    lines = [
        row("largest wood BBCOR", "NCAA 2008", f"just below {ncaa['limit']:.3f}", f"{bbcor[best]:.4f} ({best})",
            f"{bbcor[best] - ncaa['limit']:+.4f}", "the shipped wood bats and the 271 shape in three woods at "
            "32-34 in; the `ncaa` ball"),
        row("wood BBCOR against length", "NCAA 2008 (no sliding scale)", "independent of length",
            ", ".join(f"{w} {s:.4f}" for w, s in spreads.items()) + " (32 to 34 in)", "-",
            "the 271 shape stretched to each length"),
        row("largest wood exit speed in the BESR test", "Nathan 2003", f"{nathan['exit_speed_mph']} mph (BESR "
            f"{(nathan['exit_speed_mph'] - nathan['bat_mph']) / (nathan['pitch_mph'] + nathan['bat_mph']) + 0.5:.3f})",
            f"{exit_mph:.1f} mph (BESR {besr[best_besr]:.4f}, {best_besr})",
            f"{exit_mph - nathan['exit_speed_mph']:+.1f} mph", "the same bats; BESR's 70 mph pitch and 66 mph bat"),
    ]
    table = ["| bat | BBCOR | BESR |", "|---|---|---|"] + [row(n, f"{bbcor[n]:.4f}", f"{besr[n]:.4f}") for n in bats]
    return lines, table


def hollow_rows(data, folder):
    hollow = {name: certify(BATS / f"{name}.toml") for name in ("alloy_bbcor", "aluminium", "composite_bbcor")}
    alloy = hollow["alloy_bbcor"]
    frequencies = [1000, 1500, 2000, 2500, 3000, 4000]
    sweep = [certify(calibrated_alloy(folder, f))["bbcor"] for f in frequencies]
    slope = fit_slope([f / 1000 for f in frequencies], sweep)
    walls = [certify(alloy_of_wall(folder, h)) for h in (1.7, 2.2, 2.6, 3.4, 4.4, 5.4, 6.6)]
    wall_slope = fit_slope([w["hoop_frequency"] / 1000 for w in walls], [w["bbcor"] for w in walls])
    rng = data["russell_hoop_range"]
    r161 = certify(BATS / "r161.toml", "besr")["e_a"]
    aluminium = certify(BATS / "aluminium.toml", "besr")["e_a"]
    elastic = (aluminium - r161) * 140
    lines = [
        row("BBCOR of a legal -3 alloy bat", "NCAA limit", f"at most {data['legal_alloy']['bbcor']:.3f}",
            f"{alloy['bbcor']:.4f} (`alloy_bbcor`, hoop {alloy['hoop_frequency']:.0f} Hz)",
            f"{alloy['bbcor'] - data['legal_alloy']['bbcor']:+.4f}",
            "a representative 33-in, 2 5/8-in, 2.6-mm aluminium wall (no measured bat's dimensions were found); "
            "the `ncaa` ball"),
        row("BBCOR against hoop frequency, bats of different walls", "Nathan et al. 2011; Russell 2004; Sutton & "
            "Sherwood 2010", "falls as the hoop frequency rises (slope not retrieved)",
            f"{wall_slope:+.4f} per kHz over {walls[0]['hoop_frequency']:.0f}-{walls[-1]['hoop_frequency']:.0f} Hz",
            "sign agrees" if wall_slope < 0 else "sign DISAGREES",
            "`alloy_bbcor` with walls of 1.7-6.6 mm (the thicker ones break the -3 weight rule)"),
        row("BBCOR against hoop frequency, one wall made softer", "as above", "as above",
            f"{slope:+.4f} per kHz over 1-4 kHz; largest at 2 kHz", "sign agrees" if slope < 0 else "sign DISAGREES",
            "`alloy_bbcor` with its wall calibrated to each hoop frequency (its modulus scaled, its mass kept)"),
        row("lowest hoop frequency of hollow bats", "Russell 2017 (softball bats)",
            f"{rng['low_hz']}-{rng['high_hz']} Hz",
            ", ".join(f"{n} {h['hoop_frequency']:.0f} Hz" for n, h in hollow.items()), "within" if all(
                rng['low_hz'] <= h['hoop_frequency'] <= rng['high_hz'] for h in hollow.values()) else "outside",
            "baseball bats set beside a softball range"),
        row("best metal over wood batted-ball speed", "Greenwald et al. 2001", f"about {data['greenwald_cage']['difference_mph']} "
            "mph (swing speed included)", f"{elastic:.1f} mph (the bat's elastic part alone)",
            f"{elastic - data['greenwald_cage']['difference_mph']:+.1f} mph",
            "`aluminium` against `r161`, e_A at the BESR rig's peak, at 70 mph pitch + 70 mph bat; their 1997-98 "
            "bats were not described"),
    ]
    sweep_table = ["| wall (mm) | hoop frequency (Hz) | BBCOR | mass (oz) |", "|---|---|---|---|"]
    sweep_table += [row(h, f"{w['hoop_frequency']:.0f}", f"{w['bbcor']:.4f}", f"{w['mass'] / 0.028349523125:.1f}")
                    for h, w in zip((1.7, 2.2, 2.6, 3.4, 4.4, 5.4, 6.6), walls)]
    sweep_table += ["", "With the 2.6-mm wall calibrated to each hoop frequency (`[barrel] hoop_frequency`):", "",
                    "| hoop frequency (Hz) | " + " | ".join(map(str, frequencies)) + " |",
                    "|---|" + "---|" * len(frequencies), "| BBCOR | " + " | ".join(f"{b:.4f}" for b in sweep) + " |"]
    return lines, sweep_table


def main(output):
    data = tomllib.loads((ROOT / "docs" / "validation" / "published.toml").read_text())
    with tempfile.TemporaryDirectory() as folder:
        wood, wood_table = wood_rows(data, folder)
        hollow, sweep_table = hollow_rows(data, folder)
    header = ["| quantity | source | measured | predicted | residual | assumed |", "|---|---|---|---|---|---|"]
    sources = [f"- **{key}**: {entry['source']} ({entry['read']})." for key, entry in data.items()]
    page = [
        "# Validation: sweetspot against published measurements",
        "",
        "Generated by `scripts/validation` from `docs/validation/published.toml`; do not edit by hand. Each",
        "row sets a published measurement beside what sweetspot predicts for the same bat and ball, with",
        "the residual (predicted minus measured) and what had to be assumed. Nothing is fitted to these",
        "rows: the model's inputs are the ball presets' test values and the bats' dimensions and",
        "materials (README \"Balls\", \"Bat files\", \"Hollow barrels\").",
        "",
        "## Predictions",
        "",
        *header, *adair_rows(data["adair_ball_force"]), *wood, *hollow,
        "",
        "## The balls' own tests (inputs, reproduced)",
        "",
        "The presets are fitted to their specifications, so these residuals check the fit and the",
        "integration, not the model.",
        "",
        *ball_inputs(),
        "",
        "## Wood bats in the BBCOR and BESR rigs",
        "",
        *wood_table,
        "",
        "## BBCOR of `alloy_bbcor` against its hoop frequency",
        "",
        *sweep_table,
        "",
        "## Sources",
        "",
        *sources,
        "",
    ]
    Path(output).write_text("\n".join(page))


if __name__ == "__main__":
    main(sys.argv[1])
