// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The naive formulations of optimized_incidence_tree_parametrization.txt, Sections 2.1 and 2.2,
// generated for any scene: one rotation and translation per body. They are what the reduced
// system is measured against (benchmark/Rigid_incidence), not something to solve.

#ifndef CGAL_RIGID_INCIDENCE_NAIVE_SYSTEMS_H
#define CGAL_RIGID_INCIDENCE_NAIVE_SYSTEMS_H

#include <CGAL/Gmpq.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/enclose_coordinates.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// Which naive formulation `naive_system()` writes.
enum class Naive_form
{
  /// Section 2.1: per body three rotation angles as sines and cosines (Z-X-Z Euler angles,
  /// entries of degree 3) with s^2 + c^2 = 1 for each, and a translation: 9 variables a body.
  TRIGONOMETRIC,
  /// Section 2.2: per body a rotation by the stereographic unit quaternion (degree 4 over 4)
  /// and a translation: 6 variables a body.
  QUATERNION
};

/*!
\ingroup PkgRigidIncidenceRef
\brief The naive polynomial system of the collection `user` as the scene gives it (before
`standardize()`): the frame body fixed, every other body of 3 or more points with its own
rotation and translation; for every point shared by bodies b_0 < b_1 < ..., the three
coordinate equations M_0 y_0 + T_0 = M_j y_j + T_j (j >= 1); every distance, and every body
of 2 points (a bar) as its distance, |X_a - X_b|^2 = d^2 through the first body holding each
point; for the trigonometric form, s^2 + c^2 = 1 per angle. Denominators (quaternion form) are
cleared. Coefficients are exact rationals: every body of the scene has coordinates.

For Problem tetra this is the paper's 18 x 18 system (Section 2.1) and its 12 x 12 quaternion
system (Section 2.2). Scenes whose bodies share pairs give more equations than variables:
the naive formulation does not know which incidences are redundant (that is the point of
the well-formed selection).
\throws Input_error if a body lacks coordinates or a point of a distance is in no body.
*/
template <class Traits>
Polynomial_system<CGAL::Gmpq> naive_system(const Rigid_body_collection<Traits>& user, Naive_form form)
{
  typedef CGAL::Gmpq Q;
  typedef Sparse_polynomial<Q> P;
  typedef std::array<P, 3> V;
  Polynomial_system<Q> sys;
  const std::size_t nb = user.number_of_bodies();
  std::vector<bool> rigid(nb, false);
  for (std::size_t b = 0; b < nb; ++b) {
    if (!user.body(b).all_coordinates())
      throw Input_error("naive system: body '" + user.body(b).name + "' has no coordinates");
    rigid[b] = user.body(b).points.size() >= 3;
  }
  const std::size_t home = user.body_index(user.frame());
  if (home >= nb || !rigid[home]) throw Input_error("naive system: the frame body '" + user.frame() + "' is not a body of 3 or more points");
  // variables
  std::vector<std::size_t> first(nb, std::size_t(-1));
  for (std::size_t b = 0; b < nb; ++b) {
    if (!rigid[b] || b == home) continue;
    first[b] = sys.variable_names.size();
    const std::string& n = user.body(b).name;
    if (form == Naive_form::TRIGONOMETRIC)
      for (const char* v : {".s1", ".c1", ".s2", ".c2", ".s3", ".c3"}) { sys.variable_names.push_back(n + v); sys.box.push_back({-1, 1}); }
    else
      for (const char* v : {".t1", ".t2", ".t3"}) { sys.variable_names.push_back(n + v); sys.box.push_back({-1e6, 1e6}); }
    for (const char* v : {".p", ".q", ".r"}) { sys.variable_names.push_back(n + v); sys.box.push_back({-1e6, 1e6}); }
  }
  const std::size_t n = sys.variable_names.size();
  auto var = [&](std::size_t i) { return P::variable(n, i); };
  auto cst = [&](const Q& q) { return P::constant(n, q); };
  // per body: rotation numerator M (row-major), its denominator D, translation T
  std::vector<std::array<P, 9>> M(nb);
  std::vector<P> D(nb, cst(Q(1)));
  std::vector<V> T(nb, V{cst(Q(0)), cst(Q(0)), cst(Q(0))});
  for (std::size_t b = 0; b < nb; ++b) {
    if (!rigid[b]) continue;
    if (b == home) {
      for (int i = 0; i < 9; ++i) M[b][std::size_t(i)] = cst(Q(i % 4 == 0 ? 1 : 0));
      continue;
    }
    const std::size_t v = first[b];
    if (form == Naive_form::TRIGONOMETRIC) {
      // Z-X-Z Euler angles: Rz(1) Rx(2) Rz(3)
      P s1 = var(v), c1 = var(v + 1), s2 = var(v + 2), c2 = var(v + 3), s3 = var(v + 4), c3 = var(v + 5);
      M[b] = {c1 * c3 - s1 * c2 * s3, Q(-1) * (c1 * s3) - s1 * c2 * c3, s1 * s2,
              s1 * c3 + c1 * c2 * s3, c1 * c2 * c3 - s1 * s3, Q(-1) * (c1 * s2),
              s2 * s3, s2 * c3, c2};
      for (int k = 0; k < 3; ++k) T[b][std::size_t(k)] = var(v + 6 + std::size_t(k));
    } else {
      P t2 = var(v) * var(v) + var(v + 1) * var(v + 1) + var(v + 2) * var(v + 2);
      std::array<P, 4> q{cst(Q(1)) - t2, Q(2) * var(v), Q(2) * var(v + 1), Q(2) * var(v + 2)};
      const P &a = q[0], &bq = q[1], &c = q[2], &d = q[3];
      M[b] = {a * a + bq * bq - c * c - d * d, Q(2) * (bq * c - a * d), Q(2) * (bq * d + a * c),
              Q(2) * (bq * c + a * d), a * a - bq * bq + c * c - d * d, Q(2) * (c * d - a * bq),
              Q(2) * (bq * d - a * c), Q(2) * (c * d + a * bq), a * a - bq * bq - c * c + d * d};
      D[b] = (cst(Q(1)) + t2) * (cst(Q(1)) + t2);
      for (int k = 0; k < 3; ++k) T[b][std::size_t(k)] = var(v + 3 + std::size_t(k));
    }
  }
  auto local = [&](std::size_t b, std::size_t p) {
    const auto& pt = user.body(b).coordinates[user.body(b).local(p)];
    return std::array<Q, 3>{internal::exact_rational(Traits::x(pt)), internal::exact_rational(Traits::y(pt)),
                            internal::exact_rational(Traits::z(pt))};
  };
  // D_b X = M_b y + D_b T_b: the position of point p of body b, times D_b
  auto position = [&](std::size_t b, std::size_t p) {
    std::array<Q, 3> y = local(b, p);
    V X;
    for (int i = 0; i < 3; ++i)
      X[std::size_t(i)] = y[0] * M[b][std::size_t(3 * i)] + y[1] * M[b][std::size_t(3 * i + 1)] + y[2] * M[b][std::size_t(3 * i + 2)] +
                          D[b] * T[b][std::size_t(i)];
    return X;
  };
  // incidences
  for (std::size_t p = 0; p < user.number_of_points(); ++p) {
    std::vector<std::size_t> through;
    for (std::size_t b = 0; b < nb; ++b) if (rigid[b] && user.body(b).contains(p)) through.push_back(b);
    for (std::size_t j = 1; j < through.size(); ++j) {
      const std::size_t a = through[0], b = through[j];
      V Xa = position(a, p), Xb = position(b, p);
      for (int i = 0; i < 3; ++i) {
        sys.equations.push_back(Xa[std::size_t(i)] * D[b] - Xb[std::size_t(i)] * D[a]);
        sys.labels.push_back("incidence " + user.label(p) + " '" + user.body(a).name + "' = '" + user.body(b).name + "' coordinate " +
                             std::to_string(i + 1));
      }
    }
  }
  // distances (and bars)
  auto holder = [&](std::size_t p) {
    for (std::size_t b = 0; b < nb; ++b) if (rigid[b] && user.body(b).contains(p)) return b;
    throw Input_error("naive system: point '" + user.label(p) + "' is in no body of 3 or more points");
  };
  auto distance = [&](std::size_t u, std::size_t w, const Q& d2, const std::string& what) {
    const std::size_t a = holder(u), b = holder(w);
    V Xa = position(a, u), Xb = position(b, w);
    P s(n);
    for (int i = 0; i < 3; ++i) {
      P d = Xa[std::size_t(i)] * D[b] - Xb[std::size_t(i)] * D[a];
      s = s + d * d;
    }
    sys.equations.push_back(s - d2 * (D[a] * D[a] * D[b] * D[b]));
    sys.labels.push_back(what);
  };
  for (std::size_t b = 0; b < nb; ++b)
    if (user.body(b).points.size() == 2) {
      const auto& bd = user.body(b);
      std::array<Q, 3> y0 = local(b, bd.points[0]), y1 = local(b, bd.points[1]);
      Q d2 = (y0[0] - y1[0]) * (y0[0] - y1[0]) + (y0[1] - y1[1]) * (y0[1] - y1[1]) + (y0[2] - y1[2]) * (y0[2] - y1[2]);
      distance(bd.points[0], bd.points[1], d2, "bar '" + bd.name + "'");
    }
  for (const auto& d : user.distances())
    distance(d.a, d.b, internal::exact_rational(d.squared), "distance " + user.label(d.a) + "-" + user.label(d.b));
  if (form == Naive_form::TRIGONOMETRIC)
    for (std::size_t b = 0; b < nb; ++b) {
      if (first[b] == std::size_t(-1)) continue;
      for (int k = 0; k < 3; ++k) {
        P s = var(first[b] + std::size_t(2 * k)), c = var(first[b] + std::size_t(2 * k + 1));
        sys.equations.push_back(s * s + c * c - cst(Q(1)));
        sys.labels.push_back("s^2 + c^2 = 1 of '" + user.body(b).name + "' angle " + std::to_string(k + 1));
      }
    }
  return sys;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
