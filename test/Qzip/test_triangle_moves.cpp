// Tests of the hybrid Q-zip (paper, Sec. 3.2): the four moves of a triangle and their inverses, long
// triangle paths with the hybrid compass (and their homotopy invariance), the three collision cases, Q-zips
// beside triangles, and random sequences on real quad-dominant meshes, each undone exactly.
#include "qzip_test_utils.h"

#include <CGAL/Qzip/triangle_moves.h>
#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/mesh_report.h>
#include <CGAL/Qzip/optimize_singularities.h>
#include <CGAL/Qzip/preprocess.h>

#include <cmath>
#include <queue>
#include <random>
#include <set>
#include <sstream>

using namespace qzip_test;
namespace Q = CGAL::Qzip;

namespace {

template <typename Mesh> using H_ = typename boost::graph_traits<Mesh>::halfedge_descriptor;
template <typename Mesh> using V_ = typename boost::graph_traits<Mesh>::vertex_descriptor;
template <typename Mesh> using F_ = typename boost::graph_traits<Mesh>::face_descriptor;

template <typename Mesh>
std::size_t degree(H_<Mesh> h, const Mesh& m) { return CGAL::halfedges_around_face(h, m).size(); }

template <typename Mesh>
std::map<std::size_t, std::size_t> face_degrees(const Mesh& m)
{
  std::map<std::size_t, std::size_t> d;
  for(auto f : faces(m)) ++d[degree(halfedge(f, m), m)];
  return d;
}

// the face-degree histogram without the quads: VE adds one quad (and one vertex, two edges), EV removes one,
// the other moves keep the number of faces; no move changes the degree of a face that is not a quad
template <typename Mesh>
std::map<std::size_t, std::size_t> non_quad_degrees(const Mesh& m)
{
  auto d = face_degrees(m);
  d.erase(4);
  return d;
}

// the valence histogram without the interior valence-4 vertices (VE adds one, EV removes one)
template <typename Mesh>
std::map<int, int> irregular_valences(const Mesh& m)
{
  auto h = valence_histogram(m);
  h.erase(4);
  return h;
}

template <typename Mesh>
std::size_t number_of_triangles(const Mesh& m)
{
  const auto d = face_degrees(m);
  return d.count(3) ? d.at(3) : 0;
}

template <typename Mesh>
std::vector<Point> sorted_points(const Mesh& m)
{
  std::vector<Point> ps;
  for(auto v : vertices(m)) ps.push_back(get(CGAL::vertex_point, m, v));
  std::sort(ps.begin(), ps.end());
  return ps;
}

// exact restoration: same connectivity up to descriptors, same positions
template <typename Mesh>
void check_restored(const Mesh& m, const Mesh& ref)
{
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(are_isomorphic(m, ref));
  assert(sorted_points(m) == sorted_points(ref));
}

// the grid face whose lower-left corner is (i, j)
template <typename Mesh>
F_<Mesh> grid_face(const Mesh& m, int i, int j)
{
  for(auto f : faces(m))
  {
    double x = 0, y = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
    { const Point& p = get(CGAL::vertex_point, m, target(h, m)); x += p.x(); y += p.y(); }
    if(std::abs(x / 4 - (i + 0.5)) < 1e-9 && std::abs(y / 4 - (j + 0.5)) < 1e-9) return f;
  }
  assert(false);
  return F_<Mesh>();
}

// direction a triangle points to, in the plane z = 0: 0 = +x, 1 = +y, 2 = -x, 3 = -y (from its base edge,
// which is a grid edge: the direction is the base turned by a quarter turn counterclockwise)
template <typename Mesh>
int direction(H_<Mesh> h, const Mesh& m)
{
  const Point a = get(CGAL::vertex_point, m, source(h, m)), b = get(CGAL::vertex_point, m, target(h, m));
  const double dx = -(b.y() - a.y()), dy = b.x() - a.x();
  if(std::abs(dx) > std::abs(dy)) return dx > 0 ? 0 : 2;
  return dy > 0 ? 1 : 3;
}

template <typename Mesh>
bool is_canonical(H_<Mesh> h, const Mesh& m)
{
  const auto c = Q::classify_triangle(face(h, m), m);
  return c.configuration == Q::Triangle_configuration::CANONICAL && c.base == h;
}

// Splits the grid quad (i, j) along a diagonal (two oppositely oriented triangles, collided side by side)
// and separates them by moving the first one `steps` times with `sep`: two canonical triangles.
// Returns the base of the moved one; `other` gets the base of the other one.
template <typename Mesh>
H_<Mesh> make_triangle_pair(Mesh& m, int i, int j, int diagonal, Q::Triangle_move sep, int steps, H_<Mesh>& other)
{
  H_<Mesh> h = halfedge(grid_face(m, i, j), m);
  if(diagonal) h = next(h, m);
  const std::size_t nt = number_of_triangles(m);
  const H_<Mesh> d = CGAL::Euler::split_face(h, next(next(h, m), m), m);
  assert(CGAL::is_valid_polygon_mesh(m) && number_of_triangles(m) == nt + 2);
  for(H_<Mesh> b : CGAL::halfedges_around_face(d, m))
  {
    if(!Q::can_move_triangle(b, sep, m)) continue;
    Q::Triangle_move_history<Mesh> hist(m);
    H_<Mesh> nb = Q::move_triangle(b, sep, hist);
    if(!is_canonical(nb, m)) { hist.undo_last(); continue; }
    for(int s = 1; s < steps; ++s)
    {
      assert(Q::can_move_triangle(nb, sep, m));
      nb = Q::move_triangle(nb, sep, m);
      assert(is_canonical(nb, m));
    }
    other = Q::classify_triangle(face(opposite(d, m), m), m).base;
    assert(is_canonical(other, m));
    return nb;
  }
  assert(false);
  return boost::graph_traits<Mesh>::null_halfedge();
}

template <typename Mesh>
std::vector<V_<Mesh>> bfs_path(const Mesh& m, V_<Mesh> s, V_<Mesh> t, bool reverse_order,
                               const std::set<V_<Mesh>>& forbidden = std::set<V_<Mesh>>())
{
  std::map<V_<Mesh>, V_<Mesh>> pred;
  std::queue<V_<Mesh>> q;
  q.push(s); pred[s] = s;
  while(!q.empty())
  {
    const V_<Mesh> v = q.front(); q.pop();
    if(v == t) break;
    std::vector<V_<Mesh>> nb;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) nb.push_back(source(h, m));
    if(reverse_order) std::reverse(nb.begin(), nb.end());
    for(V_<Mesh> w : nb)
      if(!pred.count(w) && (w == t || !forbidden.count(w))) { pred[w] = v; q.push(w); }
  }
  std::vector<V_<Mesh>> p;
  if(!pred.count(t)) return p;
  for(V_<Mesh> v = t; ; v = pred[v]) { p.push_back(v); if(v == s) break; }
  std::reverse(p.begin(), p.end());
  return p;
}

