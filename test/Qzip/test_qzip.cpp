// Tests of the Q-zip primitive: planning, execution, invariants, undo, homotopy invariance, refusals.
#include "qzip_test_utils.h"
#include "reverse_qzip_tests.h"
#include "qzip_border_end_tests.h"
#include "qzip_feature_end_tests.h"

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/singularities.h>

#include <CGAL/Random.h>

#include <array>
#include <deque>
#include <set>

using namespace qzip_test;
namespace Q = CGAL::Qzip;

/// the number of faces each border vertex should have, from the geometry (sector rule of vertex_defect()),
/// by vertex and by position: a border vertex that a Q-zip created, or an interior vertex that took the
/// place of a border vertex, should have the number of the border vertex it replaced, the one nearest to it
template <typename Mesh>
struct Border_faces
{
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, int> by_vertex;
  std::vector<std::pair<Point, int> > by_position;

  explicit Border_faces(const Mesh& m)
  {
    for(auto v : vertices(m))
    {
      if(!on_border(v, m)) continue;
      int faces = 0;
      for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(!is_border(h, m)) ++faces;
      by_vertex[v] = faces - Q::vertex_defect(v, m);
      by_position.emplace_back(get(CGAL::vertex_point, m, v), by_vertex[v]);
    }
  }
  int expected(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m) const
  {
    const auto it = by_vertex.find(v);
    if(it != by_vertex.end()) return it->second;
    const Point& p = get(CGAL::vertex_point, m, v);
    const auto nearest = std::min_element(by_position.begin(), by_position.end(), [&p](const auto& a, const auto& b)
                                          { return CGAL::squared_distance(a.first, p) < CGAL::squared_distance(b.first, p); });
    return nearest->second;
  }
};

/// what a vertex is as a singularity: 0 if regular, its valence inside, 100 + its defect on the border.
/// Border defects count faces against `expected` (from the geometry before a Q-zip: the chain places its
/// vertices roughly, which may shift corner angles), or against the geometry when `expected` is null.
template <typename Mesh>
int singularity_code(typename boost::graph_traits<Mesh>::vertex_descriptor v, const Mesh& m,
                     const Border_faces<Mesh>* expected = nullptr)
{
  if(!on_border(v, m)) return valence(v, m) == 4 ? 0 : valence(v, m);
  int d = 0;
  if(expected == nullptr) d = Q::vertex_defect(v, m);
  else
  {
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m)) if(!is_border(h, m)) ++d;
    d -= expected->expected(v, m);
  }
  return d == 0 ? 0 : 100 + d;
}

template <typename Mesh>
std::vector<int> singularity_codes(const Mesh& m, const Border_faces<Mesh>* expected = nullptr)
{
  std::vector<int> out;
  for(auto v : vertices(m)) if(const int c = singularity_code(v, m, expected)) out.push_back(c);
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

/// What a Q-zip must preserve, measured on the whole mesh before it.
template <typename Mesh>
struct Snapshot
{
  long chi;
  std::size_t faces, quads;
  std::vector<int> singular; // singularity_codes(): interior valences and border defects
  Border_faces<Mesh> border_faces;
  explicit Snapshot(const Mesh& m)
    : chi(euler_characteristic(m)), faces(CGAL::faces(m).size()), quads(0), singular(singularity_codes(m)),
      border_faces(m)
  {
    for(auto f : CGAL::faces(m)) if(CGAL::halfedges_around_face(halfedge(f, m), m).size() == 4) ++quads;
  }
};

struct Counters
{
  std::size_t done = 0, refused = 0, rolled_back = 0, cancelling = 0, located = 0, checked_moves = 0;
  std::size_t predicted_failures = 0; // plans refused by a local check whose execution, forced, fails as predicted
  std::size_t simulated_failures = 0; // plans refused by the simulation whose execution, forced, fails as simulated
  void print(const char* what) const
  {
    std::cout << "  " << what << ": " << done << " done (" << cancelling << " cancelling singularities, "
              << located << " with the moved pair located, " << checked_moves << " moves checked to be one edge), " << refused << " refused by the plan, "
              << rolled_back << " rolled back, " << predicted_failures << " refused by a local check and "
              << simulated_failures << " by the simulation, each failing when forced" << std::endl;
  }
};

/// the invariants of a done Q-zip, checked globally (independently of the executor's own checks).
template <typename Mesh>
void check_done(const Mesh& m, const Snapshot<Mesh>& before, const Q::Qzip_result<Mesh>& r, Counters& c)
{
  assert(r.is_done());
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(euler_characteristic(m) == before.chi);
  const Snapshot<Mesh> after(m);
  // every quad is still a quad, every other face untouched; faces change by splits - collapses
  assert(after.faces - before.faces == after.quads - before.quads);
  assert(long(after.faces) - long(before.faces) == long(r.number_of_splits) - long(r.number_of_collapses));
  // no singularity created (inside or on the border): the singularity codes after are a sub-multiset of
  // those before
  const std::vector<int> singular_after = singularity_codes(m, &before.border_faces);
  assert(std::includes(before.singular.begin(), before.singular.end(), singular_after.begin(), singular_after.end()));
  ++c.done;
  if(singular_after != before.singular) { ++c.cancelling; return; }
  if(r.moved_source != boost::graph_traits<Mesh>::null_vertex())
  {
    ++c.located;
    assert(r.moved_target != boost::graph_traits<Mesh>::null_vertex());
    assert(!on_border(r.moved_source, m) && valence(r.moved_source, m) != 4);
    assert(singularity_code(r.moved_target, m, &before.border_faces) != 0);
  }
  for(auto f : r.scar_faces) assert(CGAL::halfedges_around_face(halfedge(f, m), m).size() == 4);
}

/// the graph distance in `m` from `s` to the vertex of `m` nearest to `p` (a proxy for "where a vertex
/// of the edited mesh sits in the original one").
template <typename Mesh>
int distance_to_nearest(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor s, const Point& p)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  vertex_descriptor best = s;
  double best_d = CGAL::squared_distance(get(CGAL::vertex_point, m, s), p);
  for(auto v : vertices(m))
  {
    const double d = CGAL::squared_distance(get(CGAL::vertex_point, m, v), p);
    if(d < best_d) { best_d = d; best = v; }
  }
  std::map<vertex_descriptor, int> dist;
  std::deque<vertex_descriptor> queue(1, s);
  dist[s] = 0;
  while(!queue.empty())
  {
    const vertex_descriptor v = queue.front(); queue.pop_front();
    if(v == best) return dist[v];
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
      if(!dist.count(source(h, m))) { dist[source(h, m)] = dist[v] + 1; queue.push_back(source(h, m)); }
  }
  return -1;
}

/// no singular vertex but `v` and `partner` within `radius` edges of `v`.
template <typename Mesh>
bool is_isolated(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor v,
                 typename boost::graph_traits<Mesh>::vertex_descriptor partner, int radius)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::map<vertex_descriptor, int> dist;
  std::deque<vertex_descriptor> queue(1, v);
  dist[v] = 0;
  while(!queue.empty())
  {
    const vertex_descriptor x = queue.front(); queue.pop_front();
    if(x != v && x != partner && (on_border(x, m) || valence(x, m) != 4)) return false;
    if(dist[x] == radius) continue;
    for(auto h : CGAL::halfedges_around_target(halfedge(x, m), m))
      if(!dist.count(source(h, m))) { dist[source(h, m)] = dist[x] + 1; queue.push_back(source(h, m)); }
  }
  return true;
}

/// plants the four singularities of a chain of k collapses along a row (or column) of a planar grid:
/// p_0 (3), p_1 (5), p_k (5), r_k (3), where p is the row and r the row below.
template <typename Mesh>
void plant_chain(Mesh& m, int n, int row, int col, int k, bool along_rows)
{
  make_quad_grid(m, n, n);
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::map<std::pair<int, int>, vertex_descriptor> at;
  for(auto v : vertices(m))
  {
    const Point& p = get(CGAL::vertex_point, m, v);
    at[std::make_pair(int(p.x()), int(p.y()))] = v;
  }
  auto id = [&](int i, int j) { return along_rows ? at[std::make_pair(i, j)] : at[std::make_pair(j, i)]; };
  for(int s = 0; s < k; ++s)
  {
    const vertex_descriptor p1 = id(col + s + 1, row), r0 = id(col + s, row - 1);
    bool done = false;
    for(auto h : CGAL::halfedges_around_target(halfedge(p1, m), m))
      if(!is_border(h, m) && target(next(next(h, m), m), m) == r0 && Q::can_collapse_quad(h, m))
      { Q::quad_collapse(h, m); done = true; break; }
    assert(done);
  }
}

