#!/usr/bin/env python3
"""The force on a body from a control-volume momentum balance, to check the force measures (a) and (b).

From a run's newest checkpoint (the staggered u, v, p, k, epsilon and the grid lines) and its body_<name>.csv, on
rectangles around the body at several distances from its sides, it sums along the motion (y):
  - the momentum flux out, relative to the body (rho v (u - U_b) . n),
  - the pressure on the rectangle (p n),
  - the viscous and turbulent stress (nu + C_mu k^2 / epsilon) (grad v + grad v^T) . n,
and prints the force on the body they give (minus their sum) beside (a) and (b) of the same step. With the flow
steady in the body's frame (a terminal fall, a window following the body), the rectangle's result is the force
the body feels, whatever the distance (docs/validation.md, "A window that moves by whole cells").

    /usr/bin/python3 tools/control_volume_force.py results/free_fall_block --half-width 0.15 --cell 0.015

Assumes a rectangle-shaped body whose sides are `--half-width` from its centre and cells of size `--cell` near it.
"""
import argparse
import glob
import pathlib

import h5py
import numpy as np

C_MU = 0.09


def balance(run, body, half, viscosity, density):
    checkpoint = sorted(glob.glob(str(run / "checkpoint_*.h5")))[-1]
    f = h5py.File(checkpoint, "r")
    X, Y = f["grid/x_lines"][:], f["grid/y_lines"][:]
    u, v, p = f["fields/u"][:], f["fields/v"][:], f["fields/p"][:]
    nu = np.full(p.shape, viscosity)
    if "fields/k" in f:
        k, e = f["fields/k"][:], f["fields/epsilon"][:]
        nu = nu + np.where(e > 0, C_MU * k * k / np.maximum(e, 1e-30), 0.0)
    b = np.genfromtxt(run / f"body_{body}.csv", delimiter=",", names=True)
    step = int(f.attrs["step"]) if "step" in f.attrs else len(b) - 1
    row = b[min(step, len(b) - 1)]
    xc, yc, V = row["x"], row["y"], row["v"]
    xcen, ycen = 0.5 * (X[1:] + X[:-1]), 0.5 * (Y[1:] + Y[:-1])
    dx, dy = np.diff(X), np.diff(Y)
    i0, i1 = np.argmin(abs(X - (xc - half))), np.argmin(abs(X - (xc + half)))
    j0, j1 = np.argmin(abs(Y - (yc - half))), np.argmin(abs(Y - (yc + half)))
    flux = press = stress = 0.0
    for j, sign in ((j1, 1), (j0, -1)):  # faces across y: v on them, p and nu averaged from the cells beside
        i = np.arange(i0, i1)
        flux += np.sum(v[j, i] * (v[j, i] - V) * sign * dx[i])
        press += np.sum(0.5 * (p[j - 1, i] + p[j, i]) * sign * dx[i])
        dvdy = (v[j + 1, i] - v[j - 1, i]) / (Y[j + 1] - Y[j - 1])
        stress += np.sum(2 * 0.5 * (nu[j - 1, i] + nu[j, i]) * dvdy * sign * dx[i])
    for i, sign in ((i1, 1), (i0, -1)):  # faces across x: u on them, v at the cell centres beside
        j = np.arange(j0, j1)
        vc = 0.25 * (v[j, i - 1] + v[j, i] + v[j + 1, i - 1] + v[j + 1, i])
        flux += np.sum(vc * u[j, i] * sign * dy[j])
        dvdx = (0.5 * (v[j, i] + v[j + 1, i]) - 0.5 * (v[j, i - 1] + v[j + 1, i - 1])) / (xcen[i] - xcen[i - 1])
        dudy = (u[j + 1, i] - u[j - 1, i]) / (ycen[j + 1] - ycen[j - 1])
        stress += np.sum(0.5 * (nu[j, i - 1] + nu[j, i]) * (dvdx + dudy) * sign * dy[j])
    # Per unit depth; the fields are kinematic (p / rho).
    return (-density * flux, -density * press, density * stress, row["fy_forcing"], row["fy_surface"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", type=pathlib.Path, help="results folder of the run")
    parser.add_argument("--body", default="block")
    parser.add_argument("--half-width", type=float, required=True, help="half the body's width (m)")
    parser.add_argument("--cell", type=float, required=True, help="cell size near the body (m)")
    parser.add_argument("--cells-out", type=float, nargs="+", default=[1.5, 2.5, 3.5, 4.5, 6.5])
    parser.add_argument("--viscosity", type=float, default=1.0e-6)
    parser.add_argument("--density", type=float, default=1000.0)
    a = parser.parse_args()
    for n in a.cells_out:
        flux, press, stress, forcing, surface = balance(a.run, a.body, a.half_width + n * a.cell, a.viscosity,
                                                        a.density)
        print(f"rectangle {n:4.1f} cells out: momentum flux {flux:8.1f}  pressure {press:8.1f}  stress {stress:7.1f}"
              f"  force {flux + press + stress:8.1f} N/m | (a) {forcing:8.1f} (b) {surface:8.1f}")


if __name__ == "__main__":
    main()