template <typename Mesh>
std::set<V_<Mesh>> triangle_neighbourhood(H_<Mesh> h, const Mesh& m, int rings)
{
  std::set<V_<Mesh>> s;
  for(auto x : CGAL::halfedges_around_face(h, m)) s.insert(target(x, m));
  for(int r = 0; r < rings; ++r)
  {
    std::set<V_<Mesh>> n(s);
    for(auto v : s) for(auto x : CGAL::halfedges_around_target(halfedge(v, m), m)) n.insert(source(x, m));
    s.swap(n);
  }
  return s;
}

// ------------------------------------------------------------------------------------------------
// 1. the four moves, each with its inverse and with the history undo
template <typename Mesh>
void test_single_moves()
{
  Mesh m0;
  make_quad_grid(m0, 24, 24);
  H_<Mesh> other;
  const H_<Mesh> T = make_triangle_pair(m0, 8, 12, 0, Q::Triangle_move::VERTEX_TO_EDGE, 5, other);
  const auto hist0 = irregular_valences(m0);
  const long chi0 = euler_characteristic(m0);
  {
    // the analysis reports two canonical triangles and no singularity (their tips have valence 5)
    assert(is_canonical(T, m0) && is_canonical(other, m0) && hist0.count(5) && hist0.at(5) == 2);
    const Q::Mesh_report r = Q::compute_mesh_report(m0);
    assert(r.number_of_triangles == 2 && r.number_of_canonical_triangles == 2);
    assert(r.number_of_singularities() == 0 && r.total_absolute_defect == 0 && r.number_of_interior_valence_5_like == 0);
    std::ostringstream js;
    Q::write_json(js, r);
    assert(js.str().find("\"number_of_canonical_triangles\": 2,") != std::string::npos);
    assert(Q::vertex_defect(Q::triangle_tip(T, m0), m0) == 1); // the per-vertex defect is unchanged
  }
  std::size_t done = 0;
  const Q::Triangle_move VE = Q::Triangle_move::VERTEX_TO_EDGE, VE2 = Q::Triangle_move::MIRRORED_VERTEX_TO_EDGE;
  for(int mi = 0; mi < 5; ++mi)
  {
    const Q::Triangle_move mv = Q::Triangle_move(mi);
    Mesh m;
    auto v2v = copy_mesh_with_map(m0, m);
    const H_<Mesh> h = halfedge(v2v[source(T, m0)], v2v[target(T, m0)], m).first;
    assert(is_canonical(h, m));
    const V_<Mesh> t = Q::triangle_tip(h, m), a = source(h, m), b = target(h, m);
    // the vertex the tip goes to, predicted in the mesh before the move
    const H_<Mesh> tb = opposite(next(h, m), m);
    V_<Mesh> expected = a;
    if(mv == Q::Triangle_move::RIGHT_FLIP) expected = target(Q::internal::rotate_outgoing(tb, 1, m), m);
    if(mv == Q::Triangle_move::LEFT_FLIP) expected = target(Q::internal::rotate_outgoing(tb, 3, m), m);
    if(mv == VE || mv == VE2) expected = target(Q::internal::rotate_outgoing(tb, 2, m), m);
    assert(Q::triangle_move_toward(h, expected, m) == (mv == VE2 ? VE : mv)); // the compass says VE; VE' is its mirror
    assert(Q::can_move_triangle(h, mv, m));
    const int dir0 = direction(h, m);

    Q::Triangle_move_history<Mesh> hist(m);
    const H_<Mesh> nb = Q::move_triangle(h, mv, hist);
    assert(hist.size() == 1);
    assert(CGAL::is_valid_polygon_mesh(m));
    assert(euler_characteristic(m) == chi0);
    assert(non_quad_degrees(m) == non_quad_degrees(m0)); // every other face keeps its degree
    assert(faces(m).size() + (mv == Q::Triangle_move::EDGE_TO_VERTEX) ==
           faces(m0).size() + (mv == VE || mv == VE2));
    assert(irregular_valences(m) == hist0);         // no singularity appears
    assert(is_canonical(nb, m));
    assert(Q::triangle_tip(nb, m) == expected);
    assert(direction(nb, m) == dir0);
    CGAL_USE(b);
    if(mv == VE2)
    {
      // in a regular region, VE and its mirror image give isomorphic meshes
      Mesh r;
      auto v2r = copy_mesh_with_map(m0, r);
      Q::move_triangle(halfedge(v2r[source(T, m0)], v2r[target(T, m0)], r).first, VE, r);
      assert(are_isomorphic(m, r));
    }

    // the inverse move, applied to the moved triangle, with the old tip as target
    {
      Mesh c;
      auto w2w = copy_mesh_with_map(m, c);
      const H_<Mesh> nc = halfedge(w2w[source(nb, m)], w2w[target(nb, m)], c).first;
      const Q::Triangle_move inv = Q::inverse(mv);
      assert(Q::triangle_move_toward(nc, w2w[t], c) == inv);
      assert(Q::can_move_triangle(nc, inv, c, w2w[t]));
      const H_<Mesh> back = Q::move_triangle(nc, inv, c, w2w[t]);
      assert(CGAL::is_valid_polygon_mesh(c));
      assert(is_canonical(back, c) && Q::triangle_tip(back, c) == w2w[t]);
      assert(are_isomorphic(c, m0));
    }
    hist.undo_last();
    assert(hist.empty());
    check_restored(m, m0);
    ++done;
  }
  assert(done == 5);

  // the triangle keeps its direction under every move (flat region), and each move is refused where the
  // face it needs is a triangle or the border
  {
    Mesh m;
    auto v2v = copy_mesh_with_map(m0, m);
    const H_<Mesh> h = halfedge(v2v[source(T, m0)], v2v[target(T, m0)], m).first;
    const int d0 = direction(h, m);
    H_<Mesh> cur = h;
    for(int mi : { 0, 0, 4, 2, 3, 3, 1, 4, 2 })
    {
      assert(Q::can_move_triangle(cur, Q::Triangle_move(mi), m));
      cur = Q::move_triangle(cur, Q::Triangle_move(mi), m);
      assert(is_canonical(cur, m) && direction(cur, m) == d0);
    }
  }
  // on a path, VE' is made where VE cannot: here the face VE would cut the new triangle from is a hexagon
  {
    Mesh m;
    auto v2v = copy_mesh_with_map(m0, m);
    const H_<Mesh> h = halfedge(v2v[source(T, m0)], v2v[target(T, m0)], m).first;
    const V_<Mesh> t = Q::triangle_tip(h, m);
    const V_<Mesh> w = target(Q::internal::rotate_outgoing(opposite(next(h, m), m), 2, m), m);
    const H_<Mesh> wt = halfedge(w, t, m).first;
    CGAL::Euler::join_face(next(next(wt, m), m), m);      // the far side of the face of w->t: a hexagon
    assert(degree(wt, m) == 6 && !Q::can_move_triangle(h, VE, m, w) && Q::can_move_triangle(h, VE2, m, w));
    Mesh before;
    copy_mesh(m, before);
    Q::Triangle_move_history<Mesh> hist(m);
    const auto r = Q::move_triangle_along_path(m, h, { t, w }, hist);
    assert(r.status == Q::Triangle_path_status::DONE && r.moves == std::vector<Q::Triangle_move>{ VE2 });
    assert(CGAL::is_valid_polygon_mesh(m) && is_canonical(r.base, m) && Q::triangle_tip(r.base, m) == w);
    assert(non_quad_degrees(m) == non_quad_degrees(before) && irregular_valences(m) == irregular_valences(before));
    hist.undo_last();
    check_restored(m, before);
  }
  {
    Mesh g;
    make_quad_grid(g, 3, 3);
    H_<Mesh> hb = halfedge(grid_face(g, 0, 0), g);
    const H_<Mesh> d = CGAL::Euler::split_face(hb, next(next(hb, g), g), g);
    for(H_<Mesh> x : CGAL::halfedges_around_face(d, g))
      for(int mi = 0; mi < 5; ++mi) assert(!Q::can_move_triangle(x, Q::Triangle_move(mi), g)); // border triangle
  }
  std::cout << "  single moves and inverses: ok" << std::endl;
}

