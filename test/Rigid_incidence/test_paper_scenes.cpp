// The paper scenes (tetra, quad, pent) give the numbers of the papers: standard collection
// sizes, dof counts, tree weight, root, depth sum, ties. Run with two kernels.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Rigid_incidence.h>

#include <iostream>
#include <string>

namespace RI = CGAL::Rigid_incidence;

static int failures = 0;
#define CHECK(cond, msg) do { if (!(cond)) { ++failures; std::cerr << "FAIL " << __LINE__ << ": " << msg << "\n"; } } while (0)

template <class Traits>
void check_scene(const std::string& file, std::size_t bodies, std::size_t implied, long weight, long depth_sum,
                 const std::string& root, std::size_t ties, long dof)
{
  RI::Scene s = RI::read_scene(std::string(RIGID_INCIDENCE_DATA_DIR) + "/" + file);
  auto c = RI::standardize(RI::make_collection<Traits>(s));
  std::size_t n_implied = 0;
  for (const auto& b : c.bodies()) n_implied += b.origin == RI::Body_origin::IMPLIED;
  CHECK(c.number_of_bodies() == bodies, file << ": " << c.number_of_bodies() << " bodies, expected " << bodies);
  CHECK(n_implied == implied, file << ": " << n_implied << " implied bodies, expected " << implied);
  RI::Dof_count d = RI::dof_count(c);
  CHECK(d.dof == dof, file << ": dof " << d.dof << ", expected " << dof);
  CHECK(d.connected, file << ": not connected");
  RI::Incidence_tree t = RI::optimal_incidence_tree(c);
  CHECK(t.weight == weight, file << ": weight " << t.weight << ", expected " << weight);
  CHECK(t.depth_sum == depth_sum, file << ": depth sum " << t.depth_sum << ", expected " << depth_sum);
  CHECK(c.body(t.root).name == root, file << ": root " << c.body(t.root).name << ", expected " << root);
  CHECK(t.ties == ties, file << ": ties " << t.ties << ", expected " << ties);
  CHECK(t.proven_optimal, file << ": not proven optimal");
  std::cout << file << ": " << c.number_of_bodies() << " bodies, weight " << t.weight << ", depth sum " << t.depth_sum
            << ", root " << c.body(t.root).name << ", ties " << t.ties << ", dof " << d.dof << "\n";
}

template <class Traits>
void run_all()
{
  check_scene<Traits>("tetra.json", 7, 4, 3, 3, "I1{P12,P23,P31}", 1, 0);
  check_scene<Traits>("quad.json", 9, 4, 4, 4, "c5", 1, 0);
  // pent: the six bodies c1-c2-c6-c3-c4-c5 form a cycle of weight-1 edges and leaving out
  // any one of them leaves a covering path of weight 4 whose middle body gives depth sum 6:
  // 6 rooted trees tie (the brute force of test_optimal_tree_brute_force agrees). The
  // tie-break picks the paper's tree (no implied body), rooted at c5.
  check_scene<Traits>("pent.json", 6, 1, 4, 6, "c5", 6, 0);
}

int main()
{
  run_all<RI::Rigid_incidence_traits<CGAL::Simple_cartesian<CGAL::Gmpq>>>();
  run_all<RI::Rigid_incidence_traits<CGAL::Exact_predicates_inexact_constructions_kernel>>();
  std::cout << (failures ? "FAILED" : "OK") << "\n";
  return failures ? 1 : 0;
}
