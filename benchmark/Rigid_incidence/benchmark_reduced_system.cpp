// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Benchmark of the reduced system against the papers' naive formulations: for the paper
// scenes (tetra, quad, pent) and random planted scenes of 5 to 30 bodies, the four systems
//   - Reduced_system with homogeneous quaternion charts (the package's default),
//   - Reduced_system in the papers' stereographic form,
//   - naive_system(TRIGONOMETRIC) (optimized_incidence_tree_parametrization.txt, Section 2.1),
//   - naive_system(QUATERNION)    (Section 2.2),
// side by side in one table: variables, equations, the largest degree in one variable, the
// largest total degree, the number of terms, the largest number of variables in one
// equation and the time to build the system, with the ratios naive / reduced. Written as
// PREFIX.md (Markdown), PREFIX.csv and PREFIX.svg (a bar chart of the terms, log scale).
//
// Every system is built in a child process (fork) with a time limit: a naive quaternion
// system of a large scene has distance equations of tens of thousands of terms, and a cell
// that takes longer than the cap is skipped and marked so in the table.
//
// Usage: benchmark_reduced_system [RESULTS_PREFIX] [MAX_BODIES (30)] [SEEDS (3)] [CAP_SECONDS (20)]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Rigid_incidence.h>

#include "benchmark_common.h" // RI, K, Traits, Collection, RIGID_INCIDENCE_DATA_DIR, helpers

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

typedef CGAL::Gmpq Q;

using benchmark_common::fixed;
using benchmark_common::fmt;
using benchmark_common::md_escape;
using benchmark_common::ratio_text;

// ------------------------------------------------------------------ random planted scenes
// Points at random integer world positions; bodies of 3 to 5 points. A tree phase: each body
// shares a pair (probability 3/4, a hinge) or a single point with one earlier body. Then a
// cycle-closing phase (the last quarter of the bodies): bodies of 3 or 4 points, each point
// taken from a different earlier body. No two bodies share 3 or more points, no three points
// of a body are collinear. Each body is written in its own frame y = R x + t, R = M(q)/|q|^2
// for an integer quaternion q, t integer, so the data stay rational. Then a few distances
// between points of no common body: 1 + n/10, and more while the reduced system would be
// under-constrained. Closing bodies and distances are redrawn when standardize() would merge
// bodies (a clique of 4 fixed pairs outside any body) or when they would over-constrain the
// scene, so the standard collection keeps every body (plus implied bodies: triangles of
// fixed pairs) and the reduced system is usually square.
struct Planted
{
  Collection user;
};

typedef std::array<long long, 3> IP;

static bool collinear(const IP& a, const IP& b, const IP& c)
{
  long long u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 && u[0] * v[1] - u[1] * v[0] == 0;
}

// The shape of the reduced system of a user collection, without building its polynomials:
// standardize(), the greedy incidence tree (the exact one of a 30-body scene can take seconds
// to minutes), the well-formed selection and the rigidity-matroid test, counted as
// Reduced_system does (variables: the tree weight + 3 per free point).
struct Shape
{
  bool ok = false;        // standardize() and the analysis went through
  bool collapsed = true;  // standardize() merged bodies
  long vars = 0, eqs = 0;
  bool conflict = false;  // a dependent constraint that does not follow from its body
  bool loose = false;     // a body outside the covering set held by fewer than 3 covered points
  bool square() const { return ok && !collapsed && vars == eqs && !conflict && !loose; }
};

static Shape shape_of(const Collection& user)
{
  Shape s;
  try {
    Collection c = RI::standardize(user);
    std::size_t kept = 0, merged = 0;
    for (const auto& b : c.bodies()) {
      kept += b.origin == RI::Body_origin::USER;
      merged += b.origin == RI::Body_origin::MERGED;
    }
    s.collapsed = merged != 0 || kept != user.number_of_bodies();
    RI::Incidence_tree_options greedy;
    greedy.exact_limit = 0;
    const RI::Incidence_tree t = RI::optimal_incidence_tree(c, greedy);
    const RI::Well_formed_selection wf = RI::select_well_formed_incidences(c, t);
    const std::vector<RI::Constraint> ks = RI::system_constraints(c, t, wf);
    const RI::Constraint_independence ind = RI::constraint_independence(c, t.covering_set, ks);
    for (std::size_t i = 0; i < ks.size(); ++i) {
      if (!ind.independent[i]) { s.conflict = s.conflict || !ind.follows_from_its_body(i); continue; }
      if (ks[i].origin != RI::Constraint::TREE_INCIDENCE) ++s.eqs;
    }
    std::vector<bool> covered(c.number_of_points(), false);
    for (std::size_t b : t.covering_set) for (std::size_t q : c.body(b).points) covered[q] = true;
    for (std::size_t b : t.non_covering) {
      std::size_t m = 0;
      for (std::size_t q : c.body(b).points) m += covered[q];
      s.loose = s.loose || m < 3;
    }
    s.vars = long(t.weight) + 3 * RI::dof_count(c).free_points;
    s.ok = true;
  } catch (const RI::Input_error&) {
  }
  return s;
}

