#!/usr/bin/env python3
"""Independent oracle: counts of real configurations, rigid_incidence against PHCpack.

For N small random planted scenes (2 to 4 bodies, written here, independently of the
package's C++ generator planted_scene.h) this script

1. builds the scene with exact rational data: every body has an exact rational pose (a
   rotation from a quaternion with integer components, exactly orthogonal with rational
   entries and determinant +1, and a rational translation); shared points and the other
   points are drawn in world coordinates and mapped to each body's local frame, and the
   squared distances are computed exactly, so the planted configuration solves the scene
   exactly. Bodies are attached to earlier ones by 0 to 3 shared points (hinges, ball
   joints, bodies merged by 3 points, labels in three bodies, cycles), the degrees of
   freedom left are closed by distances, each step checked by the exact rank of the
   Jacobian at the planted configuration (modulo a 61-bit prime), so the planted
   configuration is isolated. A scene in four is written with its lengths multiplied by
   1e-5, 1e-3, 1e3 or 1e6 (exactly), the frame body is not always the first of the file;
2. writes a world-coordinate polynomial system whose real solutions are exactly the
   configurations of the scene: the frame body's points are constants; every other body
   is placed by the world coordinates of three non-collinear base points (unknowns, or
   the constants / unknowns of a point already placed), its triangle held by its 3
   squared side lengths, every other point of it that matters (shared, or the end of a
   distance) given 3 unknowns of its own and equated to p0 + a (p1 - p0) + b (p2 - p0)
   + c (p1 - p0) x (p2 - p0), the rational a, b, c from the local coordinates (the cross
   product keeps the handedness: no mirror image); distances are squared-distance
   equations. The planted configuration must satisfy every equation exactly (Fractions).
   A square subsystem is chosen greedily by the rank of the exact Jacobian at the planted
   configuration (the equations a hinge makes redundant are left out; every equation
   left out is checked on every solution afterwards). Before phc sees it the square
   system is combined linearly (Gauss-Jordan on the coefficients of the quadratic
   monomials: sphere equations share |p|^2, so many become linear; the total degree
   drops from 2^n to 2^r) and, in the "reduced" form, the linear equations eliminate
   variables; both are exact rational transformations with the same solutions;
3. solves it with PHCpack (phc -b, single-threaded, phc -0<seed> for a reproducible
   seed), reads every solution list of its output and the list appended to its input,
   keeps the real solutions (imaginary parts below 1e-8 relative), polishes them with
   Newton's method on the whole system (the residual of every equation, left out or not,
   must be below 1e-8 relative), and splits them into nonsingular and singular;
4. runs `rigid_incidence solve SCENE.json --json` and compares, by the world coordinates
   of every point (in the frame body's coordinates, within --tolerance of the scene's
   size): the planted configuration must be among the package's; every package
   configuration must be a nonsingular solution of the system here (Newton from it stays
   put); when the package says complete, every configuration certified, and its
   configurations and the real nonsingular phc solutions must be the same set.

phc loses paths now and then (seen on the reduced form, for some seeds): when phc lacks
the planted configuration or one of the package's, or the counts differ, it is run again
(--phc-retries, alternating the reduced and the combined form, other seeds) and the real
solutions of the runs are united. A real phc solution the package lacks while saying
complete is a disagreement (the package missed a configuration); a package configuration
that solves the system here but that no phc run found is a phc failure.

Verdicts per scene: agree; disagree; package-incomplete (the package says incomplete and
nothing contradicts it); phc-failure (phc failed to run, missed a verified configuration,
or found a real singular solution); for scene files also refused and not-compared (below).
Exit status 0 when every scene agrees, 1 otherwise, 2 on bad usage or a refused file.
--mutate tampers with the package's answers to show that the comparison catches it.

Scene files (--scene FILE.json, repeatable): the same comparison on existing scenes in the
format "rigid-incidence-scene/1", each number read exactly (decimals, rationals, JSON
numbers from their text). A bar (a body of 2 points) enters as the distance of its points,
as in the package; a point only in bars gets 3 variables of its own; "length" is squared
exactly. A scene whose size is outside 0.1 to 1000 is divided by a power of 10 (the unit),
as a generated scene is written with one. Refused, with the reason (verdict "refused", exit
status 2): "inequalities" (the system here cannot express them: the package prunes by
them), a "free_distance" (a curve of configurations), a distance of 0 (a coincidence: the
package merges the labels), bodies the package refuses (collinear, a bar as the frame, bars
only), lengths more than 8 orders of magnitude apart. There is no planted configuration,
so the square subsystem is chosen at the configurations the package prints (the world
coordinates of every point, in the frame's coordinates: "points" of each solution of
`solve --json`): at each, the Jacobian of every equation (rows scaled to norm 1) has its
numerical rank from its singular values (one-sided Jacobi SVD, relative threshold 1e-8:
it must be the number of variables, else the configuration is a singular solution and the
scene is "not-compared"), and the equations are taken greedily in the order of the exact
choice, each kept when its row is independent of those kept (its part orthogonal to them
above 1e-8; a hinge's redundant row leaves 1e-15 or less, the margins are printed); the
choice whose square Jacobian is nonsingular (inverse condition above 1e-8) at the most
configurations wins, the first on ties (in practice they are all the same). This is
sound as the planted choice is: every configuration of the scene solves the square
subsystem, so phc's solutions include them all; every equation left out is checked on every
phc solution (Newton on the whole system, residual below 1e-8), so a solution of the
subsystem alone is never counted; a package configuration at which the chosen subsystem
were singular is noted, and would come back from phc as singular or not at all (verdict
phc-failure), never as agreement.
The planted checks are skipped; the others are the same (every package configuration a
nonsingular solution of the whole system, the same set as phc's real nonsingular solutions
when the package says complete). A scene where the package gives no configuration (none
found, under- or over-constrained, curves) is "not-compared": there is nothing to choose
the subsystem at. Before phc runs, the size of its system is printed (variables; the total
degree 2^r after the linear combination, r quadratic equations left).

  phc_compare.py --tool build/examples/Rigid_incidence/rigid_incidence \
                 --scene examples/Rigid_incidence/data/tetra.json --workdir /tmp/phc_files

Standard library only (fractions, json, random, subprocess, argparse).

  phc_compare.py --tool build/examples/Rigid_incidence/rigid_incidence --phc phc \
                 --scenes 40 --seed 1 --workdir /tmp/phc_compare

One scene again: --scenes 1 --first I (same --seed); its files are WORKDIR/phc_scene_I.*
(the scene, phc's input and output for every run).
"""

import argparse
import itertools
import json
import math
import os
import random
import re
import subprocess
import sys
import time
import traceback
from fractions import Fraction as Q

# ---------------------------------------------------------------------------------------
# exact 3-vectors


def vadd(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vscale(s, a):
    return (s * a[0], s * a[1], s * a[2])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def det3(c0, c1, c2):
    """Determinant of the matrix with columns c0, c1, c2."""
    return dot(c0, cross(c1, c2))


def matvec(m, v):
    return tuple(m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2] for i in range(3))


def transpose(m):
    return tuple(tuple(m[j][i] for j in range(3)) for i in range(3))


def frac_str(x):
    return str(x.numerator) if x.denominator == 1 else "%d/%d" % (x.numerator, x.denominator)


# ---------------------------------------------------------------------------------------
# sparse polynomials: {monomial: coefficient}, a monomial is the sorted tuple of the
# indices of its variables (with repetition), () for the constant term


def pconst(c):
    return {(): Q(c)} if c != 0 else {}


def pvar(i):
    return {(i,): Q(1)}


def _accumulate(r, m, c):
    # adds c to the coefficient of monomial m in r, dropping it when it cancels
    v = r.get(m, 0) + c
    if v == 0:
        r.pop(m, None)
    else:
        r[m] = v


def padd(p, q, s=1):
    r = dict(p)
    for m, c in q.items():
        _accumulate(r, m, s * c)
    return r


def pmul(p, q):
    r = {}
    for m1, c1 in p.items():
        for m2, c2 in q.items():
            _accumulate(r, tuple(sorted(m1 + m2)), c1 * c2)
    return r


def pscale(s, p):
    return {m: s * c for m, c in p.items()} if s != 0 else {}


def peval(p, x):
    total = 0
    for m, c in p.items():
        t = c
        for i in m:
            t = t * x[i]
        total += t
    return total


def substitute(p, v, expr):
    """p with the variable v replaced by the polynomial expr."""
    r = {}
    for m, c in p.items():
        k = m.count(v)
        if k == 0:
            r = padd(r, {m: c})
            continue
        t = {tuple(i for i in m if i != v): c}
        for _ in range(k):
            t = pmul(t, expr)
        r = padd(r, t)
    return r


def pdegree(p):
    return max((len(m) for m in p), default=0)


# polynomial 3-vectors
def pv_const(v):
    return [pconst(c) for c in v]


def pv_vars(i0):
    return [pvar(i0), pvar(i0 + 1), pvar(i0 + 2)]


def pv_add(a, b, s=1):
    return [padd(a[k], b[k], s) for k in range(3)]


def pv_scale(s, a):
    return [pscale(s, a[k]) for k in range(3)]


