// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Back-substitution (from the reduced system's parameters to a configuration of the scene:
// every body's rotation and translation, every point's coordinates, in the frame the scene
// names) and verification (the residuals of a configuration in the original, unreduced
// system of the user's bodies and distances).

#ifndef CGAL_RIGID_INCIDENCE_CONFIGURATION_H
#define CGAL_RIGID_INCIDENCE_CONFIGURATION_H

#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Reduced_system.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {

/// \ingroup PkgRigidIncidenceRef
/// A rigid motion x -> R x + t in doubles (R row-major).
struct Rigid_motion
{
  std::array<double, 9> R{{1, 0, 0, 0, 1, 0, 0, 0, 1}};  ///< rotation, row-major
  std::array<double, 3> t{{0, 0, 0}};                    ///< translation
  /// The image of `y`.
  std::array<double, 3> operator()(const std::array<double, 3>& y) const
  {
    std::array<double, 3> x;
    for (int i = 0; i < 3; ++i)
      x[std::size_t(i)] = R[std::size_t(3 * i)] * y[0] + R[std::size_t(3 * i + 1)] * y[1] + R[std::size_t(3 * i + 2)] * y[2] + t[std::size_t(i)];
    return x;
  }
  /// The inverse motion.
  Rigid_motion inverse() const
  {
    Rigid_motion m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m.R[std::size_t(3 * i + j)] = R[std::size_t(3 * j + i)];
    for (int i = 0; i < 3; ++i)
      m.t[std::size_t(i)] = -(m.R[std::size_t(3 * i)] * t[0] + m.R[std::size_t(3 * i + 1)] * t[1] + m.R[std::size_t(3 * i + 2)] * t[2]);
    return m;
  }
  /// The composition: first `b`, then this.
  Rigid_motion operator*(const Rigid_motion& b) const
  {
    Rigid_motion m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double s = 0;
        for (int k = 0; k < 3; ++k) s += R[std::size_t(3 * i + k)] * b.R[std::size_t(3 * k + j)];
        m.R[std::size_t(3 * i + j)] = s;
      }
    m.t = (*this)(b.t);
    return m;
  }
};

/// \ingroup PkgRigidIncidenceRef
/// The best rigid fit of `fit_rigid_motion()`.
struct Rigid_fit
{
  Rigid_motion motion;     ///< the rotation and translation
  bool reflected = false;  ///< the points fit a mirror image better: a body would come back mirrored
  double rms = 0;          ///< root mean square distance of the fitted points
  bool ok = false;         ///< false with fewer than 3 points, or all of them at one place
  /// the points are (nearly) collinear: the rotation about their line is not determined by
  /// them, and `motion` is one that fits (its `rms` says how well)
  bool collinear = false;
  /// with `reflected`: the best motion with a reflection (an orthogonal matrix of determinant
  /// -1), which tells a mirror image of the body (a spurious root) from points that fit neither
  Rigid_motion mirror;
};

/*!
\ingroup PkgRigidIncidenceRef
\brief The rigid motion (rotation, no reflection) that best takes the local points `y` onto the
world points `x` in the least-squares sense (Kabsch's algorithm: the SVD of the cross-covariance,
with Eigen).
*/
inline Rigid_fit fit_rigid_motion(const std::vector<std::array<double, 3>>& y, const std::vector<std::array<double, 3>>& x)
{
  Rigid_fit f;
  const std::size_t n = y.size();
  if (n < 3 || x.size() != n) return f;
  // in units of the largest coordinate (a power of two, exact): a point at 1e308 would
  // overflow the products of the cross-covariance
  double big = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k) big = (std::max)(big, (std::max)(std::abs(y[i][k]), std::abs(x[i][k])));
  if (!std::isfinite(big)) return f;
  int unit = 0;
  if (big > 0) std::frexp(big, &unit);
  auto in_units = [unit](const std::array<double, 3>& p) {
    return Eigen::Vector3d(std::ldexp(p[0], -unit), std::ldexp(p[1], -unit), std::ldexp(p[2], -unit));
  };
  Eigen::Vector3d cy = Eigen::Vector3d::Zero(), cx = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) { cy += in_units(y[i]); cx += in_units(x[i]); }
  cy /= double(n);
  cx /= double(n);
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d a = in_units(y[i]) - cy, b = in_units(x[i]) - cx;
    H += a * b.transpose();
    scale = (std::max)(scale, a.norm());
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d sv = svd.singularValues();
  if (!(scale > 0)) return f;
  // collinear: the rotation about the line is free. The singular values are products of two
  // lengths (a triangle of height h and side 1 has sv(1) ~ h^2), and their round-off is a
  // few units in the last place of sv(0): below that the body is collinear as far as doubles
  // tell, and any rotation that aligns the line fits it as well as its height allows (a
  // triangle 1e-7 off its hinge is a body of the scene, not an error)
  f.collinear = sv(1) <= 64 * std::numeric_limits<double>::epsilon() * sv(0);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  const double det = (svd.matrixV() * svd.matrixU().transpose()).determinant();
  if (det < 0) D(2, 2) = -1;
  // a reflection fits better when it is needed and the points span space
  f.reflected = det < 0 && sv(2) > 1e-9 * sv(0);
  Eigen::Matrix3d R = svd.matrixV() * D * svd.matrixU().transpose();
  Eigen::Vector3d t = cx - R * cy;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) f.motion.R[std::size_t(3 * i + j)] = R(i, j);
    f.motion.t[std::size_t(i)] = std::ldexp(t(i), unit);
  }
  if (f.reflected) {
    const Eigen::Matrix3d M = svd.matrixV() * svd.matrixU().transpose();
    const Eigen::Vector3d tm = cx - M * cy;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) f.mirror.R[std::size_t(3 * i + j)] = M(i, j);
      f.mirror.t[std::size_t(i)] = std::ldexp(tm(i), unit);
    }
  }
  double s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    auto p = f.motion(y[i]);
    for (int k = 0; k < 3; ++k) {
      const double d = std::ldexp(p[std::size_t(k)] - x[i][std::size_t(k)], -unit);
      s += d * d;
    }
  }
  f.rms = std::ldexp(std::sqrt(s / double(n)), unit);
  f.ok = true;
  return f;
}

/// \ingroup PkgRigidIncidenceRef
/// A configuration of a scene: where every point is and how every body is placed.
struct Configuration
{
  std::string frame;                          ///< the body whose frame the coordinates are in
  std::vector<std::string> labels;            ///< per point: its label
  std::vector<std::array<double, 3>> points;  ///< per point: its coordinates
  std::vector<bool> placed;                   ///< per point: whether the configuration places it
  std::vector<std::string> body_names;        ///< per body of the standard collection
  std::vector<Rigid_motion> poses;            ///< per body: local coordinates -> frame coordinates
  std::vector<bool> body_placed;              ///< per body: whether its pose is known

  /// The coordinates of the point labelled `l`, or an Input_error.
  const std::array<double, 3>& point(const std::string& l) const
  {
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == l) {
        if (!placed[i]) throw Input_error("configuration: point '" + l + "' is not placed");
        return points[i];
      }
    throw Input_error("configuration: no point '" + l + "'");
  }
};

namespace internal {
// The middle of an enclosure as a double; (inf + sup) / 2, CGAL's to_double of an interval,
// overflows at 1e308.
template <class NT> double middle(const NT& x)
{
  if constexpr (std::is_same<NT, CGAL::Interval_nt<false>>::value || std::is_same<NT, CGAL::Interval_nt<true>>::value)
    return 0.5 * x.inf() + 0.5 * x.sup();
  else
    return CGAL::to_double(x);
}
template <class NT> std::array<double, 3> to_double3(const std::array<NT, 3>& p)
{
  return {middle(p[0]), middle(p[1]), middle(p[2])};
}
} // namespace internal


/*!
\ingroup PkgRigidIncidenceRef
\brief Back-substitution, from the tree's parametrization `p` (of `c` and `tree`, in
its chart combination) without a reduced system: what `solve_scene()` uses for the roots of a
system solved along the tree (`Tree_system`), which is never expanded.
*/
template <class Traits, class NT>
Configuration configuration(const Rigid_body_collection<Traits>& c, const Incidence_tree& tree, const Incidence_tree_parametrization<Traits, NT>& p,
                            const std::vector<double>& x, const std::vector<int>& variants = {})
{
  if (x.size() != p.number_of_variables())
    throw Input_error("configuration: " + std::to_string(x.size()) + " values for " + std::to_string(p.number_of_variables()) + " variables");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i])) throw Input_error("configuration: variable '" + p.variable_names()[i] + "' is not a finite number");
  Configuration conf;
  const std::size_t nb = c.number_of_bodies(), np = c.number_of_points();
  conf.labels.resize(np);
  for (std::size_t i = 0; i < np; ++i) conf.labels[i] = c.label(i);
  conf.points.assign(np, {0, 0, 0});
  conf.placed.assign(np, false);
  conf.poses.assign(nb, Rigid_motion());
  conf.body_placed.assign(nb, false);
  for (std::size_t b = 0; b < nb; ++b) conf.body_names.push_back(c.body(b).name);
  // covering bodies: the tree's maps
  auto poses = p.template poses<double>(x);
  for (std::size_t b : tree.covering_set) {
    conf.poses[b].R = poses[b].R;
    conf.poses[b].t = poses[b].t;
    conf.body_placed[b] = true;
    const auto& body = c.body(b);
    for (std::size_t i = 0; i < body.points.size(); ++i) {
      std::size_t q = body.points[i];
      if (conf.placed[q]) continue;
      conf.points[q] = conf.poses[b](internal::to_double3(p.coordinates(b)[i]));
      conf.placed[q] = true;
    }
  }
  for (std::size_t q : c.free_points()) {
    std::size_t v = p.free_point_variable(q);
    conf.points[q] = {x[v], x[v + 1], x[v + 2]};
    conf.placed[q] = true;
  }
  // bodies outside the covering set: fit them to their placed points
  for (std::size_t b : tree.non_covering) {
    const auto& body = c.body(b);
    std::vector<Body_enclosure<CGAL::Interval_nt<false>>> enc;
    std::vector<std::array<double, 3>> local(body.points.size());
    if (body.all_coordinates()) {
      for (std::size_t i = 0; i < body.points.size(); ++i)
        local[i] = {CGAL::to_double(Traits::x(body.coordinates[i])), CGAL::to_double(Traits::y(body.coordinates[i])), CGAL::to_double(Traits::z(body.coordinates[i]))};
    } else {
      CGAL::Protect_FPU_rounding<true> guard;
      auto e = enclose_coordinates<CGAL::Interval_nt<false>>(c, b, b < variants.size() ? variants[b] : 0);
      if (!e.consistent) continue;
      for (std::size_t i = 0; i < body.points.size(); ++i)
        local[i] = internal::to_double3(e.coordinates[i]);
    }
    std::vector<std::array<double, 3>> y, w;
    for (std::size_t i = 0; i < body.points.size(); ++i)
      if (conf.placed[body.points[i]]) { y.push_back(local[i]); w.push_back(conf.points[body.points[i]]); }
    Rigid_fit f = fit_rigid_motion(y, w);
    if (!f.ok) continue;
    // placed points on a line leave the body free to turn about it: its other points are not
    // determined, so they stay unplaced (the configuration is then not verified)
    if (f.collinear && y.size() < body.points.size()) continue;
    conf.poses[b] = f.motion;
    conf.body_placed[b] = true;
    for (std::size_t i = 0; i < body.points.size(); ++i)
      if (!conf.placed[body.points[i]]) { conf.points[body.points[i]] = f.motion(local[i]); conf.placed[body.points[i]] = true; }
  }
  // the scene's frame
  conf.frame = c.body(tree.root).name;
  const std::size_t F = c.body_index(c.frame());
  if (F < nb && conf.body_placed[F]) {
    const Rigid_motion to_frame = conf.poses[F].inverse();
    for (std::size_t q = 0; q < np; ++q) if (conf.placed[q]) conf.points[q] = to_frame(conf.points[q]);
    for (std::size_t b = 0; b < nb; ++b) if (conf.body_placed[b]) conf.poses[b] = to_frame * conf.poses[b];
    conf.frame = c.frame();
  }
  // labels that name a point under another label (a distance of 0): the same place
  for (const auto& a : c.aliases()) {
    const std::size_t q = c.point_index(a.label);
    conf.labels.push_back(a.alias);
    conf.points.push_back(conf.points[q]);
    conf.placed.push_back(conf.placed[q]);
  }
  return conf;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief Back-substitution: the configuration of the scene for the parameter values `x` of the
reduced system `r` (one per variable, e.g. a root the solver found).

Every body of the covering set gets its pose from the tree's maps (composed root to leaf);
each free point its three variables; a body outside the covering set the best rigid fit of
its points that the covering set places (three or more, not collinear), which also places
its own other points; for such a body known by distances, in its placement `variants[b]`
(default 0: each placement is a configuration of its own when its own points differ, see
`solve_scene()`). All of it is then expressed in the frame of the scene's frame body
(`Rigid_body_collection::frame()`, by default the first body of the scene) when that body is
placed, else in the root's frame (`Configuration::frame` says which).
*/
template <class Traits, class NT>
Configuration configuration(const Reduced_system<Traits, NT>& r, const std::vector<double>& x, const std::vector<int>& variants = {})
{
  return configuration(r.collection(), r.tree(), r.parametrization(), x, variants);
}

/// \ingroup PkgRigidIncidenceRef
/// One residual of a configuration in the original system.
struct Residual
{
  /// What is measured.
  enum Kind
  {
    INCIDENCE,  ///< a shared point as two bodies place it: the largest coordinate difference
    DISTANCE,   ///< a distance: | |X_a - X_b|^2 - d^2 |
    BODY,       ///< a body's points against its best rigid fit: the largest distance
    MIRRORED,   ///< a body whose points fit only its mirror image (value: 1)
    UNPLACED    ///< a body or distance whose points the configuration does not place (value: infinity)
  };
  Kind kind = INCIDENCE;  ///< what is measured
  std::string what;       ///< which bodies, point or distance
  double value = 0;       ///< the residual (0 for an exact configuration)
};

/// \ingroup PkgRigidIncidenceRef
/// The residuals of a configuration, as `residuals()` returns them.
struct Residual_report
{
  std::vector<Residual> entries;  ///< every residual
  double max_incidence = 0;       ///< largest INCIDENCE and BODY residual
  double max_distance = 0;        ///< largest DISTANCE residual
  bool mirrored = false;          ///< some body fits only mirrored
  /// with `mirrored`: the largest INCIDENCE and BODY residual were the bodies that fit only
  /// mirrored allowed their mirror image (a configuration of the scene's mirrored bodies: what
  /// tells a spurious root of a system blind to handedness from points that fit no body at all)
  double max_incidence_mirrored = 0;
  /// with `mirrored`: the largest DISTANCE residual (bars and distances have no handedness)
  double max_distance_mirrored = 0;
  bool complete = true;           ///< every body and distance was placed
  /// The largest residual of any kind (infinity if incomplete or mirrored).
  double max() const
  {
    if (!complete || mirrored) return std::numeric_limits<double>::infinity();
    return (std::max)(max_incidence, max_distance);
  }
};

/// \ingroup PkgRigidIncidenceRef
/// Multiplies every length of `c` by 2^`k` (points and translations): the configuration of
/// the scene scaled by 2^`k`.
inline void scale_configuration(Configuration& c, long k)
{
  for (auto& p : c.points) for (double& x : p) x = std::ldexp(x, int(k));
  for (auto& m : c.poses) for (double& x : m.t) x = std::ldexp(x, int(k));
}

/// \ingroup PkgRigidIncidenceRef
/// The residuals of a configuration scaled by 2^`k` (see `scale_configuration()`): lengths
/// times 2^`k`, squared lengths (DISTANCE) times 4^`k`.
inline void scale_residuals(Residual_report& r, long k)
{
  for (auto& e : r.entries)
    if (e.kind == Residual::DISTANCE) e.value = std::ldexp(e.value, int(2 * k));
    else if (e.kind == Residual::INCIDENCE || e.kind == Residual::BODY) e.value = std::ldexp(e.value, int(k));
  r.max_incidence = std::ldexp(r.max_incidence, int(k));
  r.max_distance = std::ldexp(r.max_distance, int(2 * k));
  r.max_incidence_mirrored = std::ldexp(r.max_incidence_mirrored, int(k));
  r.max_distance_mirrored = std::ldexp(r.max_distance_mirrored, int(2 * k));
}

/*!
\ingroup PkgRigidIncidenceRef
\brief The residuals of `conf` in the ORIGINAL system of `original` (the collection as the
scene file gives it, before `standardize()`), so that any answer can be checked independently
of the reduction: each body of 3 or more points is fitted rigidly to the configuration's points
(`fit_rigid_motion()`; a body that only fits mirrored is reported), then every incidence of every
shared point in every pair of bodies (the largest coordinate difference of the point as the two
fitted bodies place it), every body's own fit, and every distance (bodies of 2 points, bars,
enter as their distance). Points are matched by label.
*/
template <class Traits>
Residual_report residuals(const Rigid_body_collection<Traits>& original, const Configuration& conf)
{
  Residual_report rep;
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < conf.labels.size(); ++i) index[conf.labels[i]] = i;
  auto where = [&](const std::string& l, std::array<double, 3>& out) {
    auto it = index.find(l);
    if (it == index.end() || !conf.placed[it->second]) return false;
    out = conf.points[it->second];
    return true;
  };
  auto add = [&](Residual::Kind k, const std::string& what, double v) {
    if (std::isnan(v)) v = std::numeric_limits<double>::infinity();  // never a silent pass
    rep.entries.push_back(Residual{k, what, v});
    if (k == Residual::INCIDENCE || k == Residual::BODY) rep.max_incidence = (std::max)(rep.max_incidence, v);
    if (k == Residual::DISTANCE) rep.max_distance = (std::max)(rep.max_distance, v);
    if (k == Residual::MIRRORED) rep.mirrored = true;
    if (k == Residual::UNPLACED) rep.complete = false;
  };
  auto dist2 = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
  };
  const std::size_t nb = original.number_of_bodies();
  std::vector<Rigid_fit> fit(nb);
  std::vector<std::vector<std::array<double, 3>>> local(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& body = original.body(b);
    const std::string name = "body '" + body.name + "'";
    if (!body.all_coordinates()) continue;
    std::vector<std::array<double, 3>> x;
    bool all = true;
    for (std::size_t i = 0; i < body.points.size(); ++i) {
      local[b].push_back({CGAL::to_double(Traits::x(body.coordinates[i])), CGAL::to_double(Traits::y(body.coordinates[i])),
                          CGAL::to_double(Traits::z(body.coordinates[i]))});
      std::array<double, 3> w;
      all = where(original.label(body.points[i]), w) && all;
      x.push_back(w);
    }
    if (!all) { add(Residual::UNPLACED, name, std::numeric_limits<double>::infinity()); continue; }
    if (body.points.size() == 2) { // a bar: its length
      add(Residual::DISTANCE, name + " (a bar)", std::abs(dist2(x[0], x[1]) - dist2(local[b][0], local[b][1])));
      continue;
    }
    fit[b] = fit_rigid_motion(local[b], x);
    if (!fit[b].ok) { add(Residual::UNPLACED, name + " (fewer than 3 points, or all at one place)", std::numeric_limits<double>::infinity()); continue; }
    if (fit[b].reflected) add(Residual::MIRRORED, name + " fits only mirrored", 1);
    double worst = 0, worst_mirrored = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {  // (hypot: no overflow for a point at 1e308)
      const auto p = fit[b].motion(local[b][i]);
      worst = (std::max)(worst, std::hypot(p[0] - x[i][0], p[1] - x[i][1], p[2] - x[i][2]));
      if (fit[b].reflected) {
        const auto m = fit[b].mirror(local[b][i]);
        worst_mirrored = (std::max)(worst_mirrored, std::hypot(m[0] - x[i][0], m[1] - x[i][1], m[2] - x[i][2]));
      }
    }
    add(Residual::BODY, name, worst);
    rep.max_incidence_mirrored = (std::max)(rep.max_incidence_mirrored, fit[b].reflected ? worst_mirrored : worst);
  }
  auto placed_by = [&](std::size_t b, std::size_t q, bool allow_mirror) {
    const auto& y = local[b][original.body(b).local(q)];
    return allow_mirror && fit[b].reflected ? fit[b].mirror(y) : fit[b].motion(y);
  };
  // incidences: every shared point in every pair of fitted bodies
  for (std::size_t a = 0; a < nb; ++a)
    for (std::size_t b = a + 1; b < nb; ++b) {
      if (!fit[a].ok || !fit[b].ok) continue;
      for (std::size_t q : original.common_points(a, b)) {
        double d = 0, dm = 0;
        for (int mirrored = 0; mirrored < 2; ++mirrored) {
          const auto pa = placed_by(a, q, mirrored), pb = placed_by(b, q, mirrored);
          double& e = mirrored ? dm : d;
          for (int k = 0; k < 3; ++k) e = (std::max)(e, std::abs(pa[std::size_t(k)] - pb[std::size_t(k)]));
        }
        add(Residual::INCIDENCE, "point '" + original.label(q) + "' in '" + original.body(a).name + "' and '" + original.body(b).name + "'", d);
        rep.max_incidence_mirrored = (std::max)(rep.max_incidence_mirrored, dm);
      }
    }
  for (const auto& d : original.distances()) {
    std::array<double, 3> u, w;
    const std::string what = "distance " + original.label(d.a) + "-" + original.label(d.b);
    if (!where(original.label(d.a), u) || !where(original.label(d.b), w)) {
      add(Residual::UNPLACED, what, std::numeric_limits<double>::infinity());
      continue;
    }
    add(Residual::DISTANCE, what, std::abs(dist2(u, w) - CGAL::to_double(d.squared)));
  }
  rep.max_distance_mirrored = rep.max_distance;  // (bars and distances have no handedness)
  return rep;
}

/*!
\ingroup PkgRigidIncidenceRef
\brief How far `conf` is from a singular point of the ORIGINAL system of `original`: the
smallest singular value of its Jacobian over the largest, in world coordinates (3 unknowns per
point, the frame body's points fixed; every other body of 3 or more points holds its base
triangle by its 3 squared distances and each further point at
\f$X_0 + a (X_1 - X_0) + b (X_2 - X_0) + c (X_1 - X_0) \times (X_2 - X_0)\f$, with \f$a, b, c\f$ from
its coordinates, so that a flat body stays rigid; bars and distances are squared-distance
equations, divided by the scene's size). 0 when the Jacobian is short of rank (a multiple root
or a curve of configurations), near 1 for a well-conditioned simple root; -1 when a point is
not placed. Computed in doubles (Eigen's BDCSVD) at the configuration's approximation, whose
error is far below the values it tells apart (`solve_scene()` calls a placement's exactly-zero
height a simple root when this ratio is above \f$10^{-7}\f$: further equations hold the point).
*/
template <class Traits>
double jacobian_conditioning(const Rigid_body_collection<Traits>& original, const Configuration& conf)
{
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < conf.labels.size(); ++i) index[conf.labels[i]] = i;
  const std::size_t n = original.number_of_points();
  std::vector<Eigen::Vector3d> x(n);
  double size = 0;
  for (std::size_t q = 0; q < n; ++q) {
    auto it = index.find(original.label(q));
    if (it == index.end() || !conf.placed[it->second]) return -1;
    const auto& p = conf.points[it->second];
    x[q] = Eigen::Vector3d(p[0], p[1], p[2]);
  }
  for (std::size_t q = 1; q < n; ++q) size = (std::max)(size, (x[q] - x[0]).norm());
  if (!(size > 0) || !std::isfinite(size)) return -1;
  for (auto& v : x) v /= size;
  std::vector<Eigen::RowVectorXd> rows;
  auto distance_row = [&](std::size_t a, std::size_t b) {
    Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(Eigen::Index(3 * n));
    const Eigen::Vector3d d = 2 * (x[a] - x[b]);
    r.segment<3>(Eigen::Index(3 * a)) = d.transpose();
    r.segment<3>(Eigen::Index(3 * b)) = -d.transpose();
    rows.push_back(r);
  };
  auto crossm = [](const Eigen::Vector3d& w) {
    Eigen::Matrix3d m;
    m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return m;
  };
  const std::string frame = original.frame();
  for (std::size_t bi = 0; bi < original.number_of_bodies(); ++bi) {
    const auto& b = original.body(bi);
    if (b.name == frame) {
      for (std::size_t q : b.points)
        for (int k = 0; k < 3; ++k) {
          Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(Eigen::Index(3 * n));
          r(Eigen::Index(3 * q) + k) = 1;
          rows.push_back(r);
        }
      continue;
    }
    if (b.points.size() == 2) { distance_row(b.points[0], b.points[1]); continue; }
    if (!b.all_coordinates()) return -1;
    std::size_t i1 = 0, i2 = 0;  // a base triangle off a line, with point 0
    for (std::size_t u = 1; u < b.points.size() && i2 == 0; ++u)
      for (std::size_t v = u + 1; v < b.points.size() && i2 == 0; ++v)
        if (!Traits::collinear(b.coordinates[0], b.coordinates[u], b.coordinates[v])) { i1 = u; i2 = v; }
    if (i2 == 0) return -1;
    auto local = [&](std::size_t i) {
      return Eigen::Vector3d(CGAL::to_double(Traits::x(b.coordinates[i])), CGAL::to_double(Traits::y(b.coordinates[i])),
                             CGAL::to_double(Traits::z(b.coordinates[i])));
    };
    const std::size_t g0 = b.points[0], g1 = b.points[i1], g2 = b.points[i2];
    distance_row(g0, g1);
    distance_row(g0, g2);
    distance_row(g1, g2);
    const Eigen::Vector3d ul = local(i1) - local(0), vl = local(i2) - local(0);
    Eigen::Matrix3d E;
    E << ul, vl, ul.cross(vl);
    const Eigen::Vector3d u = x[g1] - x[g0], v = x[g2] - x[g0];
    for (std::size_t i = 1; i < b.points.size(); ++i) {
      if (i == i1 || i == i2) continue;
      const Eigen::Vector3d abc = E.fullPivLu().solve(local(i) - local(0));
      // (c multiplies a product of two differences: in units of the scene's size, c size)
      const double a = abc(0), bb = abc(1), c = abc(2) * size;
      const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
      Eigen::MatrixXd block = Eigen::MatrixXd::Zero(3, Eigen::Index(3 * n));
      block.block<3, 3>(0, Eigen::Index(3 * b.points[i])) += I;
      block.block<3, 3>(0, Eigen::Index(3 * g0)) += -(1 - a - bb) * I - c * crossm(v - u);
      block.block<3, 3>(0, Eigen::Index(3 * g1)) += -a * I + c * crossm(v);
      block.block<3, 3>(0, Eigen::Index(3 * g2)) += -bb * I - c * crossm(u);
      for (int r = 0; r < 3; ++r) rows.push_back(block.row(r));
    }
  }
  for (const auto& d : original.distances()) distance_row(d.a, d.b);
  if (rows.size() < 3 * n) return 0;
  Eigen::MatrixXd J(Eigen::Index(rows.size()), Eigen::Index(3 * n));
  for (std::size_t r = 0; r < rows.size(); ++r) J.row(Eigen::Index(r)) = rows[r];
  const Eigen::VectorXd sv = Eigen::BDCSVD<Eigen::MatrixXd>(J).singularValues();
  if (sv.size() == 0 || !(sv(0) > 0)) return 0;
  return sv(sv.size() - 1) / sv(0);
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
