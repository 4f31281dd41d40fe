// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// `rigid_incidence solve`: every real configuration of a scene, certified, as text, JSON and
// an SVG gallery.

#ifndef RIGID_INCIDENCE_EXAMPLES_SOLVE_COMMAND_H
#define RIGID_INCIDENCE_EXAMPLES_SOLVE_COMMAND_H

#include <CGAL/Rigid_incidence.h>

#include <nlohmann/json.hpp>

#include <atomic>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <signal.h>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace solve_command {

namespace RI = CGAL::Rigid_incidence;

struct Solve_options
{
  long scale_exponent = 0;  // the scene was solved scaled by 2^-scale_exponent (see scaled_scene())
  double tolerance = 1e-12;
  unsigned precision = 53;
  bool fast = false;
  bool no_plan = false;        // --no-plan: each reduced system solved whole (for comparison)
  bool no_sweep = false;       // --no-sweep: never solved along the tree by a sweep (for comparison)
  bool no_propagation = false; // --no-propagation: every chart combination built (for comparison)
  bool no_consistency = false; // --no-consistency: no arc consistency along the tree (for comparison)
  std::size_t max_boxes = 0;   // 0: the solver's default
  std::string svg, near;
  std::string plot;  // --plot A.x,B.z: the coordinates plotted against each other for curves
  double max_seconds = 0;  // --max-seconds: the whole solve (0: no limit)
  bool quiet = false;      // --quiet: no progress line
  unsigned threads = 0;    // --threads: 0, every core (Subdivision_solver_parameters::threads)
  std::size_t max_listed = RI::Scene_solve_parameters().maximal_listed_configurations;  // --max-listed (0: all)
};

// SIGINT and SIGTERM during a solve: the solve stops as at its time limit and the partial
// answer is printed (the exit status is then 128 + the signal); a second one, more than half a
// second after the first, ends the program at once (the default action).
inline std::atomic<bool> interrupted{false};

// An exact count as a JSON number where it fits in 64 bits, else as its decimal digits
inline nlohmann::ordered_json count_json(const CGAL::Gmpz& n)
{
  std::ostringstream o;
  o << n;
  if (n >= 0 && o.str().size() < 20) return nlohmann::ordered_json(std::stoull(o.str()));
  return nlohmann::ordered_json(o.str());
}

// The work of a full solve (analyze, reduce), or nothing and why it could not be estimated
template <class Traits>
std::optional<RI::Scene_solve_work> estimate_work(const RI::Rigid_body_collection<Traits>& c, const RI::Incidence_tree& t,
                                                  const RI::Well_formed_selection& s, std::string& why)
{
  try {
    return RI::scene_solve_work(c, t, s);
  } catch (const std::exception& e) {
    why = e.what();
    return std::nullopt;
  }
}

// ", arc consistency kept 1.2 to 29 % of each hinge's circle (0.21 s)", or nothing
inline std::string consistency_text(const RI::Scene_solve_statistics& st)
{
  if (st.consistent_fraction.empty()) return std::string();
  const auto mm = std::minmax_element(st.consistent_fraction.begin(), st.consistent_fraction.end());
  std::ostringstream o;
  o << std::setprecision(2) << ", arc consistency kept " << 100 * *mm.first << " to " << 100 * *mm.second << " % of each hinge's circle ("
    << std::setprecision(3) << st.consistency_seconds << " s)";
  return o.str();
}

// Scene_solve_work as JSON (analyze, reduce)
inline nlohmann::ordered_json work_json(const RI::Scene_solve_work& w)
{
  nlohmann::ordered_json placements = nlohmann::ordered_json::array();
  for (const auto& p : w.placements) placements.push_back({{"body", p.first}, {"placements", p.second}});
  return {{"chart_combinations", w.chart_combinations}, {"placement_combinations", w.placement_combinations},
          {"placements", placements}, {"systems", w.systems()}, {"variables", w.variables}, {"equations", w.equations},
          {"block_sizes", w.block_sizes}, {"independent_parts", w.independent_parts},
          {"sweep", w.sweep_driver.empty() ? nlohmann::ordered_json(nullptr)
                                           : nlohmann::ordered_json{{"driver", w.sweep_driver}, {"steps", w.sweep_steps}, {"checks", w.sweep_checks}}}};
}
inline volatile std::sig_atomic_t signal_received = 0;
inline std::atomic<long long> first_signal_ns{0};
// A signal repeated within half a second is the same request: GNU timeout (and kill of a
// process group) sends SIGTERM to the program and then to its group, so the program receives
// it twice at once; only a later one ends the program (clock_gettime and raise are
// async-signal-safe).
inline void on_signal(int sig)
{
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);
  const long long ns = (long long)now.tv_sec * 1000000000LL + now.tv_nsec;
  if (!signal_received) {
    first_signal_ns.store(ns);
    signal_received = sig;
    interrupted.store(true);
  } else if (ns - first_signal_ns.load() > 500000000LL) {
    std::signal(sig, SIG_DFL);
    std::raise(sig);
  }
}

// The progress line on standard error, when it is a terminal (at most 4 times a second,
// rewritten in place, erased at the end).
struct Progress_line
{
  std::chrono::steady_clock::time_point last{};
  bool shown = false;
  void operator()(const RI::Scene_solve_progress& g)
  {
    const auto now = std::chrono::steady_clock::now();
    if (shown && now - last < std::chrono::milliseconds(250)) return;
    last = now;
    shown = true;
    std::ostringstream line;
    line << std::setprecision(3) << "rigid_incidence: solving: " << g.combinations_done << "/";
    if (g.combinations_total) line << g.combinations_total; else line << "many";
    line << " chart and placement combinations, " << g.boxes << " boxes, " << g.configurations << " configuration(s), "
         << (g.coefficient_precision ? std::to_string(g.coefficient_precision) + "-bit" : std::string("exact")) << " coefficients, "
         << g.seconds << " s";
    std::cerr << "\r" << line.str() << "\033[K" << std::flush;
  }
  ~Progress_line()
  {
    if (shown) std::cerr << "\r\033[K" << std::flush;
  }
};

