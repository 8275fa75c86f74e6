// Shared helpers of the Qzip tests: mesh builders, invariant checks, isomorphism of oriented meshes.
#ifndef QZIP_TEST_UTILS_H
#define QZIP_TEST_UTILS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/singularities.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <sys/stat.h>
#include <unordered_map>
#include <vector>

namespace qzip_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

#ifndef QZIP_SHARED_DATA_DIR
#define QZIP_SHARED_DATA_DIR "../../../shared/data/quad"
#endif

inline bool file_exists(const std::string& p)
{
  struct stat st;
  return ::stat(p.c_str(), &st) == 0;
}

/// the shared corpus folder, or "" (with a clear message) when it is absent.
inline std::string shared_corpus_dir(const char* who)
{
  const std::string dir = QZIP_SHARED_DATA_DIR;
  if(file_exists(dir + "/SOURCES.md")) return dir;
  std::cout << "skipped (" << who << "): shared corpus not found at " << dir << std::endl;
  return std::string();
}

inline std::vector<std::string> shared_corpus_files()
{
  return { "beast_quaddominant.obj", "blub_quadrangulated.obj", "gen_instantmeshes_bunny_boundary.obj",
           "gen_instantmeshes_rocker_arm.obj", "gen_instantmeshes_turbine_quaddominant.obj",
           "gen_quadriflow_anchor_sharp.obj", "gen_quadriflow_armadillo_107k.ply", "libigl_halftunnel.off",
           "libigl_horse_quad.obj", "noisy_sphere_triquad.obj", "pmp_fandisk_quads.off",
           "polylap_amo_quad.off", "polylap_loki.obj", "polylap_suzanne_half.obj",
           "quadmixer_animal_horse.obj", "quadriflow_gargoyle.obj", "quadwild_joint.obj",
           "quadwild_mnf07HeadFem.obj", "spot_quadrangulated.obj", "trimesh_quadknot.obj",
           "trimesh_target.obj" };
}

template <typename Mesh>
bool read_mesh(const std::string& path, Mesh& m)
{
  clear(m);
  return CGAL::IO::read_polygon_mesh(path, m) && CGAL::is_valid_polygon_mesh(m);
}

/// an nx x ny grid of unit quads in the plane z = 0 (open, with a boundary).
template <typename Mesh>
void make_quad_grid(Mesh& m, int nx, int ny)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  clear(m);
  auto vpm = get(CGAL::vertex_point, m);
  std::vector<vertex_descriptor> vs;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
    {
      vertex_descriptor v = add_vertex(m);
      put(vpm, v, Point(i, j, 0));
      vs.push_back(v);
    }
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      const int a = j * (nx + 1) + i;
      std::vector<vertex_descriptor> q = { vs[a], vs[a + 1], vs[a + nx + 2], vs[a + nx + 1] };
      CGAL::Euler::add_face(q, m);
    }
}

/// an nx x ny quad grid on a torus (closed, genus 1, all vertices of valence 4).
template <typename Mesh>
void make_quad_torus(Mesh& m, int nx, int ny, double R = 3., double r = 1.)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  clear(m);
  auto vpm = get(CGAL::vertex_point, m);
  std::vector<vertex_descriptor> vs;
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      const double u = 2 * CGAL_PI * i / nx, w = 2 * CGAL_PI * j / ny;
      vertex_descriptor v = add_vertex(m);
      put(vpm, v, Point((R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w)));
      vs.push_back(v);
    }
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      auto id = [&](int x, int y) { return vs[((y + ny) % ny) * nx + (x + nx) % nx]; };
      std::vector<vertex_descriptor> q = { id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) };
      CGAL::Euler::add_face(q, m);
    }
}

// the closed surface of a 7 x 3 x 1 plate of voxels with three 1 x 1 holes: genus 3, all quads (the paper's
// robustness test, Fig. 17, starts from it: triangulated, then refined by Catmull-Clark)
template <typename Mesh>
void make_genus3_voxel_plate(Mesh& m)
{
  const int X = 7, Y = 3;
  auto solid = [&](int x, int y) { return x >= 0 && y >= 0 && x < X && y < Y && !(y == 1 && (x == 1 || x == 3 || x == 5)); };
  std::vector<Point> points;
  std::map<std::array<int, 3>, std::size_t> ids;
  std::vector<std::vector<std::size_t> > quads;
  auto id = [&](int x, int y, int z)
  {
    const std::array<int, 3> k = {{ x, y, z }};
    auto it = ids.find(k);
    if(it != ids.end()) return it->second;
    points.push_back(Point(x, y, z));
    return ids[k] = points.size() - 1;
  };
  for(int x = 0; x < X; ++x)
    for(int y = 0; y < Y; ++y)
    {
      if(!solid(x, y)) continue;
      if(!solid(x + 1, y)) quads.push_back({ id(x + 1, y, 0), id(x + 1, y + 1, 0), id(x + 1, y + 1, 1), id(x + 1, y, 1) });
      if(!solid(x - 1, y)) quads.push_back({ id(x, y, 0), id(x, y, 1), id(x, y + 1, 1), id(x, y + 1, 0) });
      if(!solid(x, y + 1)) quads.push_back({ id(x, y + 1, 0), id(x, y + 1, 1), id(x + 1, y + 1, 1), id(x + 1, y + 1, 0) });
      if(!solid(x, y - 1)) quads.push_back({ id(x, y, 0), id(x + 1, y, 0), id(x + 1, y, 1), id(x, y, 1) });
      quads.push_back({ id(x, y, 1), id(x + 1, y, 1), id(x + 1, y + 1, 1), id(x, y + 1, 1) });
      quads.push_back({ id(x, y, 0), id(x, y + 1, 0), id(x + 1, y + 1, 0), id(x + 1, y, 0) });
    }
  clear(m);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, quads, m);
}

template <typename Mesh>
long euler_characteristic(const Mesh& m)
{
  return long(vertices(m).size()) - long(edges(m).size()) + long(faces(m).size());
}

template <typename Mesh>
int valence(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m)
{
  int n = 0;
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) { (void)h; ++n; }
  return n;
}

template <typename Mesh>
bool on_border(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m)
{
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
    if(is_border(h, m)) return true;
  return false;
}

/// valence histograms, interior and border, as a single map (border valences are stored as -valence).
// every inner vertex of the planar mesh `m` at the centroid of its neighbours (300 rounds; the border is fixed)
template <typename Mesh>
void relax_inside(Mesh& m)
{
  for(int iteration = 0; iteration < 300; ++iteration)
    for(auto v : vertices(m))
    {
      if(on_border(v, m)) continue;
      double x = 0, y = 0, n = 0;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
      {
        const Point& p = get(CGAL::vertex_point, m, source(h, m));
        x += p.x(); y += p.y(); n += 1;
      }
      put(get(CGAL::vertex_point, m), v, Point(x / n, y / n, 0));
    }
}

template <typename Mesh>
std::map<int, int> valence_histogram(const Mesh& m)
{
  std::map<int, int> hist;
  for(auto v : vertices(m))
    ++hist[on_border(v, m) ? -valence(v, m) : valence(v, m)];
  return hist;
}

/// the interior singular vertices (valence other than 4)
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> singular_vertices(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> out;
  for(auto v : vertices(m))
    if(!on_border(v, m) && valence(v, m) != 4) out.push_back(v);
  return out;
}

/// the interior singular vertices (valence other than 4) at between `lo` and `hi` edges from `s`, in
/// breadth-first order.
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
singularities_within(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor s, int lo, int hi)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::map<vertex_descriptor, int> dist;
  std::vector<vertex_descriptor> queue(1, s), out;
  dist[s] = 0;
  for(std::size_t i = 0; i < queue.size(); ++i)
  {
    const vertex_descriptor v = queue[i];
    const int d = dist[v];
    if(v != s && d >= lo && !on_border(v, m) && valence(v, m) != 4) out.push_back(v);
    if(d >= hi) continue;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
      if(dist.emplace(source(h, m), d + 1).second) queue.push_back(source(h, m));
  }
  return out;
}

template <typename Mesh>
bool all_faces_have_degree(const Mesh& m, std::size_t d)
{
  for(auto f : faces(m))
    if(CGAL::halfedges_around_face(halfedge(f, m), m).size() != d) return false;
  return true;
}

