// Tests of the reverse Q-zip (paper, Sec. 2.8): `Qzip::reverse_qzip()` undoes a Q-zip up to isomorphism,
// and the reverse of the reverse redoes it; Q-zips without a reverse are refused for the documented reasons.
// (Q-zips that move a border defect: qzip_border_end_tests.h.)
#ifndef QZIP_REVERSE_QZIP_TESTS_H
#define QZIP_REVERSE_QZIP_TESTS_H

#include "qzip_test_utils.h"

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/singularities.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace qzip_test {

/// how the random Q-zips of `random_reverse_qzips()` went, by `Reverse_qzip_status`.
struct Reverse_counters
{
  std::size_t forward_done = 0, reversed = 0, redone = 0, redo_refused = 0;
  std::size_t with_prelude = 0, with_created = 0; // reversed Q-zips whose reverse undid a clean-up, re-created a path vertex
  std::map<CGAL::Qzip::Reverse_qzip_status, std::size_t> by_status;

  void add(const Reverse_counters& o)
  {
    forward_done += o.forward_done; reversed += o.reversed; redone += o.redone; redo_refused += o.redo_refused;
    with_prelude += o.with_prelude; with_created += o.with_created;
    for(const auto& kv : o.by_status) by_status[kv.first] += kv.second;
  }
  std::size_t count(CGAL::Qzip::Reverse_qzip_status s) const
  { auto it = by_status.find(s); return it == by_status.end() ? std::size_t(0) : it->second; }
  void print(const char* what) const
  {
    typedef CGAL::Qzip::Reverse_qzip_status S;
    std::cout << "  " << what << ": " << forward_done << " Q-zips done, " << reversed
              << " undone by their reverse Q-zip (isomorphic; " << with_prelude << " undoing a clean-up first, "
              << with_created << " re-creating merged path vertices), " << redone
              << " redone by the reverse of the reverse (" << redo_refused << " redos refused); no reverse: "
              << count(S::SINGULARITIES_CANCELLED) << " cancelled singularities, " << count(S::CLEANED_UP)
              << " clean-up not undoable, " << count(S::GUIDE_NOT_RESTORABLE) << " without a guide" << std::endl;
  }
};

template <typename Mesh>
std::size_t number_of_singularities(const Mesh& m)
{
  std::size_t n = 0;
  for(auto v : vertices(m)) if(!on_border(v, m) && valence(v, m) != 4) ++n;
  return n;
}

/// `count` random Q-zips between singularities at most 10 edges apart, each undone by its reverse Q-zip
/// when it has one (checked against a copy of the mesh before), else by a `Qzip_history`; every few,
/// the reverse of the reverse redoes the Q-zip.
template <typename Mesh>
Reverse_counters random_reverse_qzips(Mesh& m, std::size_t count, unsigned seed)
{
  namespace Q = CGAL::Qzip;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  Reverse_counters c;
  CGAL::Random rng(seed);
  Mesh original;
  copy_mesh(m, original);
  const std::size_t singularities = number_of_singularities(m);
  for(std::size_t it = 0, attempts = 0; it < count && attempts < 20 * count; ++attempts)
  {
    std::vector<vertex_descriptor> sing;
    for(auto v : vertices(m)) if(!on_border(v, m) && (valence(v, m) == 3 || valence(v, m) == 5)) sing.push_back(v);
    if(sing.size() < 2) break;
    const vertex_descriptor s = sing[std::size_t(rng.get_int(0, int(sing.size())))];
    const auto near = singularities_within(m, s, 1, 10);
    if(near.empty()) continue;
    const vertex_descriptor t = near[std::size_t(rng.get_int(0, int(near.size())))];
    const auto path = Q::shortest_surgery_path(m, s, t);
    if(path.empty()) continue;
    const auto plan = Q::plan_qzip(m, path, Q::Strip_operation(rng.get_int(0, 4)));
    if(!plan.is_realizable()) continue;
    Q::Qzip_history<Mesh> history(m);
    const auto r = Q::execute_qzip(m, plan, history);
    if(!r.is_done())
    {
      assert(r.reverse_status == Q::Reverse_qzip_status::NOT_DONE);
      continue;
    }
    ++it;
    ++c.forward_done;
    ++c.by_status[r.reverse_status];
    switch(r.reverse_status)
    {
      case Q::Reverse_qzip_status::AVAILABLE:
      {
        const auto& rev = r.reverse_plan;
        assert(rev.is_realizable() && rev.path.size() == rev.operations.size());
        assert(rev.operations.back() == Q::Strip_operation::NO_OPERATION);
        assert(rev.number_of_collapses() == r.number_of_splits && rev.number_of_splits() == r.number_of_collapses);
        assert(rev.prelude.size() == r.number_of_cleanups);
        for(std::size_t i = 0; i < rev.path.size(); ++i)
        {
          const bool created = std::any_of(rev.created_vertices.begin(), rev.created_vertices.end(),
                                           [i](const auto& cv) { return cv.index == i; });
          assert(created == (rev.path[i] == boost::graph_traits<Mesh>::null_vertex()));
        }
        for(const auto& cv : rev.created_vertices)
          assert(cv.split < cv.index || (cv.split >= rev.path.size() && cv.split < rev.path.size() + rev.prelude.size()));
        if(!rev.prelude.empty()) ++c.with_prelude;
        if(!rev.created_vertices.empty()) ++c.with_created;
        const bool redo = it % 4 == 0;
        Mesh after;
        if(redo) copy_mesh(m, after);
        const auto back = Q::reverse_qzip(m, r);
        assert(back.is_done());
        assert(back.number_of_collapses == r.number_of_splits && back.number_of_splits == r.number_of_collapses);
        assert(CGAL::is_valid_polygon_mesh(m));
        assert(are_isomorphic(m, original));
        ++c.reversed;
        if(redo && back.reverse_status != Q::Reverse_qzip_status::AVAILABLE)
        {
          // a reverse plan is undone by its own reverse, except when its prelude re-created a
          // valence-6 vertex with several admissible splits
          assert(back.reverse_status == Q::Reverse_qzip_status::CLEANED_UP && !rev.prelude.empty());
          ++c.redo_refused;
        }
        if(redo && back.reverse_status == Q::Reverse_qzip_status::AVAILABLE)
        {
          const auto again = Q::reverse_qzip(m, back);
          assert(again.is_done() && are_isomorphic(m, after));
          ++c.redone;
          const auto back_again = Q::reverse_qzip(m, again);
          assert(back_again.is_done() && are_isomorphic(m, original));
        }
        break;
      }
      case Q::Reverse_qzip_status::SINGULARITIES_CANCELLED:
        assert(number_of_singularities(m) < singularities);
        break;
      case Q::Reverse_qzip_status::CLEANED_UP:
        assert(r.number_of_cleanups > 1);
        break;
      default:
        break;
    }
    if(r.reverse_status != Q::Reverse_qzip_status::AVAILABLE)
    {
      // refused up front: nothing happens
      const auto none = Q::reverse_qzip(m, r);
      assert(!none.is_done() && none.status == Q::Plan_status::INVALID_PATH);
      Q::undo_qzip(history);
      assert(are_isomorphic(m, original));
    }
    assert(number_of_singularities(m) == singularities);
  }
  return c;
}

/// a planar grid with planted pairs: `chains` chains of collapses along rows, each leaving a 3 and a 5 at
/// each end (see `plant_chain()` in test_qzip.cpp), at random places.
template <typename Mesh>
void plant_random_chains(Mesh& m, int n, int chains, CGAL::Random& rng)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  make_quad_grid(m, n, n);
  std::map<std::pair<int, int>, vertex_descriptor> at;
  for(auto v : vertices(m))
  {
    const Point& p = get(CGAL::vertex_point, m, v);
    at[std::make_pair(int(p.x()), int(p.y()))] = v;
  }
  for(int k = 0; k < chains; ++k)
  {
    const int len = rng.get_int(1, 7), row = 3 + 4 * k, col = rng.get_int(3, n - len - 3);
    for(int i = 0; i < len; ++i)
    {
      const vertex_descriptor p1 = at[std::make_pair(col + i + 1, row)], r0 = at[std::make_pair(col + i, row - 1)];
      for(auto h : CGAL::halfedges_around_target(halfedge(p1, m), m))
        if(!is_border(h, m) && target(next(next(h, m), m), m) == r0 && CGAL::Qzip::can_collapse_quad(h, m))
        { CGAL::Qzip::quad_collapse(h, m); break; }
    }
  }
  CGAL::Qzip::preprocess_valences(m);
}

