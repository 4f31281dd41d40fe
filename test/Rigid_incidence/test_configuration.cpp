// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Back-substitution and verification end to end: roots of the reduced system, found here by
// Newton's method from many starts in every chart (an oracle that shares nothing with the
// reduction), are turned into configurations by configuration(), whose residuals in the
// ORIGINAL system of the scene file (residuals(): every body fitted rigidly, every incidence
// of every shared point in every pair of bodies, every distance) must vanish. Also: a point
// that is not a root gives residuals that do not vanish; the frame body sits at the identity;
// fit_rigid_motion() recovers planted motions and flags mirror images; malformed calls throw.
// The mirror image (z -> -z) of every root is checked too: where a body spans space it fits
// only mirrored, and its residuals with the mirrored bodies reflected (what solve_scene()
// needs to reject a spurious root) vanish, while with one point moved they do not.

#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Rigid_incidence.h>

#include <Eigen/Dense>

#include "test_check.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Interval_nt<false> I;

// Newton's method in double on a square system; returns true and the root in x when it
// converges to |f| < tol (with a well-conditioned Jacobian unless `singular_ok`: quad's real
// roots lie on a curve of complex ones, elimination_generically_rigid_3d.txt Section 4, so
// its Jacobian is singular there and Newton converges only linearly).
template <class NT>
bool newton(const std::vector<RI::Sparse_polynomial<NT>>& f, const std::vector<std::vector<RI::Sparse_polynomial<NT>>>& J,
            std::vector<double>& x, double tol, bool singular_ok)
{
  const std::size_t n = x.size();
  for (int it = 0; it < (singular_ok ? 400 : 60); ++it) {
    Eigen::VectorXd F(n);
    Eigen::MatrixXd M(n, n);
    for (std::size_t i = 0; i < n; ++i) {
      F(long(i)) = f[i].template evaluate<double>(x);
      for (std::size_t j = 0; j < n; ++j) M(long(i), long(j)) = J[i][j].template evaluate<double>(x);
    }
    if (F.norm() < tol) {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(M);
      return singular_ok || svd.singularValues()(long(n) - 1) > 1e-9 * svd.singularValues()(0);
    }
    Eigen::VectorXd d = M.fullPivLu().solve(F);
    if (!d.allFinite()) return false;
    for (std::size_t i = 0; i < n; ++i) x[i] -= d(long(i));
    for (double v : x) if (!(std::abs(v) < 1e3)) return false;
  }
  return false;
}

