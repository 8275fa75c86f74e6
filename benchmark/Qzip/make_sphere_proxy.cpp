// Builds a stand-in for the peers' test sphere of issue 4 (a 4,672-quad sphere with 275 irregular
// vertices, not distributed): a cube sphere of 6 n x n quads per side whose singularities, beyond the
// cube's eight corners, are planted in quadruples by vertex splits and then scattered over the sphere by
// random Q-zips that keep their number and the number of quads within 1% (the others are undone; a
// collapsing motion when there are more quads than after the planting, a splitting one otherwise),
// followed by a tangential smoothing on the sphere.
//
// usage: make_sphere_proxy OUT [--n N] [--clusters C] [--scatter Q] [--seed S]
//   --n N         quads along a cube edge (default 28: 4,704 quads before the edits)
//   --clusters C  vertex splits, each planting two v3 and two v5 (default 67: 8 + 268 = 276 singularities)
//   --scatter Q   random Q-zips that move the singularities apart (default 4000)
//   --seed S      seed of the random choices (default 0)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/singularities.h>

#include "qzip_test_utils.h" // singular_vertices(), singularities_within()

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

namespace Q = CGAL::Qzip;

namespace {

Point on_sphere(const Vector& v) { return CGAL::ORIGIN + v / std::sqrt(v.squared_length()); }

// the cube [-1, 1]^3 with n x n quads per side, each lattice coordinate mapped by tan() (equal angles),
// projected onto the unit sphere, faces oriented outwards
void make_cube_sphere(Mesh& m, int n)
{
  std::map<std::array<int, 3>, vertex_descriptor> lattice;
  const double quarter = std::atan(1.);
  auto vertex_at = [&](const std::array<int, 3>& ijk) {
    auto it = lattice.find(ijk);
    if(it != lattice.end()) return it->second;
    double c[3];
    for(int a = 0; a < 3; ++a) c[a] = std::tan((2. * ijk[a] / n - 1.) * quarter);
    const vertex_descriptor v = m.add_vertex(on_sphere(Vector(c[0], c[1], c[2])));
    lattice.emplace(ijk, v);
    return v;
  };
  for(int a = 0; a < 3; ++a)
    for(int side = 0; side <= n; side += n)
      for(int u = 0; u < n; ++u)
        for(int w = 0; w < n; ++w)
        {
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          std::array<vertex_descriptor, 4> q;
          const int du[4] = { 0, 1, 1, 0 }, dw[4] = { 0, 0, 1, 1 };
          for(int k = 0; k < 4; ++k)
          {
            std::array<int, 3> ijk;
            ijk[a] = side; ijk[b] = u + du[k]; ijk[c] = w + dw[k];
            q[std::size_t(side == n ? k : 3 - k)] = vertex_at(ijk);
          }
          m.add_face(q[0], q[1], q[2], q[3]);
        }
}

std::size_t number_of_singularities(const Mesh& m)
{
  std::size_t count = 0;
  for(vertex_descriptor v : vertices(m)) if(Q::vertex_defect(v, m) != 0) ++count;
  return count;
}

// moves every vertex `iterations` times halfway to the centroid of its neighbours, back onto the sphere
void smooth_on_sphere(Mesh& m, int iterations)
{
  for(int it = 0; it < iterations; ++it)
  {
    std::vector<Point> next;
    next.reserve(num_vertices(m));
    for(vertex_descriptor v : vertices(m))
    {
      Vector sum(0, 0, 0);
      int k = 0;
      for(halfedge_descriptor h : halfedges_around_target(v, m)) { sum = sum + (m.point(source(h, m)) - CGAL::ORIGIN); ++k; }
      next.push_back(on_sphere((m.point(v) - CGAL::ORIGIN) * 0.5 + sum * (0.5 / k)));
    }
    std::size_t i = 0;
    for(vertex_descriptor v : vertices(m)) m.point(v) = next[i++];
  }
}

bool parse_count(const char* s, long& out)
{
  char* end = nullptr;
  out = std::strtol(s, &end, 10);
  return end != s && *end == '\0' && out >= 0;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2 || argv[1][0] == '-')
  { std::cerr << "usage: make_sphere_proxy OUT [--n N] [--clusters C] [--scatter Q] [--seed S]" << std::endl; return EXIT_FAILURE; }
  long n = 28, clusters = 67, scatter = 4000, seed = 0;
  for(int i = 2; i + 1 < argc; i += 2)
  {
    const std::string o = argv[i];
    long* target = o == "--n" ? &n : o == "--clusters" ? &clusters : o == "--scatter" ? &scatter : o == "--seed" ? &seed : nullptr;
    if(target == nullptr || !parse_count(argv[i + 1], *target) || n < 4)
    { std::cerr << "error: bad option " << o << " " << argv[i + 1] << std::endl; return EXIT_FAILURE; }
  }
  if(argc % 2 != 0) { std::cerr << "error: option " << argv[argc - 1] << " needs a value" << std::endl; return EXIT_FAILURE; }

