// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// internal::parse_exact_number against an independent oracle: random decimals written from an
// integer mantissa m and an exponent e in many textual forms must read as exactly m * 10^e,
// computed here with Gmpz multiplication only; fixed cases ("0.1" is 1/10, rationals, signs,
// huge digit strings); malformed texts are refused with a non-empty reason.

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Rigid_incidence/internal/parse_number.h>

#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace RIi = CGAL::Rigid_incidence::internal;

static int failures = 0, checks = 0;
#define CHECK(cond, msg)                                                              \
  do {                                                                                \
    ++checks;                                                                         \
    if (!(cond)) { ++failures; std::cerr << "FAIL line " << __LINE__ << ": " << msg << "\n"; } \
  } while (0)

// 10^k by repeated multiplication (independent of the parser's mpz_pow_ui).
static CGAL::Gmpz pow10(long k)
{
  CGAL::Gmpz r(1), ten(10);
  for (long i = 0; i < k; ++i) r *= ten;
  return r;
}

// m * 10^e as an exact rational.
static CGAL::Gmpq oracle(const CGAL::Gmpz& m, long e)
{
  if (e >= 0) return CGAL::Gmpq(m * pow10(e));
  return CGAL::Gmpq(m, pow10(-e));
}

static std::string show(const CGAL::Gmpq& q)
{
  std::ostringstream os;
  os << q;
  return os.str();
}

static void expect_value(const std::string& text, const CGAL::Gmpq& expected)
{
  CGAL::Gmpq q;
  std::string why;
  bool ok = RIi::parse_exact_number(text, q, why);
  CHECK(ok, "\"" << text.substr(0, 60) << "\" should parse, refused: " << why);
  if (ok) CHECK(q == expected, "\"" << text.substr(0, 60) << "\" read as " << show(q).substr(0, 80) << ", expected " << show(expected).substr(0, 80));
}

static void expect_refused(const std::string& text)
{
  CGAL::Gmpq q(12345);
  std::string why;
  bool ok = RIi::parse_exact_number(text, q, why);
  CHECK(!ok, "\"" << text.substr(0, 60) << "\" should be refused, read as " << show(q).substr(0, 80));
  if (!ok) CHECK(!why.empty(), "\"" << text.substr(0, 60) << "\" refused without a reason");
}

int main()
{
  std::mt19937_64 rng(20260101);
  auto uni = [&](long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); };

  // ---------------------------------------------------------------- random decimals
  // Mantissa: 1..40 random digits (leading zeros allowed); value m * 10^e written as
  // [sign] D[0:k] . D[k:] e (e + len - k), with random exponent spelling.
  for (int it = 0; it < 3000; ++it) {
    int len = int(uni(1, 40));
    std::string D;
    for (int i = 0; i < len; ++i) D += char('0' + uni(0, 9));
    bool negative = uni(0, 1) == 1;
    CGAL::Gmpz m(0);
    for (char c : D) m = m * CGAL::Gmpz(10) + CGAL::Gmpz(c - '0'); // oracle mantissa, digit by digit
    if (negative) m = -m;
    long e = uni(-60, 60);
    int k = int(uni(0, len));                 // digits before the point
    long written_e = e + (len - k);           // D[0:k].D[k:] * 10^written_e == D * 10^e
    std::string text;
    if (negative) text += "-";
    else if (uni(0, 3) == 0) text += "+";
    if (k == 0) text += "0." + D;             // "0.ddd" (not ".ddd")
    else if (k == len) text += D;             // integer mantissa, no point
    else text += D.substr(0, k) + "." + D.substr(k);
    int form = int(uni(0, 3));
    if (form == 0 && written_e == 0) {
      // no exponent at all
    } else {
      text += (uni(0, 1) ? "e" : "E");
      if (written_e < 0) text += "-";
      else if (uni(0, 1)) text += "+";
      long a = written_e < 0 ? -written_e : written_e;
      if (uni(0, 4) == 0) text += "00";         // leading zeros in the exponent
      text += std::to_string(a);
    }
    expect_value(text, oracle(m, e));
  }

  // ---------------------------------------------------------------- random rationals p/q
  for (int it = 0; it < 500; ++it) {
    long p = uni(-1000000000L, 1000000000L), d = uni(1, 1000000000L);
    bool neg_den = uni(0, 3) == 0;
    std::string text = std::to_string(p) + "/" + (neg_den ? "-" : "") + std::to_string(d);
    CGAL::Gmpq expected(CGAL::Gmpz(p), CGAL::Gmpz(neg_den ? -d : d));
    expect_value(text, expected);
    // oracle cross-check: expected * d == p (with sign)
    CHECK(expected * CGAL::Gmpq(CGAL::Gmpz(neg_den ? -d : d)) == CGAL::Gmpq(CGAL::Gmpz(p)), "oracle p/q");
  }

  // ---------------------------------------------------------------- fixed cases
  expect_value("0.1", CGAL::Gmpq(1, 10));
  expect_value("0.9", CGAL::Gmpq(9, 10));
  expect_value("-1.25e-3", CGAL::Gmpq(-1, 800));
  expect_value("3/7", CGAL::Gmpq(3, 7));
  expect_value("-6/14", CGAL::Gmpq(-3, 7));
  expect_value("+2", CGAL::Gmpq(2));
  expect_value("1E+2", CGAL::Gmpq(100));
  expect_value("1e2", CGAL::Gmpq(100));
  expect_value("0", CGAL::Gmpq(0));
  expect_value("-0", CGAL::Gmpq(0));
  expect_value("-0.0e-7", CGAL::Gmpq(0));
  expect_value("007", CGAL::Gmpq(7));
  expect_value("  -2.5\t", CGAL::Gmpq(-5, 2)); // surrounding white space is allowed (not inside a number)
  expect_value("12.5e-1", CGAL::Gmpq(5, 4));
  expect_value("5.638967899459325029363689663400",
               CGAL::Gmpq(CGAL::Gmpz("5638967899459325029363689663400"), pow10(30)));
  // beyond 64 bits
  {
    CGAL::Gmpz two64(1);
    for (int i = 0; i < 64; ++i) two64 *= CGAL::Gmpz(2);
    expect_value("18446744073709551616", CGAL::Gmpq(two64));
    expect_value("-18446744073709551617", CGAL::Gmpq(-(two64 + CGAL::Gmpz(1))));
  }
  // huge digit strings: 300 digits
  {
    std::string ones(300, '1'), big = "1" + std::string(299, '0');
    expect_value(big, CGAL::Gmpq(pow10(299)));
    CGAL::Gmpz r(0);
    for (int i = 0; i < 300; ++i) r = r * CGAL::Gmpz(10) + CGAL::Gmpz(1);
    expect_value(ones, CGAL::Gmpq(r));
    expect_value("0." + ones, CGAL::Gmpq(r, pow10(300)));
    expect_value("-" + ones + "e-300", CGAL::Gmpq(-r, pow10(300)));
    expect_value(ones + "/" + big, CGAL::Gmpq(r, pow10(299)));
    expect_value("1e300", CGAL::Gmpq(pow10(300)));
    expect_value("1e-300", CGAL::Gmpq(CGAL::Gmpz(1), pow10(300)));
  }
  // the exponent limit itself is accepted, one more is refused
  {
    long lim = RIi::max_decimal_exponent;
    expect_value("1e" + std::to_string(lim), CGAL::Gmpq(pow10(lim)));
    expect_value("1e-" + std::to_string(lim), CGAL::Gmpq(CGAL::Gmpz(1), pow10(lim)));
    expect_refused("1e" + std::to_string(lim + 1));
    expect_refused("1e-" + std::to_string(lim + 1));
  }

  // the digit limit (a coordinate of ten million digits made every exact operation crawl):
  // max_number_digits significant digits are accepted, one more is refused, in a decimal's
  // mantissa and in either part of a rational; leading zeros do not count
  {
    const std::size_t lim = RIi::max_number_digits;
    const std::string nines(lim, '9');
    CGAL::Gmpz n9(0);
    mpz_ui_pow_ui(n9.mpz(), 10, lim);
    n9 -= CGAL::Gmpz(1);
    expect_value(nines, CGAL::Gmpq(n9));
    expect_value("000" + nines, CGAL::Gmpq(n9));
    expect_value("0." + nines, CGAL::Gmpq(n9, pow10(long(lim))));
    expect_value("1/" + nines, CGAL::Gmpq(CGAL::Gmpz(1), n9));
    expect_refused(nines + "9");
    expect_refused("1." + nines);
    expect_refused("-" + nines + "9/7");
    expect_refused("7/" + nines + "9");
    CGAL::Gmpq q;
    std::string why;
    CHECK(!RIi::parse_exact_number("1." + nines, q, why) && why.find("significant digits") != std::string::npos,
          "the digit limit's reason: " << why);
    CHECK(RIi::parse_exact_number("1." + nines, q, why, 0), "no digit limit with max_digits = 0: " << why);
  }

  // ---------------------------------------------------------------- refused
  const std::vector<std::string> bad = {
    "", "1.", ".", "1e", "abc", "1/0", "1/2/3", "NaN", "nan", "-nan", "inf", "Infinity", "-Infinity", "+inf",
    "1e99999", "1e-99999", "1e999999999999999999999999", "0x10", " 1 2", "1 2", "1 .5", "- 1", "1e 2",
    "--1", "+-1", "1e+", "1e-", "e5", "/2", "2/", "1.5/2", "1/2.5", "1,5", "1..2", "1.2.3", "1e2.5",
    "0b101", "1_000", "\xc2\xbd", "1/", "/", "+", "-", "1d", "1f", "true", "null", "[1]", "\"1\""};
  for (const auto& s : bad) expect_refused(s);

  std::cout << "test_parse_number: " << checks << " checks, " << failures << " failures\n";
  return failures == 0 ? 0 : 1;
}