def pv_dot(a, b):
    r = {}
    for k in range(3):
        r = padd(r, pmul(a[k], b[k]))
    return r


def pv_cross(a, b):
    return [padd(pmul(a[1], b[2]), pmul(a[2], b[1]), -1),
            padd(pmul(a[2], b[0]), pmul(a[0], b[2]), -1),
            padd(pmul(a[0], b[1]), pmul(a[1], b[0]), -1)]


# ---------------------------------------------------------------------------------------
# rank modulo a prime (the Jacobian at the planted configuration is exact; its rank over Q
# equals the rank modulo a 61-bit prime unless the prime divides a minor: negligible)

PRIME = (1 << 61) - 1


def modp(x):
    x = Q(x)
    return x.numerator % PRIME * pow(x.denominator % PRIME, PRIME - 2, PRIME) % PRIME


class RankBasis:
    """Incremental row echelon form modulo PRIME."""

    def __init__(self, n):
        self.n = n
        self.rows = {}  # pivot column -> row (normalised: 1 at the pivot)

    def add(self, row):
        """Adds row (a list of ints mod PRIME) if independent; returns True if it was."""
        r = list(row)
        for col in range(self.n):
            if r[col] == 0:
                continue
            piv = self.rows.get(col)
            if piv is None:
                inv = pow(r[col], PRIME - 2, PRIME)
                r = [v * inv % PRIME for v in r]
                self.rows[col] = r
                return True
            f = r[col]
            r = [(a - f * b) % PRIME for a, b in zip(r, piv)]
        return False

    def rank(self):
        return len(self.rows)


# ---------------------------------------------------------------------------------------
# scenes


class Scene:
    """bodies: list of [name, {label: local (x, y, z)}] (Fractions); frame: index of the
    frame body; distances: list of (u, v, squared); world: planted world coordinates of
    every label (the frame body's pose is the identity, so world = frame coordinates);
    empty for a scene read from a file (--scene), which has no planted configuration.
    labels: every label of a scene read from a file (its bars' too)."""

    def __init__(self):
        self.bodies = []
        self.frame = 0
        self.distances = []
        self.world = {}
        self.labels = set()
        self.structure = ""

    def label_bodies(self):
        lb = {}
        for bi, (_, pts) in enumerate(self.bodies):
            for lab in pts:
                lb.setdefault(lab, []).append(bi)
        return lb

    def to_json(self, name, unit=Q(1)):
        """The scene file, every length multiplied by unit (exactly: the configurations
        are those of the scene here, multiplied by unit)."""
        return {
            "format": "rigid-incidence-scene/1",
            "name": name,
            "comment": self.structure,
            "bodies": [{"name": nm, "points": {lab: [frac_str(c * unit) for c in p] for lab, p in pts.items()}}
                       for nm, pts in self.bodies],
            "distances": [{"between": [u, v], "squared": frac_str(d * unit * unit)}
                          for u, v, d in self.distances],
            "frame": self.bodies[self.frame][0],
        }

    def size2(self):
        """Of a scene read from a file, exactly: (the square of its size, the square of its
        smallest length). Its configurations lie, in the frame's coordinates, within the
        frame body's coordinates plus the bodies' diameters and the distances."""
        big = max(c * c for p in self.bodies[self.frame][1].values() for c in p)
        small = None
        for _, pts in self.bodies:
            for a, b in itertools.combinations(list(pts.values()), 2):
                d2 = dot(vsub(a, b), vsub(a, b))
                big = max(big, d2)
                small = d2 if small is None else min(small, d2)
        for _, _, d2 in self.distances:
            big = max(big, d2)
            small = min(small, d2)
        return big, small

    def size(self):
        return float(self.size2()[0]) ** 0.5

    def scale(self):
        if not self.world:
            return max(1.0, self.size())
        return max(1.0, max(abs(float(c)) for p in self.world.values() for c in p))

    def all_labels(self):
        return sorted(self.world) if self.world else sorted(self.labels)


def rand_rational(rng, lo=-6, hi=6):
    den = rng.choice([1, 1, 2, 3, 4, 5, 7])
    return Q(rng.randint(lo * den, hi * den), den)


def rand_point(rng):
    return (rand_rational(rng), rand_rational(rng), rand_rational(rng))


def rand_rotation(rng):
    """Exactly orthogonal rational rotation (determinant +1) from an integer quaternion."""
    while True:
        a, b, c, d = (rng.randint(-4, 4) for _ in range(4))
        n = a * a + b * b + c * c + d * d
        if n > 0:
            break
    n = Q(n)
    return ((Q(a * a + b * b - c * c - d * d) / n, Q(2 * (b * c - a * d)) / n, Q(2 * (b * d + a * c)) / n),
            (Q(2 * (b * c + a * d)) / n, Q(a * a - b * b + c * c - d * d) / n, Q(2 * (c * d - a * b)) / n),
            (Q(2 * (b * d - a * c)) / n, Q(2 * (c * d + a * b)) / n, Q(a * a - b * b - c * c + d * d) / n))


def collinear(p, q, r):
    return cross(vsub(q, p), vsub(r, p)) == (0, 0, 0)


# ---------------------------------------------------------------------------------------
# the polynomial formulation


class Formulation:
    """The world-coordinate system of a scene.

    Variables come in triples, each the world position of one label (a base point of a
    body, or a shared / distance point that is not a base point of the body that first
    places it). equations: list of (origin, polynomial). square: indices of the equations
    kept in the square subsystem; the others are checked afterwards."""

    def __init__(self, scene):
        self.scene = scene
        lb = scene.label_bodies()
        in_distance = {u for u, v, _ in scene.distances} | {v for u, v, _ in scene.distances}
        needed = {lab for lab, bs in lb.items() if len(bs) > 1} | in_distance
        self.var_labels = []  # label of variable triple k (variables 3k, 3k+1, 3k+2)
        # planted values (Fractions) of the variables; None for a scene from a file
        self.values = [] if scene.world else None
        rep = {}  # label -> polynomial 3-vector of its world position
        fr_pts = scene.bodies[scene.frame][1]
        for lab, p in fr_pts.items():
            rep[lab] = pv_const(p)
        self.const = dict(fr_pts)
        self.equations = []
        self.body_maps = []  # (body index, base labels, {label: (a, b, c)})

        def new_triple(lab):
            i0 = 3 * len(self.var_labels)
            self.var_labels.append(lab)
            if self.values is not None:
                self.values.extend(scene.world[lab])
            return pv_vars(i0)

        # bodies in breadth-first order from the frame over shared labels, so that a label
        # already placed can be a base point of the next body
        order = []
        seen = {scene.frame}
        queue = [scene.frame]
        while queue:
            b = queue.pop(0)
            for lab in scene.bodies[b][1]:
                for c in lb[lab]:
                    if c not in seen:
                        seen.add(c)
                        order.append(c)
                        queue.append(c)
        order += [b for b in range(len(scene.bodies)) if b not in seen]

        for bi in order:
            name, pts = scene.bodies[bi]

            def prio(lab):
                if lab in rep:
                    return 0 if lab in self.const else 1
                return 2 if lab in needed else 3

            labs = sorted(pts, key=lambda l: (prio(l), l))
            base = None
            for tri in itertools.combinations(labs, 3):
                if not collinear(pts[tri[0]], pts[tri[1]], pts[tri[2]]):
                    base = tri
                    break
            if base is None:
                raise ValueError("body %s: all points on a line" % name)
            P = []
            for lab in base:
                if lab in rep:
                    P.append(rep[lab])
                else:
                    v = new_triple(lab)
                    P.append(v)
                    if lab in needed:
                        rep[lab] = v
            q0, q1, q2 = (pts[l] for l in base)
            for (i, j) in ((0, 1), (0, 2), (1, 2)):
                d = vsub(pts[base[i]], pts[base[j]])
                diff = pv_add(P[i], P[j], -1)
                self.equations.append(("%s: triangle %s-%s" % (name, base[i], base[j]),
                                       padd(pv_dot(diff, diff), pconst(dot(d, d)), -1)))
            e1, e2 = vsub(q1, q0), vsub(q2, q0)
            e3 = cross(e1, e2)
            D = det3(e1, e2, e3)
            E1, E2 = pv_add(P[1], P[0], -1), pv_add(P[2], P[0], -1)
            E3 = pv_cross(E1, E2)
            coeffs = {}
            for lab, q in pts.items():
                if lab in base:
                    continue
                r = vsub(q, q0)
                abc = (det3(r, e2, e3) / D, det3(e1, r, e3) / D, det3(e1, e2, r) / D)
                coeffs[lab] = abc
                if lab not in needed:
                    continue
                expr = pv_add(pv_add(pv_add(P[0], pv_scale(abc[0], E1)), pv_scale(abc[1], E2)),
                              pv_scale(abc[2], E3))
                if all(set(c) <= {()} for c in expr):
                    # a body fixed by three constant points: its points are constants
                    if lab not in rep:
                        rep[lab] = expr
                        self.const[lab] = tuple(c.get((), Q(0)) for c in expr)
                        continue
                if lab not in rep:
                    rep[lab] = new_triple(lab)
                for k in range(3):
                    self.equations.append(("%s: point %s.%s" % (name, lab, "xyz"[k]),
                                           padd(rep[lab][k], expr[k], -1)))
            self.body_maps.append((bi, base, coeffs))
        for u, v, d2 in scene.distances:
            for w in (u, v):
                if w not in rep:
                    # a free point (in a scene from a file: the far end of a bar, in no body)
                    rep[w] = new_triple(w)
        for u, v, d2 in scene.distances:
            diff = pv_add(rep[u], rep[v], -1)
            self.equations.append(("distance %s-%s" % (u, v), padd(pv_dot(diff, diff), pconst(d2), -1)))
        self.n = 3 * len(self.var_labels)
        # identically zero equations (both ends constant) say nothing
        self.equations = [(o, p) for o, p in self.equations if p]

    def check_planted(self):
        """The planted configuration must satisfy every equation exactly."""
        if self.values is None:
            return []
        bad = [(o, peval(p, self.values)) for o, p in self.equations if peval(p, self.values) != 0]
        return bad

    def select_square(self):
        """Greedy choice of equations independent at the planted configuration (exact
        Jacobian modulo a prime). Returns the rank; self.square, self.left_out."""
        basis = RankBasis(self.n)
        self.square, self.left_out = [], []
        xs = [modp(v) for v in self.values]
        for k, (o, p) in enumerate(self.equations):
            row = [0] * self.n
            for m, c in p.items():
                cm = modp(c)
                for pos, i in enumerate(m):
                    if pos > 0 and m[pos - 1] == i:
                        continue
                    mult = m.count(i)
                    t = cm * mult % PRIME
                    seen = False
                    for j in m:
                        if j == i and not seen:
                            seen = True
                            continue
                        t = t * xs[j] % PRIME
                    row[i] = (row[i] + t) % PRIME
            if basis.add(row):
                self.square.append(k)
            else:
                self.left_out.append(k)
        return basis.rank()

    def dof(self):
        return self.n - self.select_square()

    def select_square_numeric(self, fsys, configs, tau=1e-8):
        """The square subsystem of a scene without a planted configuration (--scene), chosen
        at configurations the package returns (configs: variable vectors, floats).

        At each configuration x, the Jacobian of every equation, each row scaled to norm 1
        (the rank does not change), is examined twice: its singular values (one-sided
        Jacobi SVD) give its rank, the number of them above tau times the largest: n when x
        is an isolated nonsingular solution of the whole system; and the greedy choice
        takes the equations in their order, keeping each whose row is independent of the
        rows kept so far (modified Gram-Schmidt: the part of the unit row orthogonal to them
        has norm above tau), like select_square does exactly. The redundancy a hinge makes
        holds at every configuration, and the coordinates the package prints are accurate
        to about 1e-15, so a redundant row leaves a remainder near 1e-15 and an independent
        one a remainder far above tau (both margins are recorded). A choice is kept when
        its n rows have a condition number below 1/tau at the configuration; the choice
        kept at the most configurations wins (the first on ties). Where it is singular, phc
        may report the configuration singular or miss it: a note, and the comparison says
        phc-failure rather than agree. Sound as in the planted case: every real
        configuration solves the square subsystem, and every equation left out is checked
        on every phc solution afterwards. Sets self.square, self.left_out; returns a dict of
        the evidence ("chosen" False when no configuration has rank n)."""
        m = len(self.equations)
        info = {"chosen": False, "ranks": [], "choices": [], "kept_margin": None, "dropped_margin": None}
        candidates = []  # (square, left_out)
        for x in configs:
            rows = []
            for k in range(m):
                g = fsys.grad(k, x)
                nrm = sum(v * v for v in g) ** 0.5
                rows.append([v / nrm for v in g] if nrm > 0 else g)
            sv = singular_values(rows)
            r = sum(1 for v in sv if v > tau * sv[0]) if sv and sv[0] > 0 else 0
            info["ranks"].append(r)
            if r != self.n:
                continue
            square, left_out, kept, dropped = greedy_independent_rows(rows, tau)
            if len(square) != self.n:
                info["choices"].append("the greedy choice has %d rows, the SVD rank is %d" % (len(square), r))
                continue
            if kept is not None:
                info["kept_margin"] = kept if info["kept_margin"] is None else min(kept, info["kept_margin"])
            if dropped is not None:
                info["dropped_margin"] = (dropped if info["dropped_margin"] is None
                                          else max(dropped, info["dropped_margin"]))
            if (square, left_out) not in candidates:
                candidates.append((square, left_out))
        if not candidates:
            return info
        best = None
        for square, left_out in candidates:
            conds = []
            for x in configs:
                rows = []
                for k in square:
                    g = fsys.grad(k, x)
                    nrm = sum(v * v for v in g) ** 0.5
                    rows.append([v / nrm for v in g] if nrm > 0 else g)
                sv = singular_values(rows)
                conds.append(sv[-1] / sv[0] if sv and sv[0] > 0 else 0.0)
            good = sum(1 for c in conds if c > tau)
            if best is None or good > best[0]:
                best = (good, square, left_out, conds)
        _, self.square, self.left_out, conds = best
        info["chosen"] = True
        info["candidates"] = len(candidates)
        info["inverse_conditions"] = conds
        info["singular_at"] = [j for j, c in enumerate(conds) if not c > tau]
        return info

    # positions of every label from values of the variables (floats)
    def all_points(self, x):
        pos = {lab: tuple(float(c) for c in p) for lab, p in self.const.items()}
        for k, lab in enumerate(self.var_labels):
            pos[lab] = (x[3 * k], x[3 * k + 1], x[3 * k + 2])
        for bi, base, coeffs in self.body_maps:
            P = [pos[l] for l in base]
            E1, E2 = vsub(P[1], P[0]), vsub(P[2], P[0])
            E3 = cross(E1, E2)
            for lab, (a, b, c) in coeffs.items():
                if lab not in pos:
                    pos[lab] = vadd(vadd(vadd(P[0], vscale(float(a), E1)), vscale(float(b), E2)),
                                    vscale(float(c), E3))
        return pos

    def variables_from_points(self, points):
        x = []
        for lab in self.var_labels:
            x.extend(float(c) for c in points[lab])
        return x

    def phc_polynomials(self):
        """The square subsystem, combined linearly (an invertible rational transformation,
        which keeps its solutions exactly) so that as many equations as possible lose their
        quadratic terms: Gauss-Jordan elimination on the coefficients of the degree-2
        monomials. The total degree, phc's number of paths, drops from 2^n to 2^r with r
        the rank of the quadratic parts (sphere equations share |p|^2, and so on)."""
        rows, r = self._combine([dict(self.equations[k][1]) for k in self.square])
        self.quadratic_rank = r
        for p in rows if self.values is not None else []:
            if peval(p, self.values) != 0:
                raise AssertionError("the combined system misses the planted configuration")
        return rows

    def reduce(self):
        """The square subsystem for phc, with fewer variables: the equations are combined
        (phc_polynomials) until some lose their quadratic terms; each such linear equation
        eliminates one variable (exactly, by substitution into the others, which stay of
        degree 2 at most); repeated while linear equations appear. Sets self.reduced (the
        polynomials, in the original variable indices), self.free (the variables phc
        solves for) and self.eliminated [(variable, linear polynomial in the free ones)]
        in the order to evaluate them backwards."""
        rows = self.phc_polynomials()
        eliminated = []
        while True:
            lin = [p for p in rows if pdegree(p) <= 1]
            rows = [p for p in rows if pdegree(p) > 1]
            if not lin:
                break
            for idx in range(len(lin)):
                p = lin[idx]  # up to date: every earlier elimination substituted
                if not p:
                    raise AssertionError("dependent linear equations")
                # pick the variable with the largest coefficient (exact anyway)
                v = max((m[0] for m in p if len(m) == 1), key=lambda i: abs(p[(i,)]), default=None)
                if v is None:
                    raise AssertionError("a nonzero constant equation")
                c = p[(v,)]
                expr = pscale(-1 / c, padd(p, {(v,): c}, -1))  # v = expr
                eliminated.append((v, expr))
                lin = [substitute(q, v, expr) for q in lin]
                rows = [substitute(q, v, expr) for q in rows]
            rows, _ = self._combine(rows)
        self.reduced = rows
        gone = {v for v, _ in eliminated}
        self.free = sorted({i for p in rows for m in p for i in m})
        if len(self.free) != len(rows) or set(self.free) & gone:
            raise AssertionError("the reduced system is not square (%d equations, %d variables)"
                                 % (len(rows), len(self.free)))
        self.eliminated = eliminated
        for p in rows if self.values is not None else []:
            if peval(p, self.values) != 0:
                raise AssertionError("the reduced system misses the planted configuration")
        return rows

    def expand(self, y):
        """All variables from the free ones (floats or complex), through the eliminated."""
        x = [0] * self.n
        for i, v in zip(self.free, y):
            x[i] = v
        for v, expr in reversed(self.eliminated):
            x[v] = peval(expr, x)
        return x

    @staticmethod
    def _combine(rows):
        """Gauss-Jordan elimination on the coefficients of the degree-2 monomials: (the
        combined rows, the rank of their quadratic parts)."""
        quads = sorted({m for p in rows for m in p if len(m) == 2})
        r = 0
        rows = list(rows)
        for m in quads:
            piv = next((i for i in range(r, len(rows)) if rows[i].get(m, 0) != 0), None)
            if piv is None:
                continue
            rows[r], rows[piv] = rows[piv], rows[r]
            rows[r] = pscale(1 / rows[r][m], rows[r])
            for i in range(len(rows)):
                if i != r and rows[i].get(m, 0) != 0:
                    rows[i] = padd(rows[i], rows[r], -rows[i][m])
            r += 1
        return rows, r

    def var_name(self, i):
        return "v%d" % (i + 1)

    def combined(self):
        """The square subsystem combined (phc_polynomials), every variable kept."""
        rows = self.phc_polynomials()
        self.reduced = rows
        self.free = list(range(self.n))
        self.eliminated = []
        return rows

    def phc_text(self, form="combined"):
        rows = []
        for p in (self.reduce() if form == "reduced" else self.combined()):
            terms = []
            for m, c in sorted(p.items(), key=lambda t: (-len(t[0]), t[0])):
                cf = float(c)
                s = "-" if cf < 0 else "+"
                mono = "".join("*" + self.var_name(i) for i in m)
                terms.append(" %s %.17E%s" % (s, abs(cf), mono))
            rows.append("\n".join(terms) + ";")
        return "%d %d\n%s\n" % (len(self.reduced), len(self.free), "\n".join(rows))


