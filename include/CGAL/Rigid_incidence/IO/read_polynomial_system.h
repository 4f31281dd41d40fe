// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reading of polynomial systems in PHCpack's plain-text input format, extended by two
// directives (box, inequality) placed after the polynomials. A PHCpack file is read as is, and
// a file with directives still runs through `phc -b`: PHCpack stops reading after the n
// polynomials, so it never sees them. Coefficients are read exactly (CGAL::Gmpq), never
// through a binary double.
//
// The format, as it would go in the manual:
//
//   file        = count-line , polynomial , { polynomial } , free-text ;
//                 (* exactly n polynomials; blank lines may precede the count line *)
//   count-line  = n , [ m ] , end-of-line ;     (* positive integers; m defaults to n *)
//   polynomial  = sum , ";" ;                   (* may span lines *)
//   sum         = product , { ( "+" | "-" ) , product } ;
//   product     = signed , { ( "*" | "/" ) , signed } ;  (* "/": the divisor must be a nonzero constant *)
//   signed      = { "+" | "-" } , power ;
//   power       = primary , [ ( "^" | "**" ) , exponent ] ;  (* "x^2^3" is refused: write (x^2)^3 *)
//   exponent    = integer | "(" , integer , ")" ;            (* 0 .. 1000 *)
//   primary     = number | identifier | "(" , sum , ")" ;
//   number      = ( digits , [ "." , [ digits ] ] | "." , digits ) , [ ( "e" | "E" ) , [ "+" | "-" ] , digits ] ;
//   identifier  = letter , { letter | digit | "_" } ;        (* case-sensitive; "i" and "I" are
//                                                               the imaginary unit: refused *)
//   free-text   = { line } ;      (* PHCpack's TITLE, ROOT COUNTS, THE SOLUTIONS ... *)
//   line        = box-line | inequality-line | title-line | any other line (ignored) ;
//   box-line        = "box" , ( identifier | "*" ) , bound , bound ;  (* keyword case-insensitive *)
//   bound           = number with optional sign, or integer "/" integer ;
//   inequality-line = "inequality" , sum , ( ">=" | "<=" ) , sum , ";" ;  (* on one line *)
//   title-line      = "TITLE" , ":" , text ;   (* case-insensitive; the first one is kept, with
//                                                  the non-blank lines after it up to a blank line *)
//
// Blanks (space, tab, CR, LF, FF, VT) may separate any two tokens. There is no implicit
// multiplication ("2 x" and "2(x+1)" are refused, as in PHCpack).

#ifndef CGAL_RIGID_INCIDENCE_IO_READ_POLYNOMIAL_SYSTEM_H
#define CGAL_RIGID_INCIDENCE_IO_READ_POLYNOMIAL_SYSTEM_H

#include <CGAL/Gmpq.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Polynomial_system.h>
#include <CGAL/Rigid_incidence/internal/parse_number.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <istream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/*!
\ingroup PkgRigidIncidenceIO
\brief A polynomial system as read by `read_polynomial_system()`, with what the file says
about it besides the equations.
*/
struct Polynomial_system_file
{
  /// The equations ("equation 1" .. "equation n"), the variables in order of first appearance,
  /// the box and the inequalities given by `box` and `inequality` lines.
  Polynomial_system<CGAL::Gmpq> system;
  /// `true` if the file has no `box` line at all, so that every variable has the built-in
  /// interval [-10, 10]; `false` as soon as one `box` line (named or `*`) is present.
  bool default_box = true;
  /// The text after "TITLE :" in PHCpack files, else empty: the first such line and the
  /// non-blank lines after it up to a blank line (or a directive), trimmed and joined by a space.
  std::string title;
};

