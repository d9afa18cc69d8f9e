#!/usr/bin/python3
"""Generate OpenFOAM (v1912, Debian package) cases for the square cylinder at Re 22,000
(Lyn et al. 1995) with standard k-epsilon URANS, body-fitted structured meshes made by blockMesh.

Cases (directory names):
  aligned20   square aligned with the stream; Cartesian H-grid identical to Chute's
              examples/square_cylinder_re22000 grid (uniform 0.05 D core [-1,4]x[-1.5,1.5],
              geometric stretching 1.06 outside), square cut out body-fitted.
  rotNN_MM    square turned NN degrees, MM cells per side: a rotated H-grid around the square
              (12 blocks, rotated frame) out to a rotated square of half-side S, then a ring of 16
              blocks from that rotated square to the rectangular domain.

usage: make_cases.py OUTDIR [case ...]     (default: all of aligned20 rot45_20 rot45_30 rot22.5_20)
"""
import math, os, sys

# ----------------------------------------------------------------------------- physics
D, U0, NU = 1.0, 1.0, 4.5454545e-5
TI, LSC = 0.02, 0.1
K_IN = 1.5 * (TI * U0) ** 2                      # 6e-4
EPS_IN = 0.09 ** 0.75 * K_IN ** 1.5 / (LSC * D)  # 2.415e-5
OMEGA_IN = EPS_IN / (0.09 * K_IN)                 # for the kOmegaSST side runs
X0, X1, Y0, Y1 = -5.0, 15.0, -7.0, 7.0
THICK = 1.0                                       # z thickness; Aref = D * THICK
END_TIME = 80.0


def solve_ratio(n, h0, length):
    """r such that h0 * (1 + r + ... + r^(n-1)) = length (r may be < 1)."""
    f = lambda r: h0 * n - length if abs(r - 1) < 1e-12 else h0 * (r ** n - 1) / (r - 1) - length
    lo, hi = 0.5, 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def n_for(h0, length, r):
    """number of geometric cells, first h0, ratio r, to cover length (rounded)."""
    return max(1, round(math.log(1 + length * (r - 1) / h0) / math.log(r)))


# ----------------------------------------------------------------------------- block mesh writer
class Mesh:
    def __init__(self):
        self.pts = []          # 2D vertices
        self.blocks = []       # (vertex ids p0..p3, n1, n2, g(p0p1), g(p3p2), g(p0p3), g(p1p2))
        self.edges = {}        # (i, j) -> (n, ratio i->j)
        self.patches = {}      # name -> list of (i, j) 2D edges

    def vid(self, p):
        for k, q in enumerate(self.pts):
            if abs(p[0] - q[0]) < 1e-9 and abs(p[1] - q[1]) < 1e-9:
                return k
        self.pts.append((float(p[0]), float(p[1])))
        return len(self.pts) - 1

    def edge(self, i, j, n, g):
        if (j, i) in self.edges:
            n2, g2 = self.edges[(j, i)]
            i, j, g = j, i, 1.0 / g
        else:
            n2, g2 = self.edges.get((i, j), (n, g))
        assert n2 == n and abs(g2 - g) < 1e-9 * max(g, 1), ("inconsistent edge", i, j, n, g, n2, g2)
        self.edges[(i, j)] = (n, g)

    def block(self, p, n1, n2, g01, g32, g03, g12):
        ids = [self.vid(q) for q in p]
        # CCW check
        a = sum(self.pts[ids[k]][0] * self.pts[ids[(k + 1) % 4]][1]
                - self.pts[ids[(k + 1) % 4]][0] * self.pts[ids[k]][1] for k in range(4))
        assert a > 0, "block not counter-clockwise"
        self.edge(ids[0], ids[1], n1, g01)
        self.edge(ids[3], ids[2], n1, g32)
        self.edge(ids[0], ids[3], n2, g03)
        self.edge(ids[1], ids[2], n2, g12)
        self.blocks.append((ids, n1, n2, g01, g32, g03, g12))
        return ids

    def patch(self, name, p, q):
        self.patches.setdefault(name, []).append((self.vid(p), self.vid(q)))

    def write(self, path, types):
        nv = len(self.pts)
        L = ["FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }",
             "scale 1;", "vertices", "("]
        for (x, y) in self.pts:
            L.append("    (%.10g %.10g 0)" % (x, y))
        for (x, y) in self.pts:
            L.append("    (%.10g %.10g %g)" % (x, y, THICK))
        L += [");", "blocks", "("]
        ncell = 0
        for ids, n1, n2, g01, g32, g03, g12 in self.blocks:
            v = ids + [i + nv for i in ids]
            L.append("    hex (%s) (%d %d 1) edgeGrading (%.10g %.10g %.10g %.10g  %.10g %.10g %.10g %.10g  1 1 1 1)"
                     % (" ".join(map(str, v)), n1, n2,
                        g01, g32, g32, g01, g03, g12, g12, g03))
            ncell += n1 * n2
        L += [");", "edges ( );", "boundary", "("]
        for name, lst in self.patches.items():
            L.append("    %s { type %s; faces (" % (name, types[name]))
            for i, j in lst:
                # outward normal for boundary faces: blockMesh accepts either order for a
                # boundary face, but keep (i j j+nv i+nv)
                L.append("        (%d %d %d %d)" % (i, j, j + nv, i + nv))
            L.append("    ); }")
        fb = []
        for ids, *_ in self.blocks:
            fb.append("        (%d %d %d %d)" % (ids[0], ids[3], ids[2], ids[1]))
            fb.append("        (%d %d %d %d)" % tuple(i + nv for i in ids))
        L.append("    frontAndBack { type empty; faces (")
        L += fb
        L.append("    ); }")
        L += [");", "mergePatchPairs ( );"]
        with open(path, "w") as f:
            f.write("\n".join(L) + "\n")
        return ncell


