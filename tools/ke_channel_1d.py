#!/usr/bin/python3
"""Independent 1D fully developed channel solver: standard k-epsilon + k-based
log-law wall functions (OpenFOAM nutkWallFunction / epsilonWallFunction style).

Why it is here: it checks Chute's 2D channel (examples/turbulent_channel) against a separate code, and
finds the grid-converged answer of the model. With P_k from face gradients (pk='face', Chute's choice)
it reproduces Chute's U_b+ to 4 digits (19.0965 against 19.096 at Re_tau 550, 20 cells); with the first
cell kept at y+ 27.5 and the outer region refined, the model converges to U_b+ 19.335 (550) and 20.683
(950): docs/validation.md, "Turbulent channel". Run by hand: /usr/bin/python3 tools/ke_channel_1d.py
(about a minute; needs numpy and scipy).

Nondimensional: delta=1, u_tau=1, nu=1/Re_tau, dp/dx=-1 (source 1 in momentum).
Cell-centred FV on y in [0,1] (wall at 0, symmetry at 1).
Unknowns per cell: U, ln k, ln eps. Steady residuals solved by pseudo-transient
continuation + Newton (finite-difference Jacobian with 3-colour banded colouring).
"""
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

class KEChannel:
    def __init__(self, Re_tau, faces, Cmu=0.09, C1=1.44, C2=1.92, sk=1.0, se=1.3,
                 kappa=0.41, E=9.8, yplam=11.53, pk='gauss'):
        self.pk = pk   # 'gauss': Gauss-linear cell gradient (OpenFOAM fvc::grad); 'face': mean of face-gradient^2
        self.nu = 1.0 / Re_tau
        self.yf = np.asarray(faces, float)          # face positions, yf[0]=0, yf[-1]=1
        self.N = len(self.yf) - 1
        self.h = np.diff(self.yf)                   # cell volumes
        self.yc = 0.5 * (self.yf[1:] + self.yf[:-1])
        self.dc = np.diff(self.yc)                  # centre-to-centre distances (interior faces)
        # linear-interpolation weight of cell i at interior face i+1/2
        self.w = (self.yc[1:] - self.yf[1:-1]) / self.dc
        self.Cmu, self.C1, self.C2, self.sk, self.se = Cmu, C1, C2, sk, se
        self.kappa, self.E, self.yplam = kappa, E, yplam
        self.yP = self.yc[0]

    def fields(self, x):
        N = self.N
        U = x[:N]; k = np.exp(x[N:2*N]); eps = np.exp(x[2*N:])
        return U, k, eps

    def wall(self, U, k):
        nu, yP = self.nu, self.yP
        ustar = self.Cmu**0.25 * np.sqrt(k[0])
        yp = ustar * yP / nu
        nuw = nu * (self.kappa * yp / np.log(self.E * yp) - 1.0) if yp > self.yplam else 0.0
        tauw = (nu + nuw) * U[0] / yP
        return ustar, yp, nuw, tauw

    def residual(self, x, detail=False):
        N, nu, h = self.N, self.nu, self.h
        U, k, eps = self.fields(x)
        nut = self.Cmu * k**2 / eps
        w = self.w
        nutf = w * nut[:-1] + (1 - w) * nut[1:]          # interior faces
        ustar, yp, nuw, tauw = self.wall(U, k)

        def diff(phi, gam_f):
            F = gam_f * (phi[1:] - phi[:-1]) / self.dc    # flux in +y direction at interior faces
            net = np.zeros(N)
            net[:-1] += F        # top face of cell i (gradient-driven flux into cell from above)
            net[1:] -= F         # bottom face of cell i+1
            return net

        # momentum
        RU = diff(U, nu + nutf) + 1.0 * h
        RU[0] -= tauw                                    # wall shear flux out of cell 0
        # Gauss-linear gradient at cell centres
        Uf = np.empty(N + 1)
        Uf[0] = 0.0
        Uf[1:-1] = w * U[:-1] + (1 - w) * U[1:]
        Uf[-1] = U[-1]                                   # symmetry
        dUdy = (Uf[1:] - Uf[:-1]) / h
        Pk = nut * dUdy**2
        if self.pk == 'face':
            g = np.zeros(N + 1); g[0] = U[0] / self.yP; g[1:-1] = (U[1:] - U[:-1]) / self.dc
            Pk = nut * 0.5 * (g[1:]**2 + g[:-1]**2)
        Pk[0] = tauw * ustar / (self.kappa * self.yP)
        # k
        Rk = diff(k, nu + nutf / self.sk) + (Pk - eps) * h
        # eps
        Re = diff(eps, nu + nutf / self.se) + (self.C1 * Pk - self.C2 * eps) * eps / k * h
        eps_wf = self.Cmu**0.75 * k[0]**1.5 / (self.kappa * self.yP)
        Re[0] = (eps[0] - eps_wf) * h[0]
        R = np.concatenate([RU, Rk, Re])
        if detail:
            return R, dict(U=U, k=k, eps=eps, nut=nut, Pk=Pk, ustar=ustar, yplus=yp,
                           nuw=nuw, tauw=tauw)
        return R

    def scale(self, x):
        # pseudo-time "mass" per unknown: V, V*k, V*eps  (unknowns are ln k, ln eps)
        U, k, eps = self.fields(x)
        return np.concatenate([self.h, self.h * k, self.h * eps])

    def jac(self, x, F):
        """Banded FD Jacobian by 3-colour grouping of cells (stencil i-1..i+1)."""
        N = self.N
        n = 3 * N
        rows, cols, vals = [], [], []
        F0 = F(x)
        cell = np.arange(n) % N
        for var in range(3):
            for c in range(3):
                idx = np.arange(var * N + c, (var + 1) * N, 3)
                if idx.size == 0:
                    continue
                d = 1e-7 * np.maximum(1.0, np.abs(x[idx]))
                xp = x.copy(); xp[idx] += d
                dF = (F(xp) - F0)
                # assign each row to the perturbed column whose cell is within 1
                jcell = cell[idx]
                owner = -np.ones(N, int)
                for j, jc in zip(range(idx.size), jcell):
                    for m in (jc - 1, jc, jc + 1):
                        if 0 <= m < N:
                            owner[m] = j
                # wall quantities (cell 0) only couple cells 0,1 -> fine
                jr = owner[cell]
                r = np.nonzero((jr >= 0) & (dF != 0.0))[0]
                rows.append(r); cols.append(idx[jr[r]]); vals.append(dF[r] / d[jr[r]])
        rows = np.concatenate(rows); cols = np.concatenate(cols); vals = np.concatenate(vals)
        return sp.csc_matrix((vals, (rows, cols)), shape=(n, n))

    def initial(self):
        y = self.yc; nu = self.nu
        yp = y / nu
        U = np.where(yp > 11, np.log(self.E * yp) / self.kappa, yp)
        k = np.maximum(1.0 / np.sqrt(self.Cmu) * (1 - y), 0.3)
        eps = self.Cmu**0.75 * k**1.5 / (self.kappa * y)
        return np.concatenate([U, np.log(k), np.log(eps)])

    def interp_from(self, other):
        """initial guess interpolated (in y) from another converged model"""
        N, M = self.N, other.N
        xs = other.x
        return np.concatenate([np.interp(self.yc, other.yc, xs[i*M:(i+1)*M]) for i in range(3)])

    def solve(self, x0=None, dt0=1e-3, tol=1e-11, maxit=3000, verbose=False):
        """Implicit (backward-Euler) pseudo-time marching, each step solved by Newton
        (<= 8 iterations, ln k / ln eps change limited to 1 per iteration), dt grows
        x3 per step while the steady residual falls (x1.2 otherwise); a step whose
        Newton solve produces non-finite values is rejected and dt cut.  Finished by
        pure Newton steps on the steady residual (accepted only if they reduce it)."""
        x = self.initial() if x0 is None else x0.copy()
        dt = dt0
        r0 = np.linalg.norm(self.residual(x))
        for it in range(maxit):
            xold = x.copy(); M = self.scale(xold)
            F = lambda z: self.residual(z) - M * (z - xold) / dt
            ok = True
            for _ in range(8):
                Fz = F(x)
                J = self.jac(x, F)
                dx = spla.spsolve(J, -Fz)
                if not np.all(np.isfinite(dx)):
                    ok = False; break
                lim = np.max(np.abs(dx[self.N:]))
                if lim > 1.0:
                    dx *= 1.0 / lim
                x = x + dx
                if np.linalg.norm(dx) < 1e-12 * (1 + np.linalg.norm(x)):
                    break
            r = np.linalg.norm(self.residual(x))
            if not ok or not np.isfinite(r):
                x = xold; dt *= 0.3; continue
            dt = min(dt * (3.0 if r < r0 else 1.2), 1e12)
            r0 = r
            if verbose and it % 10 == 0:
                print(it, dt, r)
            if r < tol and dt > 1e8:
                break
        for _ in range(10):
            J = self.jac(x, self.residual)
            xn = x + spla.spsolve(J, -self.residual(x))
            if np.all(np.isfinite(xn)) and np.linalg.norm(self.residual(xn)) <= np.linalg.norm(self.residual(x)):
                x = xn
            else:
                break
        self.x = x
        self.final_residual = np.linalg.norm(self.residual(x))
        return x

    def report(self, x=None):
        x = self.x if x is None else x
        R, d = self.residual(x, detail=True)
        U, k = d['U'], d['k']
        Ub = np.sum(U * self.h) / np.sum(self.h)
        # residual scaled per equation: momentum & k relative to source magnitude
        res = dict(RU=np.max(np.abs(R[:self.N])), Rk=np.max(np.abs(R[self.N:2*self.N])),
                   Re=np.max(np.abs(R[2*self.N:])))
        return dict(Ub=Ub, Cf=2.0 / Ub**2, U1=U[0], k1=k[0], Ucl=U[-1], tauw=d['tauw'],
                    yplus1=d['yplus'], res=res)


