// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Benchmark of the subdivision solver on the paper scenes (tetra, tetra ii, quad_distinct,
// pent iv) and on the Stewart-Gough platform with 40 real assembly modes, in four parts:
//   1. time and boxes against the tolerance: 1e-3, 1e-6, 1e-9, 1e-12 with Interval_nt<false>
//      (double), 1e-20 and 1e-30 with Gmpfi at 113 bits, 1e-60 at 256 bits (with MPFI); the
//      achieved accuracy is the largest distance (max norm over the parameters) of a root's
//      enclosure midpoint to the nearest root of a 512-bit Gmpfi reference solve (tolerance
//      1e-100) in the same chart combination;
//   2. the fast, non-certified mode against the certified one, through solve_scene() (the
//      pipeline of `rigid_incidence solve`): time and configurations;
//   3. the reduced system against the naive formulations (naive_system(), 12 x 12 quaternion
//      and 18 x 18 trigonometric for tetra) under the same solver and time limit;
//   4. PHCpack (`phc -b`, when installed): every chart combination of the reduced system and
//      the naive systems written in PHCpack's input format, its real solutions (inside the
//      chart's box) against ours, and its time.
// Written as PREFIX.md (Markdown), PREFIX.csv and PREFIX.svg (time against achieved accuracy,
// log-log, one line per scene).
//
// Every cell (one solver configuration on one scene, all its repeats) runs in a child process
// (fork) with a time budget: the solver's own budget (maximal_seconds: each chart combination
// gets what the previous ones left; solve_scene() splits it evenly) stops it and reports what is
// left as pending; the child is killed if it outlives the budget by 30 s, and a naive system
// whose dense Bernstein arrays cannot fit in the 8 GiB a cell may use is not attempted. Times
// are the CPU time of the solver calls (the machine may be shared; wall-clock times are in the
// CSV), the median of REPEATS repeats; a cell whose repeats take more than 3 s together is not
// repeated further. PHCpack gets the same budget per scene (its chart combinations in turn) and
// per naive system. The default run takes about 3 to 5 minutes on 2 cores.
//
// Usage: benchmark_solver [RESULTS_PREFIX (solver)] [REPEATS (3)] [CAP_SECONDS (20)]
//                         [STEWART_CAP_SECONDS (10)] [PHC (phc)] [SCENES (all; e.g. tetra,pent)]
// With BENCHMARK_SOLVER_KEEP_PHC set in the environment the PHCpack input and output files are
// kept (their folder is printed).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Rigid_incidence.h>
#ifdef CGAL_USE_MPFI
#include <CGAL/Gmpfi.h>
#endif

#include "benchmark_common.h" // RI, K, Traits, Collection, RIGID_INCIDENCE_DATA_DIR, helpers

#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

typedef CGAL::Interval_nt<false> Dbl;

static const std::size_t no_box_limit = std::size_t(1) << 40; // only the time budget stops a cell
static const double cell_memory = double(benchmark_common::cell_memory_bytes); // the address-space limit of a cell

// ------------------------------------------------------------------ formatting
using benchmark_common::csv_escape;
using benchmark_common::fixed;
using benchmark_common::fmt;
using benchmark_common::md_escape;
using benchmark_common::ratio_text;

static std::string seconds_text(double s)
{
  if (s < 1e-3) return fmt(s * 1e3, 2) + " ms";
  if (s < 1) return fmt(s * 1e3, 3) + " ms";
  return fixed(s, s < 10 ? 2 : 1) + " s";
}

static double cpu_now()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

static double median(std::vector<double> v)
{
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// ------------------------------------------------------------------ high-precision numbers
// Root midpoints travel from the child processes as decimal strings and are compared with
// MPFR at 2200 bits (enough for the exact midpoint of two doubles, or of two 512-bit bounds).
static const mpfr_prec_t wide = 2200;

struct Mp
{
  mpfr_t v;
  Mp() { mpfr_init2(v, wide); mpfr_set_zero(v, 1); }
  explicit Mp(const std::string& s) { mpfr_init2(v, wide); mpfr_set_str(v, s.c_str(), 10, MPFR_RNDN); }
  Mp(const Mp& o) { mpfr_init2(v, wide); mpfr_set(v, o.v, MPFR_RNDN); }
  Mp& operator=(const Mp& o) { mpfr_set(v, o.v, MPFR_RNDN); return *this; }
  ~Mp() { mpfr_clear(v); }
};

static std::string mp_string(mpfr_srcptr x, int digits)
{
  char* s = nullptr;
  mpfr_asprintf(&s, "%.*Re", digits, x);
  std::string out(s);
  mpfr_free_str(s);
  return out;
}

// |a - b| rounded to double
static double mp_distance(const Mp& a, const Mp& b)
{
  Mp d;
  mpfr_sub(d.v, a.v, b.v, MPFR_RNDN);
  return std::abs(mpfr_get_d(d.v, MPFR_RNDU));
}

// midpoint (as a decimal string with enough digits to be exact to the working precision) and
// width of an interval of the solver
static std::pair<std::string, double> midpoint_and_width(const Dbl& x)
{
  Mp m;
  mpfr_set_d(m.v, x.inf(), MPFR_RNDN);
  mpfr_add_d(m.v, m.v, x.sup(), MPFR_RNDN);
  mpfr_div_2ui(m.v, m.v, 1, MPFR_RNDN);
  Mp w;
  mpfr_set_d(w.v, x.sup(), MPFR_RNDN);
  mpfr_sub_d(w.v, w.v, x.inf(), MPFR_RNDN);
  return {mp_string(m.v, 25), mpfr_get_d(w.v, MPFR_RNDU)};
}

#ifdef CGAL_USE_MPFI
static std::pair<std::string, double> midpoint_and_width(const CGAL::Gmpfi& x)
{
  const CGAL::Gmpfr lo = x.inf(), hi = x.sup();
  Mp m, w;
  mpfr_add(m.v, lo.fr(), hi.fr(), MPFR_RNDN);
  mpfr_div_2ui(m.v, m.v, 1, MPFR_RNDN);
  mpfr_sub(w.v, hi.fr(), lo.fr(), MPFR_RNDN);
  const int digits = int(std::ceil(double(mpfr_get_prec(lo.fr())) * 0.30103)) + 6;
  return {mp_string(m.v, digits), mpfr_get_d(w.v, MPFR_RNDU)};
}
#endif

// ------------------------------------------------------------------ what a cell returns
enum Status { OK = 0, ERROR = 1, TIMEOUT = 2, DIED = 3, NOT_RUN = 4 };

struct Root_record
{
  long combination = 0;              // index of the chart combination (x placement)
  std::vector<std::string> midpoint; // per variable, decimal
};

struct Record
{
  int status = ERROR;
  std::string message;
  int repeats = 0;
  double cpu = 0, wall = 0;          // medians over the repeats; the solver calls only
  long vars = 0, eqs = 0, combinations = 0;
  long boxes = 0, roots = 0, certified = 0, unknown = 0, pending = 0;
  long configurations = -1, configurations_certified = -1;
  bool complete = false;
  double widest = 0;                 // widest enclosure of a root, over all its variables
  double cell_seconds = 0;           // wall clock of the whole cell (set by run_cell, not sent)
  std::string reasons;               // of the unresolved regions
  std::vector<double> combination_cpu; // per chart combination, CPU seconds (last repeat)
  std::vector<Root_record> root_list;
};

static std::string one_line(std::string s)
{
  for (char& ch : s) if (ch == '\n' || ch == '\r') ch = ' ';
  return s;
}

static std::string serialize(const Record& r)
{
  std::ostringstream os;
  os << std::setprecision(17);
  os << "status " << r.status << "\nmessage " << one_line(r.message) << "\nreasons " << one_line(r.reasons) << "\nnumbers "
     << r.repeats << " " << r.cpu << " " << r.wall << " " << r.vars << " " << r.eqs << " " << r.combinations << " " << r.boxes
     << " " << r.roots << " " << r.certified << " " << r.unknown << " " << r.pending << " " << r.configurations << " "
     << r.configurations_certified << " " << int(r.complete) << " " << r.widest << "\n";
  os << "combination_cpu";
  for (double c : r.combination_cpu) os << " " << c;
  os << "\n";
  for (const auto& x : r.root_list) {
    os << "root " << x.combination << " " << x.midpoint.size();
    for (const auto& v : x.midpoint) os << " " << v;
    os << "\n";
  }
  os << "end\n";
  return os.str();
}

static bool deserialize(const std::string& text, Record& r)
{
  std::istringstream in(text);
  std::string line;
  bool end = false;
  while (std::getline(in, line)) {
    const std::size_t sp = line.find(' ');
    const std::string key = line.substr(0, sp), rest = sp == std::string::npos ? "" : line.substr(sp + 1);
    if (key == "status") r.status = std::stoi(rest);
    else if (key == "message") r.message = rest;
    else if (key == "reasons") r.reasons = rest;
    else if (key == "numbers") {
      std::istringstream n(rest);
      int complete = 0;
      n >> r.repeats >> r.cpu >> r.wall >> r.vars >> r.eqs >> r.combinations >> r.boxes >> r.roots >> r.certified >> r.unknown >>
          r.pending >> r.configurations >> r.configurations_certified >> complete >> r.widest;
      r.complete = complete != 0;
    } else if (key == "combination_cpu") {
      std::istringstream n(rest);
      for (double c; n >> c;) r.combination_cpu.push_back(c);
    } else if (key == "root") {
      std::istringstream n(rest);
      Root_record x;
      std::size_t k = 0;
      n >> x.combination >> k;
      x.midpoint.resize(k);
      for (auto& v : x.midpoint) n >> v;
      r.root_list.push_back(x);
    } else if (key == "end") end = true;
  }
  return end;
}

// Runs `f` (returning a Record) in a child process; kills it `grace` seconds after `budget`.
template <class F>
Record run_cell(F f, double budget, double grace = 30)
{
  const benchmark_common::Forked child = benchmark_common::run_forked<Record>(
      f, [](Record& r, const std::string& m) { r.message = m; }, serialize, budget + grace);
  Record s;
  if (!child.failure.empty()) { s.message = child.failure; return s; }
  if (child.timed_out) {
    s.status = TIMEOUT;
    s.message = "killed after " + fmt(budget + grace) + " s";
  } else if (!deserialize(child.text, s)) {
    s = Record();
    s.status = DIED;
    s.message = WIFSIGNALED(child.wstatus) ? "the cell died (signal " + std::to_string(WTERMSIG(child.wstatus)) + ")" : "the cell died";
  }
  s.cell_seconds = child.seconds;
  if (s.status == ERROR && s.message.rfind("out of memory", 0) == 0) s.message += " after " + fmt(child.seconds, 2) + " s";
  return s;
}

// ------------------------------------------------------------------ scenes
struct Analysis
{
  std::string name;
  Collection user, c;
  RI::Incidence_tree tree;
  RI::Well_formed_selection selection;
  bool exact = true;            // every covering body has coordinates: Gmpq coefficients
  long vars = 0, eqs = 0, combinations = 0;
  bool square = false;
  std::string diagnostic;
  long expected = -1;           // configurations the papers (or the scene file) report
  bool long_scene = false;      // its own budget, at 1e-12 in double only
};

template <class Parametrization>
std::vector<int> chart_radix(const Parametrization& p)
{
  std::vector<int> r;
  for (const auto& e : p.edges()) r.push_back(e.number_of_charts);
  return r;
}

// The reduced system of every chart combination and placement, in the order solve_scene()
// visits them.
template <class NT>
std::vector<RI::Polynomial_system<NT>> reduced_systems(const Analysis& a)
{
  std::vector<RI::Polynomial_system<NT>> out;
  std::vector<int> radix_p = RI::internal::placement_counts(a.c, a.tree), placements(a.c.number_of_bodies(), 0);
  std::vector<int> radix_c;
  {
    RI::Reduced_system<Traits, NT> first(a.c, a.tree, a.selection);
    if (!first.is_square()) throw RI::Input_error("the reduced system is not square: " + first.diagnostic());
    radix_c = chart_radix(first.parametrization());
  }
  do {
    std::vector<int> charts(radix_c.size(), 0);
    do {
      RI::Reduced_system<Traits, NT> r(a.c, a.tree, a.selection, charts, RI::Rotation_form::QUATERNION_CHARTS, placements);
      out.push_back(r.system());
    } while (RI::internal::next_combination(charts, radix_c));
  } while (RI::internal::next_combination(placements, radix_p));
  return out;
}

// Solves every system with Subdivision_solver<IT>, REPEATS times (fewer when slow); counts,
// median times and (with keep_roots) every root's enclosure midpoint.
template <class IT, class NT>
Record solve_systems(const std::vector<RI::Polynomial_system<NT>>& systems, RI::Subdivision_solver_parameters p, double budget,
                     int repeats, bool keep_roots)
{
  Record rec;
  if (systems.empty()) { rec.message = "no system"; return rec; }
  rec.vars = long(systems.front().number_of_variables());
  rec.eqs = long(systems.front().number_of_equations());
  rec.combinations = long(systems.size());
  p.maximal_boxes = no_box_limit;
  std::vector<double> cpus, walls;
  std::vector<RI::Solver_result<IT>> last;
  double spent = 0;
  for (int rep = 0; rep < std::max(1, repeats); ++rep) {
    last.clear();
    rec.combination_cpu.clear();
    double w = 0;
    const double c0 = cpu_now();
    for (const auto& s : systems) {
      // each chart combination gets what the previous ones left of the budget
      p.maximal_seconds = std::max(0.05 * budget / double(systems.size()), budget - w);
      const double c1 = cpu_now();
      last.push_back(RI::Subdivision_solver<IT>(p).solve(s));
      rec.combination_cpu.push_back(cpu_now() - c1);
      w += last.back().statistics.seconds;
    }
    cpus.push_back(cpu_now() - c0);
    walls.push_back(w);
    spent += w;
    if (spent > 3) break;
  }
  rec.repeats = int(cpus.size());
  rec.cpu = median(cpus);
  rec.wall = median(walls);
  rec.complete = true;
  std::set<std::string> reasons;
  for (std::size_t k = 0; k < last.size(); ++k) {
    const auto& res = last[k];
    rec.boxes += long(res.statistics.boxes);
    rec.complete = rec.complete && res.complete();
    for (const auto& u : res.unresolved) {
      (u.kind == RI::Box_class::PENDING ? rec.pending : rec.unknown) += 1;
      reasons.insert(u.reason);
    }
    for (const auto& root : res.roots) {
      ++rec.roots;
      rec.certified += root.certified;
      Root_record x;
      x.combination = long(k);
      for (const auto& e : root.enclosure) {
        auto mw = midpoint_and_width(e);
        rec.widest = std::max(rec.widest, mw.second);
        x.midpoint.push_back(mw.first);
      }
      if (keep_roots) rec.root_list.push_back(x);
    }
  }
  for (const auto& r : reasons) rec.reasons += (rec.reasons.empty() ? "" : "; ") + r;
  rec.status = OK;
  return rec;
}

// Part 1 (and 3: the reduced side): the reduced systems of a scene with IT at `bits`.
template <class IT>
Record reduced_cell(const Analysis& a, double tolerance, unsigned bits, double budget, int repeats, bool fast = false)
{
  RI::Subdivision_solver_parameters p;
  p.tolerance = tolerance;
  p.precision = bits;
  p.fast = fast;
  if constexpr (std::is_same<IT, Dbl>::value) {
    if (a.exact) return solve_systems<IT>(reduced_systems<CGAL::Gmpq>(a), p, budget, repeats, true);
    return solve_systems<IT>(reduced_systems<Dbl>(a), p, budget, repeats, true);
  }
#ifdef CGAL_USE_MPFI
  else {
    if (a.exact) return solve_systems<IT>(reduced_systems<CGAL::Gmpq>(a), p, budget, repeats, true);
    CGAL::Gmpfi::set_default_precision(bits); // the coefficient enclosures at the working precision
    return solve_systems<IT>(reduced_systems<CGAL::Gmpfi>(a), p, budget, repeats, true);
  }
#endif
  return Record();
}

// Part 2: solve_scene() (the pipeline of `rigid_incidence solve`), fast or certified.
static Record scene_cell(const Analysis& a, bool fast, double budget, int repeats)
{
  RI::Scene_solve_parameters sp;
  sp.solver.fast = fast;
  sp.solver.maximal_boxes = no_box_limit;
  sp.solver.maximal_seconds = budget / double(std::max(1L, a.combinations));
  Record rec;
  std::vector<double> cpus, walls;
  RI::Scene_solve_result r;
  double spent = 0;
  for (int rep = 0; rep < std::max(1, repeats); ++rep) {
    const double c0 = cpu_now();
    r = a.exact ? RI::solve_scene<Dbl, CGAL::Gmpq>(a.user, a.c, a.tree, a.selection, sp)
                : RI::solve_scene<Dbl, Dbl>(a.user, a.c, a.tree, a.selection, sp);
    cpus.push_back(cpu_now() - c0);
    walls.push_back(r.statistics.solve_seconds);
    spent += r.statistics.solve_seconds + r.statistics.reduce_seconds + r.statistics.verify_seconds;
    if (spent > 3) break;
  }
  rec.repeats = int(cpus.size());
  rec.cpu = median(cpus);
  rec.wall = median(walls);
  rec.vars = long(r.variables.size());
  rec.eqs = long(r.equations);
  rec.combinations = long(r.statistics.chart_combinations);
  rec.boxes = long(r.statistics.boxes);
  rec.roots = long(r.statistics.roots);
  rec.configurations = long(r.configurations.size());
  rec.configurations_certified = 0;
  for (const auto& x : r.configurations) rec.configurations_certified += x.certified;
  std::set<std::string> reasons;
  for (const auto& u : r.unresolved) {
    (u.kind == RI::Box_class::PENDING ? rec.pending : rec.unknown) += 1;
    reasons.insert(u.reason);
  }
  for (const auto& x : reasons) rec.reasons += (rec.reasons.empty() ? "" : "; ") + x;
  if (!r.diagnosis.empty()) rec.reasons += (rec.reasons.empty() ? "" : "; ") + r.diagnosis;
  rec.complete = r.complete();
  rec.status = OK;
  return rec;
}

// Part 3: a naive system under the same solver (double intervals, exact coefficients).
static Record naive_cell(const Analysis& a, RI::Naive_form form, double budget, int repeats)
{
  RI::Polynomial_system<CGAL::Gmpq> sys = RI::naive_system(a.user, form);
  if (sys.number_of_equations() != sys.number_of_variables()) {
    Record rec;
    rec.vars = long(sys.number_of_variables());
    rec.eqs = long(sys.number_of_equations());
    rec.status = NOT_RUN;
    rec.message = "not square: " + std::to_string(rec.eqs) + " equations in " + std::to_string(rec.vars) + " variables";
    return rec;
  }
  RI::Subdivision_solver_parameters p;
  return solve_systems<Dbl>(std::vector<RI::Polynomial_system<CGAL::Gmpq>>{sys}, p, budget, repeats, true);
}

// The solver keeps each equation as a dense tensor-product Bernstein array over the variables
// it involves: prod (degree in x_i + 1) coefficients. The largest over the equations, and the sum.
template <class NT>
std::pair<double, double> dense_size(const RI::Polynomial_system<NT>& s)
{
  double largest = 0, sum = 0;
  for (const auto& f : s.equations) {
    const double m = f.dense_array_size();
    largest = std::max(largest, m);
    sum += m;
  }
  return {largest, sum};
}

// A lower bound of the memory Subdivision_solver<Interval_nt<false>> allocates before its first
// box: per equation the power coefficients (interval and double: 24 bytes each), the same for
// the derivative in each of its variables, and the Bernstein array of the initial box (16 bytes).
template <class NT>
double setup_bytes(const RI::Polynomial_system<NT>& s)
{
  double bytes = 0;
  for (const auto& f : s.equations) {
    double m = 1;
    std::vector<unsigned> degs;
    for (std::size_t i = 0; i < f.number_of_variables(); ++i) {
      const unsigned d = f.degree(i);
      if (d) degs.push_back(d);
      m *= double(d + 1);
    }
    double coefficients = m;
    for (unsigned d : degs) coefficients += m * double(d) / double(d + 1);
    bytes += 24 * coefficients + 16 * m;
  }
  return bytes;
}

// ------------------------------------------------------------------ PHCpack
struct Phc_system
{
  std::string text;                               // the input file
  std::vector<std::pair<double, double>> box;     // ours, to count the real solutions inside
};

template <class NT>
std::string coefficient_text(const NT& c)
{
  double x;
  if constexpr (RI::internal::is_interval_nt<NT>::value) {
    auto b = CGAL::to_interval(c);
    x = 0.5 * b.first + 0.5 * b.second;
  } else x = CGAL::to_double(c);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.16E", x);
  return buf;
}

template <class NT>
Phc_system phc_system(const RI::Polynomial_system<NT>& s)
{
  Phc_system out;
  std::ostringstream os;
  const std::size_t n = s.number_of_variables(), m = s.number_of_equations();
  os << m;
  if (m != n) os << " " << n;
  os << "\n";
  for (const auto& f : s.equations) {
    std::size_t k = 0;
    for (auto it = f.terms().rbegin(); it != f.terms().rend(); ++it, ++k) {
      std::string c = coefficient_text(it->second);
      const bool negative = !c.empty() && c[0] == '-';
      if (negative) c = c.substr(1);
      os << (k == 0 ? (negative ? "-" : "") : (negative ? " - " : " + ")) << c;
      for (std::size_t i = 0; i < n; ++i) {
        if (!it->first[i]) continue;
        os << "*x" << i + 1;
        if (it->first[i] > 1) os << "^" << it->first[i];
      }
      if (k % 4 == 3) os << "\n";
    }
    os << ";\n";
  }
  out.text = os.str();
  out.box = s.box;
  return out;
}

struct Phc_run
{
  int status = NOT_RUN;             // OK, ERROR (phc failed), TIMEOUT
  std::string message;
  double cpu = 0, wall = 0;         // of the phc process (rusage), wall clock
  long solutions = 0, real = 0;     // all solutions phc reports, real ones
  std::vector<std::vector<double>> real_points;
};

// Runs `phc -b input output` with a wall-clock cap and parses the last solution list of the
// output: a solution is real when every imaginary part is below 1e-8 (1 + |real part|).
static Phc_run run_phc(const std::string& phc, const std::string& dir, const std::string& stem, const std::string& text, std::size_t n, double cap)
{
  Phc_run r;
  const std::string in = dir + "/" + stem + ".phc", out = dir + "/" + stem + ".out";
  {
    std::ofstream f(in);
    f << text;
  }
  std::remove(out.c_str());
  CGAL::Real_timer wall;
  wall.start();
  std::cout.flush();
  pid_t pid = fork();
  if (pid < 0) { r.status = ERROR; r.message = "fork() failed"; return r; }
  if (pid == 0) {
    int devnull = open("/dev/null", O_RDWR);
    if (devnull >= 0) { dup2(devnull, 0); dup2(devnull, 1); dup2(devnull, 2); }
    execlp(phc.c_str(), phc.c_str(), "-b", in.c_str(), out.c_str(), (char*)nullptr);
    _exit(127);
  }
  int wstatus = 0;
  struct rusage ru;
  std::memset(&ru, 0, sizeof ru);
  bool done = false;
  while (!done) {
    pid_t w = wait4(pid, &wstatus, WNOHANG, &ru);
    if (w == pid) { done = true; break; }
    if (wall.time() > cap) {
      kill(pid, SIGKILL);
      wait4(pid, &wstatus, 0, &ru);
      r.status = TIMEOUT;
      r.wall = wall.time();
      r.cpu = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
      r.message = "more than " + fmt(cap) + " s";
      return r;
    }
    usleep(2000);
  }
  r.wall = wall.time();
  r.cpu = double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) {
    r.status = ERROR;
    r.message = WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 127 ? "cannot run " + phc : "phc failed";
    return r;
  }
  std::ifstream f(out);
  std::vector<std::string> lines;
  for (std::string l; std::getline(f, l);) lines.push_back(l);
  std::size_t start = std::string::npos;
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i].find("THE SOLUTIONS") != std::string::npos) start = i;
  if (start == std::string::npos) { r.status = ERROR; r.message = "no solution list in phc's output"; return r; }
  std::vector<double> re(n, 0), im(n, 0);
  bool in_solution = false;
  for (std::size_t i = start + 1; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.rfind("A list of", 0) == 0 || l.rfind("TIMING", 0) == 0) break;
    if (l.rfind("solution ", 0) == 0) { in_solution = true; std::fill(re.begin(), re.end(), 0); std::fill(im.begin(), im.end(), 0); continue; }
    if (!in_solution) continue;
    std::istringstream is(l);
    std::string name, colon;
    if (l.size() > 2 && l[0] == ' ' && l[1] == 'x') {
      double a = 0, b = 0;
      is >> name >> colon >> a >> b;
      const std::size_t k = std::size_t(std::atol(name.c_str() + 1));
      if (k >= 1 && k <= n) { re[k - 1] = a; im[k - 1] = b; }
    } else if (l.rfind("==", 0) == 0 && l.find("err") != std::string::npos) {
      ++r.solutions;
      bool real = true;
      for (std::size_t k = 0; k < n; ++k) real = real && std::abs(im[k]) <= 1e-8 * (1 + std::abs(re[k]));
      if (real) { ++r.real; r.real_points.push_back(re); }
      in_solution = false;
    }
  }
  r.status = OK;
  return r;
}