  Mesh m;
  make_cube_sphere(m, int(n));
  CGAL::Random rng(static_cast<unsigned int>(seed));

  // plant the quadruples: split a regular vertex whose 3-ring is regular into two v3 (the vertex and the
  // new one), their two common neighbours becoming v5
  std::vector<vertex_descriptor> all(vertices(m).begin(), vertices(m).end());
  for(long planted = 0, tries = 0; planted < clusters && tries < 100 * clusters; ++tries)
  {
    const vertex_descriptor v = all[std::size_t(rng.get_int(0, int(all.size())))];
    if(Q::vertex_defect(v, m) != 0 || !qzip_test::singularities_within(m, v, 1, 3).empty()) continue;
    const halfedge_descriptor h1 = halfedge(v, m);
    const halfedge_descriptor h2 = prev(opposite(prev(opposite(h1, m), m), m), m);
    if(!Q::can_split_vertex_into_quad(h1, h2, m)) continue;
    const halfedge_descriptor on_quad = Q::split_vertex_into_quad(h1, h2, m);
    const vertex_descriptor c = target(next(next(on_quad, m), m), m);
    Vector sum(0, 0, 0);
    for(halfedge_descriptor h : halfedges_around_target(c, m)) sum = sum + (m.point(source(h, m)) - CGAL::ORIGIN);
    m.point(c) = on_sphere(sum);
    ++planted;
  }

  // scatter them: random Q-zips between singularities at most 8 edges apart, undone when they cancel
  // singularities or change the number of quads by more than 1%
  const std::size_t count = number_of_singularities(m);
  const long planted_faces = long(m.number_of_faces());
  long kept = 0;
  for(long tries = 0; kept < scatter && tries < 20 * scatter; ++tries)
  {
    const std::vector<vertex_descriptor> singular = qzip_test::singular_vertices(m);
    const vertex_descriptor s = singular[std::size_t(rng.get_int(0, int(singular.size())))];
    const std::vector<vertex_descriptor> near = qzip_test::singularities_within(m, s, 1, 8);
    if(near.empty()) continue;
    const vertex_descriptor t = near[std::size_t(rng.get_int(0, int(near.size())))];
    const auto path = Q::shortest_surgery_path(m, s, t);
    if(path.empty() || path.size() > 12) continue;
    // a collapsing motion (RC, LC) when there are more quads than after the planting, else a splitting one
    const bool collapse = long(m.number_of_faces()) > planted_faces, left = rng.get_bool();
    const Q::Strip_operation motion = collapse ? (left ? Q::Strip_operation::LEFT_COLLAPSE : Q::Strip_operation::RIGHT_COLLAPSE)
                                               : (left ? Q::Strip_operation::LEFT_SPLIT : Q::Strip_operation::RIGHT_SPLIT);
    const Q::Surgery_plan<Mesh> plan = Q::plan_qzip(m, path, motion);
    if(!plan.is_realizable()) continue;
    Q::Qzip_history<Mesh> history(m);
    if(!Q::execute_qzip(m, plan, history).is_done()) continue;
    if(number_of_singularities(m) != count || std::abs(long(m.number_of_faces()) - planted_faces) > planted_faces / 100)
    { Q::undo_qzip(history); continue; }
    ++kept;
  }
  m.collect_garbage();
  smooth_on_sphere(m, 200);

  const std::string out = argv[1], tmp = out + ".tmp.obj";
  if(!CGAL::IO::write_polygon_mesh(tmp, m, CGAL::parameters::stream_precision(17)) || std::rename(tmp.c_str(), out.c_str()) != 0)
  { std::remove(tmp.c_str()); std::cerr << "error: cannot write " << out << std::endl; return EXIT_FAILURE; }
  std::cout << out << ": " << m.number_of_faces() << " quads, " << number_of_singularities(m) << " singularities ("
            << kept << " scattering Q-zips)" << std::endl;
  return EXIT_SUCCESS;
}
