// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tensor-product Bernstein arrays over the variables one equation involves, in interval
// arithmetic: conversion from the power basis on a box, de Casteljau subdivision and
// restriction, degree elevation, Horner evaluation and the projected control polygon.
// Every operation returns an enclosure of the exact array (outward rounding of the interval
// type), so a sign of the coefficients is a sign of the polynomial over the box.

#ifndef CGAL_RIGID_INCIDENCE_INTERNAL_BERNSTEIN_TENSOR_H
#define CGAL_RIGID_INCIDENCE_INTERNAL_BERNSTEIN_TENSOR_H

#include <CGAL/Rigid_incidence/internal/interval_ops.h>

#include <algorithm>
#include <limits>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

// The shape of a dense tensor over k local variables: degree d_j in each, index
// sum_j i_j * stride_j with the last variable fastest.
struct Tensor_shape
{
  std::vector<std::size_t> variables;  // global indices, increasing
  std::vector<unsigned> degrees;       // per local variable
  std::vector<std::size_t> strides;    // per local variable
  std::size_t size = 1;

  void set(const std::vector<std::size_t>& vars, const std::vector<unsigned>& degs)
  {
    variables = vars;
    degrees = degs;
    strides.assign(vars.size(), 1);
    size = 1;
    for (std::size_t j = vars.size(); j-- > 0;) {
      strides[j] = size;
      size *= degs[j] + 1;
    }
  }
  std::size_t local(std::size_t global) const
  {
    auto it = std::lower_bound(variables.begin(), variables.end(), global);
    return (it != variables.end() && *it == global) ? std::size_t(it - variables.begin()) : std::size_t(-1);
  }
  // Calls f(base) for the first element of every fiber along local axis j.
  template <class F> void for_each_fiber(std::size_t j, F f) const
  {
    const std::size_t s = strides[j], block = s * (degrees[j] + 1);
    for (std::size_t outer = 0; outer < size; outer += block)
      for (std::size_t inner = 0; inner < s; ++inner) f(outer + inner);
  }
};

// C(i, j) / C(d, j) as an interval (the power -> Bernstein matrix).
template <class IT> IT binomial_ratio(unsigned i, unsigned j, unsigned d)
{
  // C(i,j)/C(d,j) = prod_{k<j} (i-k)/(d-k)
  IT r(1);
  for (unsigned k = 0; k < j; ++k) r = r * IT(int(i - k)) / IT(int(d - k));
  return r;
}

// Power coefficients (dense, shape `s`) of p(x) in the box lo <= x <= hi (per local variable,
// as intervals whose bounds are the box's) -> Bernstein coefficients on that box.
template <class IT>
std::vector<IT> to_bernstein(const Tensor_shape& s, std::vector<IT> a, const std::vector<IT>& lo, const std::vector<IT>& width)
{
  std::vector<IT> f;
  for (std::size_t j = 0; j < s.variables.size(); ++j) {
    const unsigned d = s.degrees[j];
    if (d == 0) continue;
    const std::size_t st = s.strides[j];
    std::vector<std::vector<IT>> ratio(d + 1);
    for (unsigned i = 0; i <= d; ++i)
      for (unsigned k = 0; k <= i; ++k) ratio[i].push_back(binomial_ratio<IT>(i, k, d));
    f.resize(d + 1);
    s.for_each_fiber(j, [&](std::size_t base) {
      for (unsigned i = 0; i <= d; ++i) f[i] = a[base + i * st];
      // Taylor shift x = lo + y: repeated synthetic division
      for (unsigned i = 0; i < d; ++i)
        for (unsigned k = d - 1; k + 1 > i; --k) f[k] = f[k] + lo[j] * f[k + 1];
      // y = width * t
      IT w(1);
      for (unsigned i = 1; i <= d; ++i) { w = w * width[j]; f[i] = f[i] * w; }
      // power -> Bernstein: b_i = sum_{k<=i} C(i,k)/C(d,k) f_k
      for (unsigned i = 0; i <= d; ++i) {
        IT b(0);
        for (unsigned k = 0; k <= i; ++k) b = b + ratio[i][k] * f[k];
        a[base + i * st] = b;
      }
    });
  }
  return a;
}

// de Casteljau along local axis j at parameter t (an interval holding the exact parameter):
// `left` gets the array on [0, t], `right` on [t, 1].
template <class IT>
void split(const Tensor_shape& s, const std::vector<IT>& b, std::size_t j, const IT& t, std::vector<IT>& left, std::vector<IT>& right)
{
  left = b;
  right = b;
  const unsigned d = s.degrees[j];
  if (d == 0) return;
  const std::size_t st = s.strides[j];
  const IT u = IT(1) - t;
  const bool half = Interval_ops<IT>::lower(t) == Interval_ops<IT>::upper(t) && Interval_ops<IT>::to_double(Interval_ops<IT>::lower(t)) == 0.5;
  std::vector<IT> w(d + 1);
  s.for_each_fiber(j, [&](std::size_t base) {
    for (unsigned i = 0; i <= d; ++i) w[i] = b[base + i * st];
    left[base] = w[0];
    right[base + d * st] = w[d];
    for (unsigned r = 1; r <= d; ++r) {
      for (unsigned i = 0; i + r <= d; ++i) w[i] = half ? (w[i] + w[i + 1]) / 2 : u * w[i] + t * w[i + 1];
      left[base + r * st] = w[0];
      right[base + (d - r) * st] = w[d - r];
    }
  });
}

// The array on [tu, tv] of local axis j (tu <= tv, both intervals inside [0, 1]).
template <class IT>
std::vector<IT> restrict_axis(const Tensor_shape& s, const std::vector<IT>& b, std::size_t j, const IT& tu, const IT& tv, bool tu_zero, bool tv_one)
{
  std::vector<IT> l, r, cur = b;
  if (!tv_one) { split(s, cur, j, tv, l, r); cur.swap(l); }
  if (!tu_zero) { split(s, cur, j, tu / tv, l, r); cur.swap(r); }
  return cur;
}

// Degree elevation along local axis j from degree d to D (D >= d): returns the array in the
// shape `to` (same variables, degree D on axis j).
template <class IT>
std::vector<IT> elevate_axis(const Tensor_shape& from, const std::vector<IT>& b, std::size_t j, const Tensor_shape& to)
{
  const unsigned d = from.degrees[j], D = to.degrees[j];
  // in one step: b'_k = sum_i C(d, i) C(D - d, k - i) / C(D, k) b_i (the weights are exact
  // ratios of integers, enclosed once; 1 and 1/2 are exact)
  auto binom = [](unsigned n, unsigned k) { double r = 1; for (unsigned t = 1; t <= k; ++t) r = r * (n - k + t) / t; return r; };
  std::vector<IT> E((D + 1) * (d + 1), IT(0));
  std::vector<char> unit((D + 1) * (d + 1), 0);
  for (unsigned k = 0; k <= D; ++k)
    for (unsigned i = 0; i <= d && i <= k; ++i) {
      if (k - i > D - d) continue;
      const double num = binom(d, i) * binom(D - d, k - i), den = binom(D, k);
      E[k * (d + 1) + i] = IT(num) / IT(den);
      unit[k * (d + 1) + i] = num == den;
    }
  const std::size_t st = from.strides[j];  // the axes after j keep their degrees: the same stride
  const std::size_t bf = st * (d + 1), bt = st * (D + 1);
  std::vector<IT> out(to.size, IT(0));
  for (std::size_t o = 0, ot = 0; o < from.size; o += bf, ot += bt)
    for (std::size_t in = 0; in < st; ++in)
      for (unsigned k = 0; k <= D; ++k) {
        const unsigned i0 = k > D - d ? k - (D - d) : 0, i1 = (std::min)(k, d);
        IT sum = unit[k * (d + 1) + i0] ? b[o + in + i0 * st] : E[k * (d + 1) + i0] * b[o + in + i0 * st];
        for (unsigned i = i0 + 1; i <= i1; ++i)
          sum = sum + (unit[k * (d + 1) + i] ? b[o + in + i * st] : E[k * (d + 1) + i] * b[o + in + i * st]);
        out[ot + in + k * st] = sum;
      }
  return out;
}

// The array of `b` (shape `from`) written over the variables and degrees of `to` (a superset
// of `from`'s variables with degrees at least as high): missing variables are constant,
// lower degrees elevated.
template <class IT>
std::vector<IT> embed(const Tensor_shape& from, const std::vector<IT>& b, const Tensor_shape& to)
{
  // first: insert the missing variables with degree 0 (same data, new shape)
  std::vector<unsigned> degs(to.variables.size(), 0);
  for (std::size_t k = 0; k < from.variables.size(); ++k) degs[to.local(from.variables[k])] = from.degrees[k];
  Tensor_shape cur;
  cur.set(to.variables, degs);
  std::vector<IT> a = b;  // same linear order: degree-0 axes do not change the index
  for (std::size_t k = 0; k < to.variables.size(); ++k) {
    if (cur.degrees[k] == to.degrees[k]) continue;
    std::vector<unsigned> nd = cur.degrees;
    nd[k] = to.degrees[k];
    Tensor_shape next;
    next.set(to.variables, nd);
    a = elevate_axis(cur, a, k, next);
    cur = next;
  }
  return a;
}

// Value of a power-basis tensor at a point (one interval per local variable), Horner per axis.
template <class T>
T horner(const Tensor_shape& s, const std::vector<T>& a, const std::vector<T>& x)
{
  // contract the last axis first
  std::vector<T> cur = a;
  std::size_t size = s.size;
  for (std::size_t j = s.variables.size(); j-- > 0;) {
    const unsigned d = s.degrees[j];
    const std::size_t n = size / (d + 1);
    std::vector<T> next(n, T(0));
    for (std::size_t o = 0; o < n; ++o) {
      T v = cur[o * (d + 1) + d];
      for (unsigned i = d; i-- > 0;) v = v * x[j] + cur[o * (d + 1) + i];
      next[o] = v;
    }
    cur.swap(next);
    size = n;
  }
  return cur.empty() ? T(0) : cur[0];
}

// Does the array have a strict sign (every coefficient > 0, or every one < 0)?
template <class IT> bool strict_sign(const std::vector<IT>& b)
{
  typedef Interval_ops<IT> O;
  bool pos = true, neg = true;
  for (const IT& x : b) {
    if (!(O::lower(x) > 0)) pos = false;
    if (!(O::upper(x) < 0)) neg = false;
    if (!pos && !neg) return false;
  }
  return true;
}

// Projected-polyhedron clipping along local axis j: the parameter range [tu, tv] in [0, 1]
// outside of which the convex hull of the control points (i/d, b_i) cannot meet zero.
// Returns false if it cannot meet zero at all (no root in the box).
// The clip of one axis, from the lowest and highest coefficient per index (d + 1 each).
inline bool clip_polygon(unsigned d, const double* mn, const double* mx, double& tu, double& tv)
{
  if (d == 0) { tu = 0; tv = 1; return mn[0] <= 0 && mx[0] >= 0; }
  // crossings of the zero axis by segments between a point <= 0 and a point >= 0 (upward
  // rounding is set by the caller for Interval_nt; the interval type keeps the crossing safe)
  typedef CGAL::Interval_nt<false> D;
  typename D::Protector protect;
  bool any = false;
  double lo = 1, hi = 0;
  auto take = [&](double t1, double y1, double t2, double y2) {
    // y1 <= 0 <= y2
    D t;
    if (y1 == y2) t = D((std::min)(t1, t2), (std::max)(t1, t2));
    else t = D(t1) + (D(t2) - D(t1)) * (D(0) - D(y1)) / (D(y2) - D(y1));
    lo = (std::min)(lo, t.inf());
    hi = (std::max)(hi, t.sup());
    any = true;
  };
  for (unsigned i = 0; i <= d; ++i) {
    double ti = double(i) / d;
    if (mn[i] <= 0 && mx[i] >= 0) take(ti, 0, ti, 0);
    for (unsigned k = 0; k <= d; ++k) {
      if (k == i) continue;
      double tk = double(k) / d;
      if (mn[i] <= 0 && mx[k] >= 0) take(ti, mn[i], tk, mx[k]);
      if (mn[i] <= 0 && mn[k] >= 0) take(ti, mn[i], tk, mn[k]);
      if (mx[i] <= 0 && mx[k] >= 0) take(ti, mx[i], tk, mx[k]);
      if (mx[i] <= 0 && mn[k] >= 0) take(ti, mx[i], tk, mn[k]);
    }
  }
  if (!any) return false;
  // i/d is rounded: widen by a few ulps of 1
  tu = (std::max)(0.0, lo - 4e-16);
  tv = (std::min)(1.0, hi + 4e-16);
  return true;
}

// The projected control polygon of every axis at once (one pass over the array): for each
// axis j and index i_j, the lowest and highest coefficient with that index. Then, per axis,
// the part [tu, tv] of [0, 1] outside of which the convex hull of the control points
// (i/d, b_i) cannot meet zero. Returns false if it cannot meet zero at all (no root in the
// box). tu and tv get one entry per local axis.
template <class IT> bool clip_axes(const Tensor_shape& s, const std::vector<IT>& b, std::vector<double>& tu, std::vector<double>& tv)
{
  const std::size_t k = s.degrees.size();
  tu.assign(k, 0.0);
  tv.assign(k, 1.0);
  // the bounds as doubles once; then per axis and index, strided min and max (contiguous
  // runs of the later axes)
  std::vector<double> L(s.size), H(s.size);
  double all_lo = std::numeric_limits<double>::infinity(), all_hi = -all_lo;
  for (std::size_t a = 0; a < s.size; ++a) {
    L[a] = Interval_ops<IT>::lower_double(b[a]);
    H[a] = Interval_ops<IT>::upper_double(b[a]);
    all_lo = (std::min)(all_lo, L[a]);
    all_hi = (std::max)(all_hi, H[a]);
  }
  if (!(all_lo <= 0 && all_hi >= 0)) return false;
  std::vector<double> mn, mx;
  for (std::size_t j = 0; j < k; ++j) {
    const unsigned d = s.degrees[j];
    const std::size_t st = s.strides[j], block = st * (d + 1);
    mn.assign(d + 1, std::numeric_limits<double>::infinity());
    mx.assign(d + 1, -std::numeric_limits<double>::infinity());
    for (unsigned i = 0; i <= d; ++i) {
      double m = mn[i], M = mx[i];
      for (std::size_t outer = i * st; outer < s.size; outer += block)
        for (std::size_t in = 0; in < st; ++in) {
          m = (std::min)(m, L[outer + in]);
          M = (std::max)(M, H[outer + in]);
        }
      mn[i] = m;
      mx[i] = M;
    }
    if (!clip_polygon(d, mn.data(), mx.data(), tu[j], tv[j])) return false;
  }
  return true;
}

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif
