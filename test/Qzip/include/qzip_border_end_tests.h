// Tests of border end points (straight pieces of border and corners): every Q-zip that moved a border
// defect is undone by its reverse Q-zip (`Qzip::reverse_qzip()`), and redone by the reverse of the reverse.
#ifndef QZIP_BORDER_END_TESTS_H
#define QZIP_BORDER_END_TESTS_H

#include "qzip_test_utils.h"
#include "reverse_qzip_tests.h"

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/singularities.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

// defined in test_qzip.cpp (before main())
template <typename Mesh> void make_grid_with_border_steps(Mesh& m, unsigned seed);

namespace qzip_test {

/// how the Q-zips to border end points went
struct Border_move_counters
{
  std::size_t done = 0, cancelling = 0, moved = 0, reversed = 0, redone = 0, redo_refused = 0, rolled_back = 0;
  std::size_t from_concave_corner = 0, from_convex_corner = 0, onto_corner = 0; // done Q-zips whose target is
                                                                               // a corner, whose end e is one
  std::size_t along_border_to_convex = 0, inside_end_at_concave = 0; // done Q-zips reaching a convex corner along
                                                                   // the border, ending inside next to a concave one
  std::size_t along_border_to_concave = 0; // done Q-zips reaching a concave corner along the border
  void add(const Border_move_counters& o)
  {
    done += o.done; cancelling += o.cancelling; moved += o.moved; reversed += o.reversed; redone += o.redone;
    redo_refused += o.redo_refused; rolled_back += o.rolled_back;
    from_concave_corner += o.from_concave_corner; from_convex_corner += o.from_convex_corner; onto_corner += o.onto_corner;
    along_border_to_convex += o.along_border_to_convex; inside_end_at_concave += o.inside_end_at_concave;
    along_border_to_concave += o.along_border_to_concave;
  }
  void print(const char* what) const
  {
    std::cout << "  " << what << ": " << done << " done (" << cancelling << " cancelling singularities, " << moved
              << " moving a border defect), " << reversed << " of the moves undone by their reverse Q-zip (isomorphic), "
              << redone << " redone by the reverse of the reverse and undone again (" << redo_refused << " redos refused), "
              << rolled_back << " rolled back; " << from_concave_corner << " from a concave corner, "
              << from_convex_corner << " from a convex corner (" << along_border_to_convex << " reached along the border), "
              << onto_corner << " onto a corner, " << inside_end_at_concave << " ending inside next to a concave corner, "
              << along_border_to_concave << " reaching a concave corner along the border" << std::endl;
  }
};

/// the positions of the vertices of `m`, sorted
template <typename Mesh>
std::vector<Point> sorted_positions(const Mesh& m)
{
  std::vector<Point> out;
  for(auto v : vertices(m)) out.push_back(get(CGAL::vertex_point, m, v));
  std::sort(out.begin(), out.end());
  return out;
}

/// the number of faces a regular vertex has at `v` (from the geometry): 4 inside, 2 on a straight
/// border, 1 at a convex corner, 3 at a concave one
template <typename Mesh>
int expected_faces(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m)
{
  int faces = 0;
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(!is_border(h, m)) ++faces;
  return faces - CGAL::Qzip::vertex_defect(v, m);
}

/// the numbers of faces the border vertices of `m` should have, as a multiset
template <typename Mesh>
std::multiset<int> border_face_counts(const Mesh& m)
{
  std::multiset<int> out;
  for(auto v : vertices(m)) if(on_border(v, m)) out.insert(expected_faces(v, m));
  return out;
}

/// The sketches from the interior singularity at `from` to the border vertex at `to`: the shortest
/// surgery path, and the paths that reach it along the border (mesh on the left, on the right); with
/// `through_border_neighbours`, instead, for each border neighbour u of `to`, the shortest surgery path to u
/// followed by u->to (the arrivals along the border from either side, at corners too).
template <typename Mesh>
std::vector<std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> >
border_end_sketches(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor from,
                    typename boost::graph_traits<Mesh>::vertex_descriptor to, bool through_border_neighbours = false)
{
  if(!through_border_neighbours)
    return { CGAL::Qzip::shortest_surgery_path(m, from, to), path_along_border(m, from, 12, true, 8, to),
             path_along_border(m, from, 12, false, 8, to) };
  std::vector<std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> > out;
  for(auto h : CGAL::halfedges_around_target(halfedge(to, m), m))
    if(is_border_edge(h, m))
    {
      auto p = CGAL::Qzip::shortest_surgery_path(m, from, source(h, m));
      if(p.empty() || std::find(p.begin(), p.end(), to) != p.end()) p.clear();
      else p.push_back(to);
      out.push_back(p);
    }
  return out;
}

/// the pairs (interior singularity, border vertex with defect +1 or -1) joined by a sketch of
/// `border_end_sketches()` of at most `max_length` edges, by position
template <typename Mesh>
std::vector<std::pair<Point, Point> > border_end_pairs(const Mesh& m, std::size_t max_length)
{
  std::vector<std::pair<Point, Point> > pairs;
  for(auto t : vertices(m))
  {
    if(!on_border(t, m) || std::abs(CGAL::Qzip::vertex_defect(t, m)) != 1) continue;
    for(auto s : vertices(m))
    {
      if(on_border(s, m) || (valence(s, m) != 3 && valence(s, m) != 5)) continue;
      for(const auto& sketch : border_end_sketches(m, s, t))
        if(sketch.size() >= 2 && sketch.size() <= max_length + 1)
        { pairs.emplace_back(get(CGAL::vertex_point, m, s), get(CGAL::vertex_point, m, t)); break; }
    }
  }
  return pairs;
}

/// Every pair of `border_end_pairs()`, every sketch of `border_end_sketches()`, four motions, each on
/// a fresh copy of `m`. A done Q-zip keeps the invariants and is undone exactly by its history; when it moved
/// the border defect (no singularity cancelled) it must have a reverse Q-zip, which gives back a mesh
/// isomorphic to `m`, and the reverse of that reverse (when the clean-up leaves it no choice) the mesh after
/// the Q-zip again, then its reverse `m` again.
template <typename Mesh>
Border_move_counters reverse_border_moves(const Mesh& m, std::size_t max_length,
                                          std::vector<Mesh>* onto_convex_corner = nullptr,
                                          bool through_border_neighbours = false)
{
  namespace Q = CGAL::Qzip;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Border_move_counters c;
  for(const auto& pair : border_end_pairs(m, max_length))
    for(int motion = 0; motion < 4; ++motion)
      for(std::size_t k = 0; k < 3; ++k)
      {
        Mesh work;
        copy_mesh(m, work);
        const std::map<Point, vertex_descriptor> at = vertices_by_position(work);
        const auto sketches = border_end_sketches(work, at.at(pair.first), at.at(pair.second), through_border_neighbours);
        if(k >= sketches.size()) continue;
        const auto& sketch = sketches[k];
        if(sketch.empty() || (through_border_neighbours && expected_faces(sketch.back(), work) == 2)) continue;
        std::vector<Point> sketch_points;
        for(vertex_descriptor v : sketch) sketch_points.push_back(get(CGAL::vertex_point, work, v));
        const auto plan = Q::plan_qzip(work, sketch, Q::Strip_operation(motion));
        if(!plan.is_realizable()) continue;
        const int target_faces = expected_faces(plan.target, work);
        const int end_faces = plan.path.back() != plan.target && on_border(plan.path.back(), work)
                                ? expected_faces(plan.path.back(), work) : 2;
        const auto at_target = std::find(plan.path.begin(), plan.path.end(), plan.target);
        const bool along_border = at_target != plan.path.begin() && is_border_edge(halfedge(*(at_target - 1), plan.target, work).first, work);
        const bool inside_end = !on_border(plan.path.back(), work);
        const int target_defect = CGAL::Qzip::vertex_defect(plan.target, work);
        const int end_defect = CGAL::Qzip::vertex_defect(plan.path.back(), work);
        const Point end_point = get(CGAL::vertex_point, work, plan.path.back());
        const Qzip_invariants<Mesh> invariants(work);
        Q::Qzip_history<Mesh> history(work);
        const auto r = Q::execute_qzip(work, plan, history);
        if(!r.is_done()) { ++c.rolled_back; assert(are_isomorphic(work, m)); continue; }
        ++c.done;
        c.from_concave_corner += target_faces == 3;
        c.from_convex_corner += target_faces == 1;
        c.onto_corner += end_faces != 2;
        c.along_border_to_convex += target_faces == 1 && along_border;
        c.inside_end_at_concave += target_faces == 3 && inside_end;
        c.along_border_to_concave += target_faces == 3 && along_border;
        const bool cancelled = invariants.check_after(work, r.number_of_splits, r.number_of_collapses);
        if(!cancelled && end_point != pair.second) // the defect moved onto e, as planned
          assert(Q::vertex_defect(vertices_by_position(work).at(end_point), work) == end_defect + target_defect);
        Mesh after;
        copy_mesh(work, after);
        history.undo_all();
        assert(CGAL::is_valid_polygon_mesh(work) && are_isomorphic(work, m) && sorted_positions(work) == sorted_positions(m));
        if(cancelled)
        {
          ++c.cancelling;
          assert(r.reverse_status == Q::Reverse_qzip_status::SINGULARITIES_CANCELLED);
          continue;
        }
        ++c.moved;
        if(end_faces == 1 && onto_convex_corner != nullptr) onto_convex_corner->push_back(after);
        // the same Q-zip on another copy, undone by its reverse Q-zip
        Mesh second;
        copy_mesh(m, second);
        const std::map<Point, vertex_descriptor> at2 = vertices_by_position(second);
        std::vector<vertex_descriptor> sketch2;
        for(const Point& p : sketch_points) sketch2.push_back(at2.at(p));
        const auto again = Q::execute_qzip(second, Q::plan_qzip(second, sketch2, Q::Strip_operation(motion)));
        assert(again.is_done() && are_isomorphic(second, after));
        assert(again.reverse_status == Q::Reverse_qzip_status::AVAILABLE);
        assert(on_border(again.reverse_plan.path.front(), second)); // the reverse starts at the border end
        const auto back = Q::reverse_qzip(second, again);
        assert(back.is_done() && CGAL::is_valid_polygon_mesh(second) && are_isomorphic(second, m));
        ++c.reversed;
        if(back.reverse_status != Q::Reverse_qzip_status::AVAILABLE)
        {
          assert(back.reverse_status == Q::Reverse_qzip_status::CLEANED_UP);
          ++c.redo_refused;
          continue;
        }
        const auto redo = Q::reverse_qzip(second, back);
        assert(redo.is_done() && are_isomorphic(second, after));
        ++c.redone;
        // a border copy of a split vertex keeps its place: no corner is cut off, after two Q-zips either
        assert(border_face_counts(second) == border_face_counts(after));
        const auto undo = Q::reverse_qzip(second, redo);
        assert(undo.is_done() && are_isomorphic(second, m));
      }
  return c;
}

/// An L-shaped grid: the unit squares of [0, nx] x [0, ny] but those of [cx, nx] x [cy, ny], with a
/// concave corner at (cx, cy), and chains of collapses planted in it: each chain runs along a straight
/// row or column from `chain[0]` (inside) to `chain[1]` (a border vertex) and collapses the quads on the
/// left of its edges (`chain[2]` = 1) or on their right (0), as a Q-zip chain would; it leaves a 3-5
/// pair at its start and a border step at its end: +1 at `chain[1]` and -1 at its border neighbour on
/// the side of the collapses. The inside is then relaxed (every inner vertex at the centroid of its
/// neighbours; the border is fixed).
template <typename Mesh>
void make_l_shape_with_chains(Mesh& m, int nx, int ny, int cx, int cy, const std::vector<std::array<int, 5> >& chains)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  clear(m);
  std::map<std::pair<int, int>, vertex_descriptor> at;
  auto square = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny && !(i >= cx && j >= cy); };
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      if(square(i, j) || square(i - 1, j) || square(i, j - 1) || square(i - 1, j - 1))
      {
        const vertex_descriptor v = add_vertex(m);
        put(get(CGAL::vertex_point, m), v, Point(i, j, 0));
        at[std::make_pair(i, j)] = v;
      }
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      if(square(i, j))
      {
        const std::vector<vertex_descriptor> q = { at[std::make_pair(i, j)], at[std::make_pair(i + 1, j)],
                                                   at[std::make_pair(i + 1, j + 1)], at[std::make_pair(i, j + 1)] };
        CGAL::Euler::add_face(q, m);
      }
  for(const std::array<int, 5>& chain : chains)
  {
    const int x0 = chain[0], y0 = chain[1], x1 = chain[2], y1 = chain[3];
    const int dx = (x1 > x0) - (x1 < x0), dy = (y1 > y0) - (y1 < y0);
    std::vector<vertex_descriptor> path;
    for(int x = x0, y = y0;; x += dx, y += dy) { path.push_back(at.at(std::make_pair(x, y))); if(x == x1 && y == y1) break; }
    for(std::size_t j = path.size() - 1; j-- > 0;) // from the border end, as make_grid_with_border_steps()
    {
      const auto o = halfedge(path[j], path[j + 1], m).first;
      const auto h = chain[4] == 1 ? o : prev(opposite(o, m), m);
      assert(CGAL::Qzip::can_collapse_quad(h, m));
      CGAL::Qzip::quad_collapse(h, m);
    }
  }
  relax_inside(m);
}

