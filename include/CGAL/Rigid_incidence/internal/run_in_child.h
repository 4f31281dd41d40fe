// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A computation that cannot be stopped from inside (one exact sign of CORE::Expr that is 0
// costs a root bound, which ran for over 20 minutes in a deep tower, and CORE checks no clock)
// run in a child process that is killed at a time limit: the caller's time limit then holds
// whatever the computation does. The child sends its answer back as a string.

#ifndef CGAL_RIGID_INCIDENCE_INTERNAL_RUN_IN_CHILD_H
#define CGAL_RIGID_INCIDENCE_INTERNAL_RUN_IN_CHILD_H

#include <CGAL/Interval_nt.h>
#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#include <CGAL/Gmpfr.h>
#endif

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#define CGAL_RIGID_INCIDENCE_HAS_FORK 1
#include <cerrno>
#include <csignal>
#include <poll.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

/// What stops a wait for a child process on this thread early: the interrupt flag and the
/// deadline of the solve that runs on it (set by a Wait_stop_scope for the solve's duration).
struct Wait_stop
{
  const std::atomic<bool>* interrupt = nullptr;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  bool now() const
  {
    return (interrupt && interrupt->load(std::memory_order_relaxed)) || std::chrono::steady_clock::now() >= deadline;
  }
};

inline Wait_stop& wait_stop()
{
  thread_local Wait_stop s;
  return s;
}

class Wait_stop_scope
{
public:
  /// `seconds` <= 0: no deadline of its own. Scopes nest: the earlier deadline holds.
  Wait_stop_scope(const std::atomic<bool>* interrupt, double seconds) : saved_(wait_stop())
  {
    Wait_stop& s = wait_stop();
    if (interrupt) s.interrupt = interrupt;
    if (seconds > 0) {
      const auto d = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds < 1e9 ? seconds : 1e9));
      if (d < s.deadline) s.deadline = d;
    }
  }
  ~Wait_stop_scope() { wait_stop() = saved_; }
  Wait_stop_scope(const Wait_stop_scope&) = delete;
  Wait_stop_scope& operator=(const Wait_stop_scope&) = delete;

private:
  Wait_stop saved_;
};

struct Child_run
{
  enum Status {
    DONE,        ///< `answer` is the child's answer
    TIMED_OUT,   ///< killed at the time limit
    STOPPED,     ///< killed when the caller's solve was interrupted or reached its own limit (wait_stop())
    FAILED,      ///< the child threw, died or sent a broken answer: `why`
    NOT_STARTED  ///< no child process on this system (or fork() failed): run it here
  };
  Status status = NOT_STARTED;
  std::string answer;
  std::string why;
};

/// Runs `work()` (returning a std::string) in a child process and returns its answer, or
/// TIMED_OUT after `seconds`, or STOPPED when wait_stop() says so (the child is killed). The child touches none of the caller's
/// state: it only computes, writes its answer to a pipe and ends with _exit (no destructor
/// of the parent's objects runs twice). NOT_STARTED where there is no fork().
template <class Work>
Child_run run_in_child(Work&& work, double seconds)
{
  Child_run r;
#ifdef CGAL_RIGID_INCIDENCE_HAS_FORK
  int fd[2];
  if (::pipe(fd) != 0) return r;
  std::fflush(nullptr);  // (buffered output would otherwise be written by both processes)
  const pid_t pid = ::fork();
  if (pid < 0) { ::close(fd[0]); ::close(fd[1]); return r; }
  if (pid == 0) {
    ::close(fd[0]);
    std::string out;
    char status = 'D';
    try { out = work(); }
    catch (const std::exception& e) { status = 'F'; out = e.what(); }
    catch (...) { status = 'F'; out = "an exception of unknown type"; }
    out.insert(out.begin(), status);
    const char* p = out.data();
    std::size_t left = out.size();
    while (left > 0) {
      const ssize_t w = ::write(fd[1], p, left);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) ::_exit(3);
      p += w; left -= std::size_t(w);
    }
    ::_exit(0);
  }
  ::close(fd[1]);
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
  std::string in;
  bool timed_out = false, stopped = false;
  char buf[65536];
  while (true) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) { timed_out = true; break; }
    if (wait_stop().now()) { stopped = true; break; }
    const long ms = long(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1;
    pollfd pf{fd[0], POLLIN, 0};
    const int k = ::poll(&pf, 1, int(ms < 100 ? ms : 100));
    if (k < 0 && errno != EINTR) break;
    if (k <= 0) continue;
    const ssize_t n = ::read(fd[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of the answer (or a read error: the answer is checked below)
    in.append(buf, std::size_t(n));
  }
  ::close(fd[0]);
  if (timed_out || stopped) ::kill(pid, SIGKILL);
  int wstatus = 0;
  while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {}
  if (timed_out || stopped) { r.status = timed_out ? Child_run::TIMED_OUT : Child_run::STOPPED; return r; }
  if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0 || in.empty()) {
    r.status = Child_run::FAILED;
    r.why = WIFSIGNALED(wstatus) ? "the process of the exact decisions ended by signal " + std::to_string(WTERMSIG(wstatus))
                                  : "the process of the exact decisions ended without an answer";
    return r;
  }
  if (in[0] != 'D') { r.status = Child_run::FAILED; r.why = in.substr(1); return r; }
  r.status = Child_run::DONE;
  r.answer = in.substr(1);
#else
  (void)work; (void)seconds;
#endif
  return r;
}

