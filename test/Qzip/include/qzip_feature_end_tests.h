// Tests of feature end points: Q-zips from an interior singularity to a vertex on a feature curve (a vertex
// of a constrained edge) with one quad too many or too few in the sector the path arrives in. Every done
// Q-zip keeps the invariants, the feature edges, and is undone by its history and by its reverse Q-zip. The
// planted grids run on Surface_mesh (feature flags in a property of the mesh) and on Polyhedron_3 (in a dynamic
// edge property, an associative map); the CAD meshes on Surface_mesh.
#ifndef QZIP_FEATURE_END_TESTS_H
#define QZIP_FEATURE_END_TESTS_H

#include "qzip_test_utils.h"
#include "reverse_qzip_tests.h"
#include "qzip_border_end_tests.h"

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/singularities.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace qzip_test {

/// The feature flags of the edges of a mesh: a dynamic edge property (an associative map from the edges, which
/// the Q-zip keeps whole) for meshes without properties of their own, such as Polyhedron_3 ...
template <typename Mesh>
struct Feature_flags
{
  typedef typename boost::property_map<Mesh, CGAL::dynamic_edge_property_t<bool> >::type Map;
  static Map create(Mesh& m) { return get(CGAL::dynamic_edge_property_t<bool>(), m); }
};

/// ... and a property of the mesh for Surface_mesh ("e:qzip_test_feature")
template <>
struct Feature_flags<Surface_mesh>
{
  typedef Surface_mesh::Property_map<Surface_mesh::Edge_index, bool> Map;
  static Map create(Surface_mesh& m) { return m.add_property_map<Surface_mesh::Edge_index, bool>("e:qzip_test_feature", false).first; }
};

template <typename Mesh>
using Feature_map = typename Feature_flags<Mesh>::Map;

typedef std::set<std::pair<Point, Point> > Feature_segments; // the feature edges by the positions of their ends

inline std::pair<Point, Point> segment_key(const Point& a, const Point& b) { return std::minmax(a, b); }

template <typename Mesh>
const Point& position(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m)
{ return get(CGAL::vertex_point, m, v); }

template <typename Mesh>
std::pair<Point, Point> edge_key(typename boost::graph_traits<Mesh>::edge_descriptor e, const Mesh& m)
{ return segment_key(position(source(halfedge(e, m), m), m), position(target(halfedge(e, m), m), m)); }

/// the feature map of `m`, set on the edges whose ends are at the positions of `segments`
template <typename Mesh>
Feature_map<Mesh> mark_features(Mesh& m, const Feature_segments& segments)
{
  const Feature_map<Mesh> f = Feature_flags<Mesh>::create(m);
  for(auto e : edges(m)) put(f, e, segments.count(edge_key(e, m)) > 0);
  return f;
}

/// copies `m` into `out` with its feature edges `segments`, and returns the feature map of the copy
template <typename Mesh>
Feature_map<Mesh> copy_with_features(const Mesh& m, Mesh& out, const Feature_segments& segments)
{
  copy_mesh(m, out);
  return mark_features(out, segments);
}

/// the feature edges of `m` by the positions of their ends
template <typename Mesh>
Feature_segments feature_segments(const Mesh& m, const Feature_map<Mesh>& f)
{
  Feature_segments out;
  for(auto e : edges(m)) if(get(f, e)) out.insert(edge_key(e, m));
  return out;
}

/// the edges of `m` whose dihedral angle exceeds 60 degrees (as test_optimizer's features)
inline Feature_segments sharp_segments(const Surface_mesh& m, double degrees = 60.)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Feature_segments out;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m);
    if(is_border_edge(h, m)) continue;
    const auto n1 = PMP::compute_face_normal(face(h, m), m), n2 = PMP::compute_face_normal(face(opposite(h, m), m), m);
    if(n1 * n2 < std::cos(degrees * CGAL_PI / 180.)) out.insert(segment_key(m.point(source(h, m)), m.point(target(h, m))));
  }
  return out;
}

template <typename Mesh>
bool on_feature(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m, const Feature_map<Mesh>& f)
{
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(get(f, edge(h, m))) return true;
  return false;
}

/// whether the feature curve turns at `v` by more than 45 degrees, or branches or ends there
template <typename Mesh>
bool curve_turns_at(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m, const Feature_map<Mesh>& f)
{
  std::vector<Point> ends;
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(get(f, edge(h, m))) ends.push_back(position(source(h, m), m));
  return ends.size() != 2 || CGAL::approximate_angle(ends[0], position(v, m), ends[1]) < 135.;
}

/// The invariants of a Q-zip ending at a feature, measured on the whole mesh before it, independently of the
/// executor: a valid mesh, the same Euler characteristic, quads still quads, the same feature edges between the
/// same positions (the feature vertices keep their places), and no new singularity by the sector rule: an
/// interior vertex away from features is judged by its valence; a vertex on a feature or on the border by each
/// of its sectors (the faces between two consecutive feature or border edges around it), whose number of faces
/// is compared with the one it should have, frozen before from the geometry (a sector is named by the positions
/// of its vertex and of its two bounding edges, which the Q-zip does not move).
template <typename Mesh>
class Feature_invariants
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef qzip_test::Feature_map<Mesh> Feature_map;
  typedef std::tuple<Point, Point, Point> Sector_key;

  long chi;
  std::size_t faces = 0;
  Feature_segments segments;
  std::map<Sector_key, int> expected;
  std::vector<int> codes;

  static bool is_cut_vertex(vertex_descriptor v, const Mesh& m, const Feature_map& fm)
  { return on_border(v, m) || on_feature(v, m, fm); }

public:
  /// calls f(key, faces, angle) for every sector of the cut vertex v, named by the positions of v and of the
  /// far ends of its two bounding edges
  template <typename F>
  static void for_each_sector(vertex_descriptor v, const Mesh& m, const Feature_map& fm, F f)
  {
    auto is_cut = [&](halfedge_descriptor h) { return is_border_edge(h, m) || get(fm, edge(h, m)); };
    halfedge_descriptor start = boost::graph_traits<Mesh>::null_halfedge();
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(is_cut(h)) { start = h; break; }
    int q = 0;
    double theta = 0;
    halfedge_descriptor first = start;
    for(auto h : CGAL::halfedges_around_target(start, m))
    {
      if(!is_border(h, m))
      {
        theta += CGAL::approximate_angle(position(source(h, m), m), position(v, m), position(target(next(h, m), m), m)) * CGAL_PI / 180.;
        ++q;
      }
      if(is_cut(next(h, m)))
      {
        if(q > 0) f(Sector_key(position(v, m), position(source(first, m), m), position(target(next(h, m), m), m)), q, theta);
        first = opposite(next(h, m), m);
        q = 0;
        theta = 0;
      }
    }
  }

  Feature_invariants(const Mesh& m, const Feature_map& fm)
    : chi(euler_characteristic(m)), faces(CGAL::faces(m).size()), segments(feature_segments(m, fm))
  {
    for(vertex_descriptor v : vertices(m))
      if(is_cut_vertex(v, m, fm))
        for_each_sector(v, m, fm, [&](const Sector_key& k, int, double theta)
        { expected[k] = CGAL::Qzip::internal::ideal_number_of_faces(theta); });
    codes = singularity_codes(m, fm);
  }

  /// the sorted singularity codes: the valence of an irregular interior vertex, 100 + the defect of an
  /// irregular sector
  std::vector<int> singularity_codes(const Mesh& m, const Feature_map& fm) const
  {
    std::vector<int> out;
    for(vertex_descriptor v : vertices(m))
    {
      if(!is_cut_vertex(v, m, fm)) { if(valence(v, m) != 4) out.push_back(valence(v, m)); continue; }
      for_each_sector(v, m, fm, [&](const Sector_key& k, int q, double theta)
      {
        const auto it = expected.find(k);
        const int d = q - (it != expected.end() ? it->second : CGAL::Qzip::internal::ideal_number_of_faces(theta));
        if(d != 0) out.push_back(100 + d);
      });
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  /// the feature edges by position, as before
  bool same_features(const Mesh& m, const Feature_map& fm) const { return feature_segments(m, fm) == segments; }

  /// asserts the invariants after a done Q-zip; returns whether singularities were cancelled
  bool check_after(const Mesh& m, const Feature_map& fm, std::size_t splits, std::size_t collapses) const
  {
    assert(CGAL::is_valid_polygon_mesh(m) && all_faces_have_degree(m, 4));
    assert(euler_characteristic(m) == chi);
    assert(long(CGAL::faces(m).size()) - long(faces) == long(splits) - long(collapses));
    assert(same_features(m, fm));
    const std::vector<int> after = singularity_codes(m, fm);
    assert(std::includes(codes.begin(), codes.end(), after.begin(), after.end()));
    return after != codes;
  }
};

/// how the Q-zips to feature end points went
struct Feature_move_counters
{
  std::size_t plans = 0, done = 0, cancelling = 0, moved = 0, reversed = 0, rolled_back = 0;
  std::size_t onto_other_defect = 0; // done moves whose continuation e was itself irregular
  std::size_t with_quad_too_few = 0, at_turn = 0; // done Q-zips whose target has defect -1, lies where its curve turns
  std::map<CGAL::Qzip::Plan_status, std::size_t> refused;
  std::map<CGAL::Qzip::Reverse_qzip_status, std::size_t> no_reverse;
  std::map<CGAL::Qzip::Execution_failure, std::size_t> predicted; // EXECUTION_WOULD_FAIL, by predicted failure
  void add(const Feature_move_counters& o)
  {
    plans += o.plans; done += o.done; cancelling += o.cancelling; moved += o.moved; reversed += o.reversed;
    rolled_back += o.rolled_back; onto_other_defect += o.onto_other_defect;
    with_quad_too_few += o.with_quad_too_few; at_turn += o.at_turn;
    for(const auto& r : o.refused) refused[r.first] += r.second;
    for(const auto& r : o.no_reverse) no_reverse[r.first] += r.second;
    for(const auto& r : o.predicted) predicted[r.first] += r.second;
  }
  void print(const std::string& what) const
  {
    std::cout << "  " << what << ": " << plans << " plans, " << done << " done (" << cancelling
              << " cancelling singularities, " << moved << " moving a feature defect), " << reversed
              << " undone by their reverse Q-zip, " << rolled_back << " rolled back; " << with_quad_too_few
              << " from a defect -1, " << at_turn << " from where the curve turns, " << onto_other_defect
              << " onto another defect; refused by status:";
    for(const auto& r : refused) std::cout << " " << int(r.first) << "x" << r.second;
    std::cout << "; predicted failures (each failing when forced):";
    for(const auto& r : predicted) std::cout << " " << int(r.first) << "x" << r.second;
    std::cout << "; no reverse:";
    for(const auto& r : no_reverse) std::cout << " " << int(r.first) << "x" << r.second;
    std::cout << std::endl;
  }
};

/// The sketches from the interior singularity `s` to the feature vertex `t`: the shortest surgery path, and
/// for each neighbour `u` of `t` through which a path may pass, the shortest surgery path to `u` followed by
/// `u->t` (arrivals from every direction), when simple and of at most `max_length` edges.
template <typename Mesh, typename vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor>
std::vector<std::vector<vertex_descriptor> >
feature_end_sketches(const Mesh& m, const Feature_map<Mesh>& fm, vertex_descriptor s, vertex_descriptor t, std::size_t max_length)
{
  namespace Q = CGAL::Qzip;
  std::vector<std::vector<vertex_descriptor> > out;
  auto keep = [&](const std::vector<vertex_descriptor>& p)
  {
    if(p.size() < 2 || p.size() > max_length + 1) return;
    std::vector<vertex_descriptor> sorted(p);
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return;
    if(std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  };
  keep(Q::shortest_surgery_path(m, s, t, CGAL::parameters::edge_is_constrained_map(fm)));
  for(auto h : CGAL::halfedges_around_target(halfedge(t, m), m))
  {
    const auto u = source(h, m);
    if(u == s || on_border(u, m) || on_feature(u, m, fm)) continue;
    auto p = Q::shortest_surgery_path(m, s, u, CGAL::parameters::edge_is_constrained_map(fm));
    if(p.empty()) continue;
    p.push_back(t);
    keep(p);
  }
  return out;
}

/// the vertices at most `radius` edges from `t`
template <typename Mesh, typename vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor>
std::set<vertex_descriptor> ball(const Mesh& m, vertex_descriptor t, std::size_t radius)
{
  std::set<vertex_descriptor> seen = { t };
  std::vector<vertex_descriptor> ring = { t };
  for(std::size_t k = 0; k < radius; ++k)
  {
    std::vector<vertex_descriptor> next_ring;
    for(auto v : ring)
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
        if(seen.insert(source(h, m)).second) next_ring.push_back(source(h, m));
    ring.swap(next_ring);
  }
  return seen;
}

/// the plan of the sketch through the positions `sketch` on `m` (a copy of the mesh the sketch was found on)
template <typename Mesh>
CGAL::Qzip::Surgery_plan<Mesh> plan_on_copy(const Mesh& m, const Feature_map<Mesh>& fm, const std::vector<Point>& sketch,
                                            CGAL::Qzip::Strip_operation motion)
{
  const auto at = vertices_by_position(m);
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> path;
  for(const Point& p : sketch) path.push_back(at.at(p));
  return CGAL::Qzip::plan_qzip(m, path, motion, CGAL::parameters::edge_is_constrained_map(fm));
}

/// Every interior singularity within `max_length` edges of a feature vertex with defect +1 or -1 (at most
/// `max_targets` of them), every sketch of `feature_end_sketches()`, four motions. A realizable plan is executed
/// on a copy of `m` (with the feature edges `segments`): the Q-zip keeps the invariants (Feature_invariants) and
/// is undone exactly by its history; when it moved the feature defect it must have a reverse Q-zip, which gives
/// back a mesh isomorphic to `m` with the same feature edges (checked on another copy: the history, which undoes
/// the Q-zip on the first, re-creates elements with new descriptors).
template <typename Mesh>
Feature_move_counters feature_end_moves(const Mesh& m, const Feature_segments& segments,
                                        std::size_t max_length, std::size_t max_targets)
{
  namespace Q = CGAL::Qzip;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Feature_move_counters c;
  Mesh base;
  const Feature_map<Mesh> fbase = copy_with_features(m, base, segments);
  const auto np_base = CGAL::parameters::edge_is_constrained_map(fbase);
  std::size_t targets = 0;
  for(vertex_descriptor t : vertices(base))
  {
    if(targets == max_targets) break;
    if(on_border(t, base) || !on_feature(t, base, fbase) || std::abs(Q::vertex_defect(t, base, np_base)) != 1) continue;
    ++targets;
    for(vertex_descriptor s : ball(base, t, max_length))
    {
      if(on_border(s, base) || on_feature(s, base, fbase) || (valence(s, base) != 3 && valence(s, base) != 5)) continue;
      for(const auto& sketch : feature_end_sketches(base, fbase, s, t, max_length))
        for(int motion = 0; motion < 4; ++motion)
        {
          ++c.plans;
          const auto plan = Q::plan_qzip(base, sketch, Q::Strip_operation(motion), np_base);
          if(!plan.is_realizable() && plan.status != Q::Plan_status::EXECUTION_WOULD_FAIL)
          {
            ++c.refused[plan.status];
            continue;
          }
          std::vector<Point> sketch_points;
          for(vertex_descriptor v : sketch) sketch_points.push_back(position(v, base));
          Mesh work;
          const Feature_map<Mesh> fm = copy_with_features(base, work, segments);
          const auto np = CGAL::parameters::edge_is_constrained_map(fm);
          const auto plan_work = plan_on_copy(work, fm, sketch_points, Q::Strip_operation(motion));
          assert(plan_work.status == plan.status && plan_work.path.size() == plan.path.size());
          if(!plan.is_realizable())
          {
            ++c.refused[plan.status];
            // the simulation's prediction: forced through the executor, the plan fails and is rolled back
            ++c.predicted[plan.predicted_failure];
            Q::Surgery_plan<Mesh> forced = plan_work;
            forced.status = Q::Plan_status::REALIZABLE;
            const auto r = Q::execute_qzip(work, forced, np);
            assert(!r.is_done() && r.failure == plan.predicted_failure);
            assert(are_isomorphic(work, base) && feature_segments(work, fm) == segments);
            continue;
          }
          assert(plan.target == t);
          const vertex_descriptor end = plan.path.back();
          const int end_defect = Q::vertex_defect(end, base, np_base);
          const Feature_invariants<Mesh> invariants(work, fm);
          Q::Qzip_history<Mesh> history(work);
          const auto r = Q::execute_qzip(work, plan_work, history, np);
          if(!r.is_done())
          {
            ++c.rolled_back;
            assert(are_isomorphic(work, base) && invariants.same_features(work, fm));
            continue;
          }
          ++c.done;
          c.with_quad_too_few += Q::vertex_defect(t, base, np_base) == -1;
          c.at_turn += curve_turns_at(t, base, fbase);
          const bool cancelled = invariants.check_after(work, fm, r.number_of_splits, r.number_of_collapses);
          if(!cancelled && end != t)
          {
            // the defect left the target for the end of the path, a feature vertex that kept its place
            const vertex_descriptor end_after = vertices_by_position(work).at(position(end, base));
            assert(on_feature(end_after, work, fm));
            assert(Q::vertex_defect(end_after, work, np) == end_defect + Q::vertex_defect(t, base, np_base));
          }
          history.undo_all();
          assert(CGAL::is_valid_polygon_mesh(work) && are_isomorphic(work, base) && invariants.same_features(work, fm));
          assert(sorted_positions(work) == sorted_positions(base));
          if(cancelled)
          {
            ++c.cancelling;
            assert(r.reverse_status == Q::Reverse_qzip_status::SINGULARITIES_CANCELLED);
            continue;
          }
          ++c.moved;
          c.onto_other_defect += end_defect != 0;
          // the same Q-zip on another copy, undone by its reverse Q-zip
          if(r.reverse_status != Q::Reverse_qzip_status::AVAILABLE) { ++c.no_reverse[r.reverse_status]; continue; }
          Mesh second;
          const Feature_map<Mesh> f2 = copy_with_features(base, second, segments);
          const auto np2 = CGAL::parameters::edge_is_constrained_map(f2);
          const auto again = Q::execute_qzip(second, plan_on_copy(second, f2, sketch_points, Q::Strip_operation(motion)), np2);
          assert(again.is_done() && again.reverse_status == Q::Reverse_qzip_status::AVAILABLE);
          const auto back = Q::reverse_qzip(second, again, np2);
          assert(back.is_done() && CGAL::is_valid_polygon_mesh(second) && are_isomorphic(second, base));
          assert(invariants.same_features(second, f2));
          ++c.reversed;
        }
    }
  }
  return c;
}

/// removes the elements marked as removed (Surface_mesh), so that the vertices are numbered from 0 again
inline void collect_garbage(Surface_mesh& m) { m.collect_garbage(); }
/// nothing to do for the other meshes
template <typename Mesh> void collect_garbage(Mesh&) {}

/// A flat nx x ny grid with a feature polyline through grid points (`polyline`, axis-parallel steps) and chains of
/// collapses planted in it as in make_l_shape_with_chains(): each chain runs along a row or column from
/// `chain[0], chain[1]` (inside) to `chain[2], chain[3]` (on the feature) and collapses the quads on the left of
/// its edges (`chain[4]` = 1) or on their right (0), leaving a 3-5 pair at its start and a feature step at its
/// end. The vertices off the feature and the border are then relaxed. Returns the feature edges.
template <typename Mesh>
Feature_segments make_grid_with_feature(Mesh& m, int nx, int ny, const std::vector<std::array<int, 2> >& polyline,
                                        const std::vector<std::array<int, 5> >& chains)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  make_quad_grid(m, nx, ny);
  std::map<std::pair<int, int>, vertex_descriptor> at;
  for(vertex_descriptor v : vertices(m))
    at[std::make_pair(int(std::lround(position(v, m).x())), int(std::lround(position(v, m).y())))] = v;
  Feature_segments segments;
  for(std::size_t k = 0; k + 1 < polyline.size(); ++k)
  {
    const int dx = (polyline[k + 1][0] > polyline[k][0]) - (polyline[k + 1][0] < polyline[k][0]);
    const int dy = (polyline[k + 1][1] > polyline[k][1]) - (polyline[k + 1][1] < polyline[k][1]);
    for(int x = polyline[k][0], y = polyline[k][1]; x != polyline[k + 1][0] || y != polyline[k + 1][1]; x += dx, y += dy)
      segments.insert(segment_key(position(at.at(std::make_pair(x, y)), m), position(at.at(std::make_pair(x + dx, y + dy)), m)));
  }
  for(const std::array<int, 5>& chain : chains)
  {
    const int x0 = chain[0], y0 = chain[1], x1 = chain[2], y1 = chain[3];
    const int dx = (x1 > x0) - (x1 < x0), dy = (y1 > y0) - (y1 < y0);
    std::vector<vertex_descriptor> path;
    for(int x = x0, y = y0;; x += dx, y += dy) { path.push_back(at.at(std::make_pair(x, y))); if(x == x1 && y == y1) break; }
    for(std::size_t j = path.size() - 1; j-- > 0;)
    {
      const auto o = halfedge(path[j], path[j + 1], m).first;
      const auto h = chain[4] == 1 ? o : prev(opposite(o, m), m);
      assert(CGAL::Qzip::can_collapse_quad(h, m));
      CGAL::Qzip::quad_collapse(h, m);
    }
  }
  collect_garbage(m);
  std::set<Point> fixed;
  for(const auto& s : segments) { fixed.insert(s.first); fixed.insert(s.second); }
  const auto vpm = get(CGAL::vertex_point, m);
  for(int it = 0; it < 30; ++it)
    for(vertex_descriptor v : vertices(m))
    {
      if(on_border(v, m) || fixed.count(get(vpm, v))) continue;
      double x = 0, y = 0, n = 0;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) { x += get(vpm, source(h, m)).x(); y += get(vpm, source(h, m)).y(); ++n; }
      put(vpm, v, Point(x / n, y / n, 0));
    }
  return segments;
}

/// `m` with a chain of collapses planted as in make_grid_with_feature(), on a real mesh: from the `skip`-th
/// feature vertex of valence 4 that has a straight run of `length` interior vertices of valence 4 off the
/// features leaving it, the quads on the left of the run collapse towards
/// the feature (the feature vertex keeps its place and its feature edges), leaving a 3-5 pair at the far end
/// and a feature step at the feature vertex. False when there is no such run, or a collapse would merge a
/// feature or border vertex away.
inline bool plant_feature_chain(Surface_mesh& m, const Feature_segments& segments, std::size_t skip, std::size_t length)
{
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor vertex_descriptor;
  const Feature_map<Surface_mesh> f = mark_features(m, segments);
  auto regular_inside = [&](vertex_descriptor v) { return !on_border(v, m) && valence(v, m) == 4 && !on_feature(v, m, f); };
  for(vertex_descriptor t : vertices(m))
  {
    if(on_border(t, m) || valence(t, m) != 4 || !on_feature(t, m, f)) continue;
    for(auto h : CGAL::halfedges_around_source(t, m))
    {
      if(get(f, edge(h, m))) continue;
      std::vector<vertex_descriptor> run = { t };
      for(auto o = h; run.size() <= length && regular_inside(target(o, m));
          o = next(opposite(next(o, m), m), m)) // straight on through a valence-4 vertex
        run.push_back(target(o, m));
      if(run.size() <= length) continue;
      if(skip-- > 0) break;
      std::reverse(run.begin(), run.end());
      for(std::size_t j = run.size() - 1; j-- > 0;)
      {
        const auto o = halfedge(run[j], run[j + 1], m).first;
        const vertex_descriptor merged = target(next(next(o, m), m), m);
        if(!CGAL::Qzip::can_collapse_quad(o, m) || on_feature(merged, m, f) || on_border(merged, m)) return false;
        CGAL::Qzip::quad_collapse(o, m);
      }
      m.collect_garbage();
      return true;
    }
  }
  return false;
}

/// On the grid with a +1 planted on a straight feature line: a sketch from the feature defect to the interior
/// singularity is planned reversed (the same plan as the sketch from the singularity), and a sketch that arrives
/// along a feature edge is refused.
inline void test_feature_end_sketch_orientation()
{
  namespace Q = CGAL::Qzip;
  Surface_mesh m;
  const Feature_segments segments = make_grid_with_feature(m, 16, 12, { { { 0, 6 } }, { { 16, 6 } } }, { { { 5, 1, 5, 6, 1 } } });
  const Feature_map<Surface_mesh> f = mark_features(m, segments);
  const auto np = CGAL::parameters::edge_is_constrained_map(f);
  std::size_t realizable = 0, along = 0;
  for(auto t : vertices(m))
  {
    if(on_border(t, m) || !on_feature(t, m, f) || Q::vertex_defect(t, m, np) != 1) continue;
    for(auto s : vertices(m))
    {
      if(on_border(s, m) || on_feature(s, m, f) || (valence(s, m) != 3 && valence(s, m) != 5)) continue;
      const auto sketch = Q::shortest_surgery_path(m, s, t, np);
      if(sketch.empty()) continue;
      for(int motion = 0; motion < 4; ++motion)
      {
        const auto plan = Q::plan_qzip(m, sketch, Q::Strip_operation(motion), np);
        const auto reversed = Q::plan_qzip(m, std::vector<Surface_mesh::Vertex_index>(sketch.rbegin(), sketch.rend()),
                                           Q::Strip_operation(motion), np);
        assert(reversed.status == plan.status && reversed.path == plan.path && reversed.operations == plan.operations);
        realizable += plan.is_realizable();
      }
      // the shortest surgery path to a neighbour x of t along the feature, then x -> t
      for(auto h : CGAL::halfedges_around_target(halfedge(t, m), m))
        if(get(f, edge(h, m)) && !on_border(source(h, m), m))
        {
          auto along_feature = Q::shortest_surgery_path(m, s, source(h, m), np);
          if(along_feature.empty() || std::find(along_feature.begin(), along_feature.end(), t) != along_feature.end()) continue;
          along_feature.push_back(t);
          for(int motion = 0; motion < 4; ++motion)
          {
            const auto plan = Q::plan_qzip(m, along_feature, Q::Strip_operation(motion), np);
            assert(!plan.is_realizable());
            along += plan.status == Q::Plan_status::ENDPOINT_ADJUSTMENT;
          }
        }
    }
  }
  std::cout << "  feature ends: " << realizable << " realizable plans equal to those of the reversed sketches, " << along
            << " arrivals along a feature edge refused (ENDPOINT_ADJUSTMENT)" << std::endl;
  assert(realizable > 0 && along > 0);
}

