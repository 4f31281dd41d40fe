// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// internal/run_in_child.h: the exact decisions of a body run in a child process killed at
// their time limit (one exact sign of CORE::Expr can run for minutes and checks no clock).
// Oracles: the child's answer byte for byte; the clock (a child that never ends is killed
// within the limit and reaped; the solve's interrupt and time limit cut the wait); the numbers read back bit for bit (doubles, MPFR ends of
// Gmpfi intervals at several precisions); a broken answer refused.

#include <CGAL/Rigid_incidence/internal/run_in_child.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include "test_check.h"
#include <thread>

#ifdef CGAL_RIGID_INCIDENCE_HAS_FORK
#include <sys/wait.h>
#endif

namespace RIi = CGAL::Rigid_incidence::internal;


static double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

static void child_runs()
{
#ifdef CGAL_RIGID_INCIDENCE_HAS_FORK
  // an answer larger than a pipe's buffer, with every byte value
  std::string big;
  for (std::size_t k = 0; k < 300000; ++k) big.push_back(char(k * 7 % 256));
  RIi::Child_run r = RIi::run_in_child([&] { return big; }, 30);
  CHECK(r.status == RIi::Child_run::DONE && r.answer == big, "a 300 kB answer comes back whole");

  // the parent's memory is the child's at the fork, and the child's changes stay there
  int here = 41;
  r = RIi::run_in_child([&] { ++here; return std::to_string(here); }, 30);
  CHECK(r.status == RIi::Child_run::DONE && r.answer == "42" && here == 41, "the child works on a copy");

  // a child that never ends: killed at the limit, reaped
  const auto t0 = std::chrono::steady_clock::now();
  r = RIi::run_in_child([] {
    volatile unsigned long spin = 0;
    while (true) ++spin;
    return std::string();
  }, 0.5);
  const double took = seconds_since(t0);
  CHECK(r.status == RIi::Child_run::TIMED_OUT, "an endless child times out");
  CHECK(took >= 0.45 && took < 5, "killed at the limit of 0.5 s, not after " << took << " s");
  int ws = 0;
  CHECK(::waitpid(-1, &ws, WNOHANG) < 0, "no child is left behind");

  // the solve's interrupt (from another thread) and its time limit cut the wait
  auto endless = [] {
    volatile unsigned long spin = 0;
    while (true) ++spin;
    return std::string();
  };
  {
    std::atomic<bool> interrupt{false};
    RIi::Wait_stop_scope scope(&interrupt, 0);
    std::thread t([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      interrupt.store(true);
    });
    const auto t1 = std::chrono::steady_clock::now();
    r = RIi::run_in_child(endless, 30);
    const double cut = seconds_since(t1);
    t.join();
    CHECK(r.status == RIi::Child_run::STOPPED && cut < 5, "an interrupt cuts the wait (after " << cut << " s)");
  }
  {
    RIi::Wait_stop_scope outer(nullptr, 0.3);
    RIi::Wait_stop_scope inner(nullptr, 100);  // (the earlier deadline holds)
    const auto t1 = std::chrono::steady_clock::now();
    r = RIi::run_in_child(endless, 30);
    const double cut = seconds_since(t1);
    CHECK(r.status == RIi::Child_run::STOPPED && cut >= 0.25 && cut < 5, "the solve's time limit cuts the wait (after " << cut << " s)");
  }
  CHECK(RIi::wait_stop().interrupt == nullptr && !RIi::wait_stop().now(), "the scopes restore what was before them");
  r = RIi::run_in_child([] { return std::string("after"); }, 30);
  CHECK(r.status == RIi::Child_run::DONE && r.answer == "after", "a wait after the scopes is not cut");

  // a child that throws: its message
  r = RIi::run_in_child([]() -> std::string { throw std::runtime_error("three points exactly on a line"); }, 30);
  CHECK(r.status == RIi::Child_run::FAILED && r.why == "three points exactly on a line", "a thrown error comes back: " << r.why);

  // a child that dies: the signal
  r = RIi::run_in_child([]() -> std::string { std::abort(); }, 30);
  CHECK(r.status == RIi::Child_run::FAILED && r.why.find("signal " + std::to_string(SIGABRT)) != std::string::npos,
        "a child that aborts is reported by its signal: " << r.why);
  std::cout << "child runs: done, timed out after " << took << " s, failed, died\n";
#else
  std::cout << "no fork() here: the exact decisions run in the process, stopped between steps\n";
#endif
}

template <class I>
static bool same_bits(const I& a, const I& b)
{
  return (a.inf() == b.inf() || (std::isnan(a.inf()) && std::isnan(b.inf()))) && a.sup() == b.sup() &&
         std::signbit(a.inf()) == std::signbit(b.inf()) && std::signbit(a.sup()) == std::signbit(b.sup());
}

static void answers_read_back()
{
  typedef CGAL::Interval_nt<false> I;
  const double inf = std::numeric_limits<double>::infinity();
  const I values[] = {I(-inf, inf), I(0.1, 0.30000000000000004), I(-0.0, 0.0), I(4.9e-324, 2.2250738585072014e-308),
                      I(-1.7976931348623157e308, -1e300), I(1) / I(3)};
  RIi::Answer_writer w;
  w.text("body 'b0': a text with\nnew lines and  spaces ");
  w.integer(-12345678901234LL);
  for (const I& v : values) w.number(v);
#ifdef CGAL_USE_MPFI
  std::vector<CGAL::Gmpfi> big;
  for (unsigned bits : {53u, 128u, 300u, 4096u}) {
    CGAL::Gmpfi two(2, bits);
    big.push_back(CGAL::sqrt(two));
    big.push_back(-CGAL::Gmpfi(CGAL::Gmpq(1, 3), bits) * CGAL::Gmpfi(CGAL::Gmpq(1) / CGAL::Gmpq(1048576) / CGAL::Gmpq(1048576), bits));
  }
  for (const auto& g : big) w.number(g);
#endif
  w.text("");
  RIi::Answer_reader r(w.str());
  CHECK(r.text() == "body 'b0': a text with\nnew lines and  spaces ", "a text read back");
  CHECK(r.integer() == -12345678901234LL, "an integer read back");
  for (const I& v : values) {
    I x;
    r.number(x);
    CHECK(same_bits(x, v), "a double interval read back bit for bit: " << v << " gave " << x);
  }
#ifdef CGAL_USE_MPFI
  for (const auto& g : big) {
    CGAL::Gmpfi x;
    r.number(x);
    CHECK(x.get_precision() == g.get_precision() && mpfr_equal_p(x.left_mpfr(), g.left_mpfr()) &&
              mpfr_equal_p(x.right_mpfr(), g.right_mpfr()),
          "a Gmpfi interval at " << g.get_precision() << " bits read back exactly");
  }
#endif
  CHECK(r.text().empty() && r.at_end(), "the answer read to its end");

  // broken answers are refused, never read as numbers
  for (const std::string bad : {std::string("12 short"), std::string("7"), std::string("-3 abc")}) {
    bool refused = false;
    try {
      RIi::Answer_reader b(bad);
      (void)b.text();
    } catch (const std::exception&) { refused = true; }
    CHECK(refused, "a broken answer is refused: '" << bad << "'");
  }
}

int main()
{
  child_runs();
  answers_read_back();
  if (failures) { std::cerr << failures << " failure(s)\n"; return 1; }
  std::cout << "all run_in_child checks passed\n";
  return 0;
}