def uniform(N):
    return np.linspace(0.0, 1.0, N + 1)

def first_then_fine(N, h1, r=1.0):
    """first cell of height h1, then n uniform (r=1) or geometric cells over [h1,1]."""
    if r == 1.0:
        return np.concatenate([[0.0], np.linspace(h1, 1.0, N + 1)])
    # geometric growth from first fine cell dy0 with ratio r, N cells over 1-h1
    L = 1.0 - h1
    dy0 = L * (r - 1) / (r**N - 1)
    d = dy0 * r**np.arange(N)
    return np.concatenate([[0.0], h1 + np.concatenate([[0.0], np.cumsum(d)])])


def run(label, Re, faces, **kw):
    m = KEChannel(Re, faces, **kw)
    m.solve()
    o = m.report()
    if not (max(o['res'].values()) < 1e-9):
        # fall back: warm start from the 10-cell uniform solution (grid continuation)
        c = KEChannel(Re, uniform(10), **kw); c.solve()
        if m.N > 40:   # two-level continuation for fine grids
            c2 = KEChannel(Re, np.concatenate([faces[:1], np.linspace(faces[1], 1.0, 31)]), **kw)
            c2.solve(x0=c2.interp_from(c)); c = c2
        m.solve(x0=m.interp_from(c))
        o = m.report()
        label += " [warm]"

    print(f"{label:42s} Re={Re:4d} N={m.N:4d} y+1={o['yplus1']*0+m.yP*Re:6.2f} "
          f"Ub+={o['Ub']:8.4f} Cf={o['Cf']:.5e} U1+={o['U1']:7.4f} k1+={o['k1']:6.4f} "
          f"Ucl+={o['Ucl']:7.4f} tauw={o['tauw']:.10f} "
          f"maxres(U,k,e)=({o['res']['RU']:.1e},{o['res']['Rk']:.1e},{o['res']['Re']:.1e})")
    return m, o