def singular_values(rows):
    """Singular values of a matrix (a list of rows, floats), largest first: one-sided Jacobi
    (Hestenes) on its columns, accurate to a few ulps relative to the largest."""
    if not rows or not rows[0]:
        return []
    cols = [list(c) for c in zip(*rows)]
    n = len(cols)
    for _ in range(80):
        rotated = False
        for i in range(n - 1):
            for j in range(i + 1, n):
                ci, cj = cols[i], cols[j]
                a = sum(v * v for v in ci)
                b = sum(v * v for v in cj)
                c = sum(u * v for u, v in zip(ci, cj))
                if c == 0.0 or abs(c) <= 1e-16 * (a * b) ** 0.5:
                    continue
                rotated = True
                zeta = (b - a) / (2.0 * c)
                t = (1.0 if zeta >= 0 else -1.0) / (abs(zeta) + (1.0 + zeta * zeta) ** 0.5)
                cs = 1.0 / (1.0 + t * t) ** 0.5
                sn = cs * t
                cols[i] = [cs * u - sn * v for u, v in zip(ci, cj)]
                cols[j] = [sn * u + cs * v for u, v in zip(ci, cj)]
        if not rotated:
            break
    return sorted((sum(v * v for v in c) ** 0.5 for c in cols), reverse=True)


def greedy_independent_rows(rows, tau):
    """Rows (each of norm 1, or 0) taken in order, each kept when the part of it orthogonal
    to the rows kept so far has norm above tau (modified Gram-Schmidt, twice). Returns (kept
    indices, dropped indices, the smallest remainder kept, the largest remainder dropped)."""
    basis, kept, dropped = [], [], []
    rmin, rmax = None, None
    for k, row in enumerate(rows):
        r = list(row)
        for _ in range(2):
            for q in basis:
                f = sum(u * v for u, v in zip(r, q))
                r = [u - f * v for u, v in zip(r, q)]
        nrm = sum(v * v for v in r) ** 0.5
        if nrm > tau:
            basis.append([v / nrm for v in r])
            kept.append(k)
            rmin = nrm if rmin is None else min(rmin, nrm)
        else:
            dropped.append(k)
            rmax = nrm if rmax is None else max(rmax, nrm)
    return kept, dropped, rmin, rmax


# ---------------------------------------------------------------------------------------
# the generator


def fresh_point(scene, rng):
    """A random point apart from every point drawn so far (two points of a body must not
    coincide)."""
    taken = set(scene.world.values())
    while True:
        p = rand_point(rng)
        if p not in taken:
            return p


def attach_labels(scene, rng, counter, bodies, k):
    """k new labels shared by the given bodies, at random world positions."""
    labs = []
    for _ in range(k):
        counter[0] += 1
        lab = "S%d" % counter[0]
        scene.world[lab] = fresh_point(scene, rng)
        for b in bodies:
            scene._world_pts[b].append(lab)
        labs.append(lab)
    return labs


def private_labels(scene, rng, counter, b, k):
    for _ in range(k):
        counter[0] += 1
        lab = "P%d" % counter[0]
        scene.world[lab] = fresh_point(scene, rng)
        scene._world_pts[b].append(lab)


def localize(scene):
    """Local coordinates of every body from the world positions and the poses."""
    scene.bodies = []
    for b, labs in enumerate(scene._world_pts):
        if not labs:
            continue  # a body not attached yet (they come last)
        R, t = scene._poses[b]
        Rt = transpose(R)
        scene.bodies.append([scene._names[b], {lab: matvec(Rt, vsub(scene.world[lab], t)) for lab in labs}])


def scene_dof(scene):
    localize(scene)
    f = Formulation(scene)
    bad = f.check_planted()
    if bad:
        raise AssertionError("planted configuration violates %s" % bad[:3])
    return f.dof()


def generate_scene(rng, max_distances=6, max_variables=10):
    """A small random rigid planted scene. Bodies are attached one after the other to an
    earlier body by 0, 1, 2 or 3 shared points (new points, or points the earlier body
    already has, which may then be in three bodies; each attachment must remove exactly
    0, 3, 5 or 6 degrees of freedom at the planted configuration), sometimes a cycle is
    closed by one more shared point (if it removes exactly 3), and the remaining degrees
    of freedom are closed by as many distances between points of different bodies (each
    must remove exactly one)."""
    while True:
        k = rng.choice([2, 2, 3, 3, 3, 4])
        sc = Scene()
        sc._names = ["F"] + ["B%d" % i for i in range(1, k)]
        sc._poses = [(((Q(1), Q(0), Q(0)), (Q(0), Q(1), Q(0)), (Q(0), Q(0), Q(1))), (Q(0), Q(0), Q(0)))]
        for _ in range(1, k):
            sc._poses.append((rand_rotation(rng), rand_point(rng)))
        sc._world_pts = [[] for _ in range(k)]
        counter = [0]
        desc = []
        private_labels(sc, rng, counter, 0, rng.randint(3, 5))
        dof = 0
        ok = True
        shares = set()
        for i in range(1, k):
            j = rng.randrange(i)
            # s = 0: a body held by distances only (six of them: a Stewart platform when
            # it is the only one)
            s = rng.choices([0, 1, 2, 3], weights=[8, 42, 40, 10])[0]
            existing = [l for l in sc._world_pts[j]]
            for _ in range(s):
                if existing and rng.random() < 0.3:
                    # a point body j already has (and shares, maybe): a label in 3 bodies
                    lab = existing.pop(rng.randrange(len(existing)))
                    sc._world_pts[i].append(lab)
                else:
                    attach_labels(sc, rng, counter, [i, j], 1)
            # (a body held by distances alone gets up to 6 points: a general Stewart
            # platform, up to 40 complex configurations, when the frame has 6 too)
            private_labels(sc, rng, counter, i, max(0, 3 - s) + rng.randint(0, 3 if s == 0 else 2))
            if s:
                shares.add((j, i))
            expect = dof + 6 - {0: 0, 1: 3, 2: 5, 3: 6}[s]
            dof = scene_dof(sc)
            if dof != expect:
                ok = False
                break
            desc.append("%s-%s:%d" % (sc._names[j], sc._names[i], s))
        if not ok:
            continue
        # close a cycle by one more shared point, sometimes
        if k >= 3 and rng.random() < 0.35:
            pairs = [(a, b) for a in range(k) for b in range(a + 1, k) if (a, b) not in shares]
            rng.shuffle(pairs)
            for a, b in pairs:
                saved = ([list(p) for p in sc._world_pts], dict(sc.world), counter[0])
                attach_labels(sc, rng, counter, [a, b], 1)
                d = scene_dof(sc)
                if d == dof - 3 and d >= 0:
                    dof = d
                    desc.append("%s-%s:1(cycle)" % (sc._names[a], sc._names[b]))
                    break
                sc._world_pts, sc.world, counter[0] = saved
        if dof > max_distances:
            continue
        # distances
        lb = {}
        for b, labs in enumerate(sc._world_pts):
            for lab in labs:
                lb.setdefault(lab, set()).add(b)
        labels = sorted(lb)
        for _ in range(dof):
            placed = False
            used = {w for a, b, _ in sc.distances for w in (a, b)}
            fresh = [w for w in labels if w not in used]
            for attempt in range(60):
                # distances between points not used by a distance yet first: coupled,
                # harder systems than several distances ending at one point
                u, v = rng.sample(fresh if attempt < 30 and len(fresh) >= 2 else labels, 2)
                if lb[u] & lb[v] or (0 in lb[u] and 0 in lb[v]):
                    continue
                if any({u, v} == {a, b} for a, b, _ in sc.distances):
                    continue
                d2 = dot(vsub(sc.world[u], sc.world[v]), vsub(sc.world[u], sc.world[v]))
                sc.distances.append((u, v, d2))
                d = scene_dof(sc)
                if d == dof - 1:
                    dof = d
                    placed = True
                    break
                sc.distances.pop()
            if not placed:
                break
        if dof != 0:
            continue
        localize(sc)
        form = Formulation(sc)
        if form.n < 3:
            continue  # nothing moves
        form.select_square()
        if len(form.reduce()) > max_variables:
            continue  # too many paths for phc
        sc.structure = "bodies %d; shares %s; %d distances" % (k, ", ".join(desc), len(sc.distances))
        # the frame need not be the first body of the file
        if rng.random() < 0.3:
            perm = list(range(k))
            rng.shuffle(perm)
            sc.bodies = [sc.bodies[p] for p in perm]
            sc.frame = perm.index(0)
        return sc


