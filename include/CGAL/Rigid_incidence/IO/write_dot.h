// Copyright (c) 2026 Rigid_incidence contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Graphviz DOT output of the overlap graph with an incidence tree highlighted.

#ifndef CGAL_RIGID_INCIDENCE_IO_WRITE_DOT_H
#define CGAL_RIGID_INCIDENCE_IO_WRITE_DOT_H

#include <CGAL/Rigid_incidence/Overlap_graph.h>
#include <CGAL/Rigid_incidence/Rigid_body_collection.h>
#include <CGAL/Rigid_incidence/optimal_incidence_tree.h>
#include <CGAL/Rigid_incidence/Seam_graph.h>
#include <CGAL/Rigid_incidence/well_formed_incidences.h>

#include <ostream>
#include <set>
#include <string>

namespace CGAL {
namespace Rigid_incidence {
namespace internal {
// Escapes user text (names, labels) for a DOT string.
inline std::string dot_escape(const std::string& s)
{
  std::string r;
  for (char ch : s) { if (ch == '"' || ch == '\\') r += '\\'; r += ch; }
  return r;
}
// Quotes already escaped DOT text (which may hold line breaks written as \n).
inline std::string dot_quote(const std::string& escaped) { return "\"" + escaped + "\""; }
} // namespace internal

/*!
\ingroup PkgRigidIncidenceIO
\brief Writes the overlap graph of `c` in Graphviz DOT, with the tree `t` highlighted.

Bodies of the covering set are filled, the root is double-circled, implied bodies are
drawn as boxes, tree edges are bold and labelled with their weight, edges of weight 6
(bodies sharing no point) are omitted.
*/
template <class Traits>
void write_overlap_graph_dot(std::ostream& os, const Rigid_body_collection<Traits>& c, const Incidence_tree& t)
{
  using internal::dot_quote;
  using internal::dot_escape;
  Overlap_graph og(c);
  std::vector<bool> in_cover(c.number_of_bodies(), false);
  for (std::size_t b : t.covering_set) in_cover[b] = true;
  os << "graph overlap {\n";
  os << "  label=" << dot_quote("overlap graph of " + dot_escape(c.name.empty() ? std::string("scene") : c.name) +
                                  ": tree weight " + std::to_string(t.weight) + ", depth sum " + std::to_string(t.depth_sum) +
                                  " (bold: incidence tree; weight-6 pairs omitted)") << ";\n";
  os << "  node [fontname=Helvetica]; edge [fontname=Helvetica];\n";
  for (std::size_t i = 0; i < c.number_of_bodies(); ++i) {
    const auto& b = c.body(i);
    std::string pts;
    for (std::size_t k = 0; k < b.points.size() && k < 6; ++k) pts += (k ? "," : "") + dot_escape(c.label(b.points[k]));
    if (b.points.size() > 6) pts += ",...";
    os << "  b" << i << " [label=" << dot_quote(dot_escape(b.name) + "\\n" + pts)
       << ", shape=" << (b.origin == Body_origin::IMPLIED ? "box" : "ellipse")
       << (i == t.root ? ", peripheries=2" : "")
       << (in_cover[i] ? ", style=filled, fillcolor=\"#cfe3ff\"" : ", style=dashed, color=gray40") << "];\n";
  }
  const auto& g = og.graph();
  for (auto e : boost::make_iterator_range(boost::edges(g))) {
    std::size_t a = boost::source(e, g), b = boost::target(e, g);
    bool tree = (t.parent.size() > b && t.parent[b] == a) || (t.parent.size() > a && t.parent[a] == b);
    std::string shared;
    for (std::size_t p : g[e].shared) shared += (shared.empty() ? "" : ",") + dot_escape(c.label(p));
    os << "  b" << a << " -- b" << b << " [label=" << dot_quote(std::to_string(g[e].weight) + " (" + shared + ")")
       << (tree ? ", penwidth=3, color=\"#c0392b\"" : ", color=gray50") << "];\n";
  }
  // tree edges of weight 6 are not in the overlap graph's explicit edges
  for (const auto& te : t.edges)
    if (te.weight == 6)
      os << "  b" << te.parent << " -- b" << te.child << " [label=\"6\", penwidth=3, color=\"#c0392b\"];\n";
  os << "}\n";
}

/*!
\ingroup PkgRigidIncidenceIO
\brief Writes the seam graph of the selection's bodies in Graphviz DOT, with the chosen seam
tree highlighted.

One cluster per body holds its copies (v, c) of shared points; line seam edges are dashed;
point seam edges of the selection are drawn: bold red for the seam tree F1 (three coordinates
matched), blue for the other edges of F* (coordinates 1 and 2). Point seam edges left out are
not drawn (each point's copies form a complete graph).
*/
template <class Traits>
void write_seam_graph_dot(std::ostream& os, const Rigid_body_collection<Traits>& c, const Well_formed_selection& s)
{
  using internal::dot_escape;
  using internal::dot_quote;
  Seam_graph g(c, s.bodies);
  os << "graph seam {\n";
  os << "  label=" << dot_quote("seam graph of " + dot_escape(c.name.empty() ? std::string("scene") : c.name) + ": " +
                                  std::to_string(s.incidences.size()) + " well-formed incidences (" +
                                  std::to_string(s.tree_count) + " tree, " + std::to_string(s.remaining_count) +
                                  " remaining); red: seam tree (3 coordinates), blue: 2 coordinates, dashed: line seam edges")
     << ";\n  node [fontname=Helvetica, shape=circle, fontsize=10]; edge [fontname=Helvetica];\n";
  for (std::size_t b : s.bodies) {
    os << "  subgraph cluster_b" << b << " {\n    label=" << dot_quote(dot_escape(c.body(b).name)) << ";\n";
    for (std::size_t k = 0; k < g.vertices().size(); ++k)
      if (g.vertices()[k].body == b)
        os << "    v" << k << " [label=" << dot_quote(dot_escape(c.label(g.vertices()[k].point))) << "];\n";
    os << "  }\n";
  }
  for (const auto& e : g.shared_pairs())
    for (std::size_t b : e.bodies)
      os << "  v" << g.vertex(e.v, b) << " -- v" << g.vertex(e.w, b) << " [style=dashed, color=gray50];\n";
  std::set<std::pair<std::size_t, std::size_t>> tree;
  for (const auto& e : s.seam_tree) tree.insert(std::minmax(g.vertex(e.point, e.body_a), g.vertex(e.point, e.body_b)));
  for (const auto& se : s.point_seam_edges) {
    const std::pair<std::size_t, std::size_t> e = std::minmax(g.vertex(se.point, se.body_a), g.vertex(se.point, se.body_b));
    bool in_tree = tree.count(e) > 0;
    os << "  v" << e.first << " -- v" << e.second
       << (in_tree ? " [penwidth=3, color=\"#c0392b\", label=\"1,2,3\"];\n" : " [color=\"#2e86c1\", label=\"1,2\"];\n");
  }
  os << "}\n";
}

} // namespace Rigid_incidence
} // namespace CGAL

#endif
