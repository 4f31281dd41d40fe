// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// read_polynomial_system (PHCpack's input format with box and inequality directives) against
// independent oracles: polynomials built here term by term with Sparse_polynomial (exact
// equality of the term maps); exact decimal values written as fractions ("0.1" is 1/10);
// expansion of parentheses checked by evaluating, at rational points, the unexpanded expression
// computed here with Gmpq arithmetic, and (1 + x)^10 against binomial coefficients; random
// polynomials written in many spellings and read back; the variable order by first appearance;
// the "n m" header; box bounds rounded outward (checked with nextafter) and inequalities; a
// PHCpack file with TITLE, ROOT COUNTS and THE SOLUTIONS sections; every malformed input
// refused with an Input_error "SOURCE:LINE: message" naming the right line; random mutations
// of a valid file never crash.

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Rigid_incidence/IO/read_polynomial_system.h>

#include "test_check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Gmpq Q;
typedef RI::Sparse_polynomial<Q> P;

static bool verbose = false; // -v: print every rejection message

// ------------------------------------------------------------------------------ helpers

static RI::Polynomial_system_file read_text(const std::string& text, const std::string& source = "mem")
{
  std::istringstream in(text);
  return RI::read_polynomial_system(in, source);
}

// Reads `text`; on an exception, reports it and returns false.
static bool try_read(const std::string& text, RI::Polynomial_system_file& out, const std::string& what)
{
  try {
    out = read_text(text);
    return true;
  } catch (const std::exception& e) {
    CHECK(false, what << ": refused: " << e.what());
  }
  return false;
}

static std::string show(const P& p, const std::vector<std::string>& names)
{
  std::ostringstream os;
  p.write(os, names);
  std::string s = os.str();
  return s.size() > 300 ? s.substr(0, 300) + "..." : s;
}

// The variable x_i (of n) and constants, to build the expected polynomials.
static P var(std::size_t n, std::size_t i) { return P::variable(n, i); }
static P cst(std::size_t n, const Q& c) { return P::constant(n, c); }
static bool same(const P& a, const P& b)
{
  return a.number_of_variables() == b.number_of_variables() && a.terms() == b.terms();
}

static Q pw(const Q& x, int k)
{
  Q r(1);
  for (int i = 0; i < k; ++i) r = r * x;
  return r;
}

// ------------------------------------------------------------------------------ accepted inputs

static void test_basic()
{
  RI::Polynomial_system_file f;
  if (!try_read("2\n x^2 + y^2 - 1;\n x - y;\n", f, "basic")) return;
  const auto& s = f.system;
  CHECK(s.variable_names == std::vector<std::string>({"x", "y"}), "basic: variables");
  CHECK(s.number_of_equations() == 2, "basic: 2 equations");
  if (s.number_of_equations() != 2 || s.number_of_variables() != 2) return;
  P x = var(2, 0), y = var(2, 1);
  CHECK(same(s.equations[0], x * x + y * y - cst(2, 1)), "basic: equation 1 is " << show(s.equations[0], s.variable_names));
  CHECK(same(s.equations[1], x - y), "basic: equation 2 is " << show(s.equations[1], s.variable_names));
  CHECK(s.labels == std::vector<std::string>({"equation 1", "equation 2"}), "basic: labels");
  CHECK(s.box.size() == 2 && s.box[0] == std::make_pair(-10.0, 10.0) && s.box[1] == std::make_pair(-10.0, 10.0),
        "basic: the default box is [-10, 10]");
  CHECK(f.default_box, "basic: default_box");
  CHECK(f.title.empty(), "basic: no title");
  CHECK(s.inequalities.empty() && s.inequality_labels.empty(), "basic: no inequalities");

  // polynomials spanning lines, several on a line, blank lines before the count, CRLF, BOM, tabs
  if (try_read("\xEF\xBB\xBF\r\n\r\n  2  \r\n x^2\r\n +\ty^2 -\r\n 1; x -\n\n y;", f, "layout")) {
    CHECK(f.system.variable_names == std::vector<std::string>({"x", "y"}), "layout: variables");
    if (f.system.number_of_equations() == 2 && f.system.number_of_variables() == 2) {
      CHECK(same(f.system.equations[0], x * x + y * y - cst(2, 1)), "layout: equation 1");
      CHECK(same(f.system.equations[1], x - y), "layout: equation 2");
    }
  }
}

static void test_numbers()
{
  // each number alone as the coefficient of x: the exact value as a fraction of integers
  struct Case { const char* text; Q value; };
  const std::vector<Case> cases = {
      {"0.1", Q(1, 10)},           {"1.5E-03", Q(3, 2000)},   {"2e4", Q(20000)},      {".5", Q(1, 2)},
      {"5.", Q(5)},                {"1.25e+2", Q(125)},       {"1E0", Q(1)},          {"007", Q(7)},
      {"2/3", Q(2, 3)},            {"-7/2", Q(-7, 2)},        {"0.000", Q(0)},        {"3.e-1", Q(3, 10)},
      {"123456789012345678901234567890", Q(CGAL::Gmpz("123456789012345678901234567890"))},
      {"4.22876985355001E-02", Q(CGAL::Gmpz("422876985355001"), CGAL::Gmpz("10000000000000000"))},
      {"1e-30", Q(CGAL::Gmpz(1), CGAL::Gmpz("1000000000000000000000000000000"))},
      {"1/3/4", Q(1, 12)},         {"2^10/1024", Q(1)},       {"-(-2)", Q(2)},        {"--2", Q(2)},
  };
  for (const auto& c : cases) {
    RI::Polynomial_system_file f;
    const std::string text = std::string("1\n") + c.text + "*x + x - x;\n";
    if (!try_read(text, f, std::string("number ") + c.text)) continue;
    P expected = c.value * var(1, 0);
    CHECK(same(f.system.equations[0], expected),
          "number " << c.text << ": read as " << show(f.system.equations[0], f.system.variable_names));
  }
  // 0.1 is 1/10, not the double nearest to 0.1
  RI::Polynomial_system_file f;
  if (try_read("1\n0.1*x;", f, "0.1")) {
    const Q c = f.system.equations[0].terms().begin()->second;
    CHECK(c == Q(1, 10) && c != Q(0.1), "0.1 is exactly 1/10");
  }
  // a whole fourbar-style equation: coefficients with 12 decimals and E-notation
  if (try_read("1 3\n0.01692601*X1**2*Y1**2 - 0.888509280014*X1**2*Y2**2\n+ 4.22876985355001E-02*X1**2;\n", f, "fourbar line")) {
    const auto& s = f.system;
    CHECK(s.variable_names == std::vector<std::string>({"X1", "Y1", "Y2"}), "fourbar line: variables");
    if (s.number_of_variables() == 3) {
      P X1 = var(3, 0), Y1 = var(3, 1), Y2 = var(3, 2);
      P e = Q(1692601, 100000000) * (X1 * X1 * Y1 * Y1) - Q(CGAL::Gmpz("888509280014"), CGAL::Gmpz("1000000000000")) * (X1 * X1 * Y2 * Y2) +
            Q(CGAL::Gmpz("422876985355001"), CGAL::Gmpz("10000000000000000")) * (X1 * X1);
      CHECK(same(s.equations[0], e), "fourbar line: " << show(s.equations[0], s.variable_names));
    }
  }
}

static void test_powers()
{
  RI::Polynomial_system_file a, b, c;
  if (!try_read("2\n x**3*y**2 - 2*x**(2) + y**0;\n (x + y)**3;\n", a, "**")) return;
  if (!try_read("2\n x^3*y^2 - 2*x^(2) + y^0;\n (x + y)^3;\n", b, "^")) return;
  if (!try_read("2\n x*x*x*y*y - 2*x*x + 1;\n x*x*x + 3*x*x*y + 3*x*y*y + y*y*y;\n", c, "products")) return;
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(same(a.system.equations[i], b.system.equations[i]), "'**' and '^' differ in equation " << i + 1);
    CHECK(same(a.system.equations[i], c.system.equations[i]), "'**' and repeated products differ in equation " << i + 1);
  }
  P x = var(2, 0), y = var(2, 1);
  CHECK(same(b.system.equations[0], x * x * x * y * y - Q(2) * (x * x) + cst(2, 1)), "powers: direct construction");
  // -x^2 is -(x^2); (-x)^2 is x^2; 0^0 is 1
  if (try_read("3 1\n -x^2;\n (-x)^2;\n 0^0 + x - x;\n", a, "signs and powers")) {
    P x1 = var(1, 0);
    CHECK(same(a.system.equations[0], Q(-1) * (x1 * x1)), "-x^2 is -(x^2)");
    CHECK(same(a.system.equations[1], x1 * x1), "(-x)^2 is x^2");
    CHECK(same(a.system.equations[2], cst(1, 1)), "0^0 is 1");
  }
}

// Expansion of parentheses: the parsed polynomial evaluated at rational points against the
// unexpanded expression evaluated here.
static void test_expansion()
{
  struct Case
  {
    std::string text;
    std::size_t nvars;
    std::function<Q(const std::vector<Q>&)> value; // in the order of first appearance
  };
  const Q third(1, 3), half(1, 2);
  std::vector<Case> cases = {
      {"(x - 2*y + 1/3)^3*(x + y) - (x*y - 1)*(2*x - y)**2 + -(x - y)/4", 2,
       [&](const std::vector<Q>& v) {
         const Q &x = v[0], &y = v[1];
         return pw(x - 2 * y + third, 3) * (x + y) - (x * y - 1) * pw(2 * x - y, 2) - (x - y) / 4;
       }},
      {"((x + 1)*(y - 1) - (x - 1)^2)^2 - 3*(x*(y*(x - y) + 1) - 2)", 2,
       [&](const std::vector<Q>& v) {
         const Q &x = v[0], &y = v[1];
         return pw((x + 1) * (y - 1) - pw(x - 1, 2), 2) - 3 * (x * (y * (x - y) + 1) - 2);
       }},
      {"-(-(x + y))*(z - 0.5)^2 - (x - y)*(y - z)*(z - x) + 2.5e-1*(x + y + z)^4/(1 + 2)", 3,
       [&](const std::vector<Q>& v) {
         const Q &x = v[0], &y = v[1], &z = v[2];
         return (x + y) * pw(z - half, 2) - (x - y) * (y - z) * (z - x) + Q(1, 4) * pw(x + y + z, 4) / 3;
       }},
      {"(a - b)*(a + b)*(a^2 + b^2)*(a^4 + b^4) - (a^8 - b^8) + ((a))", 2,
       [&](const std::vector<Q>& v) { return v[0]; }},
  };
  const std::vector<Q> samples = {Q(0), Q(1), Q(-1), Q(2, 3), Q(-5, 7), Q(3), Q(1, 10), Q(-11, 4), Q(13, 5)};
  for (std::size_t c = 0; c < cases.size(); ++c) {
    RI::Polynomial_system_file f;
    const std::string header = "1 " + std::to_string(cases[c].nvars) + "\n";
    if (!try_read(header + cases[c].text + ";\n", f, "expansion " + std::to_string(c))) continue;
    const P& p = f.system.equations[0];
    CHECK(p.number_of_variables() == cases[c].nvars, "expansion " << c << ": variables");
    if (p.number_of_variables() != cases[c].nvars) continue;
    for (int k = 0; k < 12; ++k) {
      std::vector<Q> pt;
      for (std::size_t i = 0; i < cases[c].nvars; ++i) pt.push_back(samples[(k * 5 + i * 7 + c) % samples.size()]);
      const Q got = p.evaluate(pt), expected = cases[c].value(pt);
      CHECK(got == expected, "expansion " << c << " at point " << k << ": " << got << " instead of " << expected);
    }
  }
  // (1 + x)^10 - (1 - x)^10 = 2 * sum over odd k of C(10, k) x^k (binomials by Pascal's triangle)
  RI::Polynomial_system_file f;
  if (try_read("1\n(1 + x)^10 - (1 - x)^10;\n", f, "binomial")) {
    std::vector<CGAL::Gmpz> row(1, CGAL::Gmpz(1));
    for (int n = 1; n <= 10; ++n) {
      std::vector<CGAL::Gmpz> next(n + 1, CGAL::Gmpz(1));
      for (int k = 1; k < n; ++k) next[k] = row[k - 1] + row[k];
      row = next;
    }
    P e(1);
    for (int k = 1; k <= 10; k += 2) e.add_term(P::Exponent(1, unsigned(k)), Q(2 * row[k]));
    CHECK(same(f.system.equations[0], e), "binomial: " << show(f.system.equations[0], f.system.variable_names));
    CHECK(f.system.equations[0].terms().size() == 5, "binomial: 5 terms");
  }
}

