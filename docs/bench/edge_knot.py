#!/usr/bin/env python3
"""What an edge knot would buy: a 1D model of the multiplier discretisation at a contact edge.

A rigid parabola (Hertz, plane strain, E* = R = 1, load P = pi/4 so that a = 1, p0 = 1/2)
pressed onto an elastic half-plane. The half-plane's surface flexibility is exact (the 2D
log kernel: normal displacement -(2 / (pi E*)) integral p(s) ln|x - s| ds up to a constant),
so the only error left is that of the pressure discretisation, which is what this model is
for. Nodes x_j = j h with h = a / (n + t): the Hertz edge falls a fraction t of an element past
node n.

Compared, each the minimiser of the complementary energy
    Pi(p) = 1/2 <p, S p> + <p, x^2 / 2R>   subject to   integral p = P
over its own pressure space (the load constraint's multiplier is the approach):

* nodal: pressure linear between the nodes, zero at open nodes; the contact set is the KKT
  one (every nodal pressure positive, the next node's would be negative). This is the paper's
  discretisation with mortar-weighted gaps (hycon today).
* edge knot: the same, but the last element's pressure falls to zero at a free point x_e
  instead of at the next node, x_e chosen to minimise Pi (golden section over
  (x_k, x_k + 2h)). Stationarity in x_e is the local condition
      integral_{x_k}^{x_e} (x - x_k) / (x_e - x_k) g(x) dx = 0,
  the weighted gap of a virtual node at x_e with zero pressure (checked in the output).

Also printed: the L2 error of the best approximation on the same nodes (the L2 projection of
Hertz onto all their hat functions) and of the best one zero at the open nodes.

Usage: python3 docs/bench/edge_knot.py [n,n,...] [positions]   (numpy only)
"""
import sys

import numpy as np

GX, GW = np.polynomial.legendre.leggauss(24)
GX2, GW2 = np.polynomial.legendre.leggauss(40)
P = np.pi / 4


def log_integrals(t):
    """Antiderivatives of ln|t| and t ln|t|."""
    with np.errstate(divide="ignore", invalid="ignore"):
        lt = np.where(t == 0, 0.0, np.log(np.abs(t)))
    return t * lt - t, t * t / 2 * lt - t * t / 4


def inner(x, s0, s1):
    """integral over [s0, s1] of both linear shapes times -(2/pi) ln|x - s| ds."""
    h = s1 - s0
    a1, b1 = log_integrals(s1 - x)
    a0, b0 = log_integrals(s0 - x)
    i0, i1 = a1 - a0, b1 - b0
    left = (s1 - x) / h * i0 - i1 / h
    right = (x - s0) / h * i0 + i1 / h
    return -(2 / np.pi) * np.stack([left, right])


def assemble(knots):
    """S, c, w over the hat functions of the interior knots (zero at both end knots)."""
    m = len(knots)
    k0, k1 = knots[:-1], knots[1:]
    he = k1 - k0
    xs = 0.5 * (k0 + k1)[:, None] + 0.5 * he[:, None] * GX[None, :]
    ws = 0.5 * he[:, None] * GW[None, :]
    shapes = np.stack([(k1[:, None] - xs) / he[:, None], (xs - k0[:, None]) / he[:, None]])
    kernel = inner(xs[:, :, None], k0[None, None, :], k1[None, None, :])
    S = np.zeros((m, m))
    rows = np.arange(m - 1)
    for a in range(2):
        for b in range(2):
            blk = np.einsum("eg,eg,egf->ef", ws, shapes[a], kernel[b])
            np.add.at(S, (rows[:, None] + a, rows[None, :] + b), blk)
    c, w = np.zeros(m), np.zeros(m)
    for a in range(2):
        np.add.at(c, rows + a, np.sum(ws * shapes[a] * xs**2 / 2, axis=1))
        np.add.at(w, rows + a, np.sum(ws * shapes[a], axis=1))
    return S[1:-1, 1:-1], c[1:-1], w[1:-1]


def solve(knots):
    """Nodal pressures, complementary energy and approach for the pressure on `knots`."""
    S, c, w = assemble(knots)
    k = len(c)
    A = np.zeros((k + 1, k + 1))
    A[:k, :k], A[:k, k], A[k, :k] = S, w, w
    sol = np.linalg.solve(A, np.concatenate([-c, [P]]))
    lam = sol[:k]
    return lam, 0.5 * lam @ S @ lam + lam @ c, -sol[k]


def gap(knots, lam, approach, x):
    """Pointwise gap x^2/2 - approach + (S p)(x)."""
    vals = np.concatenate([[0], lam, [0]])
    g = x**2 / 2 - approach
    for f in range(len(knots) - 1):
        left, right = inner(x, knots[f], knots[f + 1])
        g = g + vals[f] * left + vals[f + 1] * right
    return g