/// every ordered pair of the planted singularities, four motions each: invariants, the moved pair within
/// one edge of where it was (positions of a planar grid as a proxy), exact undo.
/// the refusals that predict a failure of the execution: a plan that starts with a split
/// (`SPLIT_WITHOUT_GUIDE`), leaves a valence-6 vertex that the clean-up cannot split (`VALENCE_6_LEFT`), or
/// whose simulated execution fails (`EXECUTION_WOULD_FAIL`) cannot be carried out. Forced through the
/// executor, such a plan fails for the predicted reason (at the simulated step, for the simulated reason)
/// and the mesh is left as it was: no realizable plan is refused. Returns whether `plan` is such a refusal,
/// counted in `c`. A history that records the Q-zips done on `m` must be passed (the roll-back re-creates
/// elements).
template <typename Mesh, typename... History>
bool check_predicted_failure(Counters& c, Mesh& m, Q::Surgery_plan<Mesh> plan, History&... history)
{
  if(plan.status != Q::Plan_status::SPLIT_WITHOUT_GUIDE && plan.status != Q::Plan_status::VALENCE_6_LEFT &&
     plan.status != Q::Plan_status::EXECUTION_WOULD_FAIL)
    return false;
  const Q::Plan_status status = plan.status;
  assert((status == Q::Plan_status::EXECUTION_WOULD_FAIL) == (plan.predicted_failure != Q::Execution_failure::NONE));
  if(status == Q::Plan_status::EXECUTION_WOULD_FAIL) // without the simulation, the same plan passes
  {
    const auto unsimulated = Q::plan_qzip(m, plan.sketch, plan.initial_operation, Q::parameters::simulate_chain(false));
    assert(unsimulated.is_realizable() && unsimulated.path == plan.path && unsimulated.operations == plan.operations);
  }
  Mesh before;
  copy_mesh(m, before);
  plan.status = Q::Plan_status::REALIZABLE;
  const auto r = Q::execute_qzip(m, plan, history...);
  assert(!r.is_done());
  if(status == Q::Plan_status::SPLIT_WITHOUT_GUIDE)
    assert(r.failure == Q::Execution_failure::NO_GUIDE_FOR_SPLIT && r.failed_step == 0);
  else if(status == Q::Plan_status::VALENCE_6_LEFT)
    assert(r.failure == Q::Execution_failure::CLEANUP_IMPOSSIBLE);
  else
    assert(r.failure == plan.predicted_failure && r.failed_step == plan.predicted_failed_step);
  assert(are_isomorphic(m, before) && sorted_points(m) == sorted_points(before));
  ++(status == Q::Plan_status::EXECUTION_WOULD_FAIL ? c.simulated_failures : c.predicted_failures);
  return true;
}

/// The simulation of plan_qzip() keeps its buffers from plan to plan (the local copy, resized rather than
/// cleared, its hash maps, the executor's log): its decisions may not depend on the plans made before.
/// Plans between random singularities 1 to 24 edges apart (so that the copy grows and shrinks), with the
/// four motions each, are made in one order, then again in the reverse order, and must be the same.
template <typename Mesh>
void test_simulation_history(const std::string& path, unsigned seed, std::size_t& compared, std::size_t& refused)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Mesh m;
  assert(read_mesh(path, m));
  Q::preprocess_valences(m);
  const std::vector<vertex_descriptor> singular = singular_vertices(m);
  CGAL::Random rng(seed);
  std::vector<std::vector<vertex_descriptor> > paths;
  for(int attempt = 0; paths.size() < 60 && attempt < 1000; ++attempt)
  {
    const vertex_descriptor s = singular[std::size_t(rng.get_int(0, int(singular.size())))];
    const int reach = rng.get_int(1, 25);
    const std::vector<vertex_descriptor> candidates = singularities_within(m, s, reach / 2, reach);
    if(candidates.empty()) continue;
    const auto p = Q::shortest_surgery_path(m, s, candidates[std::size_t(rng.get_int(0, int(candidates.size())))]);
    if(!p.empty()) paths.push_back(p);
  }
  assert(paths.size() == 60);
  std::vector<Q::Surgery_plan<Mesh> > first;
  for(const auto& p : paths)
    for(int k = 0; k < 4; ++k) first.push_back(Q::plan_qzip(m, p, Q::Strip_operation(k)));
  for(std::size_t i = first.size(); i-- > 0;)
  {
    const Q::Surgery_plan<Mesh> again = Q::plan_qzip(m, paths[i / 4], Q::Strip_operation(i % 4));
    assert(again.status == first[i].status && again.predicted_failure == first[i].predicted_failure &&
           again.predicted_failed_step == first[i].predicted_failed_step && again.path == first[i].path &&
           again.operations == first[i].operations);
    if(again.status == Q::Plan_status::EXECUTION_WOULD_FAIL) ++refused;
    ++compared;
  }
}

template <typename Mesh>
void test_planted_pairs(Counters& c, std::size_t& longest)
{
  struct Layout { int n, row, col, k; };
  // short and long chains in the middle of the grid (pairs at distance 1 to 46), and chains next to the
  // border (row 2: the paths run one quad away from it)
  const Layout layouts[] = { {30, 12, 8, 2}, {30, 12, 8, 3}, {30, 12, 8, 6}, {30, 12, 8, 11}, {56, 20, 4, 45},
                             {30, 2, 8, 5}, {30, 2, 8, 12} };
  for(const Layout& layout : layouts)
    for(bool rows : { true, false })
    {
      Mesh m;
      plant_chain(m, layout.n, layout.row, layout.col, layout.k, rows);
      const int k = layout.k;
      const auto sing = singular_vertices(m);
      assert(sing.size() == 4);
      for(std::size_t i = 0; i < sing.size(); ++i)
        for(std::size_t j = 0; j < sing.size(); ++j)
          for(int mo = 0; i != j && mo < 4; ++mo)
          {
            Mesh w;
            auto v2v = copy_mesh_with_map(m, w);
            const auto s = v2v[sing[i]], t = v2v[sing[j]];
            const Snapshot<Mesh> before(w);
            const auto path = Q::shortest_surgery_path(w, s, t);
            assert(!path.empty() && path.front() == s && path.back() == t);
            longest = (std::max)(longest, path.size() - 1);
            const auto plan = Q::plan_qzip(w, path, Q::Strip_operation(mo));
            check_predicted_failure(c, w, plan);
            if(!plan.is_realizable()) { ++c.refused; continue; }
            Q::Qzip_history<Mesh> history(w);
            const auto r = Q::execute_qzip(w, plan, history);
            if(!r.is_done())
            {
              ++c.rolled_back;
              assert(r.failure != Q::Execution_failure::NONE && r.failed_step + 1 < plan.path.size());
              assert(are_isomorphic(w, m) && sorted_points(w) == sorted_points(m));
              continue;
            }
            const std::size_t located = c.located;
            check_done(w, before, r, c);
            if(c.located > located)
            {
              // each singularity moved by one edge: it sits next to where it was (checked where no third
              // singularity is close enough to be confused with it)
              const int ds = distance_to_nearest(m, sing[i], get(CGAL::vertex_point, w, r.moved_source));
              const int dt = distance_to_nearest(m, sing[j], get(CGAL::vertex_point, w, r.moved_target));
              if(is_isolated(m, sing[i], sing[j], 2)) { assert(ds <= 1); ++c.checked_moves; }
              if(is_isolated(m, sing[j], sing[i], 2)) { assert(dt <= 1); ++c.checked_moves; }

            }
            assert(history.size() == 1);
            Q::undo_qzip(history);
            assert(history.empty());
            assert(CGAL::is_valid_polygon_mesh(w));
            assert(are_isomorphic(w, m));
            assert(sorted_points(w) == sorted_points(m));
          }
    }
}

// ---------------------------------------------------------------------------------------------
// Homotopy invariance (paper, Sec. 3.1)

/// winding number of the closed polygon `loop` (positions in the plane z = 0) around `p`.
inline int winding_number(const std::vector<Point>& loop, const Point& p)
{
  double total = 0;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    const Point& a = loop[i];
    const Point& b = loop[(i + 1) % loop.size()];
    total += std::atan2((a.x() - p.x()) * (b.y() - p.y()) - (a.y() - p.y()) * (b.x() - p.x()),
                        (a.x() - p.x()) * (b.x() - p.x()) + (a.y() - p.y()) * (b.y() - p.y()));
  }
  return int(std::lround(total / (2 * CGAL_PI)));
}

/// the grid of the homotopy tests: a planted chain of five collapses (two v3, two v5) and, to wind
/// around, a second pair made by one split of a regular vertex between opposite edges
template <typename Mesh>
void plant_winding_grid(Mesh& m)
{
  plant_chain(m, 24, 11, 7, 5, true);
  for(auto v : vertices(m))
    if(get(CGAL::vertex_point, m, v) == Point(12, 17, 0))
    {
      auto h1 = halfedge(v, m);
      auto h2 = opposite(next(opposite(next(h1, m), m), m), m);
      auto q = Q::split_vertex_into_quad(h1, h2, m);
      const auto c = target(next(next(q, m), m), m);
      put(get(CGAL::vertex_point, m), c, Point(12.4, 17.4, 0));
      break;
    }
}