static bool inside(const std::vector<double>& x, const std::vector<std::pair<double, double>>& box)
{
  for (std::size_t i = 0; i < x.size() && i < box.size(); ++i) {
    const double slack = 1e-9 * (box[i].second - box[i].first);
    if (x[i] < box[i].first - slack || x[i] > box[i].second + slack) return false;
  }
  return true;
}

// ------------------------------------------------------------------ the run
struct Precision_cell
{
  const char* key;
  double tolerance;
  unsigned bits;  // 53: Interval_nt<false>
};

static const Precision_cell precision_cells[] = {
    {"double 1e-3", 1e-3, 53},   {"double 1e-6", 1e-6, 53},    {"double 1e-9", 1e-9, 53},      {"double 1e-12", 1e-12, 53},
    {"Gmpfi 113 1e-20", 1e-20, 113}, {"Gmpfi 113 1e-30", 1e-30, 113}, {"Gmpfi 256 1e-60", 1e-60, 256}};
static const std::size_t n_precision = sizeof precision_cells / sizeof precision_cells[0];
static const std::size_t double_1e12 = 3;

struct Scene_rows
{
  Analysis a;
  std::vector<Record> precision;         // part 1, one per precision_cells
  Record reference;                      // 512 bits, 1e-100
  std::vector<double> accuracy;          // part 1: achieved accuracy per cell (NaN: not measured)
  std::vector<long> matched, missed;     // roots matching a reference root / reference roots not found
  Record certified, fast;                // part 2
  Record naive[2];                       // part 3: QUATERNION, TRIGONOMETRIC
  std::vector<Phc_run> phc_reduced;      // part 4, per chart combination
  Phc_run phc_naive[2];
  std::vector<std::vector<std::pair<double, double>>> boxes; // per chart combination
  long phc_agree = 0;                    // chart combinations whose real solutions in the box agree with ours
  std::vector<std::string> phc_mismatch; // the others, described
  std::pair<double, double> dense_reduced{0, 0}, dense_naive[2] = {{0, 0}, {0, 0}};
  long naive_vars[2] = {0, 0}, naive_eqs[2] = {0, 0};
  double naive_bytes[2] = {0, 0};
  long phc_real_in_box = 0, phc_real = 0, phc_solutions = 0;
  double phc_cpu = 0, phc_wall = 0;
  double phc_our_cpu = 0;                // our solver's CPU time on the chart combinations phc finished
  long phc_done = 0;                     // chart combinations phc finished within the budget
  long phc_total = 0;                    // chart combinations
  long phc_ours = 0;                     // our roots in the chart combinations phc finished
  int phc_status = NOT_RUN;
  std::string phc_message;
};