/// `p` once the plane is folded at `apex`: around `apex`, the polar angles (from the direction +x) of the upper
/// half-plane, (0, pi), are squeezed into (pi - upper, pi) and those of the lower one, (pi, 2 pi), stretched over
/// (pi, 3 pi - upper). The ray towards -x stays in place (exactly), the ray towards +x turns to the angle pi - upper,
/// and no face turns over: a feature line along y = apex.y turns sharply at `apex`, whose faces above it then span
/// the angle `upper` and those below 2 pi - upper.
inline Point folded_at(const Point& p, const Point& apex, double upper)
{
  const double dx = p.x() - apex.x(), dy = p.y() - apex.y();
  if(dy == 0 && dx <= 0) return p;
  const double phi = dy < 0 ? std::atan2(dy, dx) + 2 * CGAL_PI : std::atan2(dy, dx);
  const double image = phi <= CGAL_PI ? CGAL_PI - upper + phi * upper / CGAL_PI
                                      : CGAL_PI + (phi - CGAL_PI) * (2 * CGAL_PI - upper) / CGAL_PI;
  const double r = std::sqrt(dx * dx + dy * dy);
  return Point(apex.x() + r * std::cos(image), apex.y() + r * std::sin(image), p.z());
}

/// the sectors of the feature vertex `v` (Feature_invariants::for_each_sector()), each with its number of faces and
/// the number of quads it should have, named by positions mapped by `rename`
template <typename Mesh, typename Rename>
std::map<std::tuple<Point, Point, Point>, std::pair<int, int> >
sectors_of(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m, const Feature_map<Mesh>& fm, Rename rename)
{
  std::map<std::tuple<Point, Point, Point>, std::pair<int, int> > out;
  Feature_invariants<Mesh>::for_each_sector(v, m, fm, [&](const std::tuple<Point, Point, Point>& k, int q, double theta)
  {
    out[std::make_tuple(rename(std::get<0>(k)), rename(std::get<1>(k)), rename(std::get<2>(k)))] =
      std::make_pair(q, CGAL::Qzip::internal::ideal_number_of_faces(theta));
  });
  return out;
}

/// The executor's sector check deciding (manual, "Feature End Points"): the grid of test_feature_end_moves() with a
/// +1 planted below the straight feature line at t = (5, 6), then folded at its neighbour e = (6, 6) on the line
/// (folded_at(), 45 degrees above the line): e keeps its two faces on each side, but should have one above (+1) and
/// four below (-2), a defect -1 in all. A Q-zip that moves the +1 of t into e (a move on the flat grid, where it is
/// done) gives e a third face below: as totals, t and e become regular (+1 and -1 cancel, which the check of the
/// vertices' defects accepts), but sector by sector the -2 below e becomes a -1, a singularity that was not there
/// (the sector check refuses what is not a sub-multiset, as it refuses a quad traded between two sectors). For each
/// such surgery, found on the flat grid: the plan on the folded grid is refused by its simulation
/// (`EXECUTION_WOULD_FAIL`, `SINGULARITY_CREATED`); planned without simulation it is the same surgery, whose
/// execution is rolled back (`SINGULARITY_CREATED`) leaving the mesh as it was, positions and features included;
/// the sector counts after it are measured on the flat grid, where it is done (same connectivity, only the numbers
/// of quads e should have differ). Returns the number of such surgeries.
template <typename Mesh>
std::size_t sector_check_refusals()
{
  namespace Q = CGAL::Qzip;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const Point apex(6, 6, 0), t_at(5, 6, 0);
  const auto fold = [&apex](const Point& p) { return folded_at(p, apex, CGAL_PI / 4); };
  Mesh flat;
  const Feature_segments flat_segments = make_grid_with_feature(flat, 16, 12, { { { 0, 6 } }, { { 16, 6 } } }, { { { 5, 1, 5, 6, 1 } } });
  const Feature_map<Mesh> fflat = mark_features(flat, flat_segments);
  const auto np_flat = CGAL::parameters::edge_is_constrained_map(fflat);
  Mesh folded;
  copy_mesh(flat, folded);
  for(vertex_descriptor v : vertices(folded)) put(get(CGAL::vertex_point, folded), v, fold(position(v, folded)));
  Feature_segments segments;
  for(const auto& sg : flat_segments) segments.insert(segment_key(fold(sg.first), fold(sg.second)));
  const Feature_map<Mesh> ffolded = mark_features(folded, segments);
  const auto np_folded = CGAL::parameters::edge_is_constrained_map(ffolded);

  const vertex_descriptor t = vertices_by_position(folded).at(t_at), e = vertices_by_position(folded).at(apex);
  const vertex_descriptor flat_t = vertices_by_position(flat).at(t_at);
  assert(Q::vertex_defect(flat_t, flat, np_flat) == 1 && Q::vertex_defect(vertices_by_position(flat).at(apex), flat, np_flat) == 0);
  assert(Q::vertex_defect(t, folded, np_folded) == 1 && Q::vertex_defect(e, folded, np_folded) == -1);
  const auto identity = [](const Point& p) { return p; };
  const auto e_before = sectors_of(e, folded, ffolded, identity);
  std::multiset<int> e_defects_before;
  for(const auto& sc : e_before) e_defects_before.insert(sc.second.first - sc.second.second);
  assert(e_defects_before == std::multiset<int>({ -2, 1 }));

  std::size_t refused = 0;
  for(vertex_descriptor s : ball(flat, flat_t, 10))
  {
    if(on_border(s, flat) || on_feature(s, flat, fflat) || (valence(s, flat) != 3 && valence(s, flat) != 5)) continue;
    for(const auto& sketch : feature_end_sketches(flat, fflat, s, flat_t, 10))
      for(int motion = 0; motion < 4; ++motion)
      {
        const auto plan = Q::plan_qzip(flat, sketch, Q::Strip_operation(motion), np_flat);
        if(!plan.is_realizable() || position(plan.path.back(), flat) != apex) continue;
        std::vector<Point> sketch_points;
        for(vertex_descriptor v : sketch) sketch_points.push_back(position(v, flat));
        // on the flat grid, the +1 of t moves into e, below the line, and e has a third face there
        Mesh moved;
        const Feature_map<Mesh> fmoved = copy_with_features(flat, moved, flat_segments);
        const auto done = Q::execute_qzip(moved, plan_on_copy(moved, fmoved, sketch_points, Q::Strip_operation(motion)),
                                          CGAL::parameters::edge_is_constrained_map(fmoved));
        assert(done.is_done() && done.reverse_status != Q::Reverse_qzip_status::SINGULARITIES_CANCELLED);
        // besides t and e, it touched interior vertices off the features only, which the executor judges by their
        // valences, the same on both grids
        for(vertex_descriptor v : done.touched_vertices)
          assert(!on_border(v, moved) && (!on_feature(v, moved, fmoved) || position(v, moved) == t_at || position(v, moved) == apex));
        const auto at_moved = vertices_by_position(moved);
        assert(Q::vertex_defect(at_moved.at(t_at), moved, CGAL::parameters::edge_is_constrained_map(fmoved)) == 0);
        // the sectors of e after the surgery, with the numbers of quads they should have on the folded grid
        const auto e_after = sectors_of(at_moved.at(apex), moved, fmoved, fold);
        assert(e_after.size() == e_before.size());
        int e_total_after = 0;
        std::multiset<int> e_defects_after;
        for(const auto& sc : e_after)
        {
          const int defect = sc.second.first - e_before.at(sc.first).second;
          e_total_after += defect;
          e_defects_after.insert(defect);
        }
        assert(e_total_after == 0); // t and e regular as totals: the check of the vertices' codes accepts
        assert(e_defects_after == std::multiset<int>({ -1, 1 })); // a -1 below e, new: the sector check refuses

        std::vector<Point> folded_sketch;
        for(const Point& p : sketch_points) folded_sketch.push_back(fold(p));
        const auto refusal = plan_on_copy(folded, ffolded, folded_sketch, Q::Strip_operation(motion));
        assert(refusal.status == Q::Plan_status::EXECUTION_WOULD_FAIL &&
               refusal.predicted_failure == Q::Execution_failure::SINGULARITY_CREATED);
        Mesh work;
        const Feature_map<Mesh> fwork = copy_with_features(folded, work, segments);
        const auto np_work = CGAL::parameters::edge_is_constrained_map(fwork);
        const auto at_work = vertices_by_position(work);
        std::vector<vertex_descriptor> path;
        for(const Point& p : folded_sketch) path.push_back(at_work.at(p));
        const auto forced = Q::plan_qzip(work, path, Q::Strip_operation(motion), Q::parameters::simulate_chain(false, np_work));
        assert(forced.is_realizable() && forced.operations == plan.operations && forced.path.size() == plan.path.size());
        for(std::size_t j = 0; j < plan.path.size(); ++j)
          assert(position(forced.path[j], work) == fold(position(plan.path[j], flat)));
        const auto r = Q::execute_qzip(work, forced, np_work);
        assert(!r.is_done() && r.failure == Q::Execution_failure::SINGULARITY_CREATED);
        assert(CGAL::is_valid_polygon_mesh(work) && are_isomorphic(work, folded));
        assert(sorted_positions(work) == sorted_positions(folded) && feature_segments(work, fwork) == segments);
        ++refused;
      }
  }
  return refused;
}