/// random paths through waypoints between planted singularities, avoiding the other singularities;
/// two paths whose loop winds around no other singularity are homotopic and must give isomorphic meshes.
template <typename Mesh>
void test_homotopy(unsigned seed, std::size_t& homotopic_pairs, std::size_t& distinct_classes_differing, Counters& c)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  CGAL::Random rng(seed);
  Mesh m;
  plant_winding_grid(m);
  const auto sing = singular_vertices(m);
  std::vector<vertex_descriptor> inner;
  for(auto v : vertices(m)) if(!on_border(v, m) && valence(v, m) == 4) inner.push_back(v);
  for(std::size_t i = 0; i < sing.size(); ++i)
    for(std::size_t j = 0; j < sing.size(); ++j)
    {
      if(i == j) continue;
      const vertex_descriptor s = sing[i], t = sing[j];
      std::set<vertex_descriptor> others;
      for(auto x : sing) if(x != s && x != t) others.insert(x);
      // a handful of waypoint paths
      std::vector<std::vector<vertex_descriptor> > paths;
      for(int attempt = 0; attempt < 40 && paths.size() < 6; ++attempt)
      {
        const vertex_descriptor q = inner[std::size_t(rng.get_int(0, int(inner.size())))];
        std::set<vertex_descriptor> forbid1 = others; forbid1.insert(t);
        auto p1 = bfs_path(m, s, q, forbid1);
        if(p1.empty()) continue;
        std::set<vertex_descriptor> forbid2 = others;
        for(std::size_t x = 0; x + 1 < p1.size(); ++x) forbid2.insert(p1[x]);
        auto p2 = bfs_path(m, q, t, forbid2);
        if(p2.empty()) continue;
        p1.insert(p1.end(), p2.begin() + 1, p2.end());
        paths.push_back(p1);
      }
      for(int mo = 0; mo < 4; ++mo)
      {
        std::vector<Mesh> results(paths.size());
        std::vector<bool> done(paths.size(), false);
        for(std::size_t a = 0; a < paths.size(); ++a)
        {
          auto v2v = copy_mesh_with_map(m, results[a]);
          std::vector<vertex_descriptor> path;
          for(auto v : paths[a]) path.push_back(v2v[v]);
          const auto plan = Q::plan_qzip(results[a], path, Q::Strip_operation(mo));
          check_predicted_failure(c, results[a], plan);
          if(!plan.is_realizable()) { ++c.refused; continue; }
          done[a] = Q::execute_qzip(results[a], plan).is_done();
          if(done[a]) ++c.done; else ++c.rolled_back;
        }
        for(std::size_t a = 0; a < paths.size(); ++a)
          for(std::size_t b = a + 1; b < paths.size(); ++b)
          {
            if(!done[a] || !done[b]) continue;
            // the initial tag is a motion relative to the first edge: compare paths that leave s alike
            if(paths[a][1] != paths[b][1]) continue;
            std::vector<Point> loop;
            for(auto v : paths[a]) loop.push_back(get(CGAL::vertex_point, m, v));
            for(std::size_t x = paths[b].size() - 1; x-- > 1;) loop.push_back(get(CGAL::vertex_point, m, paths[b][x]));
            bool homotopic = true;
            for(auto o : others) if(winding_number(loop, get(CGAL::vertex_point, m, o)) != 0) homotopic = false;
            const bool iso = are_isomorphic(results[a], results[b]);
            if(homotopic) { assert(iso); ++homotopic_pairs; }
            else if(!iso) ++distinct_classes_differing;
          }
      }
    }
}

struct Spiral_counts
{
  std::size_t paths = 0;            // spiral paths made (one or more turns around another singularity)
  std::size_t spirals_done = 0;     // done Q-zips along them
  std::size_t homotopic_spirals = 0; // pairs of different spirals, homotopic, done on both: isomorphic
  std::size_t turns_differing = 0;  // pairs whose loop winds around a singularity and whose meshes differ
};

/// Spiral paths: from s, a path that winds one to two and a half times around another singularity u before
/// it goes to t (waypoints on a square spiral around u, joined by shortest paths that avoid the path so far and the
/// other singularities), all leaving s along the same edge; every motion on each.
/// Each done Q-zip keeps the invariants (check_done()) and is undone exactly by the history. Two spirals whose loop winds around no other
/// singularity (the same number of turns around u) give isomorphic meshes.
template <typename Mesh>
void test_spiral_paths(unsigned seed, Spiral_counts& sc, Counters& c)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  CGAL::Random rng(seed);
  Mesh m;
  plant_winding_grid(m);
  const auto sing = singular_vertices(m);
  const auto position = [&m](vertex_descriptor v) { return get(CGAL::vertex_point, m, v); };
  std::vector<vertex_descriptor> inner;
  for(auto v : vertices(m)) if(!on_border(v, m) && valence(v, m) == 4) inner.push_back(v);
  const auto closest_inner = [&](const Point& p)
  {
    return *std::min_element(inner.begin(), inner.end(), [&](vertex_descriptor a, vertex_descriptor b)
                             { return CGAL::squared_distance(position(a), p) < CGAL::squared_distance(position(b), p); });
  };
  // the winding number around o of the loop made by path a and path b reversed
  const auto loop_winding = [&](const std::vector<vertex_descriptor>& a, const std::vector<vertex_descriptor>& b,
                                vertex_descriptor o)
  {
    std::vector<Point> loop;
    for(auto v : a) loop.push_back(position(v));
    for(std::size_t x = b.size() - 1; x-- > 1;) loop.push_back(position(b[x]));
    return winding_number(loop, position(o));
  };
  for(vertex_descriptor s : sing)
    for(vertex_descriptor t : sing)
      for(vertex_descriptor u : sing)
      {
        if(s == t || u == s || u == t) continue;
        std::set<vertex_descriptor> others;
        for(auto x : sing) if(x != s && x != t) others.insert(x);
        vertex_descriptor first = boost::graph_traits<Mesh>::null_vertex();
        for(auto h : CGAL::halfedges_around_target(halfedge(s, m), m))
          if(!on_border(source(h, m), m) && valence(source(h, m), m) == 4) { first = source(h, m); break; }
        if(first == boost::graph_traits<Mesh>::null_vertex()) continue;
        // extends `path` by a shortest path to `to` that avoids the other singularities and keeps one edge
        // away from the path so far (not from its last two vertices): the turns of a spiral have quads
        // between them for the strip operations
        const auto extend = [&](std::vector<vertex_descriptor>& path, vertex_descriptor to)
        {
          if(to == path.back()) return true;
          std::set<vertex_descriptor> forbidden = others;
          forbidden.insert(path.begin(), path.end() - 1);
          for(std::size_t x = 0; x + 2 < path.size(); ++x)
            for(auto h : CGAL::halfedges_around_target(halfedge(path[x], m), m)) forbidden.insert(source(h, m));
          forbidden.erase(path.back());
          if(to == t) forbidden.erase(t); else forbidden.insert(t);
          const auto piece = bfs_path(m, path.back(), to, forbidden);
          path.insert(path.end(), piece.empty() ? piece.end() : piece.begin() + 1, piece.end());
          return !piece.empty();
        };
        std::vector<std::vector<vertex_descriptor> > paths(1, std::vector<vertex_descriptor>{ s, first });
        if(!extend(paths[0], t)) continue;
        for(int attempt = 0; attempt < 5; ++attempt)
        {
          const int quarters = rng.get_int(4, 11), turn = rng.get_bool() ? 1 : -1;
          const double r0 = rng.get_int(2, 4), q0 = rng.get_int(0, 4);
          std::vector<vertex_descriptor> path{ s, first };
          bool ok = true;
          for(int q = 0; ok && q <= quarters; ++q)
          {
            const double angle = (q0 + turn * q) * CGAL_PI / 2, r = r0 + 0.75 * q;
            const vertex_descriptor w = closest_inner(Point(position(u).x() + r * std::cos(angle),
                                                            position(u).y() + r * std::sin(angle), 0));
            ok = w != t && (w == path.back() || std::find(path.begin(), path.end(), w) == path.end()) && extend(path, w);
          }
          if(ok && extend(path, t) && loop_winding(path, paths[0], u) != 0) paths.push_back(path);
        }
        sc.paths += paths.size() - 1;
        for(int mo = 0; mo < 4; ++mo)
        {
          std::vector<Mesh> results(paths.size());
          std::vector<bool> done(paths.size(), false);
          for(std::size_t a = 1; a < paths.size(); ++a)
          {
            Mesh& w = results[a];
            auto v2v = copy_mesh_with_map(m, w);
            std::vector<vertex_descriptor> path;
            for(auto v : paths[a]) path.push_back(v2v[v]);
            const Snapshot<Mesh> before(w);
            const auto plan = Q::plan_qzip(w, path, Q::Strip_operation(mo));
            check_predicted_failure(c, w, plan);
            if(!plan.is_realizable()) { ++c.refused; continue; }
            Q::Qzip_history<Mesh> history(w);
            const auto r = Q::execute_qzip(w, plan, history);
            if(!r.is_done()) { ++c.rolled_back; continue; }
            check_done(w, before, r, c);
            Mesh kept;
            copy_mesh(w, kept);
            Q::undo_qzip(history);
            assert(CGAL::is_valid_polygon_mesh(w) && are_isomorphic(w, m) && sorted_points(w) == sorted_points(m));
            copy_mesh(kept, w);
            done[a] = true;
            ++sc.spirals_done;
          }
          for(std::size_t a = 1; a < paths.size(); ++a)
            for(std::size_t b = a + 1; b < paths.size(); ++b)
            {
              if(!done[a] || !done[b]) continue;
              bool homotopic = true;
              for(auto o : others) homotopic = homotopic && loop_winding(paths[a], paths[b], o) == 0;
              const bool isomorphic = are_isomorphic(results[a], results[b]);
              if(homotopic) { assert(isomorphic); ++sc.homotopic_spirals; }
              else if(!isomorphic) ++sc.turns_differing;
            }
        }
      }
}