/// the L-shaped layouts of the tests (20 x 14, concave corner at (10, 7)): chains ending at the concave
/// corner (+1 there), next to it (-1 there), and next to the convex corners of a rectangle
inline std::vector<std::vector<std::array<int, 5> > > l_shape_layouts()
{
  return { { { 4, 7, 10, 7, 1 } }, { { 4, 7, 10, 7, 0 } }, { { 4, 8, 10, 8, 0 } }, { { 10, 2, 10, 7, 1 } },
           { { 10, 2, 10, 7, 0 } }, { { 3, 2, 10, 2, 1 }, { 15, 3, 15, 7, 0 } }, { { 1, 6, 1, 0, 1 }, { 19, 2, 19, 0, 0 } },
           { { 2, 12, 9, 12, 1 }, { 6, 10, 10, 10, 1 } } };
}

/// Q-zips that move a border defect (+1 reached through the mesh or along the border, -1 reached along
/// the border, both at a concave corner, and onto corners) on grids with border steps and on L-shaped grids
/// (both mesh types) and on the bundled meshes with borders: each one is undone by its reverse Q-zip.
inline void test_border_defect_reverse()
{
  Border_move_counters grids_sm, grids_ph, l_sm, l_ph, real;
  for(unsigned seed = 1; seed <= 4; ++seed)
  {
    Surface_mesh sm;
    make_grid_with_border_steps(sm, seed);
    grids_sm.add(reverse_border_moves(sm, 14));
    Polyhedron ph;
    make_grid_with_border_steps(ph, seed);
    grids_ph.add(reverse_border_moves(ph, 14));
  }
  std::vector<Surface_mesh> convex_sm;
  std::vector<Polyhedron> convex_ph;
  for(const auto& layout : l_shape_layouts())
  {
    Surface_mesh sm;
    make_l_shape_with_chains(sm, 20, 14, 10, 7, layout);
    l_sm.add(reverse_border_moves(sm, 12, &convex_sm));
    Polyhedron ph;
    make_l_shape_with_chains(ph, 20, 14, 10, 7, layout);
    l_ph.add(reverse_border_moves(ph, 12, &convex_ph));
  }
  // the meshes after a border defect moved onto a convex corner: from there
  assert(!convex_sm.empty() && convex_sm.size() == convex_ph.size());
  for(std::size_t i = 0; i < convex_sm.size(); ++i)
  {
    relax_inside(convex_sm[i]);
    l_sm.add(reverse_border_moves(convex_sm[i], 12));
    relax_inside(convex_ph[i]);
    l_ph.add(reverse_border_moves(convex_ph[i], 12));
  }
  // corners reached along the border from either side (the shortest path to a border neighbour, then to the corner)
  Border_move_counters along_sm, along_ph;
  for(const auto& layout : l_shape_layouts())
  {
    Surface_mesh sm;
    make_l_shape_with_chains(sm, 20, 14, 10, 7, layout);
    along_sm.add(reverse_border_moves<Surface_mesh>(sm, 12, nullptr, true));
    Polyhedron ph;
    make_l_shape_with_chains(ph, 20, 14, 10, 7, layout);
    along_ph.add(reverse_border_moves<Polyhedron>(ph, 12, nullptr, true));
  }
  for(std::size_t i = 0; i < convex_sm.size(); ++i)
  {
    along_sm.add(reverse_border_moves<Surface_mesh>(convex_sm[i], 12, nullptr, true));
    along_ph.add(reverse_border_moves<Polyhedron>(convex_ph[i], 12, nullptr, true));
  }
  for(const char* f : { "data/polylap_suzanne_half.obj", "data/trimesh_target.obj" })
  {
    Surface_mesh m;
    const bool ok = read_mesh(f, m);
    assert(ok);
    real.add(reverse_border_moves(m, 10));
  }
  grids_sm.print("border defects moved and reversed, grids with border steps, Surface_mesh");
  grids_ph.print("border defects moved and reversed, grids with border steps, Polyhedron_3");
  l_sm.print("border defects moved and reversed, L-shaped grids, Surface_mesh");
  l_ph.print("border defects moved and reversed, L-shaped grids, Polyhedron_3");
  real.print("border defects moved and reversed, bundled meshes with borders, Surface_mesh");
  along_sm.print("corners reached through each border neighbour, L-shaped grids, Surface_mesh");
  along_ph.print("corners reached through each border neighbour, L-shaped grids, Polyhedron_3");
  for(const Border_move_counters* c : { &grids_sm, &grids_ph, &l_sm, &l_ph, &real })
    assert(c->moved > 0 && c->reversed == c->moved && c->redone + c->redo_refused == c->moved);
  assert(grids_sm.done == grids_ph.done && grids_sm.moved == grids_ph.moved);
  assert(l_sm.done == l_ph.done && l_sm.moved == l_ph.moved && l_sm.from_concave_corner == l_ph.from_concave_corner);
  assert(l_sm.from_concave_corner > 0 && l_sm.from_convex_corner > 0 && l_sm.onto_corner > 0);
  assert(l_sm.from_convex_corner == l_ph.from_convex_corner);
  assert(l_sm.along_border_to_convex > 0 && l_sm.along_border_to_convex == l_ph.along_border_to_convex);
  assert(l_sm.inside_end_at_concave > 0 && l_sm.inside_end_at_concave == l_ph.inside_end_at_concave);
  assert(along_sm.along_border_to_convex > 0 && along_sm.along_border_to_concave > 0 && along_sm.rolled_back == 0);
  assert(along_sm.done == along_ph.done && along_sm.moved == along_ph.moved && along_ph.rolled_back == 0 &&
         along_sm.reversed == along_sm.moved && along_ph.reversed == along_ph.moved);
  // the plans that roll back on the bundled meshes are collapses in the middle of paths close to the border
  assert(grids_sm.rolled_back == 0 && grids_ph.rolled_back == 0 && l_sm.rolled_back == 0 && l_ph.rolled_back == 0);
}

} // namespace qzip_test

#endif // QZIP_BORDER_END_TESTS_H