static const char* naive_names[2] = {"naive quaternion (2.2)", "naive trigonometric (2.1)"};
static const RI::Naive_form naive_forms[2] = {RI::Naive_form::QUATERNION, RI::Naive_form::TRIGONOMETRIC};

static std::string status_text(const Record& r)
{
  switch (r.status) {
  case OK: return "";
  case TIMEOUT: return "killed (" + r.message + ")";
  case DIED: return r.message;
  case NOT_RUN: return r.message.empty() ? "not run" : r.message;
  default: return "error: " + r.message;
  }
}

// achieved accuracy of `r` against the reference: the largest distance of a root to the
// nearest reference root of its chart combination (max norm)
static double accuracy_of(const Record& r, const Record& ref, const std::vector<std::vector<Mp>>& ref_mp, long* matched, long* missed)
{
  *matched = 0;
  *missed = 0;
  if (r.status != OK || ref.status != OK || !ref.complete) return std::numeric_limits<double>::quiet_NaN();
  double worst = 0;
  std::vector<bool> found(ref.root_list.size(), false);
  for (const auto& x : r.root_list) {
    std::vector<Mp> v;
    for (const auto& s : x.midpoint) v.emplace_back(s);
    double best = std::numeric_limits<double>::infinity();
    std::size_t arg = 0;
    for (std::size_t j = 0; j < ref.root_list.size(); ++j) {
      if (ref.root_list[j].combination != x.combination || ref_mp[j].size() != v.size()) continue;
      double d = 0;
      for (std::size_t i = 0; i < v.size(); ++i) d = std::max(d, mp_distance(v[i], ref_mp[j][i]));
      if (d < best) { best = d; arg = j; }
    }
    if (best <= 1e-6) { ++*matched; found[arg] = true; }
    worst = std::max(worst, best);
  }
  for (bool f : found) *missed += !f;
  return worst;
}

static std::string accuracy_text(double a)
{
  if (std::isnan(a)) return "–";
  if (a == 0) return "0 (exact)";
  return fmt(a, 2);
}

static std::string tolerance_text(double t)
{
  const int e = int(std::lround(std::log10(t)));
  return std::abs(t - std::pow(10.0, e)) <= 1e-9 * t ? "1e" + std::to_string(e) : fmt(t, 2);
}

static const char* colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"};

// time (CPU, log) against achieved accuracy (log), one line per scene, one point per tolerance
static void write_svg(const std::string& file, const std::vector<Scene_rows>& scenes)
{
  double amin = 1, tmin = 1e300, tmax = 0;
  bool any_zero = false;
  for (const auto& s : scenes)
    for (std::size_t k = 0; k < s.accuracy.size(); ++k) {
      const double a = s.accuracy[k];
      if (std::isnan(a)) continue;
      if (a == 0) any_zero = true;
      else amin = std::min(amin, a);
      tmin = std::min(tmin, std::max(1e-6, s.precision[k].cpu));
      tmax = std::max(tmax, std::max(1e-6, s.precision[k].cpu));
    }
  if (tmax == 0) { tmin = 1e-3; tmax = 1; }
  int xlo = int(std::floor(std::log10(amin))) - 1, xhi = 0;
  if (any_zero) xlo -= 2;  // exact midpoints drawn at the left edge
  int ylo = int(std::floor(std::log10(tmin))), yhi = int(std::ceil(std::log10(tmax)));
  if (yhi <= ylo) yhi = ylo + 1;
  const int left = 80, top = 70, pw = 760, ph = 400, width = left + pw + 200, height = top + ph + 70;
  auto X = [&](double a) { return left + pw * (std::log10(a) - xlo) / double(xhi - xlo); };
  auto Y = [&](double t) { return top + ph - ph * (std::log10(std::max(1e-6, t)) - ylo) / double(yhi - ylo); };
  std::ofstream svg(file);
  benchmark_common::svg_open(svg, width, height);
  svg << "<text x=\"" << left << "\" y=\"22\" font-size=\"14\" font-weight=\"bold\">Solver time against achieved accuracy "
         "(all chart combinations; log-log)</text>\n"
      << "<text x=\"" << left << "\" y=\"40\">points: tolerance 1e-3 .. 1e-12 in double (circles), 1e-20, 1e-30 at 113 bits and "
         "1e-60 at 256 bits with Gmpfi (squares); accuracy = max distance to a 512-bit reference root</text>\n";
  const int xstep = std::max(1, (xhi - xlo) / 12);
  for (int d = xlo; d <= xhi; d += xstep) {
    double x = X(std::pow(10.0, d));
    svg << "<line x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << top + ph << "\" stroke=\"#eee\"/>"
        << "<text x=\"" << x << "\" y=\"" << top + ph + 16 << "\" text-anchor=\"middle\">"
        << (any_zero && d == xlo ? "exact" : "1e" + std::to_string(d)) << "</text>\n";
  }
  for (int d = ylo; d <= yhi; ++d) {
    double y = Y(std::pow(10.0, d));
    svg << "<line x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << left + pw << "\" y2=\"" << y << "\" stroke=\"#eee\"/>"
        << "<text x=\"" << left - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e" << d << " s</text>\n";
  }
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph << "\" fill=\"none\" stroke=\"black\"/>\n"
      << "<text x=\"" << left + pw / 2 << "\" y=\"" << top + ph + 40 << "\" text-anchor=\"middle\">achieved accuracy (max norm over the "
         "parameters; smaller is better)</text>\n"
      << "<text transform=\"translate(18," << top + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">solver CPU time</text>\n";
  // one label per arithmetic, above the points it made (their accuracies barely depend on the tolerance)
  for (unsigned bits : {53u, 113u, 256u}) {
    double sum = 0;
    int count = 0;
    for (const auto& s : scenes)
      for (std::size_t k = 0; k < s.accuracy.size(); ++k)
        if (precision_cells[k].bits == bits && !std::isnan(s.accuracy[k])) {
          sum += s.accuracy[k] == 0 ? X(std::pow(10.0, xlo)) : X(s.accuracy[k]);
          ++count;
        }
    if (!count) continue;
    std::string label;
    for (const auto& pc : precision_cells)
      if (pc.bits == bits) label += (label.empty() ? "" : ", ") + tolerance_text(pc.tolerance);
    svg << "<text x=\"" << sum / count << "\" y=\"" << top + 16 << "\" text-anchor=\"middle\" font-size=\"10\">"
        << (bits == 53 ? std::string("double") : "Gmpfi " + std::to_string(bits) + " bits") << "</text>\n<text x=\"" << sum / count
        << "\" y=\"" << top + 29 << "\" text-anchor=\"middle\" font-size=\"10\">tolerance " << label << "</text>\n";
  }
  int legend_y = top + 10;
  for (std::size_t si = 0; si < scenes.size(); ++si) {
    const auto& s = scenes[si];
    const char* col = colors[si % 6];
    std::vector<std::pair<double, double>> pts;
    std::vector<std::size_t> which;
    for (std::size_t k = 0; k < s.accuracy.size(); ++k) {
      const double a = s.accuracy[k];
      if (std::isnan(a)) continue;
      pts.push_back({a == 0 ? X(std::pow(10.0, xlo)) : X(a), Y(s.precision[k].cpu)});
      which.push_back(k);
    }
    if (pts.empty()) continue;
    svg << "<polyline fill=\"none\" stroke=\"" << col << "\" stroke-width=\"1.5\" points=\"";
    for (const auto& p : pts) svg << p.first << "," << p.second << " ";
    svg << "\"/>\n";
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const auto& pc = precision_cells[which[i]];
      const std::string title = s.a.name + ", " + pc.key + ": accuracy " + accuracy_text(s.accuracy[which[i]]) + ", " +
                                seconds_text(s.precision[which[i]].cpu);
      if (pc.bits == 53)
        svg << "<circle cx=\"" << pts[i].first << "\" cy=\"" << pts[i].second << "\" r=\"4\" fill=\"" << col << "\"><title>" << title
            << "</title></circle>\n";
      else
        svg << "<rect x=\"" << pts[i].first - 4 << "\" y=\"" << pts[i].second - 4 << "\" width=\"8\" height=\"8\" fill=\"" << col
            << "\"><title>" << title << "</title></rect>\n";
    }
    svg << "<line x1=\"" << left + pw + 15 << "\" y1=\"" << legend_y << "\" x2=\"" << left + pw + 40 << "\" y2=\"" << legend_y
        << "\" stroke=\"" << col << "\" stroke-width=\"2\"/><text x=\"" << left + pw + 45 << "\" y=\"" << legend_y + 4 << "\">" << s.a.name
        << "</text>\n";
    legend_y += 18;
  }
  svg << "</svg>\n";
}

