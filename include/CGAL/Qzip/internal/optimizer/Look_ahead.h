// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_OPTIMIZER_LOOK_AHEAD_H
#define CGAL_QZIP_INTERNAL_OPTIMIZER_LOOK_AHEAD_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/quad_quality.h>
#include <CGAL/Qzip/internal/optimizer/regions.h>
#include <CGAL/Qzip/surgery_plan.h>
#include <CGAL/Qzip/Scoring/Qzip_candidate.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// The look-ahead of the end game. A v3 and a v5 a few edges apart do not cancel by a Q-zip of the two:
// it moves both, as a pair, and no landing is on a third singularity. They cancel when one of them, `a`,
// lands on the other one, `b`: a Q-zip of `a` with a partner `c` beyond `b`, along a path through `b`,
// moves `a` one edge towards `b`, onto it when they are neighbours (and a path passing a singularity may
// cancel it as well). `cancel(a)` searches, depth first, for a short chain of such Q-zips (tried first,
// the shortest first; then Q-zips of the pair `a`, `b` itself) that ends with a cancellation: each step
// must bring `a` closer to its closest singularity of the opposite sign. The first chain found that
// passes the quality guard of the batches, after smoothing (and untangling, see passes_quality_guard()),
// is kept; every other one is undone exactly. The guard compares the quads the chain created or moved with
// those it removed or moved (not the whole region of the search: a bad quad far from the chain would
// lower the reference), so a kept chain leaves no more inverted quads and no quad below the quality floor
// unless one it replaced was already as bad.
// Works on the mesh as it is (its own searches, no scoring context).
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap,
          typename FaceIsConstrainedMap, typename Smoother>
class Look_ahead
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef boost::hash<vertex_descriptor> Vertex_hash;
  typedef Surgery_plan<PolygonMesh> Plan;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<unsigned int> >::type Mark_map;

public:
  struct Settings
  {
    int max_distance = 6;      // `a` and `b` at most this many edges apart
    int max_depth = 6;         // Q-zips in a chain
    std::size_t width = 8;     // Q-zips executed per step of the search
    std::size_t budget = 400;  // Q-zips executed per search, at most
    std::size_t judgements = 32; // chains smoothed and judged by the quality guard per search, at most
    std::size_t partners = 5;  // singularities beyond `b` tried as partner
    int partner_distance = 16; // at most this many edges beyond `b`
    int smoothing_iterations = 5;
    // a chain whose smoothed scar fails the guard is untangled with at most this many sweeps before it is
    // judged again (see passes_quality_guard()); independent of the batches' `number_of_untangling_sweeps`,
    // so that a run without untangling in its batches still untangles its chains
    int untangling_sweeps = 20;
    double quality_floor = 0.1;
    bool smooth = true;
  };

  // what a kept chain did
  struct Chain
  {
    std::vector<Plan> plans;             // its Q-zips, in the order of execution
    std::vector<int> predicted_cancellations; // for each, the cancellations its landings predicted
    std::vector<vertex_descriptor> scar; // the vertices smoothed around it (alive)
    long face_change = 0;                // its splits minus its collapses
  };

  Look_ahead(PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm,
             Smoother& smoother, const Settings& settings)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm), smoother(smoother), settings(settings),
      reached_in(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm))
  {
    for(vertex_descriptor v : vertices(pm)) put(reached_in, v, 0u);
  }

  // the number of Q-zips executed so far (kept or undone)
  std::size_t number_of_executions() const { return executions; }
  std::size_t number_of_undos() const { return undos; }
  // whether `v` was within three edges of the path of a Q-zip executed so far, before it (a vertex
  // that may have been removed, or re-created by an undo with a new descriptor)
  bool was_near_a_path(vertex_descriptor v) const { return near_paths.count(v) != 0; }

  // whether `v` can start or end a Q-zip: valence 3 or 5, no border or constrained edge, no protected face
  bool is_endpoint(vertex_descriptor v) const
  {
    const int d = valence_if_passable(v);
    return d == 3 || d == 5;
  }

  // Tries to cancel the singularity `a` (see `is_endpoint()`) with one of the opposite sign within
  // `max_distance` edges. `keeps_face_count(change)` tells whether the chain may change the number of
  // faces by `change`. Returns whether a chain was kept (described in `chain`); otherwise the mesh
  // is as before (up to descriptors of re-created elements).
  template <typename FaceBudget>
  bool cancel(vertex_descriptor a, const FaceBudget& keeps_face_count, Chain& chain)
  {
    chain = Chain();
    const int d = distance_to_opposite(a, (std::min)(settings.max_distance, settings.max_depth));
    if(d < 0) return false;
    Qzip_history<PolygonMesh, VertexPointMap> history(pm, vpm);
    Path_state state;
    {
      region_level.clear();
      std::vector<int> level;
      const std::vector<vertex_descriptor> region =
        vertex_ball(std::vector<vertex_descriptor>(1, a), region_radius() + 1, pm, level,
                    [this](vertex_descriptor v) { return region_level.emplace(v, 0).second; });
      for(std::size_t i = 0; i < region.size(); ++i) region_level[region[i]] = level[i];
    }
    near_chain.clear();
    quads_before.clear();
    next_to_chain.clear();
    refused.clear();
    budget_end = executions + settings.budget;
    judgement_end = judgements + settings.judgements;
    const bool kept = search(a, d, settings.max_depth, history, keeps_face_count, state, chain);
    if(kept)
    {
      std::reverse(chain.plans.begin(), chain.plans.end());
      std::reverse(chain.predicted_cancellations.begin(), chain.predicted_cancellations.end());
    }
    return kept;
  }