def expansion(n, r):
    """blockMesh expansion ratio (last/first) for n cells growing by r."""
    return r ** (n - 1)


# ----------------------------------------------------------------------------- aligned Cartesian H-grid
def mesh_aligned(h=0.05, ratio=1.06):
    """Chute's clustered grid: uniform h on core [-1,4]x[-1.5,1.5], geometric ratio outside."""
    m = Mesh()
    xs = [X0, -1.0, -0.5, 0.5, 4.0, X1]
    ys = [Y0, -1.5, -0.5, 0.5, 1.5, Y1]

    def seg(a, b, fine_at):   # returns (n, expansion in + direction)
        Lg = b - a
        if fine_at is None:
            return round(Lg / h), 1.0
        n = n_for(h * ratio, Lg, ratio)
        r = solve_ratio(n, h * ratio, Lg)
        E = r ** (n - 1)
        return n, (E if fine_at == "a" else 1.0 / E)

    sx = [seg(xs[0], xs[1], "b"), seg(xs[1], xs[2], None), seg(xs[2], xs[3], None),
          seg(xs[3], xs[4], None), seg(xs[4], xs[5], "a")]
    sy = [seg(ys[0], ys[1], "b"), seg(ys[1], ys[2], None), seg(ys[2], ys[3], None),
          seg(ys[3], ys[4], None), seg(ys[4], ys[5], "a")]
    for i in range(5):
        for j in range(5):
            if i == 2 and j == 2:
                continue
            p = [(xs[i], ys[j]), (xs[i + 1], ys[j]), (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1])]
            m.block(p, sx[i][0], sy[j][0], sx[i][1], sx[i][1], sy[j][1], sy[j][1])
    for j in range(5):
        m.patch("inlet", (X0, ys[j + 1]), (X0, ys[j]))
        m.patch("outlet", (X1, ys[j]), (X1, ys[j + 1]))
    for i in range(5):
        m.patch("bottom", (xs[i], Y0), (xs[i + 1], Y0))
        m.patch("top", (xs[i + 1], Y1), (xs[i], Y1))
    a, b = -0.5, 0.5
    m.patch("body", (a, a), (a, b)); m.patch("body", (a, b), (b, b))
    m.patch("body", (b, b), (b, a)); m.patch("body", (b, a), (a, a))
    info = dict(sx=sx, sy=sy)
    return m, info