// Random polynomials written in varied spellings and read back exactly.
static void test_random_round_trip()
{
  std::mt19937 rng(20260402);
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const std::vector<std::string> pool = {"x", "y", "z", "w_1", "Th2"};
  for (int it = 0; it < 150; ++it) {
    // terms as (coefficient, exponent by name)
    std::vector<std::pair<Q, std::map<std::string, unsigned>>> terms;
    const int nt = uni(1, 6);
    for (int t = 0; t < nt; ++t) {
      std::map<std::string, unsigned> e;
      for (const auto& v : pool) if (uni(0, 2) == 0) e[v] = unsigned(uni(1, 4));
      Q c;
      switch (uni(0, 2)) {
        case 0: c = Q(uni(-30, 30)); break;
        case 1: c = Q(uni(-300, 300), uni(1, 40)); break;
        default: c = Q(uni(-99999, 99999), 1000); break; // written as a decimal
      }
      terms.emplace_back(c, e);
    }
    std::string text;
    std::vector<std::string> order; // of first appearance in the text
    auto mention = [&](const std::string& v) { if (std::find(order.begin(), order.end(), v) == order.end()) order.push_back(v); };
    for (std::size_t t = 0; t < terms.size(); ++t) {
      const Q& c = terms[t].first;
      const bool negative = c < 0;
      const Q a = negative ? Q(-c) : c;
      text += negative ? (t == 0 ? "-" : " - ") : (t == 0 ? "" : " + ");
      std::ostringstream cs;
      if (a.denominator() == 1) cs << a.numerator();
      else if (a.denominator() == 1000 || (CGAL::Gmpz(1000) % a.denominator()) == 0) {
        // exact decimal: a * 1000 / 1000 written with a point (or E-notation)
        Q scaled = a * 1000;
        CGAL::Gmpz m = scaled.numerator(); // integer since the denominator divides 1000
        std::ostringstream ms;
        ms << m;
        std::string digits = ms.str();
        while (digits.size() < 4) digits = "0" + digits;
        std::string dec = digits.substr(0, digits.size() - 3) + "." + digits.substr(digits.size() - 3);
        if (uni(0, 1)) cs << dec;
        else cs << m << "E-3";
      } else cs << a.numerator() << "/" << a.denominator();
      text += cs.str();
      for (const auto& ve : terms[t].second) {
        mention(ve.first);
        const int style = uni(0, 2);
        if (style == 0) text += "*" + ve.first + "^" + std::to_string(ve.second);
        else if (style == 1) text += "*" + ve.first + "**" + std::to_string(ve.second);
        else for (unsigned k = 0; k < ve.second; ++k) text += "*" + ve.first;
      }
    }
    if (order.empty()) { text += " + 0*x"; order.push_back("x"); }
    const std::size_t n = order.size();
    P expected(n);
    for (const auto& t : terms) {
      P::Exponent e(n, 0);
      for (const auto& ve : t.second) e[std::find(order.begin(), order.end(), ve.first) - order.begin()] = ve.second;
      expected.add_term(e, t.first);
    }
    RI::Polynomial_system_file f;
    const std::string file = "1 " + std::to_string(n) + "\n" + text + ";\n";
    if (!try_read(file, f, "random " + std::to_string(it) + " \"" + text + "\"")) continue;
    CHECK(f.system.variable_names == order, "random " << it << ": variable order");
    CHECK(same(f.system.equations[0], expected),
          "random " << it << ": \"" << text << "\" read as " << show(f.system.equations[0], f.system.variable_names));
    // Sparse_polynomial::write() output ("(c)*x^2 + ...") reads back to the same polynomial
    std::ostringstream w;
    expected.write(w, order);
    RI::Polynomial_system_file g;
    std::string zeros; // every variable appears, even if its terms cancelled
    for (const auto& v : order) zeros += " + 0*" + v;
    if (try_read("1 " + std::to_string(n) + "\n" + w.str() + zeros + ";\n", g, "write round trip")) {
      // variables may appear in another order in the written text: compare through the names
      bool ok = g.system.number_of_variables() == n;
      if (ok) {
        std::vector<std::size_t> to(n);
        for (std::size_t i = 0; i < n; ++i) to[i] = std::find(order.begin(), order.end(), g.system.variable_names[i]) - order.begin();
        P back(n);
        for (const auto& t : g.system.equations[0].terms()) {
          P::Exponent e(n, 0);
          for (std::size_t i = 0; i < n; ++i) e[to[i]] = t.first[i];
          back.add_term(e, t.second);
        }
        ok = same(back, expected);
      }
      CHECK(ok, "write round trip " << it << ": \"" << w.str() << "\"");
    }
  }
}