private:
  // the state of the chain being tried: the touched vertices of its Q-zips known to be alive, and its
  // splits minus its collapses
  struct Path_state
  {
    std::vector<vertex_descriptor> touched;
    long face_change = 0;
  };

  // a quad by the positions of its corners, in the order of its halfedges from the smallest one: the same
  // key before and after a chain if and only if the chain left the quad as it was (its scaled Jacobian
  // depends only on these positions)
  typedef std::array<Point, 4> Quad_key;
  struct Quad_key_hash
  {
    std::size_t operator()(const Quad_key& k) const
    {
      std::size_t h = 0;
      for(const Point& p : k)
      {
        boost::hash_combine(h, CGAL::to_double(p.x()));
        boost::hash_combine(h, CGAL::to_double(p.y()));
        boost::hash_combine(h, CGAL::to_double(p.z()));
      }
      return h;
    }
  };
  // a quad as it was before the search (see near_chain_grows()), by its key, and its scaled Jacobian
  struct Quad_before
  {
    Quad_key key;
    double quality;
  };
  // the quads before the search that a check compares with those after it, by key: their scaled Jacobian,
  // how many have the key (more than one only on a degenerate mesh) and how many of them the check found
  struct Key_count
  {
    double quality;
    std::size_t count = 0;
    std::size_t found = 0;
  };

  struct Candidate
  {
    Plan plan;
    int predicted_cancellations;
    bool through_b; // not a Q-zip of the pair a, b itself
  };

  // the valence of v if v is passable (no border or constrained edge, no protected face around it), else -1
  int valence_if_passable(vertex_descriptor v) const
  {
    int n = 0;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) return -1;
      if(get(fcm, face(h, pm))) return -1;
      ++n;
    }
    return n;
  }

  // breadth-first search from s through passable vertices, up to `radius` edges, avoiding `avoid`:
  // the vertices reached in order, each with its distance to s and the one it was reached from
  struct Search
  {
    std::vector<vertex_descriptor> order;
    std::vector<int> level;
    std::vector<std::size_t> from; // index in `order`

    // the path from s to order[i]
    std::vector<vertex_descriptor> path_to(std::size_t i) const
    {
      std::vector<vertex_descriptor> path(1, order[i]);
      for(; i != 0; i = from[i]) path.push_back(order[from[i]]);
      std::reverse(path.begin(), path.end());
      return path;
    }
  };

  // starts a walk (search_from(), ball(), relocate()): no vertex is reached yet
  void new_round() const
  {
    if(++search_round != 0) return;
    for(vertex_descriptor v : vertices(pm)) put(reached_in, v, 0u); // the marks wrapped around
    search_round = 1;
  }

  // marks v as reached by the current walk; whether it was not before
  bool reach(vertex_descriptor v) const
  {
    if(get(reached_in, v) == search_round) return false;
    put(reached_in, v, search_round);
    return true;
  }

  void search_from(vertex_descriptor s, int radius,
                   const std::unordered_set<vertex_descriptor, Vertex_hash>& avoid, Search& out) const
  {
    new_round();
    out.order.assign(1, s);
    out.level.assign(1, 0);
    out.from.assign(1, 0);
    reach(s);
    for(std::size_t i = 0; i < out.order.size(); ++i)
    {
      const vertex_descriptor v = out.order[i];
      if(out.level[i] >= radius || (i > 0 && valence_if_passable(v) < 0)) continue;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        const vertex_descriptor w = source(h, pm);
        if(get(reached_in, w) == search_round || avoid.count(w) != 0) continue;
        reach(w);
        out.order.push_back(w);
        out.level.push_back(out.level[i] + 1);
        out.from.push_back(i);
      }
    }
  }

  // the graph distance from a to the closest endpoint singularity of the opposite sign, if at most
  // `radius`, else -1
  int distance_to_opposite(vertex_descriptor a, int radius) const
  {
    const int da = valence_if_passable(a) - 4;
    Search s;
    search_from(a, radius, {}, s);
    for(std::size_t i = 1; i < s.order.size(); ++i)
    {
      const int dv = valence_if_passable(s.order[i]);
      if((dv == 3 || dv == 5) && (dv - 4) * da < 0) return s.level[i];
    }
    return -1;
  }

  // the Q-zips of `a` towards its closest singularities of the opposite sign `b`: with `b` along the
  // shortest path, and with the closest singularities beyond `b` along that path continued through `b`
  template <typename NP>
  std::vector<Candidate> candidates(vertex_descriptor a, const NP& plan_np) const
  {
    const int da = valence_if_passable(a) - 4;
    Search sa;
    search_from(a, settings.max_distance, {}, sa);
    std::vector<std::vector<vertex_descriptor> > sketches; // and whether each goes through b
    std::vector<bool> through_b;
    std::size_t opposites = 0;
    for(std::size_t i = 1; i < sa.order.size(); ++i)
    {
      const vertex_descriptor b = sa.order[i];
      const int db = valence_if_passable(b);
      if(!(db == 3 || db == 5) || (db - 4) * da >= 0) continue;
      const std::vector<vertex_descriptor> to_b = sa.path_to(i);
      sketches.push_back(to_b);
      through_b.push_back(false);
      std::unordered_set<vertex_descriptor, Vertex_hash> avoid(to_b.begin(), to_b.end() - 1);
      Search sb;
      search_from(b, settings.partner_distance, avoid, sb);
      std::size_t partners = 0;
      for(std::size_t j = 1; j < sb.order.size(); ++j)
      {
        if(!is_endpoint(sb.order[j])) continue;
        std::vector<vertex_descriptor> sketch = to_b;
        const std::vector<vertex_descriptor> beyond = sb.path_to(j);
        sketch.insert(sketch.end(), beyond.begin() + 1, beyond.end());
        sketches.push_back(std::move(sketch));
        through_b.push_back(true);
        if(++partners == settings.partners) break;
      }
      if(++opposites == 2) break;
    }

    std::vector<Candidate> out;
    for(std::size_t i = 0; i < sketches.size(); ++i)
      for(int m = 0; m < 4; ++m)
      {
        Plan plan = plan_qzip(pm, sketches[i], Strip_operation(m), plan_np);
        if(!plan.is_realizable()) continue;
        vertex_descriptor ls, lt;
        predict_landings(plan, pm, ls, lt);
        int predicted = 0;
        for(vertex_descriptor l : { ls, lt })
        {
          if(l == GT::null_vertex() || l == plan.source || l == plan.target) continue;
          const int dl = valence_if_passable(l);
          const int moved = (l == ls ? plan.source_valence : plan.target_valence) - 4;
          if((dl == 3 || dl == 5) && (dl - 4) * moved < 0) predicted += 2;
        }
        out.push_back(Candidate{ std::move(plan), predicted, through_b[i] });
      }
    std::stable_sort(out.begin(), out.end(), [](const Candidate& x, const Candidate& y)
    {
      if(x.predicted_cancellations != y.predicted_cancellations)
        return x.predicted_cancellations > y.predicted_cancellations;
      if(x.through_b != y.through_b) return x.through_b;
      return x.plan.path.size() < y.plan.path.size(); // the shortest Q-zips distort the least
    });
    return out;
  }

  // the vertices within `radius` edges of `seeds`
  std::vector<vertex_descriptor> ball(const std::vector<vertex_descriptor>& seeds, int radius) const
  {
    new_round();
    std::vector<int> level;
    return vertex_ball(seeds, radius, pm, level, [this](vertex_descriptor v) { return reach(v); });
  }

  Quad_key quad_key(halfedge_descriptor h) const
  {
    Quad_key k;
    for(int i = 0; i < 4; ++i, h = next(h, pm)) k[i] = get(vpm, target(h, pm));
    std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
    return k;
  }

  // whether every corner of the quad of h is unchanged (see is_unchanged()): the quad is then as it was
  // before the search. A vertex that an undo re-created has a new descriptor, or that of a removed vertex
  // (which one depends on the mesh type and, on Polyhedron_3, on the heap), but never that of a vertex of
  // the region no Q-zip came near: its quads are not intact whatever descriptor it got (counting them as
  // intact recorded a quad twice in quads_before on one mesh type and once on the other)
  bool is_intact(halfedge_descriptor h) const
  {
    for(int i = 0; i < 4; ++i, h = next(h, pm)) if(!is_unchanged(target(h, pm))) return false;
    return true;
  }

  // calls f(h) once for each intact quad (see is_intact()) around the vertices of `vs`, h a halfedge of it
  template <typename F>
  void for_each_intact_quad(const std::vector<vertex_descriptor>& vs, const F& f) const
  {
    std::unordered_set<face_descriptor, boost::hash<face_descriptor> > seen;
    for(vertex_descriptor v : vs)
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
        if(!is_border(h, pm) && is_quad(h, pm) && is_intact(h) && seen.insert(face(h, pm)).second) f(h);
  }

  double quality(halfedge_descriptor h) const
  {
    return quad_scaled_jacobian(face(h, pm), pm, CGAL::parameters::vertex_point_map(vpm));
  }

  // Before a Q-zip of the search, `near_path` (the vertices within three edges of its path, alive) joins
  // near_chain. The quads around the vertices that join it, intact until now, are recorded as they are
  // (quads_before): any quad the search changes is recorded before it changes. Their neighbours outside
  // near_chain whose distance to `a` is less than region_radius() are where the walk of a check
  // starts from (see passes_quality_guard()).
  void near_chain_grows(const std::vector<vertex_descriptor>& near_path)
  {
    std::vector<vertex_descriptor> joining;
    for(vertex_descriptor v : near_path) if(near_chain.count(v) == 0) joining.push_back(v);
    for_each_intact_quad(joining, [this](halfedge_descriptor h) { quads_before.push_back(Quad_before{ quad_key(h), quality(h) }); });
    near_chain.insert(joining.begin(), joining.end());
    for(vertex_descriptor v : joining)
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        const vertex_descriptor w = source(h, pm);
        if(near_chain.count(w) != 0) continue;
        const auto it = region_level.find(w);
        if(it != region_level.end() && it->second < region_radius()) next_to_chain.push_back(w);
      }
  }

  // whether v is a vertex of the region that no Q-zip of the search came near (alive, unchanged)
  bool is_unchanged(vertex_descriptor v) const
  {
    return near_chain.count(v) == 0 && region_level.count(v) != 0;
  }

  // Compares the quads of the region after the chain with those before the search, by their keys: the
  // quads that are new or moved must have no more inverted quads among them than the quads that are gone
  // (removed or moved), and none worse than both the worst one gone and the quality floor: the guard of
  // the batches (Batch_optimizer::execute()) applied to what the chain changed. Only the quads around the
  // vertices the check smoothed (`scar`, all the changed vertices among them) can differ, and only those
  // recorded (`before`: quads_before and the intact quads around the scar before it was smoothed) can be
  // gone; any other quad is the same before and after.
  bool changed_quads_pass(const std::vector<vertex_descriptor>& scar,
                          std::unordered_map<Quad_key, Key_count, Quad_key_hash>& before) const
  {
    std::size_t inverted_new = 0, inverted_gone = 0;
    double worst_new = 1, worst_gone = 1;
    for(face_descriptor f : quads_around(scar, pm))
    {
      const auto it = before.find(quad_key(halfedge(f, pm)));
      if(it != before.end() && it->second.found < it->second.count)
      {
        ++it->second.found;
        continue;
      }
      const double j = quad_scaled_jacobian(f, pm, CGAL::parameters::vertex_point_map(vpm));
      if(j <= 0) ++inverted_new;
      worst_new = (std::min)(worst_new, j);
    }
    for(auto& entry : before)
    {
      Key_count& q = entry.second;
      if(q.found < q.count)
      {
        if(q.quality <= 0) inverted_gone += q.count - q.found;
        worst_gone = (std::min)(worst_gone, q.quality);
      }
      q.found = 0;
    }
    return inverted_new <= inverted_gone && worst_new >= (std::min)(worst_gone, settings.quality_floor);
  }

  // smooths the scar of the chain and checks it as a batch checks a surgery (see changed_quads_pass());
  // if the smoothed scar fails, untangles it (see Quad_smoother::untangle()) and checks again; restores
  // the positions if not.
  // The vertices of the region that no Q-zip of the search came near are alive and unchanged; the
  // others (removed, re-created by an undo, created, or moved) are found from them: the scar is every
  // vertex reached from them without passing one of them, and one edge around. Only live vertices are
  // walked around (the touched vertices recorded during the search may have been removed by a later Q-zip
  // and its undo; on Polyhedron_3 their handles dangle).
  bool passes_quality_guard(const Path_state& state, Chain& chain)
  {
    ++judgements;
    std::unordered_set<vertex_descriptor, Vertex_hash> reached;
    std::vector<vertex_descriptor> changed;
    auto reach_changed_neighbours = [&](vertex_descriptor v)
    {
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        const vertex_descriptor w = source(h, pm);
        if(!is_unchanged(w) && reached.insert(w).second) changed.push_back(w);
      }
    };
    // the unchanged vertices next to a changed one were next to near_chain when it grew (their rings
    // are as before), and the region's outer shell is never changed
    for(vertex_descriptor v : next_to_chain) if(near_chain.count(v) == 0) reach_changed_neighbours(v);
    for(std::size_t i = 0; i < changed.size(); ++i) reach_changed_neighbours(changed[i]);
    // another chain of the search may have left the same mesh (the same Q-zips in another order, or
    // ending the same way after Q-zips that were undone): it was refused, and would be again
    std::size_t signature = changed.size();
    for(vertex_descriptor v : changed) signature += ring_hash(v) * 0x9E3779B97F4A7C15ull;
    if(!refused.insert(signature).second) return false;
    std::vector<vertex_descriptor> scar = ball(changed, 1);
    std::sort(scar.begin(), scar.end(), [this](vertex_descriptor x, vertex_descriptor y)
    {
      const Point& p = get(vpm, x);
      const Point& q = get(vpm, y);
      if(p.x() != q.x()) return p.x() < q.x();
      if(p.y() != q.y()) return p.y() < q.y();
      return p.z() < q.z();
    });
    std::vector<Point> saved;
    saved.reserve(scar.size());
    for(vertex_descriptor v : scar) saved.push_back(get(vpm, v));
    std::unordered_map<Quad_key, Key_count, Quad_key_hash> before;
    auto count_before = [&before](const Quad_key& key, double quality)
    {
      Key_count& q = before[key];
      q.quality = quality;
      ++q.count;
    };
    for(const Quad_before& q : quads_before) count_before(q.key, q.quality);
    std::vector<vertex_descriptor> unchanged_in_scar;
    for(vertex_descriptor v : scar) if(is_unchanged(v)) unchanged_in_scar.push_back(v);
    for_each_intact_quad(unchanged_in_scar, [&](halfedge_descriptor h) { count_before(quad_key(h), quality(h)); });
    auto passes = [&]() { return changed_quads_pass(scar, before); };
    if(settings.smooth)
    {
      smoother.snap_to_surface(changed);
      smoother.smooth(scar, 3 * settings.smoothing_iterations);
    }
    if(passes() || (settings.smooth && smoother.untangle(scar, settings.untangling_sweeps, settings.quality_floor) > 0 && passes()))
    {
      chain.scar = std::move(scar);
      chain.face_change = state.face_change;
      return true;
    }
    for(std::size_t i = 0; i < scar.size(); ++i) put(vpm, scar[i], saved[i]);
    return false;
  }

  // a hash of the position of v and of the positions of its neighbours (in any order)
  std::size_t ring_hash(vertex_descriptor v) const
  {
    auto point_hash = [this](vertex_descriptor u)
    {
      const Point& p = get(vpm, u);
      std::size_t h = 0;
      boost::hash_combine(h, CGAL::to_double(p.x()));
      boost::hash_combine(h, CGAL::to_double(p.y()));
      boost::hash_combine(h, CGAL::to_double(p.z()));
      return h;
    };
    std::size_t around = 0;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      around += point_hash(source(h, pm)) * 0x9E3779B97F4A7C15ull;
    std::size_t out = point_hash(v);
    boost::hash_combine(out, around);
    return out;
  }

  // the region of a chain: its Q-zips run within 2 max_distance + partner_distance edges of `a` (`a` stays
  // within max_distance of the singularity `b` it moves to, partners are at most partner_distance beyond
  // `b`) and change vertices within three edges of their paths
  int region_radius() const { return 2 * settings.max_distance + settings.partner_distance + 4; }

  // the vertex at `p`, searched breadth first (at most 2 max_distance + 8 edges) from the first vertex of
  // `around` that no Q-zip executed so far came near (never removed, so its descriptor is valid);
  // `null_vertex()` if not found
  vertex_descriptor relocate(const Point& p, const std::vector<vertex_descriptor>& around) const
  {
    for(vertex_descriptor v : around)
    {
      if(near_paths.count(v) != 0) continue;
      new_round();
      std::vector<int> level;
      vertex_descriptor found = GT::null_vertex();
      vertex_ball(std::vector<vertex_descriptor>(1, v), 2 * settings.max_distance + 8, pm, level,
                  [&](vertex_descriptor w)
      {
        if(found != GT::null_vertex()) return false; // found: the search stops growing
        if(!reach(w)) return false;
        if(get(vpm, w) == p) found = w;
        return true;
      });
      return found;
    }
    return GT::null_vertex();
  }

  // one step of the depth-first search: a is `d` edges from its closest singularity of the opposite sign.
  // The candidates are planned again after each Q-zip executed here (an undo or a rollback may give new
  // descriptors to the vertices it re-creates, `a` among them: it is found again by its position).
  template <typename FaceBudget>
  bool search(vertex_descriptor a, int d, int depth, Qzip_history<PolygonMesh, VertexPointMap>& history,
              const FaceBudget& keeps_face_count, Path_state& state, Chain& chain)
  {
    // planned without simulating the execution, as the optimizer's candidates (see Batch_optimizer::run_batch())
    const auto plan_np = Qzip::parameters::simulate_chain(false, Qzip::parameters::face_is_constrained_map(fcm,
                           CGAL::parameters::edge_is_constrained_map(ecm).vertex_point_map(vpm)));
    const Point pa = get(vpm, a);
    const std::vector<vertex_descriptor> around = ball(std::vector<vertex_descriptor>(1, a), settings.max_distance + 4);
    std::vector<Candidate> cands = candidates(a, plan_np);
    bool stale = false;
    std::size_t tried = 0;
    for(std::size_t i = 0; tried < settings.width && executions < budget_end && judgements < judgement_end; ++i)
    {
      if(stale)
      {
        a = relocate(pa, around);
        if(a == GT::null_vertex()) return false;
        cands = candidates(a, plan_np);
        stale = false;
      }
      if(i >= cands.size()) break;
      const Candidate& c = cands[i];
      const long change = long(c.plan.number_of_splits()) - long(c.plan.number_of_collapses());
      if(!keeps_face_count(state.face_change + change)) continue;
      // a Q-zip only removes vertices within three edges of its path: the touched vertices of the
      // earlier steps farther away stay alive
      const std::vector<vertex_descriptor> near_path = ball(c.plan.path, 3);
      const std::unordered_set<vertex_descriptor, Vertex_hash> endangered(near_path.begin(), near_path.end());
      near_paths.insert(near_path.begin(), near_path.end());
      near_chain_grows(near_path);
      const Path_state saved_state = state;
      std::vector<vertex_descriptor> alive;
      for(vertex_descriptor v : state.touched) if(endangered.count(v) == 0) alive.push_back(v);

      Qzip_result<PolygonMesh> r = execute_qzip(pm, c.plan, history, plan_np);
      ++executions;
      stale = true;
      if(!r.is_done()) { state.touched = alive; continue; }
      ++tried;
      state.touched = alive;
      state.touched.insert(state.touched.end(), r.touched_vertices.begin(), r.touched_vertices.end());
      state.face_change += long(r.number_of_splits) - long(r.number_of_collapses);

      bool found = false;
      if(r.reverse_status == Reverse_qzip_status::SINGULARITIES_CANCELLED) // within the face budget as executed
        found = keeps_face_count(state.face_change) && passes_quality_guard(state, chain);
      else if(depth > 1 && r.moved_source != GT::null_vertex())
      {
        const int d2 = distance_to_opposite(r.moved_source, (std::min)(d, depth) - 1);
        found = d2 >= 0 && search(r.moved_source, d2, depth - 1, history, keeps_face_count, state, chain);
      }
      if(found)
      {
        chain.plans.push_back(c.plan);
        chain.predicted_cancellations.push_back(c.predicted_cancellations);
        return true;
      }
      undo_qzip(history);
      ++undos;
      state = saved_state;
      state.touched = alive;
    }
    return false;
  }

  PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;
  Smoother& smoother;
  Settings settings;
  // the vertices reached by the current walk (see new_round()) have the mark search_round (vertices created
  // since the construction have 0 or the mark of an older walk)
  Mark_map reached_in;
  mutable unsigned int search_round = 0;
  std::size_t executions = 0, undos = 0, budget_end = 0, judgements = 0, judgement_end = 0;
  std::unordered_set<vertex_descriptor, Vertex_hash> near_paths;
  std::unordered_set<vertex_descriptor, Vertex_hash> near_chain; // the part of near_paths of the current search
  // the distance to `a` of the vertices of the region of the current search (before it), at most region_radius() + 1
  // (one more than the chains can change: the corners of the quads around the vertices they change are in it)
  std::unordered_map<vertex_descriptor, int, Vertex_hash> region_level;
  // vertices of the region closer than region_radius() to `a` that were next to near_chain when it grew
  std::vector<vertex_descriptor> next_to_chain;
  // the chains of the current search refused by the quality guard: a hash of the vertices they changed
  // (positions and neighbours' positions, see passes_quality_guard())
  std::unordered_set<std::size_t> refused;
  // the quads around near_chain before the search changed them (see near_chain_grows())
  std::vector<Quad_before> quads_before;
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_OPTIMIZER_LOOK_AHEAD_H
