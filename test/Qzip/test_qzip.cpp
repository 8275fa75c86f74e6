// Tests of the Q-zip primitive: planning, execution, invariants, undo, homotopy invariance.
#include "qzip_test_utils.h"

#include <CGAL/Qzip/qzip.h>

#include <CGAL/Random.h>

using namespace qzip_test;
namespace Q = CGAL::Qzip;

template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> singular_vertices(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> out;
  for(auto v : vertices(m))
    if(!on_border(v, m) && valence(v, m) != 4) out.push_back(v);
  return out;
}

template <typename Mesh>
std::vector<int> singular_valences(const Mesh& m)
{
  std::vector<int> out;
  for(auto v : singular_vertices(m)) out.push_back(valence(v, m));
  std::sort(out.begin(), out.end());
  return out;
}

template <typename Mesh>
std::vector<Point> sorted_points(const Mesh& m)
{
  std::vector<Point> out;
  for(auto v : vertices(m)) out.push_back(get(CGAL::vertex_point, m, v));
  std::sort(out.begin(), out.end());
  return out;
}

/// plants the four singularities of a chain of k collapses along a row of a torus grid (see
/// QZIP_OPERATIONS.md, "Planting pairs"): p_0 (3), p_1 (5), p_k (5), r_k (3).
template <typename Mesh>
void plant_chain(Mesh& m, int nx, int ny, int row, int col, int k, bool along_rows)
{
  make_quad_torus(m, nx, ny);
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> vs(vertices(m).begin(), vertices(m).end());
  auto id = [&](int i, int j) { return vs[std::size_t(((j + ny) % ny) * nx + (i + nx) % nx)]; };
  for(int s = 0; s < k; ++s)
  {
    // quad with corners p_s, p_{s+1}, r_{s+1}, r_s; r_s merges into p_{s+1}
    vertex_descriptor p1 = along_rows ? id(col + s + 1, row) : id(col, row + s + 1);
    vertex_descriptor r0 = along_rows ? id(col + s, row - 1) : id(col - 1, row + s);
    // the halfedge of the quad whose target is p1 and whose opposite corner is r0
    bool done = false;
    for(auto h : CGAL::halfedges_around_target(halfedge(p1, m), m))
    {
      if(is_border(h, m)) continue;
      if(target(next(next(h, m), m), m) == r0 && Q::can_collapse_quad(h, m)) { Q::quad_collapse(h, m); done = true; break; }
    }
    assert(done);
  }
}

int main()
{
  Surface_mesh m;
  plant_chain(m, 24, 24, 10, 6, 6, true);
  auto sing = singular_vertices(m);
  std::cout << "planted " << sing.size() << " singularities:";
  for(auto v : sing) std::cout << " " << v << "(" << valence(v, m) << ")";
  std::cout << std::endl;
  int ok = 0, refused = 0, failed = 0;
  for(std::size_t i = 0; i < sing.size(); ++i)
    for(std::size_t j = 0; j < sing.size(); ++j)
    {
      if(i == j) continue;
      for(int mo = 0; mo < 4; ++mo)
      {
        Surface_mesh w; auto v2v = copy_mesh_with_map(m, w);
        auto s = v2v[sing[i]];
        auto t = v2v[sing[j]];
        auto path = Q::shortest_surgery_path(w, s, t);
        auto plan = Q::plan_qzip(w, path, Q::Strip_operation(mo));
        if(!plan.is_realizable()) { ++refused; std::cout << "  refused " << i << "->" << j << " " << Q::short_name(Q::Strip_operation(mo)) << ": " << Q::describe(plan.status) << std::endl; continue; }
        auto r = Q::execute_qzip(w, plan);
        if(!r.is_done()) { ++failed; std::cout << "  FAILED " << i << "->" << j << " " << Q::short_name(Q::Strip_operation(mo)) << " path " << path.size() << std::endl; assert(are_isomorphic(w, m)); continue; }
        assert(CGAL::is_valid_polygon_mesh(w));
        assert(all_faces_have_degree(w, 4));
        assert(euler_characteristic(w) == euler_characteristic(m));
        auto a = singular_valences(w), b = singular_valences(m);
        assert(std::includes(b.begin(), b.end(), a.begin(), a.end()));
        if(a != b) std::cout << "  cancelled " << (b.size() - a.size()) << " singularities " << i << "->" << j << " " << Q::short_name(Q::Strip_operation(mo)) << std::endl;
        ++ok;
      }
    }
  std::cout << ok << " ok, " << refused << " refused, " << failed << " failed" << std::endl;
  return EXIT_SUCCESS;
}
