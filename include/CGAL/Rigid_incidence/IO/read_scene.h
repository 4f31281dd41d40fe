// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reading of "rigid-incidence-scene/1" JSON files through nlohmann-json's SAX interface,
// which hands over each number's original text, so numbers are read exactly.

#ifndef CGAL_RIGID_INCIDENCE_IO_READ_SCENE_H
#define CGAL_RIGID_INCIDENCE_IO_READ_SCENE_H

#include <CGAL/Rigid_incidence/IO/Scene.h>
#include <CGAL/Rigid_incidence/Input_error.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/internal/parse_number.h>

#include <nlohmann/json.hpp>

#include <array>
#include <fstream>
#include <functional>
#include <map>
#include <istream>
#include <iterator>
#include <memory>
#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {

// A small JSON tree whose numbers keep their source text and whose objects keep their
// keys in order, duplicates included (so that a duplicate label can be reported).
struct Json_node
{
  enum Kind { NUL, BOOLEAN, NUMBER, STRING, ARRAY, OBJECT } kind = NUL;
  std::string text; // number text, string value, or "true"/"false"
  std::vector<std::pair<std::string, Json_node>> members; // OBJECT
  std::vector<Json_node> elements;                        // ARRAY

  static const char* kind_name(Kind k)
  {
    switch (k) {
      case NUL: return "null"; case BOOLEAN: return "a boolean"; case NUMBER: return "a number";
      case STRING: return "a string"; case ARRAY: return "an array"; default: return "an object";
    }
  }
};

// Nesting deeper than this is refused: no scene needs it, and it bounds recursion.
constexpr std::size_t max_json_depth = 32;

class Json_sax_builder
{
public:
  using json = nlohmann::json;
  Json_node root;
  std::string error;

  bool null() { return put(Json_node::NUL, ""); }
  bool boolean(bool b) { return put(Json_node::BOOLEAN, b ? "true" : "false"); }
  bool number_integer(json::number_integer_t v) { return put(Json_node::NUMBER, std::to_string(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return put(Json_node::NUMBER, std::to_string(v)); }
  bool number_float(json::number_float_t, const json::string_t& s) { return put(Json_node::NUMBER, s); }
  bool string(json::string_t& s) { return put(Json_node::STRING, s); }
  bool binary(json::binary_t&) { error = "binary values are not allowed"; return false; }
  bool start_object(std::size_t) { return open(Json_node::OBJECT); }
  bool key(json::string_t& k) { pending_key_ = k; has_key_ = true; return true; }
  bool end_object() { stack_.pop_back(); return true; }
  bool start_array(std::size_t) { return open(Json_node::ARRAY); }
  bool end_array() { stack_.pop_back(); return true; }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex)
  {
    error = "invalid JSON at byte " + std::to_string(position) + ": " + ex.what();
    if (std::string(ex.what()).find("number overflow") != std::string::npos)
      error += " (a plain JSON number must fit a double; write larger numbers as strings, e.g. \"1e400\")";
    return false;
  }

private:
  std::vector<Json_node*> stack_;
  std::string pending_key_;
  bool has_key_ = false;
  bool started_ = false;

  Json_node* place()
  {
    if (stack_.empty()) {
      if (started_) { error = "more than one top-level value"; return nullptr; }
      started_ = true;
      return &root;
    }
    Json_node* parent = stack_.back();
    if (parent->kind == Json_node::OBJECT) {
      parent->members.emplace_back(pending_key_, Json_node());
      has_key_ = false;
      return &parent->members.back().second;
    }
    parent->elements.emplace_back();
    return &parent->elements.back();
  }
  bool put(Json_node::Kind k, const std::string& text)
  {
    Json_node* n = place();
    if (!n) return false;
    n->kind = k; n->text = text;
    return true;
  }
  bool open(Json_node::Kind k)
  {
    if (stack_.size() >= max_json_depth) { error = "JSON nested deeper than " + std::to_string(max_json_depth) + " levels"; return false; }
    Json_node* n = place();
    if (!n) return false;
    n->kind = k;
    stack_.push_back(n);
    return true;
  }
};

class Scene_interpreter
{
public:
  explicit Scene_interpreter(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const
  {
    throw Input_error(source_ + ": " + (where.empty() ? std::string() : where + ": ") + what);
  }

  const Json_node* member(const Json_node& obj, const std::string& key, const std::string& where) const
  {
    const Json_node* found = nullptr;
    for (const auto& m : obj.members)
      if (m.first == key) {
        if (found) fail(where, "duplicate field \"" + key + "\"");
        found = &m.second;
      }
    return found;
  }

  void expect(const Json_node& n, Json_node::Kind k, const std::string& where) const
  {
    if (n.kind != k)
      fail(where, std::string("expected ") + Json_node::kind_name(k) + ", found " + Json_node::kind_name(n.kind));
  }

  CGAL::Gmpq number(const Json_node& n, const std::string& where) const
  {
    if (n.kind != Json_node::NUMBER && n.kind != Json_node::STRING)
      fail(where, std::string("expected a number (or a string holding one), found ") + Json_node::kind_name(n.kind));
    CGAL::Gmpq q;
    std::string why;
    if (!parse_exact_number(n.text, q, why))
      fail(where, "\"" + n.text.substr(0, 40) + (n.text.size() > 40 ? "..." : "") + "\" is not a valid number: " + why);
    return q;
  }

  std::string string_field(const Json_node& n, const std::string& where) const
  {
    expect(n, Json_node::STRING, where);
    return n.text;
  }

  Scene interpret(const Json_node& root) const
  {
    Scene scene;
    scene.source = source_;
    expect(root, Json_node::OBJECT, "top level");
    static const std::set<std::string> known = {"format", "name", "bodies", "distances", "inequalities", "frame", "comment", "free_distance"};
    for (const auto& m : root.members)
      if (!known.count(m.first))
        fail("field \"" + m.first + "\"", "unknown field (known: format, name, bodies, distances, inequalities, frame, comment, free_distance)");
    const Json_node* format = member(root, "format", "top level");
    if (!format) fail("", "missing field \"format\" (expected \"rigid-incidence-scene/1\")");
    std::string f = string_field(*format, "field \"format\"");
    if (f != "rigid-incidence-scene/1") fail("field \"format\"", "unknown format \"" + f + "\" (expected \"rigid-incidence-scene/1\")");
    if (const Json_node* name = member(root, "name", "top level")) scene.name = string_field(*name, "field \"name\"");
    const Json_node* bodies = member(root, "bodies", "top level");
    if (!bodies) fail("", "missing field \"bodies\"");
    expect(*bodies, Json_node::ARRAY, "field \"bodies\"");
    if (bodies->elements.empty()) fail("field \"bodies\"", "no bodies");
    std::set<std::string> body_names;
    for (std::size_t i = 0; i < bodies->elements.size(); ++i) {
      const Json_node& b = bodies->elements[i];
      std::string where = "bodies[" + std::to_string(i) + "]";
      expect(b, Json_node::OBJECT, where);
      for (const auto& m : b.members)
        if (m.first != "name" && m.first != "points") fail(where, "unknown field \"" + m.first + "\" (known: name, points)");
      Scene::Body body;
      const Json_node* bn = member(b, "name", where);
      if (!bn) fail(where, "missing field \"name\"");
      body.name = string_field(*bn, where + ".name");
      if (body.name.empty()) fail(where, "empty body name");
      where = "body '" + body.name + "'";
      if (!body_names.insert(body.name).second) fail(where, "duplicate body name");
      const Json_node* pts = member(b, "points", where);
      if (!pts) fail(where, "missing field \"points\"");
      expect(*pts, Json_node::OBJECT, where + ": field \"points\"");
      std::set<std::string> labels;
      for (const auto& m : pts->members) {
        std::string pw = where + ": point '" + m.first + "'";
        if (m.first.empty()) fail(where, "empty point label");
        if (!labels.insert(m.first).second) fail(pw, "duplicate label inside the body");
        expect(m.second, Json_node::ARRAY, pw);
        if (m.second.elements.size() != 3)
          fail(pw, "expected 3 coordinates, found " + std::to_string(m.second.elements.size()));
        Scene::Point p;
        p.label = m.first;
        p.x = number(m.second.elements[0], pw + ": coordinate x");
        p.y = number(m.second.elements[1], pw + ": coordinate y");
        p.z = number(m.second.elements[2], pw + ": coordinate z");
        body.points.push_back(p);
      }
      scene.bodies.push_back(body);
    }
    if (const Json_node* ds = member(root, "distances", "top level")) {
      expect(*ds, Json_node::ARRAY, "field \"distances\"");
      for (std::size_t i = 0; i < ds->elements.size(); ++i) {
        const Json_node& d = ds->elements[i];
        std::string where = "distances[" + std::to_string(i) + "]";
        expect(d, Json_node::OBJECT, where);
        for (const auto& m : d.members)
          if (m.first != "between" && m.first != "squared" && m.first != "length")
            fail(where, "unknown field \"" + m.first + "\" (known: between, squared, length)");
        Scene::Distance dist;
        const Json_node* between = member(d, "between", where);
        if (!between) fail(where, "missing field \"between\"");
        expect(*between, Json_node::ARRAY, where + ".between");
        if (between->elements.size() != 2) fail(where + ".between", "expected 2 point labels");
        dist.a = string_field(between->elements[0], where + ".between[0]");
        dist.b = string_field(between->elements[1], where + ".between[1]");
        where += " ('" + dist.a + "'-'" + dist.b + "')";
        if (dist.a == dist.b) fail(where, "a distance must join two different points");
        const Json_node* sq = member(d, "squared", where);
        const Json_node* len = member(d, "length", where);
        if (sq && len) fail(where, "give either \"squared\" or \"length\", not both");
        if (!sq && !len) fail(where, "missing \"squared\" or \"length\"");
        if (sq) {
          dist.squared = number(*sq, where + ".squared");
          if (dist.squared < 0) fail(where + ".squared", "a distance must be positive, or 0 (a coincidence)");
        } else {
          dist.length = number(*len, where + ".length");
          if (dist.length < 0) fail(where + ".length", "a distance must be positive, or 0 (a coincidence)");
          dist.given_as_length = true;
          dist.squared = dist.length * dist.length;
        }
        scene.distances.push_back(dist);
      }
    }
    if (const Json_node* in = member(root, "inequalities", "top level")) {
      std::set<std::string> all_labels;
      for (const auto& b : scene.bodies)
        for (const auto& p : b.points) all_labels.insert(p.label);
      expect(*in, Json_node::ARRAY, "field \"inequalities\"");
      for (std::size_t i = 0; i < in->elements.size(); ++i) {
        const Json_node& q = in->elements[i];
        std::string where = "inequalities[" + std::to_string(i) + "]";
        expect(q, Json_node::OBJECT, where);
        for (const auto& m : q.members)
          if (m.first != "orientation" && m.first != "sign") fail(where, "unknown field \"" + m.first + "\" (known: orientation, sign)");
        const Json_node* o = member(q, "orientation", where);
        if (!o) fail(where, "missing field \"orientation\" (four point labels A, B, C, D: det(B - A, C - A, D - A) >= 0)");
        expect(*o, Json_node::ARRAY, where + ".orientation");
        if (o->elements.size() != 4) fail(where + ".orientation", "expected 4 point labels, found " + std::to_string(o->elements.size()));
        Scene::Inequality ineq;
        for (std::size_t k = 0; k < 4; ++k) {
          std::string l = string_field(o->elements[k], where + ".orientation[" + std::to_string(k) + "]");
          if (!all_labels.count(l)) fail(where, "point '" + l + "' is in no body");
          if (std::find(ineq.points.begin(), ineq.points.end(), l) != ineq.points.end()) fail(where, "point '" + l + "' appears twice");
          ineq.points.push_back(l);
        }
        if (const Json_node* sg = member(q, "sign", where)) {
          std::string v = string_field(*sg, where + ".sign");
          if (v != "positive" && v != "negative") fail(where + ".sign", "expected \"positive\" or \"negative\", found \"" + v + "\"");
          ineq.negative = v == "negative";
        }
        scene.inequalities.push_back(ineq);
      }
    }
    if (const Json_node* fd = member(root, "free_distance", "top level")) free_distance(*fd, scene);
    if (const Json_node* fr = member(root, "frame", "top level")) {
      scene.frame = string_field(*fr, "field \"frame\"");
      if (!body_names.count(scene.frame)) fail("field \"frame\"", "names no body: '" + scene.frame + "'");
    }
    return scene;
  }

private:
  // "free_distance": ["A", "B"] or {"between": ["A", "B"], "range": [lo, hi]} (lengths). A pair
  // also listed in "distances" is taken out of them: its length is no longer imposed.
  void free_distance(const Json_node& fd, Scene& scene) const
  {
    const std::string where = "field \"free_distance\"";
    Scene::Free_distance f;
    f.declared = true;
    const Json_node* between = &fd;
    if (fd.kind == Json_node::OBJECT) {
      for (const auto& m : fd.members)
        if (m.first != "between" && m.first != "range") fail(where, "unknown field \"" + m.first + "\" (known: between, range)");
      between = member(fd, "between", where);
      if (!between) fail(where, "missing field \"between\" (two point labels)");
      if (const Json_node* range = member(fd, "range", where)) {
        expect(*range, Json_node::ARRAY, where + ".range");
        if (range->elements.size() != 2) fail(where + ".range", "expected [smallest, largest] length");
        f.lo = number(range->elements[0], where + ".range[0]");
        f.hi = number(range->elements[1], where + ".range[1]");
        if (f.lo < 0) fail(where + ".range", "a length cannot be negative");
        if (!(f.lo < f.hi)) fail(where + ".range", "the smallest length must be below the largest");
        f.has_range = true;
      }
    } else if (fd.kind != Json_node::ARRAY) {
      fail(where, std::string("expected [\"A\", \"B\"] or {\"between\": [\"A\", \"B\"], \"range\": [lo, hi]}, found ") +
                      Json_node::kind_name(fd.kind));
    }
    expect(*between, Json_node::ARRAY, where + ".between");
    if (between->elements.size() != 2) fail(where, "expected 2 point labels");
    f.a = string_field(between->elements[0], where + "[0]");
    f.b = string_field(between->elements[1], where + "[1]");
    if (f.a == f.b) fail(where, "a distance must join two different points");
    bool a_known = false, b_known = false;
    for (const auto& body : scene.bodies)
      for (const auto& p : body.points) {
        a_known = a_known || p.label == f.a;
        b_known = b_known || p.label == f.b;
      }
    if (!a_known) fail(where, "point '" + f.a + "' is in no body");
    if (!b_known) fail(where, "point '" + f.b + "' is in no body");
    for (std::size_t i = 0; i < scene.distances.size();) {
      const auto& d = scene.distances[i];
      if ((d.a == f.a && d.b == f.b) || (d.a == f.b && d.b == f.a)) {
        f.had_length = true;
        f.nominal_squared = d.squared;
        scene.distances.erase(scene.distances.begin() + long(i));
      } else {
        ++i;
      }
    }
    scene.free_distance = f;
  }

  std::string source_;
};

} // namespace internal

/*!
\ingroup PkgRigidIncidenceIO
\brief Reads a scene of format "rigid-incidence-scene/1" from `in`.

Numbers are read from their text (JSON numbers or strings holding an integer, an exact
decimal such as "-1.25e-3", or a rational "3/7"), never through a binary double.
`source` names the input in error messages.
Checks done here are those of the file format (valid JSON, known format and fields,
numbers, duplicate body names or labels, positive distances, the frame naming a body);
the geometric checks are made by `Rigid_body_collection`.

\throws Input_error naming the file, body, point or field at fault.
*/
inline Scene read_scene(std::istream& in, const std::string& source = "<stream>")
{
  internal::Json_sax_builder sax;
  bool ok = false;
  try {
    ok = nlohmann::json::sax_parse(in, &sax);
  } catch (const std::exception& e) {
    throw Input_error(source + ": invalid JSON: " + e.what());
  }
  if (!ok)
    throw Input_error(source + ": " + (sax.error.empty() ? std::string("invalid JSON") : sax.error));
  return internal::Scene_interpreter(source).interpret(sax.root);
}

/// \ingroup PkgRigidIncidenceIO
/// Reads a scene from the file `filename`. \throws Input_error also when the file cannot be opened.
inline Scene read_scene(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  if (!in) throw Input_error(filename + ": cannot open the file");
  return read_scene(in, filename);
}

/*!
\ingroup PkgRigidIncidenceIO
\brief Builds a `Rigid_body_collection` from a scene, converting each exact number to
`Traits::FT` (exactly when `FT` is an exact field, else to the nearest double, within the range of Rigid_incidence_traits::from_rational()).

A distance of 0 is a coincidence: its two labels name one point. Every label is replaced by
the first label of its class (in the order of the bodies) and the others become aliases of it
(`Rigid_body_collection::aliases()`, given back in every configuration). A body holding two
labels of one class at different places, or a nonzero distance between two of them, leaves
no real configuration (`No_real_configuration`); two labels of one class in one body at the
same place are one point.

\throws Input_error for geometric faults, named with the scene's source: coincident points
inside a body, a distance naming an unknown point, two distances on one pair that disagree.
*/
template <class Traits>
Rigid_body_collection<Traits> make_collection(const Scene& scene)
{
  Rigid_body_collection<Traits> c;
  c.name = scene.name;
  try {
    // coincidences: the classes of labels joined by distances of 0
    std::map<std::string, std::string> parent;
    std::function<std::string(const std::string&)> find = [&](const std::string& l) -> std::string {
      auto it = parent.find(l);
      if (it == parent.end() || it->second == l) return l;
      return it->second = find(it->second);
    };
    std::map<std::string, std::size_t> first_seen;  // the representative: the label seen first
    for (const auto& b : scene.bodies)
      for (const auto& p : b.points) first_seen.emplace(p.label, first_seen.size());
    for (std::size_t i = 0; i < scene.distances.size(); ++i) {
      const auto& d = scene.distances[i];
      if (d.squared != 0) continue;
      for (const std::string& l : {d.a, d.b})
        if (!first_seen.count(l))
          throw Input_error("distances[" + std::to_string(i) + "] ('" + d.a + "'-'" + d.b + "'): names unknown point '" + l + "'");
      std::string a = find(d.a), b = find(d.b);
      if (a == b) continue;
      auto rank = [&](const std::string& l) { return first_seen.at(l); };
      if (rank(b) < rank(a)) std::swap(a, b);
      parent[b] = a;
      parent.emplace(a, a);
    }
    std::map<std::string, std::string> why;  // per class: the distances of 0 that make it
    for (std::size_t i = 0; i < scene.distances.size(); ++i) {
      const auto& d = scene.distances[i];
      if (d.squared != 0) continue;
      std::string& w = why[find(d.a)];
      w += (w.empty() ? "" : ", ") + ("distances[" + std::to_string(i) + "] ('" + d.a + "'-'" + d.b + "') is 0");
    }
    auto rep = [&](const std::string& l) { return find(l); };
    for (const auto& b : scene.bodies) {
      std::vector<std::pair<std::string, typename Traits::Point_3>> pts;
      std::vector<std::array<Gmpq, 3>> exact;
      for (const auto& p : b.points) {
        const std::string where = "body '" + b.name + "': point '" + p.label + "': coordinate ";
        const std::string l = rep(p.label);
        bool again = false;
        for (std::size_t k = 0; k < pts.size(); ++k)
          if (pts[k].first == l) {
            if (!(exact[k][0] == p.x && exact[k][1] == p.y && exact[k][2] == p.z))
              throw No_real_configuration("body '" + b.name + "' holds '" + p.label + "' and another label of the same point ('" + l +
                                          "', made one by a distance of 0) at different places: no real configuration");
            again = true;
          }
        if (again) continue;
        pts.emplace_back(l, Traits::point(Traits::from_rational(p.x, where + "x"), Traits::from_rational(p.y, where + "y"),
                                          Traits::from_rational(p.z, where + "z")));
        exact.push_back({p.x, p.y, p.z});
      }
      c.add_body(b.name, pts);
    }
    for (std::size_t i = 0; i < scene.distances.size(); ++i) {
      const auto& d = scene.distances[i];
      const std::string where = "distances[" + std::to_string(i) + "] ('" + d.a + "'-'" + d.b + "')";
      if (d.squared == 0) continue;
      const std::string a = rep(d.a), b = rep(d.b);
      if (a == b)
        throw No_real_configuration(where + ": joins two labels of one point (made one by a distance of 0) at a nonzero distance:"
                                    " no real configuration");
      c.add_distance(a, b, Traits::from_rational(d.squared, where + ": squared value"), where);
    }
    for (const auto& l : parent)
      if (find(l.first) != l.first) c.add_alias(l.first, find(l.first), why[find(l.first)]);
    if (!scene.frame.empty()) c.set_frame(scene.frame);
  } catch (const No_real_configuration& e) {
    throw No_real_configuration(scene.source + ": " + e.what());
  } catch (const Input_error& e) {
    throw Input_error(scene.source + ": " + e.what());
  }
  return c;
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
