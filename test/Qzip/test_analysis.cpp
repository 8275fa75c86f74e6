// Tests of the analysis headers: singularities.h (valence, defect, singularity type), quad_quality.h
// (scaled Jacobian) and mesh_report.h, on synthetic grids and on real meshes whose statistics come
// from an independent tool (the tables of test/Qzip/data/SOURCES.md and /work/shared/data/quad/SOURCES.md).
//
// Usage: test_analysis [DATA_DIR]   (DATA_DIR defaults to "data", the bundled meshes of test/Qzip)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/property_map.h>
#include <CGAL/Real_timer.h>

#include <CGAL/Qzip/Named_function_parameters.h> // first: CGAL::Qzip::internal_np must not hide CGAL's tags
#include <CGAL/Qzip/mesh_report.h>
#include <CGAL/Qzip/quad_quality.h>
#include <CGAL/Qzip/singularities.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point;
typedef CGAL::Surface_mesh<Point>                           Surface_mesh;
typedef CGAL::Polyhedron_3<K>                               Polyhedron;

namespace Q = CGAL::Qzip;

typedef std::vector<std::vector<std::size_t> > Polygons;

// ------------------------------------------------------------------------------------------------
// Building small meshes

// Adds the points used by `polygons` and the faces; returns the vertex of each point (null if unused).
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
build(Mesh& m, const std::vector<Point>& points, const Polygons& polygons)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> vs(points.size(), GT::null_vertex());
  auto vpm = get(CGAL::vertex_point, m);
  for(const auto& poly : polygons)
    for(std::size_t i : poly)
      if(vs[i] == GT::null_vertex())
      {
        vs[i] = add_vertex(m);
        put(vpm, vs[i], points[i]);
      }
  for(const auto& poly : polygons)
  {
    std::vector<vertex_descriptor> fvs;
    for(std::size_t i : poly) fvs.push_back(vs[i]);
    const auto f = CGAL::Euler::add_face(fvs, m);
    assert(f != GT::null_face());
    CGAL_USE(f);
  }
  assert(CGAL::is_valid_polygon_mesh(m));
  return vs;
}

// An n x m grid of unit quads in the plane z = 0; point (i, j) has index j * (n + 1) + i.
struct Grid
{
  std::size_t n, m;
  std::vector<Point> points;
  Polygons quads;