# ---------------------------------------------------------------------------------------
# a scene from a file (--scene)


class SceneRefused(Exception):
    """A scene file this comparison does not handle (the message says why)."""


def read_scene_file(path):
    """A Scene from a file in the format "rigid-incidence-scene/1", every number exact (JSON
    numbers are read from their text, like the package does), and the unit its lengths
    are in: the Scene holds them divided by unit (a power of 10, 1 unless the scene's size
    is outside 0.1 to 1000), so that the system phc sees has coordinates of size 1 to
    1000, as for a generated scene written with a unit. A bar (a body of 2 points) becomes
    the distance of its points, as in the package; a point only in bars is a free point
    (3 variables of its own). Refused (SceneRefused): "inequalities" (the system here
    has none: the package prunes configurations by them), "free_distance" (a curve of
    configurations), distances of 0 (coincidences: labels the package merges), lengths
    and squares that are not positive numbers, bodies the package refuses (fewer than 2
    points, 3 or more all on one line, a bar as the frame, bars only), unknown labels."""
    try:
        with open(path) as fh:
            doc = json.load(fh, parse_float=str, parse_int=str)
    except (OSError, ValueError) as e:
        raise SceneRefused("cannot read %s: %s" % (path, e))
    if not isinstance(doc, dict) or doc.get("format") != "rigid-incidence-scene/1":
        raise SceneRefused("%s: not a scene in the format \"rigid-incidence-scene/1\"" % path)
    if "inequalities" in doc:
        raise SceneRefused("%s: the scene has \"inequalities\", which the world-coordinate system here "
                           "cannot express (the package prunes configurations by them): not compared" % path)
    if "free_distance" in doc:
        raise SceneRefused("%s: the scene has a \"free_distance\": its configurations form curves (a "
                           "family), and phc is compared here on isolated ones: not compared" % path)

    def num(v, what):
        if isinstance(v, bool) or not isinstance(v, str):
            raise SceneRefused("%s: %s: %r is not a number" % (path, what, v))
        try:
            return Q(v.strip())
        except (ValueError, ZeroDivisionError):
            raise SceneRefused("%s: %s: %r is not a number" % (path, what, v))

    scene = Scene()
    bars = []
    body_names = []
    for b in doc.get("bodies") or []:
        name = b.get("name")
        pts = {}
        for lab, xyz in (b.get("points") or {}).items():
            if not isinstance(xyz, list) or len(xyz) != 3:
                raise SceneRefused("%s: body '%s': point '%s': expected 3 coordinates" % (path, name, lab))
            pts[lab] = tuple(num(c, "body '%s': point '%s'" % (name, lab)) for c in xyz)
        body_names.append(name)
        if len(pts) < 2:
            raise SceneRefused("%s: body '%s' has fewer than 2 points" % (path, name))
        if len(pts) == 2:
            bars.append((name, pts))
            continue
        ps = list(pts.values())
        if all(collinear(ps[0], ps[1], r) for r in ps[2:]):
            raise SceneRefused("%s: body '%s': its points are collinear (the package refuses it)" % (path, name))
        scene.bodies.append([name, pts])
    if not scene.bodies:
        raise SceneRefused("%s: no body of 3 or more points (bars only, or no bodies)" % path)
    frame = doc.get("frame")
    if frame is None:
        scene.frame = 0  # the first body that is not a bar
    elif frame in [nm for nm, _ in bars]:
        raise SceneRefused("%s: the frame '%s' is a bar" % (path, frame))
    elif frame not in [nm for nm, _ in scene.bodies]:
        raise SceneRefused("%s: the frame '%s' names no body" % (path, frame))
    else:
        scene.frame = [nm for nm, _ in scene.bodies].index(frame)
    scene.labels = {lab for _, pts in scene.bodies for lab in pts} | {lab for _, pts in bars for lab in pts}
    for k, d in enumerate(doc.get("distances") or []):
        between = d.get("between")
        if not isinstance(between, list) or len(between) != 2 or between[0] == between[1]:
            raise SceneRefused("%s: distances[%d]: \"between\" must name two different points" % (path, k))
        u, v = between
        for w in (u, v):
            if w not in scene.labels:
                raise SceneRefused("%s: distances[%d]: names unknown point '%s'" % (path, k, w))
        if ("squared" in d) == ("length" in d):
            raise SceneRefused("%s: distances[%d]: give exactly one of \"squared\" and \"length\"" % (path, k))
        d2 = num(d["squared"], "distances[%d]" % k) if "squared" in d else num(d["length"], "distances[%d]" % k) ** 2
        if "length" in d and num(d["length"], "distances[%d]" % k) < 0 or d2 < 0:
            raise SceneRefused("%s: distances[%d]: negative" % (path, k))
        if d2 == 0:
            raise SceneRefused("%s: distances[%d] ('%s'-'%s') is 0, a coincidence (the package merges the two "
                               "labels): not supported by this comparison" % (path, k, u, v))
        scene.distances.append((u, v, d2))
    for name, pts in bars:
        (u, p), (v, q) = sorted(pts.items())
        scene.distances.append((u, v, dot(vsub(p, q), vsub(p, q))))
    # the unit: the system here at size 0.1 to 1000 (the scene's own when it is)
    big, small = scene.size2()
    if small < Q(1, 10 ** 16) * big:
        raise SceneRefused("%s: lengths from %s to %s, more than 8 orders of magnitude apart: the "
                           "comparison in floats (tolerances relative to the scene's size) would not tell "
                           "configurations apart" % (path, sqrt_str(small), sqrt_str(big)))
    unit = Q(1)
    if not Q(1, 100) <= big <= 10 ** 6:
        e = 0
        while Q(100) ** (e + 1) <= big:
            e += 1
        while Q(100) ** e > big:
            e -= 1
        unit = Q(10) ** e
        scene.bodies = [[nm, {lab: tuple(c / unit for c in p) for lab, p in pts.items()}] for nm, pts in scene.bodies]
        scene.distances = [(u, v, d2 / (unit * unit)) for u, v, d2 in scene.distances]
    scene.structure = ("file: %d bodies (%d bars), %d distances, frame %s%s"
                       % (len(scene.bodies) + len(bars), len(bars), len(doc.get("distances") or []),
                          scene.bodies[scene.frame][0], "; lengths times %s" % frac_str(unit) if unit != 1 else ""))
    return scene, unit


def sqrt_str(x):
    """The square root of a positive Fraction, printed, even beyond the range of floats."""
    lg = (math.log10(x.numerator) - math.log10(x.denominator)) / 2
    return "%.3g" % 10 ** lg if abs(lg) < 300 else "1e%d" % round(lg)


def compare_file(args, index, path, rng_seed):
    """The comparison for a scene read from a file (--scene): the package runs on the file
    itself; the square subsystem is chosen at its configurations (compare_formulation)."""
    t0 = time.time()
    rec = {"index": index, "seed": rng_seed, "scene": path, "structure": "", "problems": [], "notes": [],
           "verdict": None}
    try:
        scene, unit = read_scene_file(path)
    except SceneRefused as e:
        rec["problems"].append(str(e))
        rec["verdict"] = "refused"
        return rec
    rec["structure"] = scene.structure
    form = Formulation(scene)
    if form.n == 0:
        rec["problems"].append("nothing moves: every point is fixed by the frame body")
        rec["verdict"] = "not-compared"
        return rec
    name = "phc_file_%03d_%s" % (index, re.sub(r"[^A-Za-z0-9_.-]", "_", os.path.splitext(os.path.basename(path))[0]))
    return compare_formulation(args, rec, scene, form, path, name, unit, rng_seed, t0)


def system_size(form):
    """Sizes of the system given to phc: variables and equations of the whole system, the
    rank of the quadratic parts of the combined square subsystem (its total degree is 2 to
    that power), the variables left in the reduced form (each of its equations quadratic)."""
    form.combined()
    size = {"variables": form.n, "equations": len(form.equations), "square": len(form.square),
            "quadratic_rank": form.quadratic_rank}
    try:
        form.reduce()
        size["reduced_variables"] = len(form.free)
    except AssertionError as e:
        size["reduced_variables"] = -1
        size["reduce_error"] = str(e)
    return size


# ---------------------------------------------------------------------------------------
# float Newton and residuals on the whole system


