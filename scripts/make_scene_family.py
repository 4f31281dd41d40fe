#!/usr/bin/env python3
# Usage: scripts/make_scene_family.py FAMILY SIZE [--seed N] [--planted FILE] > scene.json
#
# Planted scenes of issue 28's families, at any size: exact rational world points, each body
# given in its own frame by a rational rotation (Cayley) and translation, so the planted
# configuration solves the scene exactly. The first body is the frame (identity pose), so
# the planted points in the frame's coordinates are the world points; --planted writes them as
# {"points": {label: [x, y, z]}} (what `rigid_incidence solve --near` reads, and what
# benchmark/Rigid_incidence/scene_families.py looks for among the configurations).
#
# FAMILY (SIZE):
#   chain K     K tetrahedra (a_i, b_i, a_i+1, b_i+1) hinged edge to edge, braced by the K-2
#               distances b_i - a_i+3, closed by a_0 - b_K
#   ring K      the same K tetrahedra closed into a ring (t_K-1 holds a_0 b_0), K >= 6, with
#               the K-6 distances b_i - a_i+3 (K = 6: the general 6R loop)
#   tree K      a binary tree of K six-point bodies, each child hinged on two points of its
#               parent; a first child is held by a distance to a point of its parent off the
#               hinge, a second one by a distance to its elder sibling
#   molecule N  a ring of N atoms, N >= 6, one triangle body per atom (its two bonds and the
#               bond angle: A_i-1 A_i A_i+1), consecutive bodies sharing a bond as a hinge, the
#               N-6 torsions fixed by the 1-4 distances A_k-1 - A_k+2
#   platforms K K Stewart-Gough 6-6 platforms stacked: plates P_0 (the frame) .. P_K of six
#               points, each held by six legs (distances) to the plate below
#   strip K     a braced strip: K triangles (p_i, p_i+1, p_i+2) hinged edge to edge, braced by
#               the K-1 distances p_i - p_i+3 (2^(K-1) configurations: each fold up or down)
import argparse, json, math, random, sys
from fractions import Fraction as F

FAMILIES = ("chain", "ring", "tree", "molecule", "platforms", "strip")


def main():
    ap = argparse.ArgumentParser(description="planted scenes of issue 28's families")
    ap.add_argument("family", choices=FAMILIES)
    ap.add_argument("size", type=int)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--planted", help="also write the planted configuration to this file")
    a = ap.parse_args()
    scene, planted = make(a.family, a.size, a.seed)
    json.dump(scene, sys.stdout, indent=1)
    sys.stdout.write("\n")
    if a.planted:
        with open(a.planted, "w") as f:
            json.dump({"points": {k: [float(v) for v in p] for k, p in planted.items()}}, f, indent=1)


class Rng:
    def __init__(self, seed):
        self.r = random.Random(seed)

    def q(self, lo, hi, den=7):
        """a rational in [lo, hi] with denominator den"""
        return F(self.r.randint(round(lo * den), round(hi * den)), den)

    def point(self, c=(0, 0, 0), s=1.0, den=7):
        return tuple(F(c[j]) + self.q(-s, s, den) for j in range(3))


def approx(x, den=7):
    return F(round(x * den), den)


def cayley(u):
    p, q, s = u
    n = 1 + p * p + q * q + s * s
    return [[(1 + p * p - q * q - s * s) / n, 2 * (p * q - s) / n, 2 * (p * s + q) / n],
            [2 * (p * q + s) / n, (1 - p * p + q * q - s * s) / n, 2 * (q * s - p) / n],
            [2 * (p * s - q) / n, 2 * (q * s + p) / n, (1 - p * p - q * q + s * s) / n]]


def local(R, t, X):  # the body's coordinates of the world point X: R^T (X - t)
    d = [X[j] - t[j] for j in range(3)]
    return [sum(R[j][i] * d[j] for j in range(3)) for i in range(3)]


def text(v):
    return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"


def d2(P, Q):
    return sum((P[j] - Q[j]) ** 2 for j in range(3))


