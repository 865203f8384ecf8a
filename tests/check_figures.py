#!/usr/bin/python3
"""Checks the claim of each N2000 figure that scripts/figures draws (physics.md §6) on the numbers
of the datasets it is drawn from, not on the images.

Usage: /usr/bin/python3 tests/check_figures.py FIGURE DIR
  FIGURE: low_impact (Figs. 7-8), high_impact (Figs. 10-11), e_eff (Fig. 12), pivot (Fig. 16),
          wall (Fig. 3), toy (Fig. 18), modes (Fig. 6), force_compression (Fig. 2), force_profile (Fig. 4),
          low_impact_histories (Fig. 9) or handle (Figs. 13-15)
  DIR holds what the figure needs: DIR/STUDY.h5 as `sweetspot run studies/STUDY.toml -o
  DIR/STUDY.h5` writes it, or for modes DIR/modes.json from `sweetspot modes R161 --json
  --shapes --count 3`.
Prints "FIGURE ok" and exits 0 when all holds.
"""
import json
import sys
from pathlib import Path

import numpy as np
import xarray as xr

from check_kinds import check_toy, check_wall

Z_CM = 0.561  # m, the R161's centre of mass with the published profile (physics.md §2)


def study(name):
    with xr.open_dataset(Path(sys.argv[2]) / f"{name}.h5", engine="h5netcdf") as ds:
        assert int(abs(ds.status).max()) == 0, f"{name}: failed points"
        return ds.load()


def peak(curve):
    return float(curve.z[int(curve.argmax())])


def at_60_cm(ds):
    return ds.sel(z=0.605)  # the slice centre just beyond 60 cm


def low_impact():
    ds = study("low_impact")
    assert 0.60 <= peak(ds.vf) <= 0.68, peak(ds.vf)  # toward the handle from the 68-cm node
    assert abs(peak(ds.vf_rigid) - Z_CM) <= 0.02, peak(ds.vf_rigid)
    assert float(abs(1e3 * ds.collision_time - 2.2).max()) < 0.2, ds.collision_time.values
    # Only mode 1 takes up appreciable energy (the pulse, about 2.2 ms, is too long for the rest).
    vibration = ds.mode_energy
    assert float(vibration.sel(mode=1).sum() / vibration.sum()) > 0.9
    assert float((vibration.sel(mode=slice(2, None)) / ds.energy_initial).max()) < 0.05
    # The ball dissipates most where the bat vibrates least.
    dissipated, vibrating = ds.energy_ball_dissipated, ds.energy_vibration
    assert np.corrcoef(dissipated, vibrating)[0, 1] < -0.8
    assert abs(peak(dissipated) - peak(-vibrating)) <= 0.03, (peak(dissipated), peak(-vibrating))


def high_impact():
    ds = study("high_impact")
    rigid, one, full = (ds.vf.sel(modes=n) for n in (0, 1, 18))
    assert 0.69 <= peak(full) <= 0.73, peak(full)
    assert abs(float(full.max() / rigid.sel(z=full.idxmax())) - 1) < 0.01
    at = at_60_cm(ds)
    rigid_60, one_60, full_60 = (float(at.vf.sel(modes=n)) for n in (0, 1, 18))
    van_zandt_60 = float(at.vf_van_zandt.sel(modes=18))
    assert abs(van_zandt_60 / rigid_60 - 1) < 0.03, (van_zandt_60, rigid_60)
    assert 0.15 < 1 - full_60 / rigid_60 < 0.30, (full_60, rigid_60)  # about 20 % below
    assert full_60 < one_60 < rigid_60, (full_60, one_60, rigid_60)
    energy = study("high_impact_energy")
    low_modes = energy.mode_energy.sel(mode=slice(1, 4)).sum("mode")
    assert float(low_modes.sum() / energy.energy_vibration.sum()) > 0.9
    assert float((low_modes / energy.energy_vibration).min()) > 0.8
    assert abs(float(1e3 * energy.collision_time.median()) - 0.6) < 0.05  # ms
    assert float(abs(energy.energy_residual / energy.energy_initial).max()) < 1e-6


def e_eff():
    full, half = (study(name).e_eff.sel(z=slice(0.595, 0.805)) for name in ("e_eff_full", "e_eff_half"))
    assert float(half.mean()) > float(full.mean()), (float(half.mean()), float(full.mean()))
    assert float(abs(half - full).max()) < 0.05  # nearly equal


def pivot():
    ds = study("pivot")
    first, later = ds.sel(window=ds.window.min()), ds.sel(window=ds.window.max())

    def apart(d):
        return abs(d.vf.sel(pivot=1) / d.vf.sel(pivot=0) - 1)

    assert float(apart(first).sel(z=slice(0.48, None)).max()) < 0.01
    assert float(apart(later).sel(z=slice(0.52, None)).max()) < 0.01
    assert float(apart(later).sel(z=slice(0.48, 0.52)).max()) > 0.01  # later contacts part them
    # ... although the rigid-bat formulas for the free and the held bat differ.
    rigid = first.vf_rigid.sel(z=slice(0.52, None))
    assert float(abs(rigid.sel(pivot=1) / rigid.sel(pivot=0) - 1).max()) > 0.05


def wall():
    check_wall(study("wall"))  # collision times within 5 % of physics.md §3


def toy():
    ds = study("toy").sortby("omega_tau")
    check_toy(ds)  # the limits 1/3 and 5/7, energy closes, Van Zandt misses in between
    for end in (0, -1):  # ... and agrees at both limits
        assert abs(float(ds.vf_van_zandt[end] / ds.vf[end]) - 1) < 0.01


def force_profile():
    ds = study("force_profile")
    # Fig. 4: one universal g(omega tau) for 1-70 m/s, although tau halves and more.
    g = ds.force_response.sel(omega_tau=slice(None, 2.95))
    spread = float((g.max("ball_speed") - g.min("ball_speed")).max())
    assert spread < 0.05, spread
    assert float(ds.collision_time.sel(ball_speed=1) / ds.collision_time.sel(ball_speed=70)) > 2.5


def force_compression():
    ds = study("force_compression")
    # N2000 Fig. 2: 58 m/s on a rigid wall, e0 = 0.53, the standard ball (physics.md §3).
    m, v, e0, k1, a = 0.145, 58.0, 0.53, 6.53e7, 1.84
    assert abs(float(ds.e_eff) - e0) < 1e-4, float(ds.e_eff)  # the rebound: exactly e0 on a wall
    # The loop's area, from the sampled F(u), is the energy the ball dissipates: (1 - e0^2) of
    # its kinetic energy, all of it, since the wall takes none.
    kinetic = 0.5 * m * v * v
    area = float(np.trapz(ds.force, ds.compression))
    assert abs(area / ((1 - e0 * e0) * kinetic) - 1) < 0.01, (area, (1 - e0 * e0) * kinetic)
    assert abs(area / float(ds.energy_ball_dissipated) - 1) < 0.01, (area, float(ds.energy_ball_dissipated))
    # The ball stops where k1 u_m^(a+1) / (a+1) takes all of it, and the loop turns there.
    u_m = ((a + 1) * kinetic / k1) ** (1 / (a + 1))
    turn = int(ds.compression.argmax())
    assert abs(float(ds.compression.max()) / u_m - 1) < 1e-3, (float(ds.compression.max()), u_m)
    assert abs(float(ds.force[turn]) / (k1 * u_m ** a) - 1) < 1e-2, (float(ds.force[turn]), k1 * u_m ** a)
    # The contact ends with the ball still compressed (the force vanishes first) and the record
    # covers it: the force is zero again by the end of the window.
    assert float(ds.force[-1]) == 0 and float(ds.force[0]) == 0