// ------------------------------------------------------------------------------------------------
// 2. long paths: random simple paths (invariants, undo), and homotopic paths give isomorphic meshes
template <typename Mesh>
void test_long_paths()
{
  Mesh m0;
  make_quad_grid(m0, 40, 40);
  H_<Mesh> other;
  const H_<Mesh> T = make_triangle_pair(m0, 20, 20, 1, Q::Triangle_move::VERTEX_TO_EDGE, 7, other);
  const auto hist0 = irregular_valences(m0);
  const auto fdeg0 = non_quad_degrees(m0);
  std::mt19937 rng(7);
  std::size_t done = 0, refused = 0, total_moves = 0;
  std::map<int, std::size_t> kinds;
  for(int trial = 0; trial < 100; ++trial)
  {
    Mesh m;
    auto v2v = copy_mesh_with_map(m0, m);
    const H_<Mesh> h = halfedge(v2v[source(T, m0)], v2v[target(T, m0)], m).first;
    const H_<Mesh> o = halfedge(v2v[source(other, m0)], v2v[target(other, m0)], m).first;
    const auto avoid = triangle_neighbourhood(o, m, 2);
    // a random simple walk of up to 14 edges, away from the other triangle and the border
    std::vector<V_<Mesh>> path = { Q::triangle_tip(h, m) };
    std::set<V_<Mesh>> used(path.begin(), path.end());
    for(int s = 0; s < 14; ++s)
    {
      std::vector<V_<Mesh>> cand;
      for(auto x : CGAL::halfedges_around_target(halfedge(path.back(), m), m))
      {
        const V_<Mesh> w = source(x, m);
        const Point p = get(CGAL::vertex_point, m, w);
        if(!used.count(w) && !avoid.count(w) && p.x() > 2 && p.x() < 38 && p.y() > 2 && p.y() < 38) cand.push_back(w);
      }
      if(cand.empty()) break;
      const V_<Mesh> w = cand[rng() % cand.size()];
      path.push_back(w); used.insert(w);
    }
    const int dir0 = direction(h, m);
    Q::Triangle_move_history<Mesh> hist(m);
    const auto r = Q::move_triangle_along_path(m, h, path, hist);
    assert(CGAL::is_valid_polygon_mesh(m));
    if(r.status != Q::Triangle_path_status::DONE)
    {
      // refused paths leave the mesh as it was; a random walk is often refused because it steps from one
      // base corner to the other (t -> a -> b: the EV towards a removes b)
      assert(r.status == Q::Triangle_path_status::INVALID_PATH || r.status == Q::Triangle_path_status::BLOCKED);
      assert(hist.empty());
      check_restored(m, m0);
      ++refused;
      continue;
    }
    assert(r.moves.size() + 1 == path.size());
    assert(irregular_valences(m) == hist0 && non_quad_degrees(m) == fdeg0);
    assert(is_canonical(r.base, m) && Q::triangle_tip(r.base, m) == path.back());
    assert(direction(r.base, m) == dir0);
    for(auto k : r.moves) ++kinds[int(k)];
    total_moves += r.moves.size();
    assert(hist.size() == 1);
    hist.undo_last();
    check_restored(m, m0);
    ++done;
  }
  assert(done >= 40);
  assert(kinds.count(0) && kinds.count(1) && kinds.count(2) && kinds.count(3)); // VE' only where VE cannot be made

  // homotopy invariance: two shortest paths to the same vertex (different tie-breaks) within a disc free of
  // other singularities give isomorphic meshes
  std::size_t pairs = 0, differing = 0;
  {
    Mesh m;
    auto v2v = copy_mesh_with_map(m0, m);
    const H_<Mesh> h = halfedge(v2v[source(T, m0)], v2v[target(T, m0)], m).first;
    const H_<Mesh> o = halfedge(v2v[source(other, m0)], v2v[target(other, m0)], m).first;
    const auto avoid = triangle_neighbourhood(o, m, 3);
    const auto ball = triangle_neighbourhood(h, m, 4);
    for(V_<Mesh> goal : ball)
    {
      if(avoid.count(goal) || goal == Q::triangle_tip(h, m)) continue;
      const auto p1 = bfs_path(m, Q::triangle_tip(h, m), goal, false, avoid);
      const auto p2 = bfs_path(m, Q::triangle_tip(h, m), goal, true, avoid);
      if(p1.size() < 2 || p2.size() < 2) continue;
      Mesh c1, c2;
      auto w1 = copy_mesh_with_map(m, c1);
      auto w2 = copy_mesh_with_map(m, c2);
      auto map_path = [](const std::vector<V_<Mesh>>& p, std::map<V_<Mesh>, V_<Mesh>>& w)
      { std::vector<V_<Mesh>> q; for(auto v : p) q.push_back(w[v]); return q; };
      Q::Triangle_move_history<Mesh> h1(c1), h2(c2);
      const auto r1 = Q::move_triangle_along_path(c1, halfedge(w1[source(h, m)], w1[target(h, m)], c1).first, map_path(p1, w1), h1);
      const auto r2 = Q::move_triangle_along_path(c2, halfedge(w2[source(h, m)], w2[target(h, m)], c2).first, map_path(p2, w2), h2);
      if(r1.status != Q::Triangle_path_status::DONE || r2.status != Q::Triangle_path_status::DONE) continue;
      assert(are_isomorphic(c1, c2));
      ++pairs;
      if(p1 != p2) ++differing;
    }
  }
  assert(differing >= 10);
  std::cout << "  long paths: " << done << " done (" << total_moves << " moves: VE " << kinds[0] << ", EV " << kinds[1]
            << ", LE " << kinds[2] << ", RE " << kinds[3] << ", VE' " << kinds[4] << "), " << refused << " refused and rolled back; "
            << differing << " pairs of different homotopic paths give isomorphic meshes" << std::endl;
}