/// Homotopy invariance on a real mesh (compare_homotopic_paths() in qzip_test_utils.h): random pairs of
/// singularities, a shortest path and a copy of it swept over one to six quads away from the other
/// singularities, every motion on both; plans refused by a check that predicts a failure are forced through
/// the executor on a copy (check_predicted_failure()).
template <typename Mesh>
void test_homotopy_on_mesh(const std::string& file, std::size_t pairs, unsigned seed, Homotopy_counts& hc, Counters& c)
{
  Mesh m;
  if(!read_mesh(file, m)) { std::cerr << "cannot read " << file << std::endl; std::exit(EXIT_FAILURE); }
  Q::preprocess_valences(m);
  compare_homotopic_paths(m, file, pairs, seed, true, hc,
                          [&c](Mesh& w, const Q::Surgery_plan<Mesh>& plan) { check_predicted_failure(c, w, plan); });
}

/// U-turn arrivals at a v5, plan by plan: for pairs of singularities (`t` of valence 5) joined by a shortest
/// path of at least two edges ending with x -> t, and each quad (x, t, u, n) beside the last edge whose corners
/// n and u are regular and off the path, the sketch arriving by the U-turn x -> n -> u -> t is planned too.
/// When the plan of the straight sketch goes around that quad at the end (E3: ... x -> n -> u), the plan of the
/// U-turn must be the same plan (the end rule straightens the U-turn). Returns the number of such plans.
template <typename Mesh>
std::size_t test_u_turn_arrivals(const Mesh& m)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const auto sing = singular_vertices(m);
  std::size_t same = 0;
  for(vertex_descriptor s : sing)
    for(vertex_descriptor t : singularities_within(m, s, 2, 8))
    {
      if(valence(t, m) != 5) continue;
      std::set<vertex_descriptor> others;
      for(auto x : sing) if(x != s && x != t) others.insert(x);
      const std::vector<vertex_descriptor> straight = bfs_path(m, s, t, others);
      if(straight.size() < 3) continue;
      const vertex_descriptor x = straight[straight.size() - 2];
      const auto xt = halfedge(x, t, m).first;
      for(auto h : { xt, opposite(xt, m) })
      {
        if(is_border(h, m) || degree(face(h, m), m) != 4) continue;
        // face(x->t) = (x, t, u, n); face(t->x) = (t, x, n, u)
        const vertex_descriptor c = target(next(h, m), m), d = target(next(next(h, m), m), m);
        const vertex_descriptor u = h == xt ? c : d, n = h == xt ? d : c;
        if(!is_regular_inside(n, m) || !is_regular_inside(u, m) ||
           std::find(straight.begin(), straight.end(), n) != straight.end() ||
           std::find(straight.begin(), straight.end(), u) != straight.end()) continue;
        std::vector<vertex_descriptor> u_turn(straight.begin(), straight.end() - 1);
        u_turn.insert(u_turn.end(), { n, u, t });
        assert(ends_with_u_turn(u_turn, m));
        for(int mo = 0; mo < 4; ++mo)
        {
          const auto p = Q::plan_qzip(m, straight, Q::Strip_operation(mo));
          const std::size_t k = p.path.size();
          if(k < 3 || p.path[k - 3] != x || p.path[k - 2] != n || p.path[k - 1] != u) continue;
          const auto q = Q::plan_qzip(m, u_turn, Q::Strip_operation(mo));
          assert(q.status == p.status && q.path == p.path && q.operations == p.operations);
          ++same;
        }
      }
    }
  return same;
}

// ---------------------------------------------------------------------------------------------
// Random Q-zips on real meshes, with every result checked and everything undone at the end

template <typename Mesh>
std::size_t random_qzips(Mesh& m, std::size_t count, unsigned seed, Counters& c)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  CGAL::Random rng(seed);
  Mesh original;
  copy_mesh(m, original);
  Q::Qzip_history<Mesh> history(m);
  std::size_t attempts = 0;
  while(history.size() < count && attempts < 20 * count)
  {
    ++attempts;
    const auto sing = singular_vertices(m);
    if(sing.size() < 2) break;
    const vertex_descriptor s = sing[std::size_t(rng.get_int(0, int(sing.size())))];
    // a singularity among the close ones
    const std::vector<vertex_descriptor> candidates = singularities_within(m, s, 1, rng.get_int(1, 16));
    if(candidates.empty()) continue;
    const vertex_descriptor t = candidates[std::size_t(rng.get_int(0, int(candidates.size())))];
    const auto path = Q::shortest_surgery_path(m, s, t);
    if(path.empty()) continue;
    const auto plan = Q::plan_qzip(m, path, Q::Strip_operation(rng.get_int(0, 4)));
    check_predicted_failure(c, m, plan, history);
    if(!plan.is_realizable()) { ++c.refused; continue; }
    const Snapshot<Mesh> before(m);
    const std::size_t recorded = history.size();
    const auto r = Q::execute_qzip(m, plan, history);
    if(!r.is_done())
    {
      ++c.rolled_back;
      assert(r.failure != Q::Execution_failure::NONE);
      assert(history.size() == recorded);
      assert(CGAL::is_valid_polygon_mesh(m) && singularity_codes(m) == before.singular);
      continue;
    }
    assert(history.size() == recorded + 1);
    check_done(m, before, r, c);
  }
  const std::size_t n = history.size();
  history.undo_all();
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(are_isomorphic(m, original));
  assert(sorted_points(m) == sorted_points(original));
  return n;
}

// ---------------------------------------------------------------------------------------------
// Refusals, constraints, visitor, named parameters

struct Counting_visitor : Q::Default_qzip_visitor<Surface_mesh>
{
  int started = 0, collapses = 0, splits = 0, finished = 0;
  void on_qzip_started(const Q::Surgery_plan<Surface_mesh>&) { ++started; }
  void on_collapse(halfedge_descriptor, const Surface_mesh&) { ++collapses; }
  void on_split(halfedge_descriptor, halfedge_descriptor, const Surface_mesh&) { ++splits; }
  void on_qzip_finished(const Q::Surgery_plan<Surface_mesh>&, bool) { ++finished; }
};

/// `VALENCE_6_LEFT` on a real mesh: a v5 next to the target whose ring leaves the clean-up no two
/// opposite regular neighbours. Every such plan among the close pairs of singularities, forced through
/// the executor on a copy, fails in the clean-up; returns their number.
template <typename Mesh>
std::size_t test_valence_6_left(const std::string& file, std::size_t wanted)
{
  Mesh m;
  assert(read_mesh(file, m));
  Q::preprocess_valences(m);
  std::size_t found = 0;
  for(auto s : singular_vertices(m))
    for(auto t : singularities_within(m, s, 1, 3))
      for(int mo = 0; mo < 4 && found < wanted; ++mo)
      {
        const auto path = Q::shortest_surgery_path(m, s, t);
        if(path.empty() || Q::plan_qzip(m, path, Q::Strip_operation(mo)).status != Q::Plan_status::VALENCE_6_LEFT) continue;
        Mesh w;
        auto v2v = copy_mesh_with_map(m, w);
        std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> p;
        for(auto v : path) p.push_back(v2v[v]);
        const auto plan = Q::plan_qzip(w, p, Q::Strip_operation(mo));
        Counters c;
        const bool predicted = check_predicted_failure(c, w, plan);
        assert(predicted && c.predicted_failures == 1);
        ++found;
      }
  return found;
}