/// A canonical code of the oriented combinatorial map seen from halfedge `start`: a breadth-first
/// numbering over next/opposite, and for each numbered halfedge the numbers of its next and opposite and
/// its border flag. Two meshes are isomorphic (orientation-preserving, all incidences) iff the code from
/// some start of one equals the code from a fixed start of the other. With `reference`, the walk stops at
/// the first difference and returns a truncated code.
template <typename Mesh>
std::vector<long> canonical_code(const Mesh& m, typename boost::graph_traits<Mesh>::halfedge_descriptor start,
                                 const std::vector<long>* reference = nullptr)
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  std::unordered_map<halfedge_descriptor, long, boost::hash<halfedge_descriptor> > id;
  std::vector<halfedge_descriptor> order;
  id.reserve(halfedges(m).size() * 2);
  id[start] = 0; order.push_back(start);
  std::vector<long> code;
  code.reserve(halfedges(m).size() * 3);
  auto push = [&](long x) { code.push_back(x); return reference == nullptr || (*reference)[code.size() - 1] == x; };
  for(std::size_t i = 0; i < order.size(); ++i)
  {
    const halfedge_descriptor h = order[i];
    for(halfedge_descriptor n : { next(h, m), opposite(h, m) })
    {
      auto it = id.find(n);
      if(it == id.end())
      {
        it = id.emplace(n, long(order.size())).first;
        order.push_back(n);
      }
      if(!push(it->second)) return code;
    }
    if(!push(is_border(h, m) ? 1 : 0)) return code;
  }
  return code;
}

/// a cheap local signature of a halfedge: valences of its source and target, border flag, face degree.
template <typename Mesh>
long halfedge_signature(typename boost::graph_traits<Mesh>::halfedge_descriptor h, const Mesh& m)
{
  const long fdeg = is_border(h, m) ? 0 : long(CGAL::halfedges_around_face(h, m).size());
  return ((valence(source(h, m), m) * 64 + valence(target(h, m), m)) * 64 + fdeg) * 2 + (is_border(h, m) ? 1 : 0);
}

/// checks that `a` and `b` are isomorphic as oriented polygon meshes (connectivity only).
template <typename MeshA, typename MeshB>
bool are_isomorphic(const MeshA& a, const MeshB& b)
{
  if(vertices(a).size() != vertices(b).size() || edges(a).size() != edges(b).size() ||
     faces(a).size() != faces(b).size())
    return false;
  if(valence_histogram(a) != valence_histogram(b)) return false;
  if(halfedges(a).size() == 0) return true;
  // choose the rarest signature to limit the candidate starts in b
  std::map<long, int> count_a, count_b;
  for(auto h : halfedges(a)) ++count_a[halfedge_signature(h, a)];
  for(auto h : halfedges(b)) ++count_b[halfedge_signature(h, b)];
  if(count_a != count_b) return false;
  long best = count_a.begin()->first;
  for(const auto& kv : count_a) if(kv.second < count_a[best]) best = kv.first;
  typename boost::graph_traits<MeshA>::halfedge_descriptor ha = *halfedges(a).begin();
  for(auto h : halfedges(a)) if(halfedge_signature(h, a) == best) { ha = h; break; }
  const std::vector<long> code_a = canonical_code(a, ha);
  for(auto hb : halfedges(b))
    if(halfedge_signature(hb, b) == best && canonical_code(b, hb, &code_a) == code_a)
      return true;
  return false;
}

template <typename Mesh>
void copy_mesh(const Mesh& src, Mesh& dst)
{
  clear(dst);
  CGAL::copy_face_graph(src, dst);
}

/// copies `src` into `dst` and returns the map from the vertices of `src` to those of `dst`.
template <typename Mesh>
std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::graph_traits<Mesh>::vertex_descriptor>
copy_mesh_with_map(const Mesh& src, Mesh& dst)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::map<vertex_descriptor, vertex_descriptor> v2v;
  clear(dst);
  CGAL::copy_face_graph(src, dst, CGAL::parameters::vertex_to_vertex_map(boost::make_assoc_property_map(v2v)));
  return v2v;
}


/// A path from the interior vertex `s` that runs along the border: the shortest path through regular
/// interior vertices to the nearest border vertex, then `steps` edges along the border (with the mesh on
/// the left of the path, or on its right), then the shortest path through regular interior vertices to
/// the nearest interior singular vertex (valence other than 4) other than `s`. Each search goes at most
/// `radius` edges. Empty when there is no such simple path.
/// With `target` a border vertex, the walk along the border stops there instead (at most `steps` edges).
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
path_along_border(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor s, int steps,
                  bool mesh_on_left, int radius,
                  typename boost::graph_traits<Mesh>::vertex_descriptor target = boost::graph_traits<Mesh>::null_vertex())
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> path;
  // breadth-first from `from` through regular interior vertices not in `path`, to the first vertex
  // accepted by `is_end`; appends the vertices after `from`
  auto extend = [&](vertex_descriptor from, auto is_end)
  {
    std::map<vertex_descriptor, vertex_descriptor> pred;
    std::map<vertex_descriptor, int> dist;
    std::vector<vertex_descriptor> queue(1, from);
    pred[from] = from; dist[from] = 0;
    for(std::size_t i = 0; i < queue.size(); ++i)
    {
      const vertex_descriptor v = queue[i];
      if(v != from && is_end(v))
      {
        std::vector<vertex_descriptor> piece;
        for(vertex_descriptor x = v; x != from; x = pred[x]) piece.push_back(x);
        path.insert(path.end(), piece.rbegin(), piece.rend());
        return true;
      }
      if(dist[v] == radius || (v != from && (on_border(v, m) || valence(v, m) != 4))) continue;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
      {
        const vertex_descriptor u = source(h, m);
        if(pred.count(u) || std::find(path.begin(), path.end(), u) != path.end()) continue;
        pred[u] = v; dist[u] = dist[v] + 1;
        queue.push_back(u);
      }
    }
    return false;
  };
  path.push_back(s);
  if(!extend(s, [&](vertex_descriptor v) { return on_border(v, m); })) return {};
  for(int k = 0; k < steps; ++k)
  {
    // with the mesh on the left, the path edge v->w has the border on its right: w->v is a border halfedge
    const vertex_descriptor v = path.back();
    vertex_descriptor w = boost::graph_traits<Mesh>::null_vertex();
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
      if(is_border(mesh_on_left ? h : opposite(h, m), m)) w = source(h, m);
    if(w == boost::graph_traits<Mesh>::null_vertex() || std::find(path.begin(), path.end(), w) != path.end()) return {};
    path.push_back(w);
    if(w == target) return path;
  }
  if(target != boost::graph_traits<Mesh>::null_vertex()) return {};
  if(!extend(path.back(), [&](vertex_descriptor v) { return v != s && !on_border(v, m) && valence(v, m) != 4; }))
    return {};
  return path;
}

/// The invariants of a Q-zip, measured on the whole mesh before it and checked after it, independently
/// of the executor's own checks: a valid mesh, the same Euler characteristic, quads still quads (faces
/// change by splits - collapses), and no new singularity: the singularity codes after (an interior
/// vertex: its valence, none if 4; a border vertex: 100 + its defect, none if 0) form a sub-multiset of
/// those before. Border defects are judged against the number of faces each border vertex should have
/// from the geometry before (the chain places its vertices roughly); a vertex new on the border takes
/// the number of the border vertex of before nearest to it.
template <typename Mesh>
class Qzip_invariants
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  long chi;
  std::size_t faces = 0, quads = 0;
  std::map<vertex_descriptor, int> expected_by_vertex;
  std::vector<std::pair<Point, int> > expected_by_position;
  std::vector<int> codes;

  static int faces_around(vertex_descriptor v, const Mesh& m)
  {
    int n = 0;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(!is_border(h, m)) ++n;
    return n;
  }
  static std::size_t number_of_quads(const Mesh& m)
  {
    std::size_t n = 0;
    for(auto f : CGAL::faces(m)) if(CGAL::halfedges_around_face(halfedge(f, m), m).size() == 4) ++n;
    return n;
  }
  int expected_faces(vertex_descriptor v, const Mesh& m) const
  {
    const auto it = expected_by_vertex.find(v);
    if(it != expected_by_vertex.end()) return it->second;
    const Point& p = get(CGAL::vertex_point, m, v);
    const auto nearest = std::min_element(expected_by_position.begin(), expected_by_position.end(),
                                          [&p](const auto& a, const auto& b)
                                          { return CGAL::squared_distance(a.first, p) < CGAL::squared_distance(b.first, p); });
    return nearest->second;
  }

public:
  explicit Qzip_invariants(const Mesh& m)
    : chi(euler_characteristic(m)), faces(CGAL::faces(m).size()), quads(number_of_quads(m))
  {
    for(vertex_descriptor v : vertices(m))
      if(on_border(v, m))
      {
        expected_by_vertex[v] = faces_around(v, m) - CGAL::Qzip::vertex_defect(v, m);
        expected_by_position.emplace_back(get(CGAL::vertex_point, m, v), expected_by_vertex[v]);
      }
    codes = singularity_codes(m);
  }

  /// the singularity code of `v`: 0 if regular, its valence inside, 100 + its defect on the border,
  /// judged against the face counts of before
  int singularity_code(vertex_descriptor v, const Mesh& m) const
  {
    if(!on_border(v, m)) return valence(v, m) == 4 ? 0 : valence(v, m);
    const int d = faces_around(v, m) - expected_faces(v, m);
    return d == 0 ? 0 : 100 + d;
  }

  /// the sorted singularity codes of `m`
  std::vector<int> singularity_codes(const Mesh& m) const
  {
    std::vector<int> out;
    for(vertex_descriptor v : vertices(m)) if(const int c = singularity_code(v, m)) out.push_back(c);
    std::sort(out.begin(), out.end());
    return out;
  }

  /// asserts the invariants after a done Q-zip with `splits` splits and `collapses` collapses; returns
  /// whether singularities were cancelled
  bool check_after(const Mesh& m, std::size_t splits, std::size_t collapses) const
  {
    assert(CGAL::is_valid_polygon_mesh(m));
    assert(euler_characteristic(m) == chi);
    const std::size_t faces_after = CGAL::faces(m).size();
    assert(faces_after - faces == number_of_quads(m) - quads);
    assert(long(faces_after) - long(faces) == long(splits) - long(collapses));
    const std::vector<int> after = singularity_codes(m);
    assert(std::includes(codes.begin(), codes.end(), after.begin(), after.end()));
    return after != codes;
  }
};

// ---------------------------------------------------------------------------------------------
// Homotopic surgery paths (test_qzip's homotopy test on real meshes, stress_qzip --homotopy)

/// a path from `a` to `b` with the fewest edges, through interior vertices not in `forbidden` (empty if none)
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
bfs_path(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor a,
         typename boost::graph_traits<Mesh>::vertex_descriptor b,
         const std::set<typename boost::graph_traits<Mesh>::vertex_descriptor>& forbidden)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::map<vertex_descriptor, vertex_descriptor> pred;
  std::deque<vertex_descriptor> queue(1, a);
  pred[a] = a;
  while(!queue.empty())
  {
    const vertex_descriptor v = queue.front(); queue.pop_front();
    if(v == b) break;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
    {
      const vertex_descriptor u = source(h, m);
      if(pred.count(u) || forbidden.count(u) || on_border(u, m)) continue;
      pred[u] = v;
      queue.push_back(u);
    }
  }
  std::vector<vertex_descriptor> path;
  if(!pred.count(b)) return path;
  for(vertex_descriptor v = b; v != a; v = pred[v]) path.push_back(v);
  path.push_back(a);
  std::reverse(path.begin(), path.end());
  return path;
}

/// an interior vertex of valence 4 whose faces are all quads: a path may sweep over it
template <typename Mesh>
bool is_regular_inside(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m)
{
  if(on_border(v, m) || valence(v, m) != 4) return false;
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
    if(degree(face(h, m), m) != 4) return false;
  return true;
}

/// whether every vertex of the faces around `v` is `a`, `b` or an interior vertex of valence 4 (and `v` is
/// not on the border)
template <typename Mesh>
bool only_regular_faces_around(typename boost::graph_traits<Mesh>::vertex_descriptor v,
                               typename boost::graph_traits<Mesh>::vertex_descriptor a,
                               typename boost::graph_traits<Mesh>::vertex_descriptor b, const Mesh& m)
{
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
  {
    if(is_border(h, m)) return false;
    for(auto g : CGAL::halfedges_around_face(h, m))
    {
      const auto w = target(g, m);
      if(w != a && w != b && (on_border(w, m) || valence(w, m) != 4)) return false;
    }
  }
  return true;
}

/// One elementary homotopy of the vertex path `path` over a single quad whose corners off the path are
/// regular (so that no singularity enters, leaves or crosses the path): either a corner cut (three
/// consecutive path vertices a, b, c are corners of one quad a, b, c, d: b, regular, is replaced by d) or an
/// edge push (a path edge a -> b is replaced by the three other sides a -> d -> c -> b of a quad on one of its
/// sides). The first edge of the path is kept (the motion is a tag relative to it). With `keep_away`, the
/// faces around the corners of the swept quad hold no singularity but the ends of the path either (the
/// chain operates on the faces around the path, and a singularity there takes part in it). Returns false
/// when the random try found no such move.
template <typename Mesh>
bool sweep_one_quad(std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& path, const Mesh& m,
                    CGAL::Random& rng, bool keep_away)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  const std::set<vertex_descriptor> on_path(path.begin(), path.end());
  auto free_regular = [&](vertex_descriptor v) { return on_path.count(v) == 0 && is_regular_inside(v, m); };
  auto away = [&](std::initializer_list<vertex_descriptor> corners)
  {
    if(!keep_away) return true;
    for(vertex_descriptor v : corners)
      if(!only_regular_faces_around(v, path.front(), path.back(), m)) return false;
    return true;
  };
  for(int attempt = 0; attempt < 20; ++attempt)
  {
    const std::size_t i = std::size_t(rng.get_int(1, int(path.size()) - 1)); // edge path[i] -> path[i+1]
    const std::pair<halfedge_descriptor, bool> ab = halfedge(path[i], path[i + 1], m);
    if(!ab.second) continue;
    const bool left = rng.get_bool();
    if(rng.get_bool() && i >= 2) // corner cut at b = path[i]: the quad holds path[i-1] -> path[i] -> path[i+1]
    {
      const halfedge_descriptor in = halfedge(path[i - 1], path[i], m).first;
      halfedge_descriptor corner;
      if(!is_border(in, m) && next(in, m) == ab.first) corner = next(ab.first, m);
      else if(!is_border(opposite(ab.first, m), m) && next(opposite(ab.first, m), m) == opposite(in, m))
        corner = prev(opposite(ab.first, m), m);
      else continue;
      if(is_border(corner, m) || degree(face(corner, m), m) != 4) continue;
      const vertex_descriptor d = target(corner, m);
      if(!is_regular_inside(path[i], m) || !free_regular(d) || !away({ path[i - 1], path[i], path[i + 1], d })) continue;
      path[i] = d;
      return true;
    }
    const halfedge_descriptor h = left ? ab.first : opposite(ab.first, m); // the quad beside the edge
    if(is_border(h, m) || degree(face(h, m), m) != 4) continue;
    // around the quad of h: h goes a -> b (left) or b -> a (right); c after b and d after c, going on
    const vertex_descriptor x = target(next(h, m), m), y = target(next(next(h, m), m), m);
    if(!free_regular(x) || !free_regular(y) || !away({ path[i], path[i + 1], x, y })) continue;
    // left: a -> b -> x -> y -> a, so a -> y -> x -> b; right: b -> a -> x -> y -> b, so a -> x -> y -> b
    const std::vector<vertex_descriptor> detour = left ? std::vector<vertex_descriptor>{ y, x }
                                                       : std::vector<vertex_descriptor>{ x, y };
    path.insert(path.begin() + std::ptrdiff_t(i) + 1, detour.begin(), detour.end());
    return true;
  }
  return false;
}

/// whether the path arrives at its last vertex by a U-turn around one quad: its last four vertices are the
/// corners of one face
template <typename Mesh>
bool ends_with_u_turn(const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& path, const Mesh& m)
{
  const std::size_t n = path.size();
  if(n < 4) return false;
  const auto xt = halfedge(path[n - 4], path[n - 1], m);
  if(!xt.second) return false;
  for(auto h : { xt.first, opposite(xt.first, m) })
  {
    if(is_border(h, m) || degree(face(h, m), m) != 4) continue;
    const auto c = target(next(h, m), m), d = target(next(next(h, m), m), m);
    if((c == path[n - 2] && d == path[n - 3]) || (c == path[n - 3] && d == path[n - 2])) return true;
  }
  return false;
}

/// what compare_homotopic_paths() counts: pairs of done Q-zips, all of them and those whose swept path
/// arrives at a valence-5 target by a U-turn around one quad
struct Homotopy_counts
{
  std::size_t done = 0, refused = 0, rolled_back = 0;
  std::size_t isomorphic = 0, differing = 0, u_turn_isomorphic = 0, u_turn_differing = 0;

  Homotopy_counts& operator+=(const Homotopy_counts& o)
  {
    done += o.done; refused += o.refused; rolled_back += o.rolled_back;
    isomorphic += o.isomorphic; differing += o.differing;
    u_turn_isomorphic += o.u_turn_isomorphic; u_turn_differing += o.u_turn_differing;
    return *this;
  }
};

/// Homotopy invariance on the mesh `m`: for `pairs` random pairs of singularities 3 to 12 edges apart, a
/// shortest path avoiding the other singularities and a copy of it swept over one to six quads
/// (sweep_one_quad(), no singularity in the swept region), each motion is planned and executed on both
/// paths (on copies of `m`; `check_plan(copy, plan)` is called on each plan before), and where both are
/// done the results are compared. Each pair that is not isomorphic is printed.
template <typename Mesh, typename CheckPlan>
void compare_homotopic_paths(const Mesh& m, const std::string& name, std::size_t pairs, unsigned seed, bool keep_away,
                             Homotopy_counts& hc, const CheckPlan& check_plan)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  CGAL::Random rng(seed);
  const std::vector<vertex_descriptor> sing = singular_vertices(m);
  if(sing.size() < 2) return;
  for(std::size_t tried = 0, used = 0; used < pairs && tried < 20 * pairs; ++tried)
  {
    const vertex_descriptor s = sing[std::size_t(rng.get_int(0, int(sing.size())))];
    const std::vector<vertex_descriptor> near = singularities_within(m, s, 3, 12);
    if(near.empty()) continue;
    const vertex_descriptor t = near[std::size_t(rng.get_int(0, int(near.size())))];
    std::set<vertex_descriptor> others;
    for(auto x : sing) if(x != s && x != t) others.insert(x);
    const std::vector<vertex_descriptor> straight = bfs_path(m, s, t, others);
    if(straight.size() < 3) continue;
    std::vector<vertex_descriptor> swept = straight;
    const int sweeps = rng.get_int(1, 7);
    int applied = 0;
    for(int k = 0; k < sweeps; ++k) if(sweep_one_quad(swept, m, rng, keep_away)) ++applied;
    if(applied == 0) continue;
    ++used;
    const bool u_turn = valence(t, m) == 5 && ends_with_u_turn(swept, m);
    for(int mo = 0; mo < 4; ++mo)
    {
      Mesh results[2];
      bool done[2];
      std::string operations[2];
      const std::vector<vertex_descriptor>* paths[2] = { &straight, &swept };
      for(int a = 0; a < 2; ++a)
      {
        auto v2v = copy_mesh_with_map(m, results[a]);
        std::vector<vertex_descriptor> path;
        for(auto v : *paths[a]) path.push_back(v2v[v]);
        const auto plan = CGAL::Qzip::plan_qzip(results[a], path, CGAL::Qzip::Strip_operation(mo));
        check_plan(results[a], plan);
        done[a] = false;
        if(!plan.is_realizable()) { ++hc.refused; continue; }
        for(CGAL::Qzip::Strip_operation op : plan.operations) operations[a] += std::to_string(int(op));
        done[a] = CGAL::Qzip::execute_qzip(results[a], plan).is_done();
        ++(done[a] ? hc.done : hc.rolled_back);
      }
      if(!done[0] || !done[1]) continue;
      if(are_isomorphic(results[0], results[1]))
      {
        ++hc.isomorphic;
        if(u_turn) ++hc.u_turn_isomorphic;
        continue;
      }
      ++hc.differing;
      if(u_turn) ++hc.u_turn_differing;
      std::cout << "    " << name << ": homotopic paths of " << straight.size() - 1 << " and " << swept.size() - 1
                << " edges, motion " << mo << ", gave different meshes (operations " << operations[0] << " and "
                << operations[1] << ")" << std::endl;
    }
  }
}

} // namespace qzip_test

#endif // QZIP_TEST_UTILS_H