static Planted random_planted_once(std::size_t n, CGAL::Random& rng)
{
  std::vector<IP> world;
  std::vector<std::vector<std::size_t>> bodies;
  std::vector<std::set<std::size_t>> adj; // pairs of points at a fixed distance (one body, or a distance)
  auto new_point = [&]() {
    IP p;
    bool dup;
    do {
      p = IP{rng.get_int(-20, 21), rng.get_int(-20, 21), rng.get_int(-20, 21)};
      dup = std::find(world.begin(), world.end(), p) != world.end();
    } while (dup);
    world.push_back(p);
    adj.emplace_back();
    return world.size() - 1;
  };
  auto no_collinear_triple = [&](const std::vector<std::size_t>& b) {
    for (std::size_t i = 0; i < b.size(); ++i)
      for (std::size_t j = i + 1; j < b.size(); ++j)
        for (std::size_t k = j + 1; k < b.size(); ++k)
          if (collinear(world[b[i]], world[b[j]], world[b[k]])) return false;
    return true;
  };
  auto common = [](const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
    std::size_t m = 0;
    for (std::size_t p : a) m += std::count(b.begin(), b.end(), p);
    return m;
  };
  auto link = [&](const std::vector<std::size_t>& b) {
    for (std::size_t p : b) for (std::size_t q : b) if (p != q) adj[p].insert(q);
  };
  // Would the pairs of `b` (a new body, or a distance when b has 2 points) close a clique of
  // 4 fixed pairs not inside b? standardize() would make it an implied body sharing 3 points
  // with a body and merge them: the scene would collapse into fewer, larger bodies.
  auto closes_k4 = [&](const std::vector<std::size_t>& b) {
    std::vector<std::set<std::size_t>> saved;
    for (std::size_t p : b) saved.push_back(adj[p]);
    link(b);
    bool bad = false;
    for (std::size_t i = 0; i < b.size() && !bad; ++i)
      for (std::size_t j = i + 1; j < b.size() && !bad; ++j) {
        std::vector<std::size_t> cn;
        for (std::size_t x : adj[b[i]]) if (adj[b[j]].count(x)) cn.push_back(x);
        for (std::size_t x : cn)
          for (std::size_t y : cn)
            if (x < y && adj[x].count(y) && !(std::count(b.begin(), b.end(), x) && std::count(b.begin(), b.end(), y))) bad = true;
      }
    for (std::size_t i = 0; i < b.size(); ++i) adj[b[i]] = saved[i];
    return bad;
  };
  auto fill = [&](std::vector<std::size_t> b, std::size_t size) {
    // complete with new points, redrawn until no three points of the body are collinear
    const std::size_t keep = b.size(), mark = world.size();
    for (int guard = 0; guard < 1000; ++guard) {
      b.resize(keep);
      world.resize(mark);
      adj.resize(mark);
      while (b.size() < size) b.push_back(new_point());
      if (no_collinear_triple(b)) return b;
    }
    return std::vector<std::size_t>();
  };
  const std::size_t closers = n >= 4 ? n / 4 : 0;
  bodies.push_back(fill({}, std::size_t(rng.get_int(3, 6))));
  link(bodies.back());
  while (bodies.size() < n - closers) {
    const std::size_t size = std::size_t(rng.get_int(3, 6));
    const std::vector<std::size_t> parent = bodies[std::size_t(rng.get_int(0, int(bodies.size())))];
    const std::size_t share = rng.get_int(0, 4) == 0 ? 1 : 2;
    std::vector<std::size_t> b;
    while (b.size() < share) {
      std::size_t p = parent[std::size_t(rng.get_int(0, int(parent.size())))];
      if (std::find(b.begin(), b.end(), p) == b.end()) b.push_back(p);
    }
    b = fill(b, size);
    if (b.empty()) continue;
    bodies.push_back(b);
    link(b);
  }
  // each body in its own rational frame: y = R x + t, R = M(q)/|q|^2, q an integer quaternion
  struct Frame { long M[3][3]; Q norm; long t[3]; };
  std::vector<Frame> frames;
  auto new_frame = [&]() {
    Frame f;
    long w, x, y, z;
    do { w = rng.get_int(-4, 5); x = rng.get_int(-4, 5); y = rng.get_int(-4, 5); z = rng.get_int(-4, 5); }
    while (w == 0 && x == 0 && y == 0 && z == 0);
    f.norm = Q(w * w + x * x + y * y + z * z);
    const long M[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
    for (int r = 0; r < 3; ++r) for (int c = 0; c < 3; ++c) f.M[r][c] = M[r][c];
    for (int r = 0; r < 3; ++r) f.t[r] = rng.get_int(-10, 11);
    return f;
  };
  for (std::size_t i = 0; i < bodies.size(); ++i) frames.push_back(new_frame());
  std::vector<std::pair<std::size_t, std::size_t>> distances;
  auto collection = [&]() {
    Collection c;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Frame& f = frames[i];
      std::vector<std::pair<std::string, K::Point_3>> pts;
      for (std::size_t p : bodies[i]) {
        Q y3[3];
        for (int r = 0; r < 3; ++r)
          y3[r] = Q(f.M[r][0] * world[p][0] + f.M[r][1] * world[p][1] + f.M[r][2] * world[p][2]) / f.norm + Q(f.t[r]);
        pts.emplace_back("p" + std::to_string(p), K::Point_3(y3[0], y3[1], y3[2]));
      }
      c.add_body("b" + std::to_string(i), pts);
    }
    for (const auto& d : distances) {
      long long d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += (world[d.first][k] - world[d.second][k]) * (world[d.first][k] - world[d.second][k]);
      c.add_distance("p" + std::to_string(d.first), "p" + std::to_string(d.second), Q(d2));
    }
    return c;
  };
  // cycle-closing bodies, each point from a different earlier body; redrawn when they would
  // over-constrain the scene (a dependent constraint, `Shape::conflict`)
  for (int guard = 0; bodies.size() < n && guard < 2000; ++guard) {
    const std::size_t size = std::min(std::size_t(rng.get_int(3, 5)), bodies.size());
    std::vector<std::size_t> from, b;
    while (from.size() < size) {
      std::size_t k = std::size_t(rng.get_int(0, int(bodies.size())));
      if (std::find(from.begin(), from.end(), k) == from.end()) from.push_back(k);
    }
    for (std::size_t k : from) {
      std::size_t p = bodies[k][std::size_t(rng.get_int(0, int(bodies[k].size())))];
      if (std::find(b.begin(), b.end(), p) != b.end()) break;
      b.push_back(p);
    }
    if (b.size() < size || !no_collinear_triple(b)) continue;
    bool ok = true;
    for (const auto& o : bodies) ok = ok && common(b, o) <= 2;
    if (!ok || closes_k4(b)) continue;
    bodies.push_back(b);
    frames.push_back(new_frame());
    const Shape sh = shape_of(collection());
    if (!sh.ok || sh.collapsed || sh.conflict) { bodies.pop_back(); frames.pop_back(); continue; }
    link(b);
  }
  // a few distances between points of no common body (3 of 4 ends drawn among the points of
  // one body only): 1 + n/10, then more (at most n) while the reduced system has fewer
  // equations than variables or a loose body; a distance that would conflict is redrawn
  std::vector<std::size_t> used;
  for (const auto& b : bodies) used.insert(used.end(), b.begin(), b.end());
  std::sort(used.begin(), used.end());
  std::vector<std::size_t> own; // points of one body only: a distance there ties a hinged body down
  for (std::size_t i = 0; i < used.size(); ++i)
    if ((i == 0 || used[i - 1] != used[i]) && (i + 1 == used.size() || used[i + 1] != used[i])) own.push_back(used[i]);
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (own.empty()) own = used;
  auto pick = [&]() {
    const auto& from = rng.get_int(0, 4) == 0 ? used : own;
    return from[std::size_t(rng.get_int(0, int(from.size())))];
  };
  Shape sh = shape_of(collection());
  for (std::size_t k = 0, guard = 0; guard < 20 * n && sh.ok && !sh.collapsed && !sh.square(); ++guard) {
    if (k >= 1 + n / 10 && sh.vars <= sh.eqs && !sh.loose) break;
    if (k >= n) break;
    std::size_t a = pick(), b = pick();
    if (a == b || adj[a].count(b) || closes_k4({a, b})) continue;
    distances.emplace_back(a, b);
    const Shape next = shape_of(collection());
    if (!next.ok || next.collapsed || next.conflict) { distances.pop_back(); continue; }
    link({a, b});
    sh = next;
    ++k;
  }
  Planted out;
  out.user = collection();
  return out;
}

// A planted scene of n bodies that standardize() does not collapse (no merged body, every user
// body kept) and whose reduced system for the greedy incidence tree is square (`Shape`): redrawn
// up to 30 times, else the last draw that does not collapse. (The table's reduced systems use
// the optimal tree; a non-square one is marked.)
static Planted random_planted(std::size_t n, CGAL::Random& rng, int* attempts)
{
  Planted fallback;
  bool have_fallback = false;
  for (int attempt = 1;; ++attempt) {
    *attempts = attempt;
    Planted p = random_planted_once(n, rng);
    const Shape sh = shape_of(p.user);
    const bool complete = p.user.number_of_bodies() == n; // every cycle-closing body found a place
    if (complete && sh.square()) return p;
    if (complete && sh.ok && !sh.collapsed) { fallback = p; have_fallback = true; }
    if (attempt >= 30 && (have_fallback || attempt >= 100)) return have_fallback ? fallback : p;
  }
}

// ------------------------------------------------------------------ statistics of a system
enum Status { OK = 0, ERROR = 1, SKIPPED = 2, DIED = 3 };

struct Stats // plain data: sent from the child process through a pipe
{
  int status = ERROR;
  int exact = 1;              // coefficients exact (Gmpq) or intervals
  int square = 0;             // reduced: is_square()
  double seconds = 0;         // build time
  long vars = 0, eqs = 0, max_var_degree = 0, max_total_degree = 0, terms = 0, max_vars_per_eq = 0;
  char message[240] = {0};
};