// ------------------------------------------------------------------------------------------------
// 3. collisions: opposite -> regular, orthogonal -> adjacent 3-5 pair, same direction -> 3 and 5 across a quad
template <typename Mesh>
void test_collisions()
{
  std::map<std::string, std::size_t> table;
  for(int diagA : { 0, 1 }) for(int diagB : { 0, 1 }) for(int sepA : { 0, 2 }) for(int sepB : { 0, 3 })
  {
    Mesh m0;
    make_quad_grid(m0, 30, 30);
    H_<Mesh> oA, oB;
    const H_<Mesh> tA = make_triangle_pair(m0, 8, 12, diagA, Q::Triangle_move(sepA), 3, oA);
    const H_<Mesh> tB = make_triangle_pair(m0, 18, 14, diagB, Q::Triangle_move(sepB), 3, oB);
    const std::vector<H_<Mesh>> tris = { tA, oA, tB, oB };
    for(int x = 0; x < 4; ++x) for(int y = 0; y < 4; ++y)
    {
      if(x / 2 == y / 2) continue;
      for(int goal_corner = 0; goal_corner < 3; ++goal_corner) for(int rev = 0; rev < 2; ++rev)
      {
        Mesh m;
        auto v2v = copy_mesh_with_map(m0, m);
        auto map_h = [&](H_<Mesh> hh) { return halfedge(v2v[source(hh, m0)], v2v[target(hh, m0)], m).first; };
        const H_<Mesh> X = map_h(tris[x]), Y = map_h(tris[y]);
        const int dx = direction(X, m), dy = direction(Y, m);
        const V_<Mesh> goal = goal_corner == 0 ? Q::triangle_tip(Y, m) : (goal_corner == 1 ? source(Y, m) : target(Y, m));
        // keep away from the two other triangles, so that X can only collide with Y
        std::set<V_<Mesh>> avoid;
        for(int z = 0; z < 4; ++z)
          if(z != x && z != y) { const auto nz = triangle_neighbourhood(map_h(tris[z]), m, 2); avoid.insert(nz.begin(), nz.end()); }
        const auto path = bfs_path(m, Q::triangle_tip(X, m), goal, rev != 0, avoid);
        if(path.size() < 2) continue;
        Q::Triangle_move_history<Mesh> hist(m);
        const auto r = Q::move_triangle_along_path(m, X, path, hist);
        assert(CGAL::is_valid_polygon_mesh(m));
        if(r.status != Q::Triangle_path_status::COLLIDED)
        {
          if(r.status != Q::Triangle_path_status::DONE) { assert(hist.empty()); check_restored(m, m0); }
          continue;
        }
        assert(euler_characteristic(m) == euler_characteristic(m0));
        assert(number_of_triangles(m) == 2); // the two triangles of the collision are gone, only them
        // the singular vertices: interior vertices of valence != 4 that are not tips of the two other triangles
        std::set<V_<Mesh>> tips;
        for(auto f : faces(m))
          if(degree(halfedge(f, m), m) == 3)
          {
            const auto c = Q::classify_triangle(f, m);
            assert(c.configuration == Q::Triangle_configuration::CANONICAL);
            tips.insert(Q::triangle_tip(c.base, m));
          }
        std::vector<V_<Mesh>> s3, s5, others;
        for(auto v : vertices(m))
        {
          if(on_border(v, m) || tips.count(v)) continue;
          const int d = valence(v, m);
          if(d == 3) s3.push_back(v); else if(d == 5) s5.push_back(v); else if(d != 4) others.push_back(v);
        }
        const std::string rel = dx == dy ? "same" : ((dx + 2) % 4 == dy ? "opposite" : "orthogonal");
        std::string res = "other";
        if(s3.empty() && s5.empty() && others.empty()) res = "regular";
        else if(s3.size() == 1 && s5.size() == 1 && others.empty())
        {
          bool diagonal = false;
          for(auto hh : CGAL::halfedges_around_target(halfedge(s3[0], m), m))
            if(!is_border(hh, m) && degree(hh, m) == 4 && target(next(next(hh, m), m), m) == s5[0]) diagonal = true;
          res = halfedge(s3[0], s5[0], m).second ? "adjacent 3-5" : (diagonal ? "3 and 5 across a quad" : "other");
        }
        const char* resolution = r.collision == Q::Collision_resolution::MERGED ? "merged"
                               : (r.collision == Q::Collision_resolution::ANNIHILATED ? "annihilated" : "tip split");
        assert(r.collision != Q::Collision_resolution::NONE);
        // whichever way the collision is resolved (a VE into a triangle that shares the tip splits the tip),
        // the result is the case for the relative direction
        if(rel == "opposite") assert(res == "regular");
        if(rel == "orthogonal") assert(res == "adjacent 3-5" && r.collision != Q::Collision_resolution::ANNIHILATED);
        if(rel == "same") assert(res == "3 and 5 across a quad" && r.collision != Q::Collision_resolution::ANNIHILATED);
        ++table[rel + " (" + resolution + ") -> " + res];
        hist.undo_last();
        check_restored(m, m0);
      }
    }
  }
  // opposite merged, annihilated or tip split; orthogonal and same, merged or tip split
  assert(table.size() == 7);
  for(const auto& kv : table) std::cout << "  collision " << kv.first << ": " << kv.second << std::endl;
}

