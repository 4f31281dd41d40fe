// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A small sparse multivariate polynomial and a polynomial system over a box: the general
// layer (no bodies, no scenes) that the reduced system produces and the solver consumes.
//
// Why not CGAL::Polynomial: it is recursive and dense in each variable (a polynomial in x0
// whose coefficients are polynomials in x1, ...), so an equation in 2 of 8 variables still
// nests through all 8, and its coefficient operations assume a field or a UFD, which interval
// types are not. The reduced systems are small (a few variables per equation, degree at most
// a few per variable) and the solver converts each equation to a tensor-product Bernstein
// array over the variables it involves; what it needs from this type is the exponent /
// coefficient list, the variables involved and the degree in each. A sorted map from
// exponent vectors to coefficients does exactly that and works for any number type with
// + - * (Gmpq, CGAL::Interval_nt, CGAL::Gmpfi, double).

#ifndef CGAL_RIGID_INCIDENCE_POLYNOMIAL_SYSTEM_H
#define CGAL_RIGID_INCIDENCE_POLYNOMIAL_SYSTEM_H

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Interval_traits.h>
#include <CGAL/Rigid_incidence/Input_error.h>

#include <algorithm>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

namespace internal {
// A coefficient that is certainly zero: exact zero, or the degenerate interval [0, 0].
template <class NT> bool certainly_zero(const NT& x)
{
  typedef CGAL::Interval_traits<NT> IT;
  if constexpr (std::is_same<typename IT::Is_interval, CGAL::Tag_true>::value) {
    typename IT::Lower lower;
    typename IT::Upper upper;
    return lower(x) == 0 && upper(x) == 0;
  } else {
    return x == NT(0);
  }
}
// A coefficient that may be zero: exact zero, or an interval containing 0.
template <class NT> bool may_be_zero(const NT& x)
{
  typedef CGAL::Interval_traits<NT> IT;
  if constexpr (std::is_same<typename IT::Is_interval, CGAL::Tag_true>::value) {
    typename IT::Lower lower;
    typename IT::Upper upper;
    return !(lower(x) > 0) && !(upper(x) < 0);
  } else {
    return x == NT(0);
  }
}
// Two coefficients certainly equal: exact equality, or the same degenerate interval [x, x].
template <class NT> bool certainly_same(const NT& x, const NT& y)
{
  typedef CGAL::Interval_traits<NT> IT;
  if constexpr (std::is_same<typename IT::Is_interval, CGAL::Tag_true>::value) {
    typename IT::Lower lower;
    typename IT::Upper upper;
    return lower(x) == upper(x) && lower(y) == upper(y) && lower(x) == lower(y);
  } else {
    return x == y;
  }
}
} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief A sparse polynomial in a fixed number of variables x_0 .. x_{n-1} with coefficients of
type `NT`: a sorted map from exponent vectors to coefficients.

Terms whose coefficient is certainly zero (an exact 0, or the interval [0, 0]) are dropped;
an interval coefficient that merely contains 0 is kept, since the exact value it encloses may
not be zero.

\tparam NT a number type with `+`, `-`, `*` and construction from `int`: `CGAL::Gmpq`,
`CGAL::Interval_nt<false>`, `CGAL::Gmpfi`, `double`.
*/
template <class NT>
class Sparse_polynomial
{
public:
  typedef std::vector<unsigned> Exponent;      ///< one exponent per variable
  typedef std::map<Exponent, NT> Term_map;     ///< exponent vector -> coefficient

  /// The zero polynomial in `n` variables.
  explicit Sparse_polynomial(std::size_t n = 0) : n_(n) {}
  /// The constant `c` in `n` variables.
  static Sparse_polynomial constant(std::size_t n, const NT& c)
  {
    Sparse_polynomial p(n);
    p.add_term(Exponent(n, 0), c);
    return p;
  }
  /// The variable x_i in `n` variables.
  static Sparse_polynomial variable(std::size_t n, std::size_t i)
  {
    if (i >= n) throw Input_error("Sparse_polynomial::variable: index " + std::to_string(i) + " of " + std::to_string(n) + " variables");
    Exponent e(n, 0);
    e[i] = 1;
    Sparse_polynomial p(n);
    p.add_term(e, NT(1));
    return p;
  }