  Grid(std::size_t n_, std::size_t m_) : n(n_), m(m_)
  {
    for(std::size_t j = 0; j <= m; ++j)
      for(std::size_t i = 0; i <= n; ++i)
        points.push_back(Point(double(i), double(j), 0));
    for(std::size_t j = 0; j < m; ++j)
      for(std::size_t i = 0; i < n; ++i)
        quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  std::size_t id(std::size_t i, std::size_t j) const { return j * (n + 1) + i; }

  // the quads whose lower-left corner (i, j) satisfies `keep`
  template <typename Pred>
  Polygons quads_if(Pred keep) const
  {
    Polygons out;
    for(std::size_t j = 0; j < m; ++j)
      for(std::size_t i = 0; i < n; ++i)
        if(keep(i, j)) out.push_back(quads[j * n + i]);
    return out;
  }
};

template <typename Mesh>
typename boost::graph_traits<Mesh>::edge_descriptor
edge_between(typename boost::graph_traits<Mesh>::vertex_descriptor a,
             typename boost::graph_traits<Mesh>::vertex_descriptor b, const Mesh& m)
{
  const auto h = halfedge(a, b, m);
  assert(h.second);
  return edge(h.first, m);
}

template <typename Mesh>
std::vector<int> all_defects(const Mesh& m)
{
  std::vector<int> out;
  for(auto v : vertices(m)) out.push_back(Q::vertex_defect(v, m));
  return out;
}

template <typename Mesh>
bool all_zero_defects(const Mesh& m)
{
  for(auto v : vertices(m))
    if(Q::vertex_defect(v, m) != 0) return false;
  return true;
}

// ------------------------------------------------------------------------------------------------
// Synthetic tests

template <typename Mesh>
void test_open_grid()
{
  Grid g(4, 3);
  Mesh m;
  const auto vs = build(m, g.points, g.quads);

  assert(Q::vertex_valence(vs[g.id(0, 0)], m) == 2);
  assert(Q::vertex_valence(vs[g.id(2, 0)], m) == 3);
  assert(Q::vertex_valence(vs[g.id(2, 1)], m) == 4);
  for(auto v : vertices(m))
  {
    assert(Q::vertex_defect(v, m) == 0); // corners (1 face, 90 deg), straight border (2 faces, 180 deg), interior
    assert(Q::singularity_type(v, m) == Q::Singularity_type::REGULAR);
  }

  auto dmap = get(CGAL::dynamic_vertex_property_t<int>(), m);
  assert(Q::compute_vertex_defects(m, dmap) == 0);

  const Q::Mesh_report r = Q::compute_mesh_report(m);
  assert(r.number_of_vertices == 20 && r.number_of_edges == 31 && r.number_of_faces == 12);
  assert(r.faces_by_degree.size() == 1 && r.faces_by_degree.at(4) == 12);
  assert(r.euler_characteristic == 1 && r.genus == 0);
  assert(r.number_of_boundary_loops == 1 && r.number_of_border_edges == 14);
  assert(r.number_of_connected_components == 1 && r.number_of_isolated_vertices == 0);
  assert(r.interior_valence_histogram.size() == 1 && r.interior_valence_histogram.at(4) == 6);
  assert(r.boundary_valence_histogram.at(2) == 4 && r.boundary_valence_histogram.at(3) == 10);
  assert(r.total_absolute_defect == 0 && r.interior_defect_sum == 0 && r.boundary_defect_sum == 0);
  assert(!r.has_singularity_lower_bound && r.singularity_lower_bound == 0);
  assert(r.number_of_quads == 12 && r.number_of_inverted_quads == 0);
  assert(std::abs(r.min_scaled_jacobian - 1) < 1e-12 && std::abs(r.mean_scaled_jacobian - 1) < 1e-12);
  assert(!r.is_closed() && r.is_pure_quad());
}

// L-shaped domain: the concave corner has 3 faces over 270 degrees, which is regular.
template <typename Mesh>
void test_L_shape()
{
  Grid g(4, 4);
  Mesh m;
  const auto vs = build(m, g.points, g.quads_if([](std::size_t i, std::size_t j) { return i < 2 || j < 2; }));
  const auto corner = vs[g.id(2, 2)];
  assert(CGAL::is_border(corner, m) && Q::vertex_valence(corner, m) == 4);
  assert(all_zero_defects(m));
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  assert(r.number_of_faces == 12 && r.euler_characteristic == 1 && r.total_absolute_defect == 0);
}

// Boundary vertices that are not regular: one quad over 180 degrees (v3-like), two over 90 (v5-like).
template <typename Mesh>
void test_boundary_defects()
{
  {
    // (1,0) is a flat corner of a single quad
    Mesh m;
    const auto vs = build(m, {Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(1, 1, 0)}, {{0, 1, 2, 3}});
    assert(Q::vertex_defect(vs[1], m) == -1);
    assert(Q::singularity_type(vs[1], m) == Q::Singularity_type::VALENCE_3_LIKE);
    assert(Q::vertex_defect(vs[0], m) == 0 && Q::vertex_defect(vs[2], m) == 0 && Q::vertex_defect(vs[3], m) == 0);
    const Q::Mesh_report r = Q::compute_mesh_report(m);
    assert(r.number_of_boundary_negative_defects == 1 && r.number_of_boundary_positive_defects == 0);
    assert(r.boundary_defect_sum == -1 && r.total_absolute_defect == 1);
    assert(r.number_of_inverted_quads == 1 && r.min_scaled_jacobian == 0); // flat corner
  }
  {
    // two quads share the origin and fill 90 degrees together
    Mesh m;
    const auto vs = build(m, {Point(0, 0, 0), Point(2, 0, 0), Point(2, 1, 0), Point(1, 1, 0), Point(1, 2, 0), Point(0, 2, 0)},
                          {{0, 1, 2, 3}, {0, 3, 4, 5}});
    assert(Q::vertex_defect(vs[0], m) == 1);
    assert(Q::singularity_type(vs[0], m) == Q::Singularity_type::VALENCE_5_LIKE);
    const Q::Mesh_report r = Q::compute_mesh_report(m);
    // (1,1) sees the two quads over 270 degrees (ideal 3): -1
    assert(Q::vertex_defect(vs[3], m) == -1);
    assert(r.number_of_boundary_positive_defects == 1 && r.number_of_boundary_negative_defects == 1);
    assert(r.boundary_defect_sum == 0 && r.total_absolute_defect == 2);
  }
  {
    // triangles are faces too: three triangles on a straight border (ideal 2) give +1; a closed
    // fan of 6 triangles gives valence 6 - 4 = +2
    Mesh m;
    const auto vs = build(m, {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0), Point(-0.5, 1, 0), Point(-1, 0, 0)},
                          {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
    assert(Q::vertex_defect(vs[0], m) == 1);
    Mesh fan;
    std::vector<Point> pts(1, Point(0, 0, 0));
    Polygons tris;
    for(int i = 0; i < 6; ++i)
    {
      pts.push_back(Point(std::cos(i * CGAL_PI / 3), std::sin(i * CGAL_PI / 3), 0));
      tris.push_back({0, std::size_t(1 + i), std::size_t(1 + (i + 1) % 6)});
    }
    const auto fvs = build(fan, pts, tris);
    assert(Q::vertex_defect(fvs[0], fan) == 2);
    for(int i = 1; i <= 6; ++i)
      assert(Q::vertex_defect(fvs[i], fan) == 1); // 2 triangles over 120 degrees: ideal 1
  }
}

// A quad collapse planted in a grid (done on the polygon list: the corner (3,3) of quad (2,2)-(3,3)
// is merged into (2,2) and the quad is removed): (2,2) becomes valence 6, (3,2) and (2,3) valence 3.
template <typename Mesh>
void test_planted_collapse()
{
  Grid g(6, 6);
  const std::size_t a = g.id(2, 2), b = g.id(3, 2), c = g.id(3, 3), d = g.id(2, 3);
  Polygons polys;
  for(auto q : g.quads)
  {
    if(q[0] == a) continue; // the collapsed quad
    for(auto& i : q) if(i == c) i = a;
    polys.push_back(q);
  }
  Mesh m;
  const auto vs = build(m, g.points, polys);
  assert(Q::vertex_valence(vs[a], m) == 6 && Q::vertex_defect(vs[a], m) == 2);
  assert(Q::vertex_defect(vs[b], m) == -1 && Q::vertex_defect(vs[d], m) == -1);
  assert(Q::singularity_type(vs[a], m) == Q::Singularity_type::VALENCE_5_LIKE);
  assert(Q::singularity_type(vs[b], m) == Q::Singularity_type::VALENCE_3_LIKE);
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  assert(r.number_of_vertices == 48 && r.number_of_faces == 35 && r.euler_characteristic == 1);
  assert(r.number_of_interior_valence_3_like == 2 && r.number_of_interior_valence_5_like == 1);
  assert(r.interior_valence_histogram.at(6) == 1 && r.interior_valence_histogram.at(3) == 2);
  assert(r.interior_defect_sum == 0 && r.boundary_defect_sum == 0 && r.total_absolute_defect == 4);
  assert(r.number_of_boundary_negative_defects == 0 && r.number_of_boundary_positive_defects == 0);

  auto dmap = get(CGAL::dynamic_vertex_property_t<int>(), m);
  assert(Q::compute_vertex_defects(m, dmap) == 3);
  for(auto v : vertices(m))
    assert(get(dmap, v) == Q::vertex_defect(v, m));
}

// A disk of k quads around a center (k = 3: a v3, k = 5: a v5) whose border is regular everywhere:
// the border vertices between two quads are flat, the outer corners have angle 180 - 360/k (< 135).
template <typename Mesh>
void test_star(int k)
{
  std::vector<Point> pts(1, Point(0, 0, 0));
  Polygons quads;
  const double step = 2 * CGAL_PI / k;
  for(int i = 0; i < k; ++i)
  {
    pts.push_back(Point(std::cos(i * step), std::sin(i * step), 0));               // 1 + 2i: on a spoke
    const double r = 1 / std::cos(step / 2);
    pts.push_back(Point(r * std::cos((i + 0.5) * step), r * std::sin((i + 0.5) * step), 0)); // 2 + 2i: outer corner
  }
  for(int i = 0; i < k; ++i)
    quads.push_back({0, std::size_t(1 + 2 * i), std::size_t(2 + 2 * i), std::size_t(1 + 2 * ((i + 1) % k))});
  Mesh m;
  const auto vs = build(m, pts, quads);
  assert(Q::vertex_defect(vs[0], m) == k - 4);
  for(std::size_t i = 1; i < vs.size(); ++i)
    assert(Q::vertex_defect(vs[i], m) == 0);
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  assert(r.number_of_interior_valence_3_like == (k == 3 ? 1u : 0u));
  assert(r.number_of_interior_valence_5_like == (k == 5 ? 1u : 0u));
  assert(r.total_absolute_defect == 1 && r.number_of_inverted_quads == 0);
}

template <typename Mesh>
void test_cube()
{
  const std::vector<Point> pts = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                                  Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), Point(0, 1, 1)};
  const Polygons quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  Mesh m;
  build(m, pts, quads);
  for(auto v : vertices(m))
    assert(Q::vertex_defect(v, m) == -1);
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  assert(r.euler_characteristic == 2 && r.genus == 0 && r.is_closed() && r.number_of_boundary_loops == 0);
  assert(r.number_of_interior_valence_3_like == 8 && r.interior_defect_sum == -4 * r.euler_characteristic);
  assert(r.has_singularity_lower_bound && r.singularity_lower_bound == 8);
  assert(std::abs(r.min_scaled_jacobian - 1) < 1e-12 && r.number_of_inverted_quads == 0);
}

template <typename Mesh>
void test_torus(std::size_t n, std::size_t m)
{
  std::vector<Point> pts;
  Polygons quads;
  const double R = 3, rr = 1;
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      const double u = 2 * CGAL_PI * i / n, v = 2 * CGAL_PI * j / m;
      pts.push_back(Point((R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u), rr * std::sin(v)));
    }
  auto id = [&](std::size_t i, std::size_t j) { return (j % m) * n + (i % n); };
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i)
      quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  Mesh mesh;
  build(mesh, pts, quads);
  assert(all_zero_defects(mesh));
  const Q::Mesh_report r = Q::compute_mesh_report(mesh);
  assert(r.number_of_vertices == n * m && r.number_of_faces == n * m && r.number_of_edges == 2 * n * m);
  assert(r.euler_characteristic == 0 && r.genus == 1 && r.is_closed());
  assert(r.has_singularity_lower_bound && r.singularity_lower_bound == 0);
  assert(r.total_absolute_defect == 0 && r.interior_valence_histogram.at(4) == n * m);
  assert(r.number_of_inverted_quads == 0 && r.min_scaled_jacobian > 0.9);
}

// Constrained (feature) edges cut the fans into sectors like border edges.
template <typename Mesh>
void test_constrained_edges()
{
  typedef typename boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
  typedef std::set<edge_descriptor> Edge_set;

  Grid g(6, 4);
  // a constrained straight line y = 2 across the grid: every vertex stays regular
  {
    Mesh m;
    const auto vs = build(m, g.points, g.quads);
    Edge_set cs;
    for(std::size_t i = 0; i < 6; ++i)
      cs.insert(edge_between(vs[g.id(i, 2)], vs[g.id(i + 1, 2)], m));
    CGAL::Boolean_property_map<Edge_set> ecm(cs);
    for(auto v : vertices(m))
      assert(Q::vertex_defect(v, m, CGAL::parameters::edge_is_constrained_map(ecm)) == 0);
    auto dmap = get(CGAL::dynamic_vertex_property_t<int>(), m);
    assert(Q::compute_vertex_defects(m, dmap, CGAL::parameters::edge_is_constrained_map(ecm)) == 0);

    // an L-shaped curve (2,2)-(3,2)-(3,4): the corner (3,2) has a 90 degree sector with 1 quad and a
    // 270 degree one with 3 quads, both ideal; (2,2) is a curve end (one sector of 360 degrees).
    Edge_set ls;
    ls.insert(edge_between(vs[g.id(2, 2)], vs[g.id(3, 2)], m));
    ls.insert(edge_between(vs[g.id(3, 2)], vs[g.id(3, 3)], m));
    ls.insert(edge_between(vs[g.id(3, 3)], vs[g.id(3, 4)], m));
    CGAL::Boolean_property_map<Edge_set> lcm(ls);
    for(auto v : vertices(m))
      assert(Q::vertex_defect(v, m, CGAL::parameters::edge_is_constrained_map(lcm)) == 0);
    const Q::Mesh_report r = Q::compute_mesh_report(m, CGAL::parameters::edge_is_constrained_map(lcm));
    assert(r.total_absolute_defect == 0);
  }

  // with a bent line, a constrained grid equals its two halves cut along the line: at every vertex,
  // defect(whole, constrained) == defect(lower half) + defect(upper half)
  {
    Grid bent = g;
    bent.points[bent.id(3, 2)] = Point(3, 2.8, 0);  // lower sector 103 deg / 2 quads, upper 257 deg / 2 quads
    bent.points[bent.id(1, 2)] = Point(1, 1.3, 0);
    bent.points[bent.id(5, 2)] = Point(5.2, 2.6, 0);
    Mesh whole, lower, upper;
    const auto vw = build(whole, bent.points, bent.quads);
    const auto vl = build(lower, bent.points, bent.quads_if([](std::size_t, std::size_t j) { return j < 2; }));
    const auto vu = build(upper, bent.points, bent.quads_if([](std::size_t, std::size_t j) { return j >= 2; }));
    Edge_set cs;
    for(std::size_t i = 0; i < 6; ++i)
      cs.insert(edge_between(vw[bent.id(i, 2)], vw[bent.id(i + 1, 2)], whole));
    CGAL::Boolean_property_map<Edge_set> ecm(cs);
    std::size_t nonzero = 0;
    for(std::size_t k = 0; k < bent.points.size(); ++k)
    {
      int parts = 0;
      if(vl[k] != boost::graph_traits<Mesh>::null_vertex()) parts += Q::vertex_defect(vl[k], lower);
      if(vu[k] != boost::graph_traits<Mesh>::null_vertex()) parts += Q::vertex_defect(vu[k], upper);
      assert(Q::vertex_defect(vw[k], whole, CGAL::parameters::edge_is_constrained_map(ecm)) == parts);
      if(vl[k] != boost::graph_traits<Mesh>::null_vertex() && Q::vertex_defect(vl[k], lower) != 0) ++nonzero;
    }
    assert(nonzero > 0); // the halves do have boundary defects
    assert(Q::vertex_defect(vl[bent.id(3, 2)], lower) == 1 && Q::vertex_defect(vu[bent.id(3, 2)], upper) == -1);
    assert(Q::vertex_defect(vw[bent.id(3, 2)], whole, CGAL::parameters::edge_is_constrained_map(ecm)) == 0);
    // each sector of a vertex of the whole is its fan in one half (and the vertices off the line are regular):
    // counted by sector, the singularities of the whole are those of the two halves, (3,2) twice although its
    // defect is 0
    const Q::Mesh_report whole_report = Q::compute_mesh_report(whole, CGAL::parameters::edge_is_constrained_map(ecm));
    const Q::Mesh_report lower_report = Q::compute_mesh_report(lower), upper_report = Q::compute_mesh_report(upper);
    assert(whole_report.number_of_singularities_by_sector ==
           lower_report.number_of_singularities() + upper_report.number_of_singularities());
    assert(whole_report.number_of_singularities_by_sector >= whole_report.number_of_singularities() + 2);
    assert(lower_report.number_of_singularities_by_sector == lower_report.number_of_singularities());
  }

  // a regular interior vertex whose constrained edges make a sharp 40 degree turn: the 40 degree sector
  // holds 1 quad (ideal 1), the 320 degree one 3 quads (ideal 4): defect -1; without constraints, 0.
  {
    const double a = 40 * CGAL_PI / 180;
    const std::vector<Point> pts = {Point(0, 0, 0), Point(2, 0, 0), Point(2 * std::cos(a), 2 * std::sin(a), 0),
                                    Point(-2, 0, 0), Point(0, -2, 0),
                                    Point(2.3, 1.0, 0), Point(-1.5, 2, 0), Point(-2, -2, 0), Point(2, -2, 0)};
    const Polygons quads = {{0, 1, 5, 2}, {0, 2, 6, 3}, {0, 3, 7, 4}, {0, 4, 8, 1}};
    Mesh m;
    const auto vs = build(m, pts, quads);
    assert(Q::vertex_defect(vs[0], m) == 0);
    Edge_set cs = {edge_between(vs[0], vs[1], m), edge_between(vs[0], vs[2], m)};
    CGAL::Boolean_property_map<Edge_set> ecm(cs);
    assert(Q::vertex_defect(vs[0], m, CGAL::parameters::edge_is_constrained_map(ecm)) == -1);
    assert(Q::singularity_type(vs[0], m, CGAL::parameters::edge_is_constrained_map(ecm))
           == Q::Singularity_type::VALENCE_3_LIKE);
    // the same through a Qzip pack mixing CGAL's tags and Qzip's own (which the analysis ignores)
    namespace QP = CGAL::Qzip::parameters;
    assert(Q::vertex_defect(vs[0], m, QP::face_is_constrained_map(CGAL::Constant_property_map<
                                        typename boost::graph_traits<Mesh>::face_descriptor, bool>(false),
                                        QP::edge_is_constrained_map(ecm).vertex_point_map(get(CGAL::vertex_point, m))))
           == -1);
    assert(Q::compute_mesh_report(m, QP::combine(QP::edge_is_constrained_map(ecm), QP::do_smooth(false)))
             .number_of_interior_valence_3_like == 1);
    // a single constrained edge (the end of a feature curve) leaves valence - 4
    Edge_set one = {edge_between(vs[0], vs[1], m)};
    assert(Q::vertex_defect(vs[0], m, CGAL::parameters::edge_is_constrained_map(
                                        CGAL::Boolean_property_map<Edge_set>(one))) == 0);
  }
}