void test_refusals_and_parameters()
{
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor vertex_descriptor;
  typedef boost::graph_traits<Surface_mesh>::edge_descriptor edge_descriptor;
  typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;
  Surface_mesh m;
  plant_chain(m, 24, 10, 5, 9, true);
  const auto sing = singular_vertices(m);
  vertex_descriptor s = sing[0], t = sing[1];
  for(auto a : sing) for(auto b : sing)
    if(a != b && Q::shortest_surgery_path(m, a, b).size() > Q::shortest_surgery_path(m, s, t).size()) { s = a; t = b; }
  const auto path = Q::shortest_surgery_path(m, s, t);
  assert(path.size() >= 9);

  // invalid paths and endpoints
  std::vector<vertex_descriptor> broken = { path[0], path[2] };
  assert(Q::plan_qzip(m, broken, Q::Strip_operation::LEFT_SPLIT).status == Q::Plan_status::INVALID_PATH);
  std::vector<vertex_descriptor> looped = { path[0], path[1], path[0] };
  assert(Q::plan_qzip(m, looped, Q::Strip_operation::LEFT_SPLIT).status == Q::Plan_status::INVALID_PATH);
  std::vector<vertex_descriptor> regular_end(path.begin(), path.end() - 1);
  if(valence(regular_end.back(), m) == 4)
    assert(Q::plan_qzip(m, regular_end, Q::Strip_operation::LEFT_SPLIT).status == Q::Plan_status::UNSUPPORTED_ENDPOINT);
  assert(Q::shortest_surgery_path(m, s, s).empty());

  // a path given by its halfedges plans like the same path given by its vertices
  {
    std::vector<boost::graph_traits<Surface_mesh>::halfedge_descriptor> halfedges;
    for(std::size_t i = 0; i + 1 < path.size(); ++i) halfedges.push_back(halfedge(path[i], path[i + 1], m).first);
    for(int motion = 0; motion < 4; ++motion)
    {
      const auto by_vertices = Q::plan_qzip(m, path, Q::Strip_operation(motion));
      const auto by_halfedges = Q::plan_qzip(m, halfedges, Q::Strip_operation(motion));
      assert(by_halfedges.status == by_vertices.status && by_halfedges.path == by_vertices.path &&
             by_halfedges.operations == by_vertices.operations);
    }
    std::swap(halfedges[0], halfedges[1]);
    assert(Q::plan_qzip(m, halfedges, Q::Strip_operation::LEFT_SPLIT).status == Q::Plan_status::INVALID_PATH);
  }

  // edge weights: making the edges around the shortest path's middle vertex expensive moves the path away
  {
    std::map<edge_descriptor, double> weights;
    for(auto e : edges(m)) weights[e] = 1.;
    for(auto h : CGAL::halfedges_around_target(halfedge(path[path.size() / 2], m), m)) weights[edge(h, m)] = 100.;
    const auto weighted = Q::shortest_surgery_path(m, s, t, Q::parameters::edge_weight_map(boost::make_assoc_property_map(weights)));
    assert(weighted.front() == s && weighted.back() == t && weighted.size() >= path.size());
    assert(std::find(weighted.begin(), weighted.end(), path[path.size() / 2]) == weighted.end());
    for(std::size_t i = 0; i + 1 < weighted.size(); ++i) assert(halfedge(weighted[i], weighted[i + 1], m).second);
  }

  // a protected face on the path: the planner refuses the path, the search goes around
  std::set<face_descriptor> protected_faces;
  for(auto h : CGAL::halfedges_around_target(halfedge(path[5], m), m))
    if(!is_border(h, m)) protected_faces.insert(face(h, m));
  auto fcm = CGAL::Boolean_property_map<std::set<face_descriptor> >(protected_faces);
  assert(Q::plan_qzip(m, path, Q::Strip_operation::LEFT_SPLIT, Q::parameters::face_is_constrained_map(fcm)).status ==
         Q::Plan_status::BORDER_OR_CONSTRAINED);
  const auto detour = Q::shortest_surgery_path(m, s, t, Q::parameters::face_is_constrained_map(fcm));
  assert(!detour.empty());
  for(std::size_t i = 1; i + 1 < detour.size(); ++i)
    for(auto h : CGAL::halfedges_around_target(halfedge(detour[i], m), m))
      assert(is_border(h, m) || protected_faces.count(face(h, m)) == 0);

  // protected faces and feature edges are bit-identical after every Q-zip along the detour
  std::map<face_descriptor, std::vector<Point> > protected_corners;
  for(auto f : protected_faces)
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) protected_corners[f].push_back(get(CGAL::vertex_point, m, v));
  std::set<edge_descriptor> features;
  for(auto h : CGAL::halfedges_around_target(halfedge(path[3], m), m)) features.insert(edge(h, m));
  std::map<edge_descriptor, std::pair<Point, Point> > feature_ends;
  for(auto e : features)
    feature_ends[e] = std::make_pair(get(CGAL::vertex_point, m, source(e, m)), get(CGAL::vertex_point, m, target(e, m)));
  auto ecm = CGAL::Boolean_property_map<std::set<edge_descriptor> >(features);
  Counting_visitor visitor;
  std::size_t done = 0;
  for(int mo = 0; mo < 4; ++mo)
  {
    Surface_mesh w = m;  // Surface_mesh copies keep descriptors
    auto np = Q::parameters::combine(CGAL::parameters::edge_is_constrained_map(ecm).visitor(std::ref(visitor)),
                                     Q::parameters::face_is_constrained_map(fcm));
    const auto r = Q::qzip(w, s, t, Q::Strip_operation(mo), np);
    if(!r.is_done()) continue;
    ++done;
    for(const auto& kv : protected_corners)
    {
      assert(!w.is_removed(kv.first));
      std::vector<Point> now;
      for(auto v : CGAL::vertices_around_face(halfedge(kv.first, w), w)) now.push_back(get(CGAL::vertex_point, w, v));
      assert(now == kv.second);
    }
    for(const auto& kv : feature_ends)
    {
      assert(!w.is_removed(kv.first));
      assert(get(CGAL::vertex_point, w, source(kv.first, w)) == kv.second.first);
      assert(get(CGAL::vertex_point, w, target(kv.first, w)) == kv.second.second);
    }
  }
  assert(done > 0);
  assert(visitor.started > 0 && visitor.finished == visitor.started && visitor.collapses + visitor.splits > 0);

  // with a user vertex point map, that map moves and the internal points stay
  Surface_mesh w = m;
  auto pts = w.add_property_map<vertex_descriptor, Point>("v:mine", Point(0, 0, 0)).first;
  std::map<vertex_descriptor, Point> native;
  for(auto v : vertices(w)) { put(pts, v, get(CGAL::vertex_point, w, v)); native[v] = get(CGAL::vertex_point, w, v); }
  const auto r = Q::qzip(w, s, t, Q::Strip_operation::LEFT_COLLAPSE, CGAL::parameters::vertex_point_map(pts));
  assert(r.is_done());
  bool moved_mine = false;
  for(auto v : vertices(w))
  {
    auto it = native.find(v);
    if(it == native.end()) continue;
    if(!r.is_done()) continue;
    if(std::find(r.touched_vertices.begin(), r.touched_vertices.end(), v) == r.touched_vertices.end())
      assert(get(CGAL::vertex_point, w, v) == it->second);
    if(get(pts, v) != get(CGAL::vertex_point, w, v)) moved_mine = true;
  }
  assert(moved_mine);
}

template <typename Mesh>
void run_corpus_file(const std::string& path, std::size_t count, unsigned seed, Counters& c)
{
  Mesh m;
  assert(read_mesh(path, m));
  Q::preprocess_valences(m);
  const std::size_t n = random_qzips(m, count, seed, c);
  std::cout << "  " << path << ": " << n << " Q-zips undone exactly" << std::endl;
}

// ---------------------------------------------------------------------------------------------
// Border end points: the terminal singularity is a border vertex with one quad too many

/// a grid whose bottom border carries steps (a border vertex with three quads next to one with one
/// quad) and whose inside carries the 3-5 pairs that made them: each is planted by collapsing, from
/// (i, k) straight down to the border, the quads on one side of the column, as a Q-zip chain would.
template <typename Mesh>
void make_grid_with_border_steps(Mesh& m, unsigned seed)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const int nx = 30, ny = 16;
  make_quad_grid(m, nx, ny);
  std::map<std::pair<int, int>, vertex_descriptor> at;
  for(vertex_descriptor v : vertices(m))
  {
    const Point& p = get(CGAL::vertex_point, m, v);
    at[std::make_pair(int(p.x()), int(p.y()))] = v;
  }
  CGAL::Random rng(seed);
  for(int column : { rng.get_int(3, 9), rng.get_int(13, 19), rng.get_int(22, 27) })
  {
    const int k = rng.get_int(3, 11);
    const bool east = rng.get_bool();
    for(int j = k; j >= 1; --j)
    {
      const auto o = halfedge(at[std::make_pair(column, j)], at[std::make_pair(column, j - 1)], m).first;
      const auto h = east ? o : prev(opposite(o, m), m);
      assert(Q::can_collapse_quad(h, m));
      Q::quad_collapse(h, m);
    }
  }
  relax_inside(m); // unfold (the border is convex and fixed)
}

/// every pair (interior singularity, border vertex with defect +1) at most `max_length` edges apart,
/// in the four motions: executed Q-zips keep every invariant (border defects included), a located
/// border end lands on the plan's last vertex, and the history gives back the mesh.
template <typename Mesh>
void border_endpoint_qzips(Mesh& m, std::size_t max_length, Counters& c, std::size_t& border_moves,
                           std::map<Q::Plan_status, std::size_t>* reached_along_border = nullptr, int target_defect = 1)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Mesh original;
  copy_mesh(m, original);
  const std::vector<std::pair<Point, Point> > pairs = interior_to_border_defect_pairs(m, max_length, target_defect);
  std::map<Point, vertex_descriptor> at;
  for(const auto& pair : pairs)
    for(int motion = 0; motion < 4; ++motion)
      for(int side = 0; side < (reached_along_border ? 2 : 1); ++side)
      {
        if(at.empty()) at = vertices_by_position(m);
        // the shortest path, or with `reached_along_border` a path that reaches the target along the
        // border (with the mesh on its left, or on its right)
        const auto sketch = reached_along_border
                              ? path_along_border(m, at.at(pair.first), 12, side == 0, 8, at.at(pair.second))
                              : Q::shortest_surgery_path(m, at.at(pair.first), at.at(pair.second));
        if(sketch.empty()) continue;
        const auto plan = Q::plan_qzip(m, sketch, Q::Strip_operation(motion));
        if(reached_along_border) ++(*reached_along_border)[plan.status];
        // from the border defect: the plan of the reversed sketch, whose chain starts inside
        const auto from_border = Q::plan_qzip(m, std::vector<vertex_descriptor>(sketch.rbegin(), sketch.rend()),
                                              Q::Strip_operation(motion));
        assert(from_border.status == plan.status && from_border.source == sketch.front() &&
               from_border.path == plan.path && from_border.operations == plan.operations);
        if(check_predicted_failure(c, m, plan)) at.clear();
        if(!plan.is_realizable()) { ++c.refused; continue; }
        assert(on_border(plan.path.back(), m) && plan.path[plan.path.size() - (target_defect == 1 ? 2 : 1)] == sketch.back());
        const Snapshot<Mesh> before(m);
        Q::Qzip_history<Mesh> history(m);
        const auto r = Q::execute_qzip(m, plan, history);
        at.clear(); // a roll-back re-creates elements too
        if(!r.is_done())
        {
          ++c.rolled_back;
          assert(CGAL::is_valid_polygon_mesh(m) && singularity_codes(m) == before.singular);
          continue;
        }
        check_done(m, before, r, c);
        if(r.moved_target != boost::graph_traits<Mesh>::null_vertex())
        {
          // +1: the defect moved to the appended border neighbour e; -1: t is regular now and the defect
          // moved to one of its neighbours (the last guide's target, E1)
          assert(on_border(r.moved_target, m));
          assert(target_defect == 1 ? r.moved_target == plan.path.back()
                                    : halfedge(r.moved_target, plan.path.back(), m).second);
          assert(Q::vertex_defect(r.moved_target, m) == target_defect);
          ++border_moves;
        }
        history.undo_all();
        assert(CGAL::is_valid_polygon_mesh(m) && are_isomorphic(m, original));
        assert(sorted_points(m) == sorted_points(original));
      }
}