  /// Number of variables.
  std::size_t number_of_variables() const { return n_; }
  /// The terms, sorted by exponent vector.
  const Term_map& terms() const { return t_; }
  /// `true` if no term is left.
  bool is_zero() const { return t_.empty(); }
  /// Adds c x^e.
  void add_term(const Exponent& e, const NT& c)
  {
    if (e.size() != n_) throw Input_error("Sparse_polynomial::add_term: exponent of the wrong length");
    if (internal::certainly_zero(c)) return;
    auto it = t_.find(e);
    if (it == t_.end()) { t_.emplace(e, c); return; }
    it->second = it->second + c;
    if (internal::certainly_zero(it->second)) t_.erase(it);
  }

  /// Sum.
  friend Sparse_polynomial operator+(Sparse_polynomial a, const Sparse_polynomial& b)
  {
    a.check(b);
    for (const auto& t : b.t_) a.add_term(t.first, t.second);
    return a;
  }
  /// Difference.
  friend Sparse_polynomial operator-(Sparse_polynomial a, const Sparse_polynomial& b)
  {
    a.check(b);
    for (const auto& t : b.t_) a.add_term(t.first, NT(0) - t.second);
    return a;
  }
  /// Product.
  friend Sparse_polynomial operator*(const Sparse_polynomial& a, const Sparse_polynomial& b)
  {
    a.check(b);
    Sparse_polynomial r(a.n_);
    Exponent e(a.n_);
    for (const auto& x : a.t_)
      for (const auto& y : b.t_) {
        for (std::size_t i = 0; i < a.n_; ++i) e[i] = x.first[i] + y.first[i];
        r.add_term(e, x.second * y.second);
      }
    return r;
  }
  /// Product with a constant.
  friend Sparse_polynomial operator*(const NT& c, const Sparse_polynomial& a)
  {
    Sparse_polynomial r(a.n_);
    for (const auto& x : a.t_) r.add_term(x.first, c * x.second);
    return r;
  }

  /// Degree in x_i (0 for the zero polynomial).
  unsigned degree(std::size_t i) const
  {
    unsigned d = 0;
    for (const auto& t : t_) d = (std::max)(d, t.first[i]);
    return d;
  }
  /// Total degree (0 for the zero polynomial).
  unsigned total_degree() const
  {
    unsigned d = 0;
    for (const auto& t : t_) {
      unsigned s = 0;
      for (unsigned x : t.first) s += x;
      d = (std::max)(d, s);
    }
    return d;
  }
  /// The degree in each variable, in one pass over the terms (all 0 for the zero polynomial).
  std::vector<unsigned> degrees() const
  {
    std::vector<unsigned> d(n_, 0);
    for (const auto& t : t_)
      for (std::size_t i = 0; i < n_; ++i) d[i] = (std::max)(d[i], t.first[i]);
    return d;
  }
  /// The variables of positive degree, increasing.
  std::vector<std::size_t> variables() const
  {
    const std::vector<unsigned> d = degrees();
    std::vector<std::size_t> v;
    for (std::size_t i = 0; i < n_; ++i) if (d[i] > 0) v.push_back(i);
    return v;
  }
  /// The number of coefficients of the dense tensor-product array over the variables of
  /// positive degree, prod (degree in x_i + 1): what `Subdivision_solver` and `trace_curves()`
  /// store for this polynomial (as a double: it may exceed any integer type).
  double dense_array_size() const
  {
    double m = 1;
    for (unsigned d : degrees()) m *= double(d) + 1;
    return m;
  }
  /// The partial derivative with respect to x_i.
  Sparse_polynomial derivative(std::size_t i) const
  {
    if (i >= n_) throw Input_error("Sparse_polynomial::derivative: variable " + std::to_string(i) + " of " + std::to_string(n_));
    Sparse_polynomial r(n_);
    for (const auto& t : t_) {
      if (t.first[i] == 0) continue;
      Exponent e = t.first;
      --e[i];
      r.add_term(e, NT(int(t.first[i])) * t.second);
    }
    return r;
  }
  /// The value at `x` (one value per variable), in the type `T` (`NT`, or an interval type
  /// to enclose the value over a box), Horner-free: a sum of monomials.
  template <class T>
  T evaluate(const std::vector<T>& x) const
  {
    if (x.size() != n_) throw Input_error("Sparse_polynomial::evaluate: " + std::to_string(x.size()) + " values for " +
                                          std::to_string(n_) + " variables");
    T s(0);
    for (const auto& t : t_) {
      T m = convert<T>(t.second);
      for (std::size_t i = 0; i < n_; ++i)
        for (unsigned k = 0; k < t.first[i]; ++k) m = m * x[i];
      s = s + m;
    }
    return s;
  }