/// counts the valence-6 clean-up splits (Sec. 2.7) at a vertex next to a feature, and those whose delimiters are
/// feature vertices: the chain's own splits are at path vertices, of valence 3 to 5 (a v5 start, a transient)
template <typename Mesh>
struct Cleanup_next_to_feature : CGAL::Qzip::Default_qzip_visitor<Mesh>
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  const Feature_map<Mesh>* fm = nullptr;
  std::size_t next_to_feature = 0, feature_delimiters = 0;
  void on_split(halfedge_descriptor h1, halfedge_descriptor h2, const Mesh& m)
  {
    const auto v = target(h1, m);
    if(valence(v, m) != 6) return;
    bool near = false;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) near = near || on_feature(source(h, m), m, *fm);
    next_to_feature += near;
    feature_delimiters += on_feature(source(h1, m), m, *fm) || on_feature(source(h2, m), m, *fm);
  }
};

/// The valence-6 clean-up next to a feature line: on a grid with a straight feature line and two chains of
/// collapses planted along rows next to it (their 3-5 pairs one and two rows from the line), Q-zips between every
/// two interior singularities (shortest surgery path, four motions) that leave a valence-6 vertex next to the line.
/// The clean-up splits it between two opposite neighbours of valence 4, which each gain an edge: a feature vertex
/// of valence 4 would take a quad too many in one of its sectors, so it is never chosen as a delimiter (before, the
/// executor chose it and then refused the new feature defect: 2 plans of this grid were refused by the simulation,
/// and the optimizer rolled back one surgery on quadwild_joint at 60 degrees). Every plan the local checks pass is
/// done, keeps the invariants (Feature_invariants) and is undone exactly. Returns the number of those with a
/// clean-up split next to the line.
template <typename Mesh>
std::size_t valence_6_cleanups_next_to_feature()
{
  namespace Q = CGAL::Qzip;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Mesh base;
  const Feature_segments segments = make_grid_with_feature(base, 16, 12, { { { 0, 6 } }, { { 16, 6 } } },
                                                           { { { 3, 2, 5, 2, 1 } }, { { 12, 7, 10, 7, 0 } } });
  const Feature_map<Mesh> fbase = mark_features(base, segments);
  const auto np_base = CGAL::parameters::edge_is_constrained_map(fbase);
  std::vector<vertex_descriptor> singular;
  for(vertex_descriptor v : vertices(base))
    if(!on_border(v, base) && !on_feature(v, base, fbase) && (valence(v, base) == 3 || valence(v, base) == 5)) singular.push_back(v);
  std::size_t with_cleanup = 0;
  for(vertex_descriptor s : singular)
    for(vertex_descriptor t : singular)
    {
      const auto sketch = s == t ? std::vector<vertex_descriptor>() : Q::shortest_surgery_path(base, s, t, np_base);
      if(sketch.empty()) continue;
      std::vector<Point> sketch_points;
      for(vertex_descriptor v : sketch) sketch_points.push_back(position(v, base));
      for(int motion = 0; motion < 4; ++motion)
      {
        const auto plan = Q::plan_qzip(base, sketch, Q::Strip_operation(motion), np_base);
        assert(plan.status != Q::Plan_status::EXECUTION_WOULD_FAIL);
        if(!plan.is_realizable()) continue;
        Mesh work;
        const Feature_map<Mesh> fm = copy_with_features(base, work, segments);
        Cleanup_next_to_feature<Mesh> watcher;
        watcher.fm = &fm;
        const Feature_invariants<Mesh> invariants(work, fm);
        Q::Qzip_history<Mesh> history(work);
        const auto r = Q::execute_qzip(work, plan_on_copy(work, fm, sketch_points, Q::Strip_operation(motion)), history,
                                       CGAL::parameters::edge_is_constrained_map(fm).visitor(std::ref(watcher)));
        assert(r.is_done());
        invariants.check_after(work, fm, r.number_of_splits, r.number_of_collapses);
        assert(watcher.feature_delimiters == 0);
        with_cleanup += watcher.next_to_feature > 0;
        history.undo_all();
        assert(CGAL::is_valid_polygon_mesh(work) && are_isomorphic(work, base) && sorted_positions(work) == sorted_positions(base));
      }
    }
  return with_cleanup;
}

