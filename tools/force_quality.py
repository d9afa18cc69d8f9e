#!/usr/bin/env python3
"""Quality of the force series on a free body (issue "Forces a user can trust"), from a run's body_<name>.csv.

Over a window of the run (default: the last half), it prints
  - the mean of the hydrodynamic force (a) (forcing estimate) along the fall, and its ripple: rms and peak to
    peak of (a) about a linear trend, in % of the mean, with the dominant frequency of the ripple against the
    cell-crossing frequency |v| / h (h: the cell size across which the body moves, --cell);
  - the balance at terminal speed: (a) against the net weight (gravity + buoyancy), and the surface-stress sum
    (b) = pressure + viscous + turbulent against (a);
  - the marker slip (max and rms) in % of the body speed;
  - the start of the fall: the first steps' lengths and accelerations, against the potential-flow value
    a0 = (rho_b - rho_f) g / (rho_b + C_a rho_f) with the given added-mass coefficient C_a (per displaced
    volume; 1.19 for a square moving normal to a side, DNV-RP-H103 table A-1: C_A 1.51 on pi a^2 / 4).

    /usr/bin/python3 tools/force_quality.py results/free_fall_block --cell 0.015 --from 2 --to 4
"""
import argparse
import pathlib

import numpy as np


def load(run: pathlib.Path, body: str) -> dict:
    path = run / f"body_{body}.csv"
    data = np.genfromtxt(path, delimiter=",", names=True)
    return {name: data[name] for name in data.dtype.names}


def ripple(t: np.ndarray, f: np.ndarray) -> tuple[float, float, float]:
    """rms and peak to peak of f about its linear trend, and the ripple's dominant frequency (Hz)."""
    trend = np.polyval(np.polyfit(t, f, 1), t)
    r = f - trend
    # Steps are not uniform: resample on the mean step before the FFT.
    dt = (t[-1] - t[0]) / (len(t) - 1)
    tu = np.linspace(t[0], t[-1], len(t))
    ru = np.interp(tu, t, r)
    spectrum = np.abs(np.fft.rfft(ru * np.hanning(len(ru))))
    freq = np.fft.rfftfreq(len(ru), dt)
    peak = freq[1 + np.argmax(spectrum[1:])]
    return float(np.sqrt(np.mean(r * r))), float(r.max() - r.min()), float(peak)


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run", type=pathlib.Path, help="results folder")
    p.add_argument("--body", default="block")
    p.add_argument("--cell", type=float, required=True, help="cell size along the fall (m)")
    p.add_argument("--from", dest="t0", type=float, default=None, help="window start (s); default: half the run")
    p.add_argument("--to", dest="t1", type=float, default=None, help="window end (s); default: the end")
    p.add_argument("--added-mass", type=float, default=1.19, help="C_a per displaced volume (square: 1.19)")
    p.add_argument("--density-ratio", type=float, default=2.5, help="rho_b / rho_f")
    p.add_argument("--gravity", type=float, default=9.81)
    a = p.parse_args()

    s = load(a.run, a.body)
    t = s["t"]
    t0 = a.t0 if a.t0 is not None else 0.5 * t[-1]
    t1 = a.t1 if a.t1 is not None else t[-1]
    w = (t >= t0) & (t <= t1)
    speed = np.hypot(s["u"][w], s["v"][w])
    fa = s["fy_forcing"][w]
    fb = s["fy_surface"][w]
    net = -(s["fy_gravity"][w] + s["fy_buoyancy"][w])
    rms, p2p, peak = ripple(t[w], fa)
    crossing = speed.mean() / a.cell
    mean = fa.mean()
    print(f"window {t0:g}-{t1:g} s, {w.sum()} steps, mean speed {speed.mean():.4g} m/s")
    print(f"(a) mean {mean:.5g} N; ripple rms {100 * rms / abs(mean):.2f} %, peak to peak {100 * p2p / abs(mean):.1f} %, "
          f"at {peak:.4g} Hz (cell crossing |v|/h = {crossing:.4g} Hz)")
    print(f"net weight {net.mean():.5g} N: (a) / net = {mean / net.mean():.4f}")
    parts = {k: s[f"fy_{k}"][w].mean() for k in ("pressure", "viscous", "turbulent")}
    print(f"(b) mean {fb.mean():.5g} N = pressure {parts['pressure']:.5g} + viscous {parts['viscous']:.5g} + "
          f"turbulent {parts['turbulent']:.5g}; (b) / (a) = {fb.mean() / mean:.4f}")
    print(f"slip: max {100 * s['max_slip'][w].max() / speed.mean():.2f} %, rms {100 * np.sqrt(np.mean(s['rms_slip'][w] ** 2)) / speed.mean():.2f} % of the speed")
    rb = a.density_ratio
    a0 = (rb - 1.0) * a.gravity / (rb + a.added_mass)
    print(f"start: potential-flow a0 = {a0:.4g} m/s^2 (C_a {a.added_mass}); first steps:")
    for k in range(1, min(6, len(t))):
        print(f"  step {k}: dt {t[k] - t[k - 1]:.4g} s, a_y {s['ay'][k]:.4g} m/s^2, (a) {s['fy_forcing'][k]:.5g} N")


if __name__ == "__main__":
    main()