def spectrum(history, frequency_hz):
    """|sum x(t) exp(-2 pi i f t)|: how strongly frequency f shows in a sampled history."""
    t = history.time.values
    return float(abs(np.sum(history.values * np.exp(-2j * np.pi * frequency_hz * t))))


def low_impact_histories():
    ds = study("histories_low")
    f = ds.frequency.values  # one bat: no bat dimension
    for probe in ds.probe.values:
        a = ds.acceleration.sel(probe=probe)
        m1, m2, m3 = (spectrum(a, f[n]) for n in range(3))
        assert m2 < 0.2 * max(m1, m3), (probe, m1, m2, m3)  # the impact is at the node of mode 2
        # 6 cm sees mode 1 most; 16 cm, near mode 1's node, mode 3.
        assert (m1 > m3) if probe < 0.1 else (m3 > m1), (probe, m1, m3)


def max_abs(x):
    return float(abs(x).max("time"))


def handle():
    ds = study("histories_handle")
    at68 = ds.sel(z=0.685)
    # Fig. 13: 13 cm is near the centre of percussion of the 68-cm impact (13.8 cm for this
    # profile): almost no rigid part; 6 and 20 cm, on either side of it, recoil opposite ways.
    rigid = at68.displacement - at68.vibration_displacement
    r6, r13, r20 = (rigid.sel(probe=p) for p in (0.06, 0.13, 0.20))
    assert max_abs(r13) < 0.15 * min(max_abs(r6), max_abs(r20)), (max_abs(r6), max_abs(r13), max_abs(r20))
    assert float(r6[-1] * r20[-1]) < 0, (float(r6[-1]), float(r20[-1]))
    # Fig. 15: the velocity at 13 cm passes 5 % of its later maximum only 0.4-0.8 ms after first
    # contact, when over 90 % of the impulse is already delivered.
    v = abs(at68.velocity.sel(probe=0.13))
    first = int(np.argmax(v.values > 0.05 * float(v.max())))
    onset = float(v.time[first])
    impulse = np.concatenate([[0], np.cumsum(np.diff(at68.time) * 0.5 * (at68.force[1:].values + at68.force[:-1].values))])
    delivered = impulse[first] / impulse[-1]
    assert 0.4e-3 <= onset <= 0.8e-3, onset
    assert delivered > 0.9, delivered
    # Fig. 14: the vibration at 13 cm is smallest for the impact at 71 cm, of 61, 71 and 81 cm.
    amplitude = [max_abs(ds.vibration_displacement.sel(z=z, probe=0.13)) for z in (0.615, 0.715, 0.815)]
    assert amplitude[1] < min(amplitude[0], amplitude[2]), amplitude


def modes():
    m = json.loads((Path(sys.argv[2]) / "modes.json").read_text())
    z = np.array(m["z_m"])
    assert len(z) == m["slices"] and len(m["shapes"]) == len(m["nodes_m"]) == 3
    paper_nodes = [[0.17, 0.68], [0.07, 0.39, 0.72], [0.05, 0.25, 0.50, 0.74]]  # physics.md §2
    for psi, nodes, paper in zip(map(np.array, m["shapes"]), m["nodes_m"], paper_nodes):
        assert abs(np.abs(psi).max() - 1) < 1e-12 and psi[-1] > 0
        crossings = z[:-1][np.sign(psi[:-1]) != np.sign(psi[1:])]
        assert len(crossings) == len(nodes) and np.all(abs(crossings + 0.005 - nodes) <= 0.005), (crossings, nodes)
        assert np.allclose(nodes, paper, atol=0.02), (nodes, paper)


if __name__ == "__main__":
    figure = sys.argv[1]
    checks = (low_impact, high_impact, e_eff, pivot, wall, toy, modes, force_compression, force_profile,
              low_impact_histories, handle)
    {f.__name__: f for f in checks}[figure]()
    print(figure, "ok")