def det3(u, v, w):
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def sub(P, Q):
    return tuple(P[j] - Q[j] for j in range(3))


def build(name, comment, world, bodies, distances, seed):
    """world: label -> point; bodies: [(name, [labels])] (the first is the frame);
    distances: [(label, label)]"""
    g = Rng(seed * 7919 + 17)
    out = []
    for i, (bname, labels) in enumerate(bodies):
        if i == 0:
            R = [[F(1), F(0), F(0)], [F(0), F(1), F(0)], [F(0), F(0), F(1)]]
            t = (F(0), F(0), F(0))
        else:
            R = cayley((g.q(-2, 2, 3), g.q(-2, 2, 3), g.q(-2, 2, 3)))
            t = g.point(s=5)
        out.append({"name": bname, "points": {lab: [text(v) for v in local(R, t, world[lab])] for lab in labels}})
    dist = [{"between": [u, v], "squared": text(d2(world[u], world[v]))} for u, v in distances]
    scene = {"format": "rigid-incidence-scene/1", "name": name, "comment": comment, "bodies": out,
             "distances": dist, "frame": bodies[0][0]}
    used = {lab for _, labels in bodies for lab in labels}
    return scene, {lab: world[lab] for lab in sorted(used)}


def make(family, k, seed):
    g = Rng(seed)
    planted = f"planted with exact rational poses (seed {seed}), scripts/make_scene_family.py {family} {k}"
    if family in ("chain", "ring"):
        if family == "ring" and k < 6:
            sys.exit("make_scene_family: a ring needs 6 tetrahedra at least")
        if k < 1:
            sys.exit("make_scene_family: a chain needs 1 tetrahedron at least")
        world = {}
        n = k + 1 if family == "chain" else k
        for i in range(n):
            if family == "chain":
                c = (2.5 * i, 0, 0)
            else:  # around a circle of circumference about 2.5 k
                r = 2.5 * k / (2 * math.pi)
                c = (r * math.cos(2 * math.pi * i / k), r * math.sin(2 * math.pi * i / k), 0)
            a = tuple(approx(c[j]) + g.q(-0.5, 0.5) for j in range(3))
            world[f"a{i}"] = a
            world[f"b{i}"] = (a[0] + g.q(-1, 1), a[1] + g.q(-1, 1), a[2] + g.q(1.5, 3))
        bodies = [(f"t{i}", [f"a{i}", f"b{i}", f"a{(i + 1) % n}", f"b{(i + 1) % n}"]) for i in range(k)]
        if family == "chain":
            dist = [(f"b{i}", f"a{i + 3}") for i in range(k - 2)] + [("a0", f"b{k}")]
            what = f"A chain of {k} tetrahedra (a_i, b_i, a_i+1, b_i+1) hinged edge to edge, braced by the distances b_i-a_i+3 and closed by a0-b{k}"
        else:
            dist = [(f"b{i}", f"a{(i + 3) % k}") for i in range(k - 6)]
            what = f"A ring of {k} tetrahedra (a_i, b_i, a_i+1, b_i+1) hinged edge to edge, with the {k - 6} distances b_i-a_i+3"
        return build(f"{family}{k}", f"{what}; {planted}.", world, bodies, dist, seed)
    if family == "tree":
        if k < 1:
            sys.exit("make_scene_family: a tree needs 1 body at least")
        world = {}
        own = []  # each body's own points (labels), four (six for the root)
        bodies = []
        dist = []
        centre = []
        for i in range(k):
            if i == 0:
                c = (0, 0, 0)
                labels = [f"r{j}" for j in range(6)]
                for lab in labels:
                    world[lab] = g.point(c, 2)
                own.append(labels)
                bodies.append(("n0", labels))
                centre.append(c)
                continue
            p = (i - 1) // 2
            slot = (i - 1) % 2
            hinge = own[p][2 * slot: 2 * slot + 2]
            depth = int(math.log2(i + 1))
            c = (centre[p][0] + (3 if slot else -3) / depth, centre[p][1] + 1.5, centre[p][2] + 2.5)
            labels = [f"n{i}_{j}" for j in range(4)]
            for lab in labels:
                world[lab] = g.point(c, 1.5)
            own.append(labels)
            centre.append(c)
            bodies.append((f"n{i}", hinge + labels))
            if slot == 0:  # a point of the parent off the hinge
                off = [lab for lab in (own[p] if p else [f"r{j}" for j in range(6)]) if lab not in hinge]
                dist.append((labels[3], off[-1]))
            else:  # the elder sibling
                dist.append((labels[3], own[i - 1][3]))
        what = f"A binary tree of {k} six-point bodies, each child hinged on two points of its parent, held by one distance (a first child to its parent, a second one to its elder sibling)"
        return build(f"tree{k}", f"{what}; {planted}.", world, bodies, dist, seed)
    if family == "molecule":
        if k < 6:
            sys.exit("make_scene_family: a molecular ring needs 6 atoms at least")
        r = 1.5 * k / (2 * math.pi)
        world = {}
        for i in range(k):
            c = (r * math.cos(2 * math.pi * i / k), r * math.sin(2 * math.pi * i / k), 0.5 * (-1) ** i)
            world[f"A{i}"] = tuple(approx(c[j]) + g.q(-0.25, 0.25, 8) for j in range(3))
        bodies = [(f"m{i}", [f"A{(i - 1) % k}", f"A{i}", f"A{(i + 1) % k}"]) for i in range(k)]
        dist = [(f"A{(j - 1) % k}", f"A{(j + 2) % k}") for j in range(k - 6)]
        what = f"A molecular ring of {k} atoms: one triangle body per atom (its two bonds and the bond angle), consecutive bodies sharing a bond as a hinge, the {k - 6} torsions fixed by 1-4 distances"
        return build(f"molecule{k}", f"{what}; {planted}.", world, bodies, dist, seed)
    if family == "platforms":
        if k < 1:
            sys.exit("make_scene_family: platforms needs 1 plate at least")
        world = {}
        bodies = []
        for j in range(k + 1):
            labels = []
            for i in range(6):
                ang = 2 * math.pi * (i + 0.5 * (j % 2)) / 6
                c = (3 * math.cos(ang), 3 * math.sin(ang), 3 * j)
                lab = f"P{j}_{i}"
                world[lab] = tuple(approx(c[m]) + g.q(-0.4, 0.4) for m in range(3))
                labels.append(lab)
            bodies.append((f"plate{j}", labels))
        dist = [(f"P{j - 1}_{i}", f"P{j}_{(i + 1) % 6}") for j in range(1, k + 1) for i in range(6)]
        what = f"{k} Stewart-Gough 6-6 platform(s) stacked: each plate held by six legs to the plate below"
        return build(f"platforms{k}", f"{what}; {planted}.", world, bodies, dist, seed)
    if family == "strip":
        if k < 1:
            sys.exit("make_scene_family: a strip needs 1 triangle at least")
        world = {}
        for i in range(k + 2):
            c = (1.2 * i, 1.5 * (i % 2), 0)
            while True:
                p = tuple(approx(c[j]) + g.q(-0.3, 0.3) for j in range(3))
                # generic: no four consecutive points coplanar (each fold has two sides)
                if i < 3 or det3(sub(world[f"p{i - 2}"], world[f"p{i - 3}"]), sub(world[f"p{i - 1}"], world[f"p{i - 3}"]),
                                 sub(p, world[f"p{i - 3}"])) != 0:
                    break
            world[f"p{i}"] = p
        bodies = [(f"t{i}", [f"p{i}", f"p{i + 1}", f"p{i + 2}"]) for i in range(k)]
        dist = [(f"p{i}", f"p{i + 3}") for i in range(k - 1)]
        what = f"A braced strip of {k} triangles (p_i, p_i+1, p_i+2) hinged edge to edge, braced by the distances p_i-p_i+3 ({2 ** (k - 1)} configurations)"
        return build(f"strip{k}", f"{what}; {planted}.", world, bodies, dist, seed)
    raise AssertionError(family)


if __name__ == "__main__":
    main()