template <class Traits>
void check_scene(const RI::Rigid_body_collection<Traits>& user, const std::string& name, CGAL::Random& rng, int starts,
                 int min_roots, bool singular_ok = false, bool spatial = true)
{
  auto c = RI::standardize(user);
  auto t = RI::optimal_incidence_tree(c);
  auto s = RI::select_well_formed_incidences(c, t);
  CGAL::Protect_FPU_rounding<true> guard;
  RI::Reduced_system<Traits, I> probe(c, t, s);
  CHECK(probe.is_square(), name << ": not square: " << probe.diagnostic());
  if (!probe.is_square()) return;
  const std::size_t combos = probe.number_of_chart_combinations();
  int roots = 0, mirrored = 0, mirrored_images = 0;
  double worst = 0;
  for (std::size_t combo = 0; combo < combos && combo < 64; ++combo) {
    std::vector<int> charts;
    std::size_t k = combo;
    for (const auto& e : probe.parametrization().edges()) { charts.push_back(int(k % std::size_t(e.number_of_charts))); k /= std::size_t(e.number_of_charts); }
    RI::Reduced_system<Traits, I> r(c, t, s, charts);
    std::vector<RI::Sparse_polynomial<I>> f;
    for (const auto& e : r.equations()) f.push_back(e.polynomial);
    const std::size_t n = r.number_of_variables();
    std::vector<std::vector<RI::Sparse_polynomial<I>>> J(n);
    for (std::size_t i = 0; i < n; ++i) for (std::size_t j = 0; j < n; ++j) J[i].push_back(f[i].derivative(j));
    double scale = 1;
    for (const auto& p : f) for (const auto& term : p.terms()) scale = std::max(scale, std::abs(CGAL::to_double(term.second)));
    for (int st = 0; st < starts; ++st) {
      std::vector<double> x(n);
      for (double& v : x) v = rng.get_double(-1, 1);
      if (!newton(f, J, x, (singular_ok ? 1e-9 : 1e-10) * scale, singular_ok)) continue;
      bool inside = true;
      for (std::size_t i = 0; i < n; ++i) inside = inside && x[i] >= r.parametrization().box()[i].first - 1e-9 && x[i] <= r.parametrization().box()[i].second + 1e-9;
      if (!inside) continue;
      ++roots;
      RI::Configuration conf = RI::configuration(r, x);
      RI::Residual_report rep = RI::residuals(user, conf);
      CHECK(rep.complete, name << ": a root leaves bodies or distances unplaced");
      if (rep.mirrored) {
        // a body known by distances may come back mirrored: reported, not hidden; with the
        // mirrored bodies allowed their mirror image, a root is an exact (mirrored) solution
        ++mirrored;
        CHECK(rep.max_incidence_mirrored < 1e-6 && rep.max_distance_mirrored < 1e-6,
              name << ": a mirrored root, residuals " << rep.max_incidence_mirrored << ", " << rep.max_distance_mirrored << " with its mirror image");
        std::vector<double> y = x;
        y[0] += 0.05;
        const RI::Residual_report bad = RI::residuals(user, RI::configuration(r, y));
        CHECK(std::max(bad.max_incidence_mirrored, bad.max_distance_mirrored) > 1e-6,
              name << ": a point that is no root fits as a mirror image");
        continue;
      }
      double m = rep.max();
      worst = std::max(worst, m);
      CHECK(m < 1e-6, name << ": residual " << m << " at a root of the reduced system (chart combination " << combo << ")");
      // the frame body sits at the identity
      const std::size_t F = c.body_index(c.frame());
      CHECK(conf.frame == c.frame() && conf.body_placed[F], name << ": not in the scene's frame");
      if (conf.body_placed[F])
        for (int q = 0; q < 9; ++q) CHECK(std::abs(conf.poses[F].R[std::size_t(q)] - (q % 4 == 0 ? 1 : 0)) < 1e-9, name << ": frame pose not the identity");
      // its mirror image (z -> -z): every body that spans space fits only mirrored, and as a
      // mirror image it holds (what solve_scene() rejects as a spurious root); one point moved
      // off it fits no body, mirrored or not (what solve_scene() must not reject)
      {
        RI::Configuration cm = conf;
        for (auto& p : cm.points) p[2] = -p[2];
        const RI::Residual_report rm = RI::residuals(user, cm);
        if (rm.mirrored) {
          ++mirrored_images;
          CHECK(rm.max_incidence_mirrored < 1e-6 && rm.max_distance_mirrored < 1e-6,
                name << ": the mirror image of a root, residuals " << rm.max_incidence_mirrored << ", " << rm.max_distance_mirrored);
          for (std::size_t q = 0; q < cm.points.size(); ++q) {
            RI::Configuration cq = cm;
            cq.points[q][0] += 0.05;
            const RI::Residual_report rq = RI::residuals(user, cq);
            if (!rq.mirrored) continue;
            CHECK(std::max(rq.max_incidence_mirrored, rq.max_distance_mirrored) > 1e-6,
                  name << ": the mirror image with point " << cm.labels[q] << " moved fits as a mirror image");
          }
        }
      }
      // a point that is not a root: perturb one parameter, the residuals must not vanish
      std::vector<double> y = x;
      y[0] += 0.05;
      double bad = RI::residuals(user, RI::configuration(r, y)).max();
      CHECK(bad > 1e-6, name << ": residual " << bad << " at a point that is no root");
    }
  }
  CHECK(roots >= min_roots, name << ": Newton found only " << roots << " roots");
  CHECK(!spatial || mirrored_images > 0, name << ": no root's mirror image has a body that fits only mirrored");
  std::cout << name << ": " << roots << " Newton roots (" << mirrored << " with a mirrored body, " << mirrored_images << " mirror images checked), worst residual " << worst << "\n";
}