/// Forces `plan`, refused without the simulation, through `execute_qzip()` on a copy of `m` with the feature edges
/// `segments`: the executor must roll it back, with the mesh, its positions and its feature edges as they were.
/// Returns why it failed.
template <typename Mesh>
CGAL::Qzip::Execution_failure assert_forced_plan_fails(const Mesh& m, const Feature_segments& segments,
                                                       const CGAL::Qzip::Surgery_plan<Mesh>& plan)
{
  namespace Q = CGAL::Qzip;
  Mesh work;
  const Feature_map<Mesh> fm = copy_with_features(m, work, segments);
  const auto np = CGAL::parameters::edge_is_constrained_map(fm);
  const auto at = vertices_by_position(work);
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> sketch;
  for(auto v : plan.sketch) sketch.push_back(at.at(position(v, m)));
  Q::Surgery_plan<Mesh> forced = Q::plan_qzip(work, sketch, plan.initial_operation, Q::parameters::simulate_chain(false, np));
  assert(forced.status == plan.status && forced.operations == plan.operations && forced.path.size() == plan.path.size());
  forced.status = Q::Plan_status::REALIZABLE;
  const auto r = Q::execute_qzip(work, forced, np);
  assert(!r.is_done() && r.failure != Q::Execution_failure::NONE);
  assert(CGAL::is_valid_polygon_mesh(work) && are_isomorphic(work, m));
  assert(sorted_positions(work) == sorted_positions(m) && feature_segments(work, fm) == segments);
  return r.failure;
}

/// The moved v3 of an E1 end on a feature (manual, "End Rules E1-E3"): a Q-zip to an interior v3 `t` gives `t` one
/// more edge, and the last guide's target, the moved v3, loses one. After a last collapse that is the corner of the
/// collapsed quad next to `t` other than the path vertex `u`; on a feature it takes the -1 in the sector of that quad,
/// which the executor refuses unless it cancels a +1 there. On grids with a feature line turning by a right angle at
/// (8, 6) and a chain of collapses planted in its 270 degree sector, leaving 3-5 pairs next to the turn: every sketch
/// from an interior singularity to an interior v3 (the shortest surgery path, and those arriving through each
/// neighbour), four motions, planned without the simulation. Among the plans ending with a collapse whose moved v3
/// would be a feature vertex, one that `plan_qzip()` accepts is done, keeping the invariants; one it refuses
/// `BORDER_OR_CONSTRAINED` is rolled back when forced, the mesh unchanged. Returns the number of those that the
/// executor refuses for a new singularity: without the check of `plan_qzip()` they pass and are rolled back.
template <typename Mesh>
std::size_t moved_v3_on_feature_refusals()
{
  namespace Q = CGAL::Qzip;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::size_t refused = 0;
  for(const std::array<int, 5>& chain : { std::array<int, 5>{ { 9, 1, 9, 5, 1 } }, std::array<int, 5>{ { 13, 5, 9, 5, 0 } },
                                          std::array<int, 5>{ { 13, 7, 9, 7, 1 } } })
  {
    Mesh base;
    const Feature_segments segments = make_grid_with_feature(base, 16, 12, { { { 0, 6 } }, { { 8, 6 } }, { { 8, 12 } } }, { chain });
    const Feature_map<Mesh> fbase = mark_features(base, segments);
    const auto np_base = CGAL::parameters::edge_is_constrained_map(fbase);
    for(vertex_descriptor t : vertices(base))
    {
      if(on_border(t, base) || on_feature(t, base, fbase) || valence(t, base) != 3) continue;
      for(vertex_descriptor s : ball(base, t, 8))
      {
        if(s == t || on_border(s, base) || on_feature(s, base, fbase) || (valence(s, base) != 3 && valence(s, base) != 5)) continue;
        for(const auto& sketch : feature_end_sketches(base, fbase, s, t, 8))
          for(int motion = 0; motion < 4; ++motion)
          {
            const auto plan = Q::plan_qzip(base, sketch, Q::Strip_operation(motion), Q::parameters::simulate_chain(false, np_base));
            const std::size_t n = plan.path.size();
            if(plan.target != t || n < 2 || plan.path.back() != t || !Q::is_collapse(plan.operations[n - 2])) continue;
            // the corner of the last collapsed quad next to t, other than u
            const vertex_descriptor u = plan.path[n - 2];
            const auto ut = halfedge(u, t, base).first;
            const auto quad = plan.operations[n - 2] == Q::Strip_operation::RIGHT_COLLAPSE ? ut : opposite(ut, base);
            vertex_descriptor moved_v3 = boost::graph_traits<Mesh>::null_vertex();
            for(auto h : CGAL::halfedges_around_face(quad, base))
              if(source(h, base) == t && target(h, base) != u) moved_v3 = target(h, base);
              else if(target(h, base) == t && source(h, base) != u) moved_v3 = source(h, base);
            if(!on_feature(moved_v3, base, fbase)) continue;
            if(plan.is_realizable())
            {
              Mesh work;
              const Feature_map<Mesh> fm = copy_with_features(base, work, segments);
              const Feature_invariants<Mesh> invariants(work, fm);
              std::vector<Point> sketch_points;
              for(vertex_descriptor v : sketch) sketch_points.push_back(position(v, base));
              const auto r = Q::execute_qzip(work, plan_on_copy(work, fm, sketch_points, Q::Strip_operation(motion)),
                                             CGAL::parameters::edge_is_constrained_map(fm));
              assert(r.is_done());
              invariants.check_after(work, fm, r.number_of_splits, r.number_of_collapses);
            }
            else if(plan.status == Q::Plan_status::BORDER_OR_CONSTRAINED)
              refused += assert_forced_plan_fails(base, segments, plan) == Q::Execution_failure::SINGULARITY_CREATED;
          }
      }
    }
  }
  return refused;
}

/// A feature target at the end of its curve: a vertex t with a single constrained edge t-e, whose one sector is
/// bounded on both sides by that edge (manual, "Feature End Points"). On a grid whose feature line ends at
/// t = (5, 6), lifted into a cone point (four quads in about 270 degrees where three are expected: +1), and a chain
/// of collapses planted to the line at (3, 6) from above, which leaves e = (4, 6) with -1: the border rules read in
/// the sector of t find no gap, and the chain would leave t's +1 and create an interior v3. Every sketch from an
/// interior singularity to t, four motions, planned without the simulation, is refused; a plan refused
/// `UNSUPPORTED_ENDPOINT` once prepared (its path goes on to e) is rolled back when forced, the mesh unchanged.
/// Returns the number of those.
template <typename Mesh>
std::size_t curve_end_refusals()
{
  namespace Q = CGAL::Qzip;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Mesh base;
  const Feature_map<Mesh> fbase = mark_features(base, make_grid_with_feature(base, 16, 12, { { { 0, 6 } }, { { 5, 6 } } },
                                                                             { { { 3, 11, 3, 6, 1 } } }));
  const vertex_descriptor t = vertices_by_position(base).at(Point(5, 6, 0));
  const vertex_descriptor e = vertices_by_position(base).at(Point(4, 6, 0));
  put(get(CGAL::vertex_point, base), t, Point(5, 6, 0.8)); // corners of about 67 degrees
  const Feature_segments segments = feature_segments(base, fbase);
  const auto np_base = CGAL::parameters::edge_is_constrained_map(fbase);
  assert(Q::vertex_defect(t, base, np_base) == 1 && Q::vertex_defect(e, base, np_base) == -1);
  assert(CGAL::Qzip::internal::number_of_constrained_edges(t, base, fbase) == 1);
  std::size_t refused = 0;
  for(vertex_descriptor s : ball(base, t, 10))
  {
    if(on_border(s, base) || on_feature(s, base, fbase) || (valence(s, base) != 3 && valence(s, base) != 5)) continue;
    for(const auto& sketch : feature_end_sketches(base, fbase, s, t, 10))
      for(int motion = 0; motion < 4; ++motion)
      {
        const auto plan = Q::plan_qzip(base, sketch, Q::Strip_operation(motion), Q::parameters::simulate_chain(false, np_base));
        assert(!plan.is_realizable());
        if(plan.status == Q::Plan_status::UNSUPPORTED_ENDPOINT && plan.path.back() != t)
        {
          assert(plan.path.back() == e);
          refused += assert_forced_plan_fails(base, segments, plan) == Q::Execution_failure::SINGULARITY_CREATED;
        }
      }
  }
  return refused;
}