def solve_linear(A, b):
    """Gaussian elimination with partial pivoting; None if singular."""
    n = len(b)
    M = [list(A[i]) + [b[i]] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        if abs(M[p][c]) < 1e-300:
            return None
        M[c], M[p] = M[p], M[c]
        for r in range(c + 1, n):
            f = M[r][c] / M[c][c]
            if f != 0:
                for cc in range(c, n + 1):
                    M[r][cc] -= f * M[c][cc]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        s = M[r][n] - sum(M[r][cc] * x[cc] for cc in range(r + 1, n))
        x[r] = s / M[r][r]
    return x


class FloatSystem:
    def __init__(self, form):
        self.form = form
        self.n = form.n
        self.polys = [[(float(c), m) for m, c in p.items()] for _, p in form.equations]
        # scale of each equation: its largest coefficient
        self.eq_scale = [max(abs(c) for c, _ in p) for p in self.polys]

    @property
    def square(self):
        # the form's (a scene from a file chooses it after this is made)
        return self.form.square

    def value(self, k, x):
        s = 0.0
        for c, m in self.polys[k]:
            t = c
            for i in m:
                t *= x[i]
            s += t
        return s

    def grad(self, k, x):
        g = [0.0] * self.n
        for c, m in self.polys[k]:
            for pos, i in enumerate(m):
                t = c
                for q, j in enumerate(m):
                    if q != pos:
                        t *= x[j]
                g[i] += t
        return g

    def newton(self, x, iters=8):
        x = list(x)
        for _ in range(iters):
            F = [self.value(k, x) for k in self.square]
            J = [self.grad(k, x) for k in self.square]
            dx = solve_linear(J, [-f for f in F])
            if dx is None:
                return x, False
            x = [a + b for a, b in zip(x, dx)]
            if max(abs(d) for d in dx) <= 1e-15 * max(1.0, max(abs(a) for a in x)):
                break
        return x, True

    def residual(self, x, scale):
        """Largest residual of every equation (the square ones and those left out), each
        relative to its coefficients and the square of the scene's size."""
        return max(abs(self.value(k, x)) / (self.eq_scale[k] * scale * scale) for k in range(len(self.polys)))

    def min_singular_estimate(self, x):
        """1 / (norm of the inverse Jacobian of the square subsystem), estimated."""
        J = [self.grad(k, x) for k in self.square]
        n = self.n
        norm_inv = 0.0
        for c in range(n):
            e = [0.0] * n
            e[c] = 1.0
            col = solve_linear(J, e)
            if col is None:
                return 0.0
            norm_inv = max(norm_inv, max(abs(v) for v in col))
        normJ = max(max(abs(v) for v in row) for row in J)
        return 1.0 / (norm_inv * normJ) if norm_inv > 0 else 0.0


# ---------------------------------------------------------------------------------------
# phc


def parse_phc_solutions(text):
    """Every solution list ("THE SOLUTIONS") of a phc output or input file, joined: a list
    of dicts {vars: {name: complex}, m, err, rco, res, tag}; None if there is none. phc -b
    appends the final list to its input file; its output file has the lists of the
    separate stages (the solutions with zero coordinates, found by the stable mixed
    volume, come in a list of their own)."""
    sols = None
    pos = text.find("THE SOLUTIONS")
    while pos >= 0:
        _, part = parse_one_solution_list(text[pos:])
        sols = (sols or []) + part
        pos = text.find("THE SOLUTIONS", pos + 1)
    return sols


def parse_one_solution_list(text):
    lines = text.splitlines()
    sols = []
    cur = None
    for ln in lines[1:]:
        s = ln.strip()
        if s.startswith("== #regu") or s.startswith("TIMING") or s.startswith("THE SOLUTIONS"):
            break
        if re.match(r"^(solution \d+|== \d+ =)", s):
            cur = {"vars": {}, "tag": s}
            sols.append(cur)
            continue
        if cur is None:
            continue
        if s.startswith("m :") or s.startswith("m:"):
            try:
                cur["m"] = int(s.split(":")[1].split()[0])
            except (ValueError, IndexError):
                cur["m"] = 1
            continue
        if s.startswith("t :") or s.startswith("the solution"):
            continue
        if s.startswith("== err"):
            parts = s.replace("=", " ").split()
            for key in ("err", "rco", "res"):
                if key in parts:
                    i = parts.index(key)
                    try:
                        cur[key] = float(parts[i + 2] if parts[i + 1] == ":" else parts[i + 1])
                    except (ValueError, IndexError):
                        pass
            continue
        if ":" in s:
            name, rest = s.split(":", 1)
            vals = rest.split()
            if len(vals) >= 2:
                try:
                    cur["vars"][name.strip()] = complex(float(vals[0]), float(vals[1]))
                except ValueError:
                    pass
    return None, sols


def run_phc(phc, form, path_in, path_out, seed, timeout, variant):
    with open(path_in, "w") as fh:
        fh.write(form.phc_text(variant))
    if os.path.exists(path_out):
        os.remove(path_out)
    t0 = time.time()
    try:
        proc = subprocess.run([phc, "-b", "-0%d" % seed, path_in, path_out], stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "phc timed out after %d s" % timeout, time.time() - t0
    dt = time.time() - t0
    if not os.path.exists(path_out):
        return None, "phc wrote no output (status %d): %s" % (proc.returncode, proc.stderr[-500:]), dt
    with open(path_out) as fh:
        text = fh.read()
    with open(path_in) as fh:
        appended = fh.read()
    sols_in = parse_phc_solutions(appended)
    sols_out = parse_phc_solutions(text)
    if sols_in is None and sols_out is None:
        return None, "no solution list in the phc output (status %d)" % proc.returncode, dt
    sols = (sols_in or []) + (sols_out or [])
    summary = {}
    for ln in text.splitlines():
        if ln.strip().startswith("== #regu"):
            parts = ln.replace("=", " ").replace(":", " ").split()
            for key in ("#regu", "#sing", "#clus", "#infi", "#fail", "#real", "#cmplx"):
                if key in parts:
                    try:
                        summary[key] = int(parts[parts.index(key) + 1])
                    except (ValueError, IndexError):
                        pass
    # "paths": the length of phc's final list (appended to the input file)
    return {"solutions": sols, "summary": summary, "paths": len(sols_in or [])}, None, dt


def real_phc_solutions(form, fsys, phc_result, scale):
    """Real solutions of the whole system among phc's: (nonsingular, singular, other)
    lists of variable vectors (polished by Newton)."""
    names = [form.var_name(i) for i in form.free]
    nonsing, sing, spurious = [], [], []
    for s in phc_result["solutions"]:
        if any(nm not in s["vars"] for nm in names):
            continue
        z = form.expand([s["vars"][nm] for nm in names])
        size = max(1.0, max(abs(c) for c in z))
        if max(abs(complex(c).imag) for c in z) > 1e-8 * size:
            continue
        x = [complex(c).real for c in z]
        x2, ok = fsys.newton(x)
        if ok and max(abs(a - b) for a, b in zip(x, x2)) < 1e-6 * size:
            x = x2
        res = fsys.residual(x, scale)
        entry = {"x": x, "rco": s.get("rco"), "m": s.get("m", 1), "res": res}
        if res > 1e-8:
            spurious.append(entry)  # a solution of the square subsystem only
            continue
        sigma = fsys.min_singular_estimate(x)
        entry["sigma"] = sigma
        if s.get("m", 1) > 1 or sigma < 1e-9 or (s.get("rco") is not None and s["rco"] < 1e-10):
            sing.append(entry)
        else:
            nonsing.append(entry)
    return distinct(nonsing, scale), distinct(sing, scale), spurious


def distinct(entries, scale):
    out = []
    for e in entries:
        if not any(max(abs(a - b) for a, b in zip(e["x"], f["x"])) < 1e-6 * scale for f in out):
            out.append(e)
    return out


# ---------------------------------------------------------------------------------------
# the package


def run_tool(tool, scene_path, timeout):
    t0 = time.time()
    try:
        proc = subprocess.run([tool, "solve", scene_path, "--json"], stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "rigid_incidence timed out after %d s" % timeout, time.time() - t0
    dt = time.time() - t0
    try:
        out = json.loads(proc.stdout.decode())
    except ValueError:
        return None, "rigid_incidence status %d, no JSON: %s" % (proc.returncode, proc.stderr.decode()[-800:]), dt
    out["_status"] = proc.returncode
    return out, None, dt


def config_distance(pa, pb, labels):
    return max(abs(pa[l][k] - pb[l][k]) for l in labels for k in range(3))


# ---------------------------------------------------------------------------------------
# one scene


def compare_scene(args, index, rng_seed):
    rng = random.Random(rng_seed)
    t0 = time.time()
    scene = generate_scene(rng, max_variables=args.max_variables)
    # a scene in four is written at another scale (the package's tolerances are relative to
    # the scene's size; the system here stays at size 1 to 10)
    unit = rng.choice([Q(1)] * 12 + [Q(1, 1000), Q(1000), Q(10 ** 6), Q(1, 10 ** 5)])
    if unit != 1:
        scene.structure += "; lengths times %s" % frac_str(unit)
    name = "phc_scene_%03d" % index
    scene_path = os.path.join(args.workdir, name + ".json")
    with open(scene_path, "w") as fh:
        json.dump(scene.to_json(name, unit), fh, indent=1)
    rec = {"index": index, "seed": rng_seed, "scene": scene_path, "structure": scene.structure,
           "problems": [], "notes": [], "verdict": None, "t_generate": time.time() - t0}
    form = Formulation(scene)
    bad = form.check_planted()
    if bad:
        rec["problems"].append("the planted configuration does not solve the system: %s" % bad[:3])
        rec["verdict"] = "disagree"
        return rec
    rank = form.select_square()
    if rank != form.n:
        rec["problems"].append("the system is not rigid at the planted configuration (rank %d of %d)" % (rank, form.n))
        rec["verdict"] = "disagree"
        return rec
    return compare_formulation(args, rec, scene, form, scene_path, name, unit, rng_seed, t0)


def compare_formulation(args, rec, scene, form, scene_path, name, unit, rng_seed, t0):
    """Steps 3 and 4 for one scene: a generated one (form.values holds the planted
    configuration, the square subsystem is chosen already) or one read from a file
    (form.values is None: the square subsystem is chosen here, at the package's
    configurations, by select_square_numeric). rng_seed seeds phc's runs."""
    planted = form.values is not None
    if planted:
        rec["variables"] = form.n
        rec["equations"] = len(form.equations)
        rec["left_out"] = [form.equations[k][0] for k in form.left_out]
    scale = scene.scale()
    labels = scene.all_labels()
    planted_pts = {l: tuple(float(c) for c in p) for l, p in scene.world.items()} if planted else None
    fsys = FloatSystem(form)
    tol = args.tolerance * scale

    # the package
    pkg, err, t_pkg = run_tool(args.tool, scene_path, args.timeout)
    rec["t_package"] = t_pkg
    if pkg is None:
        rec["problems"].append(err)
        rec["verdict"] = "disagree"
        return rec
    sols = pkg.get("solutions", [])
    if args.mutate and sols:
        # a check of this script: a tampered package answer must be caught
        if args.mutate == "drop":
            sols = sols[:-1]
        elif args.mutate == "perturb":
            lab = sorted(sols[-1]["points"])[-1]
            sols[-1]["points"][lab][0] += 1e-3 * scale * float(unit)
    pkg_pts = []
    for s in sols:
        pts = {l: tuple(c / float(unit) for c in v) for l, v in s.get("points", {}).items()}
        missing = [l for l in labels if l not in pts]
        if missing:
            rec["problems"].append("a package configuration lacks the points %s" % missing)
            continue
        pkg_pts.append({"points": pts, "certified": s.get("certified"), "singular": s.get("singular")})
    rec["package"] = {"complete": pkg.get("complete"), "certified": pkg.get("certified"),
                      "solutions": len(sols),
                      "certified_solutions": sum(1 for s in sols if s.get("certified")),
                      "unresolved": len(pkg.get("unresolved") or []),
                      "curves": len(pkg.get("curves") or []),
                      "no_configuration": pkg.get("no_configuration"),
                      "diagnosis": pkg.get("diagnosis"), "status": pkg["_status"]}
    if pkg.get("curves"):
        rec["problems"].append("the package finds curves of configurations; the planted one is isolated"
                               if planted else "the package finds curves of configurations; phc compares "
                               "isolated ones")
    if planted:
        # the planted configuration must be one of the package's
        dmin = min((config_distance(planted_pts, p["points"], labels) for p in pkg_pts), default=float("inf"))
        if dmin > tol:
            rec["problems"].append("the planted configuration is not among the package's (closest at %.3g)" % dmin)
    else:
        # no planted configuration: the square subsystem is chosen at the package's
        if not pkg_pts:
            rec["problems"].append("the package gives no configuration (%s): the square subsystem of a scene "
                                   "from a file is chosen at the package's configurations"
                                   % (pkg.get("no_configuration") or pkg.get("diagnosis") or "none found"))
            rec["verdict"] = "not-compared"
            rec["t_total"] = time.time() - t0
            return rec
        info = form.select_square_numeric(fsys, [form.variables_from_points(p["points"]) for p in pkg_pts])
        if not info["chosen"]:
            rec["problems"].append("the system is not rigid at any package configuration (numerical ranks %s "
                                   "of %d%s; each is a singular solution of the whole system, which phc "
                                   "cannot confirm as nonsingular): no square subsystem chosen"
                                   % (info["ranks"], form.n, "; " + "; ".join(info["choices"]) if info["choices"]
                                      else ""))
            rec["verdict"] = "not-compared"
            rec["t_total"] = time.time() - t0
            return rec
        rec["variables"] = form.n
        rec["equations"] = len(form.equations)
        rec["left_out"] = [form.equations[k][0] for k in form.left_out]
        rec["square_choice"] = info
        for j in info["singular_at"]:
            rec["notes"].append("package configuration %d is a singular solution of the square subsystem chosen "
                                "(inverse condition %.3g; not of the whole system): phc may miss it"
                                % (j, info["inverse_conditions"][j]))
        if len(info["ranks"]) != sum(1 for r in info["ranks"] if r == form.n):
            rec["notes"].append("numerical ranks of the whole Jacobian at the package's configurations: %s "
                                "(of %d)" % (info["ranks"], form.n))
        rec["system"] = system_size(form)
        print("  %s: %d variables, %d equations (%d left out: %s); combined: %d quadratic equations (total "
              "degree 2^%d); reduced: %d variables (total degree 2^%d); rank margins: kept >= %.3g, dropped "
              "<= %s; square subsystem inverse condition >= %.3g"
              % (name, form.n, len(form.equations), len(form.left_out), ", ".join(rec["left_out"]) or "none",
                 rec["system"]["quadratic_rank"], rec["system"]["quadratic_rank"],
                 rec["system"]["reduced_variables"], rec["system"]["reduced_variables"],
                 info["kept_margin"], "%.3g" % info["dropped_margin"] if info["dropped_margin"] is not None
                 else "(none dropped)", min(info["inverse_conditions"])),
              file=sys.stderr, flush=True)
    # every package configuration must solve the system here
    for j, p in enumerate(pkg_pts):
        x0 = form.variables_from_points(p["points"])
        x1, ok = fsys.newton(x0)
        # how far Newton moved it, over every point (the variables place only some)
        moved = config_distance(p["points"], form.all_points(x1), labels) if ok else float("inf")
        res = fsys.residual(x1, scale)
        p["x"] = x1
        sigma = fsys.min_singular_estimate(x1) if ok else 0.0
        if not ok or moved > tol or res > 1e-8:
            rec["problems"].append("package configuration %d is not a solution of the system here "
                                   "(Newton moved it by %.3g, residual %.3g)" % (j, moved, res))
        elif sigma < 1e-9 and not p["singular"]:
            rec["problems"].append("package configuration %d is a singular solution of the system here "
                                   "(inverse condition %.3g), not marked singular" % (j, sigma))
        cfg_res = fsys.residual(x0, scale)
        if cfg_res > 1e-6:
            rec["problems"].append("package configuration %d has residual %.3g in the system here" % (j, cfg_res))
    # package configurations distinct
    for a in range(len(pkg_pts)):
        for b in range(a + 1, len(pkg_pts)):
            if config_distance(pkg_pts[a]["points"], pkg_pts[b]["points"], labels) < tol:
                rec["problems"].append("package configurations %d and %d are the same" % (a, b))

    # phc, with reruns under other seeds when the counts differ
    t_phc = 0.0
    real_ns, real_s, spurious = [], [], []
    phc_runs = []
    phc_error = None
    n_pkg_cert = rec["package"]["certified_solutions"]
    # the reruns alternate between the two forms of the system: phc's path tracking was
    # seen to lose paths on the reduced form for some seeds where the combined one (more
    # variables, slower root counts) did not
    variants = [args.form, "combined" if args.form == "reduced" else "reduced"]
    for run in range(1 + args.phc_retries):
        seed = (rng_seed * 7919 + 104729 * run) % 2147483647 + 1
        res, err, dt = run_phc(args.phc, form, os.path.join(args.workdir, name + ".phc%d.in" % run),
                               os.path.join(args.workdir, name + ".phc%d.out" % run), seed, args.timeout,
                               variants[run % 2])
        t_phc += dt
        if res is None:
            phc_error = err
            continue
        phc_runs.append({"seed": seed, "form": variants[run % 2], "paths": res["paths"],
                         "summary": res["summary"], "seconds": dt})
        ns, sg, sp = real_phc_solutions(form, fsys, res, scale)
        real_ns = distinct(real_ns + ns, scale)
        real_s = distinct(real_s + sg, scale)
        spurious += sp
        # enough when phc has the planted configuration and every one of the package's,
        # and as many as the package when it says complete
        found = [form.all_points(e["x"]) for e in real_ns]
        xp = [float(v) for v in form.values] if planted else None
        if ((not planted or any(max(abs(a - b) for a, b in zip(xp, e["x"])) < tol for e in real_ns)) and not real_s
                and all(any(config_distance(p["points"], q, labels) < tol for q in found) for p in pkg_pts)
                and (len(real_ns) == n_pkg_cert or not rec["package"]["complete"])):
            break
    rec["t_phc"] = t_phc
    rec["phc_runs"] = phc_runs
    if not phc_runs:
        rec["problems"].append("phc failed: %s" % phc_error)
        rec["verdict"] = "phc-failure"
        rec["t_total"] = time.time() - t0
        return rec
    rec["phc"] = {"real_nonsingular": len(real_ns), "real_singular": len(real_s),
                  "subsystem_only": len(distinct(spurious, scale)), "paths": phc_runs[0]["paths"]}
    phc_pts = [form.all_points(e["x"]) for e in real_ns]
    if planted:
        xp = [float(v) for v in form.values]
        if not any(max(abs(a - b) for a, b in zip(xp, e["x"])) < tol for e in real_ns + real_s):
            rec["notes"].append("phc did not find the planted configuration")
    # matching
    pkg_unmatched = [j for j, p in enumerate(pkg_pts)
                     if not any(config_distance(p["points"], q, labels) < tol for q in phc_pts)]
    phc_unmatched = [j for j, q in enumerate(phc_pts)
                     if not any(config_distance(p["points"], q, labels) < tol for p in pkg_pts)]
    rec["pkg_unmatched"] = pkg_unmatched
    rec["phc_unmatched"] = phc_unmatched
    rec["lists"] = {"package": [{l: p["points"][l] for l in labels} for p in pkg_pts],
                    "phc": [{l: q[l] for l in labels} for q in phc_pts],
                    "phc_singular": [form.all_points(e["x"]) for e in real_s]}
    complete = bool(rec["package"]["complete"])
    if complete:
        uncert = [j for j, p in enumerate(pkg_pts) if not p["certified"]]
        if uncert:
            rec["problems"].append("complete, yet configurations %s are not certified" % uncert)
    if n_pkg_cert != len(real_ns):
        rec["notes"].append("count: the package certifies %d configurations (%s), phc finds %d real "
                            "nonsingular solutions (%d singular)"
                            % (n_pkg_cert, "complete" if complete else "incomplete", len(real_ns), len(real_s)))
    if phc_unmatched:
        msg = ("real nonsingular phc solutions %s (each checked by Newton on the whole system) are not "
               "among the package's configurations" % phc_unmatched)
        if complete:
            rec["problems"].append(msg)  # the package missed a configuration
        else:
            rec["notes"].append(msg + " (the package says it is incomplete)")
    if pkg_unmatched:
        if any(msg.startswith("package configuration") for msg in rec["problems"]):
            rec["problems"].append("package configurations %s are not real phc solutions" % pkg_unmatched)
        else:
            # each solves the system here (Newton converged to a nonsingular solution next
            # to it, checked above): phc lost the paths, even with the reruns
            rec["notes"].append("package configurations %s (each a nonsingular solution of the system "
                                "here, by Newton) were not found by phc" % pkg_unmatched)
    if real_s:
        rec["notes"].append("phc finds %d real singular solutions" % len(real_s))
    if rec["problems"]:
        rec["verdict"] = "disagree"
    elif pkg_unmatched or real_s:
        rec["verdict"] = "phc-failure"
    elif not complete or phc_unmatched:
        rec["verdict"] = "package-incomplete"
    else:
        rec["verdict"] = "agree"
    rec["t_total"] = time.time() - t0
    return rec


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tool", required=True, help="the rigid_incidence executable")
    ap.add_argument("--phc", default="phc", help="the phc executable (run as phc -b, one thread)")
    ap.add_argument("--scenes", type=int, default=40)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--first", type=int, default=0, help="index of the first scene (to rerun one)")
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--timeout", type=int, default=900, help="seconds per run of either program")
    ap.add_argument("--tolerance", type=float, default=1e-6,
                    help="match tolerance on world coordinates, relative to the scene's size")
    ap.add_argument("--phc-retries", type=int, default=3,
                    help="extra phc runs with other seeds when the counts differ")
    ap.add_argument("--max-variables", type=int, default=10,
                    help="largest system given to phc (variables after the linear eliminations; "
                         "at most 2^N paths); larger scenes are drawn again (generated scenes only)")
    ap.add_argument("--form", choices=["combined", "reduced"], default="reduced",
                    help="the system given to phc first: the square subsystem combined to fewer "
                         "quadratic equations, or also with the linear equations eliminated "
                         "(default; fewer variables, faster root counts); reruns alternate")
    ap.add_argument("--mutate", choices=["drop", "perturb"],
                    help="tamper with the package's answers (drop the last configuration, or move "
                         "one of its points by 1e-3 of the scene's size) to check that this script "
                         "catches it: every scene should then disagree")
    ap.add_argument("--json", help="write every scene's record to this file")
    ap.add_argument("--scene", action="append", metavar="FILE.json",
                    help="compare on this existing scene file (format \"rigid-incidence-scene/1\") "
                         "instead of generated ones; repeatable (the files in order, --scenes and "
                         "--first ignored). No planted configuration: the square subsystem is chosen "
                         "by the numerical rank of the Jacobian at the package's configurations. "
                         "Scenes with \"inequalities\", a \"free_distance\" or a distance of 0 are "
                         "refused (exit status 2)")
    args = ap.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    records = []
    t_start = time.time()
    jobs = (list(enumerate(args.scene)) if args.scene
            else [(i, None) for i in range(args.first, args.first + args.scenes)])
    for i, path in jobs:
        scene_seed = args.seed * 1000003 + i
        try:
            rec = compare_scene(args, i, scene_seed) if path is None else compare_file(args, i, path, scene_seed)
        except Exception:  # a bug here is a failure too, with the seed to rerun it
            rec = {"index": i, "seed": scene_seed, "verdict": "disagree",
                   "problems": ["exception in phc_compare.py: " + traceback.format_exc()], "notes": [],
                   "scene": path or os.path.join(args.workdir, "phc_scene_%03d.json" % i), "structure": "?"}
        records.append(rec)
        pk = rec.get("package", {})
        ph = rec.get("phc", {})
        head = "scene %3d seed %d" % (i, rec["seed"]) if path is None else "file %s" % path
        print("%s: %-18s package %s%s, phc %s real (%s singular, %s endpoints, %d runs), "
              "%d vars; %.2fs + %.2fs  [%s]"
              % (head, rec["verdict"], pk.get("certified_solutions", "?"),
                 "" if pk.get("complete") else " (incomplete)", ph.get("real_nonsingular", "?"),
                 ph.get("real_singular", "?"), ph.get("paths", "?"), len(rec.get("phc_runs", [])),
                 rec.get("variables", 0),
                 rec.get("t_package", 0), rec.get("t_phc", 0), rec["structure"]),
              file=sys.stderr, flush=True)
        for msg in rec["problems"]:
            print("    problem: " + msg, file=sys.stderr)
        for msg in rec["notes"]:
            print("    note: " + msg, file=sys.stderr)
        if rec["verdict"] == "refused":
            pass
        elif rec["verdict"] != "agree" and path is not None:
            print("    rerun: %s --tool %s --phc %s --scene %s --workdir %s"
                  % (sys.argv[0], args.tool, args.phc, path, args.workdir), file=sys.stderr)
        elif rec["verdict"] != "agree":
            print("    rerun: %s --tool %s --phc %s --scenes 1 --seed %d --first %d --workdir %s"
                  % (sys.argv[0], args.tool, args.phc, args.seed, i, args.workdir), file=sys.stderr)
            print("    scene file %s:" % rec["scene"], file=sys.stderr)
            if os.path.exists(rec["scene"]):
                with open(rec["scene"]) as fh:
                    print("    " + fh.read().replace("\n", "\n    "), file=sys.stderr)
            if "lists" in rec:
                for key in ("package", "phc", "phc_singular"):
                    print("    %s configurations:" % key, file=sys.stderr)
                    for c in rec["lists"][key]:
                        print("      " + ", ".join("%s (%.9g, %.9g, %.9g)" % ((l,) + tuple(c[l]))
                                                   for l in sorted(c)), file=sys.stderr)
    elapsed = time.time() - t_start
    counts = {}
    for r in records:
        counts[r["verdict"]] = counts.get(r["verdict"], 0) + 1
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(records, fh, indent=1, default=str)
    t_pkg = sum(r.get("t_package", 0) for r in records)
    t_phc = sum(r.get("t_phc", 0) for r in records)
    print("\nsummary (seed %d, %.1f s: package %.1f s, phc %.1f s)" % (args.seed, elapsed, t_pkg, t_phc))
    print("  %-22s %d" % ("scenes", len(records)))
    for key in ("agree", "disagree", "package-incomplete", "phc-failure", "not-compared", "refused"):
        if key in ("not-compared", "refused") and key not in counts:
            continue  # (only scene files are refused or not compared)
        print("  %-22s %d" % ({"agree": "agreed", "disagree": "disagreements"}.get(key, key), counts.get(key, 0)))
    hist = {}
    for r in records:
        if "phc" in r:
            hist[r["phc"]["real_nonsingular"]] = hist.get(r["phc"]["real_nonsingular"], 0) + 1
    print("  real configurations per scene (phc): %s" % ", ".join("%d: %d" % kv for kv in sorted(hist.items())))
    bad = [r for r in records if r["verdict"] != "agree"]
    for r in bad:
        if args.scene:
            print("  file %s (%s): %s" % (r["scene"], r["verdict"], "; ".join(r["problems"] + r["notes"])))
            continue
        print("  scene %d (seed %d, %s): %s" % (r["index"], r["seed"], r["verdict"],
                                                "; ".join(r["problems"] + r["notes"])))
    if any(r["verdict"] == "refused" for r in records):
        return 2
    return 0 if not bad else 1


if __name__ == "__main__":
    sys.exit(main())