template <class Traits>
RI::Rigid_body_collection<Traits> scene(const std::string& f)
{
  return RI::make_collection<Traits>(RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + f));
}

int main()
{
  typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Exact;
  typedef RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel> Epick;
  CGAL::Random rng(5);
  check_scene(scene<Exact>("tetra.json"), "tetra [exact]", rng, 12, 2);
  check_scene(scene<Exact>("quad.json"), "quad [exact]", rng, 6, 2, true, false);  // (flat bodies: no handedness)
  check_scene(scene<Exact>("pent.json"), "pent [exact]", rng, 6, 1);
  check_scene(scene<Epick>("tetra.json"), "tetra [epick]", rng, 8, 2);

  // fit_rigid_motion: a planted motion is recovered; a mirror image is flagged
  {
    std::vector<std::array<double, 3>> y{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {1, 1, 1}}, x, xm;
    const double a = 0.7, ca = std::cos(a), sa = std::sin(a);
    RI::Rigid_motion m;
    m.R = {ca, -sa, 0, sa, ca, 0, 0, 0, 1};
    m.t = {1e3, -2, 5};
    for (const auto& p : y) { x.push_back(m(p)); auto q = m(p); q[2] = -q[2]; xm.push_back(q); }
    RI::Rigid_fit f = RI::fit_rigid_motion(y, x);
    CHECK(f.ok && !f.reflected && f.rms < 1e-9, "fit of a planted motion: rms " << f.rms);
    for (int i = 0; i < 9; ++i) CHECK(std::abs(f.motion.R[std::size_t(i)] - m.R[std::size_t(i)]) < 1e-9, "fitted rotation");
    RI::Rigid_fit g = RI::fit_rigid_motion(y, xm);
    CHECK(g.ok && g.reflected && g.rms > 0.1, "a mirror image is not flagged");
    for (std::size_t i = 0; i < y.size(); ++i) {  // its mirror motion takes the body onto it
      const auto p = g.mirror(y[i]);
      CHECK(std::abs(p[0] - xm[i][0]) + std::abs(p[1] - xm[i][1]) + std::abs(p[2] - xm[i][2]) < 1e-9, "mirror motion of point " << i);
    }
    RI::Rigid_fit h = RI::fit_rigid_motion({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}});
    // collinear points: the rotation about their line is free; one that fits is returned,
    // flagged (a triangle 1e-7 off its hinge is a body of a scene, and its residual counts)
    CHECK(h.ok && h.collinear && h.rms < 1e-12, "collinear points: ok " << h.ok << ", collinear " << h.collinear << ", rms " << h.rms);
    RI::Rigid_fit h1 = RI::fit_rigid_motion({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CHECK(h1.ok && !h1.collinear, "a proper triangle flagged collinear");
    RI::Rigid_fit h2 = RI::fit_rigid_motion({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
    CHECK(!h2.ok, "three points at one place fitted");
    RI::Rigid_motion id = m.inverse() * m;
    for (int i = 0; i < 9; ++i) CHECK(std::abs(id.R[std::size_t(i)] - (i % 4 == 0 ? 1 : 0)) < 1e-12, "inverse");
  }
  // malformed calls
  {
    auto user = scene<Exact>("pent.json");
    auto c = RI::standardize(user);
    auto t = RI::optimal_incidence_tree(c);
    auto s = RI::select_well_formed_incidences(c, t);
    RI::Reduced_system<Exact, CGAL::Gmpq> r(c, t, s);
    bool threw = false;
    try { RI::configuration(r, std::vector<double>(r.number_of_variables() + 1, 0.0)); } catch (const RI::Input_error&) { threw = true; }
    CHECK(threw, "a wrong number of values accepted");
    threw = false;
    std::vector<double> x(r.number_of_variables(), 0.0);
    x[0] = std::nan("");
    try { RI::configuration(r, x); } catch (const RI::Input_error& e) { threw = std::string(e.what()).find("not a finite") != std::string::npos; }
    CHECK(threw, "a NaN parameter accepted");
  }
  std::cout << checks << " checks, " << failures << " failures: " << (failures ? "FAILED" : "OK") << "\n";
  return failures ? 1 : 0;
}