/// Q-zips ending at feature defects on planted grids (a straight feature line, a feature line with a right-angle
/// turn) and on real CAD meshes (fandisk bundled; anchor_sharp and joint from the shared corpus when present).
inline void test_feature_end_moves()
{
  Feature_move_counters grids, real;
  // a straight horizontal feature line at y = 6, chains arriving from below and from above, on either side
  const std::vector<std::array<int, 2> > straight = { { 0, 6 }, { 16, 6 } };
  const std::vector<std::array<int, 2> > turning = { { 0, 6 }, { 8, 6 }, { 8, 12 } };
  const std::vector<std::pair<std::vector<std::array<int, 2> >, std::vector<std::array<int, 5> > > > layouts = {
    { straight, { { 5, 1, 5, 6, 1 } } }, { straight, { { 5, 1, 5, 6, 0 } } }, { straight, { { 10, 11, 10, 6, 1 } } },
    { straight, { { 4, 2, 4, 6, 1 }, { 11, 10, 11, 6, 0 } } },
    { turning, { { 8, 1, 8, 6, 1 } } }, { turning, { { 8, 1, 8, 6, 0 } } }, { turning, { { 3, 10, 8, 10, 1 } } },
    { turning, { { 13, 9, 8, 9, 0 } } }, { turning, { { 7, 1, 7, 6, 0 } } }, { turning, { { 9, 1, 9, 6, 1 } } },
    { turning, { { 13, 7, 8, 7, 1 } } } };
  Feature_move_counters grids_ph;
  for(std::size_t k = 0; k < layouts.size(); ++k)
  {
    Surface_mesh m;
    const Feature_segments segments = make_grid_with_feature(m, 16, 12, layouts[k].first, layouts[k].second);
    const Feature_move_counters c = feature_end_moves(m, segments, 10, 8);
    c.print("feature layout " + std::to_string(k));
    grids.add(c);
    Polyhedron ph;
    const Feature_segments segments_ph = make_grid_with_feature(ph, 16, 12, layouts[k].first, layouts[k].second);
    assert(segments_ph == segments);
    grids_ph.add(feature_end_moves(ph, segments_ph, 10, 8));
  }
  // fandisk has a single feature defect, with no singularity a surgery path reaches: chains planted at four
  // feature vertices
  {
    Surface_mesh fandisk;
    const bool ok = read_mesh("data/pmp_fandisk_quads.off", fandisk);
    assert(ok);
    const Feature_segments segments = sharp_segments(fandisk);
    for(std::size_t k = 0; k < 4; ++k)
    {
      Surface_mesh m;
      copy_mesh(fandisk, m);
      const bool planted = plant_feature_chain(m, segments, 25 * k, 4);
      assert(planted);
      const Feature_move_counters c = feature_end_moves(m, segments, 8, 4);
      c.print("pmp_fandisk_quads.off, chain planted at feature vertex " + std::to_string(25 * k));
      real.add(c);
    }
  }
  std::vector<std::string> files;
  const std::string corpus = shared_corpus_dir("feature ends on anchor_sharp and joint");
  if(!corpus.empty())
    for(const char* f : { "gen_quadriflow_anchor_sharp.obj", "quadwild_joint.obj" }) files.push_back(corpus + "/" + f);
  for(const std::string& f : files)
  {
    Surface_mesh m;
    const bool ok = read_mesh(f, m);
    assert(ok);
    const Feature_move_counters c = feature_end_moves(m, sharp_segments(m), 10, 12);
    c.print(f);
    real.add(c);
  }
  grids.print("feature defects, planted grids");
  grids_ph.print("feature defects, planted grids, Polyhedron_3 (feature flags in a dynamic edge property)");
  real.print("feature defects, CAD meshes");
  assert(grids_ph.plans == grids.plans && grids_ph.done == grids.done && grids_ph.moved == grids.moved &&
         grids_ph.cancelling == grids.cancelling && grids_ph.refused == grids.refused);
  for(const Feature_move_counters* c : { &grids, &grids_ph, &real })
    assert(c->moved > 0 && c->reversed == c->moved && c->rolled_back == 0 && c->no_reverse.empty());
  assert(grids.with_quad_too_few > 0 && grids.at_turn > 0);
  test_feature_end_sketch_orientation();
  // a number of cases met on both mesh types: printed, positive and the same
  const auto on_both = [](const char* what, std::size_t on_surface_mesh, std::size_t on_polyhedron)
  {
    std::cout << "  " << what << ": " << on_surface_mesh << " (" << on_polyhedron << " on Polyhedron_3)" << std::endl;
    assert(on_surface_mesh > 0 && on_polyhedron == on_surface_mesh);
  };
  on_both("feature ends, sector check: Q-zips moving a +1 into a sector -2 refused (the defects of t and e cancel as "
          "totals), rolled back when forced", sector_check_refusals<Surface_mesh>(), sector_check_refusals<Polyhedron>());
  on_both("interior v3 targets whose moved v3 would be a feature vertex: plans refused without the simulation, rolled "
          "back when forced", moved_v3_on_feature_refusals<Surface_mesh>(), moved_v3_on_feature_refusals<Polyhedron>());
  on_both("feature targets at the end of their curve: plans refused without the simulation, rolled back when forced",
          curve_end_refusals<Surface_mesh>(), curve_end_refusals<Polyhedron>());
  on_both("valence-6 clean-up next to a feature line: Q-zips done with it, delimiters off the feature",
          valence_6_cleanups_next_to_feature<Surface_mesh>(), valence_6_cleanups_next_to_feature<Polyhedron>());
}

} // namespace qzip_test

#endif // QZIP_FEATURE_END_TESTS_H