int main(int argc, char** argv)
{
  const std::string prefix = argc > 1 ? argv[1] : "solver";
  const int repeats = argc > 2 ? std::stoi(argv[2]) : 3;
  const double cap = argc > 3 ? std::stod(argv[3]) : 20.0;
  const double long_cap = argc > 4 ? std::stod(argv[4]) : 60.0;
  const std::string phc = argc > 5 ? argv[5] : "phc";
  const std::string only = argc > 6 ? "," + std::string(argv[6]) + "," : ""; // e.g. tetra,pent
  CGAL::Real_timer total;
  total.start();
#ifdef CGAL_USE_MPFI
  const bool mpfi = true;
#else
  const bool mpfi = false;
#endif

  // is phc there?
  std::string phc_version;
  bool have_phc = false;
  {
    std::string which = "command -v " + phc + " >/dev/null 2>&1";
    have_phc = std::system(which.c_str()) == 0;
    if (have_phc) {
      FILE* p = popen((phc + " --version 2>&1").c_str(), "r");
      if (p) {
        char buf[256];
        if (std::fgets(buf, sizeof buf, p)) phc_version = buf;
        pclose(p);
        while (!phc_version.empty() && (phc_version.back() == '\n' || phc_version.back() == '\r')) phc_version.pop_back();
      }
    }
  }
  char dir_template[] = "/tmp/benchmark_solver_phcXXXXXX";
  const std::string phc_dir = have_phc && mkdtemp(dir_template) ? dir_template : "";
  if (phc_dir.empty()) have_phc = false;

  const std::map<std::string, long> expected = {{"tetra", 4}, {"tetra_ii", 4}, {"quad_distinct", 16}, {"pent", 8}, {"stewart_gough40", 40}};
  std::vector<Scene_rows> scenes;
  for (const char* f : {"tetra", "tetra_ii", "quad_distinct", "pent", "stewart_gough40"}) {
    if (!only.empty() && only.find("," + std::string(f) + ",") == std::string::npos) continue;
    Scene_rows s;
    Analysis& a = s.a;
    a.name = f;
    a.expected = expected.at(f);
    a.long_scene = a.name == "stewart_gough40";
    const double budget = a.long_scene ? long_cap : cap;
    try {
      RI::Scene sc = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + f + ".json");
      a.user = RI::make_collection<Traits>(sc);
      a.c = RI::standardize(a.user);
      a.tree = RI::optimal_incidence_tree(a.c);
      a.selection = RI::select_well_formed_incidences(a.c, a.tree);
      for (std::size_t b : a.tree.covering_set) a.exact = a.exact && a.c.body(b).all_coordinates();
      RI::Reduced_system<Traits, Dbl> first(a.c, a.tree, a.selection);
      a.vars = long(first.number_of_variables());
      a.eqs = long(first.number_of_equations());
      a.square = first.is_square();
      a.diagnostic = first.diagnostic();
      long placements = 1;
      for (int k : RI::internal::placement_counts(a.c, a.tree)) placements *= k;
      a.combinations = long(first.number_of_chart_combinations()) * placements;
    } catch (const std::exception& e) {
      std::cout << f << ": analysis failed: " << e.what() << std::endl;
      continue;
    }
    try {
      CGAL::Protect_FPU_rounding<true> guard;
      s.dense_reduced = a.exact ? dense_size(reduced_systems<CGAL::Gmpq>(a).front()) : dense_size(reduced_systems<Dbl>(a).front());
      for (int k = 0; k < 2; ++k) {
        const RI::Polynomial_system<CGAL::Gmpq> sys = RI::naive_system(a.user, naive_forms[k]);
        s.dense_naive[k] = dense_size(sys);
        s.naive_vars[k] = long(sys.number_of_variables());
        s.naive_eqs[k] = long(sys.number_of_equations());
        s.naive_bytes[k] = setup_bytes(sys);
      }
    } catch (const std::exception&) {
    }
    std::cout << "== " << f << ": reduced system " << a.vars << " x " << a.eqs << ", " << a.combinations << " chart combination(s), "
              << (a.exact ? "exact" : "interval") << " coefficients" << std::endl;

    // part 1: tolerance and precision
    s.precision.resize(n_precision);
    for (std::size_t k = 0; k < n_precision; ++k) {
      const Precision_cell& pc = precision_cells[k];
      Record& r = s.precision[k];
      if (a.long_scene && k != double_1e12) { r.status = NOT_RUN; r.message = "not run (the long scene: double 1e-12 only)"; continue; }
      if (pc.bits > 53 && !mpfi) { r.status = NOT_RUN; r.message = "no MPFI in this build"; continue; }
      if (pc.bits == 53) r = run_cell([&]() { return reduced_cell<Dbl>(a, pc.tolerance, 53, budget, repeats); }, budget);
#ifdef CGAL_USE_MPFI
      else r = run_cell([&]() { return reduced_cell<CGAL::Gmpfi>(a, pc.tolerance, pc.bits, budget, repeats); }, budget);
#endif
      std::cout << "  " << std::left << std::setw(18) << pc.key << std::right;
      if (r.status == OK)
        std::cout << seconds_text(r.cpu) << " CPU (" << r.repeats << " repeat(s)), " << r.boxes << " boxes, " << r.roots << " roots"
                  << (r.complete ? ", complete" : ", NOT complete: " + r.reasons);
      else std::cout << status_text(r);
      std::cout << std::endl;
    }
    if (mpfi && !a.long_scene) {
#ifdef CGAL_USE_MPFI
      s.reference = run_cell([&]() { return reduced_cell<CGAL::Gmpfi>(a, 1e-100, 512, 3 * cap, 1); }, 3 * cap);
#endif
      std::cout << "  reference 512 bits: ";
      if (s.reference.status == OK)
        std::cout << seconds_text(s.reference.cpu) << " CPU, " << s.reference.roots << " roots"
                  << (s.reference.complete ? ", complete" : ", NOT complete") << ", widest enclosure " << fmt(s.reference.widest, 2);
      else std::cout << status_text(s.reference);
      std::cout << std::endl;
    } else {
      s.reference.status = NOT_RUN;
      s.reference.message = a.long_scene ? "not run (the long scene)" : "no MPFI in this build";
    }
    {
      std::vector<std::vector<Mp>> ref_mp;
      for (const auto& x : s.reference.root_list) {
        ref_mp.emplace_back();
        for (const auto& v : x.midpoint) ref_mp.back().emplace_back(v);
      }
      for (std::size_t k = 0; k < n_precision; ++k) {
        long m = 0, miss = 0;
        s.accuracy.push_back(accuracy_of(s.precision[k], s.reference, ref_mp, &m, &miss));
        s.matched.push_back(m);
        s.missed.push_back(miss);
      }
    }

    // part 2: fast against certified, through solve_scene()
    s.certified = run_cell([&]() { return scene_cell(a, false, budget, repeats); }, budget);
    s.fast = run_cell([&]() { return scene_cell(a, true, budget, repeats); }, budget);
    for (const Record* r : {&s.certified, &s.fast}) {
      std::cout << "  solve_scene " << (r == &s.fast ? "fast     " : "certified") << " ";
      if (r->status == OK)
        std::cout << seconds_text(r->cpu) << " CPU, " << r->configurations << " configurations (" << r->configurations_certified
                  << " certified)" << (r->complete ? ", complete" : ", not complete") << (r->reasons.empty() ? "" : ": " + r->reasons);
      else std::cout << status_text(*r);
      std::cout << std::endl;
    }

    // part 3: naive formulations under the same solver and budget
    for (int k = 0; k < 2; ++k) {
      if (s.naive_vars[k] && s.naive_vars[k] != s.naive_eqs[k]) {
        s.naive[k].status = NOT_RUN;
        s.naive[k].message = "not square: " + std::to_string(s.naive_eqs[k]) + " equations in " + std::to_string(s.naive_vars[k]) + " variables";
      } else if (s.naive_bytes[k] > cell_memory) {
        // it would only fill the memory for half a minute and fail
        s.naive[k].status = NOT_RUN;
        s.naive[k].message = "not run: the solver's dense Bernstein arrays need at least " + fmt(s.naive_bytes[k] / double(1 << 30), 3) +
                             " GiB (cell limit " + fmt(cell_memory / double(1 << 30)) + " GiB)";
      } else s.naive[k] = run_cell([&]() { return naive_cell(a, naive_forms[k], budget, repeats); }, budget);
      const Record& r = s.naive[k];
      std::cout << "  " << std::left << std::setw(26) << naive_names[k] << std::right;
      if (r.status == OK)
        std::cout << r.vars << " x " << r.eqs << ", " << seconds_text(r.cpu) << " CPU, " << r.boxes << " boxes, " << r.roots << " roots"
                  << (r.complete ? ", complete" : ", NOT complete: " + r.reasons);
      else std::cout << status_text(r);
      std::cout << std::endl;
    }

    // part 4: PHCpack on every chart combination and on the naive systems
    if (have_phc) {
      std::vector<Phc_system> systems;
      try {
        CGAL::Protect_FPU_rounding<true> guard;
        if (a.exact) for (const auto& sys : reduced_systems<CGAL::Gmpq>(a)) systems.push_back(phc_system(sys));
        else for (const auto& sys : reduced_systems<Dbl>(a)) systems.push_back(phc_system(sys));
      } catch (const std::exception& e) {
        s.phc_status = ERROR;
        s.phc_message = e.what();
      }
      const Record& ours = s.precision[double_1e12];
      s.phc_status = systems.empty() ? s.phc_status : OK;
      s.phc_total = long(systems.size());
      for (std::size_t k = 0; k < systems.size(); ++k) {
        // the chart combinations in turn, while the scene's budget lasts
        const double left = budget - s.phc_wall;
        if (left <= 0) break;
        Phc_run r = run_phc(phc, phc_dir, a.name + "_chart" + std::to_string(k), systems[k].text, std::size_t(a.vars), left);
        s.phc_wall += r.wall;
        if (r.status != OK) {
          if (r.status != TIMEOUT) { s.phc_status = r.status; s.phc_message = r.message; }
          break;
        }
        s.phc_cpu += r.cpu;
        ++s.phc_done;
        if (k < ours.combination_cpu.size()) s.phc_our_cpu += ours.combination_cpu[k];
        s.phc_solutions += r.solutions;
        s.phc_real += r.real;
        // the real solutions in the chart's box against our roots of this combination
        std::vector<std::vector<double>> mine, theirs;
        for (const auto& x : ours.root_list)
          if (x.combination == long(k)) {
            std::vector<double> v;
            for (const auto& m : x.midpoint) v.push_back(std::strtod(m.c_str(), nullptr));
            mine.push_back(v);
          }
        for (const auto& p : r.real_points) if (inside(p, systems[k].box)) theirs.push_back(p);
        s.phc_real_in_box += long(theirs.size());
        s.phc_ours += long(mine.size());
        bool agree = ours.status == OK && ours.complete && mine.size() == theirs.size();
        for (const auto& v : mine) {
          bool hit = false;
          for (const auto& p : theirs) {
            double d = 0;
            for (std::size_t i = 0; i < v.size(); ++i) d = std::max(d, std::abs(v[i] - p[i]));
            hit = hit || d <= 1e-6;
          }
          agree = agree && hit;
        }
        s.phc_agree += agree;
        if (!agree) {
          std::ostringstream m;
          m << "chart combination " << k << ": phc " << theirs.size() << " real solution(s) in the box, ours " << mine.size();
          for (const auto& p : r.real_points)
            if (!inside(p, systems[k].box)) {
              double out = 0;
              for (std::size_t i = 0; i < p.size(); ++i)
                out = std::max(out, std::max(systems[k].box[i].first - p[i], p[i] - systems[k].box[i].second));
              if (out < 1e-3) m << "; a real solution of phc lies " << fmt(out, 2) << " outside the box";
            }
          for (const auto& v : mine) {
            double best = std::numeric_limits<double>::infinity();
            for (const auto& p : r.real_points) {
              double d = 0;
              for (std::size_t i = 0; i < v.size(); ++i) d = std::max(d, std::abs(v[i] - p[i]));
              best = std::min(best, d);
            }
            std::string point;
            for (std::size_t i = 0; i < v.size(); ++i) point += (i ? ", " : "") + fmt(v[i], 6);
            if (best > 1e-6) m << "; our root (" << point << ") is " << (std::isinf(best) ? std::string("not") : fmt(best, 2) + " from the nearest")
                               << " real solution of phc";
          }
          s.phc_mismatch.push_back(m.str());
          std::cout << "    " << m.str() << std::endl;
        }
        s.phc_reduced.push_back(r);
      }
      if (s.phc_status == OK && s.phc_done < s.phc_total) {
        s.phc_message = "budget of " + fmt(budget) + " s spent after " + std::to_string(s.phc_done) + " of " + std::to_string(s.phc_total) +
                        " chart combinations";
        if (s.phc_done == 0) s.phc_status = TIMEOUT;
      }
      std::cout << "  phc, reduced system: ";
      if (s.phc_status == OK)
        std::cout << seconds_text(s.phc_cpu) << " CPU over " << s.phc_done << " of " << s.phc_total << " chart combination(s) (ours "
                  << seconds_text(s.phc_our_cpu) << "), " << s.phc_solutions << " solutions, " << s.phc_real << " real, "
                  << s.phc_real_in_box << " real in the charts' boxes (ours: " << s.phc_ours << "), agreement in " << s.phc_agree
                  << " of " << s.phc_done << (s.phc_message.empty() ? "" : "; " + s.phc_message) << std::endl;
      else std::cout << s.phc_message << std::endl;
      for (int k = 0; k < 2; ++k) {
        if (s.naive_vars[k] && s.naive_vars[k] != s.naive_eqs[k]) { s.phc_naive[k].message = s.naive[k].message; continue; }
        RI::Polynomial_system<CGAL::Gmpq> sys;
        try {
          sys = RI::naive_system(a.user, naive_forms[k]);
        } catch (const std::exception& e) {
          s.phc_naive[k].status = ERROR;
          s.phc_naive[k].message = e.what();
          continue;
        }
        s.phc_naive[k] = run_phc(phc, phc_dir, a.name + (k == 0 ? "_naive_quaternion" : "_naive_trigonometric"), phc_system(sys).text,
                                 sys.number_of_variables(), budget);
        std::cout << "  phc, " << std::left << std::setw(26) << naive_names[k] << std::right;
        if (s.phc_naive[k].status == OK)
          std::cout << seconds_text(s.phc_naive[k].cpu) << " CPU, " << s.phc_naive[k].solutions << " solutions, " << s.phc_naive[k].real
                    << " real" << std::endl;
        else std::cout << s.phc_naive[k].message << std::endl;
      }
    } else {
      s.phc_message = "phc not found";
    }
    scenes.push_back(std::move(s));
  }
  total.stop();

  // ---------------------------------------------------------------- CSV
  std::ofstream csv(prefix + ".csv");
  csv << "part,scene,system,arithmetic,bits,tolerance,status,repeats,cpu_seconds,wall_seconds,variables,equations,chart_combinations,"
         "boxes,roots,certified,unknown,pending,complete,configurations,configurations_certified,expected_configurations,reference_roots,"
         "roots_matching_reference,reference_roots_missed,widest_enclosure,achieved_accuracy,ratio,phc_solutions,phc_real,"
         "phc_real_in_box,phc_agreeing_combinations,dense_array_largest,dense_array_sum,note\n";
  auto csv_record = [&](const std::string& part, const Scene_rows& s, const std::string& system, const std::string& arith, unsigned bits,
                        double tol, const Record& r, const std::string& extra, std::pair<double, double> dense = {0, 0}) {
    csv << part << "," << s.a.name << "," << system << "," << arith << "," << bits << "," << (tol > 0 ? fmt(tol, 2) : "") << ","
        << (r.status == OK ? "ok" : r.status == TIMEOUT ? "killed" : r.status == NOT_RUN ? "not_run" : "error") << ",";
    if (r.status == OK)
      csv << r.repeats << "," << r.cpu << "," << r.wall << "," << r.vars << "," << r.eqs << "," << r.combinations << "," << r.boxes << ","
          << r.roots << "," << r.certified << "," << r.unknown << "," << r.pending << "," << (r.complete ? "true" : "false") << ","
          << (r.configurations >= 0 ? std::to_string(r.configurations) : "") << ","
          << (r.configurations_certified >= 0 ? std::to_string(r.configurations_certified) : "") << ",";
    else csv << ",,,,,,,,,,,,,,";
    csv << s.a.expected << "," << extra << "," << (dense.first > 0 ? fmt(dense.first, 12) : "") << ","
        << (dense.second > 0 ? fmt(dense.second, 12) : "") << "," << csv_escape(r.status == OK ? r.reasons : status_text(r)) << "\n";
  };
  for (const auto& s : scenes) {
    const std::string ref_roots = s.reference.status == OK ? std::to_string(s.reference.roots) : "";
    for (std::size_t k = 0; k < n_precision; ++k) {
      const auto& pc = precision_cells[k];
      const Record& r = s.precision[k];
      std::ostringstream extra;
      extra << ref_roots << "," << (std::isnan(s.accuracy[k]) ? "" : std::to_string(s.matched[k])) << ","
            << (std::isnan(s.accuracy[k]) ? "" : std::to_string(s.missed[k])) << "," << (r.status == OK ? fmt(r.widest, 3) : "") << ","
            << (std::isnan(s.accuracy[k]) ? "" : fmt(s.accuracy[k], 3)) << ",,,,,";
      csv_record("tolerance", s, "reduced", pc.bits == 53 ? "Interval_nt<false>" : "Gmpfi", pc.bits, pc.tolerance, r, extra.str(),
                 s.dense_reduced);
    }
    csv_record("tolerance", s, "reduced (reference)", "Gmpfi", 512, 1e-100, s.reference,
               ref_roots + ",,," + (s.reference.status == OK ? fmt(s.reference.widest, 3) : "") + ",,,,,,");
    const double ratio_cf = s.certified.status == OK && s.fast.status == OK && s.fast.cpu > 0 ? s.certified.cpu / s.fast.cpu : NAN;
    csv_record("fast", s, "solve_scene certified", "Interval_nt<false>", 53, 1e-12, s.certified, ",,,,," + (std::isnan(ratio_cf) ? "" : fmt(ratio_cf, 3)) + ",,,,");
    csv_record("fast", s, "solve_scene fast", "Interval_nt<false>", 53, 1e-12, s.fast, ",,,,,,,,,");
    const Record& red = s.precision[double_1e12];
    for (int k = 0; k < 2; ++k) {
      const Record& r = s.naive[k];
      const double ratio = r.status == OK && red.status == OK && red.cpu > 0 ? r.cpu / red.cpu : NAN;
      std::ostringstream extra;
      extra << ",,," << (r.status == OK ? fmt(r.widest, 3) : "") << ",," << (std::isnan(ratio) ? "" : fmt(ratio, 3)) << ",";
      const Phc_run& p = s.phc_naive[k];
      if (p.status == OK) extra << p.solutions << "," << p.real << ",,";
      else extra << ",,,";
      csv_record("naive", s, naive_names[k], "Interval_nt<false>", 53, 1e-12, r, extra.str(), s.dense_naive[k]);
    }
    {
      Record pr;
      pr.status = s.phc_status == OK ? OK : (s.phc_status == TIMEOUT ? TIMEOUT : s.phc_status == NOT_RUN ? NOT_RUN : ERROR);
      pr.message = s.phc_message;
      pr.repeats = 1;
      pr.cpu = s.phc_cpu;
      pr.wall = s.phc_wall;
      pr.vars = s.a.vars;
      pr.eqs = s.a.eqs;
      pr.combinations = s.phc_done;
      pr.roots = s.phc_real_in_box;
      pr.certified = s.phc_ours;
      pr.complete = pr.status == OK && s.phc_done == s.phc_total;
      pr.reasons = s.phc_message;
      const double ratio = pr.status == OK && s.phc_our_cpu > 0 ? s.phc_cpu / s.phc_our_cpu : NAN;
      csv_record("phcpack", s, "reduced (phc -b)", "phc", 53, 0, pr,
                 ",,,,," + (std::isnan(ratio) ? "" : fmt(ratio, 3)) + "," + std::to_string(s.phc_solutions) + "," +
                     std::to_string(s.phc_real) + "," + std::to_string(s.phc_real_in_box) + "," + std::to_string(s.phc_agree));
    }
  }

  // ---------------------------------------------------------------- Markdown
  const std::string cpu = benchmark_common::cpu_model();
  double load[3] = {0, 0, 0};
  getloadavg(load, 3);
  const std::string command = benchmark_common::command_line(argc, argv), date = benchmark_common::utc_date();

  std::ofstream md(prefix + ".md");
  md << "# Subdivision solver: tolerance, precision, fast mode, naive formulations, PHCpack\n\n"
     << "Command: `" << command << "` (" << repeats << " repeats, budget " << cap << " s per cell, " << long_cap
     << " s for stewart_gough40)  \n"
     << "Machine: " << cpu << ", " << sysconf(_SC_NPROCESSORS_ONLN) << " cores online (load average " << fixed(load[0], 1)
     << " at the end), " << benchmark_common::os_release() << "; compiler " << __VERSION__ << "; MPFI " << (mpfi ? "yes" : "no")
     << "; PHCpack: " << (have_phc ? "`" + phc + "` (" + phc_version + ")" : "not found") << "; " << date << "; total run "
     << fixed(total.time(), 1) << " s.\n\n"
     << "Scenes (examples/Rigid_incidence/data): tetra and tetra_ii (4 configurations), quad_distinct (16), pent (pent iv, 8) "
        "and stewart_gough40 (the Stewart-Gough platform with 40 real assembly modes, solved in double at 1e-12 only, with its own budget). "
        "Every cell solves the reduced system in every chart combination (as `solve_scene()` does) in a child process with a "
        "time budget: the solver's `maximal_seconds` (each chart combination gets what the previous ones left; what is left is "
        "*pending*), `maximal_boxes` unlimited. **Times are CPU seconds of the solver calls** (building the systems excluded), "
        "the median of the repeats (a cell whose repeats take more than 3 s together is not repeated further); wall-clock "
        "times are in the CSV. Coefficients: exact (`Gmpq`) when every covering body has coordinates (quad_distinct, pent, "
        "stewart_gough40), else certified intervals (`Interval_nt<false>`, or `Gmpfi` at the working precision).\n\n";

  // part 1
  md << "## 1. Tolerance and precision\n\n"
     << "`Subdivision_solver_parameters::tolerance` (the width to which a certified root's enclosure is tightened) from 1e-3 "
        "to 1e-12 with `Interval_nt<false>`, and 1e-20, 1e-30 (113 bits), 1e-60 (256 bits) with `CGAL::Gmpfi`. *roots* = "
        "certified roots over all chart combinations (a root on the border of two charts counts twice) / roots of the "
        "reference solve (`Gmpfi` at 512 bits, tolerance 1e-100, same charts); *widest encl.* = the widest enclosure of a "
        "root (a certified bound on its error); *accuracy* = the largest distance (max norm over the parameters) from a root's "
        "enclosure midpoint to the nearest reference root of its chart combination.\n\n"
     << "| scene | arithmetic | tolerance | solver CPU | boxes | roots / ref. | complete | widest encl. | accuracy |\n"
     << "|:--|:--|--:|--:|--:|--:|:--|--:|--:|\n";
  for (const auto& s : scenes) {
    bool first = true;
    for (std::size_t k = 0; k < n_precision; ++k) {
      const Record& r = s.precision[k];
      const auto& pc = precision_cells[k];
      if (s.a.long_scene && r.status == NOT_RUN) continue;
      md << "| " << (first ? "**" + s.a.name + "**" : "") << " | " << (pc.bits == 53 ? "double" : "Gmpfi " + std::to_string(pc.bits))
         << " | " << tolerance_text(pc.tolerance) << " | ";
      first = false;
      if (r.status != OK) { md << "*" << md_escape(status_text(r)) << "* | | | | | |\n"; continue; }
      md << seconds_text(r.cpu) << " | " << r.boxes << " | " << r.certified << " / "
         << (s.reference.status == OK ? std::to_string(s.reference.roots) : "–") << " | "
         << (r.complete ? "yes" : "**no**: " + md_escape(r.reasons) + " (" + std::to_string(r.unknown) + " unknown, " +
                                      std::to_string(r.pending) + " pending)")
         << " | " << (r.roots ? fmt(r.widest, 2) : "–") << " | " << accuracy_text(s.accuracy[k]) << " |\n";
    }
    if (s.reference.status == OK)
      md << "| | *reference* Gmpfi 512 | 1e-100 | " << seconds_text(s.reference.cpu) << " | " << s.reference.boxes << " | "
         << s.reference.certified << " | " << (s.reference.complete ? "yes" : "**no**") << " | " << fmt(s.reference.widest, 2)
         << " | |\n";
    else if (!s.a.long_scene)
      md << "| | *reference* Gmpfi 512 | 1e-100 | *" << md_escape(status_text(s.reference)) << "* | | | | | |\n";
  }
  const std::string svg_name = prefix.substr(prefix.find_last_of('/') + 1) + ".svg";
  md << "\nPlot of the solver time against the achieved accuracy: [" << svg_name << "](" << svg_name << ")\n\n";

  // part 2
  md << "## 2. Fast mode against certified\n\n"
     << "`solve_scene()` (the pipeline of `rigid_incidence solve`: every chart combination, back-substitution, residuals in "
        "the scene, merging across charts) with `parameters.solver.fast` false / true, tolerance 1e-12, double. *CPU* = the "
        "whole `solve_scene()` call; *configurations* = after merging (certified ones in brackets); *expected* = the "
        "papers' count (stewart_gough40: Dietmaier's 40 real assembly modes).\n\n"
     << "| scene | expected | certified: CPU | boxes | configurations | complete | fast: CPU | boxes | configurations | certified / fast |\n"
     << "|:--|--:|--:|--:|--:|:--|--:|--:|--:|--:|\n";
  for (const auto& s : scenes) {
    md << "| **" << s.a.name << "** | " << s.a.expected << " | ";
    for (const Record* r : {&s.certified, &s.fast}) {
      if (r->status != OK) { md << "*" << md_escape(status_text(*r)) << "* | | | " << (r == &s.certified ? "| " : ""); continue; }
      md << seconds_text(r->cpu) << " | " << r->boxes << " | " << r->configurations;
      if (r == &s.certified) {
        md << " (" << r->configurations_certified << ")";
        md << " | " << (r->complete ? "yes" : "**no**: " + md_escape(r->reasons)) << " | ";
      } else md << (r->pending ? " (" + std::to_string(r->pending) + " pending)" : "") << " | ";
    }
    md << (s.certified.status == OK && s.fast.status == OK && s.fast.cpu > 0 ? ratio_text(s.certified.cpu / s.fast.cpu) : "–") << " |\n";
  }

  // part 3
  md << "\n## 3. Reduced system against the naive formulations\n\n"
     << "The same solver (`Subdivision_solver<Interval_nt<false>>`, tolerance 1e-12, exact coefficients for the naive systems) "
        "and the same budget (" << cap << " s, " << long_cap << " s for stewart_gough40) on the reduced system (every chart "
        "combination: the double 1e-12 cell of part 1) and directly on `naive_system(user collection, QUATERNION / "
        "TRIGONOMETRIC)` with its own box (rotation parameters in [-1e6, 1e6] or sines and cosines in [-1, 1], translations "
        "in [-1e6, 1e6]). A naive system that is not square (the scene's bodies share pairs: the naive formulation keeps "
        "redundant incidences) is not solved; a naive system whose dense arrays cannot fit in the 8 GiB a cell may use is "
        "not attempted (an attempt fills the memory and fails). *dense array* = the solver keeps each equation as a dense tensor-product "
        "Bernstein array over the variables it involves, prod (degree + 1) coefficients: the largest over the equations "
        "(the sum in the CSV). *× time* = naive / reduced (a lower bound when the naive solve ran out of time).\n\n"
     << "| scene | system | vars × eqs | dense array | solver CPU | boxes | roots | complete | × time | × boxes |\n"
     << "|:--|:--|--:|--:|--:|--:|--:|:--|--:|--:|\n";
  for (const auto& s : scenes) {
    const Record& red = s.precision[double_1e12];
    auto dense = [](const std::pair<double, double>& d) { return d.first > 0 ? fmt(d.first, d.first < 1e6 ? 6 : 3) : std::string("–"); };
    md << "| **" << s.a.name << "** | reduced (" << s.a.combinations << " charts) | " << s.a.vars << " × " << s.a.eqs << " | "
       << dense(s.dense_reduced) << " | ";
    if (red.status == OK)
      md << seconds_text(red.cpu) << " | " << red.boxes << " | " << red.certified << " | "
         << (red.complete ? "yes" : "**no** (" + md_escape(red.reasons) + ")") << " | | |\n";
    else md << "*" << md_escape(status_text(red)) << "* | | | | | |\n";
    for (int k = 0; k < 2; ++k) {
      const Record& r = s.naive[k];
      md << "| | " << naive_names[k] << " | ";
      if (r.status != OK) {
        md << (s.naive_vars[k] ? std::to_string(s.naive_vars[k]) + " × " + std::to_string(s.naive_eqs[k]) : "") << " | " << dense(s.dense_naive[k]) << " | *"
           << md_escape(status_text(r)) << "* | | | | | |\n";
        continue;
      }
      md << r.vars << " × " << r.eqs << " | " << dense(s.dense_naive[k]) << " | " << seconds_text(r.cpu) << " | " << r.boxes << " | " << r.certified << " | "
         << (r.complete ? "yes" : "**no** (" + md_escape(r.reasons) + ")") << " | ";
      if (red.status == OK && red.cpu > 0 && (red.complete || r.complete)) {
        const std::string bound = red.complete == r.complete ? "" : (red.complete ? "> " : "< ");
        md << bound << ratio_text(r.cpu / red.cpu) << " | " << bound << ratio_text(double(r.boxes) / double(std::max(1L, red.boxes))) << " |\n";
      } else md << "– | – |\n";
    }
  }

  // part 4
  md << "\n## 4. PHCpack\n\n";
  if (!have_phc)
    md << "`" << phc << "` was not found (Debian package `phcpack`): this part was not run.\n";
  else {
    md << "Every chart combination of the reduced system, and the naive systems, written in PHCpack's input format (variables "
          "x1 .. xn, coefficients rounded to 17 significant digits; interval coefficients by their midpoints) and solved by "
          "`phc -b` (blackbox: root count, polyhedral or linear-product homotopy, path tracking, refinement; one task). The "
          "chart combinations are solved in turn while the scene's budget (" << cap << " s, " << long_cap << " s for "
          "stewart_gough40, wall clock) lasts; the run that exceeds it is killed and not counted; each naive system gets the "
          "budget too. *phc CPU* = user + system time of the phc processes; *our CPU* = our solver (part 1, double, 1e-12) on "
          "the same chart combinations, or on the naive system (part 3); a solution is real when its imaginary parts are "
          "below 1e-8 (1 + |real part|); *real in box* = real solutions inside the chart's box (the box our solver searches); "
          "*ours* = our certified roots there; *agree* = chart combinations where the two sets are the same (same number, "
          "each of ours within 1e-6 of one of phc's), out of those phc finished. *× time* = phc / ours. PHCpack is "
          "randomized (its gamma constant): a path that fails can lose a solution in one run and not in the next.\n\n"
       << "| scene | system | phc CPU | our CPU | × time | solutions | real | real in box | ours | agree |\n"
       << "|:--|:--|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const auto& s : scenes) {
      const Record& red = s.precision[double_1e12];
      md << "| **" << s.a.name << "** | reduced (" << (s.phc_done < s.phc_total ? std::to_string(s.phc_done) + " of " : "")
         << s.phc_total << " charts) | ";
      if (s.phc_status == OK)
        md << seconds_text(s.phc_cpu) << " | " << (red.status == OK ? seconds_text(s.phc_our_cpu) : "–") << " | "
           << (red.status == OK && s.phc_our_cpu > 0 ? ratio_text(s.phc_cpu / s.phc_our_cpu) : "–") << " | " << s.phc_solutions << " | "
           << s.phc_real << " | " << s.phc_real_in_box << " | " << (red.status == OK ? std::to_string(s.phc_ours) : "–")
           << (red.status == OK && !red.complete ? " (not complete)" : "") << " | " << s.phc_agree << " / " << s.phc_done << " |\n";
      else md << "*" << md_escape(s.phc_message) << "* | " << (red.status == OK ? seconds_text(red.cpu) : "–") << " | | | | | "
              << (red.status == OK ? std::to_string(red.certified) + (red.complete ? "" : " (not complete)") : "–") << " | |\n";
      for (int k = 0; k < 2; ++k) {
        const Phc_run& p = s.phc_naive[k];
        const Record& r = s.naive[k];
        md << "| | " << naive_names[k] << " | ";
        if (p.status != OK) { md << "*" << md_escape(p.message.empty() ? "not run" : p.message) << "* | | | | | | | |\n"; continue; }
        md << seconds_text(p.cpu) << " | " << (r.status == OK ? seconds_text(r.cpu) : "–") << " | "
           << (r.status == OK && r.cpu > 0 ? (r.complete ? "" : "< ") + ratio_text(p.cpu / r.cpu) : "–") << " | " << p.solutions
           << " | " << p.real << " | | " << (r.status == OK ? std::to_string(r.certified) + (r.complete ? "" : " (not complete)") : "–")
           << " | |\n";
      }
    }
  }

  // observations computed from the numbers
  md << "\n## Observations\n\n";
  bool any = false;
  for (unsigned bits : {53u, 113u, 256u}) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    bool same_boxes = true, measured = false;
    for (const auto& s : scenes) {
      long boxes = -1;
      for (std::size_t k = 0; k < n_precision; ++k) {
        if (precision_cells[k].bits != bits || s.precision[k].status != OK) continue;
        if (boxes >= 0 && s.precision[k].boxes != boxes) same_boxes = false;
        boxes = s.precision[k].boxes;
        if (std::isnan(s.accuracy[k])) continue;
        lo = std::min(lo, s.accuracy[k]);
        hi = std::max(hi, s.accuracy[k]);
        measured = true;
      }
    }
    if (!measured) continue;
    std::string tols;
    for (const auto& pc : precision_cells) if (pc.bits == bits) tols += (tols.empty() ? "" : ", ") + tolerance_text(pc.tolerance);
    md << "- " << (bits == 53 ? std::string("double") : "Gmpfi at " + std::to_string(bits) + " bits") << " (tolerance " << tols
       << "): achieved accuracy between " << accuracy_text(lo) << " and " << accuracy_text(hi) << " on every scene"
       << (same_boxes ? "; the tolerance changes neither the boxes nor the roots" : "") << ".\n";
    any = true;
  }
  for (const auto& s : scenes) {
    const Record &d = s.precision[double_1e12], &m = s.precision[4];
    if (d.status == OK && m.status == OK && d.complete && m.complete && d.cpu > 0)
      md << "- " << s.a.name << ": Gmpfi at 113 bits (1e-20) costs " << ratio_text(m.cpu / d.cpu) << " times the double solve (1e-12), "
         << (m.boxes == d.boxes ? "with the same boxes" : std::to_string(m.boxes) + " boxes against " + std::to_string(d.boxes)) << ".\n";
  }
  for (const auto& s : scenes) {
    for (std::size_t k = 0; k < n_precision; ++k) {
      const Record& r = s.precision[k];
      if (r.status != OK) continue;
      if (!r.complete) {
        md << "- " << s.a.name << ", " << precision_cells[k].key << ": not complete (" << r.unknown << " unknown, " << r.pending
           << " pending: " << md_escape(r.reasons) << "), " << r.certified << " roots certified.\n";
        any = true;
      }
      if (s.reference.status == OK && (r.certified != s.reference.roots || s.missed[k] > 0)) {
        md << "- " << s.a.name << ", " << precision_cells[k].key << ": " << r.certified << " roots against " << s.reference.roots
           << " in the reference (" << s.missed[k] << " reference roots not found).\n";
        any = true;
      }
    }
    if (s.certified.status == OK && s.certified.configurations != s.a.expected) {
      md << "- " << s.a.name << ": " << s.certified.configurations << " configurations in certified mode, " << s.a.expected << " expected.\n";
      any = true;
    }
    if (s.fast.status == OK && s.fast.configurations != s.a.expected) {
      md << "- " << s.a.name << ": fast mode finds " << s.fast.configurations << " configurations, " << s.a.expected << " expected.\n";
      any = true;
    }
    if (s.phc_status == OK && s.phc_agree != s.phc_done) {
      md << "- " << s.a.name << ": PHCpack's real solutions in the chart boxes agree with our roots in " << s.phc_agree << " of "
         << s.phc_done << " chart combinations (" << s.phc_real_in_box << " against our " << s.phc_ours << "):\n";
      for (const auto& m : s.phc_mismatch) md << "  - " << md_escape(m) << "\n";
      any = true;
    }
    if (s.phc_status == OK && s.phc_done < s.phc_total) {
      md << "- " << s.a.name << ": PHCpack finished " << s.phc_done << " of " << s.phc_total << " chart combinations within the budget of "
         << (s.a.long_scene ? long_cap : cap) << " s.\n";
      any = true;
    }
  }
  if (!any) md << "- Nothing unexpected: every cell found the reference roots and the expected configurations.\n";
  write_svg(prefix + ".svg", scenes);
  std::cout << "total " << fixed(total.time(), 1) << " s; wrote " << prefix << ".md, " << prefix << ".csv and " << prefix << ".svg\n";
  if (!phc_dir.empty() && std::getenv("BENCHMARK_SOLVER_KEEP_PHC")) std::cout << "PHCpack files kept in " << phc_dir << "\n";
  else if (!phc_dir.empty()) {
    std::string rm = "rm -rf '" + phc_dir + "'";
    if (std::system(rm.c_str()) != 0) std::cerr << "could not remove " << phc_dir << "\n";
  }
  return 0;
}
