// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Test helpers shared by test_standardize and test_enclose_coordinates: planted scenes (a
// global configuration of labelled points with rational coordinates, bodies cut out of it
// and each expressed in its own frame by a random RATIONAL rotation and translation), an
// independent combinatorial oracle for the standard collection (bit masks, brute-force
// clique enumeration, exact predicates on the planted points), and exact Gmpq interval
// bounds used to check interval enclosures without trusting interval arithmetic.

#ifndef RIGID_INCIDENCE_TEST_PLANTED_SCENE_H
#define RIGID_INCIDENCE_TEST_PLANTED_SCENE_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Random.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/enclose_coordinates.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace planted {

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;

// ------------------------------------------------------------------ exact 3D geometry
struct QP { Q x, y, z; };
inline QP operator-(const QP& a, const QP& b) { return QP{a.x - b.x, a.y - b.y, a.z - b.z}; }
inline QP operator+(const QP& a, const QP& b) { return QP{a.x + b.x, a.y + b.y, a.z + b.z}; }
inline QP operator*(const Q& s, const QP& a) { return QP{s * a.x, s * a.y, s * a.z}; }
inline Q dot(const QP& a, const QP& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline QP cross(const QP& a, const QP& b)
{ return QP{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline Q sqdist(const QP& a, const QP& b) { QP d = a - b; return dot(d, d); }
inline bool is_zero(const QP& a) { return a.x == 0 && a.y == 0 && a.z == 0; }
inline bool collinear(const QP& a, const QP& b, const QP& c) { return is_zero(cross(b - a, c - a)); }
inline int orientation(const QP& a, const QP& b, const QP& c, const QP& d)
{
  Q v = dot(cross(b - a, c - a), d - a);
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

// A rigid map x -> R x + t with R rational: R = (quaternion matrix) / |q|^2, q integer.
// With `mirror` the map is composed with the reflection z -> -z (determinant -1).
struct Rigid
{
  Q R[3][3];
  QP t;
  QP apply(const QP& p) const
  {
    return QP{R[0][0] * p.x + R[0][1] * p.y + R[0][2] * p.z + t.x,
              R[1][0] * p.x + R[1][1] * p.y + R[1][2] * p.z + t.y,
              R[2][0] * p.x + R[2][1] * p.y + R[2][2] * p.z + t.z};
  }
};

struct Rng
{
  CGAL::Random r;
  explicit Rng(unsigned seed) : r(seed) {}
  int uniform(int lo, int hi) { return r.get_int(lo, hi + 1); } // inclusive
  Q rational(int num, int den_max) { return Q(uniform(-num, num), uniform(1, den_max)); }
  QP point(int num = 30, int den_max = 6) { return QP{rational(num, den_max), rational(num, den_max), rational(num, den_max)}; }
};

inline Rigid rotation_from_quaternion(long w, long x, long y, long z, const QP& t, bool mirror = false)
{
  Rigid m;
  Q n = Q(w * w + x * x + y * y + z * z);
  long M[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                  {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                  {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  for (int r = 0; r < 3; ++r) for (int s = 0; s < 3; ++s) m.R[r][s] = Q(M[r][s]) / n;
  if (mirror) for (int r = 0; r < 3; ++r) m.R[r][2] = -m.R[r][2]; // R * diag(1,1,-1)
  m.t = t;
  return m;
}

inline Rigid random_rigid(Rng& g, bool mirror = false, int tnum = 50)
{
  long w, x, y, z;
  do { w = g.uniform(-4, 4); x = g.uniform(-4, 4); y = g.uniform(-4, 4); z = g.uniform(-4, 4); }
  while (w == 0 && x == 0 && y == 0 && z == 0);
  return rotation_from_quaternion(w, x, y, z, g.point(tnum, 7), mirror);
}

// ------------------------------------------------------------------ planted scenes
struct Scene
{
  struct Body { std::string name; std::vector<int> pts; std::vector<QP> local; };
  struct Dist { int a, b; Q sq; std::string name; };

  std::vector<std::string> labels;
  std::vector<QP> global;          // the planted configuration
  std::vector<Body> bodies;
  std::vector<Dist> distances;

  int index(const std::string& l) const
  {
    for (std::size_t i = 0; i < labels.size(); ++i) if (labels[i] == l) return int(i);
    throw std::logic_error("test scene: no point " + l);
  }
  int add_point(const std::string& l, const QP& p) { labels.push_back(l); global.push_back(p); return int(labels.size() - 1); }
  const QP& at(const std::string& l) const { return global[index(l)]; }
  Q sq(int a, int b) const { return sqdist(global[a], global[b]); }
  Q sq(const std::string& a, const std::string& b) const { return sq(index(a), index(b)); }

  // A body made of planted points, expressed in its own frame by the rigid map `m`.
  void add_body(const std::string& name, const std::vector<std::string>& ls, const Rigid& m)
  {
    Body b; b.name = name;
    for (const auto& l : ls) { b.pts.push_back(index(l)); b.local.push_back(m.apply(at(l))); }
    bodies.push_back(b);
  }
  // A body with explicit local coordinates (for inconsistent or mirrored inputs).
  void add_body_local(const std::string& name, const std::vector<std::string>& ls, const std::vector<QP>& local)
  {
    Body b; b.name = name;
    for (const auto& l : ls) b.pts.push_back(index(l));
    b.local = local;
    bodies.push_back(b);
  }
  void add_distance(const std::string& a, const std::string& b)
  { distances.push_back(Dist{index(a), index(b), sq(a, b), "d:" + a + "-" + b}); }
  void add_distance_value(const std::string& a, const std::string& b, const Q& v)
  { distances.push_back(Dist{index(a), index(b), v, "d:" + a + "-" + b}); }
};

template <class Traits>
typename Traits::Point_3 to_point(const QP& p)
{ return Traits::point(Traits::from_rational(p.x), Traits::from_rational(p.y), Traits::from_rational(p.z)); }

template <class Traits>
RI::Rigid_body_collection<Traits> make_collection(const Scene& s)
{
  RI::Rigid_body_collection<Traits> c;
  for (const auto& b : s.bodies) {
    std::vector<std::pair<std::string, typename Traits::Point_3>> pts;
    for (std::size_t i = 0; i < b.pts.size(); ++i) pts.emplace_back(s.labels[b.pts[i]], to_point<Traits>(b.local[i]));
    c.add_body(b.name, pts);
  }
  for (const auto& d : s.distances) c.add_distance(s.labels[d.a], s.labels[d.b], Traits::from_rational(d.sq), d.name);
  return c;
}

// ------------------------------------------------------------------ scene generators
// Generic random points: no three collinear, no four coplanar.
inline bool generic(const std::vector<QP>& v)
{
  const std::size_t n = v.size();
  for (std::size_t a = 0; a < n; ++a) for (std::size_t b = a + 1; b < n; ++b) {
    if (sqdist(v[a], v[b]) == 0) return false;
    for (std::size_t c = b + 1; c < n; ++c) {
      if (collinear(v[a], v[b], v[c])) return false;
      for (std::size_t d = c + 1; d < n; ++d) if (orientation(v[a], v[b], v[c], v[d]) == 0) return false;
    }
  }
  return true;
}

inline Scene generic_points(Rng& g, const std::vector<std::string>& ls, const Q& scale = Q(1))
{
  std::vector<QP> v;
  do {
    v.clear();
    for (std::size_t i = 0; i < ls.size(); ++i) v.push_back(scale * g.point());
  } while (!generic(v));
  Scene s;
  for (std::size_t i = 0; i < ls.size(); ++i) s.add_point(ls[i], v[i]);
  return s;
}

// A random rigid map whose translation is of the size `sc` of the scene.
inline Rigid scaled_rigid(Rng& g, const Q& sc, bool mirror = false)
{
  Rigid m = random_rigid(g, mirror);
  m.t = sc * m.t;
  return m;
}

inline QP reflect(const QP& x, const QP& p1, const QP& p2, const QP& p3)
{
  QP n = cross(p2 - p1, p3 - p1);
  return x - (Q(2) * dot(x - p1, n) / dot(n, n)) * n;
}

// Four bodies B1..B4, each holding one corner K_i of a K4 of distances (all six pairs):
// spatial (two mirror placements) or, with `planar`, K4 in the plane of K1 K2 K3 (one).
inline Scene k4_of_distances(Rng& g, bool planar)
{
  Scene s = generic_points(g, {"K1", "K2", "K3", "x1", "y1", "x2", "y2", "x3", "y3", "x4", "y4"});
  QP k4 = planar ? s.at("K1") + Q(3, 5) * (s.at("K2") - s.at("K1")) + Q(4, 7) * (s.at("K3") - s.at("K1")) : g.point();
  s.add_point("K4", k4);
  for (int i = 1; i <= 4; ++i) {
    std::string n = std::to_string(i);
    s.add_body("B" + n, {"K" + n, "x" + n, "y" + n}, random_rigid(g));
  }
  for (int i = 1; i <= 4; ++i) for (int j = i + 1; j <= 4; ++j) s.add_distance("K" + std::to_string(i), "K" + std::to_string(j));
  return s;
}

// A random planted scene: `nbodies` bodies of 3 to 5 points drawn from a small pool of
// generic points (so that bodies overlap), each in its own random frame, and 0 to 3
// distances between points of the bodies.
inline Scene random_scene(Rng& g, int nbodies)
{
  const int np = std::min(g.uniform(nbodies + 3, 3 * nbodies + 3), 16);
  std::vector<std::string> ls;
  for (int i = 0; i < np; ++i) ls.push_back("p" + std::to_string(i));
  Scene s = generic_points(g, ls);
  std::vector<int> used;
  for (int b = 0; b < nbodies; ++b) {
    int size = g.uniform(3, std::min(5, np));
    std::vector<int> pick;
    while (int(pick.size()) < size) {
      int p = g.uniform(0, np - 1);
      if (std::find(pick.begin(), pick.end(), p) == pick.end()) pick.push_back(p);
    }
    std::vector<std::string> names;
    for (int p : pick) { names.push_back(ls[p]); used.push_back(p); }
    s.add_body("b" + std::to_string(b), names, random_rigid(g));
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  int nd = g.uniform(0, 3);
  for (int k = 0; k < nd; ++k) {
    int a = used[g.uniform(0, int(used.size()) - 1)], b = used[g.uniform(0, int(used.size()) - 1)];
    if (a == b) continue;
    bool dup = false;
    for (const auto& d : s.distances) dup = dup || (d.a == a && d.b == b) || (d.a == b && d.b == a);
    if (!dup) s.add_distance(ls[a], ls[b]);
  }
  return s;
}

// ------------------------------------------------------------------ bit masks, cliques
typedef std::uint64_t Mask;
inline Mask bit(int i) { return Mask(1) << i; }
inline int popcount(Mask m) { return __builtin_popcountll(m); }
inline bool subset(Mask a, Mask b) { return (a & ~b) == 0; }
inline std::vector<int> members(Mask m)
{ std::vector<int> v; for (int i = 0; i < 64; ++i) if (m & bit(i)) v.push_back(i); return v; }

// All maximal cliques with >= 3 vertices of the graph `adj` (adjacency masks), by plain
// enumeration of every clique in increasing vertex order (no Bron-Kerbosch).
inline void enumerate_cliques(const std::vector<Mask>& adj, Mask k, Mask cand, std::vector<Mask>& out)
{
  if (popcount(k) >= 3) {
    Mask common = ~Mask(0);
    for (int v : members(k)) common &= adj[v];
    common &= ~k;
    if (adj.size() < 64) common &= (bit(int(adj.size())) - 1);
    if (common == 0) out.push_back(k);
  }
  for (int v : members(cand)) {
    Mask higher = ~((bit(v) << 1) - 1);
    enumerate_cliques(adj, k | bit(v), cand & adj[v] & higher, out);
  }
}
inline std::vector<Mask> maximal_cliques(const std::vector<Mask>& adj)
{
  std::vector<Mask> out;
  Mask all = adj.size() >= 64 ? ~Mask(0) : bit(int(adj.size())) - 1;
  enumerate_cliques(adj, 0, all, out);
  std::sort(out.begin(), out.end());
  return out;
}

// Do the planted points of `m` span space (4 of them not coplanar)?
inline bool spatial(const Scene& s, Mask m)
{
  std::vector<int> v = members(m);
  for (std::size_t a = 0; a < v.size(); ++a) for (std::size_t b = a + 1; b < v.size(); ++b)
    for (std::size_t c = b + 1; c < v.size(); ++c) for (std::size_t d = c + 1; d < v.size(); ++d)
      if (orientation(s.global[v[a]], s.global[v[b]], s.global[v[c]], s.global[v[d]]) != 0) return true;
  return false;
}

// The pairs of points whose distance the scene fixes directly: two points of one input body,
// or the ends of an input distance (as adjacency masks over scene point indices).
inline std::vector<Mask> constraint_pairs(const Scene& s)
{
  std::vector<Mask> adj(s.labels.size(), 0);
  for (const auto& b : s.bodies)
    for (int p : b.pts) for (int q : b.pts) if (p != q) adj[p] |= bit(q);
  for (const auto& d : s.distances) { adj[d.a] |= bit(d.b); adj[d.b] |= bit(d.a); }
  return adj;
}

// ------------------------------------------------------------------ the oracle
// An independent re-derivation of the standard collection of a planted scene: sets of
// point indices only; geometry (collinearity) decided exactly on the planted points.
struct Oracle
{
  struct Set { Mask pts; RI::Body_origin origin; std::set<std::string> members; };
  bool throws = false;
  std::string why;
  std::vector<Set> sets;
  std::vector<std::pair<int, int>> remaining; // distances left, as sorted point pairs
};

inline bool all_collinear(const Scene& s, Mask m)
{
  std::vector<int> v = members(m);
  for (std::size_t i = 2; i < v.size(); ++i) if (!collinear(s.global[v[0]], s.global[v[1]], s.global[v[i]])) return false;
  return true;
}

inline Oracle oracle_standardize(const Scene& s)
{
  Oracle o;
  struct D { int a, b; std::string name; };
  std::vector<D> ds;
  for (const auto& d : s.distances) ds.push_back(D{d.a, d.b, d.name});
  for (const auto& b : s.bodies) {
    Mask m = 0;
    for (int p : b.pts) m |= bit(p);
    // collinearity of the body as the user gave it (its local coordinates)
    bool col = true;
    for (std::size_t i = 2; i < b.local.size(); ++i) col = col && collinear(b.local[0], b.local[1], b.local[i]);
    if (col) {
      for (std::size_t i = 0; i < b.pts.size(); ++i)
        for (std::size_t j = i + 1; j < b.pts.size(); ++j) ds.push_back(D{b.pts[i], b.pts[j], "body '" + b.name + "' (a bar)"});
    } else o.sets.push_back(Oracle::Set{m, RI::Body_origin::USER, {b.name}});
  }
  const int n = int(s.labels.size());
  for (int guard = 0; guard < 1000; ++guard) {
    bool changed = false;
    // distances inside a set
    for (std::size_t k = 0; k < ds.size();) {
      Mask e = bit(ds[k].a) | bit(ds[k].b);
      bool in = false;
      for (auto& st : o.sets) if (subset(e, st.pts)) { st.members.insert(ds[k].name); in = true; break; }
      if (in) { ds.erase(ds.begin() + k); changed = true; } else ++k;
    }
    // sets inside sets (of two equal sets the earlier stays)
    bool again = true;
    while (again) {
      again = false;
      for (std::size_t i = 0; i < o.sets.size() && !again; ++i)
        for (std::size_t j = 0; j < o.sets.size() && !again; ++j) {
          if (i == j || !subset(o.sets[i].pts, o.sets[j].pts)) continue;
          if (o.sets[i].pts == o.sets[j].pts && i < j) continue;
          o.sets[j].members.insert(o.sets[i].members.begin(), o.sets[i].members.end());
          o.sets.erase(o.sets.begin() + i);
          again = changed = true;
        }
    }
    if (changed) continue;
    // sets sharing 3 or more points
    for (std::size_t i = 0; i < o.sets.size() && !changed; ++i)
      for (std::size_t j = i + 1; j < o.sets.size() && !changed; ++j) {
        Mask common = o.sets[i].pts & o.sets[j].pts;
        if (popcount(common) < 3) continue;
        if (all_collinear(s, common)) { o.throws = true; o.why = "collinear shared points"; return o; }
        o.sets[i].pts |= o.sets[j].pts;
        o.sets[i].origin = RI::Body_origin::MERGED;
        o.sets[i].members.insert(o.sets[j].members.begin(), o.sets[j].members.end());
        o.sets.erase(o.sets.begin() + j);
        changed = true;
      }
    if (changed) continue;
    // maximal cliques of fixed pairs not inside a set
    std::vector<Mask> adj(n, 0);
    for (const auto& st : o.sets) for (int p : members(st.pts)) adj[p] |= st.pts & ~bit(p);
    for (const auto& d : ds) { adj[d.a] |= bit(d.b); adj[d.b] |= bit(d.a); }
    for (Mask k : maximal_cliques(adj)) {
      bool inside = false;
      for (const auto& st : o.sets) inside = inside || subset(k, st.pts);
      if (inside) continue;
      if (all_collinear(s, k)) { o.throws = true; o.why = "collinear implied body"; return o; }
      o.sets.push_back(Oracle::Set{k, RI::Body_origin::IMPLIED, {}});
      changed = true;
    }
    if (!changed) {
      for (const auto& d : ds) o.remaining.emplace_back(std::min(d.a, d.b), std::max(d.a, d.b));
      std::sort(o.remaining.begin(), o.remaining.end());
      o.remaining.erase(std::unique(o.remaining.begin(), o.remaining.end()), o.remaining.end());
      return o;
    }
  }
  throw std::logic_error("oracle: no fixpoint");
}

// The mask (in scene point indices) of a body of a package collection.
template <class Collection>
Mask body_mask(const Scene& s, const Collection& c, std::size_t i)
{
  Mask m = 0;
  for (std::size_t p : c.body(i).points) m |= bit(s.index(c.label(p)));
  return m;
}

inline std::string mask_text(const Scene& s, Mask m)
{
  std::string t = "{";
  bool first = true;
  for (int p : members(m)) { t += (first ? "" : ",") + s.labels[p]; first = false; }
  return t + "}";
}

// ------------------------------------------------------------------ exact interval bounds
// An interval [lo, hi] with exact rational ends: enclosures returned by the package are
// converted exactly (a double is a dyadic rational) and combined exactly, so containment
// checks do not depend on the rounding of the test's own arithmetic.
struct QI { Q lo, hi; };
inline QI qi(const CGAL::Interval_nt<false>& x) { return QI{Q(x.inf()), Q(x.sup())}; }
inline QI operator+(const QI& a, const QI& b) { return QI{a.lo + b.lo, a.hi + b.hi}; }
inline QI operator-(const QI& a, const QI& b) { return QI{a.lo - b.hi, a.hi - b.lo}; }
inline QI operator*(const QI& a, const QI& b)
{
  Q p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return QI{*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
inline QI square(const QI& a)
{
  if (a.lo >= 0) return QI{a.lo * a.lo, a.hi * a.hi};
  if (a.hi <= 0) return QI{a.hi * a.hi, a.lo * a.lo};
  return QI{Q(0), std::max(a.lo * a.lo, a.hi * a.hi)};
}
inline bool contains(const QI& a, const Q& v) { return a.lo <= v && v <= a.hi; }
inline int certain_sign(const QI& a) { return a.lo > 0 ? 1 : (a.hi < 0 ? -1 : 0); }

typedef std::array<CGAL::Interval_nt<false>, 3> IP;
inline QI enclosed_sqdist(const IP& a, const IP& b)
{
  return square(qi(a[0]) - qi(b[0])) + square(qi(a[1]) - qi(b[1])) + square(qi(a[2]) - qi(b[2]));
}
// Orientation determinant of four enclosed points, exactly bounded.
inline QI enclosed_orientation(const IP& a, const IP& b, const IP& c, const IP& d)
{
  QI u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) { u[k] = qi(b[k]) - qi(a[k]); v[k] = qi(c[k]) - qi(a[k]); w[k] = qi(d[k]) - qi(a[k]); }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}
inline bool contains_point(const IP& a, const QP& p)
{ return contains(qi(a[0]), p.x) && contains(qi(a[1]), p.y) && contains(qi(a[2]), p.z); }

} // namespace planted

namespace planted {
// Placements of body i up to rigid motion: what standardize() tells exactly, else enumerated.
template <class Traits>
std::size_t placements(const CGAL::Rigid_incidence::Rigid_body_collection<Traits>& c, std::size_t i)
{
  if (c.body(i).mirror_variants > 0) return std::size_t(c.body(i).mirror_variants);
  return CGAL::Rigid_incidence::enclose_all_placements<CGAL::Interval_nt<false>>(c, i).size();
}
} // namespace planted

#endif
