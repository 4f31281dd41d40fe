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
#include <cmath>
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

// The binomial coefficient C(n, k) in doubles: exact for n <= 50 (every partial product
// C(n - k + t, t) t stays below 2^53), rounded above; use binomial_enclosure() there.
inline double binomial(unsigned n, unsigned k)
{
  double r = 1;
  for (unsigned t = 1; t <= k; ++t) r = r * (n - k + t) / t;
  return r;
}

// C(n, k) as an interval that contains it: the exact double up to n = 50, above it the
// product of the factors (n - k + t) / t in outward-rounded interval arithmetic.
template <class IT> IT binomial_enclosure(unsigned n, unsigned k)
{
  if (n <= 50) return IT(binomial(n, k));
  IT r(1);
  for (unsigned t = 1; t <= k; ++t) r = r * IT(double(n - k + t)) / IT(double(t));
  return r;
}

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
  std::vector<IT> f, ratio;
  for (std::size_t j = 0; j < s.variables.size(); ++j) {
    const unsigned d = s.degrees[j];
    if (d == 0) continue;
    const std::size_t st = s.strides[j];
    // C(i, k) / C(d, k), row i: one division where it is not 1 (the solver converts small
    // arrays on every box of a system with interval coefficients)
    ratio.resize((d + 1) * (d + 1));
    for (unsigned i = 0; i <= d; ++i)
      for (unsigned k = 0; k <= i; ++k) {
        // (binomial() is exact up to degree 50; above, binomial_ratio() encloses the ratio)
        ratio[i * (d + 1) + k] = k == 0 || i == d ? IT(1) : d <= 50 ? IT(binomial(i, k)) / IT(binomial(d, k)) : binomial_ratio<IT>(i, k, d);
      }
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
        for (unsigned k = 0; k <= i; ++k) b = b + ratio[i * (d + 1) + k] * f[k];
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
  const unsigned d = s.degrees[j];
  if (d == 0) { left = b; right = b; return; }
  // every entry of both halves is written below
  left.resize(b.size());
  right.resize(b.size());
  const std::size_t st = s.strides[j];
  const IT u = IT(1) - t;
  const bool half = Interval_ops<IT>::lower(t) == Interval_ops<IT>::upper(t) && Interval_ops<IT>::to_double(Interval_ops<IT>::lower(t)) == 0.5;
  IT w[64];
  std::vector<IT> wv;
  IT* wp = d < 64 ? w : (wv.resize(d + 1), wv.data());
  s.for_each_fiber(j, [&](std::size_t base) {
    for (unsigned i = 0; i <= d; ++i) wp[i] = b[base + i * st];
    left[base] = wp[0];
    right[base + d * st] = wp[d];
    for (unsigned r = 1; r <= d; ++r) {
      if (half) for (unsigned i = 0; i + r <= d; ++i) wp[i] = Interval_ops<IT>::half_sum(wp[i], wp[i + 1]);
      else for (unsigned i = 0; i + r <= d; ++i) wp[i] = u * wp[i] + t * wp[i + 1];
      left[base + r * st] = wp[0];
      right[base + (d - r) * st] = wp[d - r];
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

// How to write an array of shape `from` over the variables and degrees of `to` (a superset
// of `from`'s variables with degrees at least as high): missing variables are constant (their
// axis is inserted with degree 0, which leaves the linear order unchanged), lower degrees are
// elevated one axis at a time. The elevation weights are enclosed once, when the plan is made.
template <class IT> class Embedding
{
  struct Step
  {
    Tensor_shape from, to;
    std::size_t axis;
    std::vector<IT> weight;   // (D + 1) x (d + 1): b'_k = sum_i weight[k][i] b_i
    std::vector<char> unit;   // the weight is exactly 1
  };
  std::vector<Step> steps_;

public:
  Embedding() {}
  Embedding(const Tensor_shape& from, const Tensor_shape& to)
  {
    std::vector<unsigned> degs(to.variables.size(), 0);
    for (std::size_t k = 0; k < from.variables.size(); ++k) degs[to.local(from.variables[k])] = from.degrees[k];
    Tensor_shape cur;
    cur.set(to.variables, degs);
    for (std::size_t k = 0; k < to.variables.size(); ++k) {
      if (cur.degrees[k] == to.degrees[k]) continue;
      Step st;
      st.from = cur;
      std::vector<unsigned> nd = cur.degrees;
      nd[k] = to.degrees[k];
      st.to.set(to.variables, nd);
      st.axis = k;
      // degree elevation d -> D in one step: b'_k = sum_i C(d, i) C(D - d, k - i) / C(D, k) b_i
      const unsigned d = cur.degrees[k], D = to.degrees[k];
      st.weight.assign((D + 1) * (d + 1), IT(0));
      st.unit.assign((D + 1) * (d + 1), 0);
      for (unsigned q = 0; q <= D; ++q)
        for (unsigned i = 0; i <= d && i <= q; ++i) {
          if (q - i > D - d) continue;
          st.weight[q * (d + 1) + i] = binomial_enclosure<IT>(d, i) * binomial_enclosure<IT>(D - d, q - i) / binomial_enclosure<IT>(D, q);
          // by Vandermonde's identity the weights of row q sum to 1: one term is 1 exactly
          // when it is the row's only one (q = 0, q = D, or d = 0)
          const unsigned i0 = q > D - d ? q - (D - d) : 0, i1 = (std::min)(q, d);
          st.unit[q * (d + 1) + i] = i0 == i1;
        }
      cur = st.to;
      steps_.push_back(std::move(st));
    }
  }
  // `out` gets the array of `b` over the target shape; `scratch` is a work buffer.
  void apply(const std::vector<IT>& b, std::vector<IT>& out, std::vector<IT>& scratch) const
  {
    if (steps_.empty()) { out = b; return; }
    const std::vector<IT>* src = &b;
    for (std::size_t t = 0; t < steps_.size(); ++t) {
      const Step& st = steps_[t];
      // the last step writes `out`; the others alternate between `out` and `scratch` so that
      // source and target never coincide
      std::vector<IT>& dst = ((steps_.size() - 1 - t) % 2 == 0) ? out : scratch;
      const unsigned d = st.from.degrees[st.axis], D = st.to.degrees[st.axis];
      const std::size_t s = st.from.strides[st.axis];  // the axes after it keep their degrees
      const std::size_t bf = s * (d + 1), bt = s * (D + 1);
      dst.resize(st.to.size);
      for (std::size_t o = 0, ot = 0; o < st.from.size; o += bf, ot += bt)
        for (unsigned q = 0; q <= D; ++q) {
          const unsigned i0 = q > D - d ? q - (D - d) : 0, i1 = (std::min)(q, d);
          for (std::size_t in = 0; in < s; ++in) {
            const IT* x = &(*src)[o + in];
            IT sum = st.unit[q * (d + 1) + i0] ? x[i0 * s] : st.weight[q * (d + 1) + i0] * x[i0 * s];
            for (unsigned i = i0 + 1; i <= i1; ++i)
              sum = sum + (st.unit[q * (d + 1) + i] ? x[i * s] : st.weight[q * (d + 1) + i] * x[i * s]);
            dst[ot + in + q * s] = sum;
          }
        }
      src = &dst;
    }
  }
};

// The array of `b` (shape `from`) written over the variables and degrees of `to`.
template <class IT>
std::vector<IT> embed(const Tensor_shape& from, const std::vector<IT>& b, const Tensor_shape& to)
{
  std::vector<IT> out, scratch;
  Embedding<IT>(from, to).apply(b, out, scratch);
  return out;
}

// Value of a power-basis tensor at a point (one interval per local variable), Horner per axis.
// (`cur` is a work buffer.)
template <class T>
T horner(const Tensor_shape& s, const std::vector<T>& a, const std::vector<T>& x, std::vector<T>& cur)
{
  if (s.variables.empty()) return a.empty() ? T(0) : a[0];
  // contract the last axis first; after the first contraction in place (group o is read
  // before index o <= o * (d + 1) is written)
  std::size_t size = s.size;
  for (std::size_t j = s.variables.size(); j-- > 0;) {
    const unsigned d = s.degrees[j];
    const std::size_t n = size / (d + 1);
    const bool first = size == s.size;
    const T* src = first ? a.data() : cur.data();
    if (first) cur.resize(n);
    for (std::size_t o = 0; o < n; ++o) {
      T v = src[o * (d + 1) + d];
      for (unsigned i = d; i-- > 0;) v = v * x[j] + src[o * (d + 1) + i];
      cur[o] = v;
    }
    size = n;
  }
  return cur[0];
}
template <class T>
T horner(const Tensor_shape& s, const std::vector<T>& a, const std::vector<T>& x)
{
  std::vector<T> cur;
  return horner(s, a, x, cur);
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
  // crossings of the zero axis by segments between a point <= 0 and a point >= 0, in plain
  // double: t1 + (t2 - t1) * (-y1) / (y2 - y1) with 0 <= -y1 <= y2 - y1 is off by a few units
  // in the last place of 1 in any rounding mode, so widening each crossing by 2e-15 (and the
  // i/d rounding with it) keeps the clip safe without switching the rounding mode
  bool any = false;
  double lo = 1, hi = 0;
  auto take = [&](double t1, double y1, double t2, double y2) {
    // y1 <= 0 <= y2
    double a = t1, b = t2;
    const double den = y2 - y1;
    if (y1 != y2 && std::isfinite(den) && den > 0) a = b = t1 + (t2 - t1) * ((-y1) / den);
    lo = (std::min)(lo, (std::min)(a, b));
    hi = (std::max)(hi, (std::max)(a, b));
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
  tu = (std::max)(0.0, lo - 2e-15);
  tv = (std::min)(1.0, hi + 2e-15);
  return true;
}

// Work buffers of clip_axes, kept between calls.
struct Clip_workspace
{
  std::vector<double> L, H, mn, mx, buffer;
  std::size_t used = 0;
};

// The projected control polygons' extremes: for each axis j of a dense tensor (extents
// dims[0..k), last axis fastest) and index i, mn[j][i] = the least L over the entries whose
// j-th index is i, mx[j][i] = the largest H. Halving the axes: the least over the later half's
// block (contiguous) gives the earlier half's tensor, the least over the earlier half's
// indices (contiguous rows) the later half's; about 2 passes over the data instead of k.
inline void marginal_extremes(const double* L, const double* H, const std::size_t* dims, std::size_t k, double* const* mn,
                              double* const* mx, Clip_workspace& w)
{
  if (k == 1) {
    for (std::size_t i = 0; i < dims[0]; ++i) { mn[0][i] = L[i]; mx[0][i] = H[i]; }
    return;
  }
  const std::size_t h = k / 2;
  std::size_t P = 1, S = 1;
  for (std::size_t j = 0; j < h; ++j) P *= dims[j];
  for (std::size_t j = h; j < k; ++j) S *= dims[j];
  double* BL = w.buffer.data() + w.used;
  double* BH = BL + P;
  double* CL = BH + P;
  double* CH = CL + S;
  w.used += 2 * (P + S);
  for (std::size_t t = 0; t < S; ++t) { CL[t] = L[t]; CH[t] = H[t]; }
  for (std::size_t o = 0; o < P; ++o) {
    const double* l = L + o * S;
    const double* u = H + o * S;
    double m = l[0], M = u[0];
    for (std::size_t t = 0; t < S; ++t) {
      m = (std::min)(m, l[t]);
      M = (std::max)(M, u[t]);
      CL[t] = (std::min)(CL[t], l[t]);
      CH[t] = (std::max)(CH[t], u[t]);
    }
    BL[o] = m;
    BH[o] = M;
  }
  marginal_extremes(BL, BH, dims, h, mn, mx, w);
  marginal_extremes(CL, CH, dims + h, k - h, mn + h, mx + h, w);
}

// The projected control polygon of every axis: per axis, the part [tu, tv] of [0, 1] outside
// of which the convex hull of the control points (i/d, b_i) cannot meet zero. Returns false if
// it cannot meet zero at all (no root in the box). tu and tv get one entry per local axis. L
// and H are the coefficients' lower and upper bounds.
inline bool clip_bounds(const Tensor_shape& s, const double* L, const double* H, std::vector<double>& tu, std::vector<double>& tv,
                        Clip_workspace& w)
{
  const std::size_t k = s.degrees.size();
  tu.assign(k, 0.0);
  tv.assign(k, 1.0);
  if (k == 0) return L[0] <= 0 && H[0] >= 0;
  std::size_t total = 0, dims[64];
  std::vector<std::size_t> dimv;
  std::size_t* d = k <= 64 ? dims : (dimv.resize(k), dimv.data());
  for (std::size_t j = 0; j < k; ++j) { d[j] = s.degrees[j] + 1; total += d[j]; }
  w.mn.resize(total);
  w.mx.resize(total);
  double* mnp[64];
  double* mxp[64];
  std::vector<double*> mnv, mxv;
  double** mn = k <= 64 ? mnp : (mnv.resize(k), mnv.data());
  double** mx = k <= 64 ? mxp : (mxv.resize(k), mxv.data());
  for (std::size_t j = 0, o = 0; j < k; o += d[j], ++j) { mn[j] = w.mn.data() + o; mx[j] = w.mx.data() + o; }
  // each level of the halving takes at most 2 (size + 1) doubles
  std::size_t levels = 1;
  while ((std::size_t(1) << levels) < k) ++levels;
  if (w.buffer.size() < 2 * (s.size + 1) * (levels + 1)) w.buffer.resize(2 * (s.size + 1) * (levels + 1));
  w.used = 0;
  marginal_extremes(L, H, d, k, mn, mx, w);
  double all_lo = std::numeric_limits<double>::infinity(), all_hi = -all_lo;
  for (std::size_t i = 0; i < d[0]; ++i) { all_lo = (std::min)(all_lo, mn[0][i]); all_hi = (std::max)(all_hi, mx[0][i]); }
  if (!(all_lo <= 0 && all_hi >= 0)) return false;
  for (std::size_t j = 0; j < k; ++j)
    if (!clip_polygon(s.degrees[j], mn[j], mx[j], tu[j], tv[j])) return false;
  return true;
}

// The same on an array of intervals.
template <class IT>
bool clip_axes(const Tensor_shape& s, const std::vector<IT>& b, std::vector<double>& tu, std::vector<double>& tv, Clip_workspace& w)
{
  w.L.resize(s.size);
  w.H.resize(s.size);
  for (std::size_t a = 0; a < s.size; ++a) {
    w.L[a] = Interval_ops<IT>::lower_double(b[a]);
    w.H[a] = Interval_ops<IT>::upper_double(b[a]);
  }
  return clip_bounds(s, w.L.data(), w.H.data(), tu, tv, w);
}

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif
