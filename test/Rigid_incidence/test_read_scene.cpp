// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Reading scenes ("rigid-incidence-scene/1") from memory, with two kernels (Simple_cartesian<Gmpq>
// and Epick): accepted scenes give the exact numbers written in the text (oracle: Gmpq built
// here from integers, and the C++ compiler's own reading of decimal literals for the nearest
// double); every malformed scene of the issue is refused with RI::Input_error whose message
// names the source and the body, point or field at fault; geometric contradictions are refused
// by RI::standardize with a message naming the bodies and points involved.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Rigid_incidence.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace RI = CGAL::Rigid_incidence;

typedef RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>> Exact_traits;
typedef RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel> Epick_traits;

static int failures = 0, checks = 0;
static bool verbose = false; // -v: print every rejection message
#define CHECK(cond, msg)                                                                         \
  do {                                                                                           \
    ++checks;                                                                                    \
    if (!(cond)) { ++failures; std::cerr << "FAIL line " << __LINE__ << ": " << msg << "\n"; } \
  } while (0)

// ------------------------------------------------------------------------------ scene texts

static const std::string FMT = "\"format\": \"rigid-incidence-scene/1\"";

// Two bodies sharing the point A; c1 = {A, B, C}, c2 = {A, D, E}.
static const std::string BODY_C1 = R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"]}})";
static const std::string BODY_C2 = R"({"name": "c2", "points": {"A": ["0","0","0"], "D": ["0","0","1"], "E": ["1","1","1"]}})";

// A scene with the given bodies (JSON array content) and extra top-level members.
static std::string scene(const std::string& bodies, const std::string& extra = "")
{
  return "{" + FMT + ", \"name\": \"t\", \"bodies\": [" + bodies + "]" + (extra.empty() ? "" : ", " + extra) + "}";
}
static std::string two_bodies(const std::string& extra = "") { return scene(BODY_C1 + ", " + BODY_C2, extra); }
// c1 as above and a second body c2 with the given points (JSON object content).
static std::string with_c2(const std::string& points, const std::string& extra = "")
{
  return scene(BODY_C1 + ", {\"name\": \"c2\", \"points\": {" + points + "}}", extra);
}
static std::string with_distances(const std::string& distances) { return two_bodies("\"distances\": [" + distances + "]"); }

// ------------------------------------------------------------------------------ pipeline

enum Stage { READ = 0, COLLECT = 1, STANDARDIZE = 2, DONE = 3 };
static const char* stage_name(int s)
{
  static const char* n[] = {"read_scene", "make_collection", "standardize", "accepted"};
  return n[s];
}

template <class Traits>
struct Outcome
{
  Stage stage = READ;          // stage that threw, or DONE
  std::string message;
  bool foreign_exception = false; // something else than Input_error escaped
  RI::Scene scene;
  RI::Rigid_body_collection<Traits> collection, standard;
};

template <class Traits>
Outcome<Traits> run(const std::string& text, const std::string& source, bool with_standardize = true)
{
  Outcome<Traits> o;
  try {
    std::istringstream in(text);
    o.stage = READ;
    o.scene = RI::read_scene(in, source);
    o.stage = COLLECT;
    o.collection = RI::make_collection<Traits>(o.scene);
    o.stage = STANDARDIZE;
    if (with_standardize) o.standard = RI::standardize(o.collection);
    o.stage = DONE;
  } catch (const RI::Input_error& e) {
    o.message = e.what();
  } catch (const std::exception& e) {
    o.foreign_exception = true;
    o.message = std::string("std::exception: ") + e.what();
  } catch (...) {
    o.foreign_exception = true;
    o.message = "unknown exception";
  }
  return o;
}

static std::string excerpt(const std::string& s) { return s.size() > 300 ? s.substr(0, 300) + "..." : s; }

// `needles`: each must occur in the message; "x||y" accepts either alternative.
static bool contains_needle(const std::string& msg, const std::string& needle)
{
  std::size_t start = 0;
  while (true) {
    std::size_t bar = needle.find("||", start);
    std::string alt = needle.substr(start, bar == std::string::npos ? std::string::npos : bar - start);
    if (msg.find(alt) != std::string::npos) return true;
    if (bar == std::string::npos) return false;
    start = bar + 2;
  }
}

struct Bad_case
{
  std::string name;
  std::string text;
  std::vector<std::string> needles; // substrings the message must contain (besides the source)
  bool geometric = false;           // found by standardize: the message need not name the source
};

template <class Traits>
void expect_rejected(const char* kernel, const Bad_case& c)
{
  const std::string source = "mem/" + c.name + ".json";
  Outcome<Traits> o = run<Traits>(c.text, source);
  const std::string who = std::string("[") + kernel + "] " + c.name;
  if (verbose) std::cout << who << " (" << stage_name(o.stage) << "): " << excerpt(o.message) << "\n";
  CHECK(!o.foreign_exception, who << ": a non-Input_error exception escaped: " << excerpt(o.message));
  CHECK(o.stage != DONE, who << ": malformed scene accepted");
  if (o.stage == DONE || o.foreign_exception) return;
  if (!c.geometric || o.stage != STANDARDIZE)
    CHECK(o.message.find(source) != std::string::npos,
          who << ": message does not name the source '" << source << "': " << excerpt(o.message));
  for (const auto& n : c.needles)
    CHECK(contains_needle(o.message, n), who << ": message (from " << stage_name(o.stage) << ") does not mention \"" << n
                                             << "\": " << excerpt(o.message));
}

// ------------------------------------------------------------------------------ malformed cases

static std::vector<Bad_case> malformed_cases()
{
  std::vector<Bad_case> v;
  auto add = [&](const std::string& name, const std::string& text, std::vector<std::string> needles, bool geometric = false) {
    v.push_back(Bad_case{name, text, needles, geometric});
  };
  const std::string ok = two_bodies();

  // ---- invalid JSON
  add("json_empty", "", {"invalid JSON"});
  add("json_whitespace_only", "  \n ", {"invalid JSON"});
  add("json_truncated", ok.substr(0, ok.size() / 2), {"invalid JSON"});
  add("json_truncated_in_number", "{" + FMT + ", \"bodies\": [{\"name\": \"c1\", \"points\": {\"A\": [1.", {"invalid JSON"});
  add("json_trailing_garbage", ok + " garbage", {"invalid JSON"});
  add("json_trailing_brace", ok + "}", {"invalid JSON"});
  add("json_two_values", ok + " {}", {"invalid JSON"});
  add("json_missing_comma", "{" + FMT + " \"bodies\": []}", {"invalid JSON"});
  add("json_trailing_comma", "{" + FMT + ", \"bodies\": [" + BODY_C1 + ", " + BODY_C2 + ",]}", {"invalid JSON"});
  add("json_single_quotes", "{'format': 'rigid-incidence-scene/1'}", {"invalid JSON"});
  add("json_unterminated_string", "{\"format\": \"rigid-incidence-scene/1", {"invalid JSON"});
  add("json_comment", "// a scene\n" + ok, {"invalid JSON"});
  add("json_bare_word", "scene", {"invalid JSON"});
  add("json_nan_literal", with_c2(R"("A": ["0","0","0"], "D": [NaN, 0, 1])"), {"invalid JSON"});
  add("json_infinity_literal", with_c2(R"("A": ["0","0","0"], "D": [Infinity, 0, 1])"), {"invalid JSON"});
  add("json_control_char_in_string", "{\"format\": \"rigid-incidence-scene/1\x01\"}", {"invalid JSON"});
  add("json_deep_arrays", std::string(100000, '['), {"nest||deep"});
  add("json_deep_arrays_balanced", std::string(100000, '[') + std::string(100000, ']'), {"nest||deep"});
  {
    std::string deep;
    for (int i = 0; i < 100000; ++i) deep += "{\"a\":";
    add("json_deep_objects", deep, {"nest||deep"});
  }
  add("json_deep_inside_scene",
      with_c2("\"A\": [\"0\",\"0\",\"0\"], \"D\": " + std::string(60, '[') + "1" + std::string(60, ']')), {"nest||deep"});

  // ---- format and top level
  add("top_level_array", "[" + ok + "]", {"object"});
  add("format_unknown", "{\"format\": \"rigid-incidence-scene/2\", \"bodies\": [" + BODY_C1 + ", " + BODY_C2 + "]}",
      {"format", "rigid-incidence-scene/2"});
  add("format_missing", "{\"bodies\": [" + BODY_C1 + ", " + BODY_C2 + "]}", {"format"});
  add("format_not_string", "{\"format\": 1, \"bodies\": [" + BODY_C1 + "]}", {"format"});
  add("format_duplicate", "{" + FMT + ", " + FMT + ", \"bodies\": [" + BODY_C1 + "]}", {"format", "duplicate"});
  add("unknown_top_field", two_bodies("\"bodys\": []"), {"bodys"});
  add("free_distance_unknown_point", two_bodies("\"free_distance\": [\"B\", \"Q\"]"), {"free_distance", "'Q'"});
  add("free_distance_same_point", two_bodies("\"free_distance\": [\"B\", \"B\"]"), {"free_distance", "two different points"});
  add("free_distance_three_points", two_bodies("\"free_distance\": [\"A\", \"B\", \"C\"]"), {"free_distance", "2 point labels"});
  add("free_distance_number", two_bodies("\"free_distance\": 3"), {"free_distance", "expected"});
  add("free_distance_bad_range", two_bodies("\"free_distance\": {\"between\": [\"B\", \"D\"], \"range\": [5, 2]}"),
      {"free_distance", "range", "below"});
  add("free_distance_negative_range", two_bodies("\"free_distance\": {\"between\": [\"B\", \"D\"], \"range\": [-1, 2]}"),
      {"free_distance", "negative"});
  add("free_distance_range_not_number", two_bodies("\"free_distance\": {\"between\": [\"B\", \"D\"], \"range\": [\"x\", 2]}"),
      {"free_distance", "range[0]"});
  add("free_distance_unknown_field", two_bodies("\"free_distance\": {\"between\": [\"B\", \"D\"], \"step\": 1}"),
      {"free_distance", "step"});
  add("free_distance_no_between", two_bodies("\"free_distance\": {\"range\": [1, 2]}"), {"free_distance", "between"});
  add("inequality_three_points", two_bodies("\"inequalities\": [{\"orientation\": [\"A\", \"B\", \"C\"]}]"), {"inequalities[0]", "4 point labels"});
  add("unknown_body_field",
      scene(BODY_C1 + R"(, {"name": "c2", "colour": "red", "points": {"A": ["0","0","0"], "D": ["0","0","1"]}})"),
      {"colour", "'c2'||bodies[1]"});
  add("unknown_distance_field", with_distances(R"({"between": ["B","D"], "squared": "2", "weight": 1})"),
      {"weight", "distances[0]"});
  add("bodies_missing", "{" + FMT + "}", {"bodies"});
  add("bodies_empty", scene(""), {"bodies"});
  add("bodies_not_array", "{" + FMT + ", \"bodies\": " + BODY_C1 + "}", {"bodies"});
  add("body_missing_name", scene(BODY_C1 + R"(, {"points": {"A": ["0","0","0"], "D": ["0","0","1"]}})"),
      {"bodies[1]", "name"});
  add("body_empty_name", scene(BODY_C1 + R"(, {"name": "", "points": {"A": ["0","0","0"], "D": ["0","0","1"]}})"),
      {"bodies[1]||body ''", "name"});
  add("body_points_missing", scene(BODY_C1 + R"(, {"name": "c2"})"), {"'c2'", "points"});
  add("body_points_array", scene(BODY_C1 + R"(, {"name": "c2", "points": [["0","0","0"], ["0","0","1"]]})"),
      {"'c2'", "points"});

  // ---- coordinates
  add("coordinates_missing", with_c2(R"("A": ["0","0","0"], "D": [])"), {"'c2'", "'D'", "coordinate"});
  add("coordinates_null", with_c2(R"("A": ["0","0","0"], "D": null)"), {"'c2'", "'D'"});
  add("coordinates_object", with_c2(R"("A": ["0","0","0"], "D": {"x": 0, "y": 0, "z": 1})"), {"'c2'", "'D'"});
  add("coordinates_two", with_c2(R"("A": ["0","0","0"], "D": ["0","1"])"), {"'c2'", "'D'", "coordinate"});
  add("coordinates_four", with_c2(R"("A": ["0","0","0"], "D": ["0","1","2","3"])"), {"'c2'", "'D'", "coordinate"});
  add("coordinate_non_numeric", with_c2(R"("A": ["0","0","0"], "D": ["0","abc","1"])"), {"'c2'", "'D'", "coordinate y"});
  add("coordinate_boolean", with_c2(R"("A": ["0","0","0"], "D": ["0","1",true])"), {"'c2'", "'D'", "coordinate z"});
  add("coordinate_null", with_c2(R"("A": ["0","0","0"], "D": [null,"1","1"])"), {"'c2'", "'D'", "coordinate x"});
  add("coordinate_array", with_c2(R"("A": ["0","0","0"], "D": [["1"],"1","1"])"), {"'c2'", "'D'", "coordinate x"});
  add("coordinate_empty_string", with_c2(R"("A": ["0","0","0"], "D": ["","1","1"])"), {"'c2'", "'D'", "coordinate x"});
  add("coordinate_nan", with_c2(R"("A": ["0","0","0"], "D": ["NaN","1","1"])"), {"'c2'", "'D'", "coordinate x", "NaN"});
  add("coordinate_nan_lowercase", with_c2(R"("A": ["0","0","0"], "D": ["1","nan","1"])"), {"'c2'", "'D'", "coordinate y", "NaN"});
  add("coordinate_inf", with_c2(R"("A": ["0","0","0"], "D": ["1","1","inf"])"), {"'c2'", "'D'", "coordinate z", "infinite"});
  add("coordinate_minus_infinity", with_c2(R"("A": ["0","0","0"], "D": ["-Infinity","1","1"])"),
      {"'c2'", "'D'", "coordinate x", "infinite"});
  add("coordinate_huge_exponent", with_c2(R"("A": ["0","0","0"], "D": ["1e99999","1","1"])"),
      {"'c2'", "'D'", "coordinate x", "exponent"});
  add("coordinate_hex", with_c2(R"("A": ["0","0","0"], "D": ["0x10","1","1"])"), {"'c2'", "'D'", "coordinate x"});
  add("coordinate_zero_denominator", with_c2(R"("A": ["0","0","0"], "D": ["1/0","1","1"])"), {"'c2'", "'D'", "coordinate x"});
  add("coordinate_inner_space", with_c2(R"("A": ["0","0","0"], "D": ["1 2","1","1"])"), {"'c2'", "'D'", "coordinate x"});
  add("coordinate_trailing_point", with_c2(R"("A": ["0","0","0"], "D": ["1.","1","1"])"), {"'c2'", "'D'", "coordinate x"});

  // ---- bodies and labels
  add("body_duplicate_name", scene(BODY_C1 + ", " + BODY_C1), {"'c1'", "duplicate"});
  add("label_duplicate", with_c2(R"("A": ["0","0","0"], "D": ["0","0","1"], "A": ["1","1","1"])"),
      {"'c2'", "'A'", "duplicate"});
  add("label_empty", with_c2(R"("A": ["0","0","0"], "": ["0","0","1"])"), {"'c2'", "label"});
  add("body_one_point", with_c2(R"("A": ["0","0","0"])"), {"'c2'", "2 points"});
  add("body_no_points", with_c2(""), {"'c2'", "2 points"});
  add("points_coincident", with_c2(R"("A": ["0","0","0"], "D": ["1","2","3"], "E": ["1","2","3"])"),
      {"'c2'", "'D'", "'E'", "coincide"});
  add("points_coincident_rational_decimal",
      with_c2(R"("A": ["0","0","0"], "D": ["0.1","0.5","1"], "E": ["1/10","1/2","1e0"])"), {"'c2'", "'D'", "'E'", "coincide"});
  add("points_coincident_plain_number",
      with_c2(R"("A": ["0","0","0"], "D": [0.1, 0.5, 1], "E": ["1/10","5e-1","10/10"])"), {"'c2'", "'D'", "'E'", "coincide"});

  // ---- distances
  add("distance_unknown_label", with_distances(R"({"between": ["B","Z"], "squared": "2"})"), {"distances[0]", "'Z'"});
  add("distance_squared_negative", with_distances(R"({"between": ["B","D"], "squared": "-2"})"),
      {"distances[0]", "squared", "positive"});
  add("distance_length_negative", with_distances(R"({"between": ["B","D"], "length": -1.5})"),
      {"distances[0]", "length", "positive"});
  add("distance_nan", with_distances(R"({"between": ["B","D"], "squared": "NaN"})"), {"distances[0]", "squared", "NaN"});
  add("distance_infinite", with_distances(R"({"between": ["B","D"], "length": "Infinity"})"),
      {"distances[0]", "length", "infinite"});
  add("distance_non_numeric", with_distances(R"({"between": ["B","D"], "squared": "two"})"), {"distances[0]", "squared"});
  add("distance_same_point", with_distances(R"({"between": ["B","B"], "squared": "2"})"), {"distances[0]", "'B'"});
  add("distance_both_values", with_distances(R"({"between": ["B","D"], "squared": "2", "length": "1"})"),
      {"distances[0]", "squared", "length"});
  add("distance_no_value", with_distances(R"({"between": ["B","D"]})"), {"distances[0]", "squared||length"});
  add("distance_one_label", with_distances(R"({"between": ["B"], "squared": "2"})"), {"distances[0]", "between"});
  add("distance_labels_not_strings", with_distances(R"({"between": [1, 2], "squared": "2"})"), {"distances[0]", "between"});
  add("distance_disagree", with_distances(R"({"between": ["B","D"], "squared": "2"}, {"between": ["B","D"], "length": "2"})"),
      {"distances[1]", "distances[0]", "'B'", "'D'"});
  add("distance_disagree_reversed",
      with_distances(R"({"between": ["B","D"], "squared": "2"}, {"between": ["D","B"], "squared": "3"})"),
      {"distances[1]", "distances[0]", "'B'", "'D'"});

  // ---- frame
  add("frame_unknown", two_bodies("\"frame\": \"c9\""), {"frame", "c9"});
  add("frame_not_string", two_bodies("\"frame\": 1"), {"frame"});

  // ---- geometric contradictions, found by standardize
  // a distance inside a body that disagrees with the body (|BC|^2 = 2 in c1)
  add("distance_inside_body_disagrees", with_distances(R"({"between": ["C","B"], "squared": "3"})"),
      {"'c1'", "'B'", "'C'", "distances[0]"}, true);
  // c2 = {A, B, C} lies in c1 = {A, B, C, D}; only |AB| differs (5 vs 8.2)
  add("shared_points_disagree_subset",
      scene(R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","2","0"], "C": ["0","2","0"], "D": ["0","0","1"]}},
               {"name": "c2", "points": {"A": ["0","0","0"], "B": ["0.6","2.8","0"], "C": ["0","2","0"]}})"),
      {"'c1'", "'c2'", "'A'", "'B'"}, true);
  // c1 and c2 share A, B, C (merged); only |AB| differs
  add("shared_points_disagree_merge",
      scene(R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","2","0"], "C": ["0","2","0"], "D": ["0","0","1"]}},
               {"name": "c2", "points": {"A": ["0","0","0"], "B": ["0.6","2.8","0"], "C": ["0","2","0"], "E": ["5","5","5"]}})"),
      {"'c1'", "'c2'", "'A'", "'B'"}, true);
  // c1 and c2 share only A and B, at distance 1 in c1 and 2 in c2: no configuration exists
  add("shared_points_disagree_two",
      scene(R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"]}},
               {"name": "c2", "points": {"A": ["0","0","0"], "B": ["2","0","0"], "D": ["0","0","1"]}})"),
      {"'c1'", "'c2'", "'A'", "'B'"}, true);
  // mirror images sharing 4 non-coplanar points (D at z = 1 and z = -1), each with a point of its own
  add("mirror_bodies",
      scene(R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"], "D": ["0","0","1"], "E": ["1","1","1"]}},
               {"name": "c2", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"], "D": ["0","0","-1"], "F": ["5","5","5"]}})"),
      {"'c1'", "'c2'", "mirror"}, true);
  // the same, c2 has no point of its own: it lies in c1 (absorbed) but is its mirror image
  add("mirror_body_inside",
      scene(R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"], "D": ["0","0","1"], "E": ["1","1","1"]}},
               {"name": "c2", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"], "D": ["0","0","-1"]}})"),
      {"'c1'", "'c2'", "mirror"}, true);
  // triangle A-B-C of fixed distances |AB| = 1 (c1), |BC| = 1 (c2), |AC| = 3 (distance)
  const std::string tri = R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "U": ["0","1","0"]}},
                             {"name": "c2", "points": {"B": ["0","0","0"], "C": ["1","0","0"], "V": ["0","1","0"]}})";
  add("implied_triangle_inequality", scene(tri, R"("distances": [{"between": ["A","C"], "length": "3"}])"),
      {"'A'", "'B'", "'C'", "triangle"}, true);
  return v;
}

// ------------------------------------------------------------------------------ accepted scenes

template <class Traits>
typename Traits::Point_3 coords(const RI::Rigid_body_collection<Traits>& c, const std::string& body, const std::string& label)
{
  const auto& b = c.body(c.body_index(body));
  return b.coordinates[b.local(c.point_index(label))];
}

static const RI::Scene::Point* scene_point(const RI::Scene& s, const std::string& body, const std::string& label)
{
  for (const auto& b : s.bodies)
    if (b.name == body)
      for (const auto& p : b.points) if (p.label == label) return &p;
  return nullptr;
}

// FT of the kernel against the exact rational q: equal for the exact kernel; for Epick, equal
// to `nearest`, the nearest double as the C++ compiler reads the decimal literal.
template <class Traits>
bool ft_is(const typename Traits::FT& x, const CGAL::Gmpq& q, double nearest)
{
  if constexpr (Traits::has_exact_ft) return x == typename Traits::FT(q);
  else return CGAL::to_double(x) == nearest;
}

template <class FT>
std::string show(const FT& x)
{
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

static CGAL::Gmpz pow10(int k)
{
  CGAL::Gmpz r(1);
  for (int i = 0; i < k; ++i) r *= CGAL::Gmpz(10);
  return r;
}

template <class Traits>
void accepted_scenes(const char* kernel)
{
  const std::string K = std::string("[") + kernel + "] ";
  // ---- numbers as strings and plain JSON numbers; exact values
  {
    const std::string text = with_c2(
        R"("A": ["0","0","0"], "D": [0.1, -1.25e-3, 1E+2], "E": ["0.1", "-1.25e-3", "3/7"],
           "F": [123456789012345678901234567890, "-1180591620717411303425", -0],
           "G": [2.5e-1, 0.3, 7])");
    auto o = run<Traits>(text, "mem/numbers.json");
    CHECK(o.stage == DONE, K << "numbers: refused: " << o.message);
    if (o.stage == DONE) {
      const auto* d = scene_point(o.scene, "c2", "D");
      const auto* e = scene_point(o.scene, "c2", "E");
      const auto* f = scene_point(o.scene, "c2", "F");
      const auto* g = scene_point(o.scene, "c2", "G");
      CHECK(d && e && f && g, K << "numbers: points missing in the scene");
      if (d && e && f && g) {
        CHECK(d->x == CGAL::Gmpq(1, 10), K << "plain 0.1 is not exactly 1/10 in the scene: " << d->x);
        CHECK(d->y == CGAL::Gmpq(-1, 800), K << "plain -1.25e-3 is not -1/800: " << d->y);
        CHECK(d->z == CGAL::Gmpq(100), K << "plain 1E+2 is not 100: " << d->z);
        CHECK(e->x == CGAL::Gmpq(1, 10), K << "\"0.1\" is not exactly 1/10: " << e->x);
        CHECK(e->y == CGAL::Gmpq(-1, 800), K << "\"-1.25e-3\" is not -1/800: " << e->y);
        CHECK(e->z == CGAL::Gmpq(3, 7), K << "\"3/7\" is not 3/7: " << e->z);
        CGAL::Gmpz big(0);
        for (char ch : std::string("123456789012345678901234567890")) big = big * CGAL::Gmpz(10) + CGAL::Gmpz(ch - '0');
        CGAL::Gmpz two70(1);
        for (int i = 0; i < 70; ++i) two70 *= CGAL::Gmpz(2);
        CHECK(f->x == CGAL::Gmpq(big), K << "plain 30-digit integer read as " << f->x);
        CHECK(f->y == CGAL::Gmpq(-(two70 + CGAL::Gmpz(1))), K << "\"-(2^70+1)\" read as " << f->y);
        CHECK(f->z == CGAL::Gmpq(0), K << "plain -0 read as " << f->z);
        CHECK(g->x == CGAL::Gmpq(1, 4) && g->y == CGAL::Gmpq(3, 10) && g->z == CGAL::Gmpq(7),
              K << "plain 2.5e-1, 0.3, 7 read as " << g->x << ", " << g->y << ", " << g->z);
      }
      // in the collection: exact kernel exactly, Epick the nearest double
      auto pd = coords(o.collection, "c2", "D");
      auto pe = coords(o.collection, "c2", "E");
      auto pf = coords(o.collection, "c2", "F");
      auto pg = coords(o.collection, "c2", "G");
      CHECK(ft_is<Traits>(pd.x(), CGAL::Gmpq(1, 10), 0.1), K << "collection: plain 0.1 became (nearest double expected, 0.10000000000000001) " << show(pd.x()));
      CHECK(ft_is<Traits>(pe.x(), CGAL::Gmpq(1, 10), 0.1), K << "collection: \"0.1\" became " << show(pe.x()));
      CHECK(ft_is<Traits>(pd.y(), CGAL::Gmpq(-1, 800), -1.25e-3), K << "collection: -1.25e-3 became " << show(pd.y()));
      CHECK(ft_is<Traits>(pe.z(), CGAL::Gmpq(3, 7), 3.0 / 7.0), K << "collection: \"3/7\" became " << show(pe.z()));
      CHECK(ft_is<Traits>(pg.y(), CGAL::Gmpq(3, 10), 0.3), K << "collection: plain 0.3 became " << show(pg.y()));
      CHECK(ft_is<Traits>(pf.x(), CGAL::Gmpq(CGAL::Gmpz("123456789012345678901234567890")), 123456789012345678901234567890.0),
            K << "collection: 30-digit integer became " << show(pf.x()));
      CHECK(ft_is<Traits>(pf.y(), CGAL::Gmpq(CGAL::Gmpz("-1180591620717411303425")), -1180591620717411303425.0),
            K << "collection: -(2^70+1) became " << show(pf.y()));
    }
  }
  // ---- plain JSON numbers whose double underflows or overflows, read from their text
  {
    // 1e-400 underflows a double to 0: read from its text it stays 10^-400
    auto o = run<Traits>(with_c2(R"("A": ["0","0","0"], "D": [1e-400, 0, 1])"), "mem/tiny_exponent.json");
    if constexpr (Traits::has_exact_ft) {
      CHECK(o.stage == DONE, K << "plain 1e-400 refused: " << o.message);
      if (o.stage == DONE) {
        const auto* d = scene_point(o.scene, "c2", "D");
        CHECK(d && d->x == CGAL::Gmpq(CGAL::Gmpz(1), pow10(400)), K << "plain 1e-400 not read as 10^-400");
      }
    } else {
      // beyond the range of the double kernel: refused, naming the coordinate, and not as if it were 0
      CHECK(o.stage == COLLECT, K << "plain 1e-400 with a double kernel: " << stage_name(o.stage) << " " << o.message);
      CHECK(o.message.find("mem/tiny_exponent.json") != std::string::npos && o.message.find("'D'") != std::string::npos &&
                o.message.find("coordinate x") != std::string::npos,
            K << "1e-400 with a double kernel: message does not name the file, point and coordinate: " << o.message);
      CHECK(o.message.find(": 0 is outside") == std::string::npos,
            K << "1e-400 with a double kernel: the message calls the value 0 (a non-zero value below the range): " << o.message);
    }
  }
  if constexpr (!Traits::has_exact_ft) {
    // the double kernel's range (1e-50 <= |x| <= 1e50): refused with a message naming the field
    struct R { const char* name; std::string text; std::vector<std::string> needles; };
    for (const R& r : {R{"range_big", with_c2(R"("A": ["0","0","0"], "D": ["0","-1e60","1"])"), {"'c2'", "'D'", "coordinate y", "range"}},
                       R{"range_small", with_c2(R"("A": ["0","0","0"], "D": ["0","1","1e-60"])"), {"'c2'", "'D'", "coordinate z", "range"}},
                       R{"range_distance", with_distances(R"({"between": ["B","D"], "squared": "1e120"})"), {"distances[0]", "range"}}}) {
      auto o = run<Traits>(r.text, std::string("mem/") + r.name + ".json");
      CHECK(o.stage != DONE && !o.foreign_exception, K << r.name << ": accepted by the double kernel");
      CHECK(o.message.find(std::string("mem/") + r.name + ".json") != std::string::npos, K << r.name << ": no source in " << o.message);
      for (const auto& n : r.needles) CHECK(o.message.find(n) != std::string::npos, K << r.name << ": no \"" << n << "\" in " << o.message);
    }
  }
  {
    // nlohmann-json's lexer refuses a plain JSON number beyond the range of a double before
    // the SAX interface sees its text: the scene is refused with a hint to quote it.
    auto o = run<Traits>(with_c2(R"("A": ["0","0","0"], "D": [1e400, 0, 0])"), "mem/big_exponent.json");
    CHECK(o.stage != DONE && !o.foreign_exception, K << "plain 1e400 accepted");
    CHECK(o.message.find("mem/big_exponent.json") != std::string::npos, K << "1e400: no source in " << o.message);
    CHECK(o.message.find("as strings") != std::string::npos, K << "1e400: no hint to quote it in " << o.message);
    auto q = run<Traits>(with_c2(R"("A": ["0","0","0"], "D": ["1e40", 0, 0])"), "mem/quoted_exponent.json");
    CHECK(q.stage == DONE, K << "quoted 1e40 refused: " << q.message);
  }
  // ---- length vs squared
  {
    auto o = run<Traits>(with_distances(R"({"between": ["B","D"], "length": "3"}, {"between": ["C","E"], "squared": "9"},
                                           {"between": ["B","E"], "length": 0.5}, {"between": ["C","D"], "length": "2/3"})"),
                         "mem/lengths.json", false); // reading only: these distances need not be realizable
    CHECK(o.stage == DONE, K << "lengths: refused: " << o.message);
    if (o.stage == DONE) {
      CHECK(o.scene.distances.size() == 4, K << "lengths: " << o.scene.distances.size() << " distances read");
      if (o.scene.distances.size() == 4) {
        const auto& d = o.scene.distances;
        CHECK(d[0].given_as_length && d[0].length == CGAL::Gmpq(3) && d[0].squared == CGAL::Gmpq(9),
              K << "length 3 read as squared " << d[0].squared);
        CHECK(!d[1].given_as_length && d[1].squared == CGAL::Gmpq(9), K << "squared 9 read as " << d[1].squared);
        CHECK(d[2].squared == CGAL::Gmpq(1, 4), K << "length 0.5 read as squared " << d[2].squared);
        CHECK(d[3].squared == CGAL::Gmpq(4, 9), K << "length 2/3 read as squared " << d[3].squared);
      }
      const auto& cd = o.collection.distances();
      CHECK(cd.size() == 4, K << "lengths: collection has " << cd.size() << " distances");
      if (cd.size() == 4) {
        CHECK(o.collection.label(cd[0].a) == "B" && o.collection.label(cd[0].b) == "D", K << "distance 0 joins the wrong points");
        CHECK(ft_is<Traits>(cd[0].squared, CGAL::Gmpq(9), 9.0), K << "length 3 -> squared " << cd[0].squared);
        CHECK(ft_is<Traits>(cd[2].squared, CGAL::Gmpq(1, 4), 0.25), K << "length 0.5 -> squared " << cd[2].squared);
        CHECK(ft_is<Traits>(cd[3].squared, CGAL::Gmpq(4, 9), 4.0 / 9.0), K << "length 2/3 -> squared " << cd[3].squared);
      }
    }
  }
  // ---- an equal duplicate distance (length 2 = squared 4, reversed labels) is accepted once
  {
    auto o = run<Traits>(with_distances(R"({"between": ["B","D"], "length": "2"}, {"between": ["D","B"], "squared": "4"})"),
                         "mem/dup_equal.json", false);
    CHECK(o.stage == DONE, K << "equal duplicate distance refused: " << o.message);
    if (o.stage == DONE) CHECK(o.collection.distances().size() == 1, K << "equal duplicate kept " << o.collection.distances().size());
  }
  // ---- frame: default = first body, explicit, and kept by standardize; members in any order
  {
    auto o = run<Traits>(two_bodies("\"comment\": \"a comment is allowed\""), "mem/frame_default.json");
    CHECK(o.stage == DONE, K << "plain two bodies refused: " << o.message);
    if (o.stage == DONE) {
      CHECK(o.scene.frame.empty() || o.scene.frame == "c1", K << "scene frame " << o.scene.frame);
      CHECK(o.collection.frame() == "c1", K << "default frame is '" << o.collection.frame() << "', not the first body");
      CHECK(o.standard.frame() == "c1", K << "default frame after standardize '" << o.standard.frame() << "'");
      CHECK(o.scene.name == "t" && o.collection.name == "t", K << "scene name lost");
      CHECK(o.collection.number_of_bodies() == 2 && o.collection.number_of_points() == 5,
            K << "two bodies: " << o.collection.number_of_bodies() << " bodies, " << o.collection.number_of_points() << " points");
      std::size_t a = o.collection.point_index("A");
      CHECK(a != o.collection.npos && o.collection.body(0).contains(a) && o.collection.body(1).contains(a),
            K << "A is not shared by c1 and c2");
      CHECK(o.collection.shared_points().size() == 1, K << "shared points " << o.collection.shared_points().size());
    }
    std::string reversed = "{\"frame\": \"c2\", \"bodies\": [" + BODY_C1 + ", " + BODY_C2 + "], " + FMT + "}";
    auto o2 = run<Traits>(reversed, "mem/frame_explicit.json");
    CHECK(o2.stage == DONE, K << "explicit frame refused: " << o2.message);
    if (o2.stage == DONE) {
      CHECK(o2.scene.frame == "c2", K << "scene frame '" << o2.scene.frame << "'");
      CHECK(o2.collection.frame() == "c2", K << "explicit frame '" << o2.collection.frame() << "'");
      CHECK(o2.standard.frame() == "c2", K << "explicit frame after standardize '" << o2.standard.frame() << "'");
    }
    // the frame body is absorbed by standardize: the frame must still be traceable (a body of
    // the standard collection, or one whose sources include it)
    auto o3 = run<Traits>(scene(R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"], "D": ["0","0","1"]}},
                                   {"name": "c2", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "C": ["0","1","0"]}},
                                   {"name": "c3", "points": {"D": ["0","0","0"], "E": ["1","0","0"], "F": ["0","1","0"]}})",
                                "\"frame\": \"c2\""),
                          "mem/frame_absorbed.json");
    CHECK(o3.stage == DONE, K << "frame on an absorbed body refused: " << o3.message);
    if (o3.stage == DONE) {
      bool traced = o3.standard.body_index(o3.standard.frame()) != o3.standard.npos;
      for (std::size_t i = 0; i < o3.standard.number_of_bodies() && !traced; ++i)
        for (const auto& src : o3.standard.body(i).sources) traced = traced || src == o3.standard.frame();
      CHECK(traced, K << "frame '" << o3.standard.frame() << "' names no body of the standard collection and no source");
    }
  }
  // ---- a realizable implied triangle (|AB| = |BC| = |AC| = 1) is accepted and gives an
  //      implied body named by its sorted labels
  {
    const std::string tri = R"({"name": "c1", "points": {"A": ["0","0","0"], "B": ["1","0","0"], "U": ["0","1","0"]}},
                               {"name": "c2", "points": {"B": ["0","0","0"], "C": ["1","0","0"], "V": ["0","1","0"]}})";
    auto o = run<Traits>(scene(tri, R"("distances": [{"between": ["C","A"], "length": 1}])"), "mem/triangle_ok.json");
    CHECK(o.stage == DONE, K << "realizable implied triangle refused: " << o.message);
    if (o.stage == DONE) {
      std::size_t i = o.standard.body_index("I1{A,B,C}");
      CHECK(i != o.standard.npos, K << "no implied body I1{A,B,C}");
      if (i != o.standard.npos) CHECK(o.standard.body(i).origin == RI::Body_origin::IMPLIED, K << "I1{A,B,C} not implied");
    }
  }
  // ---- the shipped scenes read and standardize
  for (const char* f : {"tetra", "tetra_i", "quad", "pent"}) {
    try {
      RI::Scene s = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + f + ".json");
      auto c = RI::make_collection<Traits>(s);
      auto sc = RI::standardize(c);
      CHECK(sc.number_of_bodies() >= c.number_of_bodies() - 1, K << f << ": standard collection has " << sc.number_of_bodies());
    } catch (const std::exception& e) {
      CHECK(false, K << "shipped scene " << f << " refused: " << e.what());
    }
  }
  // ---- a missing file names the file
  try {
    RI::read_scene(std::string("/nonexistent/dir/scene.json"));
    CHECK(false, K << "missing file accepted");
  } catch (const RI::Input_error& e) {
    CHECK(std::string(e.what()).find("/nonexistent/dir/scene.json") != std::string::npos, K << "missing file: " << e.what());
  }
}

// Maintenance: `test_read_scene --write-malformed DIR` writes each malformed case (except the
// two largest nesting cases) to DIR/<name>.json, the files run through the command-line tool by
// cmake/cli.cmake, and prints the table of expected stderr regexes for cli.cmake.
static int write_malformed(const std::string& dir)
{
  for (const auto& c : malformed_cases()) {
    if (c.name == "json_deep_objects" || c.name == "json_deep_arrays_balanced") continue;
    std::string text = c.text;
    // a little layout for the eye (outside strings: the texts hold no such sequence in a string)
    for (const std::string& from : {std::string("\"bodies\": ["), std::string(", {\"name\""), std::string(", \"distances\"")}) {
      std::string to = from == "\"bodies\": [" ? from + "\n  " : ",\n  " + from.substr(2);
      for (std::size_t pos = 0; (pos = text.find(from, pos)) != std::string::npos; pos += to.size()) text.replace(pos, from.size(), to);
    }
    for (std::size_t pos = 0; (pos = text.find("\n ", pos)) != std::string::npos; pos += 3) {
      std::size_t end = text.find_first_not_of(' ', pos + 1);
      text.replace(pos, end - pos, "\n  ");
    }
    std::ofstream out(dir + "/" + c.name + ".json", std::ios::binary);
    out << text << (text.empty() || c.name.rfind("json_", 0) == 0 ? "" : "\n");
    std::string rx;
    for (const auto& n : c.needles) {
      std::string r;
      for (char ch : n) r += std::string("[](){}.*+?^$|\\").find(ch) != std::string::npos ? '.' : ch;
      // "a||b" became "a..b": restore the alternative
      std::size_t bar = n.find("||");
      if (bar != std::string::npos) r = "(" + r.substr(0, bar) + "|" + r.substr(bar + 2) + ")";
      rx += (rx.empty() ? "" : "&&") + r;
    }
    std::cout << "  " << c.name << " \"" << rx << "\"\n";
  }
  return 0;
}

// A distance of 0 is a coincidence (issue 27, item 5): the labels name one point.
template <class Traits>
void coincidences(const char* kernel)
{
  const std::string k = std::string("coincidence [") + kernel + "]: ";
  auto collect = [](const std::string& text) {
    std::istringstream in(text);
    return RI::make_collection<Traits>(RI::read_scene(in, "mem/coincidence.json"));
  };
  for (const std::string& zero : {std::string("\"squared\": 0"), std::string("\"squared\": \"0/7\""), std::string("\"length\": \"-0.0\"")}) {
    auto c = collect(with_distances(R"({"between": ["D","B"], )" + zero + "}"));
    // B is seen first (body c1): D becomes another name of it
    CHECK(c.point_index("D") == decltype(c)::npos && c.point_index("B") != decltype(c)::npos, k << zero << ": 'D' is still a point");
    CHECK(c.aliases().size() == 1 && c.aliases()[0].alias == "D" && c.aliases()[0].label == "B" &&
              c.aliases()[0].why.find("distances[0]") != std::string::npos,
          k << zero << ": the alias D -> B is missing");
    CHECK(c.body(c.body_index("c2")).contains(c.point_index("B")), k << zero << ": body c2 does not hold 'B'");
    CHECK(c.distances().empty(), k << zero << ": the distance of 0 stayed a distance");
  }
  // a chain of coincidences, and a distance through them: one class, its first label
  {
    const std::string c3 = R"({"name": "c3", "points": {"A": ["0","0","0"], "F": ["0","2","0"], "G": ["2","0","1"]}})";
    auto c = collect(scene(BODY_C1 + ", " + BODY_C2 + ", " + c3,
                           R"("distances": [{"between": ["F","D"], "squared": 0}, {"between": ["D","B"], "squared": 0}, {"between": ["G","E"], "squared": "3"}])"));
    CHECK(c.aliases().size() == 2, k << "chain: " << c.aliases().size() << " aliases");
    for (const auto& a : c.aliases()) CHECK(a.label == "B", k << "chain: '" << a.alias << "' names '" << a.label << "', not 'B'");
    CHECK(c.distances().size() == 1, k << "chain: " << c.distances().size() << " distances left, not 1");
  }
  // two labels of one point at different places in one body, or at a nonzero distance: no
  // real configuration (not a malformed file)
  bool threw = false;
  try { collect(with_distances(R"({"between": ["B","C"], "squared": 0})")); }
  catch (const RI::No_real_configuration& e) { threw = std::string(e.what()).find("'c1'") != std::string::npos; }
  CHECK(threw, k << "a body holding both labels apart is not 'no real configuration' naming it");
  threw = false;
  try { collect(with_distances(R"({"between": ["B","D"], "squared": 0}, {"between": ["D","B"], "squared": 2})")); }
  catch (const RI::No_real_configuration& e) { threw = std::string(e.what()).find("distances[1]") != std::string::npos; }
  CHECK(threw, k << "a nonzero distance between two labels of one point is not 'no real configuration'");
}

int main(int argc, char** argv)
{
  if (argc > 2 && std::string(argv[1]) == "--write-malformed") return write_malformed(argv[2]);
  verbose = argc > 1 && std::string(argv[1]) == "-v";
  auto t0 = std::chrono::steady_clock::now();
  accepted_scenes<Exact_traits>("exact");
  accepted_scenes<Epick_traits>("epick");
  coincidences<Exact_traits>("exact");
  coincidences<Epick_traits>("epick");
  const auto cases = malformed_cases();
  for (const auto& c : cases) {
    expect_rejected<Exact_traits>("exact", c);
    expect_rejected<Epick_traits>("epick", c);
  }
  // The rejection is a property of the text: a valid scene must pass the same pipeline, so the
  // cases above are not rejected for an unrelated reason (sanity of the base texts).
  for (const std::string& ok : {two_bodies(), with_c2(R"("A": ["0","0","0"], "D": ["0","0","1"])"),
                                with_distances(R"({"between": ["B","D"], "squared": "2"})")}) {
    auto o = run<Exact_traits>(ok, "mem/base.json");
    CHECK(o.stage == DONE, "base scene refused: " << o.message);
  }
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "test_read_scene: " << cases.size() << " malformed cases x 2 kernels, " << checks << " checks, " << failures
            << " failures (" << secs << " s)\n";
  return failures == 0 ? 0 : 1;
}