  /// Writes the polynomial with the given variable names (x0, x1, ... if empty).
  void write(std::ostream& os, const std::vector<std::string>& names = {}) const
  {
    if (t_.empty()) { os << "0"; return; }
    bool first = true;
    for (auto it = t_.rbegin(); it != t_.rend(); ++it) {
      os << (first ? "" : " + ") << "(" << it->second << ")";
      for (std::size_t i = 0; i < n_; ++i) {
        if (!it->first[i]) continue;
        os << "*" << (i < names.size() ? names[i] : "x" + std::to_string(i));
        if (it->first[i] > 1) os << "^" << it->first[i];
      }
      first = false;
    }
  }

private:
  template <class T> static T convert(const NT& c)
  {
    if constexpr (std::is_same<T, NT>::value) return c;
    else if constexpr (std::is_same<T, double>::value) return CGAL::to_double(c);
    else if constexpr (std::is_same<T, CGAL::Interval_nt<false>>::value || std::is_same<T, CGAL::Interval_nt<true>>::value)
      return T(CGAL::to_interval(c));
    else return T(c);
  }
  void check(const Sparse_polynomial& b) const
  {
    if (b.n_ != n_) throw Input_error("Sparse_polynomial: " + std::to_string(n_) + " and " + std::to_string(b.n_) + " variables mixed");
  }
  std::size_t n_;
  Term_map t_;
};

/*!
\ingroup PkgRigidIncidenceRef
\brief A system of polynomial equations f_i = 0 in named variables over a box.

Layer 1 of the package: it knows nothing of bodies or scenes, so any polynomial system can be
written in it and handed to the solver. Each equation carries a free-text label (the reduced
system puts the incidence or distance it comes from there).
*/
template <class NT>
struct Polynomial_system
{
  std::vector<std::string> variable_names;           ///< one per variable
  std::vector<std::pair<double, double>> box;        ///< per variable: [lower, upper] searched
  std::vector<Sparse_polynomial<NT>> equations;      ///< f_i = 0
  std::vector<std::string> labels;                   ///< per equation: where it comes from
  /// Inequality constraints g_j >= 0 (optional): the solver discards boxes where some g_j < 0
  /// certainly and marks a root where some g_j may be 0 (`Solver_root::on_inequality_boundary`).
  std::vector<Sparse_polynomial<NT>> inequalities;
  std::vector<std::string> inequality_labels;        ///< per inequality: where it comes from (optional)

  /// Number of variables.
  std::size_t number_of_variables() const { return variable_names.size(); }
  /// Number of equations.
  std::size_t number_of_equations() const { return equations.size(); }
  /// Number of inequalities.
  std::size_t number_of_inequalities() const { return inequalities.size(); }
};