def hertz(x):
    return 0.5 * np.sqrt(np.clip(1 - x * x, 0, None))


def pieces(cuts):
    cuts = np.array(sorted(set(cuts)))
    a, b = cuts[:-1], cuts[1:]
    xs = (0.5 * (a + b))[:, None] + (0.5 * (b - a))[:, None] * GX2[None, :]
    return xs.ravel(), ((0.5 * (b - a))[:, None] * GW2[None, :]).ravel()


def l2(knots, lam):
    vals = np.concatenate([[0], lam, [0]])
    end = max(abs(knots[0]), abs(knots[-1]), 1.0)
    xs, ws = pieces(list(knots) + [-1.0, 1.0, -end, end])
    ph = np.interp(xs, knots, vals, left=0, right=0)
    return np.sqrt(np.sum(ws * (ph - hertz(xs)) ** 2) / np.sum(ws * hertz(xs) ** 2))


def best(knots):
    """L2 error of the projection of Hertz onto the hats of the interior knots."""
    m = len(knots)
    xs, ws = pieces(list(knots) + [-1.0, 1.0])
    phi = np.array([np.interp(xs, knots, np.eye(m)[i]) for i in range(1, m - 1)])
    return l2(knots, np.linalg.solve((phi * ws) @ phi.T, (phi * ws) @ hertz(xs)))


def nodal(h):
    """The KKT contact set -k..k and its pressures."""
    for k in range(int(1 / h) - 3, int(1 / h) + 4):
        knots = h * np.arange(-(k + 1), k + 2)
        lam, _, _ = solve(knots)
        if lam.min() > 0 and solve(h * np.arange(-(k + 2), k + 3))[0][0] <= 0:
            return knots, lam, k
    raise RuntimeError("no KKT contact set")


def edge_knot(h, k):
    """Nodes -k..k in contact, the edge knot x_e at the least complementary energy."""

    def at(xe):
        knots = np.concatenate([[-xe], h * np.arange(-k, k + 1), [xe]])
        return solve(knots), knots

    ratio = (np.sqrt(5) - 1) / 2
    lo, hi = k * h + 1e-3 * h, k * h + 1.999 * h
    c1, c2 = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
    f1, f2 = at(c1)[0][1], at(c2)[0][1]
    for _ in range(40):
        if f1 < f2:
            hi, c2, f2 = c2, c1, f1
            c1 = hi - ratio * (hi - lo)
            f1 = at(c1)[0][1]
        else:
            lo, c1, f1 = c1, c2, f2
            c2 = lo + ratio * (hi - lo)
            f2 = at(c2)[0][1]
    (lam, _, approach), knots = at(0.5 * (lo + hi))
    xk, xe = k * h, knots[-1]
    xs, ws = pieces([xk, xe])
    weight = (xs - xk) / (xe - xk)
    virtual = np.sum(ws * weight * gap(knots, lam, approach, xs)) / np.sum(ws * weight)
    return knots, lam, virtual / approach


def main():
    ns = [int(v) for v in (sys.argv[1] if len(sys.argv) > 1 else "16,32,64,128").split(",")]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    print(f"{'n':>4} {'edge':>6} {'nodal %':>8} {'best %':>8} {'set %':>8} "
          f"{'knot %':>8} {'(x_e-a)/h':>9} {'virtual gap':>11}")
    for n in ns:
        rows = []
        for j in range(count):
            t = (j + 0.5) / count
            h = 1.0 / (n + t)
            knots, lam, k = nodal(h)
            e_nodal, e_set = l2(knots, lam), best(knots)
            e_best = best(h * np.arange(-(n + 3), n + 4))
            kk, kl, virtual = edge_knot(h, k)
            e_knot = l2(kk, kl)
            rows.append((e_nodal, e_best, e_set, e_knot))
            print(f"{n:>4} {t:>6.3f} {100 * e_nodal:>8.4f} {100 * e_best:>8.4f} "
                  f"{100 * e_set:>8.4f} {100 * e_knot:>8.4f} {(kk[-1] - 1) / h:>+9.3f} "
                  f"{virtual:>11.1e}", flush=True)
        r = np.array(rows)
        mean, worst = 100 * r.mean(axis=0), 100 * r.max(axis=0)
        print(f"n = {n}: mean (worst) nodal {mean[0]:.4f}% ({worst[0]:.4f}), best "
              f"{mean[1]:.4f}% ({worst[1]:.4f}), with the set {mean[2]:.4f}% ({worst[2]:.4f}), "
              f"edge knot {mean[3]:.4f}% ({worst[3]:.4f})", flush=True)


if __name__ == "__main__":
    main()