template <class NT>
void accumulate(const RI::Sparse_polynomial<NT>& p, Stats& s)
{
  std::vector<unsigned> deg(p.number_of_variables(), 0);
  for (const auto& t : p.terms()) {
    long total = 0;
    for (std::size_t i = 0; i < t.first.size(); ++i) {
      total += t.first[i];
      deg[i] = std::max(deg[i], t.first[i]);
    }
    s.max_total_degree = std::max(s.max_total_degree, total);
  }
  long nv = 0;
  for (unsigned d : deg) {
    nv += d > 0;
    s.max_var_degree = std::max(s.max_var_degree, long(d));
  }
  s.max_vars_per_eq = std::max(s.max_vars_per_eq, nv);
  s.terms += long(p.terms().size());
}

static void set_message(Stats& s, const std::string& m)
{
  std::snprintf(s.message, sizeof s.message, "%s", m.c_str());
}

struct Analysis
{
  Collection c;
  RI::Incidence_tree tree;
  RI::Well_formed_selection selection;
  bool exact = true;
};

template <class NT>
Stats build_reduced(const Analysis& a, RI::Rotation_form form)
{
  typename std::conditional<RI::internal::is_interval_nt<NT>::value, CGAL::Protect_FPU_rounding<true>, int>::type guard{};
  (void)guard;
  Stats s;
  CGAL::Real_timer timer;
  timer.start();
  RI::Reduced_system<Traits, NT> r(a.c, a.tree, a.selection, {}, form);
  timer.stop();
  s.seconds = timer.time();
  s.exact = RI::internal::is_interval_nt<NT>::value ? 0 : 1;
  s.vars = long(r.number_of_variables());
  s.eqs = long(r.number_of_equations());
  s.square = r.is_square();
  for (const auto& e : r.equations()) {
    accumulate(e.polynomial, s);
    // the equation's own record agrees with the polynomial
    unsigned dmax = 0;
    for (unsigned d : e.degrees) dmax = std::max(dmax, d);
    if (long(e.total_degree) > s.max_total_degree || long(dmax) > s.max_var_degree || long(e.variables.size()) > s.max_vars_per_eq) {
      set_message(s, "Reduced_equation fields disagree with the polynomial");
      return s;
    }
  }
  if (!r.is_square()) set_message(s, r.diagnostic());
  s.status = OK;
  return s;
}

static Stats build_naive(const Collection& user, RI::Naive_form form)
{
  Stats s;
  CGAL::Real_timer timer;
  timer.start();
  RI::Polynomial_system<Q> sys = RI::naive_system(user, form);
  timer.stop();
  s.seconds = timer.time();
  s.vars = long(sys.number_of_variables());
  s.eqs = long(sys.number_of_equations());
  s.square = s.vars == s.eqs;
  for (const auto& p : sys.equations) accumulate(p, s);
  s.status = OK;
  return s;
}