// A user vertex_point_map is used instead of the internal points.
template <typename Mesh>
void test_vertex_point_map()
{
  Grid g(3, 3);
  Mesh m;
  const auto vs = build(m, g.points, g.quads);
  // squash the grid onto the x axis in the user map: corner angles become 0 or 180 degrees
  auto vpm = get(CGAL::dynamic_vertex_property_t<Point>(), m);
  for(auto v : vertices(m))
  {
    const Point& p = get(CGAL::vertex_point, m, v);
    put(vpm, v, Point(p.x(), p.x() == 0 || p.x() == 3 ? 0.001 * p.y() : 0, 0));
  }
  assert(Q::vertex_defect(vs[g.id(1, 0)], m) == 0);
  assert(Q::vertex_defect(vs[g.id(1, 0)], m, CGAL::parameters::vertex_point_map(vpm)) != 0);
  const Q::Mesh_report r = Q::compute_mesh_report(m, CGAL::parameters::vertex_point_map(vpm));
  assert(r.number_of_inverted_quads == 9 && r.min_scaled_jacobian <= 0);
  assert(Q::quad_scaled_jacobian(*faces(m).begin(), m, CGAL::parameters::vertex_point_map(vpm)) <= 0);
}

template <typename Mesh>
void test_scaled_jacobian()
{
  const double s3 = std::sqrt(3.) / 2;
  Mesh m;
  build(m, {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),             // square
            Point(3, 0, 0), Point(4, 0, 0), Point(4.5, s3, 0), Point(3.5, s3, 0),       // 60 degree rhombus
            Point(6, 0, 0), Point(8, 0, 0), Point(6.5, 0.5, 0), Point(6, 2, 0),         // dart (reflex corner)
            Point(9, 0, 0), Point(10, 0, 0), Point(10, 0, 0), Point(9, 1, 0)},          // zero-length edge
        {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}, {12, 13, 14, 15}});
  std::vector<double> sj;
  for(auto f : faces(m)) sj.push_back(Q::quad_scaled_jacobian(f, m));
  // faces come in insertion order for both mesh types
  assert(std::abs(sj[0] - 1) < 1e-12);
  assert(std::abs(sj[1] - s3) < 1e-12);
  assert(sj[2] < 0);
  assert(sj[3] == 0);
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  assert(r.number_of_inverted_quads == 2 && r.number_of_connected_components == 4);
  assert(r.min_scaled_jacobian == sj[2]);
  assert(std::abs(r.mean_scaled_jacobian - (sj[0] + sj[1] + sj[2] + sj[3]) / 4) < 1e-12);
}

template <typename Mesh>
void test_report_output()
{
  Grid g(2, 2);
  Mesh m;
  build(m, g.points, g.quads_if([](std::size_t i, std::size_t j) { return i + j != 2; })); // 3 quads
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  std::ostringstream js, tx, op;
  Q::write_json(js, r);
  Q::write_text(tx, r);
  op << r;
  const std::string j = js.str();
  assert(j.front() == '{' && j.find("\"number_of_faces\": 3,") != std::string::npos);
  assert(j.find("\"faces_by_degree\": {\"4\": 3}") != std::string::npos);
  assert(j.find("\"singularity_lower_bound\": null") != std::string::npos);
  assert(j.find("nan") == std::string::npos && j.find("inf") == std::string::npos);
  int depth = 0;
  for(char c : j) { if(c == '{') ++depth; if(c == '}') --depth; assert(depth >= 0); }
  assert(depth == 0);
  const std::string text = tx.str();
  assert(text == op.str() && std::count(text.begin(), text.end(), '\n') <= 6);

  // no quad: the quality fields are JSON null, never NaN
  Mesh t;
  build(t, {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)}, {{0, 1, 2}});
  std::ostringstream tj;
  Q::write_json(tj, Q::compute_mesh_report(t));
  assert(tj.str().find("\"min_scaled_jacobian\": null") != std::string::npos);
}