void test_border_endpoints()
{
  Counters grid_sm, grid_ph, real;
  std::size_t moves_sm = 0, moves_ph = 0, moves_real = 0;
  Counters along_c, along_real, minus_c;
  std::size_t moves_minus = 0;
  std::map<Q::Plan_status, std::size_t> minus;
  std::size_t moves_along = 0, moves_along_real = 0;
  std::map<Q::Plan_status, std::size_t> along, along_real_plans;
  for(unsigned seed = 1; seed <= 4; ++seed)
  {
    Surface_mesh sm;
    make_grid_with_border_steps(sm, seed);
    border_endpoint_qzips(sm, 14, grid_sm, moves_sm);
    border_endpoint_qzips(sm, 14, along_c, moves_along, &along);
    border_endpoint_qzips(sm, 14, minus_c, moves_minus, &minus, -1);
    Polyhedron ph;
    make_grid_with_border_steps(ph, seed);
    border_endpoint_qzips(ph, 14, grid_ph, moves_ph);
  }
  along_c.print("border end points reached along the border, planted grids, Surface_mesh");
  std::cout << "    plans:";
  for(const auto& kv : along) std::cout << " " << kv.second << " (" << Q::describe(kv.first) << ")";
  std::cout << "; border defects moved: " << moves_along << std::endl;
  assert(moves_along > 0);
  grid_sm.print("border end points, planted grids, Surface_mesh");
  grid_ph.print("border end points, planted grids, Polyhedron_3");
  assert(grid_sm.done == grid_ph.done && moves_sm == moves_ph);
  assert(moves_sm > 0 && grid_sm.cancelling > 0); // the border defect moves, or cancels a neighbour one
  for(const char* f : { "data/polylap_suzanne_half.obj", "data/trimesh_target.obj" })
  {
    Surface_mesh m;
    const bool ok = read_mesh(f, m);
    assert(ok);
    border_endpoint_qzips(m, 10, real, moves_real);
    border_endpoint_qzips(m, 10, along_real, moves_along_real, &along_real_plans);
    border_endpoint_qzips(m, 10, minus_c, moves_minus, &minus, -1);
  }
  along_real.print("border end points reached along the border, bundled meshes with borders");
  minus_c.print("border end points with one quad too few, reached along the border, grids and bundled meshes");
  std::cout << "    plans:";
  for(const auto& kv : minus) std::cout << " " << kv.second << " (" << Q::describe(kv.first) << ")";
  std::cout << "; border defects moved: " << moves_minus << std::endl;
  assert(moves_minus > 0);
  std::cout << "    plans:";
  for(const auto& kv : along_real_plans) std::cout << " " << kv.second << " (" << Q::describe(kv.first) << ")";
  std::cout << "; border defects moved: " << moves_along_real << std::endl;
  real.print("border end points, bundled meshes with borders");
  assert(moves_real > 0);
  // 11 rolled back on the bundled meshes before the simulation, which refuses them now
  for(const Counters* c : { &grid_sm, &grid_ph, &along_c, &along_real, &minus_c, &real }) assert(c->rolled_back == 0);
  assert(real.simulated_failures + along_real.simulated_failures > 0);
  std::cout << "  border defects moved by one edge: " << moves_sm << " + " << moves_ph << " (grids), "
            << moves_real << " (bundled meshes)" << std::endl;
}


// ---------------------------------------------------------------------------------------------
// Paths along the border: inner path vertices on the border

/// how the border-path Q-zips went: done, or the plan status that refused them
struct Border_path_counters
{
  Counters c;
  std::map<Q::Plan_status, std::size_t> refused;
  std::map<Q::Reverse_qzip_status, std::size_t> no_reverse;
  std::map<Q::Execution_failure, std::size_t> failures;
  std::size_t plans = 0, halfedge_form = 0, reversed = 0;
  std::size_t no_reverse_count(Q::Reverse_qzip_status st) const
  { const auto it = no_reverse.find(st); return it == no_reverse.end() ? 0 : it->second; }
  void print(const char* what) const
  {
    std::cout << "  " << what << ": " << plans << " plans, " << c.done << " done (" << c.cancelling
              << " cancelling singularities), " << c.rolled_back << " rolled back (";
    for(const auto& kv : failures) std::cout << kv.second << ": " << Q::describe(kv.first) << "; ";
    std::cout << "); refused:";
    for(const auto& kv : refused) std::cout << " " << kv.second << " (" << Q::describe(kv.first) << ")";
    std::cout << "; " << c.predicted_failures << " refused by a local check and " << c.simulated_failures
              << " by the simulation, each failing when forced";
    std::cout << "; " << reversed << " undone by their reverse Q-zip (isomorphic), "
              << no_reverse_count(Q::Reverse_qzip_status::SINGULARITIES_CANCELLED) << " without a reverse (cancelled singularities)"
              << std::endl;
  }
};

/// a grid with singularities near its bottom border, planted at (x, y) by `kind`: 0 (1) a split of a
/// regular vertex between its east and west (north and south) edges, which leaves two v5 on either side of
/// it and two v3 (the split vertex and its copy); k >= 2 a chain of k collapses up the column x, merging
/// (x - 1, y + i) into (x, y + i + 1), which leaves a 3-5 pair (x, y), (x, y + 1) and a 5-3 pair
/// (x, y + k), (x - 1, y + k)
template <typename Mesh>
void make_grid_with_planted_pairs(Mesh& m, int nx, int ny, const std::vector<std::array<int, 3> >& splits)
{
  make_quad_grid(m, nx, ny);
  std::map<std::pair<int, int>, typename boost::graph_traits<Mesh>::vertex_descriptor> at;
  for(auto v : vertices(m))
    at[std::make_pair(int(get(CGAL::vertex_point, m, v).x()), int(get(CGAL::vertex_point, m, v).y()))] = v;
  for(const std::array<int, 3>& sp : splits)
  {
    const int x = sp[0], y = sp[1];
    if(sp[2] >= 2)
    {
      for(int i = 0; i < sp[2]; ++i)
      {
        const auto p = at[std::make_pair(x, y + i + 1)], r = at[std::make_pair(x - 1, y + i)];
        const auto h = halfedge(at[std::make_pair(x, y + i)], p, m).first; // the quad on its left has corners p, r
        assert(target(next(next(h, m), m), m) == r && Q::can_collapse_quad(h, m));
        Q::quad_collapse(h, m);
      }
      continue;
    }
    const bool vertical = sp[2] == 1;
    const auto v = at[std::make_pair(x, y)];
    const auto b = vertical ? at[std::make_pair(x, y + 1)] : at[std::make_pair(x + 1, y)];
    const auto d = vertical ? at[std::make_pair(x, y - 1)] : at[std::make_pair(x - 1, y)];
    const auto q = Q::split_vertex_into_quad(halfedge(b, v, m).first, halfedge(d, v, m).first, m);
    const auto c = target(next(next(q, m), m), m);
    put(get(CGAL::vertex_point, m), c, vertical ? Point(x - 0.5, y, 0) : Point(x, y + 0.5, 0));
  }
}

/// the vertex path through the grid points `corners`, joined by straight runs of unit edges; empty when a
/// point is missing or two consecutive points are not joined by an edge
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
grid_polyline(const Mesh& m, const std::map<Point, typename boost::graph_traits<Mesh>::vertex_descriptor>& at,
              const std::vector<std::pair<int, int> >& corners)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> path;
  for(std::size_t k = 0; k < corners.size(); ++k)
  {
    int x = corners[k].first, y = corners[k].second;
    const int tx = k + 1 < corners.size() ? corners[k + 1].first : x, ty = k + 1 < corners.size() ? corners[k + 1].second : y;
    do
    {
      const auto it = at.find(Point(x, y, 0));
      if(it == at.end()) return {};
      if(path.empty() || path.back() != it->second)
      {
        if(!path.empty() && !halfedge(path.back(), it->second, m).second) return {};
        path.push_back(it->second);
      }
      if(x == tx && y == ty) break;
      x += (tx > x) - (tx < x); y += (ty > y) - (ty < y);
    } while(true);
  }
  return path;
}

