// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// `rigid_incidence family`: a scene with a free distance solved as curves over that distance,
// with its folds (certified), the number of configurations between them, and an SVG gallery
// (configurations at sample lengths, grouped by branch) with a plot of the bodies' rotation
// angles against the length.

#ifndef RIGID_INCIDENCE_EXAMPLES_FAMILY_COMMAND_H
#define RIGID_INCIDENCE_EXAMPLES_FAMILY_COMMAND_H

#include "solve_command.h"

#include <CGAL/Rigid_incidence.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace family_command {

namespace RI = CGAL::Rigid_incidence;
using solve_command::Solve_options;

struct Family_options
{
  Solve_options solve;         // --tolerance, --precision, --max-boxes, --svg
  std::size_t samples = 6;     // --samples: lengths drawn in the gallery
  bool json = false;
};

// A bound of every distance between two points of a connected scene: the sum of the bodies'
// diameters and of the fixed distances (a path from one point to the other crosses each at
// most once). Rounded up to a whole number.
inline CGAL::Gmpq default_range_end(const RI::Scene& scene)
{
  double s = 0;
  for (const auto& b : scene.bodies) {
    double d = 0;
    for (std::size_t i = 0; i < b.points.size(); ++i)
      for (std::size_t j = i + 1; j < b.points.size(); ++j) {
        const double dx = CGAL::to_double(b.points[i].x - b.points[j].x), dy = CGAL::to_double(b.points[i].y - b.points[j].y),
                     dz = CGAL::to_double(b.points[i].z - b.points[j].z);
        d = std::max(d, std::sqrt(dx * dx + dy * dy + dz * dz));
      }
    s += d;
  }
  for (const auto& d : scene.distances) s += std::sqrt(CGAL::to_double(d.squared));
  return CGAL::Gmpq(std::ceil(s * (1 + 1e-9)) + 1);
}

// The configurations of a branch at `length`: at each crossing of its polyline, the points
// interpolated linearly between the two frames around it (for drawing).
inline std::vector<RI::Configuration> configurations_at(const RI::Family_branch& b, double length)
{
  std::vector<RI::Configuration> out;
  const auto& d = b.lengths;
  const std::size_t m = d.size(), segments = b.curve.closed ? m : (m ? m - 1 : 0);
  for (std::size_t i = 0; i < segments; ++i) {
    const std::size_t j = (i + 1) % m;
    if ((d[i] < length) == (d[j] < length)) continue;
    const double t = d[j] != d[i] ? (length - d[i]) / (d[j] - d[i]) : 0.0;
    RI::Configuration c = b.curve.configurations[i];
    const auto& e = b.curve.configurations[j];
    for (std::size_t p = 0; p < c.points.size() && p < e.points.size(); ++p)
      for (int k = 0; k < 3; ++k) c.points[p][k] += t * (e.points[p][k] - c.points[p][k]);
    out.push_back(c);
  }
  return out;
}

// The rotation angle of R in degrees and its axis (unit, or zero when the angle is 0 or 180).
inline double rotation_angle(const std::array<double, 9>& R, std::array<double, 3>& axis)
{
  const double c = std::max(-1.0, std::min(1.0, 0.5 * (R[0] + R[4] + R[8] - 1)));
  axis = {R[7] - R[5], R[2] - R[6], R[3] - R[1]};
  const double s = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (auto& a : axis) a = s > 1e-12 ? a / s : 0.0;
  return std::acos(c) * 180 / CGAL_PI;
}

// The gallery and the plot.
inline void write_family_svg(const std::string& file, const RI::Scene& scene, const RI::Family_result& r, std::size_t samples,
                             const std::string& title)
{
  std::ofstream out(file);
  if (!out) throw RI::Input_error("--svg: cannot write '" + file + "'");
  out << std::fixed << std::setprecision(2);
  const double lo = r.range.first, hi = r.range.second;
  std::vector<double> at;
  for (std::size_t k = 0; k < samples; ++k) at.push_back(lo + (double(k) + 0.5) * (hi - lo) / double(samples));
  // the gallery: per branch, a row per sample length with the branch's configurations there
  std::size_t cols = 1;
  std::vector<std::vector<std::vector<RI::Configuration>>> cells(r.branches.size());
  for (std::size_t b = 0; b < r.branches.size(); ++b)
    for (double d : at) {
      cells[b].push_back(configurations_at(r.branches[b], d));
      cols = std::max(cols, cells[b].back().size());
    }
  const double cell = 120, label = 150, top = 40;
  const double gallery_h = double(r.branches.size() * samples) * cell + 24.0 * double(r.branches.size());
  // the plot: one panel per body of the scene, its rotation angle against the length
  const double pw = 300, ph = 200, gap = 50;
  const std::size_t panels = scene.bodies.size(), pcols = std::max<std::size_t>(1, std::min<std::size_t>(panels, 3));
  const std::size_t prows = (panels + pcols - 1) / pcols;
  const double width = std::max(label + double(cols) * cell, double(pcols) * (pw + gap) + gap);
  const double plot_top = top + gallery_h + 40;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << plot_top + double(prows) * (ph + gap) + 40
      << "\" font-family=\"sans-serif\" font-size=\"10\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"8\" y=\"18\" font-size=\"13\">" << title << "</text>\n"
      << "<text x=\"8\" y=\"32\">configurations at " << samples << " lengths of " << r.a << "-" << r.b
      << " (drawn from the traced branches), grouped by branch</text>\n";
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  double y = top;
  for (std::size_t b = 0; b < r.branches.size(); ++b) {
    const auto& br = r.branches[b];
    out << "<text x=\"8\" y=\"" << y + 16 << "\" font-size=\"12\" fill=\"" << colours[b % 8] << "\">branch " << b + 1
        << (br.curve.certified ? " (certified)" : " (NOT certified)") << (br.curve.closed ? ", closed" : "") << "</text>\n";
    y += 24;
    for (std::size_t k = 0; k < samples; ++k) {
      out << "<text x=\"8\" y=\"" << y + cell / 2 << "\">" << r.a << "-" << r.b << " = " << solve_command::short_number(at[k]) << ": "
          << cells[b][k].size() << "</text>\n";
      for (std::size_t i = 0; i < cells[b][k].size(); ++i)
        solve_command::draw_frame(out, scene, cells[b][k][i], label + double(i) * cell, y, cell, "");
      y += cell;
    }
  }
  // each body's rotation relative to its pose in the first frame of the first branch (for a
  // body hinged on the frame: its hinge rotation since then), signed about the axis where it
  // is largest
  std::vector<std::array<double, 9>> start(scene.bodies.size(), {{1, 0, 0, 0, 1, 0, 0, 0, 1}});
  if (!r.branches.empty()) {
    auto poses = solve_command::user_poses(scene, r.branches.front().curve.configurations.front());
    for (std::size_t k = 0; k < poses.size(); ++k)
      if (poses[k].second.ok) start[k] = poses[k].second.motion.R;
  }
  auto relative = [&](std::size_t k, const std::array<double, 9>& R) {  // R start^T
    std::array<double, 9> M;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) M[3 * i + j] = R[3 * i] * start[k][3 * j] + R[3 * i + 1] * start[k][3 * j + 1] + R[3 * i + 2] * start[k][3 * j + 2];
    return M;
  };
  std::vector<std::array<double, 3>> ref(scene.bodies.size(), {0, 0, 0});
  std::vector<double> best(scene.bodies.size(), 0);
  for (const auto& br : r.branches)
    for (const auto& c : br.curve.configurations) {
      auto poses = solve_command::user_poses(scene, c);
      for (std::size_t k = 0; k < poses.size(); ++k) {
        if (!poses[k].second.ok) continue;
        std::array<double, 3> ax;
        const double t = rotation_angle(relative(k, poses[k].second.motion.R), ax);
        const double s = std::sin(t * CGAL_PI / 180);
        if (s > best[k]) { best[k] = s; ref[k] = ax; }
      }
    }
  for (std::size_t k = 0; k < panels; ++k) {
    const double px = gap + double(k % pcols) * (pw + gap), py = plot_top + double(k / pcols) * (ph + gap);
    auto X = [&](double d) { return px + (d - lo) / (hi - lo) * pw; };
    auto Y = [&](double a) { return py + ph / 2 - a / 180 * (ph / 2); };
    out << "<rect x=\"" << px << "\" y=\"" << py << "\" width=\"" << pw << "\" height=\"" << ph << "\" fill=\"none\" stroke=\"#999\"/>\n"
        << "<text x=\"" << px << "\" y=\"" << py - 6 << "\">" << scene.bodies[k].name << ": rotation since the first frame (deg) vs "
        << r.a << "-" << r.b << "</text>\n"
        << "<line x1=\"" << px << "\" y1=\"" << Y(0) << "\" x2=\"" << px + pw << "\" y2=\"" << Y(0) << "\" stroke=\"#ddd\"/>\n"
        << "<text x=\"" << px << "\" y=\"" << py + ph + 12 << "\">" << solve_command::short_number(lo) << "</text>\n"
        << "<text x=\"" << px + pw - 20 << "\" y=\"" << py + ph + 12 << "\">" << solve_command::short_number(hi) << "</text>\n";
    for (const auto& f : r.folds)
      out << "<line x1=\"" << X(f.length.first) << "\" y1=\"" << py << "\" x2=\"" << X(f.length.first) << "\" y2=\"" << py + ph
          << "\" stroke=\"#aaa\" stroke-dasharray=\"3 3\"/>\n";
    for (std::size_t b = 0; b < r.branches.size(); ++b) {
      const auto& br = r.branches[b];
      std::vector<std::pair<double, double>> pts;
      for (std::size_t i = 0; i < br.curve.configurations.size(); ++i) {
        auto poses = solve_command::user_poses(scene, br.curve.configurations[i]);
        if (k >= poses.size() || !poses[k].second.ok) continue;
        std::array<double, 3> ax;
        double a = rotation_angle(relative(k, poses[k].second.motion.R), ax);
        if (ax[0] * ref[k][0] + ax[1] * ref[k][1] + ax[2] * ref[k][2] < 0) a = -a;
        pts.push_back({br.lengths[i], a});
      }
      if (br.curve.closed && !pts.empty()) pts.push_back(pts.front());
      std::string path;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const bool jump = i == 0 || std::abs(pts[i].second - pts[i - 1].second) > 180;
        std::ostringstream os;
        os << std::fixed << std::setprecision(2) << (jump ? " M" : " L") << X(pts[i].first) << "," << Y(pts[i].second);
        path += os.str();
      }
      if (!path.empty())
        out << "<path d=\"" << path << "\" fill=\"none\" stroke=\"" << colours[b % 8] << "\" stroke-width=\"1.2\"/>\n";
    }
  }
  out << "</svg>\n";
}

template <class Traits>
int family(const RI::Scene& scene, const RI::Rigid_body_collection<Traits>& input, const Family_options& o, const std::string& scene_file)
{
  if (!scene.free_distance.declared)
    throw RI::Input_error(scene_file + ": the scene declares no free distance (add \"free_distance\": {\"between\": [\"A\", \"B\"], "
                                       "\"range\": [smallest, largest]})");
  const auto& fd = scene.free_distance;
  const CGAL::Gmpq lo = fd.has_range ? fd.lo : CGAL::Gmpq(0), hi = fd.has_range ? fd.hi : default_range_end(scene);
  RI::Family_parameters p;
  p.scene.solver.tolerance = o.solve.tolerance;
  p.scene.solver.precision = o.solve.precision;
  if (o.solve.max_boxes) p.scene.solver.maximal_boxes = p.tracer.maximal_boxes = o.solve.max_boxes;
  p.tracer.precision = o.solve.precision;
  if (o.solve.fast) throw RI::Input_error("--fast: a family is traced with certified topology only");
  RI::Family_result r;
  try {
    if (o.solve.precision <= 53) r = RI::solve_family<CGAL::Interval_nt<false>>(input, fd.a, fd.b, lo, hi, p);
    else {
#ifdef CGAL_USE_MPFI
      r = RI::solve_family<CGAL::Gmpfi>(input, fd.a, fd.b, lo, hi, p);
#else
      throw RI::Input_error("--precision above 53 bits needs MPFI (Debian libmpfi-dev); this build has none");
#endif
    }
  } catch (const RI::Input_error& e) {
    throw RI::Input_error(scene_file + ": " + e.what());
  }
  const std::string name = scene.name.empty() ? scene_file : scene.name;
  if (!o.solve.svg.empty())
    write_family_svg(o.solve.svg, scene, r, o.samples,
                     name + ": " + std::to_string(r.branches.size()) + " branch(es), " + std::to_string(r.folds.size()) + " fold(s)" +
                         (r.complete() ? ", complete" : ", NOT complete"));
  const auto& st = r.statistics;
  auto fold_groups = [&]() {  // folds at one length (mirror images) together
    std::vector<std::vector<std::size_t>> g;
    for (std::size_t k = 0; k < r.folds.size(); ++k) {
      if (!g.empty() && r.folds[k].length.first <= r.folds[g.back().front()].length.second) g.back().push_back(k);
      else g.push_back({k});
    }
    return g;
  };
  if (o.json) {
    nlohmann::ordered_json j;
    j["scene"] = scene_file;
    j["free_distance"] = {{"between", {fd.a, fd.b}}, {"range", {r.range.first, r.range.second}}, {"range_given", fd.has_range}};
    j["variables"] = r.variables;
    j["complete"] = r.complete();
    j["diagnosis"] = r.diagnosis.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.diagnosis);
    nlohmann::ordered_json folds = nlohmann::ordered_json::array();
    for (const auto& f : r.folds)
      folds.push_back({{"length", {f.length.first, f.length.second}}, {"certified", f.certified}, {"change", f.change},
                       {"max_residual", f.max_residual}, {"charts", f.charts}, {"found_in_charts", f.found},
                       {"points", solve_command::points_json(f.configuration)}});
    j["folds"] = folds;
    nlohmann::ordered_json counts = nlohmann::ordered_json::array();
    for (const auto& c : r.counts) counts.push_back({{"from", c.lo}, {"to", c.hi}, {"count", c.count}});
    j["counts"] = counts;
    nlohmann::ordered_json branches = nlohmann::ordered_json::array();
    for (const auto& b : r.branches) {
      nlohmann::ordered_json x;
      x["certified"] = b.curve.certified;
      x["closed"] = b.curve.closed;
      x["ends"] = {solve_command::curve_end_name(b.curve.ends[0]), solve_command::curve_end_name(b.curve.ends[1])};
      x["max_residual"] = b.curve.max_residual;
      x["lengths"] = b.lengths;
      nlohmann::ordered_json paths = nlohmann::ordered_json::object();
      const auto& f0 = b.curve.configurations.front();
      for (std::size_t i = 0; i < f0.labels.size(); ++i) {
        if (!f0.placed[i]) continue;
        nlohmann::ordered_json path = nlohmann::ordered_json::array();
        for (const auto& f : b.curve.configurations) path.push_back({f.points[i][0], f.points[i][1], f.points[i][2]});
        paths[f0.labels[i]] = path;
      }
      x["points"] = paths;
      nlohmann::ordered_json pieces = nlohmann::ordered_json::array();
      for (const auto& q : b.curve.pieces) pieces.push_back({{"charts", q.charts}, {"parameters", q.parameters}});
      x["pieces"] = pieces;
      branches.push_back(x);
    }
    j["branches"] = branches;
    nlohmann::ordered_json un = nlohmann::ordered_json::array();
    for (const auto& u : r.unresolved) {
      nlohmann::ordered_json box = nlohmann::ordered_json::array();
      for (const auto& b : u.box) box.push_back({b.first, b.second});
      un.push_back({{"class", u.kind == RI::Box_class::PENDING ? "pending" : "unknown"}, {"reason", u.reason}, {"charts", u.charts}, {"box", box}});
    }
    j["unresolved"] = un;
    j["stats"] = {{"chart_combinations", st.chart_combinations}, {"curve_boxes", st.curve_boxes}, {"fold_boxes", st.fold_boxes},
                  {"determinant_terms", st.determinant_terms},
                  {"seconds", {{"reduce", st.reduce_seconds}, {"trace", st.trace_seconds}, {"folds", st.fold_seconds}, {"verify", st.verify_seconds}}}};
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << std::setprecision(10);
  std::cout << "family " << name << ": free distance " << fd.a << "-" << fd.b << " over [" << r.range.first << ", " << r.range.second << "]"
            << (fd.has_range ? "" : " (no range given: 0 to a bound of every distance in the scene)") << "; reduced system of "
            << r.variables.size() - 1 << " parameters and the squared length, " << st.chart_combinations << " chart combination(s) traced\n";
  if (!r.diagnosis.empty()) std::cout << "diagnosis: " << r.diagnosis << "\n";
  std::cout << r.branches.size() << " branch(es), " << r.folds.size() << " fold(s)";
  if (r.complete()) std::cout << ", all certified: complete\n";
  else std::cout << "; the result is NOT complete" << (r.unresolved.empty() ? "" : " (unresolved regions below)") << "\n";
  if (!r.folds.empty()) {
    std::cout << "\nfolds (the length in a certified interval; the change of the number of configurations across it):\n";
    for (const auto& g : fold_groups()) {
      const auto& f = r.folds[g.front()];
      bool all = true;
      for (std::size_t k : g) all = all && r.folds[k].certified;
      std::cout << "  " << fd.a << "-" << fd.b << " in [" << f.length.first << ", " << f.length.second << "]: " << (f.change > 0 ? "+" : "")
                << f.change << (g.size() > 1 ? " (" + std::to_string(g.size()) + " folds at this length)" : std::string())
                << (all ? "" : ", NOT certified") << "\n";
    }
  }
  std::cout << "\nconfigurations per length (between folds):\n";
  for (const auto& c : r.counts) std::cout << "  (" << c.lo << ", " << c.hi << "): " << c.count << "\n";
  if (!r.branches.empty()) {
    std::cout << "\nbranches:\n";
    for (std::size_t i = 0; i < r.branches.size(); ++i) {
      const auto& b = r.branches[i];
      std::cout << "  branch " << i + 1 << (b.curve.certified ? " (certified)" : " (NOT certified)") << ": " << b.curve.configurations.size()
                << " frames in " << b.curve.pieces.size() << " chart piece(s), ";
      if (b.curve.closed) std::cout << "closed";
      else std::cout << "from " << solve_command::curve_end_name(b.curve.ends[0]) << " to " << solve_command::curve_end_name(b.curve.ends[1]);
      std::cout << ", lengths " << *std::min_element(b.lengths.begin(), b.lengths.end()) << " .. "
                << *std::max_element(b.lengths.begin(), b.lengths.end()) << ", max residual " << std::setprecision(3) << b.curve.max_residual
                << std::setprecision(10) << "\n";
    }
  }
  if (!r.unresolved.empty()) {
    std::cout << "\nunresolved regions:\n";
    for (const auto& u : r.unresolved) {
      std::cout << "  " << (u.kind == RI::Box_class::PENDING ? "pending" : "unknown") << " (" << u.reason << "), charts";
      for (int ch : u.charts) std::cout << " " << ch;
      std::cout << "\n";
    }
  }
  std::cout << "\nstatistics: " << st.curve_boxes << " tracer boxes, " << st.fold_boxes << " fold solver boxes, fold determinant of "
            << st.determinant_terms << " terms; seconds: reduce " << st.reduce_seconds << ", trace " << st.trace_seconds << ", folds "
            << st.fold_seconds << ", verify " << st.verify_seconds << "\n";
  return 0;
}

} // namespace family_command

#endif