static void test_variables_and_header()
{
  RI::Polynomial_system_file f;
  // order of first appearance, across equations
  if (try_read("2 4\n z*b + a;\n a*c - z;\n", f, "order")) {
    CHECK(f.system.variable_names == std::vector<std::string>({"z", "b", "a", "c"}), "variables in order of first appearance");
    if (f.system.number_of_variables() == 4) {
      P z = var(4, 0), b = var(4, 1), a = var(4, 2), c = var(4, 3);
      CHECK(same(f.system.equations[0], z * b + a), "order: equation 1");
      CHECK(same(f.system.equations[1], a * c - z), "order: equation 2");
    }
  }
  // names are case-sensitive, with digits and underscores; a variable with only zero
  // coefficients still counts (as in PHCpack's symbol table)
  if (try_read("1 4\n X + x*x_1 + 0*Y2;\n", f, "names")) {
    CHECK(f.system.variable_names == std::vector<std::string>({"X", "x", "x_1", "Y2"}), "names: case-sensitive, in order");
    if (f.system.number_of_variables() == 4)
      CHECK(same(f.system.equations[0], var(4, 0) + var(4, 1) * var(4, 2)), "names: equation");
  }
  // "n m": fewer and more equations than variables
  if (try_read("1 2\n x + y - 1;\n", f, "1 2")) {
    CHECK(f.system.number_of_equations() == 1 && f.system.number_of_variables() == 2, "'1 2': one equation in two variables");
    CHECK(f.system.box.size() == 2, "'1 2': a box interval per variable");
  }
  if (try_read("3 2\n x + y - 1;\n x - y;\n x*y;\n", f, "3 2")) {
    CHECK(f.system.number_of_equations() == 3 && f.system.number_of_variables() == 2, "'3 2': three equations in two variables");
    CHECK(f.system.labels.size() == 3 && f.system.labels[2] == "equation 3", "'3 2': labels");
  }
}

static void test_directives()
{
  const std::string text =
      "3\n x^2 + y^2 + z^2 - 1;\n x - y;\n z*x - 0.25;\n"
      "BOX y 0.1 0.7\n"
      "box * -1/2 3\n"
      "   box x -2 2.5\n"
      "inequality x - y >= 0;\n"
      "Inequality x*y <= 1/2;\n"
      "inequality  x >= y^2 - z ;\n"
      "boxes are written on lines starting with the word box\n" // not a directive: first word "boxes"
      "an inequality in prose is ignored\n";
  RI::Polynomial_system_file f;
  if (!try_read(text, f, "directives")) return;
  const auto& s = f.system;
  CHECK(!f.default_box, "directives: default_box is false");
  CHECK(s.variable_names == std::vector<std::string>({"x", "y", "z"}), "directives: variables");
  if (s.box.size() != 3 || s.number_of_variables() != 3) { CHECK(false, "directives: box size"); return; }
  CHECK(s.box[0] == std::make_pair(-2.0, 2.5), "box x: exact bounds stay exact");
  CHECK(s.box[2] == std::make_pair(-0.5, 3.0), "box *: the default for z");
  // 0.1 and 0.7 are not doubles: the lower bound is the largest double below 1/10, the upper
  // bound the smallest double above 7/10
  const double lo = s.box[1].first, hi = s.box[1].second;
  CHECK(Q(lo) < Q(1, 10) && Q(std::nextafter(lo, 1.0)) > Q(1, 10), "box y: 0.1 rounded down to the next double, got " << lo);
  CHECK(Q(hi) > Q(7, 10) && Q(std::nextafter(hi, 0.0)) < Q(7, 10), "box y: 0.7 rounded up to the next double, got " << hi);
  P x = var(3, 0), y = var(3, 1), z = var(3, 2);
  CHECK(s.number_of_inequalities() == 3 && s.inequality_labels.size() == 3, "directives: 3 inequalities");
  if (s.number_of_inequalities() == 3 && s.inequality_labels.size() == 3) {
    CHECK(same(s.inequalities[0], x - y), "x - y >= 0 stored as x - y");
    CHECK(same(s.inequalities[1], cst(3, Q(1, 2)) - x * y), "x*y <= 1/2 stored as 1/2 - x*y");
    CHECK(same(s.inequalities[2], x - (y * y - z)), "x >= y^2 - z stored as x - y^2 + z");
    CHECK(s.inequality_labels[0] == "x - y >= 0", "inequality label: '" << s.inequality_labels[0] << "'");
    CHECK(s.inequality_labels[1] == "x*y <= 1/2", "inequality label: '" << s.inequality_labels[1] << "'");
    CHECK(s.inequality_labels[2] == "x >= y^2 - z", "inequality label: '" << s.inequality_labels[2] << "'");
  }
  CHECK(same(s.equations[2], x * z - cst(3, Q(1, 4))), "directives: equation 3");

  // a title ends at a blank line or at a directive; only the first TITLE counts
  if (try_read("1\n x;\ntitle: one\nbox x 0 1\nnot the title\nTITLE : two\n", f, "title and directive")) {
    CHECK(f.title == "one" && f.system.box[0] == std::make_pair(0.0, 1.0), "title ended by a directive: '" << f.title << "'");
  }
  // only 'box *': not the built-in default
  if (try_read("1\n x;\nbox * 0 1\n", f, "box * only")) {
    CHECK(!f.default_box && f.system.box[0] == std::make_pair(0.0, 1.0), "box * only");
  }
  // a named box and the built-in default for the other variable
  if (try_read("1 2\n x + y;\nbox x -1 1\n", f, "named box only")) {
    CHECK(!f.default_box, "named box only: default_box false");
    CHECK(f.system.box[0] == std::make_pair(-1.0, 1.0) && f.system.box[1] == std::make_pair(-10.0, 10.0), "named box only: boxes");
  }
  // a directive right after the last ';' on the same line, and negative decimal bounds
  if (try_read("1\n x - 1; box x -.5 5.\n", f, "directive on the last line")) {
    CHECK(f.system.box[0] == std::make_pair(-0.5, 5.0), "box on the line of the last ';'");
  }
}

// A PHCpack file (in the style of PHCpack's Demo/fourbar) with the directives between the
// polynomials and the TITLE, and the usual sections after.
static void test_phcpack_file()
{
  const std::string text =
      "2\n"
      "\n"
      " 0.5*X1**2*Y1 - 1.25E-01*X1*Y1**2\n"
      "+ 3*X1 - Y1;\n"
      "\n"
      " X1**2 + Y1**2 - 2;\n"
      "box X1 -3 3\n"
      "inequality Y1 >= -1;\n"
      "\n"
      "TITLE : a small four-bar like\n"
      "   test system\n"
      "\n"
      "ROOT COUNTS :\n"
      "\n"
      "total degree : 6\n"
      "mixed volume : 4\n"
      "\n"
      "REFERENCES :\n"
      "\n"
      "Written for this test; i and I and 'x + ;' in the free text are ignored.\n"
      "\n"
      "THE SOLUTIONS :\n"
      "\n"
      "2 2\n"
      "===========================================================\n"
      "solution 1 :\n"
      "t :  1.00000000000000E+00   0.00000000000000E+00\n"
      "m : 1\n"
      "the solution for t :\n"
      " X1 :  1.00000000000000E+00   0.00000000000000E+00\n"
      " Y1 :  1.00000000000000E+00   0.00000000000000E+00\n"
      "== err :  0.000E+00 = rco :  1.000E+00 = res :  0.000E+00 ==\n"
      "solution 2 :\n"
      "t :  1.00000000000000E+00   0.00000000000000E+00\n"
      "m : 1\n"
      "the solution for t :\n"
      " X1 : -1.00000000000000E+00   0.00000000000000E+00\n"
      " Y1 : -1.00000000000000E+00   0.00000000000000E+00\n"
      "== err :  0.000E+00 = rco :  1.000E+00 = res :  0.000E+00 ==\n";
  RI::Polynomial_system_file f;
  if (!try_read(text, f, "PHCpack file")) return;
  const auto& s = f.system;
  CHECK(f.title == "a small four-bar like test system", "PHCpack file: title (on two lines) '" << f.title << "'");
  CHECK(s.variable_names == std::vector<std::string>({"X1", "Y1"}), "PHCpack file: variables");
  CHECK(s.number_of_equations() == 2, "PHCpack file: 2 equations");
  if (s.number_of_equations() != 2 || s.number_of_variables() != 2) return;
  P X1 = var(2, 0), Y1 = var(2, 1);
  CHECK(same(s.equations[0], Q(1, 2) * (X1 * X1 * Y1) - Q(1, 8) * (X1 * Y1 * Y1) + Q(3) * X1 - Y1), "PHCpack file: equation 1");
  CHECK(same(s.equations[1], X1 * X1 + Y1 * Y1 - cst(2, 2)), "PHCpack file: equation 2");
  CHECK(!f.default_box && s.box[0] == std::make_pair(-3.0, 3.0) && s.box[1] == std::make_pair(-10.0, 10.0), "PHCpack file: box");
  CHECK(s.number_of_inequalities() == 1 && same(s.inequalities[0], Y1 + cst(2, 1)), "PHCpack file: inequality Y1 + 1 >= 0");
  // the same file with the directives after THE SOLUTIONS
  const std::string moved = text.substr(0, text.find("box X1")) + text.substr(text.find("\nTITLE") + 1) + "box X1 -3 3\ninequality Y1 >= -1;\n";
  RI::Polynomial_system_file g;
  if (try_read(moved, g, "PHCpack file, directives at the end")) {
    CHECK(g.title == f.title && g.system.box == s.box && g.system.number_of_inequalities() == 1, "directives at the end");
    CHECK(same(g.system.equations[0], s.equations[0]) && same(g.system.equations[1], s.equations[1]), "directives at the end: equations");
  }
  // plain PHCpack file: no directive
  if (try_read(text.substr(0, text.find("box X1")) + text.substr(text.find("\nTITLE") + 1), g, "PHCpack file without directives")) {
    CHECK(g.default_box && g.system.box[0] == std::make_pair(-10.0, 10.0) && g.system.inequalities.empty(), "no directives: defaults");
  }
}