// ------------------------------------------------------------------------------------------------
// Real meshes: statistics from the corpus' SOURCES.md tables (an independent tool).

struct Expected
{
  const char* file;
  std::size_t V, F;
  std::map<std::size_t, std::size_t> faces_by_degree;
  std::size_t border_edges, loops;
  long chi;
  std::size_t components;
  long genus;
  std::size_t val3, val4, val5, val6plus, irregular;
};

const std::vector<Expected>& corpus_table()
{
  static const std::vector<Expected> table = {
    {"beast_quaddominant.obj", 32311, 32364, {{3, 124}, {4, 32228}, {5, 10}, {6, 2}}, 0, 0, 2, 1, 0, 634, 30987, 652, 36, 1324},
    {"blub_quadrangulated.obj", 7106, 7104, {{4, 7104}}, 0, 0, 2, 1, 0, 26, 7068, 8, 4, 38},
    {"gen_instantmeshes_bunny_boundary.obj", 43831, 43670, {{4, 43670}}, 328, 5, -3, 1, 0, 444, 42635, 424, 0, 868},
    {"gen_instantmeshes_rocker_arm.obj", 12054, 12054, {{4, 12054}}, 0, 0, 0, 1, 1, 157, 11738, 157, 1, 316},
    {"gen_instantmeshes_turbine_quaddominant.obj", 15930, 16050, {{3, 392}, {4, 15466}, {5, 192}}, 0, 0, -20, 1, 11, 230, 15205, 480, 15, 725},
    {"gen_quadriflow_anchor_sharp.obj", 5760, 5766, {{4, 5766}}, 0, 0, -6, 1, 4, 30, 5676, 54, 0, 84},
    {"gen_quadriflow_armadillo_107k.ply", 106798, 106796, {{4, 106796}}, 0, 0, 2, 1, 0, 145, 106516, 137, 0, 282},
    {"libigl_halftunnel.off", 831, 784, {{4, 784}}, 96, 3, -1, 1, 0, 4, 723, 8, 0, 12},
    {"libigl_horse_quad.obj", 2400, 2398, {{4, 2398}}, 0, 0, 2, 1, 0, 72, 2264, 64, 0, 136},
    {"noisy_sphere_triquad.obj", 482, 512, {{3, 64}, {4, 448}}, 0, 0, 2, 1, 0, 0, 480, 0, 2, 2},
    {"pmp_fandisk_quads.off", 766, 764, {{4, 764}}, 0, 0, 2, 1, 0, 19, 736, 11, 0, 30},
    {"polylap_amo_quad.off", 837, 835, {{4, 835}}, 0, 0, 2, 1, 0, 22, 801, 14, 0, 36},
    {"polylap_loki.obj", 27514, 27352, {{4, 27352}}, 328, 4, -2, 1, 0, 182, 26841, 144, 19, 345},
    {"polylap_suzanne_half.obj", 912, 865, {{3, 1}, {4, 864}}, 95, 2, 0, 1, 0, 23, 777, 16, 1, 40},
    {"quadmixer_animal_horse.obj", 2316, 2314, {{4, 2314}}, 0, 0, 2, 1, 0, 70, 2184, 62, 0, 132},
    {"quadriflow_gargoyle.obj", 4117, 4115, {{4, 4115}}, 0, 0, 2, 1, 0, 94, 3937, 86, 0, 180},
    {"quadwild_joint.obj", 21794, 21796, {{4, 21796}}, 0, 0, -2, 1, 2, 19, 21748, 27, 0, 46},
    {"quadwild_mnf07HeadFem.obj", 9711, 9727, {{4, 9727}}, 0, 0, -16, 1, 9, 61, 9530, 115, 5, 181},
    {"spot_quadrangulated.obj", 2930, 2928, {{4, 2928}}, 0, 0, 2, 1, 0, 56, 2830, 40, 4, 100},
    {"trimesh_quadknot.obj", 1440, 1440, {{4, 1440}}, 0, 0, 0, 1, 1, 0, 1440, 0, 0, 0},
    {"trimesh_target.obj", 1715, 1660, {{3, 2}, {4, 1658}}, 120, 6, -4, 1, 0, 64, 1451, 74, 5, 144},
  };
  return table;
}

const Expected& expected_for(const std::string& file)
{
  for(const Expected& e : corpus_table())
    if(file == e.file) return e;
  std::cerr << "no expected statistics for " << file << std::endl;
  assert(false);
  std::abort();
}

bool file_exists(const std::string& path)
{
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

template <typename Mesh>
void check_real_mesh(const std::string& path, const Expected& e)
{
  Mesh m;
  const bool ok = CGAL::IO::read_polygon_mesh(path, m);
  if(!ok) std::cerr << "cannot read " << path << std::endl;
  assert(ok);
  assert(CGAL::is_valid_polygon_mesh(m));
  const Q::Mesh_report r = Q::compute_mesh_report(m);
  // without constrained edges a border vertex has one sector (canonical triangles' tips aside)
  assert(r.number_of_canonical_triangles != 0 || r.number_of_singularities_by_sector == r.number_of_singularities());

  assert(r.number_of_vertices == e.V);
  assert(r.number_of_faces == e.F);
  assert(r.faces_by_degree == e.faces_by_degree);
  assert(r.number_of_border_edges == e.border_edges);
  assert(r.number_of_boundary_loops == e.loops);
  assert(r.euler_characteristic == e.chi);
  assert(r.number_of_connected_components == e.components);
  assert(r.genus == e.genus);
  std::size_t v6plus = 0, irregular = 0;
  for(const auto& kv : r.interior_valence_histogram)
  {
    if(kv.first >= 6) v6plus += kv.second;
    if(kv.first != 4) irregular += kv.second;
  }
  auto count = [&](std::size_t val) { auto it = r.interior_valence_histogram.find(val);
                                      return it == r.interior_valence_histogram.end() ? std::size_t(0) : it->second; };
  assert(count(3) == e.val3 && count(4) == e.val4 && count(5) == e.val5);
  assert(v6plus == e.val6plus && irregular == e.irregular);

  // interior defects are valence - 4; counts agree with the histogram
  std::size_t below = 0, above = 0;
  for(const auto& kv : r.interior_valence_histogram)
  {
    if(kv.first < 4) below += kv.second;
    if(kv.first > 4) above += kv.second;
  }
  // ... except at the tip of a canonical triangle (valence 5), which is counted as a triangle, not as a v5
  std::size_t triangles = 0, canonical = 0;
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, int> tips;
  for(auto f : faces(m))
  {
    if(CGAL::halfedges_around_face(halfedge(f, m), m).size() != 3) continue;
    ++triangles;
    const auto c = Q::classify_triangle(f, m);
    if(c.configuration != Q::Triangle_configuration::CANONICAL) continue;
    ++canonical;
    ++tips[Q::triangle_tip(c.base, m)];
  }
  std::size_t lone_tips = 0; // tips of exactly one canonical triangle: valence 5, defect 0 in the report
  for(const auto& kv : tips) if(kv.second == 1) ++lone_tips;
  assert(r.number_of_triangles == triangles && r.number_of_canonical_triangles == canonical);
  assert(triangles == (r.faces_by_degree.count(3) ? r.faces_by_degree.at(3) : 0));
  // a tip has valence 5 (defect 1); less one per canonical triangle it is the tip of: 0 or negative
  assert(r.number_of_interior_valence_3_like == below + (tips.size() - lone_tips));
  assert(r.number_of_interior_valence_5_like + tips.size() == above);
  if(canonical > 0) std::cout << "  " << e.file << ": " << triangles << " triangles, " << canonical
                                           << " canonical: their tips are not counted as v5" << std::endl;

  // closed meshes: sum of (valence - 4) = 2E - 4V = -4 chi + sum over faces of (4 - degree)
  if(r.is_closed())
  {
    long face_term = 0;
    for(const auto& kv : r.faces_by_degree)
      face_term += (4 - static_cast<long>(kv.first)) * static_cast<long>(kv.second);
    assert(r.interior_defect_sum == -4 * r.euler_characteristic + face_term - long(canonical));
    if(r.is_pure_quad())
    {
      assert(r.interior_defect_sum == -4 * r.euler_characteristic);
      assert(r.has_singularity_lower_bound && r.singularity_lower_bound == std::size_t(4 * std::labs(e.chi)));
      assert(r.total_absolute_defect >= r.singularity_lower_bound);
    }
    else
      assert(!r.has_singularity_lower_bound);
  }
  else
    assert(!r.has_singularity_lower_bound && r.number_of_boundary_negative_defects + r.number_of_boundary_positive_defects
                                              <= r.number_of_vertices);

  assert(r.number_of_quads == (r.faces_by_degree.count(4) ? r.faces_by_degree.at(4) : 0));
  assert(r.min_scaled_jacobian <= r.mean_scaled_jacobian && r.mean_scaled_jacobian <= 1);

  // compute_vertex_defects agrees with vertex_defect
  auto dmap = get(CGAL::dynamic_vertex_property_t<int>(), m);
  const std::size_t nz = Q::compute_vertex_defects(m, dmap);
  std::size_t nz2 = 0;
  for(auto v : vertices(m))
  {
    assert(get(dmap, v) == Q::vertex_defect(v, m));
    if(get(dmap, v) != 0) ++nz2;
  }
  assert(nz == nz2);
}

template <typename Mesh>
void run_synthetic()
{
  test_open_grid<Mesh>();
  test_L_shape<Mesh>();
  test_boundary_defects<Mesh>();
  test_planted_collapse<Mesh>();
  test_star<Mesh>(3);
  test_star<Mesh>(5);
  test_cube<Mesh>();
  test_torus<Mesh>(8, 5);
  test_constrained_edges<Mesh>();
  test_vertex_point_map<Mesh>();
  test_scaled_jacobian<Mesh>();
  test_report_output<Mesh>();
}

template <typename Mesh>
void run_real(const std::string& data_dir, const char* mesh_name)
{
  CGAL::Real_timer timer;
  timer.start();
  const std::vector<std::string> bundled = {"noisy_sphere_triquad.obj", "pmp_fandisk_quads.off", "polylap_amo_quad.off",
                                            "polylap_suzanne_half.obj", "quadriflow_gargoyle.obj",
                                            "trimesh_quadknot.obj", "trimesh_target.obj"};
  for(const std::string& f : bundled)
  {
    const std::string path = data_dir + "/" + f;
    if(!file_exists(path)) std::cerr << "missing bundled mesh " << path << std::endl;
    assert(file_exists(path));
    check_real_mesh<Mesh>(path, expected_for(f));
  }
  check_real_mesh<Mesh>(CGAL::data_file_path("meshes/spot_quadrangulated.obj"), expected_for("spot_quadrangulated.obj"));
  check_real_mesh<Mesh>(CGAL::data_file_path("meshes/blub_quadrangulated.obj"), expected_for("blub_quadrangulated.obj"));
  std::cout << "  " << mesh_name << ": bundled meshes OK (" << timer.time() << " s)" << std::endl;

#ifdef QZIP_SHARED_DATA_DIR
  const std::string shared = QZIP_SHARED_DATA_DIR;
#else
  const std::string shared;
#endif
  if(shared.empty() || !file_exists(shared + "/SOURCES.md"))
  {
    std::cout << "  skipped: shared corpus not found at '" << shared << "'" << std::endl;
    return;
  }
  timer.reset();
  std::size_t n = 0;
  for(const Expected& e : corpus_table())
  {
    const std::string path = shared + "/" + e.file;
    if(!file_exists(path)) std::cerr << "missing corpus mesh " << path << std::endl;
    assert(file_exists(path));
    check_real_mesh<Mesh>(path, e);
    ++n;
  }
  std::cout << "  " << mesh_name << ": " << n << " shared corpus meshes OK (" << timer.time() << " s)" << std::endl;
}

int main(int argc, char** argv)
{
  const std::string data_dir = (argc > 1) ? argv[1] : "data";

  run_synthetic<Surface_mesh>();
  std::cout << "Surface_mesh: synthetic tests OK" << std::endl;
  run_synthetic<Polyhedron>();
  std::cout << "Polyhedron_3: synthetic tests OK" << std::endl;

  run_real<Surface_mesh>(data_dir, "Surface_mesh");
  run_real<Polyhedron>(data_dir, "Polyhedron_3");

  std::cout << "done" << std::endl;
  return EXIT_SUCCESS;
}