namespace internal {

// Limits that keep a hostile or mistaken file from exhausting memory or time; each one is
// refused with an Input_error naming the line. The test lowers some of them.
struct Polynomial_reader_limits
{
  unsigned max_exponent = 1000;              // largest exponent after '^' or '**'
  unsigned max_degree = 100000;              // largest degree of a variable in any expansion
  std::size_t max_terms = 1000000;           // terms of one polynomial, also while expanding
  std::size_t max_total_terms = 1000000;     // terms of all equations and inequalities together
  std::size_t max_exponent_entries = std::size_t(1) << 25; // terms x variables (memory of the exponents)
  unsigned long long max_work = 10000000ULL; // term-by-term products for expanding the whole file
  std::size_t max_coefficient_bits = 262144; // bits of a coefficient's numerator or denominator
  std::size_t max_nesting = 200;             // depth of nested parentheses
  std::size_t max_count = 100000;            // largest n or m on the first line
};

struct Poly_token
{
  enum Kind { NUMBER, IDENT, PLUS, MINUS, STAR, SLASH, POW, LPAREN, RPAREN, SEMI, GE, LE, GT, LT, EQ, END, ERROR };
  Kind kind = END;
  std::string text;  // the source text (or the message, for ERROR)
  std::size_t line = 1;
};

inline std::string quote_char(char c)
{
  unsigned char u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  static const char* hex = "0123456789abcdef";
  return std::string("'\\x") + hex[u >> 4] + hex[u & 15] + "'";
}

inline bool poly_is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool poly_is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
inline bool poly_is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

inline std::string lower_case(std::string s)
{
  for (char& c : s) if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return s;
}

inline std::string trim_blanks(const std::string& s)
{
  std::size_t a = 0, b = s.size();
  while (a < b && poly_is_blank(s[a])) ++a;
  while (b > a && poly_is_blank(s[b - 1])) --b;
  return s.substr(a, b - a);
}

// "1 polynomial", "2 polynomials"
inline std::string count_of(std::size_t n, const std::string& word)
{
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

inline std::string shorten(const std::string& s, std::size_t n = 40)
{
  return s.size() > n ? s.substr(0, n) + "..." : s;
}

// PHCpack accepts ".5" and "5." as numbers; parse_decimal() wants digits on both sides of the
// point, so a 0 is inserted where one is missing. Texts holding '/' are left alone.
inline std::string complete_decimal_point(const std::string& s)
{
  if (s.find('/') != std::string::npos) return s;
  std::string r = s;
  std::size_t i = (!r.empty() && (r[0] == '+' || r[0] == '-')) ? 1 : 0;
  if (i < r.size() && r[i] == '.') r.insert(i, "0");
  std::size_t p = r.find('.');
  if (p != std::string::npos && (p + 1 == r.size() || !poly_is_digit(r[p + 1]))) r.insert(p + 1, "0");
  return r;
}

// Splits text[begin, end) into tokens; `line` is the line number at `begin`.
class Poly_lexer
{
public:
  Poly_lexer(const std::string& text, std::size_t begin, std::size_t end, std::size_t line)
    : s_(text), pos_(begin), end_(end), line_(line), last_line_(line) {}

  std::size_t position() const { return pos_; }
  std::size_t line() const { return line_; }

  Poly_token next()
  {
    while (pos_ < end_ && poly_is_blank(s_[pos_])) {
      if (s_[pos_] == '\n') ++line_;
      ++pos_;
    }
    Poly_token t;
    // the end is reported at the line of the last token (not at a final empty line)
    if (pos_ >= end_) { t.kind = Poly_token::END; t.line = last_line_; return t; }
    t.line = last_line_ = line_;
    const char c = s_[pos_];
    const std::size_t start = pos_;
    if (poly_is_digit(c) || (c == '.' && pos_ + 1 < end_ && poly_is_digit(s_[pos_ + 1]))) {
      while (pos_ < end_ && poly_is_digit(s_[pos_])) ++pos_;
      if (pos_ < end_ && s_[pos_] == '.') {
        ++pos_;
        while (pos_ < end_ && poly_is_digit(s_[pos_])) ++pos_;
      }
      if (pos_ < end_ && (s_[pos_] == 'e' || s_[pos_] == 'E')) {
        std::size_t j = pos_ + 1;
        if (j < end_ && (s_[j] == '+' || s_[j] == '-')) ++j;
        if (j < end_ && poly_is_digit(s_[j])) {
          pos_ = j;
          while (pos_ < end_ && poly_is_digit(s_[pos_])) ++pos_;
        }
      }
      t.kind = Poly_token::NUMBER;
      t.text = s_.substr(start, pos_ - start);
      return t;
    }
    if (poly_is_letter(c)) {
      while (pos_ < end_ && (poly_is_letter(s_[pos_]) || poly_is_digit(s_[pos_]) || s_[pos_] == '_')) ++pos_;
      t.kind = Poly_token::IDENT;
      t.text = s_.substr(start, pos_ - start);
      return t;
    }
    ++pos_;
    t.text = std::string(1, c);
    switch (c) {
      case '+': t.kind = Poly_token::PLUS; return t;
      case '-': t.kind = Poly_token::MINUS; return t;
      case '/': t.kind = Poly_token::SLASH; return t;
      case '(': t.kind = Poly_token::LPAREN; return t;
      case ')': t.kind = Poly_token::RPAREN; return t;
      case ';': t.kind = Poly_token::SEMI; return t;
      case '^': t.kind = Poly_token::POW; return t;
      case '*':
        if (pos_ < end_ && s_[pos_] == '*') { ++pos_; t.kind = Poly_token::POW; t.text = "**"; }
        else t.kind = Poly_token::STAR;
        return t;
      case '>':
      case '<':
        if (pos_ < end_ && s_[pos_] == '=') { ++pos_; t.kind = (c == '>') ? Poly_token::GE : Poly_token::LE; t.text += "="; }
        else t.kind = (c == '>') ? Poly_token::GT : Poly_token::LT;
        return t;
      case '=': t.kind = Poly_token::EQ; return t;
      default:
        break;
    }
    t.kind = Poly_token::ERROR;
    t.text = "unexpected character " + quote_char(c);
    if (c == '_') t.text += " (an identifier starts with a letter)";
    else if (c == '.') t.text += " (a number needs a digit next to its decimal point)";
    else if (c == '[' || c == ']' || c == '{' || c == '}') t.text += " (use '(' and ')' for grouping)";
    return t;
  }

private:
  const std::string& s_;
  std::size_t pos_, end_, line_, last_line_;
};

class Polynomial_system_reader
{
  typedef Sparse_polynomial<CGAL::Gmpq> P;
  typedef Poly_token T;

public:
  Polynomial_system_reader(const std::string& text, const std::string& source, const Polynomial_reader_limits& limits)
    : text_(text), source_(source), lim_(limits) {}

  Polynomial_system_file read()
  {
    std::size_t pos = 0, line = 1;
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos = 3; // UTF-8 byte order mark
    read_count_line(pos, line);
    std::size_t header_line = line;
    // the count line ends at its newline
    while (pos < text_.size() && text_[pos] != '\n') ++pos;

    // Pass 1: the variables in order of first appearance, and the end of the n polynomials.
    Poly_lexer lex(text_, pos, text_.size(), line);
    std::size_t semis = 0;
    while (true) {
      T t = lex.next();
      // at most m + 1 variables: the (m+1)-th is refused when pass 2 reaches it
      if (t.kind == T::IDENT && t.text != "i" && t.text != "I" && names_.size() <= m_ && !var_index_.count(t.text)) {
        var_index_.emplace(t.text, names_.size());
        names_.push_back(t.text);
      }
      if (t.kind == T::SEMI && ++semis == n_) break;
      if (t.kind == T::END || t.kind == T::ERROR) break;
    }
    const std::size_t free_begin = lex.position(), free_line = lex.line();
    semicolons_in_file_ = static_cast<std::size_t>(std::count(text_.begin() + static_cast<std::ptrdiff_t>(pos), text_.end(), ';'));
    k_ = names_.size();
    static_cap_ = (std::min)(lim_.max_terms, lim_.max_exponent_entries / (std::max<std::size_t>)(k_, 1));
    total_cap_ = (std::min)(lim_.max_total_terms, lim_.max_exponent_entries / (std::max<std::size_t>)(k_, 1));

    // Pass 2: the polynomials, lexed again (tokens are not stored: a long file stays cheap).
    Polynomial_system_file out;
    Polynomial_system<CGAL::Gmpq>& sys = out.system;
    Poly_lexer lex2(text_, pos, text_.size(), line);
    start(lex2);
    in_inequality_ = false;
    for (poly_ = 1; poly_ <= n_; ++poly_) {
      const T& first = cur();
      if (first.kind == T::END)
        fail(first.line, "found " + count_of(poly_ - 1, "polynomial") + " ending with ';' but the first line announces " +
                             std::to_string(n_));
      if (first.kind == T::SEMI) fail(first.line, "polynomial " + std::to_string(poly_) + " is empty (write 0 for the zero polynomial)");
      P p = parse_sum();
      const T& t = cur();
      if (t.kind != T::SEMI) fail_at(t);
      store(p, t.line);
      if (poly_ < n_) advance();
      sys.equations.push_back(p);
      sys.labels.push_back("equation " + std::to_string(poly_));
    }
    if (k_ < m_) {
      std::string msg = "the first line ";
      if (m_given_) msg += "announces " + std::to_string(m_) + " variables";
      else msg += "announces " + std::to_string(n_) + " equations and no number of variables, so " + std::to_string(m_) + " variables are expected";
      msg += ", but the polynomials use " + std::to_string(k_) + (k_ ? " (" + name_list() + ")" : std::string());
      if (!m_given_) msg += "; write \"n m\" on the first line for a system that is not square";
      fail(header_line, msg);
    }
    sys.variable_names = names_;

    // The free text after the polynomials: box, inequality and TITLE lines.
    read_free_text(free_begin, free_line, out);
    return out;
  }

private:
  // ------------------------------------------------------------------------------ errors
  [[noreturn]] void fail(std::size_t line, const std::string& what) const
  {
    throw Input_error(source_ + ":" + std::to_string(line) + ": " + what);
  }

  // The hint added to errors inside a polynomial the file does not terminate.
  std::string missing_polynomials_hint() const
  {
    if (in_inequality_ || semicolons_in_file_ >= n_ || poly_ <= semicolons_in_file_) return "";
    return " (the file has only " + std::to_string(semicolons_in_file_) + " ';' but the first line announces " +
           count_of(n_, "polynomial") + ")";
  }

  std::string where() const
  {
    return in_inequality_ ? std::string("inequality: ") : std::string();
  }

  std::string token_name(const T& t) const
  {
    if (t.kind == T::END) return in_inequality_ ? "the end of the line" : "the end of the file";
    return "'" + shorten(t.text) + "'";
  }

  // An error at token t, which cannot continue the expression.
  [[noreturn]] void fail_at(const T& t) const
  {
    switch (t.kind) {
      case T::ERROR: fail(t.line, where() + t.text + missing_polynomials_hint());
      case T::END:
        if (in_inequality_) fail(t.line, "inequality: missing ';' at the end of the line");
        else {
          std::string msg = "polynomial " + std::to_string(poly_) + " is missing its ';' (end of the file reached)";
          if (!open_.empty()) msg += "; the '(' at line " + std::to_string(open_.back()) + " is not closed either";
          fail(t.line, msg + missing_polynomials_hint());
        }
      case T::SEMI:
        if (!open_.empty())
          fail(open_.back(), where() + "unbalanced parentheses: '(' not closed before the ';' at line " + std::to_string(t.line));
        fail(t.line, where() + "expected a number, a variable or '(' before ';'");
      case T::RPAREN:
        if (open_.empty()) fail(t.line, where() + "unbalanced parentheses: ')' without a matching '('");
        fail(t.line, where() + "expected a number, a variable or '(' before ')'");
      case T::GE: case T::LE:
        if (in_inequality_ && !open_.empty())
          fail(open_.back(), "inequality: unbalanced parentheses: '(' not closed before '" + t.text + "'");
        if (!in_inequality_)
          fail(t.line, "unexpected '" + t.text + "' in a polynomial (inequalities go on 'inequality' lines after the polynomials)" +
                           missing_polynomials_hint());
        fail(t.line, "inequality: unexpected '" + t.text + "'");
      case T::GT: case T::LT: case T::EQ:
        if (in_inequality_) fail(t.line, "inequality: an inequality needs '>=' or '<=', found '" + t.text + "'");
        fail(t.line, "unexpected character '" + t.text + "'" + missing_polynomials_hint());
      case T::NUMBER: case T::IDENT: case T::LPAREN:
        fail(t.line, where() + "missing operator before '" + shorten(t.text) + "' (write '*' for a product)" + missing_polynomials_hint());
      default:
        fail(t.line, where() + "unexpected '" + t.text + "'" + missing_polynomials_hint());
    }
  }

  std::string name_list() const
  {
    std::string s;
    for (std::size_t i = 0; i < names_.size() && i < 20; ++i) s += (i ? ", " : "") + names_[i];
    if (names_.size() > 20) s += ", ...";
    return s;
  }

  // ------------------------------------------------------------------------------ count line
  void read_count_line(std::size_t& pos, std::size_t& line)
  {
    // skip blank lines
    while (true) {
      std::size_t e = text_.find('\n', pos);
      std::size_t stop = (e == std::string::npos) ? text_.size() : e;
      bool blank = true;
      for (std::size_t i = pos; i < stop; ++i) if (!poly_is_blank(text_[i])) { blank = false; break; }
      if (!blank) break;
      if (e == std::string::npos) fail(1, "missing count: the file holds no polynomial system (expected the number of equations on the first line)");
      pos = e + 1;
      ++line;
    }
    std::size_t e = text_.find('\n', pos);
    std::string l = text_.substr(pos, (e == std::string::npos ? text_.size() : e) - pos);
    std::vector<std::string> words;
    std::istringstream ws(l);
    for (std::string w; ws >> w;) words.push_back(w);
    auto bad = [&](const std::string& why) {
      fail(line, "bad count: the first line must hold the number of equations, optionally followed by the number of "
                 "variables (\"n\" or \"n m\"), found '" + shorten(trim_blanks(l)) + "'" + why);
    };
    if (words.size() > 2) bad(" (more than two numbers)");
    std::size_t v[2] = {0, 0};
    for (std::size_t i = 0; i < words.size(); ++i) {
      for (char c : words[i]) if (!poly_is_digit(c)) bad("");
      std::size_t nz = words[i].find_first_not_of('0');
      std::string d = (nz == std::string::npos) ? "0" : words[i].substr(nz);
      if (d.size() > 9 || std::stoul(d) > lim_.max_count)
        fail(line, "bad count: " + shorten(words[i]) + " is more than the limit of " + std::to_string(lim_.max_count));
      v[i] = std::stoul(d);
      if (v[i] == 0) fail(line, std::string("bad count: the number of ") + (i ? "variables" : "equations") + " must be positive");
    }
    n_ = v[0];
    m_given_ = (words.size() == 2);
    m_ = m_given_ ? v[1] : n_;
  }

  // ------------------------------------------------------------------------------ arithmetic
  static std::size_t bits(const CGAL::Gmpq& q)
  {
    std::size_t a = mpz_sizeinbase(mpq_numref(q.mpq()), 2), b = mpz_sizeinbase(mpq_denref(q.mpq()), 2);
    return (std::max)(a, b);
  }
  [[noreturn]] void check_bits_fail(std::size_t line) const
  {
    fail(line, where() + "a coefficient would need more than " + std::to_string(lim_.max_coefficient_bits) +
                   " bits (numbers this large are refused)");
  }
  void check_bits(const CGAL::Gmpq& q, std::size_t line) const
  {
    if (bits(q) > lim_.max_coefficient_bits) check_bits_fail(line);
  }
  std::string cap_text() const
  {
    const std::size_t cap = term_cap();
    std::string s = std::to_string(cap) + " terms";
    if (static_cap_ < lim_.max_terms && cap == static_cap_)
      s += " (with " + std::to_string(k_) + " variables, the exponents of more terms would take too much memory)";
    else if (cap < static_cap_)
      s += " (the whole system is limited to " + std::to_string(total_cap_) + " terms, " + std::to_string(total_terms_) +
           " of which are used by the polynomials before)";
    return s;
  }
  void check_size(const P& p, std::size_t line) const
  {
    if (p.terms().size() > term_cap())
      fail(line, where() + "the expanded polynomial would have more than " + cap_text());
  }
  void add_into(P& a, const P& b, bool subtract, std::size_t line) const
  {
    for (const auto& t : b.terms()) {
      a.add_term(t.first, subtract ? CGAL::Gmpq(-t.second) : t.second);
      auto it = a.terms().find(t.first);
      if (it != a.terms().end()) check_bits(it->second, line);
    }
    check_size(a, line);
  }
  P scale(const CGAL::Gmpq& c, const P& a, std::size_t line) const
  {
    P r(k_);
    for (const auto& t : a.terms()) {
      CGAL::Gmpq x = c * t.second;
      check_bits(x, line);
      r.add_term(t.first, x);
    }
    return r;
  }
  P mul(const P& a, const P& b, std::size_t line)
  {
    unsigned long long pairs = static_cast<unsigned long long>(a.terms().size()) * b.terms().size();
    if (pairs > term_cap())
      fail(line, where() + "expanding this product of " + std::to_string(a.terms().size()) + " and " + std::to_string(b.terms().size()) +
                     " terms would need " + std::to_string(pairs) + " term products: the expanded polynomial could have more than " +
                     cap_text());
    work_ += pairs;
    if (work_ > lim_.max_work)
      fail(line, where() + "expanding the products of this file needs more than " + std::to_string(lim_.max_work) +
                     " term-by-term products (refused as too expensive)");
    P r(k_);
    P::Exponent e(k_);
    for (const auto& x : a.terms())
      for (const auto& y : b.terms()) {
        for (std::size_t i = 0; i < k_; ++i) {
          e[i] = x.first[i] + y.first[i];
          if (e[i] > lim_.max_degree)
            fail(line, where() + "the degree in '" + names_[i] + "' would exceed " + std::to_string(lim_.max_degree));
        }
        CGAL::Gmpq c = x.second * y.second;
        check_bits(c, line);
        r.add_term(e, c);
      }
    return r;
  }
  P power(const P& b, unsigned k, std::size_t line)
  {
    if (k == 0) return P::constant(k_, CGAL::Gmpq(1));
    if (b.terms().size() == 1) { // c x^e: (c^k) x^(k e) directly
      const auto& t = *b.terms().begin();
      P::Exponent e(k_);
      for (std::size_t i = 0; i < k_; ++i) {
        if (static_cast<unsigned long long>(t.first[i]) * k > lim_.max_degree)
          fail(line, where() + "the degree in '" + names_[i] + "' would exceed " + std::to_string(lim_.max_degree));
        e[i] = t.first[i] * k;
      }
      // |c| >= 2^(bits-1), so c^k needs at least (bits-1)*k+1 bits
      if ((static_cast<unsigned long long>(bits(t.second)) - 1) * k + 1 > lim_.max_coefficient_bits) check_bits_fail(line);
      CGAL::Gmpq c;
      mpz_pow_ui(mpq_numref(c.mpq()), mpq_numref(t.second.mpq()), k);
      mpz_pow_ui(mpq_denref(c.mpq()), mpq_denref(t.second.mpq()), k); // coprime powers: c stays canonical
      check_bits(c, line);
      work_ += 1;
      P r(k_);
      r.add_term(e, c);
      return r;
    }
    P r = b;
    for (unsigned i = 1; i < k; ++i) r = mul(r, b, line);
    return r;
  }
  void store(const P& p, std::size_t line)
  {
    total_terms_ += p.terms().size();
    if (total_terms_ > total_cap_)
      fail(line, where() + "the system would have more than " + std::to_string(total_cap_) + " terms in all");
  }

  // ------------------------------------------------------------------------------ parser
  // LL(1): the parser sees one token at a time; END and ERROR are never consumed.
  void start(Poly_lexer& lexer) { lexer_ = &lexer; tok_ = lexer.next(); }
  const T& cur() const { return tok_; }
  void advance() { if (tok_.kind != T::END && tok_.kind != T::ERROR) tok_ = lexer_->next(); }
  std::size_t term_cap() const
  {
    return (std::min)(static_cap_, total_cap_ > total_terms_ ? total_cap_ - total_terms_ : std::size_t(0));
  }

  P parse_sum()
  {
    P r = parse_product();
    while (cur().kind == T::PLUS || cur().kind == T::MINUS) {
      const bool minus = cur().kind == T::MINUS;
      const std::size_t line = cur().line;
      advance();
      P q = parse_product();
      add_into(r, q, minus, line);
    }
    return r;
  }

  P parse_product()
  {
    P r = parse_signed();
    while (true) {
      const T& op = cur();
      if (op.kind == T::STAR) {
        const std::size_t line = op.line;
        advance();
        P q = parse_signed();
        r = mul(r, q, line);
      } else if (op.kind == T::SLASH) {
        const std::size_t line = op.line;
        advance();
        P q = parse_signed();
        if (q.is_zero()) fail(line, where() + "division by zero");
        if (q.terms().size() != 1 || q.total_degree() != 0)
          fail(line, where() + "division by a non-constant expression (only division by a number is allowed)");
        r = scale(CGAL::Gmpq(1) / q.terms().begin()->second, r, line);
      } else break;
    }
    const T& t = cur();
    if (t.kind == T::NUMBER || t.kind == T::IDENT || t.kind == T::LPAREN) fail_at(t);
    return r;
  }

  P parse_signed()
  {
    bool negative = false;
    while (cur().kind == T::PLUS || cur().kind == T::MINUS) {
      if (cur().kind == T::MINUS) negative = !negative;
      advance();
    }
    P r = parse_power();
    if (negative) return scale(CGAL::Gmpq(-1), r, cur().line);
    return r;
  }

  P parse_power()
  {
    P b = parse_primary();
    if (cur().kind != T::POW) return b;
    const T op = cur();
    advance();
    unsigned k = parse_exponent(op);
    b = power(b, k, op.line);
    if (cur().kind == T::POW)
      fail(cur().line, where() + "repeated power 'a" + op.text + "b" + cur().text + "c' is ambiguous: use parentheses, e.g. (x^2)^3");
    return b;
  }

  unsigned parse_exponent(const T& op)
  {
    const std::string intro = "bad exponent after '" + op.text + "': ";
    bool paren = false;
    if (cur().kind == T::LPAREN) { paren = true; advance(); }
    const T t = cur();
    if (t.kind == T::MINUS) fail(t.line, where() + intro + "negative exponents are not allowed");
    if (t.kind != T::NUMBER) fail(t.line, where() + intro + "expected a nonnegative integer, found " + token_name(t));
    for (char c : t.text)
      if (!poly_is_digit(c)) fail(t.line, where() + intro + "'" + shorten(t.text) + "' is not a nonnegative integer");
    std::size_t nz = t.text.find_first_not_of('0');
    std::string d = (nz == std::string::npos) ? "0" : t.text.substr(nz);
    if (d.size() > 9 || std::stoul(d) > lim_.max_exponent)
      fail(t.line, where() + intro + "exponent " + shorten(t.text) + " is above the limit of " + std::to_string(lim_.max_exponent));
    advance();
    if (paren) {
      if (cur().kind != T::RPAREN) fail(cur().line, where() + intro + "expected ')' after the exponent, found " + token_name(cur()));
      advance();
    }
    return static_cast<unsigned>(std::stoul(d));
  }

  P parse_primary()
  {
    const T t = cur();
    switch (t.kind) {
      case T::NUMBER: {
        CGAL::Gmpq q;
        std::string why;
        if (!parse_decimal(complete_decimal_point(t.text), q, why))
          fail(t.line, where() + "bad number '" + shorten(t.text) + "': " + why);
        check_bits(q, t.line);
        advance();
        return P::constant(k_, q);
      }
      case T::IDENT: {
        if (t.text == "i" || t.text == "I")
          fail(t.line, where() + "complex coefficients are not supported ('" + t.text + "' is the imaginary unit in PHCpack)");
        auto it = var_index_.find(t.text);
        if (in_inequality_ && it == var_index_.end())
          fail(t.line, "inequality: '" + shorten(t.text) + "' is not a variable of the polynomials (" + name_list() + ")");
        if (it == var_index_.end() || it->second >= m_) {
          std::string msg = "'" + shorten(t.text) + "' is variable number " + std::to_string(m_ + 1) + ", more variables than the " +
                            std::to_string(m_) + " announced on the first line (" + name_list() + ")";
          if (!m_given_) msg += "; write \"n m\" on the first line for a system that is not square";
          fail(t.line, msg + missing_polynomials_hint());
        }
        advance();
        return P::variable(k_, it->second);
      }
      case T::LPAREN: {
        if (open_.size() >= lim_.max_nesting)
          fail(t.line, where() + "parentheses nested deeper than " + std::to_string(lim_.max_nesting) + " levels");
        open_.push_back(t.line);
        advance();
        if (cur().kind == T::RPAREN) fail(cur().line, where() + "empty parentheses '()'");
        P r = parse_sum();
        if (cur().kind != T::RPAREN) fail_at(cur());
        open_.pop_back();
        advance();
        return r;
      }
      case T::END:
        if (in_inequality_) fail(t.line, "inequality: expected a number, a variable or '(' at the end of the line");
        fail_at(t);
      case T::STAR: case T::SLASH: case T::POW:
        fail(t.line, where() + "expected a number, a variable or '(' before '" + t.text + "'" + missing_polynomials_hint());
      default:
        fail_at(t);
    }
  }

  // ------------------------------------------------------------------------------ free text
  void read_free_text(std::size_t pos, std::size_t line, Polynomial_system_file& out)
  {
    Polynomial_system<CGAL::Gmpq>& sys = out.system;
    std::vector<std::size_t> box_line(k_, 0);
    std::vector<std::pair<double, double>> own_box(k_);
    std::size_t star_line = 0;
    std::pair<double, double> star_box(-10.0, 10.0);
    bool have_title = false, in_title = false;
    while (pos <= text_.size()) {
      std::size_t e = text_.find('\n', pos);
      const std::size_t stop = (e == std::string::npos) ? text_.size() : e;
      std::size_t a = pos;
      while (a < stop && poly_is_blank(text_[a])) ++a;
      std::size_t w = a;
      while (w < stop && !poly_is_blank(text_[w])) ++w;
      const std::string word = lower_case(text_.substr(a, w - a));
      if (word == "box") {
        in_title = false;
        read_box(text_.substr(w, stop - w), line, box_line, own_box, star_line, star_box);
      } else if (word == "inequality") {
        in_title = false;
        read_inequality(w, stop, line, sys);
      } else if (a == stop) {
        in_title = false; // a blank line ends the title's paragraph
      } else if (in_title) {
        const std::string more = trim_blanks(text_.substr(a, stop - a));
        out.title += (out.title.empty() ? "" : " ") + more;
      } else if (!have_title && word.compare(0, 5, "title") == 0) {
        std::size_t c = a + 5;
        while (c < stop && (text_[c] == ' ' || text_[c] == '\t')) ++c;
        if (c < stop && text_[c] == ':') {
          out.title = trim_blanks(text_.substr(c + 1, stop - c - 1));
          have_title = in_title = true;
        }
      }
      if (e == std::string::npos) break;
      pos = e + 1;
      ++line;
    }
    out.default_box = (star_line == 0);
    sys.box.assign(k_, star_box);
    for (std::size_t i = 0; i < k_; ++i)
      if (box_line[i]) { sys.box[i] = own_box[i]; out.default_box = false; }
  }

  CGAL::Gmpq bound(const std::string& word, std::size_t line) const
  {
    CGAL::Gmpq q;
    std::string why;
    if (!parse_exact_number(complete_decimal_point(word), q, why))
      fail(line, "box: bad number '" + shorten(word) + "': " + why + " (write a number such as -1.5, 2e3 or 1/3)");
    return q;
  }

  void read_box(const std::string& rest, std::size_t line, std::vector<std::size_t>& box_line,
                std::vector<std::pair<double, double>>& own_box, std::size_t& star_line, std::pair<double, double>& star_box) const
  {
    std::vector<std::string> words;
    std::istringstream ws(rest);
    for (std::string x; ws >> x;) words.push_back(x);
    if (words.size() != 3)
      fail(line, "box: expected 'box NAME LO HI' (or 'box * LO HI'), found " + std::to_string(words.size() + 1) + " words");
    const std::string& name = words[0];
    std::size_t idx = 0;
    if (name != "*") {
      auto it = var_index_.find(name);
      if (it == var_index_.end() || it->second >= k_)
        fail(line, "box: unknown variable '" + shorten(name) + "' (the variables are " + name_list() + ")");
      idx = it->second;
      if (box_line[idx]) fail(line, "box: second box line for '" + name + "' (the first is at line " + std::to_string(box_line[idx]) + ")");
    } else if (star_line) {
      fail(line, "box: second 'box *' line (the first is at line " + std::to_string(star_line) + ")");
    }
    const CGAL::Gmpq lo = bound(words[1], line), hi = bound(words[2], line);
    if (!(lo < hi)) fail(line, "box: the lower bound " + words[1] + " is not less than the upper bound " + words[2]);
    // outward rounding: the double box contains the exact one
    const double dlo = CGAL::to_interval(lo).first, dhi = CGAL::to_interval(hi).second;
    if (!std::isfinite(dlo) || !std::isfinite(dhi) || std::abs(dlo) > 1e300 || std::abs(dhi) > 1e300)
      fail(line, "box: a bound is out of the range of a double");
    if (name == "*") { star_line = line; star_box = std::make_pair(dlo, dhi); }
    else { box_line[idx] = line; own_box[idx] = std::make_pair(dlo, dhi); }
  }

  void read_inequality(std::size_t begin, std::size_t stop, std::size_t line, Polynomial_system<CGAL::Gmpq>& sys)
  {
    Poly_lexer lex(text_, begin, stop, line); // one line: every token is on `line`
    start(lex);
    in_inequality_ = true;
    open_.clear();
    if (cur().kind == T::END) fail(line, "inequality: empty (expected 'inequality EXPR >= EXPR;' or 'inequality EXPR <= EXPR;')");
    P lhs = parse_sum();
    const T op = cur();
    if (op.kind == T::SEMI || op.kind == T::END) fail(line, "inequality without '>=' or '<='");
    if (op.kind != T::GE && op.kind != T::LE) fail_at(op);
    advance();
    P rhs = parse_sum();
    if (cur().kind == T::GE || cur().kind == T::LE) fail(line, "inequality: only one '>=' or '<=' is allowed");
    if (cur().kind != T::SEMI) fail_at(cur());
    advance();
    if (cur().kind != T::END) fail(line, "inequality: unexpected text after ';'");
    P g = (op.kind == T::GE) ? lhs : rhs;
    add_into(g, (op.kind == T::GE) ? rhs : lhs, true, line);
    store(g, line);
    sys.inequalities.push_back(g);
    std::string label = trim_blanks(text_.substr(begin, stop - begin));
    if (!label.empty() && label.back() == ';') label = trim_blanks(label.substr(0, label.size() - 1));
    sys.inequality_labels.push_back(label);
  }

  const std::string& text_;
  std::string source_;
  Polynomial_reader_limits lim_;
  std::size_t n_ = 0, m_ = 0, k_ = 0;
  bool m_given_ = false;
  Poly_lexer* lexer_ = nullptr;
  T tok_;
  std::map<std::string, std::size_t> var_index_;
  std::vector<std::string> names_;
  std::size_t poly_ = 0;
  std::size_t semicolons_in_file_ = 0;
  bool in_inequality_ = false;
  std::vector<std::size_t> open_; // lines of the open '('
  std::size_t static_cap_ = 0, total_cap_ = 0, total_terms_ = 0;
  unsigned long long work_ = 0;
};

// read_polynomial_system() with explicit limits (the test lowers them).
inline Polynomial_system_file read_polynomial_system(std::istream& in, const std::string& source_name,
                                                     const Polynomial_reader_limits& limits)
{
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Input_error(source_name + ": cannot read the input");
  return Polynomial_system_reader(text, source_name, limits).read();
}

} // namespace internal

/*!
\ingroup PkgRigidIncidenceIO
\brief Reads a polynomial system in PHCpack's input format, with optional `box` and
`inequality` directives after the polynomials.

The file starts with the number of equations n, optionally followed by the number of
variables m (default n), then n polynomials, each ended by ';' and possibly spanning lines:
sums, differences and products ('*') of numbers, variables and parenthesized expressions,
powers with '^' or '**' and a nonnegative integer exponent (at most 1000), division by a
nonzero constant only. Numbers are integers or decimals with an optional exponent
("1.5E-03", "2e4", ".5", "5."), read exactly: "0.1" is 1/10; a rational is written as a
division such as "2/3". Variables are identifiers (a letter, then letters, digits and '_',
case-sensitive), numbered in order of first appearance, as PHCpack does; there must be
exactly m of them. The imaginary unit 'i' or 'I' is refused: complex coefficients are not supported.

Whatever follows the n-th ';' is free text, which PHCpack files use for their TITLE,
ROOT COUNTS, THE SOLUTIONS ... sections. It is scanned only for lines whose first word is
one of these keywords (case-insensitive), every other line being ignored:
- `box NAME LO HI`: the search interval of variable NAME (LO < HI, numbers exact, also "p/q");
- `box * LO HI`: the interval of every variable without a line of its own (the default,
  when no `box *` line is given, is [-10, 10]);
- `inequality EXPR >= EXPR2;` or `inequality EXPR <= EXPR2;` on one line, stored as the
  constraint g >= 0 with g = EXPR - EXPR2 (resp. EXPR2 - EXPR); EXPR and EXPR2 use only
  variables of the polynomials; the label is the text of the inequality;
- `TITLE : text`: the first one gives `Polynomial_system_file::title` (continued on the
  following lines up to a blank line, as in PHCpack files, where a blank line ends each section).

A PHCpack file is thus read as is, and a file with these directives still runs through
`phc -b`: PHCpack stops reading after the n polynomials and never sees them.

The equations are labelled "equation 1" .. "equation n". The exact box bounds are rounded
outward to doubles (lower bound down, upper bound up), so the box contains the exact one.

Parentheses are expanded exactly. Rather than run out of memory or time, the reader refuses a
polynomial that would have more than one million terms (a product of factors with t1 and t2
terms counts as t1*t2 while it is expanded), a system with more than one million terms in all
(fewer when there are more than 33 variables: terms times variables is at most 2^25), more than
ten million term-by-term products to expand the whole file, coefficients beyond 262144 bits,
degrees beyond 100000, parentheses nested deeper than 200 levels and counts above 100000.

`source_name` names the input in error messages.
\throws Input_error whose message is "SOURCE:LINE: message", for a missing or bad count,
fewer polynomials than announced, a missing ';', an unexpected character, unbalanced
parentheses, a bad exponent, division by a non-constant or by zero, complex coefficients,
more or fewer variables than announced, a bad `box` line (unknown variable, LO >= HI, bad
number), a bad `inequality` line (no ">=" or "<=", a variable not in the equations, no ';'),
and the limits above.
*/
inline Polynomial_system_file read_polynomial_system(std::istream& in, const std::string& source_name = "input")
{
  return internal::read_polynomial_system(in, source_name, internal::Polynomial_reader_limits());
}

/// \ingroup PkgRigidIncidenceIO
/// Reads a polynomial system from the file `path` (see the stream version); error messages
/// name `path`. \throws Input_error also when the file cannot be opened.
inline Polynomial_system_file read_polynomial_system(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Input_error(path + ": cannot open the file");
  return read_polynomial_system(in, path);
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
