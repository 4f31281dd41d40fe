// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Independent oracles for incidence selections: the exact rank of the Jacobian of the
// incidence equations (equation (1) of well_formed_optimal_incidences.txt) and the
// incidences a tree eliminates (Section 6.1), written apart from the package's code.

#ifndef RIGID_INCIDENCE_TEST_INCIDENCE_ORACLES_H
#define RIGID_INCIDENCE_TEST_INCIDENCE_ORACLES_H

#include <CGAL/Gmpq.h>
#include <CGAL/Random.h>
#include <CGAL/Rigid_incidence/Incidence.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>

#include <array>
#include <map>
#include <vector>

namespace incidence_oracles {
namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;

// Exact rank by Gaussian elimination over the rationals.
inline std::size_t rank(std::vector<std::vector<Q>> m)
{
  std::size_t r = 0, cols = m.empty() ? 0 : m[0].size();
  for (std::size_t col = 0; col < cols && r < m.size(); ++col) {
    std::size_t piv = r;
    while (piv < m.size() && m[piv][col] == 0) ++piv;
    if (piv == m.size()) continue;
    std::swap(m[piv], m[r]);
    for (std::size_t i = 0; i < m.size(); ++i)
      if (i != r && m[i][col] != 0) {
        Q f = m[i][col] / m[r][col];
        for (std::size_t j = col; j < cols; ++j) m[i][j] -= f * m[r][j];
      }
    ++r;
  }
  return r;
}

// The Jacobian of the incidences: body j moves points by w_j x y + t_j; the first body of D is fixed.
template <class C>
 std::size_t jacobian_rank(const C& c, const RI::Incidence_set& I, const std::vector<std::size_t>& D, CGAL::Random& rng)
{
  std::vector<std::array<Q, 3>> y(c.number_of_points());
  for (auto& p : y) for (auto& x : p) x = Q(rng.get_int(-1000, 1000), rng.get_int(1, 97));
  std::map<std::size_t, int> column; // body -> first of its 6 columns, -1 for the fixed body
  for (std::size_t k = 0; k < D.size(); ++k) column[D[k]] = k == 0 ? -1 : int(6 * (k - 1));
  const std::size_t cols = 6 * (D.size() - 1);
  std::vector<std::vector<Q>> rows;
  for (const RI::Incidence& i : I) {
    std::vector<Q> row(cols, Q(0));
    const auto& v = y[i.point];
    // d/d(w, t) of coordinate p of w x v + t
    std::array<Q, 3> dw;
    if (i.coordinate == 1) dw = {Q(0), v[2], -v[1]};
    else if (i.coordinate == 2) dw = {-v[2], Q(0), v[0]};
    else dw = {v[1], -v[0], Q(0)};
    for (int s : {0, 1}) {
      std::size_t b = s == 0 ? i.body_a : i.body_b;
      int col = column.at(b);
      if (col < 0) continue;
      Q sign = s == 0 ? Q(1) : Q(-1);
      for (int k = 0; k < 3; ++k) row[std::size_t(col + k)] += sign * dw[std::size_t(k)];
      row[std::size_t(col + 3 + i.coordinate - 1)] += sign;
    }
    rows.push_back(row);
  }
  return rank(rows);
}

// The incidences a tree eliminates (Section 6.1): an edge sharing one point v gives the triple
// (v, 1..3); an edge sharing a pair (v, w) the triple on v and the double (w, 1..2).
template <class C>
 RI::Incidence_set tree_incidences(const C& c, const RI::Incidence_tree& t)
{
  RI::Incidence_set I;
  for (const auto& e : t.edges) {
    auto shared = c.common_points(e.parent, e.child);
    if (shared.size() >= 1) I.insert(shared[0], e.parent, e.child, {1, 2, 3});
    if (shared.size() >= 2) I.insert(shared[1], e.parent, e.child, {1, 2});
  }
  return I;
}

} // namespace incidence_oracles

#endif
