// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The few interval operations the subdivision solver needs, one adapter for
// CGAL::Interval_nt<false> (double bounds, the FPU rounding mode set upward by the caller) and
// one for CGAL::Gmpfi (Gmpfr bounds, MPFR's own directed rounding at the default precision).

#ifndef CGAL_RIGID_INCIDENCE_INTERNAL_INTERVAL_OPS_H
#define CGAL_RIGID_INCIDENCE_INTERNAL_INTERVAL_OPS_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Interval_traits.h>
#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#endif

#include <cmath>
#include <type_traits>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

template <class IT> struct Interval_ops;

template <bool P> struct Interval_ops<CGAL::Interval_nt<P>>
{
  typedef CGAL::Interval_nt<P> I;
  typedef double Bound;
  static const bool multiprecision = false;
  static double lower(const I& x) { return x.inf(); }
  static double upper(const I& x) { return x.sup(); }
  static I make(double lo, double hi) { return I(lo, hi); }
  static I point(double b) { return I(b); }
  static double to_double(double b) { return b; }
  static double lower_double(const I& x) { return x.inf(); }
  static double upper_double(const I& x) { return x.sup(); }
  static Bound bound_from_double(double d) { return d; }
  // an enclosure of the coefficient c
  template <class NT> static I from(const NT& c)
  {
    if constexpr (std::is_same<NT, double>::value) return I(c);
    else return I(CGAL::to_interval(c));
  }
  // precision of the bounds, in bits
  static unsigned bits() { return 53; }
  // can [lo, hi] still be split in two nonempty intervals of representable bounds?
  static bool splittable(double lo, double hi)
  {
    double m = 0.5 * lo + 0.5 * hi;
    return m > lo && m < hi;
  }
  // (a + b) / 2 (the rounding upward: the lower bound is negated, halved, negated back, so
  // that a halving that underflows still rounds outward)
  static I half_sum(const I& a, const I& b)
  {
    if constexpr (P) return (a + b) / 2;
    else {
      const I s = a + b;
      return I(-((-s.inf()) * 0.5), s.sup() * 0.5);
    }
  }
};

#ifdef CGAL_USE_MPFI
template <> struct Interval_ops<CGAL::Gmpfi>
{
  typedef CGAL::Gmpfi I;
  typedef CGAL::Gmpfr Bound;
  static const bool multiprecision = true;
  static Bound lower(const I& x) { return x.inf(); }
  static Bound upper(const I& x) { return x.sup(); }
  static I make(const Bound& lo, const Bound& hi) { return I(lo, hi); }
  static I point(const Bound& b) { return I(b); }
  static double to_double(const Bound& b) { return CGAL::to_double(b); }
  static double lower_double(const I& x) { return CGAL::to_interval(x).first; }
  static double upper_double(const I& x) { return CGAL::to_interval(x).second; }
  static Bound bound_from_double(double d) { return Bound(d, std::max<long>(53, long(I::get_default_precision()))); }
  template <class NT> static I from(const NT& c)
  {
    if constexpr (std::is_same<NT, CGAL::Interval_nt<false>>::value || std::is_same<NT, CGAL::Interval_nt<true>>::value)
      return I(Bound(c.inf(), 53), Bound(c.sup(), 53));
    else return I(c);
  }
  static unsigned bits() { return unsigned(I::get_default_precision()); }
  static I half_sum(const I& a, const I& b) { return (a + b) / 2; }
  static bool splittable(const Bound& lo, const Bound& hi)
  {
    I m = (I(lo) + I(hi)) / 2;
    return m.inf() > lo && m.inf() < hi;
  }
};
#endif

// Sets what the interval type needs for the length of a solve: the FPU rounding mode for
// Interval_nt, the default MPFR precision for Gmpfi.
template <class IT> struct Solver_precision_guard
{
  typename IT::Protector protect;
  explicit Solver_precision_guard(unsigned) {}
};
#ifdef CGAL_USE_MPFI
template <> struct Solver_precision_guard<CGAL::Gmpfi>
{
  CGAL::Gmpfi::Precision_type old;
  explicit Solver_precision_guard(unsigned bits) : old(CGAL::Gmpfi::set_default_precision(bits < 2 ? 2 : bits)) {}
  ~Solver_precision_guard() { CGAL::Gmpfi::set_default_precision(old); }
};
#endif

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif
