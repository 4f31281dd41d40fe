// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Test helper shared by test_optimal_tree_brute_force and test_rdof: random collections of
// rigid bodies (labelled points with distinct integer global coordinates, the same in every
// body, so every collection is consistent) in several shapes: chains, cycles, hinges
// (bodies on one shared pair), stars, fans through one point, random subsets of a small
// pool, random attachment, two disconnected pieces. No two bodies share 3 or more points,
// no body's point set lies inside another's, every body has 2 or more points (mostly 3-5).

#ifndef RIGID_INCIDENCE_TEST_RANDOM_COLLECTIONS_H
#define RIGID_INCIDENCE_TEST_RANDOM_COLLECTIONS_H

#include <CGAL/Random.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace random_collections {

namespace RI = CGAL::Rigid_incidence;

struct Structure
{
  std::vector<std::array<int, 3>> coords;   // per point: distinct integer global coordinates
  std::vector<std::vector<int>> bodies;     // per body: point ids
  std::vector<bool> implied;                // per body: drop its coordinates (an implied body)
  std::vector<std::pair<int, int>> distances;
  std::string shape;
};

class Generator
{
public:
  explicit Generator(CGAL::Random& r) : rng_(r) {}

  Structure s;

  int fresh()
  {
    while (true) {
      std::array<int, 3> p{rng_.get_int(-40, 41), rng_.get_int(-40, 41), rng_.get_int(-40, 41)};
      if (used_.insert(p).second) { s.coords.push_back(p); return int(s.coords.size()) - 1; }
    }
  }
  std::vector<int> fresh(int k) { std::vector<int> r; for (int i = 0; i < k; ++i) r.push_back(fresh()); return r; }

  // Mostly 3 to 5 points, sometimes 2.
  int body_size() { return rng_.get_double() < 0.15 ? 2 : rng_.get_int(3, 6); }

  std::vector<int> pick(std::vector<int> from, int k)
  {
    std::vector<int> r;
    for (int i = 0; i < k && !from.empty(); ++i) {
      int j = rng_.get_int(0, int(from.size()));
      r.push_back(from[j]);
      from.erase(from.begin() + j);
    }
    return r;
  }

  // Adds the body if it has >= 2 distinct points, shares at most 2 with every body, and
  // neither contains nor is contained in another body.
  bool add(std::vector<int> b)
  {
    std::sort(b.begin(), b.end());
    if (b.size() < 2 || std::adjacent_find(b.begin(), b.end()) != b.end()) return false;
    for (const auto& o : s.bodies) {
      std::vector<int> common;
      std::set_intersection(b.begin(), b.end(), o.begin(), o.end(), std::back_inserter(common));
      if (common.size() >= 3 || common.size() == b.size() || common.size() == o.size()) return false;
    }
    s.bodies.push_back(b);
    return true;
  }

  std::vector<int> points_from(std::size_t first) const
  {
    std::set<int> p;
    for (std::size_t i = first; i < s.bodies.size(); ++i) p.insert(s.bodies[i].begin(), s.bodies[i].end());
    return std::vector<int>(p.begin(), p.end());
  }

  std::vector<int> concat(std::vector<int> a, const std::vector<int>& b) { a.insert(a.end(), b.begin(), b.end()); return a; }

  // The shapes; each adds `count` bodies (or fewer) connected only to bodies it adds itself.
  void chain(int count, bool closed)
  {
    std::size_t first = s.bodies.size();
    add(fresh(body_size()));
    for (int i = 1; i < count; ++i) {
      const std::vector<int> prev = s.bodies.back();
      int k = rng_.get_int(1, 3);
      bool closing = closed && i == count - 1 && count >= 3;
      for (int attempt = 0; attempt < 30; ++attempt) {
        std::vector<int> b = pick(prev, k);
        if (closing) {
          std::vector<int> back = pick(s.bodies[first], rng_.get_int(1, 3));
          for (int p : back) if (std::find(b.begin(), b.end(), p) == b.end()) b.push_back(p);
        }
        int extra = std::max(1, body_size() - int(b.size()));
        if (rng_.get_double() < 0.15 && b.size() >= 3) extra = 0;
        if (add(concat(b, fresh(extra)))) break;
      }
    }
  }
  void hinge(int count)
  {
    std::size_t first = s.bodies.size();
    std::vector<int> axis = fresh(2);
    int h = count <= 2 ? count : rng_.get_int(2, count + 1); // (get_int(a, a) is undefined)
    for (int i = 0; i < h; ++i) add(concat(axis, fresh(rng_.get_int(1, 4))));
    for (int i = h; i < count; ++i) attach_one(first, 0.0);
  }
  void star(int count)
  {
    add(fresh(rng_.get_int(4, 7)));
    const std::vector<int> center = s.bodies.back();
    for (int i = 1; i < count; ++i)
      for (int attempt = 0; attempt < 30; ++attempt)
        if (add(concat(pick(center, rng_.get_int(1, 3)), fresh(rng_.get_int(1, 4))))) break;
  }
  void fan(int count)
  {
    std::size_t first = s.bodies.size();
    int hub = fresh();
    for (int i = 0; i < count; ++i)
      for (int attempt = 0; attempt < 30; ++attempt) {
        std::vector<int> b{hub};
        if (i > 0 && rng_.get_double() < 0.3) {
          std::vector<int> other = pick(s.bodies[first + std::size_t(rng_.get_int(0, int(s.bodies.size() - first)))], 1);
          if (other[0] != hub) b.push_back(other[0]);
        }
        if (add(concat(b, fresh(rng_.get_int(1, 4))))) break;
      }
  }
  void pool(int count)
  {
    std::vector<int> pts = fresh(rng_.get_int(5, 11));
    for (int i = 0; i < count; ++i)
      for (int attempt = 0; attempt < 100; ++attempt)
        if (add(pick(pts, std::min<int>(body_size(), int(pts.size()))))) break;
  }
  // A body with 0..3 points of the bodies added since `first` (0 of them: a separate body),
  // plus fresh points; with probability `cross`, no fresh point (a body across others).
  void attach_one(std::size_t first, double cross)
  {
    for (int attempt = 0; attempt < 30; ++attempt) {
      std::vector<int> existing = points_from(first);
      if (rng_.get_double() < cross) {
        if (add(pick(existing, rng_.get_int(2, 4)))) return;
        continue;
      }
      static const int ks[] = {0, 1, 1, 2, 2};
      int k = ks[rng_.get_int(0, 5)];
      std::vector<int> b = pick(existing, k);
      int extra = std::max(2 - int(b.size()), std::max(1, body_size() - k));
      if (add(concat(b, fresh(extra)))) return;
    }
  }
  void attach(int count)
  {
    std::size_t first = s.bodies.size();
    add(fresh(body_size()));
    for (int i = 1; i < count; ++i) attach_one(first, 0.2);
  }

  void shape(int which, int count)
  {
    switch (which) {
      case 0: s.shape += "chain"; chain(count, false); break;
      case 1: s.shape += "cycle"; chain(count, true); break;
      case 2: s.shape += "hinge"; hinge(count); break;
      case 3: s.shape += "star"; star(count); break;
      case 4: s.shape += "fan"; fan(count); break;
      case 5: s.shape += "pool"; pool(count); break;
      default: s.shape += "attach"; attach(count); break;
    }
  }

  // A collection of about `n` bodies; shape 7 is two disconnected pieces.
  void generate(int which, int n)
  {
    if (which == 7 && n >= 2) {
      int a = rng_.get_int(1, n);
      shape(rng_.get_int(0, 7), a);
      s.shape += "+";
      shape(rng_.get_int(0, 7), n - a);
    } else shape(which == 7 ? 6 : which, n);
  }

  void shuffle_bodies()
  {
    for (std::size_t i = s.bodies.size(); i > 1; --i) std::swap(s.bodies[i - 1], s.bodies[std::size_t(rng_.get_int(0, int(i)))]);
  }

private:
  CGAL::Random& rng_;
  std::set<std::array<int, 3>> used_;
};

inline std::string label(int p) { return "p" + std::to_string(p); }

template <class Traits>
RI::Rigid_body_collection<Traits> build(const Structure& s)
{
  typedef typename Traits::FT FT;
  RI::Rigid_body_collection<Traits> c;
  auto pt = [&](int p) { return Traits::point(FT(s.coords[p][0]), FT(s.coords[p][1]), FT(s.coords[p][2])); };
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    std::vector<std::pair<std::string, typename Traits::Point_3>> pts;
    for (int p : s.bodies[i]) pts.emplace_back(label(p), pt(p));
    c.add_body("b" + std::to_string(i), pts);
  }
  // Implied bodies: known by their squared distances only, as standardize() builds them.
  for (std::size_t i = 0; i < s.implied.size(); ++i) {
    if (!s.implied[i]) continue;
    auto& b = c.mutable_bodies()[i];
    b.origin = RI::Body_origin::IMPLIED;
    b.squared_distances.clear();
    for (std::size_t u = 0; u < b.points.size(); ++u)
      for (std::size_t v = u + 1; v < b.points.size(); ++v)
        b.squared_distances.push_back({u, v, Traits::squared_distance(b.coordinates[u], b.coordinates[v])});
    b.has_coordinates.assign(b.points.size(), false);
  }
  for (const auto& d : s.distances)
    c.add_distance(label(d.first), label(d.second), Traits::squared_distance(pt(d.first), pt(d.second)));
  // The frame defaults to the first body, which standardize() refuses if it is a bar (two
  // points): name the first body of 3 or more points instead.
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    if (s.bodies[i].size() >= 3) { c.set_frame("b" + std::to_string(i)); break; }
  return c;
}

} // namespace random_collections

#endif