template <typename Mesh>
Reverse_counters reverse_qzips_on_file(const std::string& path, std::size_t count, unsigned seed)
{
  Mesh m;
  assert(read_mesh(path, m));
  CGAL::Qzip::preprocess_valences(m);
  return random_reverse_qzips(m, count, seed);
}

template <typename Mesh>
Reverse_counters reverse_qzips_on_grids(std::size_t count, unsigned seed)
{
  Reverse_counters c;
  CGAL::Random rng(seed);
  for(int g = 0; g < 4; ++g)
  {
    Mesh m;
    plant_random_chains(m, 24, 5, rng);
    c.add(random_reverse_qzips(m, count, seed + unsigned(g)));
  }
  return c;
}

/// every vertex of `m` by its position
template <typename Mesh>
std::map<Point, typename boost::graph_traits<Mesh>::vertex_descriptor> vertices_by_position(const Mesh& m)
{
  std::map<Point, typename boost::graph_traits<Mesh>::vertex_descriptor> at;
  for(auto v : vertices(m)) at[get(CGAL::vertex_point, m, v)] = v;
  return at;
}

/// the pairs (interior singularity, border vertex with defect +1) at most `max_length` edges apart, by
/// position: an undo may give re-created vertices new descriptors (Polyhedron_3). With `defect` -1, the
/// pairs (interior singularity, border vertex with defect -1) joined by a path along the border
/// (`path_along_border()`, at most 12 border edges; no path through interior vertices reaches them).
template <typename Mesh>
std::vector<std::pair<Point, Point> > interior_to_border_defect_pairs(const Mesh& m, std::size_t max_length, int defect = 1)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> sources, targets;
  for(vertex_descriptor v : vertices(m))
  {
    if(on_border(v, m)) { if(CGAL::Qzip::vertex_defect(v, m) == defect) targets.push_back(v); }
    else if(valence(v, m) == 3 || valence(v, m) == 5) sources.push_back(v);
  }
  std::vector<std::pair<Point, Point> > pairs;
  for(vertex_descriptor t : targets)
    for(vertex_descriptor s : sources)
    {
      const auto path = defect == 1 ? CGAL::Qzip::shortest_surgery_path(m, s, t) : path_along_border(m, s, 12, true, 8, t);
      const auto other = defect == 1 ? path : path_along_border(m, s, 12, false, 8, t);
      if((path.size() >= 2 && path.size() <= max_length + 1) || (other.size() >= 2 && other.size() <= max_length + 1))
        pairs.emplace_back(get(CGAL::vertex_point, m, s), get(CGAL::vertex_point, m, t));
    }
  return pairs;
}