// A string of numbers, flags and texts, read back exactly (doubles and MPFR numbers in
// hexadecimal): the child's answer.
class Answer_writer
{
public:
  void integer(long long v) { s_ += std::to_string(v); s_ += ' '; }
  void text(const std::string& t) { integer((long long)t.size()); s_ += t; }
  void real(double d)
  {
    char b[64];
    std::snprintf(b, sizeof b, "%a ", d);
    s_ += b;
  }
  template <bool P> void number(const CGAL::Interval_nt<P>& x) { real(x.inf()); real(x.sup()); }
#ifdef CGAL_USE_MPFI
  void number(const CGAL::Gmpfi& x)
  {
    integer((long long)x.get_precision());
    mpfr(x.left_mpfr());
    mpfr(x.right_mpfr());
  }
#endif
  const std::string& str() const { return s_; }

private:
#ifdef CGAL_USE_MPFI
  void mpfr(mpfr_srcptr x)
  {
    integer((long long)mpfr_get_prec(x));
    if (mpfr_nan_p(x)) { text("@NaN@"); return; }
    if (mpfr_inf_p(x)) { text(mpfr_sgn(x) > 0 ? "@Inf@" : "-@Inf@"); return; }
    mpfr_exp_t e = 0;
    char* d = mpfr_get_str(nullptr, &e, 16, 0, x, MPFR_RNDN);  // exact in base 16
    std::string t(d);
    mpfr_free_str(d);
    const bool neg = !t.empty() && t[0] == '-';
    if (neg) t.erase(0, 1);
    text(std::string(neg ? "-" : "") + "0." + t + "@" + std::to_string((long long)e));
  }
#endif
  std::string s_;
};

class Answer_reader
{
public:
  explicit Answer_reader(const std::string& s) : s_(s) {}
  long long integer()
  {
    const std::size_t e = s_.find(' ', i_);
    if (e == std::string::npos) throw std::runtime_error("a broken answer from the process of the exact decisions");
    const long long v = std::stoll(s_.substr(i_, e - i_));
    i_ = e + 1;
    return v;
  }
  std::string text()
  {
    const long long n = integer();
    if (n < 0 || std::size_t(n) > s_.size() - i_) throw std::runtime_error("a broken answer from the process of the exact decisions");
    std::string t = s_.substr(i_, std::size_t(n));
    i_ += std::size_t(n);
    return t;
  }
  double real()
  {
    const std::size_t e = s_.find(' ', i_);
    if (e == std::string::npos) throw std::runtime_error("a broken answer from the process of the exact decisions");
    const double v = std::strtod(s_.substr(i_, e - i_).c_str(), nullptr);
    i_ = e + 1;
    return v;
  }
  template <bool P> void number(CGAL::Interval_nt<P>& x)
  {
    const double a = real(), b = real();
    x = CGAL::Interval_nt<P>(a, b);
  }
#ifdef CGAL_USE_MPFI
  void number(CGAL::Gmpfi& x)
  {
    const long long p = integer();
    const CGAL::Gmpfr a = mpfr(), b = mpfr();
    x = CGAL::Gmpfi(a, b, CGAL::Gmpfi::Precision_type(p));  // (exact: each end has at most p bits)
  }
#endif
  bool at_end() const { return i_ == s_.size(); }

private:
#ifdef CGAL_USE_MPFI
  CGAL::Gmpfr mpfr()
  {
    const long long p = integer();
    const std::string t = text();
    if (p < MPFR_PREC_MIN || p > MPFR_PREC_MAX) throw std::runtime_error("a broken number in the answer of the process of the exact decisions");
    CGAL::Gmpfr g;  // (its own number: the constructors from an mpfr_t share the digits)
    mpfr_set_prec(g.fr(), mpfr_prec_t(p));
    if (mpfr_set_str(g.fr(), t.c_str(), 16, MPFR_RNDN) != 0)
      throw std::runtime_error("a broken number in the answer of the process of the exact decisions");
    return g;
  }
#endif
  const std::string& s_;
  std::size_t i_ = 0;
};

} // namespace internal
} // namespace Rigid_incidence
} // namespace CGAL

#endif // CGAL_RIGID_INCIDENCE_INTERNAL_RUN_IN_CHILD_H