// Runs `build` in a child process; kills it after `cap` seconds (wall clock).
template <class F>
Stats run_cell(F build, double cap)
{
  const benchmark_common::Forked child = benchmark_common::run_forked<Stats>(
      build, [](Stats& r, const std::string& m) { set_message(r, m); },
      [](const Stats& r) { return std::string(reinterpret_cast<const char*>(&r), sizeof r); }, cap);
  Stats s;
  if (!child.failure.empty()) { set_message(s, child.failure); return s; }
  if (child.text.size() >= sizeof s) std::memcpy(&s, child.text.data(), sizeof s);
  else if (child.timed_out) {
    s.status = SKIPPED;
    std::ostringstream m;
    m << "skipped: building takes more than " << cap << " s";
    set_message(s, m.str());
  } else {
    s.status = DIED;
    set_message(s, WIFSIGNALED(child.wstatus) ? "the build died (signal " + std::to_string(WTERMSIG(child.wstatus)) + ", e.g. out of memory)"
                                              : std::string("the build died"));
  }
  return s;
}

// ------------------------------------------------------------------ the run
static const char* system_names[4] = {"reduced, quaternion charts", "reduced, stereographic", "naive trigonometric (2.1)",
                                      "naive quaternion (2.2)"};
static const char* system_keys[4] = {"reduced_charts", "reduced_stereographic", "naive_trigonometric", "naive_quaternion"};
static const char* colors[4] = {"#1f77b4", "#17becf", "#d62728", "#ff7f0e"};

struct Row
{
  std::string scene, group;
  std::size_t user_bodies = 0, standard_bodies = 0, points = 0, distances = 0;
  long dof = 0;
  double analysis_seconds = 0;
  int attempts = 0; // random scenes: draws until the reduced system was square
  bool exact = true; // the reduced systems' coefficients: exact, or intervals
  std::string note;
  std::array<Stats, 4> cells;
};

static Row run_scene(const std::string& name, const std::string& group, const Collection& user, double cap)
{
  Row row;
  row.scene = name;
  row.group = group;
  row.user_bodies = user.number_of_bodies();
  row.points = user.number_of_points();
  row.distances = user.distances().size();
  Analysis a;
  CGAL::Real_timer t;
  t.start();
  try {
    a.c = RI::standardize(user);
    a.tree = RI::optimal_incidence_tree(a.c);
    a.selection = RI::select_well_formed_incidences(a.c, a.tree);
  } catch (const std::exception& e) {
    row.note = std::string("analysis failed: ") + e.what();
    for (auto& c : row.cells) set_message(c, row.note);
    return row;
  }
  t.stop();
  row.analysis_seconds = t.time();
  row.standard_bodies = a.c.number_of_bodies();
  row.dof = RI::dof_count(a.c).dof;
  for (std::size_t b : a.tree.covering_set) a.exact = a.exact && a.c.body(b).all_coordinates();
  row.exact = a.exact;
  for (int k = 0; k < 2; ++k) {
    RI::Rotation_form form = k == 0 ? RI::Rotation_form::QUATERNION_CHARTS : RI::Rotation_form::STEREOGRAPHIC;
    row.cells[std::size_t(k)] = run_cell([&]() {
      return a.exact ? build_reduced<CGAL::Gmpq>(a, form) : build_reduced<CGAL::Interval_nt<false>>(a, form);
    }, cap);
  }
  row.cells[2] = run_cell([&]() { return build_naive(user, RI::Naive_form::TRIGONOMETRIC); }, cap);
  row.cells[3] = run_cell([&]() { return build_naive(user, RI::Naive_form::QUATERNION); }, cap);
  std::cout << name << ": " << row.user_bodies << " bodies (" << row.standard_bodies << " standard), dof " << row.dof
            << ", analysis " << fixed(row.analysis_seconds, 4) << " s";
  for (int k = 0; k < 4; ++k) {
    const Stats& s = row.cells[std::size_t(k)];
    std::cout << "\n  " << std::left << std::setw(28) << system_names[k] << std::right;
    if (s.status == OK)
      std::cout << s.vars << " vars, " << s.eqs << " eqs, " << s.terms << " terms, max deg " << s.max_var_degree << "/"
                << s.max_total_degree << ", " << fixed(s.seconds, 3) << " s";
    else std::cout << s.message;
  }
  std::cout << std::endl;
  return row;
}

static std::string ratio(const Stats& naive, const Stats& reduced, bool terms)
{
  if (naive.status != OK || reduced.status != OK) return "";
  return ratio_text(terms ? double(naive.terms) / double(std::max(1L, reduced.terms)) : double(naive.vars) / double(std::max(1L, reduced.vars)));
}