// ------------------------------------------------------------------------------------------------
// 4. Q-zip beside triangles: with Non_quad_face_map, surgery paths avoid the triangles, which stay triangles
template <typename Mesh>
std::set<std::vector<Point>> triangle_corners(const Mesh& m)
{
  std::set<std::vector<Point>> s;
  for(auto f : faces(m))
    if(degree(halfedge(f, m), m) == 3)
    {
      std::vector<Point> ps;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m)) ps.push_back(get(CGAL::vertex_point, m, target(h, m)));
      std::sort(ps.begin(), ps.end());
      s.insert(ps);
    }
  return s;
}

template <typename Mesh>
void test_qzip_beside_triangles(Mesh& m, const std::string& name, std::size_t attempts)
{
  Mesh m0;
  copy_mesh(m, m0);
  const auto tri0 = triangle_corners(m);
  const auto fdeg0 = non_quad_degrees(m);
  const long chi0 = euler_characteristic(m);
  const auto fcm = Q::make_non_quad_face_map(m);
  std::mt19937 rng(11);
  Q::Qzip_history<Mesh> history(m);
  std::size_t done = 0, tried = 0;
  for(std::size_t k = 0; k < attempts; ++k)
  {
    // the singularities away from the triangles, collected again after each Q-zip (descriptors of removed
    // vertices dangle)
    std::vector<V_<Mesh>> singular;
    for(auto v : vertices(m))
    {
      if(on_border(v, m)) continue;
      bool near_triangle = false;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(get(fcm, face(h, m))) near_triangle = true;
      const int d = valence(v, m);
      if((d == 3 || d == 5) && !near_triangle) singular.push_back(v);
    }
    if(singular.size() < 2) break;
    const V_<Mesh> s = singular[rng() % singular.size()], t = singular[rng() % singular.size()];
    if(s == t) continue;
    const int ds = valence(s, m), dt = valence(t, m);
    if((ds != 3 && ds != 5) || (dt != 3 && dt != 5)) continue;
    const auto path = Q::shortest_surgery_path(m, s, t, Q::parameters::face_is_constrained_map(fcm));
    if(path.empty() || path.size() > 40) continue;
    // the intended behaviour of the search: no path vertex is incident to a triangle
    for(auto v : path)
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
        assert(is_border(h, m) || degree(h, m) == 4);
    const auto plan = Q::plan_qzip(m, path, Q::Strip_operation(int(rng() % 4)), Q::parameters::face_is_constrained_map(fcm));
    ++tried;
    if(!plan.is_realizable()) continue;
    const auto r = Q::execute_qzip(m, plan, history, Q::parameters::face_is_constrained_map(fcm));
    assert(CGAL::is_valid_polygon_mesh(m));
    if(!r.is_done()) continue;
    ++done;
    assert(euler_characteristic(m) == chi0);
    assert(non_quad_degrees(m) == fdeg0);    // quad collapses and splits only: every triangle stays a triangle
    assert(triangle_corners(m) == tri0);     // and is not even touched
  }
  history.undo_all();
  check_restored(m, m0);
  std::cout << "  Q-zip beside triangles on " << name << ": " << done << " Q-zips done out of " << tried
            << " planned, triangles untouched, all undone" << std::endl;
}