namespace internal {

// The dense arrays a solver over tensor-product Bernstein forms allocates for `s` (each equation
// and inequality over the variables it involves, with `per_variable` and `per_pair` more arrays
// of at most its size per involved variable and per pair of them: derivatives), against `limit`
// coefficients: an Input_error (prefixed by `who`) naming the largest equation instead of a
// failed allocation, or of the machine's whole memory, for an equation in many variables.
template <class NT>
void check_dense_storage(const Polynomial_system<NT>& s, double limit, double per_variable, double per_pair, const std::string& who)
{
  double total = 0, worst = -1;
  std::size_t at = 0;
  auto add = [&](const Sparse_polynomial<NT>& f, std::size_t i) {
    const double k = double(f.variables().size()), m = f.dense_array_size();
    total += m * (1 + per_variable * k + per_pair * k * k);
    if (m > worst) { worst = m; at = i; }
  };
  for (std::size_t i = 0; i < s.equations.size(); ++i) add(s.equations[i], i);
  for (const auto& g : s.inequalities) add(g, std::size_t(-1));
  if (!(total > limit)) return;
  std::string which = "an inequality", degrees;
  if (at != std::size_t(-1)) {
    // the equation's label (where it comes from: "equation 3" of a file, a distance of a scene)
    which = at < s.labels.size() && !s.labels[at].empty() ? s.labels[at] : "equation " + std::to_string(at);
    for (std::size_t v : s.equations[at].variables())
      degrees += (degrees.empty() ? "" : ", ") + (v < s.variable_names.size() && !s.variable_names[v].empty() ? s.variable_names[v] : "x" + std::to_string(v)) +
                 "^" + std::to_string(s.equations[at].degree(v));
  }
  std::ostringstream os;
  os.precision(3);
  os << who << ": the system's dense tensor-product arrays (with their derivatives) would need " << total
     << " coefficients, more than maximal_coefficients = " << limit << "; the largest is " << which
     << (degrees.empty() ? std::string() : " in " + degrees) << ", " << worst
     << " coefficients by itself. Introduce auxiliary variables (e.g. y = x^2 as an equation of its own) so that each equation "
        "involves fewer variables, or raise maximal_coefficients";
  throw Input_error(os.str());
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceRef
\brief The determinant of a square matrix of polynomials (all in the same variables), by Laplace
expansion with the minors of the lower rows shared: about n 2^(n-1) polynomial products.
*/
template <class NT>
Sparse_polynomial<NT> determinant(const std::vector<std::vector<Sparse_polynomial<NT>>>& m)
{
  const std::size_t n = m.size();
  if (n == 0) throw Input_error("determinant: empty matrix");
  if (n > 20) throw Input_error("determinant: " + std::to_string(n) + " rows is too many for the expansion");
  const std::size_t vars = m[0][0].number_of_variables();
  for (const auto& row : m)
    if (row.size() != n) throw Input_error("determinant: the matrix is not square");
  // minor[S]: the determinant of the last |S| rows and the columns in S (a bit mask)
  std::map<unsigned long, Sparse_polynomial<NT>> minor, next;
  for (std::size_t j = 0; j < n; ++j) minor[1ul << j] = m[n - 1][j];
  for (std::size_t i = n - 1; i-- > 0;) {
    next.clear();
    for (const auto& sub : minor)
      for (std::size_t j = 0; j < n; ++j) {
        if (sub.first & (1ul << j)) continue;
        if (m[i][j].is_zero() || sub.second.is_zero()) {
          next.emplace(sub.first | (1ul << j), Sparse_polynomial<NT>(vars));
          continue;
        }
        // the sign of column j among the columns of S + j: (-1)^(columns of S before j)
        std::size_t before = 0;
        for (std::size_t k = 0; k < j; ++k) before += (sub.first >> k) & 1ul;
        Sparse_polynomial<NT> t = m[i][j] * sub.second;
        auto it = next.find(sub.first | (1ul << j));
        if (it == next.end()) it = next.emplace(sub.first | (1ul << j), Sparse_polynomial<NT>(vars)).first;
        it->second = before % 2 ? it->second - t : it->second + t;
      }
    minor.swap(next);
  }
  return minor.begin()->second;
}

namespace internal {

// An exact power of two near |q| (q != 0): 2^e with e = bits(num) - bits(den).
inline long binary_exponent(const CGAL::Gmpq& q)
{
  return long(mpz_sizeinbase(mpq_numref(q.mpq()), 2)) - long(mpz_sizeinbase(mpq_denref(q.mpq()), 2));
}

// The system with each equation and inequality multiplied by an exact power of two that brings
// its largest coefficient near 1, when some coefficient's magnitude is beyond 2^+-60 (for exact
// rational coefficients; others are returned as they are). The roots, their multiplicities and
// the inequalities' signs are unchanged, and the coefficients' double enclosures no longer
// overflow or underflow: 1e400 x - 1e400 was an interval [-inf, inf] ("positive-dimensional").
template <class NT>
const Polynomial_system<NT>& scaled_to_unit(const Polynomial_system<NT>& s, Polynomial_system<NT>& out)
{
  if constexpr (!std::is_same<NT, CGAL::Gmpq>::value) { (void)out; return s; }
  else {
    auto exponent_range = [](const Sparse_polynomial<NT>& f, long& lo, long& hi) {
      bool any = false;
      for (const auto& t : f.terms()) {
        if (t.second == 0) continue;
        long e = binary_exponent(t.second);
        lo = any ? (std::min)(lo, e) : e;
        hi = any ? (std::max)(hi, e) : e;
        any = true;
      }
      return any;
    };
    bool needed = false;
    for (const auto* list : {&s.equations, &s.inequalities})
      for (const auto& f : *list) {
        long lo = 0, hi = 0;
        if (exponent_range(f, lo, hi) && (hi > 60 || lo < -60)) needed = true;
      }
    if (!needed) return s;
    out = s;
    for (auto* list : {&out.equations, &out.inequalities})
      for (auto& f : *list) {
        long lo = 0, hi = 0;
        if (!exponent_range(f, lo, hi) || hi == 0) continue;
        CGAL::Gmpz p(1);
        mpz_mul_2exp(p.mpz(), p.mpz(), (unsigned long)(hi < 0 ? -hi : hi));
        f = (hi > 0 ? CGAL::Gmpq(CGAL::Gmpz(1), p) : CGAL::Gmpq(p)) * f;
      }
    return out;
  }
}

} // namespace internal

} // namespace Rigid_incidence
} // namespace CGAL

#endif