static void write_svg(const std::string& file, const std::vector<Row>& rows, double cap)
{
  long top = 1;
  for (const auto& r : rows) for (const auto& s : r.cells) if (s.status == OK) top = std::max(top, s.terms);
  int decades = std::max(1, int(std::ceil(std::log10(double(top)) - 1e-12)));
  const int bar = 9, gap = 14, left = 70, plot_h = 360, top_margin = 70, bottom = 110;
  const int group_w = 4 * bar + gap;
  const int legend_w = 4 * 190 + 230;
  const int width = left + std::max(int(rows.size()) * group_w, legend_w) + 30, height = top_margin + plot_h + bottom;
  auto y_of = [&](double v) { return top_margin + plot_h - plot_h * (std::log10(std::max(1.0, v)) / decades); };
  std::ofstream svg(file);
  benchmark_common::svg_open(svg, width, height);
  svg << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\" font-weight=\"bold\">Total number of terms per system (log scale)</text>\n";
  // legend
  int lx = left;
  for (int k = 0; k < 4; ++k) {
    svg << "<rect x=\"" << lx << "\" y=\"32\" width=\"12\" height=\"12\" fill=\"" << colors[k] << "\"/>"
        << "<text x=\"" << lx + 16 << "\" y=\"42\">" << system_names[k] << "</text>\n";
    lx += 190;
  }
  svg << "<rect x=\"" << lx << "\" y=\"32\" width=\"12\" height=\"12\" fill=\"none\" stroke=\"#888\" stroke-dasharray=\"3,2\"/>"
      << "<text x=\"" << lx + 16 << "\" y=\"42\">skipped (&gt; " << cap << " s to build)</text>\n";
  // axis and grid
  for (int d = 0; d <= decades; ++d) {
    double y = y_of(std::pow(10.0, d));
    svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << width - 20 << "\" y2=\"" << y << "\" stroke=\"#ddd\"/>"
        << "<text x=\"" << left - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e" << d << "</text>\n";
  }
  svg << "<line x1=\"" << left << "\" y1=\"" << top_margin << "\" x2=\"" << left << "\" y2=\"" << top_margin + plot_h
      << "\" stroke=\"black\"/>\n"
      << "<text transform=\"translate(16," << top_margin + plot_h / 2 << ") rotate(-90)\" text-anchor=\"middle\">terms</text>\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int x0 = left + gap / 2 + int(i) * group_w;
    for (int k = 0; k < 4; ++k) {
      const Stats& s = rows[i].cells[std::size_t(k)];
      const int x = x0 + k * bar;
      if (s.status == OK) {
        double y = y_of(double(s.terms));
        svg << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << bar - 1 << "\" height=\"" << top_margin + plot_h - y
            << "\" fill=\"" << colors[k] << "\"><title>" << rows[i].scene << ", " << system_names[k] << ": " << s.terms
            << " terms</title></rect>\n";
      } else {
        svg << "<rect x=\"" << x << "\" y=\"" << top_margin << "\" width=\"" << bar - 1 << "\" height=\"" << plot_h
            << "\" fill=\"none\" stroke=\"" << colors[k] << "\" stroke-dasharray=\"3,2\"><title>" << rows[i].scene << ", "
            << system_names[k] << ": " << s.message << "</title></rect>\n";
      }
    }
    const int cx = x0 + 2 * bar;
    svg << "<text transform=\"translate(" << cx << "," << top_margin + plot_h + 10 << ") rotate(-55)\" text-anchor=\"end\">"
        << rows[i].scene << "</text>\n";
  }
  svg << "<line x1=\"" << left << "\" y1=\"" << top_margin + plot_h << "\" x2=\"" << width - 20 << "\" y2=\""
      << top_margin + plot_h << "\" stroke=\"black\"/>\n</svg>\n";
}