/// plans and executes `path` in `motion` on a copy of `m`, checks the invariants and the undo by a
/// history, and leaves the result in `result`; true when the Q-zip was done
template <typename Mesh>
bool border_path_qzip(const Mesh& m, const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& path,
                      int motion, Mesh& result, Border_path_counters& bc)
{
  auto v2v = copy_mesh_with_map(m, result);
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> p;
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> hs;
  for(std::size_t i = 0; i < path.size(); ++i)
  {
    p.push_back(v2v[path[i]]);
    if(i > 0) hs.push_back(halfedge(p[i - 1], p[i], result).first);
  }
  ++bc.plans;
  const auto plan = Q::plan_qzip(result, p, Q::Strip_operation(motion));
  if((bc.halfedge_form++) % 3 == 0) // the halfedge form of the same path gives the same plan
  {
    const auto by_halfedges = Q::plan_qzip(result, hs, Q::Strip_operation(motion));
    assert(by_halfedges.status == plan.status && by_halfedges.path == plan.path && by_halfedges.operations == plan.operations);
  }
  check_predicted_failure(bc.c, result, plan);
  if(!plan.is_realizable()) { ++bc.refused[plan.status]; return false; }
  Mesh original;
  copy_mesh(result, original);
  const Snapshot<Mesh> before(result);
  Q::Qzip_history<Mesh> history(result);
  const auto r = Q::execute_qzip(result, plan, history);
  if(!r.is_done())
  {
    ++bc.c.rolled_back;
    ++bc.failures[r.failure];
    assert(CGAL::is_valid_polygon_mesh(result) && are_isomorphic(result, original));
    assert(sorted_points(result) == sorted_points(original));
    return false;
  }
  check_done(result, before, r, bc.c);
  Mesh done;
  copy_mesh(result, done);
  history.undo_all();
  assert(CGAL::is_valid_polygon_mesh(result) && are_isomorphic(result, original));
  assert(sorted_points(result) == sorted_points(original));
  if(r.reverse_status == Q::Reverse_qzip_status::AVAILABLE)
  {
    // the same Q-zip on another copy, undone by its reverse Q-zip
    Mesh second;
    auto v2v2 = copy_mesh_with_map(m, second);
    std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> p2;
    for(auto v : path) p2.push_back(v2v2[v]);
    const auto again = Q::execute_qzip(second, Q::plan_qzip(second, p2, Q::Strip_operation(motion)));
    assert(again.is_done() && are_isomorphic(second, done));
    const auto back = Q::reverse_qzip(second, again);
    assert(back.is_done() && are_isomorphic(second, original));
    ++bc.reversed;
  }
  else ++bc.no_reverse[r.reverse_status];
  copy_mesh(done, result);
  return true;
}

/// Pairs of singularities near the border of a grid, joined by a path that runs along the border (with
/// the mesh on its left or on its right, around a corner or not) and by the path one row inside it; the
/// strip between the two is regular, so when both are realizable the two meshes must be isomorphic.
struct Border_homotopy_counters
{
  Border_path_counters along, inside;
  std::size_t both = 0, only_along = 0, only_inside = 0, around_corner = 0;
  void print(const char* what) const
  {
    along.print((std::string(what) + ", paths along the border").c_str());
    inside.print((std::string(what) + ", paths one row inside").c_str());
    std::cout << "    done along the border and inside (isomorphic): " << both << " (" << around_corner
              << " around a corner); only along the border: " << only_along << "; only inside: " << only_inside << std::endl;
  }
};

template <typename Mesh>
void test_border_path_homotopy(Border_homotopy_counters& bc)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const std::vector<std::vector<std::array<int, 3> > > layouts = {
    { { 5, 2, 0 }, { 11, 3, 1 } }, { { 4, 3, 0 }, { 10, 2, 0 } }, { { 3, 4, 1 }, { 12, 2, 1 } }, { { 6, 2, 1 }, { 2, 6, 0 } },
    { { 3, 5, 0 }, { 12, 4, 0 } }, { { 4, 2, 1 }, { 13, 5, 1 } }, { { 3, 2, 6 }, { 10, 3, 5 } },
    { { 4, 3, 7 }, { 12, 2, 0 } }, { { 6, 2, 5 }, { 11, 2, 6 } } };
  for(const auto& layout : layouts)
  {
    Mesh m;
    make_grid_with_planted_pairs(m, 16, 12, layout);
    std::map<Point, vertex_descriptor> at;
    for(auto v : vertices(m)) at[get(CGAL::vertex_point, m, v)] = v;
    const auto sing = singular_vertices(m);
    for(vertex_descriptor s : sing)
      for(vertex_descriptor t : sing)
      {
        const Point ps = get(CGAL::vertex_point, m, s), pt = get(CGAL::vertex_point, m, t);
        const int xs = int(ps.x()), ys = int(ps.y()), xt = int(pt.x()), yt = int(pt.y());
        if(s == t || ps != Point(xs, ys, 0) || pt != Point(xt, yt, 0)) continue;
        // along the bottom border (the mesh on the left going east, on the right going west), and around
        // the bottom-left corner; the path one row inside each
        std::vector<std::pair<std::vector<std::pair<int, int> >, std::vector<std::pair<int, int> > > > shapes;
        for(int dx : { 0, -1, 1 })
          if(xs + dx != xt)
            shapes.push_back({ { { xs, ys }, { xs + dx, ys }, { xs + dx, 0 }, { xt, 0 }, { xt, yt } },
                               { { xs, ys }, { xs + dx, ys }, { xs + dx, 1 }, { xt, 1 }, { xt, yt } } });
        if(xs > 1 && ys > 1)
          shapes.push_back({ { { xs, ys }, { 0, ys }, { 0, 0 }, { xt, 0 }, { xt, yt } },
                             { { xs, ys }, { 1, ys }, { 1, 1 }, { xt, 1 }, { xt, yt } } });
        for(const auto& shape : shapes)
        {
          const bool corner = shape.first.size() == 5 && shape.first[2] == std::make_pair(0, 0);
          const auto along = grid_polyline(m, at, shape.first), inside = grid_polyline(m, at, shape.second);
          if(along.empty() || inside.empty() || !Q::internal::is_simple_edge_path(along, m) ||
             !Q::internal::is_simple_edge_path(inside, m) || along[1] != inside[1])
            continue;
          // no other singularity on the paths, none between them
          std::vector<Point> loop;
          for(auto v : along) loop.push_back(get(CGAL::vertex_point, m, v));
          for(std::size_t x = inside.size() - 1; x-- > 1;) loop.push_back(get(CGAL::vertex_point, m, inside[x]));
          bool clear = true;
          for(vertex_descriptor o : sing)
          {
            if(o == s || o == t) continue;
            if(std::count(along.begin(), along.end(), o) || std::count(inside.begin(), inside.end(), o) ||
               winding_number(loop, get(CGAL::vertex_point, m, o)) != 0)
              clear = false;
          }
          if(!clear) continue;
          for(int motion = 0; motion < 4; ++motion)
          {
            Mesh by_border, by_inside;
            const bool a = border_path_qzip(m, along, motion, by_border, bc.along);
            const bool b = border_path_qzip(m, inside, motion, by_inside, bc.inside);
            if(a && b) { assert(are_isomorphic(by_border, by_inside)); ++bc.both; if(corner) ++bc.around_corner; }
            else if(a) ++bc.only_along;
            else if(b) ++bc.only_inside;
          }
        }
      }
  }
}

/// Q-zips along caller-given paths that run along the border of real meshes (see path_along_border())
template <typename Mesh>
void border_path_qzips(const std::string& file, std::size_t count, unsigned seed, Border_path_counters& bc)
{
  Mesh m;
  const bool ok = read_mesh(file, m);
  assert(ok);
  Q::preprocess_valences(m);
  CGAL::Random rng(seed);
  const auto sing = singular_vertices(m);
  for(std::size_t tried = 0, found = 0; found < count && tried < 40 * count; ++tried)
  {
    const auto s = sing[std::size_t(rng.get_int(0, int(sing.size())))];
    const auto path = path_along_border(m, s, rng.get_int(1, 7), rng.get_bool(), 8);
    if(path.empty()) continue;
    ++found;
    Mesh result;
    border_path_qzip(m, path, rng.get_int(0, 4), result, bc);
  }
}