// Parses a positive number option; an Input_error names the option.
inline double parse_positive(const std::string& opt, const std::string& v)
{
  char* end = nullptr;
  double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(x) || !(x > 0))
    throw RI::Input_error(opt + ": '" + v + "' is not a positive number");
  return x;
}

// The power of two nearest the size of a scene: the largest coordinate of a point of two or
// more bodies or of a distance, or distance (0 for an empty scene); as solve_scene() measures
// a collection (a frame point at 1e308 alone does not make the scene's hinges tiny).
inline long scene_size_exponent(const RI::Scene& scene)
{
  std::map<std::string, int> uses;
  for (const auto& b : scene.bodies)
    for (const auto& p : b.points) ++uses[p.label];
  for (const auto& d : scene.distances) { uses[d.a] += 2; uses[d.b] += 2; }
  bool any = false;
  long hi = 0;
  auto see = [&](const CGAL::Gmpq& q, long div) {
    if (q == 0) return;
    long x = RI::internal::binary_exponent(q) / div;
    hi = any ? (std::max)(hi, x) : x;
    any = true;
  };
  for (const auto& b : scene.bodies)
    for (const auto& p : b.points)
      if (uses[p.label] >= 2) { see(p.x, 1); see(p.y, 1); see(p.z, 1); }
  for (const auto& d : scene.distances) see(d.squared, 2);
  return hi;
}

// The scene with every length multiplied by 2^e, exactly: the same configurations, scaled.
// The tool solves a scene whose size is beyond 2^+-20 at unit size (the reduced system's
// coefficients grow as the sixth power of the size and left the range of doubles at 1e55),
// and scales the configurations back.
inline RI::Scene scaled_scene(RI::Scene s, long e)
{
  CGAL::Gmpz p(1);
  mpz_mul_2exp(p.mpz(), p.mpz(), (unsigned long)(e < 0 ? -e : e));
  const CGAL::Gmpq f = e >= 0 ? CGAL::Gmpq(p) : CGAL::Gmpq(CGAL::Gmpz(1), p);
  for (auto& b : s.bodies)
    for (auto& q : b.points) { q.x *= f; q.y *= f; q.z *= f; }
  for (auto& d : s.distances) { d.squared *= f * f; d.length *= f; }
  s.free_distance.lo *= f;
  s.free_distance.hi *= f;
  s.free_distance.nominal_squared *= f * f;
  return s;
}

// The pose of every body of the scene file (each has coordinates): the best rigid fit of its
// points onto the configuration's.
inline std::vector<std::pair<std::string, RI::Rigid_fit>> user_poses(const RI::Scene& scene, const RI::Configuration& conf)
{
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < conf.labels.size(); ++i) index[conf.labels[i]] = i;
  std::vector<std::pair<std::string, RI::Rigid_fit>> out;
  for (const auto& b : scene.bodies) {
    std::vector<std::array<double, 3>> y, x;
    for (const auto& p : b.points) {
      auto it = index.find(p.label);
      if (it == index.end() || !conf.placed[it->second]) continue;
      y.push_back({CGAL::to_double(p.x), CGAL::to_double(p.y), CGAL::to_double(p.z)});
      x.push_back(conf.points[it->second]);
    }
    RI::Rigid_fit f;
    if (y.size() >= 3) f = RI::fit_rigid_motion(y, x);
    else if (y.size() >= 1) {  // a bar or a single point: a translation (its rotation is not defined)
      f.ok = false;
      f.motion.t = {x[0][0] - y[0][0], x[0][1] - y[0][1], x[0][2] - y[0][2]};
    }
    out.push_back({b.name, f});
  }
  return out;
}

inline nlohmann::ordered_json points_json(const RI::Configuration& conf)
{
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < conf.labels.size(); ++i)
    if (conf.placed[i]) j[conf.labels[i]] = {conf.points[i][0], conf.points[i][1], conf.points[i][2]};
  return j;
}

// The configuration to order the solutions by (--near): {"points": {label: [x, y, z]}}, or a
// `solve --json` output (its first solution).
inline std::map<std::string, std::array<double, 3>> read_near(const std::string& file)
{
  std::ifstream in(file);
  if (!in) throw RI::Input_error(file + ": cannot open the configuration given to --near");
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw RI::Input_error(file + ": not JSON (" + e.what() + ")");
  }
  if (j.is_object() && j.contains("solutions") && j["solutions"].is_array() && !j["solutions"].empty()) j = j["solutions"][0];
  if (!j.is_object() || !j.contains("points") || !j["points"].is_object())
    throw RI::Input_error(file + ": expected {\"points\": {label: [x, y, z], ...}} (or the output of solve --json)");
  std::map<std::string, std::array<double, 3>> out;
  for (auto it = j["points"].begin(); it != j["points"].end(); ++it) {
    const auto& v = it.value();
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      throw RI::Input_error(file + ": point '" + it.key() + "' is not [x, y, z]");
    out[it.key()] = {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  }
  if (out.empty()) throw RI::Input_error(file + ": no point given");
  return out;
}

inline double near_distance(const RI::Configuration& c, const std::map<std::string, std::array<double, 3>>& ref, std::size_t& common)
{
  double s = 0;
  common = 0;
  for (std::size_t i = 0; i < c.labels.size(); ++i) {
    if (!c.placed[i]) continue;
    auto it = ref.find(c.labels[i]);
    if (it == ref.end()) continue;
    for (int k = 0; k < 3; ++k) s += (c.points[i][k] - it->second[k]) * (c.points[i][k] - it->second[k]);
    ++common;
  }
  return common ? std::sqrt(s / double(common)) : std::numeric_limits<double>::infinity();
}

// One configuration as a projected line drawing in the cell at (ox, oy): bodies as edges
// between their points, distances dashed, shared points marked; one view direction for all.
inline void draw_frame(std::ostream& out, const RI::Scene& scene, const RI::Configuration& conf, double ox, double oy, double cell,
                       const std::string& caption)
{
  const double az = 0.6, el = 0.45, pad = cell / 13;  // view: azimuth and elevation in radians
  auto project = [&](const std::array<double, 3>& p) {
    double x = std::cos(az) * p[0] - std::sin(az) * p[1];
    double y0 = std::sin(az) * p[0] + std::cos(az) * p[1];
    double y = std::cos(el) * p[2] - std::sin(el) * y0;
    return std::array<double, 2>{x, -y};
  };
  std::map<std::string, int> uses;
  for (const auto& b : scene.bodies) for (const auto& p : b.points) ++uses[p.label];
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  std::map<std::string, std::array<double, 2>> q;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (std::size_t i = 0; i < conf.labels.size(); ++i) {
    if (!conf.placed[i]) continue;
    auto p = project(conf.points[i]);
    q[conf.labels[i]] = p;
    for (int a = 0; a < 2; ++a) { lo[a] = std::min(lo[a], p[a]); hi[a] = std::max(hi[a], p[a]); }
  }
  const double s = (cell - 2 * pad) / std::max(1e-300, std::max(hi[0] - lo[0], hi[1] - lo[1]));
  auto X = [&](const std::array<double, 2>& p) { return ox + pad + (p[0] - lo[0]) * s; };
  auto Y = [&](const std::array<double, 2>& p) { return oy + pad + (p[1] - lo[1]) * s; };
  out << "<g>\n<rect x=\"" << ox + 2 << "\" y=\"" << oy + 2 << "\" width=\"" << cell - 4 << "\" height=\"" << cell - 4
      << "\" fill=\"none\" stroke=\"#ccc\"/>\n<text x=\"" << ox + 8 << "\" y=\"" << oy + 14 << "\">" << caption << "</text>\n";
  std::size_t bi = 0;
  for (const auto& b : scene.bodies) {
    const char* col = colours[bi++ % 8];
    for (std::size_t i = 0; i < b.points.size(); ++i)
      for (std::size_t j = i + 1; j < b.points.size(); ++j) {
        auto a = q.find(b.points[i].label), c = q.find(b.points[j].label);
        if (a == q.end() || c == q.end()) continue;
        out << "<line x1=\"" << X(a->second) << "\" y1=\"" << Y(a->second) << "\" x2=\"" << X(c->second) << "\" y2=\"" << Y(c->second)
            << "\" stroke=\"" << col << "\" stroke-width=\"1.3\"/>\n";
      }
  }
  for (const auto& d : scene.distances) {
    auto a = q.find(d.a), c = q.find(d.b);
    if (a == q.end() || c == q.end()) continue;
    out << "<line x1=\"" << X(a->second) << "\" y1=\"" << Y(a->second) << "\" x2=\"" << X(c->second) << "\" y2=\"" << Y(c->second)
        << "\" stroke=\"#555\" stroke-dasharray=\"4 3\"/>\n";
  }
  for (const auto& p : q) {
    bool shared = uses[p.first] > 1;
    out << "<circle cx=\"" << X(p.second) << "\" cy=\"" << Y(p.second) << "\" r=\"" << (shared ? 3.5 : 2) << "\" fill=\""
        << (shared ? "black" : "white") << "\" stroke=\"black\"/>\n";
    if (shared && cell >= 200) out << "<text x=\"" << X(p.second) + 4 << "\" y=\"" << Y(p.second) - 4 << "\">" << p.first << "</text>\n";
  }
  out << "</g>\n";
}

inline const char* curve_end_name(RI::Curve_end e)
{
  switch (e) {
  case RI::Curve_end::CLOSED: return "closed";
  case RI::Curve_end::BOUNDARY: return "boundary";
  case RI::Curve_end::UNRESOLVED: return "unresolved";
  default: return "inequality";
  }
}

inline std::string short_number(double x)
{
  std::ostringstream os;
  os << std::setprecision(2) << x;
  return os.str();
}

// The gallery: each configuration as a projected line drawing, side by side.
inline void write_svg(const std::string& file, const RI::Scene& scene, const RI::Scene_solve_result& r, const std::string& title)
{
  std::ofstream out(file);
  if (!out) throw RI::Input_error("--svg: cannot write '" + file + "'");
  out << std::fixed << std::setprecision(2);  // coordinates in pixels
  const std::size_t n = r.configurations.size(), cols = n == 0 ? 1 : std::min<std::size_t>(n, 4), rows = n == 0 ? 1 : (n + cols - 1) / cols;
  const double cell = 260;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << cols * cell << "\" height=\"" << rows * cell + 30
      << "\" font-family=\"sans-serif\" font-size=\"10\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"8\" y=\"18\" font-size=\"13\">" << title << "</text>\n";
  if (n == 0) out << "<text x=\"8\" y=\"60\">no configuration" << (r.complete() ? "" : " certified (see the unresolved regions)") << "</text>\n";
  for (std::size_t k = 0; k < n; ++k)
    draw_frame(out, scene, r.configurations[k].configuration, (k % cols) * cell, 30 + (k / cols) * cell, cell,
               "#" + std::to_string(k + 1) + (r.configurations[k].certified ? " certified" : " not certified") + ", residual " +
                   short_number(r.configurations[k].max_residual));
  out << "</svg>\n";
}

// The point coordinate named "LABEL.x" (or .y, .z): its index in the configuration, and axis.
inline std::pair<std::size_t, int> coordinate_named(const RI::Configuration& conf, const std::string& name)
{
  const auto dot = name.rfind('.');
  if (dot == std::string::npos || dot + 2 != name.size() || name[dot + 1] < 'x' || name[dot + 1] > 'z')
    throw RI::Input_error("--plot: '" + name + "' is not LABEL.x, LABEL.y or LABEL.z");
  for (std::size_t i = 0; i < conf.labels.size(); ++i)
    if (conf.labels[i] == name.substr(0, dot) && conf.placed[i]) return {i, name[dot + 1] - 'x'};
  throw RI::Input_error("--plot: no placed point '" + name.substr(0, dot) + "' in the scene");
}

// The motion of a scene with one degree of freedom: per branch a strip of frames evenly
// spaced along it, then a plot of one point coordinate against another for every branch
// (`plot`: "A.x,B.z"; empty: the point that moves most, its two most varying coordinates).
inline void write_curves_svg(const std::string& file, const RI::Scene& scene, const RI::Scene_solve_result& r, const std::string& title,
                             const std::string& plot)
{
  std::ofstream out(file);
  if (!out) throw RI::Input_error("--svg: cannot write '" + file + "'");
  out << std::fixed << std::setprecision(2);
  const std::size_t frames = 6;
  const double cell = 150, plot_size = 420;
  const std::size_t n = r.curves.size();
  // the plotted coordinates
  std::pair<std::size_t, int> ax{0, 0}, ay{0, 1};
  std::string xname, yname;
  const RI::Configuration& c0 = r.curves.front().configurations.front();
  if (!plot.empty()) {
    const auto comma = plot.find(',');
    if (comma == std::string::npos) throw RI::Input_error("--plot: expected two coordinates, e.g. E1.x,E1.z");
    xname = plot.substr(0, comma);
    yname = plot.substr(comma + 1);
    ax = coordinate_named(c0, xname);
    ay = coordinate_named(c0, yname);
  } else {
    // the point and axes that vary most over all branches
    std::vector<std::array<double, 3>> lo(c0.points.size(), {1e300, 1e300, 1e300}), hi(c0.points.size(), {-1e300, -1e300, -1e300});
    for (const auto& c : r.curves)
      for (const auto& f : c.configurations)
        for (std::size_t i = 0; i < f.points.size(); ++i)
          for (int a = 0; a < 3; ++a) { lo[i][a] = std::min(lo[i][a], f.points[i][a]); hi[i][a] = std::max(hi[i][a], f.points[i][a]); }
    double best = -1;
    for (std::size_t i = 0; i < c0.points.size(); ++i) {
      if (!c0.placed[i]) continue;
      std::array<int, 3> order{{0, 1, 2}};
      std::sort(order.begin(), order.end(), [&](int a, int b) { return hi[i][a] - lo[i][a] > hi[i][b] - lo[i][b]; });
      const double spread = hi[i][order[0]] - lo[i][order[0]] + hi[i][order[1]] - lo[i][order[1]];
      if (spread > best) {
        best = spread;
        ax = {i, std::min(order[0], order[1])};
        ay = {i, std::max(order[0], order[1])};
      }
    }
    xname = c0.labels[ax.first] + "." + char('x' + ax.second);
    yname = c0.labels[ay.first] + "." + char('x' + ay.second);
  }
  const double width = std::max(frames * cell, plot_size + 40), height = 30 + n * (cell + 20) + plot_size + 60;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"10\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"8\" y=\"18\" font-size=\"13\">" << title << "</text>\n";
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  for (std::size_t k = 0; k < n; ++k) {
    const auto& c = r.curves[k];
    const double oy = 30 + k * (cell + 20);
    out << "<text x=\"8\" y=\"" << oy + 12 << "\" fill=\"" << colours[k % 8] << "\">branch " << k + 1 << (c.certified ? ", certified" : ", not certified")
        << (c.closed ? ", closed" : "") << ", " << c.configurations.size() << " frames, residual " << short_number(c.max_residual) << "</text>\n";
    for (std::size_t f = 0; f < frames; ++f) {
      const std::size_t at = c.configurations.size() == 1 ? 0 : f * (c.configurations.size() - 1) / (frames - 1);
      draw_frame(out, scene, c.configurations[at], f * cell, oy + 16, cell, std::to_string(at + 1));
    }
  }
  // the plot
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& c : r.curves)
    for (const auto& f : c.configurations) {
      const double v[2] = {f.points[ax.first][ax.second], f.points[ay.first][ay.second]};
      for (int a = 0; a < 2; ++a) { lo[a] = std::min(lo[a], v[a]); hi[a] = std::max(hi[a], v[a]); }
    }
  const double px = 40, py = 30 + n * (cell + 20) + 20, side = plot_size - 20;
  const double span = std::max(1e-300, std::max(hi[0] - lo[0], hi[1] - lo[1]));
  auto X = [&](double v) { return px + (v - lo[0]) / span * side; };
  auto Y = [&](double v) { return py + side - (v - lo[1]) / span * side; };
  out << "<rect x=\"" << px << "\" y=\"" << py << "\" width=\"" << side << "\" height=\"" << side << "\" fill=\"none\" stroke=\"#999\"/>\n"
      << "<text x=\"" << px << "\" y=\"" << py + side + 16 << "\">" << xname << " from " << short_number(lo[0]) << " (equal scales; "
      << yname << " up from " << short_number(lo[1]) << ")</text>\n";
  for (std::size_t k = 0; k < n; ++k) {
    const auto& c = r.curves[k];
    out << "<polyline fill=\"none\" stroke=\"" << colours[k % 8] << "\" stroke-width=\"1.2\" points=\"";
    for (const auto& f : c.configurations) out << X(f.points[ax.first][ax.second]) << "," << Y(f.points[ay.first][ay.second]) << " ";
    if (c.closed) out << X(c.configurations.front().points[ax.first][ax.second]) << "," << Y(c.configurations.front().points[ay.first][ay.second]);
    out << "\"/>\n";
  }
  out << "</svg>\n";
}

template <class IT, class NT, class Traits>
RI::Scene_solve_result run(const RI::Scene& scene, const RI::Rigid_body_collection<Traits>& input, const RI::Rigid_body_collection<Traits>& c,
                           const RI::Incidence_tree& t, const RI::Well_formed_selection& s, const Solve_options& o)
{
  RI::Scene_solve_parameters p;
  for (const auto& q : scene.inequalities) {
    RI::Orientation_inequality g;
    for (std::size_t k = 0; k < 4; ++k) g.points[k] = q.points[k];
    g.negative = q.negative;
    p.inequalities.push_back(g);
  }
  p.solver.tolerance = o.tolerance;
  p.solver.precision = o.precision;
  p.solver.fast = o.fast;
  p.solver.threads = o.threads;
  if (o.max_boxes) p.solver.maximal_boxes = o.max_boxes;
  p.maximal_seconds = o.max_seconds;
  p.maximal_listed_configurations = o.max_listed;
  p.solve_with_plan = !o.no_plan;
  p.sweep = !o.no_sweep;
  p.chart_propagation = !o.no_propagation;
  if (o.no_consistency) p.consistency_cells = 0;
  p.interrupt = &interrupted;
  Progress_line line;
  if (!o.quiet && isatty(2)) p.progress = std::ref(line);
  return RI::solve_scene<IT, NT>(input, c, t, s, p);
}

template <class Traits>
int solve(const RI::Scene& scene, const RI::Rigid_body_collection<Traits>& input, const RI::Rigid_body_collection<Traits>& c,
          const RI::Incidence_tree& t, const RI::Well_formed_selection& s, const RI::Dof_count& dof, const Solve_options& o, bool json,
          const std::string& scene_file, double analysis_seconds)
{
  // exact coefficients when every covering body has coordinates (and no other body holds a
  // pair through a placement), else certified intervals
  const bool exact = RI::exact_coefficients(c, t);
  RI::Scene_solve_result r;
  struct sigaction act {};
  act.sa_handler = on_signal;
  sigemptyset(&act.sa_mask);
  act.sa_flags = SA_RESTART;  // (the handler stays installed: on_signal decides what a repeat does)
  ::sigaction(SIGINT, &act, nullptr);
  ::sigaction(SIGTERM, &act, nullptr);
  if (o.precision <= 53) {
    if (exact) r = run<CGAL::Interval_nt<false>, CGAL::Gmpq>(scene, input, c, t, s, o);
    else r = run<CGAL::Interval_nt<false>, CGAL::Interval_nt<false>>(scene, input, c, t, s, o);
  } else {
#ifdef CGAL_USE_MPFI
    if (exact) r = run<CGAL::Gmpfi, CGAL::Gmpq>(scene, input, c, t, s, o);
    else {
      CGAL::Gmpfi::Precision_type old = CGAL::Gmpfi::set_default_precision(o.precision);
      r = run<CGAL::Gmpfi, CGAL::Gmpfi>(scene, input, c, t, s, o);
      CGAL::Gmpfi::set_default_precision(old);
    }
#else
    throw RI::Input_error("--precision above 53 bits needs MPFI (Debian libmpfi-dev); this build has none");
#endif
  }
  // the tool scaled the scene before reading it into the kernel (a double kernel could not
  // hold it); solve_scene() scales what it is given by itself
  if (o.scale_exponent != 0) RI::internal::scale_result(r, o.scale_exponent);  // (a curve's max_residual stays at unit size)
  if (!o.near.empty()) {
    auto ref = read_near(o.near);
    std::stable_sort(r.configurations.begin(), r.configurations.end(), [&](const RI::Scene_configuration& a, const RI::Scene_configuration& b) {
      std::size_t ca, cb;
      return near_distance(a.configuration, ref, ca) < near_distance(b.configuration, ref, cb);
    });
  }
  if (!o.svg.empty() && !r.curves.empty())
    write_curves_svg(o.svg, scene, r, (scene.name.empty() ? scene_file : scene.name) + ": " + std::to_string(r.curves.size()) +
                                           " curve branch(es) of configurations" + (r.complete() ? ", complete" : ", NOT complete"),
                     o.plot);
  else if (!o.svg.empty())
    write_svg(o.svg, scene, r, (scene.name.empty() ? scene_file : scene.name) + ": " + std::to_string(r.configurations.size()) +
                                  " configuration(s)" + (r.complete() ? ", complete" : ", NOT complete"));
  const auto& st = r.statistics;
  if (json) {
    nlohmann::ordered_json j;
    j["scene"] = scene_file;
    j["analysis"] = {{"bodies", scene.bodies.size()}, {"standard_bodies", c.number_of_bodies()}, {"dof", dof.dof},
                     {"verdict", dof.verdict()}, {"covering_set", t.covering_set.size()}, {"tree_weight", t.weight}};
    nlohmann::ordered_json vars = nlohmann::ordered_json::array();
    for (const auto& v : r.variables) vars.push_back(v);
    j["reduced_system"] = {{"variables", vars}, {"equations", r.equations}};
    j["complete"] = r.complete();
    j["certified"] = !r.fast;
    j["scale_exponent"] = r.scale_exponent;
    j["diagnosis"] = r.diagnosis.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.diagnosis);
    j["no_configuration"] = r.no_configuration.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.no_configuration);
    j["limits"] = r.limits;
    j["configuration_count"] = count_json(r.configuration_count);
    j["listing"] = r.listing.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.listing);
    j["unlisted_not_certified"] = r.unlisted_not_certified;
    nlohmann::ordered_json parts = nlohmann::ordered_json::array();
    for (const auto& q : r.parts) {
      nlohmann::ordered_json sols = nlohmann::ordered_json::array();
      for (const auto& x : q.solutions) {
        nlohmann::ordered_json params = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < q.variables.size() && i < x.parameters.size(); ++i)
          params[q.variables[i]] = {x.parameters[i].first, x.parameters[i].second};
        sols.push_back({{"certified", x.certified}, {"charts", x.charts}, {"found_in_charts", x.found}, {"parameters", params}});
      }
      parts.push_back({{"placements", q.placements}, {"bodies", q.bodies}, {"variables", q.variables}, {"count", q.solutions.size()},
                       {"unresolved", q.unresolved}, {"solutions", sols}});
    }
    j["parts"] = parts;
    j["coefficient_precision"] = r.coefficient_precision;
    j["precision_history"] = r.precision_history;
    nlohmann::ordered_json co = nlohmann::ordered_json::array();
    for (const auto& a : input.aliases()) co.push_back({{"label", a.alias}, {"same_point_as", a.label}, {"because", a.why}});
    j["coincidences"] = co;
    nlohmann::ordered_json pl = nlohmann::ordered_json::array();
    for (const auto& x : r.placements)
      pl.push_back({{"body", x.body}, {"placements", x.placements}, {"complete", x.complete}, {"precision_bits", x.precision}, {"decided_exactly", x.decided_exactly},
                    {"relative_width", x.relative_width},
                    {"singular", x.singular.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(x.singular)},
                    {"inconsistent", x.inconsistent.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(x.inconsistent)},
                    {"undecided", x.undecided.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(x.undecided)}});
    j["placements"] = pl;
    nlohmann::ordered_json sols = nlohmann::ordered_json::array();
    for (const auto& x : r.configurations) {
      nlohmann::ordered_json sj;
      sj["certified"] = x.certified;
      sj["singular"] = x.singular;
      if (x.singular) sj["singular_reason"] = x.singular_reason;
      if (!scene.inequalities.empty()) sj["on_inequality_boundary"] = x.on_inequality_boundary;
      nlohmann::ordered_json params = nlohmann::ordered_json::object();
      for (std::size_t i = 0; i < x.variables.size(); ++i) params[x.variables[i]] = {x.parameters[i].first, x.parameters[i].second};
      sj["parameters"] = params;
      sj["charts"] = x.charts;
      sj["found_in_charts"] = x.found;
      sj["coefficient_precision"] = x.coefficient_precision;
      nlohmann::ordered_json bodies = nlohmann::ordered_json::object();
      for (const auto& b : user_poses(scene, x.configuration)) {
        const auto& m = b.second.motion;
        nlohmann::ordered_json bj;
        if (b.second.ok) bj["rotation"] = {{m.R[0], m.R[1], m.R[2]}, {m.R[3], m.R[4], m.R[5]}, {m.R[6], m.R[7], m.R[8]}};
        else bj["rotation"] = nullptr;
        bj["translation"] = {m.t[0], m.t[1], m.t[2]};
        bodies[b.first] = bj;
      }
      sj["bodies"] = bodies;
      sj["points"] = points_json(x.configuration);
      sj["max_residual"] = x.max_residual;
      sj["max_relative_residual"] = x.max_relative_residual;
      sols.push_back(sj);
    }
    j["solutions"] = sols;
    nlohmann::ordered_json un = nlohmann::ordered_json::array();
    for (const auto& u : r.unresolved) {
      nlohmann::ordered_json uj;
      uj["class"] = u.kind == RI::Box_class::PENDING ? "pending" : "unknown";
      uj["reason"] = u.reason;
      nlohmann::ordered_json box = nlohmann::ordered_json::array();
      for (const auto& b : u.box) box.push_back({b.first, b.second});
      uj["box"] = box;
      uj["boxes"] = u.boxes;
      uj["charts"] = u.charts;
      uj["points"] = points_json(u.at_centre);
      un.push_back(uj);
    }
    j["unresolved"] = un;
    nlohmann::ordered_json cj = nlohmann::ordered_json::array();
    for (const auto& c : r.curves) {
      nlohmann::ordered_json x;
      x["certified"] = c.certified;
      x["closed"] = c.closed;
      x["ends"] = {curve_end_name(c.ends[0]), curve_end_name(c.ends[1])};
      x["note"] = c.note.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(c.note);
      x["max_residual"] = c.max_residual;
      if (!scene.inequalities.empty()) x["on_inequality_boundary"] = c.on_inequality_boundary;
      // each point's path along the branch, in the frame of the configurations
      nlohmann::ordered_json paths = nlohmann::ordered_json::object();
      const auto& f0 = c.configurations.front();
      for (std::size_t i = 0; i < f0.labels.size(); ++i) {
        if (!f0.placed[i]) continue;
        nlohmann::ordered_json path = nlohmann::ordered_json::array();
        for (const auto& f : c.configurations) path.push_back({f.points[i][0], f.points[i][1], f.points[i][2]});
        paths[f0.labels[i]] = path;
      }
      x["points"] = paths;
      nlohmann::ordered_json pieces = nlohmann::ordered_json::array();
      for (const auto& p : c.pieces) pieces.push_back({{"charts", p.charts}, {"parameters", p.parameters}});
      x["pieces"] = pieces;
      cj.push_back(x);
    }
    j["curves"] = cj;
    j["stats"] = {{"chart_combinations", st.chart_combinations}, {"excluded_at_once", st.excluded_at_once},
                  {"boxes", st.boxes}, {"krawczyk_tests", st.krawczyk_tests}, {"roots", st.roots},
                  {"duplicates_merged", st.duplicates}, {"spurious_rejected", st.spurious}, {"curve_boxes", st.curve_boxes},
                  {"placements_excluded", st.placements_excluded},
                  {"planned_systems", st.planned_systems}, {"block_solves", st.block_solves},
                  {"block_solves_reused", st.block_solves_reused}, {"excluded_by_plan", st.excluded_by_plan}, {"excluded_by_propagation", st.excluded_by_propagation},
                  {"swept", st.swept},
                  {"consistency", st.consistent_fraction.empty() ? nlohmann::ordered_json(nullptr)
                                  : nlohmann::ordered_json{{"kept", st.consistent_fraction}, {"seconds", st.consistency_seconds}}},
                  {"coefficient_width", st.coefficient_width}, {"threads", st.threads},
                  {"seconds", {{"analysis", analysis_seconds}, {"reduce", st.reduce_seconds}, {"solve", st.solve_seconds},
                               {"verify", st.verify_seconds}}}};
    std::cout << j.dump(2) << "\n";
    return signal_received && !r.complete() ? 128 + int(signal_received) : 0;  // (a signal after the last combination cut nothing)
  }
  std::cout << std::setprecision(10);
  std::cout << "scene " << scene_file << ": reduced system of " << r.variables.size() << " variables, " << r.equations << " equations; "
            << st.chart_combinations << " chart combination(s) solved" << (r.fast ? " in the FAST, NON-CERTIFIED mode" : "") << "\n";
  for (const auto& a : input.aliases())
    std::cout << "'" << a.alias << "' and '" << a.label << "' are one point, '" << a.label << "' (" << a.why << ")\n";
  if (r.scale_exponent != 0)
    std::cout << "the scene's size is about 2^" << r.scale_exponent << ": solved scaled by 2^" << -r.scale_exponent
              << " (exactly), its configurations given back at the scene's own scale\n";
  if (!r.diagnosis.empty()) std::cout << "diagnosis: " << r.diagnosis << "\n";
  if (!r.no_configuration.empty()) std::cout << "no real configuration: " << r.no_configuration << "\n";
  for (const auto& x : r.placements)
    std::cout << "placements of body '" << x.body << "': " << x.placements << (x.complete ? "" : " (NOT all)") << ", enclosed at "
              << x.precision << " bits" << (x.decided_exactly ? ", its choices decided exactly" : "") << " (relative width "
              << std::setprecision(2) << x.relative_width << std::setprecision(10) << ")"
              << (x.singular.empty() ? "" : "; singular: " + x.singular) << "\n";
  for (const auto& l : r.limits) std::cout << "limit reached: " << l << "\n";
  if (!r.precision_history.empty()) {
    std::cout << "coefficients re-solved at " << r.coefficient_precision << " bits; before:\n";
    for (const auto& h : r.precision_history) std::cout << "  at " << h << "\n";
  }
  for (const auto& q : scene.inequalities)
    std::cout << "inequality: det(" << q.points[1] << " - " << q.points[0] << ", " << q.points[2] << " - " << q.points[0] << ", "
              << q.points[3] << " - " << q.points[0] << ") " << (q.negative ? "<= 0" : ">= 0") << "\n";
  if (!r.parts.empty()) {
    // the factored answer: per placement combination, its parts and their counts
    std::cout << "independent parts (the configurations are their product):\n";
    for (const auto& q : r.parts) {
      std::cout << "  " << q.solutions.size() << " solution(s) of the part placing";
      for (const auto& b : q.bodies) std::cout << " " << b;
      std::cout << " (" << q.variables.size() << " variables";
      if (q.unresolved) std::cout << ", " << q.unresolved << " unresolved region(s)";
      std::cout << ")";
      bool any = false;
      for (int v : q.placements) any = any || v != 0;
      if (any) {
        std::cout << ", placements";
        for (int v : q.placements) std::cout << " " << v;
      }
      std::cout << "\n";
    }
  }
  std::cout << r.configuration_count << " configuration(s)" << (r.curves.empty() ? "" : " and " + std::to_string(r.curves.size()) + " curve branch(es)");
  std::size_t uncertified = 0, singular = 0;
  for (const auto& x : r.configurations) { uncertified += !x.certified; singular += x.singular; }
  if (uncertified) std::cout << " (" << uncertified << " not certified)";
  if (r.unlisted_not_certified) std::cout << " (" << r.unlisted_not_certified << " not listed and not certified)";
  std::size_t part_uncertified = 0;  // (each in every product it enters)
  for (const auto& q : r.parts)
    for (const auto& x : q.solutions) part_uncertified += !x.certified;
  if (part_uncertified) std::cout << " (" << part_uncertified << " part solution(s) not certified)";
  if (singular) std::cout << " (" << singular << " singular)";
  if (r.complete()) std::cout << ", all certified: complete\n";
  else std::cout << "; the result is NOT complete" << (r.unresolved.empty() ? "" : " (unresolved regions below)") << "\n";
  if (!r.listing.empty()) std::cout << "listed: " << r.listing << " (--max-listed N)\n";
  std::size_t k = 0;
  for (const auto& x : r.configurations) {
    std::cout << "\nconfiguration " << ++k << ": " << (x.certified ? "certified" : "NOT certified")
              << (x.on_inequality_boundary ? " (on an inequality's boundary)" : "")
              << (x.singular ? ", SINGULAR (a double configuration: " + x.singular_reason + ")" : "")
              << (x.coefficient_precision != 53 && x.coefficient_precision != 0 ? ", coefficients at " + std::to_string(x.coefficient_precision) + " bits" : std::string())
              << ", max residual "
              << std::setprecision(3) << x.max_residual << " (relative to the scene's size " << x.max_relative_residual << ")"
              << std::setprecision(10) << " in the original system\n  parameters:";
    for (std::size_t i = 0; i < x.variables.size(); ++i)
      std::cout << " " << x.variables[i] << " in [" << x.parameters[i].first << ", " << x.parameters[i].second << "]";
    std::cout << "\n  bodies (rotation row-major; translation):\n";
    for (const auto& b : user_poses(scene, x.configuration)) {
      const auto& m = b.second.motion;
      std::cout << "    " << b.first << ":";
      if (b.second.ok) std::cout << " R = [" << m.R[0] << " " << m.R[1] << " " << m.R[2] << "; " << m.R[3] << " " << m.R[4] << " " << m.R[5]
                                 << "; " << m.R[6] << " " << m.R[7] << " " << m.R[8] << "]";
      std::cout << " t = (" << m.t[0] << ", " << m.t[1] << ", " << m.t[2] << ")\n";
    }
    std::cout << "  points (frame " << x.configuration.frame << "):\n";
    for (std::size_t i = 0; i < x.configuration.labels.size(); ++i)
      if (x.configuration.placed[i])
        std::cout << "    " << x.configuration.labels[i] << " = (" << x.configuration.points[i][0] << ", " << x.configuration.points[i][1] << ", "
                  << x.configuration.points[i][2] << ")\n";
  }
  if (!r.curves.empty()) {
    std::cout << "\n" << r.curves.size() << " curve branch(es) of configurations (the scene moves):\n";
    for (std::size_t i = 0; i < r.curves.size(); ++i) {
      const auto& c = r.curves[i];
      std::cout << "  branch " << i + 1 << (c.certified ? " (certified)" : " (NOT certified)") << ": " << c.configurations.size() << " frames in "
                << c.pieces.size() << " chart piece(s), ";
      if (c.closed) std::cout << "closed";
      else std::cout << "from " << curve_end_name(c.ends[0]) << " to " << curve_end_name(c.ends[1]);
      std::cout << ", max residual " << std::setprecision(3) << c.max_residual << std::setprecision(10)
                << (c.on_inequality_boundary ? ", clipped by an inequality" : "") << "\n";
      if (!c.note.empty()) std::cout << "    note: " << c.note << "\n";
    }
  }
  if (!r.unresolved.empty()) {
    std::cout << "\nunresolved regions:\n";
    for (const auto& u : r.unresolved) {
      std::cout << "  " << (u.kind == RI::Box_class::PENDING ? "pending" : "unknown") << " (" << u.reason << "), " << u.boxes
                << " box(es), charts";
      for (int ch : u.charts) std::cout << " " << ch;
      std::cout << ", box";
      for (const auto& b : u.box) std::cout << " [" << b.first << ", " << b.second << "]";
      std::cout << "\n";
    }
  }
  std::cout << "\nstatistics: " << st.boxes << " boxes, " << st.krawczyk_tests << " Krawczyk tests, " << st.roots << " roots ("
            << st.duplicates << " found twice, " << st.spurious << " rejected by the original system)"
            << (st.swept ? std::string() : ", " + std::to_string(st.excluded_at_once) + " of " + std::to_string(st.chart_combinations) + " chart combinations excluded at once")
            << (st.placements_excluded ? ", " + std::to_string(st.placements_excluded) + " combinations of placements excluded (shared points at distances that differ)" : std::string())
            << (st.excluded_by_propagation ? ", " + std::to_string(st.excluded_by_propagation) + " chart combinations never built (excluded by propagation along the tree)" : std::string())
            << (st.swept ? std::string(", solved along the tree by a sweep (no chart combination built)") : std::string())
            << consistency_text(st)
            << (st.planned_systems ? ", " + std::to_string(st.planned_systems) + " systems solved along their solution plan (" +
                                         std::to_string(st.block_solves) + " block solves, " +
                                         (st.block_solves_reused ? std::to_string(st.block_solves_reused) + " reused (independent parts), " : std::string()) +
                                         std::to_string(st.excluded_by_plan) +
                                         " combinations excluded by a block without roots)"
                                   : std::string())
            << "; seconds: analysis " << analysis_seconds << ", reduce "
            << st.reduce_seconds << ", solve " << st.solve_seconds << ", verify " << st.verify_seconds;
  if (st.threads > 1) std::cout << " (summed over " << st.threads << " threads)";
  std::cout << "\n";
  return signal_received && !r.complete() ? 128 + int(signal_received) : 0;  // (a signal after the last combination cut nothing)
}

} // namespace solve_command

#endif