int main(int argc, char** argv)
{
  const std::string prefix = argc > 1 ? argv[1] : "reduced_system";
  const std::size_t max_n = argc > 2 ? std::size_t(std::stoul(argv[2])) : 30;
  const int seeds = argc > 3 ? std::stoi(argv[3]) : 3;
  const double cap = argc > 4 ? std::stod(argv[4]) : 20.0;
  std::vector<Row> rows;
  CGAL::Real_timer total;
  total.start();
  for (const char* f : {"tetra", "quad", "pent"}) {
    RI::Scene sc = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + f + ".json");
    Collection user = RI::make_collection<Traits>(sc);
    rows.push_back(run_scene(f, "paper", user, cap));
  }
  for (std::size_t n = 5; n <= max_n; n += 5)
    for (int s = 0; s < seeds; ++s) {
      CGAL::Random rng(unsigned(20260000 + 100 * n + std::size_t(s)));
      int attempts = 0;
      Planted p = random_planted(n, rng, &attempts);
      rows.push_back(run_scene("random" + std::to_string(n) + "-s" + std::to_string(s), "random " + std::to_string(n), p.user, cap));
      rows.back().attempts = attempts;
    }
  total.stop();

  // CSV: one line per scene and system
  std::ofstream csv(prefix + ".csv");
  csv << "scene,draws,user_bodies,standard_bodies,points,distances,dof,system,status,coefficients,variables,equations,"
         "max_degree_in_one_variable,max_total_degree,terms,max_variables_per_equation,build_seconds,analysis_seconds,"
         "variables_naive_over_reduced_charts,terms_naive_over_reduced_charts,terms_naive_over_reduced_stereographic,note\n";
  for (const auto& r : rows)
    for (int k = 0; k < 4; ++k) {
      const Stats& s = r.cells[std::size_t(k)];
      const bool naive = k >= 2, ok = s.status == OK;
      const std::string note = benchmark_common::csv_escape(s.message);
      csv << r.scene << "," << r.attempts << "," << r.user_bodies << "," << r.standard_bodies << "," << r.points << "," << r.distances << "," << r.dof << ","
          << system_keys[k] << "," << (ok ? "ok" : s.status == SKIPPED ? "skipped" : "error") << ","
          << (naive || r.exact ? "exact" : "interval") << ",";
      if (ok)
        csv << s.vars << "," << s.eqs << "," << s.max_var_degree << "," << s.max_total_degree << "," << s.terms << ","
            << s.max_vars_per_eq << "," << s.seconds << ",";
      else csv << ",,,,,,,";
      csv << (naive ? "" : fmt(r.analysis_seconds, 4)) << ",";
      if (naive)
        csv << ratio(s, r.cells[0], false) << "," << ratio(s, r.cells[0], true) << "," << ratio(s, r.cells[1], true) << ",";
      else csv << ",,,";
      csv << note << "\n";
    }

  // Markdown
  const std::string cpu = benchmark_common::cpu_model(), command = benchmark_common::command_line(argc, argv);
  const std::string date = benchmark_common::utc_date();

  std::ofstream md(prefix + ".md");
  md << "# Reduced system against the naive formulations\n\n"
     << "Command: `" << command << "` (max bodies " << max_n << ", " << seeds << " seeds per size, cap " << cap << " s per system)  \n"
     << "Machine: " << cpu << ", " << sysconf(_SC_NPROCESSORS_ONLN) << " cores online, " << benchmark_common::os_release()
     << "; compiler " << __VERSION__ << "; " << date << "; total run " << fixed(total.time(), 1) << " s.\n\n"
     << "Scenes: the papers' tetra, quad and pent (examples/Rigid_incidence/data), and random planted scenes "
        "`randomN-sK` of N bodies (seed K): points at integer world positions, bodies of 3-5 points sharing a pair "
        "(probability 3/4) or a point with one earlier body, the last quarter of the bodies closing cycles (3-4 points, each "
        "from a different earlier body), each body in its own rational frame (rotation M(q)/|q|^2 of an integer quaternion), "
        "and distances between points of no common body (1 + N/10, or fewer when the scene is already well-constrained, "
        "more while the reduced system would have fewer equations than variables). Closing bodies and distances that would "
        "make `standardize()` merge bodies or that would over-constrain the scene are redrawn; a scene whose reduced system "
        "(for the greedy tree) is still not square is redrawn, up to 30 times (CSV column `draws`).\n\n"
     << "Systems: **reduced, quaternion charts** = `Reduced_system(c, tree, selection, {}, Rotation_form::QUATERNION_CHARTS)` "
        "(chart 0 on every edge) and **reduced, stereographic** = the same in `Rotation_form::STEREOGRAPHIC`, both on the standard "
        "collection with the optimal incidence tree and its well-formed selection; **naive trigonometric (2.1)** and "
        "**naive quaternion (2.2)** = `naive_system(user collection, Naive_form::TRIGONOMETRIC / QUATERNION)` (denominators "
        "cleared), exact coefficients.\n\n"
     << "Columns: *bodies* = bodies of the scene as given / after `standardize()`; *dof* = `dof_count()` of the standard "
        "collection (0: well-constrained by the count, > 0 under-, < 0 over-constrained); *coeff.* = coefficient type "
        "(exact `Gmpq` when every body of the covering set has coordinates, else `Interval_nt<false>`); *vars*, *eqs* = "
        "variables and equations; *deg/var* = the largest degree of one variable in one equation; *tot. deg* = the largest "
        "total degree; *terms* = the total number of terms over all equations; *vars/eq* = the largest number of variables in "
        "one equation; *build s* = wall time (`CGAL::Real_timer`) to build the system (for the reduced systems the "
        "constructor of `Reduced_system` only; *prep s* is the preceding `standardize()` + `optimal_incidence_tree()` + "
        "`select_well_formed_incidences()`); *vars ×*, *terms ×* = naive / reduced (quaternion charts), *terms × st.* = naive / "
        "reduced (stereographic). A reduced system marked * is not square (`is_square()` false; the CSV column `note` "
        "gives its `diagnostic()`). A cell that takes more than " << cap << " s to build is skipped (its child process is "
        "killed) and marked *skipped*.\n\n"
     << "| scene | bodies | dof | system | coeff. | vars | eqs | deg/var | tot. deg | terms | vars/eq | build s | prep s | vars × | terms × | terms × st. |\n"
     << "|:--|--:|--:|:--|:--|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& r : rows) {
    for (int k = 0; k < 4; ++k) {
      const Stats& s = r.cells[std::size_t(k)];
      const bool naive = k >= 2;
      md << "| " << (k == 0 ? "**" + r.scene + "**" : "") << " | "
         << (k == 0 ? std::to_string(r.user_bodies) + " / " + std::to_string(r.standard_bodies) : "") << " | "
         << (k == 0 ? std::to_string(r.dof) : "") << " | " << system_names[k] << (!naive && s.status == OK && !s.square ? " *" : "")
         << " | " << (naive || r.exact ? "exact" : "interval") << " | ";
      if (s.status == OK)
        md << s.vars << " | " << s.eqs << " | " << s.max_var_degree << " | " << s.max_total_degree << " | " << s.terms << " | "
           << s.max_vars_per_eq << " | " << fixed(s.seconds, s.seconds < 1 ? 4 : 2) << " | ";
      else md << "*" << (s.status == SKIPPED ? "skipped (> " + fmt(cap) + " s)" : md_escape(s.message)) << "* | | | | | | | ";
      md << (naive ? "" : fixed(r.analysis_seconds, 4)) << " | ";
      if (naive) md << ratio(s, r.cells[0], false) << " | " << ratio(s, r.cells[0], true) << " | " << ratio(s, r.cells[1], true) << " |\n";
      else md << " | | |\n";
    }
  }
  // summary per group: geometric means of the term ratios over the cells built
  md << "\nGeometric means per group of scenes (over the cells built; skipped cells left out, their count in brackets):\n\n"
     << "| scenes | reduced charts: terms | reduced stereographic: terms | naive trig.: terms | naive quat.: terms | vars × trig. | vars × quat. | terms × trig. | terms × quat. |\n"
     << "|:--|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  std::vector<std::string> groups;
  for (const auto& r : rows) if (std::find(groups.begin(), groups.end(), r.group) == groups.end()) groups.push_back(r.group);
  for (const auto& g : groups) {
    double lt[4] = {0, 0, 0, 0}, lv[2] = {0, 0}, lr[2] = {0, 0};
    int nt[4] = {0, 0, 0, 0}, nr[2] = {0, 0}, skipped[4] = {0, 0, 0, 0};
    for (const auto& r : rows) {
      if (r.group != g) continue;
      for (int k = 0; k < 4; ++k) {
        const Stats& s = r.cells[std::size_t(k)];
        if (s.status == OK) { lt[k] += std::log(double(std::max(1L, s.terms))); ++nt[k]; }
        else ++skipped[k];
      }
      for (int k = 0; k < 2; ++k) {
        const Stats &s = r.cells[std::size_t(k + 2)], &red = r.cells[0];
        if (s.status != OK || red.status != OK) continue;
        lv[k] += std::log(double(s.vars) / double(std::max(1L, red.vars)));
        lr[k] += std::log(double(s.terms) / double(std::max(1L, red.terms)));
        ++nr[k];
      }
    }
    md << "| " << g;
    for (int k = 0; k < 4; ++k)
      md << " | " << (nt[k] ? fixed(std::exp(lt[k] / nt[k]), 0) : "–") << (skipped[k] ? " (" + std::to_string(skipped[k]) + ")" : "");
    for (int k = 0; k < 2; ++k) md << " | " << (nr[k] ? ratio_text(std::exp(lv[k] / nr[k])) : "–");
    for (int k = 0; k < 2; ++k) md << " | " << (nr[k] ? ratio_text(std::exp(lr[k] / nr[k])) : "–");
    md << " |\n";
  }
  const std::string svg_name = prefix.substr(prefix.find_last_of('/') + 1) + ".svg";
  md << "\nChart of the terms (log scale): [" << svg_name << "](" << svg_name << ")\n";
  write_svg(prefix + ".svg", rows, cap);
  std::cout << "total " << fixed(total.time(), 1) << " s; wrote " << prefix << ".md, " << prefix << ".csv and " << prefix << ".svg\n";
  return 0;
}