// ------------------------------------------------------------------------------------------------
// 5. real quad-dominant meshes: preparation, random moves and paths with collisions, undo
template <typename Mesh>
void test_real_mesh(const std::string& file, std::size_t steps)
{
  Mesh m;
  if(!read_mesh(file, m)) { std::cerr << "cannot read " << file << std::endl; assert(false); return; }
  const std::string name = file.substr(file.find_last_of('/') + 1);
  Mesh input;
  copy_mesh(m, input);
  const long chi0 = euler_characteristic(m);
  const std::size_t tri_in = number_of_triangles(m);

  Q::Triangle_move_history<Mesh> prep_history(m);
  const auto pr = Q::prepare_triangles(m, prep_history);
  assert(CGAL::is_valid_polygon_mesh(m) && euler_characteristic(m) == chi0);
  assert(number_of_triangles(m) + 2 * pr.merged_pairs == tri_in);
  assert(pr.canonical + pr.singular_corners + pr.adjacent + pr.on_border == number_of_triangles(m));
  std::cout << "  " << name << ": " << tri_in << " triangles; preparation merged " << pr.merged_pairs
            << " adjacent pairs, separated " << pr.separated << "; now " << pr.canonical << " canonical, "
            << pr.singular_corners << " with singular corners, " << pr.adjacent << " adjacent, "
            << pr.on_border << " on the border" << std::endl;

  Mesh prepared;
  copy_mesh(m, prepared);
  // one history for everything: a second history would not see the descriptors the first one re-creates
  Q::Triangle_move_history<Mesh>& hist = prep_history;
  const std::size_t prep_groups = hist.size();
  std::mt19937 rng(5);
  std::size_t moves = 0, paths = 0, collisions = 0;
  for(std::size_t s = 0; s < steps; ++s)
  {
    std::vector<H_<Mesh>> bases;
    for(auto f : faces(m))
      if(degree(halfedge(f, m), m) == 3)
      {
        const auto c = Q::classify_triangle(f, m);
        if(c.base != boost::graph_traits<Mesh>::null_halfedge()) bases.push_back(c.base);
      }
    if(bases.empty()) break;
    const H_<Mesh> h = bases[rng() % bases.size()];
    const std::size_t tri_before = number_of_triangles(m);
    auto fd_before = non_quad_degrees(m);
    if(rng() % 3 != 0)
    {
      const Q::Triangle_move mv = Q::Triangle_move(int(rng() % 5));
      if(!Q::can_move_triangle(h, mv, m)) continue;
      Q::move_triangle(h, mv, hist);
      ++moves;
      assert(non_quad_degrees(m) == fd_before); // a move changes the degree of no face but the two triangles
    }
    else
    {
      // a random walk of the tip
      std::vector<V_<Mesh>> path = { Q::triangle_tip(h, m) };
      std::set<V_<Mesh>> used(path.begin(), path.end());
      for(int k = 0; k < 8; ++k)
      {
        std::vector<V_<Mesh>> cand;
        for(auto x : CGAL::halfedges_around_target(halfedge(path.back(), m), m))
          if(!used.count(source(x, m))) cand.push_back(source(x, m));
        if(cand.empty()) break;
        path.push_back(cand[rng() % cand.size()]);
        used.insert(path.back());
      }
      const auto r = Q::move_triangle_along_path(m, h, path, hist);
      if(!r.is_done()) { assert(non_quad_degrees(m) == fd_before); continue; }
      ++paths;
      if(r.status == Q::Triangle_path_status::COLLIDED)
      {
        ++collisions;
        assert(number_of_triangles(m) + 2 == tri_before); // #triangles changes only by collisions
        auto fd = non_quad_degrees(m);
        fd_before[3] -= 2;
        if(fd_before[3] == 0) fd_before.erase(3);
        assert(fd == fd_before);
      }
      else assert(non_quad_degrees(m) == fd_before);
    }
    assert(CGAL::is_valid_polygon_mesh(m));
    assert(euler_characteristic(m) == chi0);
  }
  while(hist.size() > prep_groups) hist.undo_last();
  check_restored(m, prepared);
  hist.undo_all();
  check_restored(m, input);
  std::cout << "    " << moves << " random moves, " << paths << " paths (" << collisions
            << " collisions), all undone, preparation undone" << std::endl;
}

// ------------------------------------------------------------------------------------------------
// 6. the optimizer on hybrid meshes: its triangle pairing moves triangles towards each other and collides
//    them into quads, then its Q-zips cancel the singularities; the pipeline of the example
//    optimize_singularities: preprocess_valences() (which splits the poles of a UV sphere), then
//    optimize_singularities(). The number of faces stays within `tolerance` (face_count_tolerance) of that of
//    the mesh given to the optimizer: the collisions, which remove one face each, count.
template <typename Mesh>
void test_optimizer_on_hybrid_mesh(const std::string& file, std::size_t batches, double tolerance = 0.1)
{
  Mesh m;
  const bool ok = read_mesh(file, m);
  assert(ok); CGAL_USE(ok);
  const std::string name = file.substr(file.find_last_of('/') + 1);
  const Q::Mesh_report in = Q::compute_mesh_report(m);
  Q::preprocess_valences(m);
  assert(CGAL::is_valid_polygon_mesh(m));
  const Q::Mesh_report pre = Q::compute_mesh_report(m);
  assert(pre.number_of_triangles == in.number_of_triangles);
  const auto s = Q::optimize_singularities(m, Q::parameters::stop_predicate(Q::Batch_count_stop_predicate(batches),
                                              Q::parameters::face_count_tolerance(tolerance)));
  const Q::Mesh_report out = Q::compute_mesh_report(m);
  assert(s.initial_number_of_faces == pre.number_of_faces && s.number_of_faces == out.number_of_faces);
  assert(s.number_of_triangle_collisions <= tolerance * double(pre.number_of_faces)); // else the collisions alone leave it
  assert(std::abs(double(out.number_of_faces) - double(pre.number_of_faces)) <= tolerance * double(pre.number_of_faces));
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(out.euler_characteristic == in.euler_characteristic);
  assert(s.initial_number_of_triangles == in.number_of_triangles && s.number_of_triangles == out.number_of_triangles);
  assert(out.number_of_triangles + 2 * s.number_of_triangle_collisions == in.number_of_triangles); // only collisions remove triangles
  for(std::size_t d = 5; d < 10; ++d) assert(out.faces_by_degree.count(d) == in.faces_by_degree.count(d)); // other polygons untouched
  assert(out.number_of_inverted_quads <= pre.number_of_inverted_quads);                       // the optimizer inverts no quad
  // fewer triangles (a lone triangle has no partner), fewer singularities: in sum of |defect| (canonical
  // triangles' tips not counted), and in singular vertices plus triangles (the number of singular vertices
  // alone grows on the UV sphere, whose two poles of valence 32 carry 56 units of defect)
  if(in.number_of_triangles >= 2) assert(out.number_of_triangles < in.number_of_triangles);
  else assert(out.number_of_triangles == in.number_of_triangles);
  assert(out.total_absolute_defect < in.total_absolute_defect);
  assert(out.number_of_singularities() + out.number_of_triangles < in.number_of_singularities() + in.number_of_triangles);
  std::cout << "  optimizer on " << name << ": triangles " << in.number_of_triangles << " -> " << out.number_of_triangles
            << " (" << s.number_of_triangle_collisions << " collisions kept, " << s.number_of_undone_triangle_paths
            << " undone), singular vertices " << in.number_of_singularities() << " -> " << out.number_of_singularities()
            << ", sum |defect| " << in.total_absolute_defect << " -> " << out.total_absolute_defect
            << ", inverted quads " << in.number_of_inverted_quads << " -> " << out.number_of_inverted_quads
            << ", faces " << pre.number_of_faces << " -> " << out.number_of_faces << " (tolerance " << tolerance << ")" << std::endl;
}