void test_border_paths()
{
  Border_homotopy_counters grid_sm, grid_ph;
  Border_path_counters real;
  test_border_path_homotopy<Surface_mesh>(grid_sm);
  test_border_path_homotopy<Polyhedron>(grid_ph);
  grid_sm.print("planted grids, Surface_mesh");
  grid_ph.print("planted grids, Polyhedron_3");
  assert(grid_sm.along.c.done == grid_ph.along.c.done && grid_sm.both == grid_ph.both);
  // one row inside: 2 plans rolled back before the simulation (a new singularity), then refused by it; they
  // arrived at a v5 by a U-turn, which the end rule now straightens, and are done
  assert(grid_sm.along.c.rolled_back == 0 && grid_sm.inside.c.rolled_back == 0 && grid_ph.along.c.rolled_back == 0 &&
         grid_ph.inside.c.rolled_back == 0);
  assert(grid_sm.inside.c.simulated_failures == grid_ph.inside.c.simulated_failures);
  assert(grid_sm.inside.refused.count(Q::Plan_status::SPLIT_WITHOUT_GUIDE) != 0);
  assert(grid_sm.both > 0 && grid_sm.around_corner > 0 && grid_sm.along.reversed > 0);
  // every Q-zip along the border either cancelled singularities or has a reverse Q-zip
  assert(grid_sm.along.c.done == grid_sm.along.reversed + grid_sm.along.no_reverse_count(Q::Reverse_qzip_status::SINGULARITIES_CANCELLED));
  for(const char* f : { "data/polylap_suzanne_half.obj", "data/trimesh_target.obj" })
    border_path_qzips<Surface_mesh>(f, 60, 5, real);
  border_path_qzips<Polyhedron>("data/polylap_suzanne_half.obj", 30, 6, real);
  real.print("paths along the border, bundled meshes");
  assert(real.c.rolled_back == 0); // 3 before the simulation
  assert(real.c.done > 0 && real.c.done == real.reversed + real.no_reverse_count(Q::Reverse_qzip_status::SINGULARITIES_CANCELLED));
}

int main(int argc, char** argv)
{
  const std::size_t per_mesh = argc > 1 ? std::size_t(std::atoi(argv[1])) : 150;

  Counters planted_sm, planted_ph;
  std::size_t longest = 0;
  test_planted_pairs<Surface_mesh>(planted_sm, longest);
  planted_sm.print("planted pairs, Surface_mesh");
  test_planted_pairs<Polyhedron>(planted_ph, longest);
  planted_ph.print("planted pairs, Polyhedron_3");
  std::cout << "  longest planted path: " << longest << " edges" << std::endl;
  assert(longest >= 45);
  assert(planted_sm.done > 0 && planted_sm.located > 0);
  assert(planted_sm.done == planted_ph.done && planted_sm.located == planted_ph.located);
  assert(planted_sm.rolled_back == 0 && planted_ph.rolled_back == 0);

  std::size_t homotopic = 0, differing = 0;
  Counters homotopy;
  for(unsigned seed = 1; seed <= 3; ++seed)
    test_homotopy<Surface_mesh>(seed, homotopic, differing, homotopy);
  test_homotopy<Polyhedron>(4, homotopic, differing, homotopy);
  std::cout << "  homotopy: " << homotopic << " homotopic path pairs gave isomorphic meshes; "
            << differing << " non-homotopic pairs gave different meshes" << std::endl;
  homotopy.print("homotopy, waypoint paths");
  assert(homotopic > 100);
  // a first split without guide (SPLIT_WITHOUT_GUIDE); the 5 plans whose simulation failed arrived at a v5 by a
  // U-turn and lost t, and are realizable since the end rule straightens that arrival
  assert(homotopy.rolled_back == 0 && homotopy.predicted_failures >= 1);

  Spiral_counts spirals;
  Counters spiral_plans;
  test_spiral_paths<Surface_mesh>(5, spirals, spiral_plans);
  test_spiral_paths<Polyhedron>(6, spirals, spiral_plans);
  std::cout << "  spiral paths: " << spirals.paths << " paths winding one to two and a half times around another singularity, "
            << spirals.spirals_done << " Q-zips done along them (each checked and undone), " << spirals.homotopic_spirals
            << " pairs of homotopic spirals isomorphic, " << spirals.turns_differing
            << " pairs with different turns giving different meshes" << std::endl;
  spiral_plans.print("spiral paths");
  assert(spirals.spirals_done > 100 && spirals.homotopic_spirals > 20 && spirals.turns_differing > 0);
  assert(spiral_plans.rolled_back == 0);

  Homotopy_counts homotopy_real;
  Counters homotopy_real_plans;
  unsigned homotopy_seed = 20;
  for(const std::string f : { "data/polylap_amo_quad.off", "data/pmp_fandisk_quads.off", "data/polylap_suzanne_half.obj",
                              "data/quadriflow_gargoyle.obj", "data/trimesh_target.obj" })
    test_homotopy_on_mesh<Surface_mesh>(f, 40, homotopy_seed++, homotopy_real, homotopy_real_plans);
  test_homotopy_on_mesh<Surface_mesh>(CGAL::data_file_path("meshes/spot_quadrangulated.obj"), 40, homotopy_seed++,
                                      homotopy_real, homotopy_real_plans);
  test_homotopy_on_mesh<Polyhedron>("data/polylap_amo_quad.off", 20, homotopy_seed++, homotopy_real, homotopy_real_plans);
  std::cout << "  homotopy on real meshes (a shortest path and its copy swept over 1-6 regular quads away from other "
               "singularities): " << homotopy_real.isomorphic << " pairs of done Q-zips isomorphic ("
            << homotopy_real.u_turn_isomorphic << " arriving at a v5 by a U-turn around one quad), "
            << homotopy_real.differing << " not; " << homotopy_real.done << " done, " << homotopy_real.refused
            << " refused by the plan, " << homotopy_real.rolled_back << " rolled back, "
            << homotopy_real_plans.predicted_failures << " refused by a local check and "
            << homotopy_real_plans.simulated_failures << " by the simulation, each failing when forced" << std::endl;
  // the end rule E3 straightens a U-turn arrival (manual, "What Our Tests Found"): before, those pairs
  // differed
  assert(homotopy_real.isomorphic > 300 && homotopy_real.u_turn_isomorphic > 20);
  assert(homotopy_real.differing == 0);
  assert(homotopy_real.rolled_back == 0);
  {
    Surface_mesh grid, amo;
    plant_chain(grid, 24, 11, 7, 5, true);
    assert(read_mesh("data/polylap_amo_quad.off", amo));
    Q::preprocess_valences(amo);
    const std::size_t on_grid = test_u_turn_arrivals(grid), on_amo = test_u_turn_arrivals(amo);
    std::cout << "  U-turn arrivals at a v5 planned as the straight arrival: " << on_grid << " plans (planted grid), "
              << on_amo << " (polylap_amo_quad)" << std::endl;
    assert(on_grid > 0 && on_amo > 0);
  }

  test_refusals_and_parameters();
  std::cout << "  refusals, constraints, visitor and named parameters ok" << std::endl;
  const std::size_t valence_6_sm = test_valence_6_left<Surface_mesh>("data/noisy_sphere_triquad.obj", 5);
  const std::size_t valence_6_ph = test_valence_6_left<Polyhedron>("data/noisy_sphere_triquad.obj", 5);
  std::cout << "  plans refused for a valence 6 left without clean-up, noisy_sphere_triquad: " << valence_6_sm
            << " (Surface_mesh), " << valence_6_ph << " (Polyhedron_3), each failing when forced" << std::endl;
  assert(valence_6_sm > 0 && valence_6_sm == valence_6_ph);

  test_border_endpoints();
  test_border_paths();

  test_reverse_qzip(per_mesh / 3);
  test_border_defect_reverse();
  test_feature_end_moves();

  Counters random_sm, random_ph;
  for(const std::string f : { "data/polylap_amo_quad.off", "data/pmp_fandisk_quads.off", "data/polylap_suzanne_half.obj",
                              "data/quadriflow_gargoyle.obj", "data/trimesh_target.obj" })
    run_corpus_file<Surface_mesh>(f, per_mesh, 7, random_sm);
  for(const std::string f : { CGAL::data_file_path("meshes/spot_quadrangulated.obj"),
                              CGAL::data_file_path("meshes/blub_quadrangulated.obj") })
    run_corpus_file<Surface_mesh>(f, per_mesh, 8, random_sm);
  run_corpus_file<Polyhedron>("data/polylap_amo_quad.off", per_mesh / 2, 9, random_ph);
  run_corpus_file<Polyhedron>(CGAL::data_file_path("meshes/spot_quadrangulated.obj"), per_mesh / 2, 10, random_ph);
  random_sm.print("random Q-zips on bundled meshes, Surface_mesh");
  random_ph.print("random Q-zips on bundled meshes, Polyhedron_3");
  assert(random_sm.done > 0 && random_ph.done > 0);
  assert(random_sm.rolled_back == 0 && random_ph.rolled_back == 0);

  std::size_t compared = 0, refused_by_simulation = 0;
  test_simulation_history<Surface_mesh>("data/quadriflow_gargoyle.obj", 12, compared, refused_by_simulation);
  test_simulation_history<Polyhedron>("data/polylap_amo_quad.off", 13, compared, refused_by_simulation);
  std::cout << "  simulation buffers: " << compared << " plans made again in the reverse order gave the same plans ("
            << refused_by_simulation << " refused by the simulation)" << std::endl;
  assert(compared == 480 && refused_by_simulation > 0);

  const std::string dir = shared_corpus_dir("random Q-zips on the shared corpus");
  if(!dir.empty())
  {
    Counters shared;
    for(const std::string& f : shared_corpus_files())
    {
      if(f == "trimesh_quadknot.obj") continue; // no singularity at all
      run_corpus_file<Surface_mesh>(dir + "/" + f, per_mesh * 2 / 3, 11, shared);
    }
    shared.print("random Q-zips on the shared corpus, Surface_mesh");
    // 16 rollbacks before VALENCE_6_LEFT was refused by the plan, 13 before the simulation
    assert(shared.rolled_back == 0 && shared.simulated_failures > 0);
  }
  return EXIT_SUCCESS;
}
