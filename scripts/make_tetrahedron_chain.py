#!/usr/bin/env python3
# Usage: scripts/make_tetrahedron_chain.py K [SEED] > chain.json (test/Rigid_incidence/data/
# tetrahedron_chain10.json is K = 10, SEED = 1).
# A planted chain of k tetrahedra (a_i, b_i, a_{i+1}, b_{i+1}) hinged edge to edge, braced by
# the k-2 distances b_i - a_{i+3} and closed by a_0 - b_k (issue 28's first family): exact
# rational world points, each body given in its own frame by a rational rotation (Cayley) and
# translation, so the planted configuration solves the scene exactly.
import json, os, random, sys
from fractions import Fraction as F
k = int(sys.argv[1]); seed = int(sys.argv[2]) if len(sys.argv) > 2 else 1
rnd = random.Random(seed)
def r(lo=-5, hi=5, den=7): return F(rnd.randint(lo*den, hi*den), den)
a = []; b = []
x = F(0)
for i in range(k + 1):
    a.append((x, r(-1,1), r(-1,1))); b.append((x + r(0,1), r(2,4), r(-2,2))); x += F(2) + r(0,1)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_scene_family import cayley, local, d2, text as s  # the exact helpers of the families
bodies = []
for i in range(k):
    R = cayley((r(-2,2,3), r(-2,2,3), r(-2,2,3))) if i else [[F(1),0,0],[0,F(1),0],[0,0,F(1)]]
    t = (r(), r(), r()) if i else (F(0), F(0), F(0))
    pts = {}
    for lab, X in ((f"a{i}", a[i]), (f"b{i}", b[i]), (f"a{i+1}", a[i+1]), (f"b{i+1}", b[i+1])):
        pts[lab] = [s(v) for v in local(R, t, X)]
    bodies.append({"name": f"t{i}", "points": pts})
dist = [{"between": [f"b{i}", f"a{i+3}"], "squared": s(d2(b[i], a[i+3]))} for i in range(k - 2)]
dist.append({"between": ["a0", f"b{k}"], "squared": s(d2(a[0], b[k]))})
print(json.dumps({"format": "rigid-incidence-scene/1", "name": f"tetrahedron_chain{k}",
  "comment": f"A chain of {k} tetrahedra (a_i, b_i, a_i+1, b_i+1) hinged edge to edge, braced by the distances b_i-a_i+3 and closed by a0-b{k} (issue 28's first family), planted with exact rational poses (seed {seed}). Its solve runs for minutes: the tests of the whole-solve time limit (--max-seconds) and of the interrupt use it; the partial answer must be valid and say it is incomplete.",
  "bodies": bodies, "distances": dist, "frame": "t0"}, indent=1))
