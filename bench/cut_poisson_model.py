#!/usr/bin/env python3
"""How many whole-grid direct solves the cut pressure problem needs (core/solvers/cut_poisson_preconditioner.hpp).

A model of the study's free fall on the sharp carrier's ghost faces: the x axis of examples/free_fall_block (100
uniform cells of 0.015 m over the 1.5 m core, 25 cells each side stretched by 1.05), 400 uniform cells along y, the
0.3 m block's sides 0.4 of a cell off the grid lines (its front and base cut their cells), p = 0 on top. The cut
matrix A (faces scaled by their open fraction, the covered cells' rows the identity) against the whole grid's L,
which the direct solve inverts; a right-hand side like a divergence (smooth near the block, noise everywhere). Prints
the direct solves each Krylov method needs to a relative residual of 1e-8 from a zero start:

    L^-1 alone (CG)                      the direct solve as PCG's preconditioner, nothing else
    window, L, window (CG)               the kept preconditioner: symmetric multiplicative Schwarz, one direct
                                         solve per iteration
    L, window (GMRES)                    the same, one-sided
    L, window, L (CG)                    symmetric the other way round, two direct solves per iteration

Usage: bench/cut_poisson_model.py [offset in cells, default 0.4] [margins, default 3 6 10 16 25]
Needs python3-numpy and python3-scipy. Measured 2026-11-27: L^-1 alone 164; window, L, window 8 (margin 6), 6 (16);
L, window (GMRES) 12 / 10; L, window, L 38 / 22 (both of its solves counted).
"""
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sl

offset = float(sys.argv[1]) if len(sys.argv) > 1 else 0.4
margins = [int(m) for m in sys.argv[2:]] or [3, 6, 10, 16, 25]

h, ny = 0.015, 400
right = [0.75]
width = h
for _ in range(25):
    width *= 1.05
    right.append(right[-1] + width)
xf = np.concatenate([-np.array(right[::-1]), np.linspace(-0.75, 0.75, 101)[1:-1], np.array(right)])
yf = np.arange(ny + 1) * h - ny * h / 2
nx = len(xf) - 1
xc, yc = 0.5 * (xf[1:] + xf[:-1]), 0.5 * (yf[1:] + yf[:-1])
bx0, bx1, by0, by1 = -0.15, 0.15, -0.15 + offset * h, 0.15 + offset * h


def inside(x, y):
    return bx0 - 1e-12 < x < bx1 + 1e-12 and by0 < y < by1


def open_fraction(a, b, lo, hi):
    return 1.0 - max(0.0, min(b, hi) - max(a, lo)) / (b - a)


def index(i, j):
    return j * nx + i


N = nx * ny
covered = np.array([all(inside(xf[a], yf[b]) for a in (i, i + 1) for b in (j, j + 1))
                    for j in range(ny) for i in range(nx)])
cut, whole = ([], [], []), ([], [], [])
diag_cut, diag_whole = np.zeros(N), np.zeros(N)


def couple(p, q, c, alpha):
    whole[0].extend([p, q]), whole[1].extend([q, p]), whole[2].extend([-c, -c])
    diag_whole[p] += c
    diag_whole[q] += c
    if alpha > 0 and not covered[p] and not covered[q]:
        cut[0].extend([p, q]), cut[1].extend([q, p]), cut[2].extend([-c * alpha] * 2)
        diag_cut[p] += c * alpha
        diag_cut[q] += c * alpha


for j in range(ny):
    for i in range(1, nx):
        alpha = open_fraction(yf[j], yf[j + 1], by0, by1) if bx0 - 1e-12 <= xf[i] <= bx1 + 1e-12 else 1.0
        couple(index(i - 1, j), index(i, j), (yf[j + 1] - yf[j]) / (xc[i] - xc[i - 1]), alpha)
for j in range(1, ny):
    for i in range(nx):
        alpha = open_fraction(xf[i], xf[i + 1], bx0, bx1) if by0 <= yf[j] <= by1 else 1.0
        couple(index(i, j - 1), index(i, j), (xf[i + 1] - xf[i]) / (yc[j] - yc[j - 1]), alpha)
for i in range(nx):  # p = 0 on the top face
    p = index(i, ny - 1)
    diag_cut[p] += (xf[i + 1] - xf[i]) / (0.5 * h)
    diag_whole[p] += (xf[i + 1] - xf[i]) / (0.5 * h)
diag_cut[covered] = diag_whole[covered]
A = sp.csr_matrix((cut[2] + list(diag_cut), (cut[0] + list(range(N)), cut[1] + list(range(N)))), shape=(N, N))
L = sp.csr_matrix((whole[2] + list(diag_whole), (whole[0] + list(range(N)), whole[1] + list(range(N)))),
                  shape=(N, N))
direct = sl.factorized(L.tocsc())
X, Y = np.meshgrid(xc, yc)
b = (np.exp(-(X**2 + Y**2) / 0.05) * np.sin(7 * X) + 0.1 * np.random.default_rng(1).standard_normal(X.shape)).ravel()
b[covered] = 0.0
print(f"{nx} x {ny} cells, {covered.sum()} covered, {(abs(A - L).sum(axis=1) > 1e-12).sum()} rows cut")

for margin in margins:
    ib = np.where((xc > bx0 - margin * h) & (xc < bx1 + margin * h))[0]
    jb = np.where((yc > by0 - margin * h) & (yc < by1 + margin * h))[0]
    W = np.array([index(i, j) for j in jb for i in ib])
    local = sl.factorized(A[W][:, W].tocsc())
    solves = [0]

    def alone(r):
        solves[0] += 1
        return direct(r)

    def window_whole_window(r):
        solves[0] += 1
        z = np.zeros(N)
        z[W] = local(r[W])
        z += direct(r - A @ z)
        z[W] += local((r - A @ z)[W])
        return z

    def whole_window(r):
        solves[0] += 1
        z = direct(r)
        z[W] += local((r - A @ z)[W])
        return z

    def whole_window_whole(r):
        solves[0] += 2
        z = direct(r)
        z[W] += local((r - A @ z)[W])
        return z + direct(r - A @ z)

    rows = [("L^-1 alone (CG)", alone, sl.cg), ("window, L, window (CG)", window_whole_window, sl.cg),
            ("L, window (GMRES)", whole_window, sl.gmres), ("L, window, L (CG)", whole_window_whole, sl.cg)]
    print(f"margin {margin} cells: window of {len(W)} cells")
    for name, apply, krylov in rows:
        if name.startswith("L^-1") and margin != margins[0]:
            continue
        solves[0] = 0
        extra = {"restart": 100} if krylov is sl.gmres else {}
        x, info = krylov(A, b, M=sl.LinearOperator((N, N), matvec=apply), tol=1e-8, maxiter=500, **extra)
        residual = np.linalg.norm(b - A @ x) / np.linalg.norm(b)
        print(f"  {name:24s} {solves[0]:4d} direct solves (relative residual {residual:.1e}, info {info})")
