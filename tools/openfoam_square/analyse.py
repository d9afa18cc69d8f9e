#!/usr/bin/python3
"""Force statistics of one case: mean C_D, C_L mean/rms over a window, Strouhal number from the
lift spectrum (peak bin + parabola through it and its two neighbours), and from upward mean
crossings as a check; y+ on the body; cells; wall time.
usage: analyse.py CASEDIR [t0 [t1]]"""
import glob, os, re, sys
import numpy as np

d = sys.argv[1]
t0 = float(sys.argv[2]) if len(sys.argv) > 2 else 20.0
t1 = float(sys.argv[3]) if len(sys.argv) > 3 else 80.0


def load_coeffs(d):
    rows, cols = [], None
    for f in sorted(glob.glob(os.path.join(d, "postProcessing/forces/*/coefficient*.dat"))
                    + glob.glob(os.path.join(d, "postProcessing/forces/*/forceCoeffs*.dat")),
                    key=lambda p: float(p.split("/")[-2])):
        for line in open(f):
            if line.startswith("#"):
                h = line[1:].split()
                if h and h[0] == "Time":
                    cols = h
                continue
            v = line.split()
            if v:
                rows.append([float(x) for x in v])
    a = np.array(rows)
    a = a[np.argsort(a[:, 0], kind="stable")]
    # keep the last value of duplicated times (restart overlap)
    _, idx = np.unique(a[::-1, 0], return_index=True)
    a = a[::-1][idx]
    return cols, a


cols, a = load_coeffs(d)
t = a[:, 0]
cd = a[:, cols.index("Cd")]
cl = a[:, cols.index("Cl")]
tend = t[-1]
t1 = min(t1, tend)
w = (t >= t0) & (t <= t1)
tw, cdw, clw = t[w], cd[w], cl[w]
# time-weighted statistics (variable time step): trapezoid
T = tw[-1] - tw[0]
mean = lambda y: np.trapz(y, tw) / T
CD = mean(cdw)
CLm = mean(clw)
CLrms = np.sqrt(mean((clw - CLm) ** 2))
CDrms = np.sqrt(mean((cdw - CD) ** 2))
# spectrum on a uniform resampling
n = max(1024, int(T / np.min(np.diff(tw))))
tu = np.linspace(tw[0], tw[-1], n)
y = np.interp(tu, tw, clw)
y = y - y.mean()
dt = tu[1] - tu[0]
F = np.abs(np.fft.rfft(y))
fr = np.fft.rfftfreq(n, dt)
k = int(np.argmax(F[1:])) + 1
if 1 <= k < len(F) - 1:
    y0, y1, y2 = F[k - 1], F[k], F[k + 1]
    den = y0 - 2 * y1 + y2
    delta = 0.5 * (y0 - y2) / den if den != 0 else 0.0
else:
    delta = 0.0
St = (k + delta) * (fr[1] - fr[0])   # D = U = 1
# check: Hann window, 16x zero padding, same parabola
Fp = np.abs(np.fft.rfft(y * np.hanning(n), 16 * n))
kp = int(np.argmax(Fp[1:])) + 1
z0, z1, z2 = Fp[kp - 1], Fp[kp], Fp[kp + 1]
St_pad = (kp + 0.5 * (z0 - z2) / (z0 - 2 * z1 + z2)) / (16 * n * dt)
# upward crossings of the mean
s = clw - CLm
up = [tw[i] - s[i] * (tw[i + 1] - tw[i]) / (s[i + 1] - s[i]) for i in range(len(s) - 1)
      if s[i] < 0 <= s[i + 1]]
St_cross = (len(up) - 1) / (up[-1] - up[0]) if len(up) >= 2 else float("nan")
# y+ on the body (yPlus function object)
yp = []
for f in glob.glob(os.path.join(d, "postProcessing/yPlus/*/yPlus.dat")):
    for line in open(f):
        v = line.split()
        if v and not line.startswith("#") and v[1] == "body":
            tt = float(v[0])
            if tt >= t0:
                yp.append((float(v[2]), float(v[3]), float(v[4])))
yp = np.array(yp) if yp else None
cells = None
mi = os.path.join(d, "MESHINFO")
if os.path.exists(mi):
    cells = int(open(mi).read().split()[1])
wall = None
if os.path.exists(os.path.join(d, "WALLTIME")):
    wall = int(open(os.path.join(d, "WALLTIME")).read().split()[1])
print("case %s" % os.path.basename(os.path.abspath(d)))
print("window %.2f-%.2f s (end of data %.2f s), samples %d" % (tw[0], tw[-1], tend, len(tw)))
print("CD_mean %.4f  CD_rms %.4f" % (CD, CDrms))
print("CL_mean %.4f  CL_rms %.4f" % (CLm, CLrms))
print("St_spectrum %.4f  (bin %.4f, %d bins)  St_hann_pad16 %.4f  St_crossings %.4f (%d upward crossings)"
      % (St, fr[1] - fr[0], len(F), St_pad, St_cross, len(up)))
if yp is not None:
    print("yplus_body min %.1f  max %.1f  mean-of-average %.1f  (over %d samples, t >= %.0f)"
          % (yp[:, 0].min(), yp[:, 1].max(), yp[:, 2].mean(), len(yp), t0))
print("cells %s  wall_seconds %s" % (cells, wall))