# ----------------------------------------------------------------------------- rotated H-grid + ring
def mesh_rotated(theta_deg, nside=20, Lu=1.5, Ld=3.5, nO=None, ratio_in=1.03):
    """Square of side D turned theta about the origin; body-fitted rotated H-grid out to the rotated
    rectangle xi in [-Su, Sd], eta in [-Sd, Su] (rotated frame, S = 0.5 + L; the corner (Sd, -Sd)
    points downstream for theta = 45), then 16 ring blocks to the domain rectangle."""
    th = math.radians(theta_deg)
    c, s = math.cos(th), math.sin(th)
    rot = lambda xi, et: (c * xi - s * et, s * xi + c * et)
    h = D / nside
    Su, Sd = 0.5 + Lu, 0.5 + Ld
    nu_ = n_for(h, Lu, ratio_in)
    nd_ = n_for(h, Ld, ratio_in)
    Eu = solve_ratio(nu_, h, Lu) ** (nu_ - 1)
    Ed = solve_ratio(nd_, h, Ld) ** (nd_ - 1)
    hu, hd = h * Eu, h * Ed
    m = Mesh()
    qx = [-Su, -0.5, 0.0, 0.5, Sd]
    qy = [-Sd, -0.5, 0.0, 0.5, Su]
    sx = [(nu_, 1.0 / Eu), (nside // 2, 1.0), (nside // 2, 1.0), (nd_, Ed)]
    sy = [(nd_, 1.0 / Ed), (nside // 2, 1.0), (nside // 2, 1.0), (nu_, Eu)]
    for i in range(4):
        for j in range(4):
            if i in (1, 2) and j in (1, 2):
                continue
            p = [rot(qx[i], qy[j]), rot(qx[i + 1], qy[j]), rot(qx[i + 1], qy[j + 1]), rot(qx[i], qy[j + 1])]
            m.block(p, sx[i][0], sy[j][0], sx[i][1], sx[i][1], sy[j][1], sy[j][1])
    nL, h_last, S = (nu_, nd_), max(hu, hd), (Su, Sd)
    # body patch (rotated frame square [-0.5,0.5]^2, four sides split at 0)
    bq = [(0.5, -0.5), (0.5, 0.0), (0.5, 0.5), (0.0, 0.5), (-0.5, 0.5), (-0.5, 0.0),
          (-0.5, -0.5), (0.0, -0.5)]
    for k in range(8):
        a, b = bq[k], bq[(k + 1) % 8]
        m.patch("body", rot(*b), rot(*a))
    # boundary of the inner region, CCW, in rotated frame, with the 2D edge data
    ring, hl = [], []
    for et in qy[:-1]:
        ring.append((Sd, et)); hl.append(hd if et != -Sd else max(hu, hd))
    for xi in qx[::-1][:-1]:
        ring.append((xi, Su)); hl.append(hu if xi != Sd else max(hu, hd))
    for et in qy[::-1][:-1]:
        ring.append((-Su, et)); hl.append(hu if et != Su else max(hu, hd))
    for xi in qx[:-1]:
        ring.append((xi, -Sd)); hl.append(hd if xi != -Su else max(hu, hd))
    P = [rot(*p) for p in ring]
    nP = len(P)
    ang = [math.atan2(y, x) % (2 * math.pi) for x, y in P]
    # rectangle corners CCW from the upper right
    RC = [(X1, Y1), (X0, Y1), (X0, Y0), (X1, Y0)]
    rc_ang = [math.atan2(y, x) % (2 * math.pi) for x, y in RC]
    assign = {}
    for ci, a in enumerate(rc_ang):
        best = min((k for k in range(nP) if k not in assign.values()),
                   key=lambda k: abs((ang[k] - a + math.pi) % (2 * math.pi) - math.pi))
        assign[ci] = best
    # rectangle sides between consecutive corners: place intermediate ring points by arc length
    plen = [math.dist(P[k], P[(k + 1) % nP]) for k in range(nP)]
    R = [None] * nP
    for ci in range(4):
        k0, k1 = assign[ci], assign[(ci + 1) % 4]
        A, B = RC[ci], RC[(ci + 1) % 4]
        ks = [k0]
        k = k0
        while k != k1:
            k = (k + 1) % nP
            ks.append(k)
        # intermediate points: ray from the origin through the ring point, cut with side AB
        fs = []
        for kk in ks:
            dx, dy = P[kk]
            ex, ey = B[0] - A[0], B[1] - A[1]
            det = dx * (-ey) - dy * (-ex)
            f = (dx * A[1] - dy * A[0]) / det if abs(det) > 1e-12 else 0.5
            fs.append(f)
        fs[0], fs[-1] = 0.0, 1.0
        ok = all(0.0 <= fs[t] < fs[t + 1] <= 1.0 for t in range(len(fs) - 1))
        if not ok:   # fall back on arc length
            tot = sum(plen[ks[t]] for t in range(len(ks) - 1))
            fs, acc = [], 0.0
            for t, kk in enumerate(ks):
                fs.append(acc / tot)
                if t < len(ks) - 1:
                    acc += plen[kk]
        for kk, f in zip(ks, fs):
            R[kk] = (A[0] + f * (B[0] - A[0]), A[1] + f * (B[1] - A[1]))
    if nO is None:
        nO = round(30 * nside / 20)
    g_rad = []
    for k in range(nP):
        Lr = math.dist(P[k], R[k])
        r = solve_ratio(nO, hl[k] * 1.04, Lr)
        g_rad.append(max(r, 1.0) ** (nO - 1))   # short edges: uniform (finer) cells
    for k in range(nP):
        k1 = (k + 1) % nP
        i, j = m.vid(P[k]), m.vid(P[k1])
        if (i, j) in m.edges:
            nt, gt = m.edges[(i, j)]
        else:
            nt, g = m.edges[(j, i)]
            gt = 1.0 / g
        m.block([P[k], R[k], R[k1], P[k1]], nO, nt, g_rad[k], g_rad[k1], gt, gt)
        # patch for the outer edge R[k] -> R[k1]
        (xa, ya), (xb, yb) = R[k], R[k1]
        if abs(xa - X1) < 1e-9 and abs(xb - X1) < 1e-9:
            name = "outlet"
        elif abs(xa - X0) < 1e-9 and abs(xb - X0) < 1e-9:
            name = "inlet"
        elif abs(ya - Y1) < 1e-9 and abs(yb - Y1) < 1e-9:
            name = "top"
        elif abs(ya - Y0) < 1e-9 and abs(yb - Y0) < 1e-9:
            name = "bottom"
        else:
            raise RuntimeError("ring edge not on one rectangle side: %s %s" % (R[k], R[k1]))
        m.patch(name, R[k], R[k1])
    info = dict(h=h, S=S, nL=nL, h_last=(hu, hd), nO=nO,
                g_rad=[round(g, 3) for g in g_rad])
    return m, info


# ----------------------------------------------------------------------------- case files
HDR = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"

PATCH_TYPES = dict(inlet="patch", outlet="patch", top="patch", bottom="patch", body="wall")


def field(cls, name, dim, internal, bcs):
    s = HDR % (cls, name) + "dimensions %s;\ninternalField uniform %s;\nboundaryField\n{\n" % (dim, internal)
    for p, bc in bcs.items():
        s += "    %s { %s }\n" % (p, bc)
    s += "    frontAndBack { type empty; }\n}\n"
    return s


def write_case(d, mesh, info, nside, model="kEpsilon"):
    for sub in ("system", "constant", "0.orig"):
        os.makedirs(os.path.join(d, sub), exist_ok=True)
    ncell = mesh.write(os.path.join(d, "system", "blockMeshDict"), PATCH_TYPES)
    U = "(%g 0 0)" % U0
    slip = "type slip;"
    files = {
        "0.orig/U": field("volVectorField", "U", "[0 1 -1 0 0 0 0]", U, dict(
            inlet="type fixedValue; value uniform %s;" % U,
            outlet="type inletOutlet; inletValue uniform (0 0 0); value uniform %s;" % U,
            top=slip, bottom=slip, body="type noSlip;")),
        "0.orig/p": field("volScalarField", "p", "[0 2 -2 0 0 0 0]", "0", dict(
            inlet="type zeroGradient;", outlet="type fixedValue; value uniform 0;",
            top=slip, bottom=slip, body="type zeroGradient;")),
        "0.orig/k": field("volScalarField", "k", "[0 2 -2 0 0 0 0]", "%.6g" % K_IN, dict(
            inlet="type fixedValue; value uniform %.6g;" % K_IN,
            outlet="type inletOutlet; inletValue uniform %.6g; value uniform %.6g;" % (K_IN, K_IN),
            top=slip, bottom=slip, body="type kqRWallFunction; value uniform %.6g;" % K_IN)),
        "0.orig/epsilon": field("volScalarField", "epsilon", "[0 2 -3 0 0 0 0]", "%.6g" % EPS_IN, dict(
            inlet="type fixedValue; value uniform %.6g;" % EPS_IN,
            outlet="type inletOutlet; inletValue uniform %.6g; value uniform %.6g;" % (EPS_IN, EPS_IN),
            top=slip, bottom=slip, body="type epsilonWallFunction; value uniform %.6g;" % EPS_IN)),
        "0.orig/omega": field("volScalarField", "omega", "[0 0 -1 0 0 0 0]", "%.6g" % OMEGA_IN, dict(
            inlet="type fixedValue; value uniform %.6g;" % OMEGA_IN,
            outlet="type inletOutlet; inletValue uniform %.6g; value uniform %.6g;" % (OMEGA_IN, OMEGA_IN),
            top=slip, bottom=slip, body="type omegaWallFunction; value uniform %.6g;" % OMEGA_IN)),
        "0.orig/nut": field("volScalarField", "nut", "[0 2 -1 0 0 0 0]", "0", dict(
            inlet="type calculated; value uniform 0;", outlet="type calculated; value uniform 0;",
            top="type calculated; value uniform 0;", bottom="type calculated; value uniform 0;",
            body="type nutkWallFunction; value uniform 0;")),
        "constant/transportProperties": HDR % ("dictionary", "transportProperties")
        + "transportModel Newtonian;\nnu %.8g;\n" % NU,
        "constant/turbulenceProperties": HDR % ("dictionary", "turbulenceProperties")
        + "simulationType RAS;\nRAS\n{\n    RASModel %s;\n" % model + "    turbulence on;\n    printCoeffs on;\n}\n",
        "system/controlDict": HDR % ("dictionary", "controlDict") + """
application pimpleFoam;
startFrom latestTime;
startTime 0;
stopAt endTime;
endTime %g;
deltaT 0.002;
writeControl adjustableRunTime;
writeInterval 10;
purgeWrite 0;
writeFormat ascii;
writePrecision 8;
timeFormat general;
timePrecision 8;
runTimeModifiable true;
adjustTimeStep yes;
maxCo 0.7;
maxDeltaT 0.05;
functions
{
    forces
    {
        type forceCoeffs;
        libs ("libforces.so");
        writeControl timeStep;
        writeInterval 1;
        log false;
        patches (body);
        rho rhoInf;
        rhoInf 1;
        liftDir (0 1 0);
        dragDir (1 0 0);
        CofR (0 0 0);
        pitchAxis (0 0 1);
        magUInf %g;
        lRef %g;
        Aref %g;
    }
    yPlus
    {
        type yPlus;
        libs ("libfieldFunctionObjects.so");
        writeControl timeStep;
        writeInterval 200;
        log false;
    }
}
""" % (END_TIME, U0, D, D * THICK),
        "system/fvSchemes": HDR % ("dictionary", "fvSchemes") + """
ddtSchemes { default backward; }
gradSchemes { default Gauss linear; }
divSchemes
{
    default none;
    div(phi,U) Gauss linearUpwind grad(U);
    div(phi,k) Gauss limitedLinear 1;
    div(phi,epsilon) Gauss limitedLinear 1;
    div(phi,omega) Gauss limitedLinear 1;
    div((nuEff*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear limited corrected 0.5; }
interpolationSchemes { default linear; }
snGradSchemes { default limited corrected 0.5; }
wallDist { method meshWave; }
""",
        "system/fvSolution": HDR % ("dictionary", "fvSolution") + """
solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-7; relTol 0.01; }
    pFinal { $p; relTol 0; tolerance 1e-7; }
    "(U|k|epsilon|omega)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0.1; }
    "(U|k|epsilon|omega)Final" { $U; relTol 0; }
}
PIMPLE
{
    momentumPredictor yes;
    nOuterCorrectors 1;
    nCorrectors 2;
    nNonOrthogonalCorrectors 1;
}
""",
        # asymmetric start: a cross-flow patch behind the body (only the initial field)
        "system/setFieldsDict": HDR % ("dictionary", "setFieldsDict") + """
defaultFieldValues ( );
regions
(
    boxToCell { box (0.6 0 -1) (3 1.5 2); fieldValues ( volVectorFieldValue U (1 0.15 0) ); }
);
""",
    }
    for k, v in files.items():
        with open(os.path.join(d, k), "w") as f:
            f.write(v)
    with open(os.path.join(d, "MESHINFO"), "w") as f:
        f.write("cells %d\nnside %d\n%s\n" % (ncell, nside, info))
    return ncell


CASES = {
    "aligned20": lambda: (mesh_aligned(), 20),
    "rot45_20": lambda: (mesh_rotated(45.0, 20), 20),
    "rot45_30": lambda: (mesh_rotated(45.0, 30), 30),
    "rot22.5_20": lambda: (mesh_rotated(22.5, 20), 20),
    "rot0_20": lambda: (mesh_rotated(0.0, 20), 20),     # aligned square on the diamond's topology
}

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    names = sys.argv[2:] or ["aligned20", "rot45_20", "rot45_30", "rot22.5_20"]
    for nm in names:
        base, model = (nm[:-4], "kOmegaSST") if nm.endswith("_sst") else (nm, "kEpsilon")
        (m, info), ns = CASES[base]()
        nc = write_case(os.path.join(out, nm), m, info, ns, model)
        print(nm, model, "cells", nc, info)