/// the reverse Q-zip on planted grids and real meshes, Surface_mesh and Polyhedron_3; `per_mesh` bounds
/// the number of Q-zips per mesh.
inline void test_reverse_qzip(std::size_t per_mesh)
{
  Reverse_counters grids_sm = reverse_qzips_on_grids<Surface_mesh>(per_mesh, 21);
  Reverse_counters grids_ph = reverse_qzips_on_grids<Polyhedron>(per_mesh, 21);
  grids_sm.print("reverse Q-zips on planted grids, Surface_mesh");
  grids_ph.print("reverse Q-zips on planted grids, Polyhedron_3");

  Reverse_counters real_sm, real_ph;
  for(const std::string f : { "data/polylap_amo_quad.off", "data/pmp_fandisk_quads.off", "data/polylap_suzanne_half.obj",
                              "data/quadriflow_gargoyle.obj", "data/trimesh_target.obj", "data/noisy_sphere_triquad.obj" })
  {
    real_sm.add(reverse_qzips_on_file<Surface_mesh>(f, per_mesh, 31));
    real_ph.add(reverse_qzips_on_file<Polyhedron>(f, per_mesh / 2, 32));
  }
  const std::string dir = shared_corpus_dir("reverse Q-zips on the shared corpus");
  if(!dir.empty())
    for(const std::string f : { "blub_quadrangulated.obj", "spot_quadrangulated.obj", "libigl_horse_quad.obj",
                                "quadwild_joint.obj", "polylap_loki.obj", "beast_quaddominant.obj" })
      real_sm.add(reverse_qzips_on_file<Surface_mesh>(dir + "/" + f, per_mesh / 2, 33));
  real_sm.print("reverse Q-zips on real meshes, Surface_mesh");
  real_ph.print("reverse Q-zips on real meshes, Polyhedron_3");
  for(const Reverse_counters* c : { &grids_sm, &grids_ph, &real_sm, &real_ph })
    assert(c->forward_done > 0 && c->reversed > 0);
  assert(grids_sm.redone > 0 && real_sm.redone > 0);
  // clean-ups undone first and merged path vertices re-created, on both mesh types
  assert(real_sm.with_prelude > 0 && real_ph.with_prelude > 0 && real_sm.with_created > 0 && real_ph.with_created > 0);
}

} // namespace qzip_test

#endif // QZIP_REVERSE_QZIP_TESTS_H
