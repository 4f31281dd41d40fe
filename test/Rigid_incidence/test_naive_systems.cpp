// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// naive_system(): the papers' sizes for Problem tetra (Section 2.1: 18 x 18, incidence
// equations of total degree 3, distances of degree 6, trigonometric relations of degree 2;
// Section 2.2: 12 x 12), and an independent oracle on planted scenes: the true values of the
// naive variables, computed in double from the planted rigid motions (Z-X-Z Euler angles of
// M = Rz(1) Rx(2) Rz(3), as naive_systems.h writes it; the stereographic t = v / (1 + w) of
// the unit quaternion (w, v), w >= 0; translations), make every equation vanish up to
// rounding, and changing any one variable that occurs makes some equation nonzero. The
// numbers of variables and equations are counted independently from the planted scene.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Rigid_incidence.h>

#include "planted_scene.h"
#include "test_check.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> K;
typedef RI::Rigid_incidence_traits<K> Traits;
typedef CGAL::Gmpq Q;

static bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

// ------------------------------------------------------------------ Problem tetra
static void check_tetra()
{
  RI::Scene scene = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/tetra.json");
  auto user = RI::make_collection<Traits>(scene);
  RI::Polynomial_system<Q> trig = RI::naive_system(user, RI::Naive_form::TRIGONOMETRIC);
  CHECK(trig.number_of_variables() == 18, "tetra trigonometric: " << trig.number_of_variables() << " variables, expected 18");
  CHECK(trig.number_of_equations() == 18, "tetra trigonometric: " << trig.number_of_equations() << " equations, expected 18");
  CHECK(trig.labels.size() == trig.equations.size() && trig.box.size() == trig.variable_names.size(), "tetra: labels or box sizes");
  int incidences = 0, distances = 0, relations = 0;
  unsigned max_degree = 0, max_incidence = 0;
  for (std::size_t i = 0; i < trig.equations.size(); ++i) {
    const std::string& l = trig.labels[i];
    const unsigned d = trig.equations[i].total_degree();
    max_degree = std::max(max_degree, d);
    if (starts_with(l, "incidence")) {
      // coordinates 1 and 2 through rows 1, 2 of M (degree 3), coordinate 3 through its row
      // 3 (s2 s3, s2 c3, c2: degree 2); the paper's "incidence equations of degree 3"
      ++incidences;
      max_incidence = std::max(max_incidence, d);
      const unsigned expected = l.back() == '3' ? 2 : 3;
      CHECK(d == expected, "tetra trigonometric: " << l << " of total degree " << d << ", expected " << expected);
    } else if (starts_with(l, "distance")) {
      ++distances;
      CHECK(d == 6, "tetra trigonometric: " << l << " of total degree " << d << ", expected 6");
    } else if (starts_with(l, "s^2 + c^2")) {
      ++relations;
      CHECK(d == 2, "tetra trigonometric: " << l << " of total degree " << d << ", expected 2");
    } else CHECK(false, "tetra trigonometric: unexpected equation " << l);
  }
  CHECK(incidences == 9 && distances == 3 && relations == 6,
        "tetra trigonometric: " << incidences << " incidence, " << distances << " distance, " << relations
                                << " trigonometric equations, expected 9, 3, 6");
  CHECK(max_incidence == 3, "tetra trigonometric: incidence equations of degree " << max_incidence << ", expected 3");
  CHECK(max_degree == 6, "tetra trigonometric: maximum degree " << max_degree << ", expected 6 (the paper's d)");
  RI::Polynomial_system<Q> quat = RI::naive_system(user, RI::Naive_form::QUATERNION);
  CHECK(quat.number_of_variables() == 12, "tetra quaternion: " << quat.number_of_variables() << " variables, expected 12");
  CHECK(quat.number_of_equations() == 12, "tetra quaternion: " << quat.number_of_equations() << " equations, expected 12");
  int qi = 0, qd = 0;
  for (const auto& l : quat.labels) { qi += starts_with(l, "incidence"); qd += starts_with(l, "distance"); }
  CHECK(qi == 9 && qd == 3, "tetra quaternion: " << qi << " incidence and " << qd << " distance equations, expected 9 and 3");
  std::cout << "tetra: trigonometric " << trig.number_of_variables() << " x " << trig.number_of_equations() << ", quaternion "
            << quat.number_of_variables() << " x " << quat.number_of_equations() << "\n";
}

// ------------------------------------------------------------------ planted scenes
struct Planted_scene
{
  planted::Scene scene;
  std::vector<planted::Rigid> maps;   // per body: local = R * world + t
  std::string frame;
};

// Bodies of 3 or 4 points sharing 1 to 3 points with earlier bodies (so every body is
// connected to the frame), maybe a bar (a body of 2 points) between two points of different
// bodies, and 0 to 2 distances; a random frame body. Rotations are proper (no mirror).
// With `cheap`, every distance has one end in the frame body (written through it, so of low
// degree): the quaternion form's distance between two moving bodies has some 60,000 terms,
// and the bar (if any) is the only one of those.
static Planted_scene make_planted(planted::Rng& g, int nbodies, bool cheap)
{
  std::vector<std::string> ls;
  for (int i = 0; i < 4 + 3 * nbodies; ++i) ls.push_back("p" + std::to_string(i));
  Planted_scene ps;
  ps.scene = planted::generic_points(g, ls);
  int next = 0;
  std::vector<std::vector<int>> bodies;
  for (int b = 0; b < nbodies; ++b) {
    std::vector<int> pts;
    if (b > 0) {
      const int share = g.uniform(1, 3);
      for (int guard = 0; int(pts.size()) < share && guard < 100; ++guard) {
        const auto& other = bodies[std::size_t(g.uniform(0, b - 1))];
        int p = other[std::size_t(g.uniform(0, int(other.size()) - 1))];
        if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
      }
    }
    const int size = g.uniform(3, 4);
    while (int(pts.size()) < size) pts.push_back(next++);
    bodies.push_back(pts);
    std::vector<std::string> names;
    for (int p : pts) names.push_back(ls[std::size_t(p)]);
    ps.maps.push_back(planted::random_rigid(g));
    ps.scene.add_body("b" + std::to_string(b), names, ps.maps.back());
  }
  auto in_one_body = [&](int a, int c) {
    for (const auto& b : bodies)
      if (std::count(b.begin(), b.end(), a) && std::count(b.begin(), b.end(), c)) return true;
    return false;
  };
  if (g.uniform(0, 1)) { // a bar
    for (int guard = 0; guard < 100; ++guard) {
      int a = g.uniform(0, next - 1), c = g.uniform(0, next - 1);
      if (a == c || in_one_body(a, c)) continue;
      ps.maps.push_back(planted::random_rigid(g));
      ps.scene.add_body("bar", {ls[std::size_t(a)], ls[std::size_t(c)]}, ps.maps.back());
      break;
    }
  }
  int frame = g.uniform(0, nbodies - 1);
  // the points whose first body (the one a distance is written through) is the frame body
  std::vector<int> own;
  for (int p : bodies[std::size_t(frame)]) {
    bool earlier = false;
    for (int b = 0; b < frame; ++b) earlier = earlier || std::count(bodies[std::size_t(b)].begin(), bodies[std::size_t(b)].end(), p);
    if (!earlier) own.push_back(p);
  }
  if (own.empty()) { frame = 0; own = bodies[0]; }
  ps.frame = "b" + std::to_string(frame);
  const int nd = g.uniform(0, 2);
  for (int k = 0, guard = 0; k < nd && guard < 100; ++guard) {
    int a = cheap ? own[std::size_t(g.uniform(0, int(own.size()) - 1))] : g.uniform(0, next - 1), c = g.uniform(0, next - 1);
    if (a == c || in_one_body(a, c)) continue;
    bool dup = false;
    for (const auto& d : ps.scene.distances) dup = dup || (d.a == a && d.b == c) || (d.a == c && d.b == a);
    if (dup) continue;
    ps.scene.add_distance(ls[std::size_t(a)], ls[std::size_t(c)]);
    ++k;
  }
  return ps;
}

typedef std::array<std::array<double, 3>, 3> Mat;

// The unit quaternion (w, v), w >= 0, of the proper rotation M (Shepperd's method).
static std::array<double, 4> quaternion_of(const Mat& M)
{
  const double tr = M[0][0] + M[1][1] + M[2][2];
  std::array<double, 4> q;
  if (tr >= std::max({M[0][0], M[1][1], M[2][2]})) {
    double w = std::sqrt(1 + tr) / 2;
    q = {w, (M[2][1] - M[1][2]) / (4 * w), (M[0][2] - M[2][0]) / (4 * w), (M[1][0] - M[0][1]) / (4 * w)};
  } else if (M[0][0] >= M[1][1] && M[0][0] >= M[2][2]) {
    double x = std::sqrt(1 + M[0][0] - M[1][1] - M[2][2]) / 2;
    q = {(M[2][1] - M[1][2]) / (4 * x), x, (M[0][1] + M[1][0]) / (4 * x), (M[0][2] + M[2][0]) / (4 * x)};
  } else if (M[1][1] >= M[2][2]) {
    double y = std::sqrt(1 - M[0][0] + M[1][1] - M[2][2]) / 2;
    q = {(M[0][2] - M[2][0]) / (4 * y), (M[0][1] + M[1][0]) / (4 * y), y, (M[1][2] + M[2][1]) / (4 * y)};
  } else {
    double z = std::sqrt(1 - M[0][0] - M[1][1] + M[2][2]) / 2;
    q = {(M[1][0] - M[0][1]) / (4 * z), (M[0][2] + M[2][0]) / (4 * z), (M[1][2] + M[2][1]) / (4 * z), z};
  }
  if (q[0] < 0) for (double& x : q) x = -x;
  return q;
}

// An equation in double, sparse in its variables: per term the coefficient and the
// (variable, exponent) pairs; evaluated with its scale, the sum of |coefficient * monomial|.
struct Double_equation
{
  std::vector<std::size_t> variables;
  std::vector<std::pair<double, std::vector<std::pair<std::size_t, unsigned>>>> terms;
  explicit Double_equation(const RI::Sparse_polynomial<Q>& f) : variables(f.variables())
  {
    for (const auto& t : f.terms()) {
      std::vector<std::pair<std::size_t, unsigned>> m;
      for (std::size_t i = 0; i < t.first.size(); ++i) if (t.first[i]) m.emplace_back(i, t.first[i]);
      terms.emplace_back(CGAL::to_double(t.second), m);
    }
  }
  // |value| / scale at x
  double relative(const std::vector<double>& x) const
  {
    double v = 0, s = 0;
    for (const auto& t : terms) {
      double m = t.first;
      for (const auto& e : t.second) for (unsigned k = 0; k < e.second; ++k) m *= x[e.first];
      v += m;
      s += std::fabs(m);
    }
    return std::fabs(v) / std::max(s, 1e-300);
  }
};
static void check_planted(unsigned seed, int nbodies, RI::Naive_form form)
{
  const bool trig = form == RI::Naive_form::TRIGONOMETRIC;
  const std::string what = std::string(trig ? "trigonometric" : "quaternion") + " seed " + std::to_string(seed) + ": ";
  planted::Rng g(seed);
  Planted_scene ps = make_planted(g, nbodies, !trig);
  auto user = planted::make_collection<Traits>(ps.scene);
  user.set_frame(ps.frame);
  CGAL::Real_timer timer;
  timer.start();
  RI::Polynomial_system<Q> sys = RI::naive_system(user, form);
  timer.stop();
  std::size_t terms = 0;
  for (const auto& f : sys.equations) terms += f.terms().size();
  std::cout << what << ps.scene.bodies.size() << " bodies, " << ps.scene.distances.size() << " distances: "
            << sys.number_of_variables() << " variables, " << sys.number_of_equations() << " equations, " << terms
            << " terms, built in " << timer.time() << " s\n";

  // independent counts from the planted scene
  const auto& sc = ps.scene;
  std::size_t rigid = 0, bars = 0, incidence_rows = 0;
  for (const auto& b : sc.bodies) (b.pts.size() >= 3 ? rigid : bars) += 1;
  for (std::size_t p = 0; p < sc.labels.size(); ++p) {
    std::size_t through = 0;
    for (const auto& b : sc.bodies)
      if (b.pts.size() >= 3 && std::count(b.pts.begin(), b.pts.end(), int(p))) ++through;
    if (through > 1) incidence_rows += 3 * (through - 1);
  }
  const std::size_t nvars = (trig ? 9 : 6) * (rigid - 1);
  const std::size_t neqs = incidence_rows + bars + sc.distances.size() + (trig ? 3 * (rigid - 1) : 0);
  CHECK(sys.number_of_variables() == nvars, what << sys.number_of_variables() << " variables, expected " << nvars);
  CHECK(sys.number_of_equations() == neqs, what << sys.number_of_equations() << " equations, expected " << neqs);
  if (sys.number_of_variables() != nvars) return;

  // the true values: M_b = R_h R_b^T (body frame -> frame body's frame), T_b = t_h - M_b t_b
  std::size_t home = 0;
  for (std::size_t b = 0; b < sc.bodies.size(); ++b) if (sc.bodies[b].name == ps.frame) home = b;
  const planted::Rigid& h = ps.maps[home];
  std::vector<double> x;
  for (std::size_t b = 0; b < sc.bodies.size(); ++b) {
    if (b == home || sc.bodies[b].pts.size() < 3) continue;
    const planted::Rigid& m = ps.maps[b];
    Q Mq[3][3];
    Mat M;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        Mq[i][j] = h.R[i][0] * m.R[j][0] + h.R[i][1] * m.R[j][1] + h.R[i][2] * m.R[j][2];
        M[std::size_t(i)][std::size_t(j)] = CGAL::to_double(Mq[i][j]);
      }
    Q T[3] = {h.t.x, h.t.y, h.t.z};
    const Q tb[3] = {m.t.x, m.t.y, m.t.z};
    for (int i = 0; i < 3; ++i) T[i] = T[i] - (Mq[i][0] * tb[0] + Mq[i][1] * tb[1] + Mq[i][2] * tb[2]);
    Mat back;
    if (trig) {
      // M = Rz(1) Rx(2) Rz(3) = [c1c3 - s1c2s3, -c1s3 - s1c2c3, s1s2; s1c3 + c1c2s3, c1c2c3 - s1s3, -c1s2; s2s3, s2c3, c2]
      double c2 = M[2][2], s2 = std::sqrt(M[2][0] * M[2][0] + M[2][1] * M[2][1]), s1, c1, s3, c3;
      if (Mq[2][0] != 0 || Mq[2][1] != 0) { // s2 > 0 (decided exactly)
        s3 = M[2][0] / s2; c3 = M[2][1] / s2; s1 = M[0][2] / s2; c1 = -M[1][2] / s2;
      } else { // gimbal lock: Rz(1 +- 3); take angle 3 = 0
        s2 = 0; c2 = c2 > 0 ? 1 : -1; s3 = 0; c3 = 1; c1 = M[0][0]; s1 = M[1][0];
      }
      for (double v : {s1, c1, s2, c2, s3, c3}) x.push_back(v);
      back = Mat{{{c1 * c3 - s1 * c2 * s3, -c1 * s3 - s1 * c2 * c3, s1 * s2},
                  {s1 * c3 + c1 * c2 * s3, c1 * c2 * c3 - s1 * s3, -c1 * s2},
                  {s2 * s3, s2 * c3, c2}}};
    } else {
      std::array<double, 4> q = quaternion_of(M);
      double t[3] = {q[1] / (1 + q[0]), q[2] / (1 + q[0]), q[3] / (1 + q[0])};
      for (double v : t) x.push_back(v);
      const double t2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2], a = (1 - t2) / (1 + t2), bq = 2 * t[0] / (1 + t2),
                   c = 2 * t[1] / (1 + t2), d = 2 * t[2] / (1 + t2);
      back = Mat{{{a * a + bq * bq - c * c - d * d, 2 * (bq * c - a * d), 2 * (bq * d + a * c)},
                  {2 * (bq * c + a * d), a * a - bq * bq + c * c - d * d, 2 * (c * d - a * bq)},
                  {2 * (bq * d - a * c), 2 * (c * d + a * bq), a * a - bq * bq - c * c + d * d}}};
    }
    double err = 0;
    for (int i = 0; i < 3; ++i) for (int j = 0; j < 3; ++j) err = std::max(err, std::fabs(back[i][j] - M[i][j]));
    CHECK(err < 1e-12, what << "oracle: the rotation of body " << sc.bodies[b].name << " is not reproduced (error " << err << ")");
    for (int i = 0; i < 3; ++i) x.push_back(CGAL::to_double(T[i]));
  }
  CHECK(x.size() == nvars, what << "oracle: " << x.size() << " values for " << nvars << " variables");
  if (x.size() != nvars) return;

  std::vector<Double_equation> eqs;
  for (const auto& f : sys.equations) eqs.emplace_back(f);
  double worst = 0;
  std::size_t worst_eq = 0;
  for (std::size_t i = 0; i < eqs.size(); ++i) {
    const double r = eqs[i].relative(x);
    if (r > worst) { worst = r; worst_eq = i; }
    // the package's own evaluation agrees (up to rounding) with this one
    const double v = sys.equations[i].evaluate<double>(x);
    CHECK(std::isfinite(v), what << "evaluate<double> of '" << sys.labels[i] << "' is not finite");
  }
  CHECK(worst <= 1e-8, what << "the planted configuration does not solve '" << sys.labels[worst_eq] << "': relative residual " << worst);

  // every variable that occurs: changing it alone breaks some equation (only the equations
  // involving it can change)
  std::vector<bool> occurs(nvars, false);
  for (const auto& e : eqs) for (std::size_t v : e.variables) occurs[v] = true;
  std::size_t perturbed = 0;
  for (std::size_t v = 0; v < nvars; ++v) {
    if (!occurs[v]) continue;
    std::vector<double> y = x;
    y[v] += 0.1 * std::max(1.0, std::fabs(y[v]));
    double rp = 0;
    for (const auto& e : eqs)
      if (std::binary_search(e.variables.begin(), e.variables.end(), v)) rp = std::max(rp, e.relative(y));
    CHECK(rp > 1e-6, what << "changing " << sys.variable_names[v] << " leaves every equation at zero (relative " << rp << ")");
    ++perturbed;
  }
  // every rigid body other than the frame shares a point with an earlier body: all its
  // variables occur (the generator connects every body)
  CHECK(perturbed == nvars, what << perturbed << " of " << nvars << " variables occur in an equation");
}

int main()
{
  check_tetra();
  int scenes = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const int nbodies = 2 + int(seed % 4); // 2 to 5 bodies
    check_planted(seed, nbodies, RI::Naive_form::TRIGONOMETRIC);
    check_planted(seed, nbodies, RI::Naive_form::QUATERNION);
    ++scenes;
  }
  std::cout << scenes << " planted scenes, " << checks << " checks, " << failures << " failures\n";
  std::cout << (failures ? "FAILED" : "OK") << "\n";
  return failures ? 1 : 0;
}