template <typename Mesh>
void run_all()
{
  test_single_moves<Mesh>();
  test_long_paths<Mesh>();
  test_collisions<Mesh>();

  // Q-zip beside triangles
  for(const char* f : { "data/polylap_suzanne_half.obj", "data/trimesh_target.obj" })
  {
    Mesh m;
    const bool ok = read_mesh(f, m);
    assert(ok); CGAL_USE(ok);
    test_qzip_beside_triangles(m, f, 60);
  }

  for(const char* f : { "data/noisy_sphere_triquad.obj", "data/polylap_suzanne_half.obj", "data/trimesh_target.obj" })
    test_real_mesh<Mesh>(f, 150);

  for(const char* f : { "data/noisy_sphere_triquad.obj", "data/polylap_suzanne_half.obj", "data/trimesh_target.obj" })
    test_optimizer_on_hybrid_mesh<Mesh>(f, 30);
  // a budget tight enough that the collisions matter (the sphere's 32 collisions are 6% of its faces)
  test_optimizer_on_hybrid_mesh<Mesh>("data/noisy_sphere_triquad.obj", 30, 0.07);
}

} // namespace

int main()
{
  std::cout << "Surface_mesh" << std::endl;
  run_all<Surface_mesh>();
  std::cout << "Polyhedron_3" << std::endl;
  run_all<Polyhedron>();

  const std::string dir = shared_corpus_dir("hybrid corpus meshes");
  if(!dir.empty())
  {
    // the quad-dominant meshes of the corpus (SOURCES.md), with pentagons and hexagons
    for(const char* f : { "beast_quaddominant.obj", "gen_instantmeshes_turbine_quaddominant.obj" })
    {
      std::cout << "shared corpus, " << f << " (Surface_mesh)" << std::endl;
      test_real_mesh<Surface_mesh>(dir + "/" + f, 40);
      test_optimizer_on_hybrid_mesh<Surface_mesh>(dir + "/" + f, 30);
    }
    // Polyhedron_3 on beast: an undone EV re-creates the vertex it removed under a new descriptor, which
    // prepare_triangles() must not use afterwards (it used to: a dangling vertex handle)
    std::cout << "shared corpus, beast_quaddominant.obj (Polyhedron_3)" << std::endl;
    test_real_mesh<Polyhedron>(dir + "/beast_quaddominant.obj", 40);
  }
  return EXIT_SUCCESS;
}
