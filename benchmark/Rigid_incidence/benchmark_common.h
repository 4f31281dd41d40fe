// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the benchmark programs (benchmark_reduced_system, benchmark_solver) share: the kernel
// and the folder of the paper scenes, number and text formatting for their tables, the description of the machine in the Markdown header, the
// opening of the SVG chart, and the runner of one cell in a forked child process with a time
// limit.

#ifndef RIGID_INCIDENCE_BENCHMARK_COMMON_H
#define RIGID_INCIDENCE_BENCHMARK_COMMON_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Rigid_incidence.h>

#include <cmath>
#include <cstddef>
#include <ctime>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <new>
#include <ostream>
#include <sstream>
#include <string>

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

// The folder of the paper scenes' JSON files (CMake passes the source tree's).
#ifndef RIGID_INCIDENCE_DATA_DIR
#define RIGID_INCIDENCE_DATA_DIR "examples/Rigid_incidence/data"
#endif

// The scenes are read and built with exact rational coordinates.
namespace RI = CGAL::Rigid_incidence;
typedef CGAL::Simple_cartesian<CGAL::Gmpq> K;
typedef RI::Rigid_incidence_traits<K> Traits;
typedef RI::Rigid_body_collection<Traits> Collection;

namespace benchmark_common {

// ------------------------------------------------------------------ formatting
// `x` with `prec` significant digits (the stream's default notation).
inline std::string fmt(double x, int prec = 3)
{
  std::ostringstream os;
  os << std::setprecision(prec) << x;
  return os.str();
}

// `x` with `prec` digits after the point.
inline std::string fixed(double x, int prec)
{
  std::ostringstream os;
  os << std::fixed << std::setprecision(prec) << x;
  return os.str();
}

// A ratio for a table: "–" when not finite, 2 significant digits below 0.1, else 2, 1 or 0
// decimals as it grows.
inline std::string ratio_text(double r)
{
  if (!std::isfinite(r)) return "–";
  if (r < 0.1) return fmt(r, 2);
  return fixed(r, r < 10 ? 2 : (r < 100 ? 1 : 0));
}

// Text for a Markdown table cell: no '|' and no line break.
inline std::string md_escape(std::string s)
{
  for (char& ch : s) if (ch == '|' || ch == '\n') ch = ' ';
  return s;
}

// Text for a CSV field: no ',', '"' or line break.
inline std::string csv_escape(std::string s)
{
  for (char& ch : s) if (ch == ',' || ch == '"' || ch == '\n') ch = ';';
  return s;
}

// ------------------------------------------------------------------ the Markdown header
// The "model name" of /proc/cpuinfo, or "unknown CPU".
inline std::string cpu_model()
{
  std::string cpu = "unknown CPU";
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) { cpu = line.substr(line.find(':') + 2); break; }
  return cpu;
}

// The operating system and its release (uname), e.g. "Linux 6.8.0".
inline std::string os_release()
{
  struct utsname u;
  uname(&u);
  return std::string(u.sysname) + " " + u.release;
}

// The command line, its words separated by single spaces.
inline std::string command_line(int argc, char** argv)
{
  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  return command;
}

// The current date and time, e.g. "2026-01-31 12:00 UTC".
inline std::string utc_date()
{
  std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return date;
}

// ------------------------------------------------------------------ SVG
// The XML declaration, the <svg> element of `width` x `height` (sans-serif, 11 px) and a white
// background; the caller writes the chart and the closing </svg>.
inline void svg_open(std::ostream& svg, int width, int height)
{
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width
      << " " << height << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

// ------------------------------------------------------------------ a cell in a child process
// The address space a cell's child process may use.
const std::size_t cell_memory_bytes = std::size_t(8) << 30;

// What the parent got from the child of run_forked().
struct Forked
{
  std::string failure;    // "pipe() failed" or "fork() failed" (nothing ran); else empty
  std::string text;       // the bytes the child sent, possibly cut short
  bool timed_out = false; // the child was killed at the time limit
  int wstatus = 0;        // of waitpid()
  double seconds = 0;     // wall clock from the fork to the child's end
};

// Runs `build()` (returning a Result) in a forked child process limited to 8 GiB of address
// space. An exception there gives a default Result whose message `set_message(result, text)`
// sets ("out of memory (8 GiB)" for std::bad_alloc, else what()). The child sends back
// `encode(result)` through a pipe and exits; the parent reads until the child closes the pipe
// and kills the child when `limit` seconds (wall clock) have passed.
template <class Result, class Build, class Set_message, class Encode>
Forked run_forked(Build build, Set_message set_message, Encode encode, double limit)
{
  std::cout.flush();
  std::cerr.flush();
  Forked out;
  int fd[2];
  if (pipe(fd) != 0) { out.failure = "pipe() failed"; return out; }
  pid_t pid = fork();
  if (pid < 0) { out.failure = "fork() failed"; close(fd[0]); close(fd[1]); return out; }
  if (pid == 0) {
    close(fd[0]);
    struct rlimit lim;
    lim.rlim_cur = lim.rlim_max = rlim_t(cell_memory_bytes); // 8 GiB of address space per cell
    setrlimit(RLIMIT_AS, &lim);
    Result r;
    try {
      r = build();
    } catch (const std::bad_alloc&) {
      r = Result();
      set_message(r, "out of memory (8 GiB)");
    } catch (const std::exception& e) {
      r = Result();
      set_message(r, e.what());
    }
    const std::string text = encode(r);
    std::size_t put = 0;
    while (put < text.size()) {
      ssize_t w = write(fd[1], text.data() + put, text.size() - put);
      if (w <= 0) break;
      put += std::size_t(w);
    }
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  CGAL::Real_timer wall;
  wall.start();
  char buf[65536];
  for (;;) {
    double left = limit - wall.time();
    if (left <= 0) { out.timed_out = true; break; }
    struct pollfd p = {fd[0], POLLIN, 0};
    int k = poll(&p, 1, int(std::ceil(left * 1000)));
    if (k == 0) { out.timed_out = true; break; }
    if (k < 0) continue;
    ssize_t m = read(fd[0], buf, sizeof buf);
    if (m <= 0) break;
    out.text.append(buf, std::size_t(m));
  }
  close(fd[0]);
  if (out.timed_out) kill(pid, SIGKILL);
  waitpid(pid, &out.wstatus, 0);
  out.seconds = wall.time();
  return out;
}

} // namespace benchmark_common

#endif // RIGID_INCIDENCE_BENCHMARK_COMMON_H