if __name__ == "__main__":
    print("=== Base cases (standard k-eps, sigma_e=1.3, kappa=0.41, E=9.8) ===")
    run("(a) 550, 10 uniform", 550, uniform(10))
    run("(b) 550, 5 uniform", 550, uniform(5))
    run("(b) 550, 15 uniform", 550, uniform(15))
    run("(c) 950, 10 uniform", 950, uniform(10))
    print("=== Sensitivity on (a) ===")
    run("(a) sigma_e=1.22", 550, uniform(10), se=1.22)
    run("(a) E=exp(0.41*5.2) (B=5.2)", 550, uniform(10), E=np.exp(0.41 * 5.2))
    run("(a) sigma_e=1.22 + B=5.2", 550, uniform(10), se=1.22, E=np.exp(0.41 * 5.2))
    print("=== Grid: first cell fixed at y+=27.5 (h1=0.1), finer outer ===")
    for n in (9, 18, 36, 90, 180, 360):
        run(f"(a) h1=0.1 + {n} uniform outer", 550, first_then_fine(n, 0.1))
    for n, r in ((40, 1.05), (80, 1.02), (200, 1.01)):
        # geometric outer grid starting small near first cell
        run(f"(a) h1=0.1 + {n} geometric r={r}", 550, first_then_fine(n, 0.1, r))
    print("=== Same outer refinement at Re 950 (h1=0.1) ===")
    for n in (9, 90, 360):
        run(f"(c) h1=0.1 + {n} uniform outer", 950, first_then_fine(n, 0.1))
    print("=== Variant: P_k from face gradients (mean of g_f^2 over the 2 faces) ===")
    run("(a) 550, 10 uniform, face Pk", 550, uniform(10), pk='face')
    run("(b) 550, 5 uniform, face Pk", 550, uniform(5), pk='face')
    run("(b) 550, 15 uniform, face Pk", 550, uniform(15), pk='face')
    run("(c) 950, 10 uniform, face Pk", 950, uniform(10), pk='face')
    run("(a) sigma_e=1.22, face Pk", 550, uniform(10), se=1.22, pk='face')
    run("(a) B=5.2, face Pk", 550, uniform(10), E=np.exp(0.41 * 5.2), pk='face')
    for n in (18, 90, 360):
        run(f"(a) h1=0.1 + {n} uniform outer, face Pk", 550, first_then_fine(n, 0.1), pk='face')
    for n in (90, 360):
        run(f"(c) h1=0.1 + {n} uniform outer, face Pk", 950, first_then_fine(n, 0.1), pk='face')