static void test_files()
{
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path();
  const fs::path p = dir / ("rps_test_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()) + ".phc");
  {
    std::ofstream out(p);
    out << "2\n x^2 - 2;\n x*y - 1;\nTITLE : from a file\n";
  }
  try {
    RI::Polynomial_system_file f = RI::read_polynomial_system(p.string());
    CHECK(f.title == "from a file" && f.system.number_of_equations() == 2, "file: read");
  } catch (const std::exception& e) {
    CHECK(false, "file: " << e.what());
  }
  {
    std::ofstream out(p);
    out << "2\n x^2 - 2;\n x*y - $;\n";
  }
  try {
    RI::read_polynomial_system(p.string());
    CHECK(false, "file with an error: accepted");
  } catch (const RI::Input_error& e) {
    CHECK(std::string(e.what()).find(p.string() + ":3:") == 0, "file: the message names the path and line: " << e.what());
  }
  std::error_code ec;
  fs::remove(p, ec);
  const std::string missing = (dir / "rps_test_no_such_directory" / "none.phc").string();
  try {
    RI::read_polynomial_system(missing);
    CHECK(false, "missing file: accepted");
  } catch (const RI::Input_error& e) {
    CHECK(std::string(e.what()).find(missing) != std::string::npos, "missing file: message " << e.what());
  } catch (...) {
    CHECK(false, "missing file: another exception");
  }
}

// ------------------------------------------------------------------------------ refused inputs

struct Bad
{
  std::string name;
  std::string text;
  std::size_t line;                  // expected line in "SOURCE:LINE:"
  std::vector<std::string> needles;  // substrings the message must contain
};

static void expect_refused(const Bad& b, const RI::internal::Polynomial_reader_limits* limits = nullptr)
{
  const std::string source = "mem/" + b.name;
  std::string msg;
  bool input_error = false, other = false;
  try {
    std::istringstream in(b.text);
    if (limits) RI::internal::read_polynomial_system(in, source, *limits);
    else RI::read_polynomial_system(in, source);
  } catch (const RI::Input_error& e) {
    input_error = true;
    msg = e.what();
  } catch (const std::exception& e) {
    other = true;
    msg = e.what();
  } catch (...) {
    other = true;
  }
  if (verbose) std::cout << b.name << ": " << msg << "\n";
  CHECK(!other, b.name << ": an exception other than Input_error: " << msg);
  CHECK(input_error || other, b.name << ": accepted");
  if (!input_error) return;
  const std::string prefix = source + ":" + std::to_string(b.line) + ": ";
  CHECK(msg.compare(0, prefix.size(), prefix) == 0, b.name << ": message does not start with '" << prefix << "': " << msg);
  for (const auto& n : b.needles)
    CHECK(msg.find(n) != std::string::npos, b.name << ": message does not mention \"" << n << "\": " << msg);
}

static void test_errors()
{
  const std::string ok2 = "2\n x + y;\n x - y;\n"; // lines 1-3
  std::vector<Bad> bad = {
      // count
      {"empty", "", 1, {"missing count"}},
      {"blank_only", "\n \n\t\n", 1, {"missing count"}},
      {"count_word", "x\n x;\n", 1, {"bad count", "'x'"}},
      {"count_three", "\n\n2 3 4\n x;\n", 3, {"bad count", "more than two"}},
      {"count_zero", "0\n", 1, {"bad count", "equations must be positive"}},
      {"count_zero_vars", "1 0\n x;\n", 1, {"bad count", "variables must be positive"}},
      {"count_decimal", "2.5\n x;\n", 1, {"bad count", "'2.5'"}},
      {"count_negative", "-1\n x;\n", 1, {"bad count"}},
      {"count_huge", "99999999999999999999\n x;\n", 1, {"bad count", "limit"}},
      {"count_then_poly", "1 x + 1;\n", 1, {"bad count"}},
      // polynomials
      {"fewer_polynomials", "3\n x + y + z;\n x - y;\n\n", 3, {"found 2 polynomials", "announces 3"}},
      {"no_polynomial", "2\n\n", 1, {"found 0 polynomials", "announces 2"}},
      {"missing_semicolon_at_end", "2\n x + y;\n x -\n y\n\n", 4, {"polynomial 2", "missing its ';'"}},
      {"title_as_polynomial", "3\n x + y + z;\n x;\n\nTITLE : x\n", 5, {"'TITLE'", "only 2 ';'", "announces 3"}},
      {"title_as_polynomial_nm", "3 4\n x + y + z;\n x;\n\nTITLE : x\n", 5, {"unexpected character ':'", "only 2 ';'", "announces 3"}},
      {"empty_polynomial", "2\n x;\n ;\n", 3, {"polynomial 2 is empty"}},
      {"unexpected_char", "1\n x + $y;\n", 2, {"unexpected character '$'"}},
      {"unexpected_char_later", "2\n x + y;\n\n x @ y;\n", 4, {"unexpected character '@'"}},
      {"unexpected_control_char", "1\n x\x01 + 1;\n", 2, {"unexpected character '\\x01'"}},
      {"unexpected_bracket", "1\n [x + 1];\n", 2, {"unexpected character '['"}},
      {"unexpected_equals", "1\n x = 1;\n", 2, {"unexpected character '='"}},
      {"comparison_in_polynomial", "1\n x >= 1;\n", 2, {"'>='", "inequality"}},
      {"lone_point", "1\n x + .;\n", 2, {"unexpected character '.'"}},
      {"underscore_start", "1\n _x;\n", 2, {"unexpected character '_'"}},
      {"unbalanced_open", "2\n x + y;\n 3*(x - 1;\n", 3, {"unbalanced parentheses", "'('"}},
      {"unbalanced_open_multiline", "1 2\n (x\n + (y - 1)\n ;\n", 2, {"unbalanced parentheses", "line 4"}},
      {"unbalanced_close", "1\n x + 1);\n", 2, {"unbalanced parentheses", "')'"}},
      {"unbalanced_close_nested", "1\n ((x))) * 2;\n", 2, {"unbalanced parentheses", "')'"}},
      {"unbalanced_open_at_end", "1\n (x + 1\n", 2, {"missing its ';'", "'(' at line 2"}},
      {"empty_parentheses", "1\n x*();\n", 2, {"empty parentheses"}},
      {"missing_operator", "1\n 2 x;\n", 2, {"missing operator", "'x'"}},
      {"missing_operator_paren", "1\n (x + 1)(x - 1);\n", 2, {"missing operator", "'('"}},
      {"missing_operand", "1\n x + ;\n", 2, {"before ';'"}},
      {"leading_star", "1\n * x;\n", 2, {"before '*'"}},
      {"triple_star", "1\n x***2;\n", 2, {"bad exponent", "'*'"}},
      // exponents
      {"exponent_negative", "1\n x^-1;\n", 2, {"bad exponent", "negative"}},
      {"exponent_decimal", "1\n\n x^1.5;\n", 3, {"bad exponent", "'1.5'"}},
      {"exponent_variable", "1\n x**y;\n", 2, {"bad exponent", "'y'"}},
      {"exponent_missing", "1\n x^;\n", 2, {"bad exponent"}},
      {"exponent_too_large", "1\n x^1001;\n", 2, {"bad exponent", "limit of 1000"}},
      {"exponent_huge", "1\n x^99999999999999999999999;\n", 2, {"bad exponent", "limit of 1000"}},
      {"exponent_unclosed", "1\n x^(2;\n", 2, {"bad exponent", "')'"}},
      {"exponent_repeated", "1\n x^2^3;\n", 2, {"ambiguous"}},
      // division
      {"divide_by_variable", "1\n 1/x;\n", 2, {"division by a non-constant"}},
      {"divide_by_polynomial", "1 2\n x/(y + 1);\n", 2, {"division by a non-constant"}},
      {"divide_by_zero", "1\n x/0;\n", 2, {"division by zero"}},
      {"divide_by_zero_decimal", "1\n x/0.000;\n", 2, {"division by zero"}},
      {"divide_by_cancelled", "1 2\n x/(y - y);\n", 2, {"division by zero"}},
      // complex
      {"complex_i", "2\n x + y;\n x + i*y;\n", 3, {"complex coefficients are not supported"}},
      {"complex_I", "1\n 2*I + x;\n", 2, {"complex coefficients are not supported"}},
      // variables and the header
      {"more_variables", "1\n x + y;\n", 2, {"'y'", "more variables", "1 announced"}},
      {"more_variables_nm", "2 2\n x + y;\n x*y - z;\n", 3, {"'z'", "more variables", "2 announced"}},
      {"fewer_variables", "2\n x^2 - 1;\n x - 1;\n", 1, {"2 variables are expected", "use 1 (x)"}},
      {"fewer_variables_nm", "2 3\n x + y;\n x - y;\n", 1, {"announces 3 variables", "use 2 (x, y)"}},
      // numbers
      {"number_exponent_absurd", "1\n 1e5000*x;\n", 2, {"bad number", "exponent out of range"}},
      // box
      {"box_unknown_variable", ok2 + "box z 0 1\n", 4, {"box", "unknown variable 'z'"}},
      {"box_equal_bounds", ok2 + "\nbox x 1 1\n", 5, {"box", "not less than"}},
      {"box_reversed_bounds", ok2 + "box x 2 1/2\n", 4, {"box", "not less than"}},
      {"box_bad_number", ok2 + "box x a 1\n", 4, {"box", "bad number 'a'"}},
      {"box_absurd_number", ok2 + "box x 0 1e9999\n", 4, {"box", "bad number"}},
      {"box_out_of_double", ok2 + "box x 0 1e400\n", 4, {"box", "range of a double"}},
      {"box_arity", ok2 + "box x 0\n", 4, {"box", "expected 'box NAME LO HI'"}},
      {"box_duplicate", ok2 + "box x 0 1\nbox x 0 2\n", 5, {"box", "second box line for 'x'", "line 4"}},
      {"box_star_duplicate", ok2 + "box * 0 1\nbox * 0 2\n", 5, {"box", "second 'box *'"}},
      // inequalities
      {"inequality_no_comparison", ok2 + "inequality x + y;\n", 4, {"without '>=' or '<='"}},
      {"inequality_no_comparison_eol", ok2 + "inequality x + y\n", 4, {"without '>=' or '<='"}},
      {"inequality_strict", ok2 + "inequality x > 0;\n", 4, {"'>=' or '<='", "'>'"}},
      {"inequality_equal", ok2 + "inequality x = 0;\n", 4, {"'>=' or '<='", "'='"}},
      {"inequality_unknown_variable", ok2 + "TITLE : t\ninequality x*z >= 0;\n", 5, {"'z' is not a variable"}},
      {"inequality_no_semicolon", ok2 + "inequality x >= 0\n", 4, {"missing ';'"}},
      {"inequality_two_comparisons", ok2 + "inequality 0 <= x <= 1;\n", 4, {"only one"}},
      {"inequality_after_semicolon", ok2 + "inequality x >= 0; y\n", 4, {"after ';'"}},
      {"inequality_complex", ok2 + "inequality i*x >= 0;\n", 4, {"complex coefficients are not supported"}},
      {"inequality_empty", ok2 + "inequality\n", 4, {"inequality", "empty"}},
      {"inequality_bad_char", ok2 + "inequality x # 0;\n", 4, {"inequality", "'#'"}},
      {"inequality_unbalanced", ok2 + "inequality (x >= 0;\n", 4, {"inequality", "unbalanced parentheses"}},
      // limits
      {"terms_limit", "1 3\n (" + [] { std::string s = "1"; for (int i = 1; i <= 100; ++i) s += "+x^" + std::to_string(i); return s; }() + ")*(" +
                          [] { std::string s = "1"; for (int i = 1; i <= 100; ++i) s += "+y^" + std::to_string(i); return s; }() + ")*(" +
                          [] { std::string s = "1"; for (int i = 1; i <= 100; ++i) s += "+z^" + std::to_string(i); return s; }() + ");\n",
       2, {"1000000 terms"}},
      {"degree_limit", "1\n (x^1000)^1000;\n", 2, {"degree in 'x'", "100000"}},
      {"coefficient_limit", "1\n (2^1000)^1000*x;\n", 2, {"bits"}},
      {"nesting_limit", "1\n" + std::string(1000, '(') + "x" + std::string(1000, ')') + ";\n", 2, {"nested deeper than 200"}},
  };
  for (const auto& b : bad) expect_refused(b);

  // limits lowered (the defaults would take too long for a unit test)
  RI::internal::Polynomial_reader_limits small;
  small.max_work = 2000;
  expect_refused({"work_limit", "1 3\n\n (x + y + z)^30;\n", 3, {"2000 term-by-term products"}}, &small);
  small = RI::internal::Polynomial_reader_limits();
  small.max_total_terms = 10;
  expect_refused({"total_terms_limit", "3\n x + y + z;\n (x + y + z)^3;\n x;\n", 3, {"whole system is limited to 10 terms"}}, &small);
  small = RI::internal::Polynomial_reader_limits();
  small.max_terms = 50;
  expect_refused({"term_limit_sum", "1\n " + [] { std::string s = "0"; for (int i = 1; i <= 60; ++i) s += "+x^" + std::to_string(i); return s; }() + ";\n",
                  2, {"more than 50 terms"}}, &small);
  // the lowered limits still accept what is below them
  small = RI::internal::Polynomial_reader_limits();
  small.max_work = 2000;
  try {
    std::istringstream in("1 3\n (x + y + z)^5;\n");
    RI::Polynomial_system_file f = RI::internal::read_polynomial_system(in, "mem", small);
    CHECK(f.system.equations[0].terms().size() == 21, "(x + y + z)^5 has 21 terms");
  } catch (const std::exception& e) {
    CHECK(false, "(x + y + z)^5 under a work limit of 2000: " << e.what());
  }
}

// Random mutations of a valid file: accepted or refused with an Input_error, nothing else.
static void test_mutations()
{
  const std::string base = "3 3\n x^2 + 0.5*y**2 - (z - 1)*(z + 2)/3;\n x*y - 1.5e-2;\n -(x - y)^3 + z;\n"
                           "box x -1 1\nbox * -2 2\ninequality x + y >= z^2;\nTITLE : mutated\n";
  const std::string alphabet = "0123456789.eE+-*/^()[];:<>=xyzi \n\t$_";
  std::mt19937 rng(7);
  auto uni = [&](std::size_t lo, std::size_t hi) { return std::uniform_int_distribution<std::size_t>(lo, hi)(rng); };
  int accepted = 0, refused = 0;
  for (int it = 0; it < 3000; ++it) {
    std::string s = base;
    const std::size_t edits = uni(1, 3);
    for (std::size_t k = 0; k < edits; ++k) {
      const std::size_t pos = uni(0, s.size() - 1);
      switch (uni(0, 2)) {
        case 0: s.erase(pos, 1); break;
        case 1: s.insert(pos, 1, alphabet[uni(0, alphabet.size() - 1)]); break;
        default: s[pos] = alphabet[uni(0, alphabet.size() - 1)]; break;
      }
    }
    try {
      read_text(s, "mutant");
      ++accepted;
    } catch (const RI::Input_error& e) {
      ++refused;
      const std::string msg = e.what();
      CHECK(msg.compare(0, 7, "mutant:") == 0 && msg.size() > 9 && msg[7] >= '1' && msg[7] <= '9',
            "mutant " << it << ": message without a line: " << msg);
    } catch (const std::exception& e) {
      CHECK(false, "mutant " << it << ": another exception: " << e.what());
    }
  }
  CHECK(accepted > 0 && refused > 0, "mutations: " << accepted << " accepted, " << refused << " refused");
}

int main(int argc, char** argv)
{
  for (int i = 1; i < argc; ++i) if (std::string(argv[i]) == "-v") verbose = true;
  const auto start = std::chrono::steady_clock::now();
  test_basic();
  test_numbers();
  test_powers();
  test_expansion();
  test_random_round_trip();
  test_variables_and_header();
  test_directives();
  test_phcpack_file();
  test_files();
  test_errors();
  test_mutations();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "test_read_polynomial_system: " << checks << " checks, " << failures << " failures (" << seconds << " s)\n";
  return failures == 0 ? 0 : 1;
}
