// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Exact reading of number text: decimals with exponent, rationals p/q, integers.
// Nothing passes through a binary double, so "0.1" is exactly 1/10.

#ifndef CGAL_RIGID_INCIDENCE_INTERNAL_PARSE_NUMBER_H
#define CGAL_RIGID_INCIDENCE_INTERNAL_PARSE_NUMBER_H

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include <cctype>
#include <cstdlib>
#include <string>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

// Exponents beyond this are refused: 10^1e9 would exhaust memory, and no scene needs it.
constexpr long max_decimal_exponent = 4000;

// Numbers with more significant digits than this (in a decimal's mantissa, or in p or q of a
// rational) are refused: a coordinate of ten million digits made every later exact operation
// crawl, and no measured scene needs more than a few dozen.
constexpr std::size_t max_number_digits = 10000;

// The number of significant digits of an unsigned digit string (leading zeros do not count).
inline std::size_t significant_digits(const std::string& digits)
{
  std::size_t nz = digits.find_first_not_of("0+-");
  return nz == std::string::npos ? 0 : digits.size() - nz;
}

inline std::string too_many_digits(std::size_t n, std::size_t max_digits)
{
  return std::to_string(n) + " significant digits, more than the " + std::to_string(max_digits) + " a number may have";
}

// Parses an optionally signed decimal "[-+]digits[.digits][(e|E)[-+]digits]" into q (as in
// JSON, digits on both sides of a decimal point). On failure returns false and sets why.
inline bool parse_decimal(const std::string& s, CGAL::Gmpq& q, std::string& why, std::size_t max_digits = max_number_digits)
{
  std::size_t i = 0, n = s.size();
  bool negative = false;
  if (i < n && (s[i] == '+' || s[i] == '-')) { negative = (s[i] == '-'); ++i; }
  std::string digits;
  long frac_digits = 0;
  std::size_t mantissa_digits = 0;
  while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) { digits += s[i++]; ++mantissa_digits; }
  if (mantissa_digits == 0) { why = "no digits before the decimal point"; return false; }
  if (i < n && s[i] == '.') {
    ++i;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) { digits += s[i++]; ++frac_digits; ++mantissa_digits; }
    if (frac_digits == 0) { why = "no digits after the decimal point"; return false; }
  }
  long exponent = 0;
  if (i < n && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    bool eneg = false;
    if (i < n && (s[i] == '+' || s[i] == '-')) { eneg = (s[i] == '-'); ++i; }
    std::size_t start = i;
    while (i < n && std::isdigit(static_cast<unsigned char>(s[i]))) {
      if (exponent > max_decimal_exponent * 10) { why = "exponent out of range"; return false; }
      exponent = exponent * 10 + (s[i++] - '0');
    }
    if (i == start) { why = "no digits in the exponent"; return false; }
    if (eneg) exponent = -exponent;
  }
  if (i != n) { why = "unexpected character '" + std::string(1, s[i]) + "'"; return false; }
  if (max_digits && significant_digits(digits) > max_digits) { why = too_many_digits(significant_digits(digits), max_digits); return false; }
  if (exponent > max_decimal_exponent || exponent < -max_decimal_exponent) {
    why = "exponent out of range (|e| <= " + std::to_string(max_decimal_exponent) + ")"; return false;
  }
  long e10 = exponent - frac_digits;
  // strip leading zeros so that mpz parsing is simple
  std::size_t nz = digits.find_first_not_of('0');
  digits = (nz == std::string::npos) ? std::string("0") : digits.substr(nz);
  CGAL::Gmpz mant(digits);
  CGAL::Gmpz ten(10), p(1);
  long ae = e10 < 0 ? -e10 : e10;
  mpz_pow_ui(p.mpz(), ten.mpz(), static_cast<unsigned long>(ae));
  if (e10 >= 0) q = CGAL::Gmpq(mant * p);
  else q = CGAL::Gmpq(mant, p);
  if (negative) q = -q;
  return true;
}

// Parses a number given as text: an integer, an exact decimal ("0.9", "-1.25e-3") or a
// rational "p/q" with integer p and q != 0, of at most `max_digits` significant digits (0: no
// limit). On failure returns false and sets why.
inline bool parse_exact_number(const std::string& text, CGAL::Gmpq& q, std::string& why,
                               std::size_t max_digits = max_number_digits)
{
  // surrounding white space is allowed, white space inside a number is not
  std::size_t first = 0, last = text.size();
  while (first < last && std::isspace(static_cast<unsigned char>(text[first]))) ++first;
  while (last > first && std::isspace(static_cast<unsigned char>(text[last - 1]))) --last;
  std::string s = text.substr(first, last - first);
  if (s.empty()) { why = "empty number"; return false; }
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower.find("nan") != std::string::npos) { why = "NaN is not a number"; return false; }
  if (lower.find("inf") != std::string::npos) { why = "infinite values are not allowed"; return false; }
  std::size_t slash = s.find('/');
  if (slash == std::string::npos) return parse_decimal(s, q, why, max_digits);
  std::string num = s.substr(0, slash), den = s.substr(slash + 1);
  auto is_int = [](const std::string& t) {
    std::size_t k = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
    if (k >= t.size()) return false;
    for (; k < t.size(); ++k) if (!std::isdigit(static_cast<unsigned char>(t[k]))) return false;
    return true;
  };
  if (!is_int(num) || !is_int(den)) { why = "a rational must be p/q with integers p and q"; return false; }
  for (const std::string* t : {&num, &den})
    if (max_digits && significant_digits(*t) > max_digits) { why = too_many_digits(significant_digits(*t), max_digits); return false; }
  auto strip_plus = [](const std::string& t) { return (t[0] == '+') ? t.substr(1) : t; };
  CGAL::Gmpz p(strip_plus(num)), d(strip_plus(den));
  if (d == 0) { why = "zero denominator"; return false; }
  q = CGAL::Gmpq(p, d);
  return true;
}

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif
