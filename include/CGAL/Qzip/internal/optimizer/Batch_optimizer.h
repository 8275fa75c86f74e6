// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_OPTIMIZER_BATCH_OPTIMIZER_H
#define CGAL_QZIP_INTERNAL_OPTIMIZER_BATCH_OPTIMIZER_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/quad_quality.h>
#include <CGAL/Qzip/internal/optimizer/regions.h>
#include <CGAL/Qzip/smoothing.h>
#include <CGAL/Qzip/stop_predicates.h>
#include <CGAL/Qzip/Scoring/Qzip_candidate.h>
#include <CGAL/Qzip/Scoring/Scoring_context.h>
#include <CGAL/Qzip/internal/vertex_defect.h>
#include <CGAL/Qzip/internal/optimizer/Erased_policies.h>
#include <CGAL/Qzip/internal/optimizer/Look_ahead.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>

#include <boost/container/small_vector.hpp>
#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

struct Optimizer_settings
{
  bool smooth = true;
  int smoothing_iterations = 5;
  // a surgery whose smoothed scar fails the quality checks is untangled with at most this many sweeps
  // (see Quad_smoother::untangle()) and checked again before it is undone (0: undone at once)
  int untangling_sweeps = 20;
  double face_count_tolerance = 0.1;
  // the number of faces the face budget is measured from (Optimizer_statistics::initial_number_of_faces):
  // that of the mesh given to optimize_singularities(), before its triangle pairing (0: the number at the
  // start of the batches)
  std::size_t input_number_of_faces = 0;
  unsigned int seed = 0;
  std::size_t neighbors_per_type = 3;
  // no surgery nor smoothing move leaves a quad worse than both this scaled Jacobian and the worst quad
  // around it before (the named parameter `quality_floor`)
  double quality_floor = 0.1;
  bool end_game = true;
  std::size_t max_end_game_rounds = 10;
  // a source whose best candidate is skipped (its region already operated on in the batch, or the face
  // budget spent) tries its next best ones, up to this many. Until session 24: 3. With 12, the rocker arm
  // ends 0.9 to 1.6 singularities lower on average (seeds 0-63) and reaches 10 singularities sooner, and the
  // corpus 6 to 13 lower in sum (seeds 0-2), in about the same time (RESULTS.md, session 24)
  std::size_t alternatives = 12;
  // a chosen plan whose path meets only regions of surgeries of the batch that were undone is planned
  // again there (see Batch_optimizer::replan()) instead of skipped
  bool replan_after_undos = true;
  // a kept Q-zip is followed by more Q-zips of the same pair in the same batch while each end is more than
  // this many edges from the singularity of the opposite sign it is pulled towards (0: never, see follow())
  std::size_t follow_min_distance = 3;
  // a batch executes the best half of the candidates it chose (the paper's scheme), or all of them, best
  // first, when the singularities are sparse: at least this many edges, on average, from their partners
  // (Optimizer_statistics::pairing_distance over the number of singularities). Refining a mesh doubles its
  // distances: the corpus meshes stay below 20 in most batches (the rocker arm's tail, 14 singularities at 352
  // edges, passes 25), the gargoyle's Catmull-Clark refinements start at 10 (CC2), 20 (CC3) and 40 (CC4), and
  // pass 25 as their closest pairs cancel.
  double sparse_pairing_distance = 25;
  // in a sparse batch, a source that is the target of the candidate an earlier source chose is not scored
  // (see Batch_optimizer::run_batch())
  bool skip_chosen_targets = true;
  bool look_ahead = true;       // chains of Q-zips that bring a singularity onto one of the opposite sign
  int look_ahead_distance = 14; // the two at most this many edges apart
  int look_ahead_depth = 14;    // Q-zips in a chain
  // no batch, end-game round nor look-ahead chain starts once run() has taken this many seconds (the time
  // limit of optimize_singularities() less what it spent before the batches)
  double time_limit = (std::numeric_limits<double>::infinity)();
};

// The multiple-choice batches of the paper's Sec. 4.1 (see optimize_singularities()).
// The scoring functor, the stop predicate and the visitor are held behind fixed types (see Erased_policies.h).
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap,
          typename GeomTraits>
class Batch_optimizer
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef Scoring_context<PolygonMesh, VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap> Context;
  typedef Erased_scoring<PolygonMesh, Context> Scoring;
  typedef Erased_optimizer_visitor<PolygonMesh> Visitor;
  typedef Quad_smoother<PolygonMesh, VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap, GeomTraits> Smoother;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<unsigned int> >::type Stamp_map;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type Id_map;

  // a surgery of the end game, by the positions of its ends and its motion
  typedef std::array<double, 7> Surgery_key;

  struct Scored
  {
    Surgery_plan<PolygonMesh> plan;
    double score;
    Point source_point;
    int predicted_cancellations;
    Surgery_key key{}; // in the end game
    std::vector<Scored> alternatives; // in a batch: the next best candidates of the source, tried if this one is skipped
    std::pair<std::size_t, std::size_t> partners{ no_partner, no_partner }; // see watch_partners()
    std::vector<Point> sketch_points{}; // in a batch: where the vertices of plan.sketch were (see replan())
  };
  static constexpr std::size_t no_partner = std::size_t(-1);
  enum Outcome { KEPT, UNDONE, FAILED, SKIPPED };

  PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;
  const Scoring scoring;
  const Erased_stop_predicate stop;
  Visitor visitor;
  Optimizer_settings settings;

  Context ctx;
  Smoother& smoother;
  CGAL::Random rng;
  Optimizer_statistics stats;
  CGAL::Real_timer timer;

  Stamp_map search_stamp, op_stamp, scar_stamp, outer_stamp;
  Stamp_map kept_stamp; // batch_epoch: in the region of a surgery kept in this batch (see replan())
  unsigned int search_epoch = 0, batch_epoch = 0, outer_epoch = 0;
  // op_stamp: the number of the surgery whose region first covered the vertex; the surgeries of this
  // batch are numbered from first_in_batch, those of the current pair (see follow()) from first_of_pair
  unsigned int surgery_serial = 0, first_in_batch = 1, first_of_pair = 1;
  // every mark of the batch (see restore_marks())
  std::vector<std::pair<vertex_descriptor, unsigned int> > marks_in_batch;
  // the partners of the chosen candidates of the batch (see watch_partners()): partner_id is
  // partner_base + 1 + their index, and a partner is lost once the region of a surgery covers it, unless
  // it was an end of that surgery and the surgery was kept: then it is where the surgery moved it
  Id_map partner_id;
  std::size_t partner_base = 0;
  std::vector<vertex_descriptor> partner_vertices;
  std::vector<unsigned char> partner_lost;
  // partner search on the context's arrays: the queue, and for each of its entries the place in the
  // queue of the vertex it was reached from (written in sequence: no store at a random place per vertex)
  std::vector<unsigned int> search_visit;
  std::vector<int> index_queue, queue_parent;
  unsigned int search_round = 0;
  std::vector<vertex_descriptor> singular;
  std::size_t singular_of_sign[2] = { 0, 0 }; // how many of them are v3-like (0) and v5-like (1)
  std::vector<vertex_descriptor> edited_vertices; // the scars of the surgeries of the batch (see Scoring_context::begin_batch())
  std::size_t best_pairing_distance = 0; // the smallest pairing distance since the count last decreased
  std::set<Surgery_key> rejected; // end-game surgeries executed and undone, not to be tried again
  std::set<Surgery_key> undone_in_batches; // the same in the batches since the count last dropped (see reject())

public:
  // `smoother` (its reference surface: the mesh as the caller was given it; projecting unless smoothing is
  // off) smooths and projects the scars; its quality floor becomes that of `settings`
  // (`scoring` and `stop` are copied, `visitor` is called by reference)
  template <typename ScoringFunctor, typename StopPredicate, typename OptimizerVisitor>
  Batch_optimizer(PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm,
                  Smoother& smoother, const ScoringFunctor& scoring, const StopPredicate& stop,
                  OptimizerVisitor& visitor, const Optimizer_settings& settings)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm), scoring(scoring), stop(stop), visitor(visitor), settings(settings),
      ctx(pm, vpm, ecm, fcm), smoother(smoother), rng(settings.seed),
      search_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      op_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      scar_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      outer_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      kept_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      partner_id(get(CGAL::dynamic_vertex_property_t<std::size_t>(), pm))
  {
    smoother.quality_floor = settings.quality_floor;
    for(vertex_descriptor v : vertices(pm))
    {
      put(search_stamp, v, 0u);
      put(op_stamp, v, 0u);
      put(scar_stamp, v, 0u);
      put(outer_stamp, v, 0u);
      put(kept_stamp, v, 0u);
      put(partner_id, v, std::size_t(0));
    }
  }

  Optimizer_statistics run()
  {
    timer.start();
    take_singular(ctx.begin_batch());
    stats.initial_number_of_singularities = stats.number_of_singularities = singular.size();
    stats.number_of_faces = faces(pm).size();
    stats.initial_number_of_faces = settings.input_number_of_faces != 0 ? settings.input_number_of_faces
                                                                         : stats.number_of_faces;
    stats.pairing_distance = best_pairing_distance = pairing_distance();
    visitor.on_started(stats);
    for(;;)
    {
      while(!out_of_time() && !stop(stats))
        run_batch(false);
      const std::size_t kept = stats.number_of_surgeries;
      if(!settings.end_game || !run_end_game() || out_of_time()) break;
      // The end game cancelled singularities: the batches go on from there if the stop predicate agrees,
      // asked as after a batch that made progress with the surgeries of the end game.
      stats.batches_without_improvement = stats.batches_without_progress = 0;
      stats.candidates_in_last_batch = stats.surgeries_in_last_batch = stats.number_of_surgeries - kept;
      if(stop(stats)) break;
    }
    stats.elapsed_seconds = timer.time();
    visitor.on_finished(stats);
    return stats;
  }

private:
  // ---------------------------------------------------------------------------------------------
  // helpers

  // whether the time limit is reached (see Optimizer_settings::time_limit); recorded in the statistics
  bool out_of_time()
  {
    if(!(timer.time() >= settings.time_limit)) return false;
    stats.reached_time_limit = true;
    return true;
  }

  static bool point_less(const Point& a, const Point& b)
  {
    if(a.x() != b.x()) return a.x() < b.x();
    if(a.y() != b.y()) return a.y() < b.y();
    return a.z() < b.z();
  }

  void sort_by_position(std::vector<vertex_descriptor>& vs) const
  {
    std::vector<std::pair<Point, vertex_descriptor> > keyed;
    keyed.reserve(vs.size());
    for(vertex_descriptor v : vs) keyed.emplace_back(get(vpm, v), v);
    std::sort(keyed.begin(), keyed.end(), [](const std::pair<Point, vertex_descriptor>& a,
                                              const std::pair<Point, vertex_descriptor>& b)
              { return point_less(a.first, b.first); });
    for(std::size_t i = 0; i < vs.size(); ++i) vs[i] = keyed[i].second;
  }

  // v may start a surgery: interior valence 3 or 5, passable (at the start of the batch)
  bool is_endpoint(vertex_descriptor v) const
  {
    const int i = ctx.index(v);
    const int d = ctx.valence_at(i);
    return (d == 3 || d == 5) && ctx.is_passable_at(i);
  }

  // vertices within `radius` edges of `seeds` (seeds first)
  std::vector<vertex_descriptor> ball(const std::vector<vertex_descriptor>& seeds, int radius)
  {
    std::vector<int> level;
    return ball(seeds, radius, level);
  }

  // same, with the distance of each vertex to the seeds
  std::vector<vertex_descriptor> ball(const std::vector<vertex_descriptor>& seeds, int radius, std::vector<int>& level)
  {
    ++search_epoch;
    return vertex_ball(seeds, radius, pm, level, [this](vertex_descriptor v)
    {
      if(get(search_stamp, v) == search_epoch) return false;
      put(search_stamp, v, search_epoch);
      return true;
    });
  }

  // the number of inverted quads incident to `region` and the smallest scaled Jacobian among them
  std::pair<std::size_t, double> quality(const std::vector<vertex_descriptor>& region) const
  {
    return region_quality(region, pm, vpm);
  }

  // whether a singularity of the sign opposite to that of s lies within `radius` edges of s
  bool has_opposite_within(vertex_descriptor s, int radius) const
  {
    const int d = ctx.defect(s);
    for(const auto& j : ctx.nearest_singularities(s))
    {
      if(j.distance > radius) break;
      if(j.defect * d < 0) return true;
    }
    return false;
  }

  // whether the singularities are far apart (see Optimizer_settings::sparse_pairing_distance)
  bool is_sparse() const
  {
    return !(double(stats.pairing_distance) < settings.sparse_pairing_distance * double(singular.size()));
  }

  // see Optimizer_statistics::pairing_distance (on the context, just refreshed)
  std::size_t pairing_distance() const
  {
    std::size_t sum = 0;
    for(vertex_descriptor v : singular)
    {
      const int d = ctx.opposite_singularity_distance(v, ctx.defect(v), GT::null_vertex(), GT::null_vertex());
      if(d >= 0) sum += std::size_t(d);
    }
    return sum;
  }

  // ---------------------------------------------------------------------------------------------
  // candidates

  // the singular vertices of the context just refreshed
  void take_singular(std::vector<vertex_descriptor>&& now)
  {
    singular = std::move(now);
    singular_of_sign[0] = singular_of_sign[1] = 0;
    for(vertex_descriptor v : singular) ++singular_of_sign[ctx.defect(v) > 0 ? 1 : 0];
  }

  // breadth-first search from s through passable vertices (on the mesh as it was at the start of the
  // batch, by vertex index): the closest singularities of each type that can end a surgery
  // (`neighbors_per_type` of each), and the border/feature singularities met before. The search stops
  // once no vertex left could be taken: each type has its partners, or all singularities of that type
  // were met (a mesh with fewer than `neighbors_per_type` of a type would otherwise be searched whole).
  // Vertices are judged as they are discovered, which is the order of the queue: the search stops at the
  // discovery of the last partner, without expanding the rest of the level before it.
  std::vector<std::vector<vertex_descriptor> > partner_paths(vertex_descriptor s)
  {
    const int is = ctx.index(s);
    if(search_visit.size() < ctx.number_of_vertices()) search_visit.assign(ctx.number_of_vertices(), 0u);
    if(++search_round == 0) { std::fill(search_visit.begin(), search_visit.end(), 0u); search_round = 1; }
    index_queue.clear();
    queue_parent.clear();
    index_queue.push_back(is);
    queue_parent.push_back(0);
    search_visit[std::size_t(is)] = search_round;
    std::size_t n3 = 0, n5 = 0, others = 0;
    const std::size_t k = settings.neighbors_per_type;
    // the singularities of each type not met yet, s excluded
    const int ds = ctx.defect_at(is);
    std::size_t unmet3 = singular_of_sign[0] - (ds < 0 ? 1 : 0), unmet5 = singular_of_sign[1] - (ds > 0 ? 1 : 0);
    std::vector<std::size_t> partners; // by their places in the queue
    // whether no vertex left could be taken
    auto over = [&]() { return (n3 >= k || unmet3 == 0) && (n5 >= k || unmet5 == 0); };
    // takes the singular vertex at place q of the queue as a partner if it may be one; returns over()
    auto meet = [&](std::size_t q)
    {
      const int v = index_queue[q];
      const int d = ctx.defect_at(v);
      const int dv = ctx.valence_at(v);
      const bool usable = ctx.is_passable_at(v) && (dv == 3 || dv == 5);
      if(usable && d < 0 && n3 < k) { ++n3; partners.push_back(q); }
      else if(usable && d > 0 && n5 < k) { ++n5; partners.push_back(q); }
      else if(!usable && others < 2 * k && ((d < 0 && n3 < k) || (d > 0 && n5 < k)))
      { ++others; partners.push_back(q); } // boundary/feature defects
      --(d < 0 ? unmet3 : unmet5);
      return over();
    };
    bool done = over();
    for(std::size_t i = 0; i < index_queue.size() && !done; ++i)
    {
      const int v = index_queue[i];
      if(v != is && !ctx.is_passable_at(v)) continue;
      for(const int* w = ctx.neighbors_begin(v); w != ctx.neighbors_end(v); ++w)
      {
        if(search_visit[std::size_t(*w)] == search_round) continue;
        search_visit[std::size_t(*w)] = search_round;
        index_queue.push_back(*w);
        queue_parent.push_back(int(i));
        if(ctx.defect_at(*w) != 0 && meet(index_queue.size() - 1)) { done = true; break; }
      }
    }
    std::vector<std::vector<vertex_descriptor> > paths;
    for(std::size_t t : partners)
    {
      std::vector<vertex_descriptor> path;
      for(std::size_t q = t; ; q = std::size_t(queue_parent[q]))
      {
        path.push_back(ctx.vertex(index_queue[q]));
        if(q == 0) break;
      }
      std::reverse(path.begin(), path.end());
      paths.push_back(std::move(path));
    }
    return paths;
  }

  // changing the number of faces by `change` keeps it within the tolerance, or brings it closer to the
  // initial one
  bool keeps_face_count(long change) const
  {
    const long f0 = long(stats.initial_number_of_faces);
    const long fnow = long(stats.number_of_faces);
    const long fafter = fnow + change;
    return std::abs(double(fafter - f0)) <= settings.face_count_tolerance * double(f0) ||
           std::abs(fafter - f0) < std::abs(fnow - f0);
  }

  // so does the plan, as planned (its execution may collapse more: the clean-up of valence-2 vertices)
  bool keeps_face_count(const Surgery_plan<PolygonMesh>& plan) const
  {
    return keeps_face_count(long(plan.number_of_splits()) - long(plan.number_of_collapses()));
  }

  // scores the candidates of source s (the four motions along the paths to its closest partners) and
  // hands each realizable one that keeps the face count to `handle(candidate, plan, score)`, which may
  // take the plan
  template <typename NP, typename Handler>
  void score_candidates(vertex_descriptor s, const NP& plan_np, const Handler& handle)
  {
    const auto paths = partner_paths(s);
    for(const auto& path : paths)
    {
      const vertex_descriptor t = path.back();
      for(int m = 0; m < 4; ++m)
      {
        Surgery_plan<PolygonMesh> plan = plan_qzip(pm, path, Strip_operation(m), plan_np);
        if(!plan.is_realizable()) continue;
        if(!keeps_face_count(plan)) continue;
        Qzip_candidate<PolygonMesh> c;
        c.plan = &plan;
        c.source = s;
        c.target = t;
        c.source_defect = ctx.defect(s);
        c.target_defect = ctx.defect(t);
        c.sketch_length = int(path.size()) - 1;
        predict_landings(plan, pm, c.source_landing, c.target_landing);
        if(c.source_landing != GT::null_vertex() && c.source_landing != t && c.source_landing != s &&
           ctx.defect(c.source_landing) * c.source_defect < 0) c.predicted_cancellations += 2;
        if(c.target_landing != GT::null_vertex() && c.target_landing != s && c.target_landing != t &&
           c.target_landing != c.source_landing && ctx.defect(c.target_landing) * c.target_defect < 0)
          c.predicted_cancellations += 2;
        handle(c, plan, scoring(c, ctx));
      }
    }
    ctx.clear_cache();
  }

  // the best improving candidate of s (negative score), if any
  template <typename NP>
  bool best_candidate(vertex_descriptor s, const NP& plan_np, Scored& best)
  {
    std::vector<Scored> improving;
    score_candidates(s, plan_np,
                     [&](const Qzip_candidate<PolygonMesh>& c, Surgery_plan<PolygonMesh>& plan, double score)
    {
      if(score >= 0 || undone_in_batches.count(key(plan)) != 0) return;
      Scored e;
      e.score = score;
      e.predicted_cancellations = c.predicted_cancellations;
      e.plan = std::move(plan);
      improving.push_back(std::move(e));
    });
    if(improving.empty()) return false;
    std::stable_sort(improving.begin(), improving.end(), [](const Scored& a, const Scored& b) { return a.score < b.score; });
    const std::size_t alternatives = (std::min)(improving.size() - 1, settings.alternatives);
    auto sketch_points = [this](Scored& c)
    {
      for(vertex_descriptor v : c.plan.sketch) c.sketch_points.push_back(get(vpm, v));
    };
    best = std::move(improving[0]);
    best.source_point = get(vpm, s);
    sketch_points(best);
    best.alternatives.clear();
    for(std::size_t i = 1; i <= alternatives; ++i)
    {
      improving[i].source_point = best.source_point;
      sketch_points(improving[i]);
      best.alternatives.push_back(std::move(improving[i]));
    }
    return true;
  }

  Surgery_key key(const Surgery_plan<PolygonMesh>& plan) const
  {
    const Point& a = get(vpm, plan.source);
    const Point& b = get(vpm, plan.target);
    return Surgery_key{{ a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), double(int(plan.initial_operation)) }};
  }

  // every improving candidate of s whose landings predict a cancellation (for the end game), except
  // those already rejected
  template <typename NP>
  void cancelling_candidates(vertex_descriptor s, const NP& plan_np, std::vector<Scored>& out)
  {
    score_candidates(s, plan_np,
                     [&](const Qzip_candidate<PolygonMesh>& c, Surgery_plan<PolygonMesh>& plan, double score)
    {
      if(score >= 0 || c.predicted_cancellations == 0) return;
      const Surgery_key k = key(plan);
      if(rejected.count(k) != 0) return;
      out.push_back(Scored{ std::move(plan), score, get(vpm, s), c.predicted_cancellations, k });
    });
  }

  // ---------------------------------------------------------------------------------------------
  // execution

  // remembers a surgery that was executed and undone (or rolled back), by the positions of its ends and its
  // motion: it would be undone again, and the source chooses its next best candidate instead while its ends
  // stay where they were; in the end game for good, in the batches until a batch lowers the number of
  // singularities (the mesh around may have changed enough for it to pass)
  void reject(const Surgery_key& k, bool end_game)
  {
    (end_game ? rejected : undone_in_batches).insert(k);
  }

  // marks the vertices of `region` not yet operated on in this batch as operated on by the current surgery
  void mark(const std::vector<vertex_descriptor>& region)
  {
    for(vertex_descriptor v : region)
    {
      if(get(op_stamp, v) < first_in_batch)
      {
        put(op_stamp, v, surgery_serial);
        marks_in_batch.emplace_back(v, surgery_serial);
      }
      const std::size_t p = get(partner_id, v);
      if(p > partner_base) partner_lost[p - partner_base - 1] = 1;
    }
  }

  // After an execution rolled back: the vertices it created and removed again are dead, and their
  // descriptors may have been those of vertices removed earlier in the batch, which the plans of other
  // candidates still name; a recycled descriptor lost its mark (Surface_mesh resets the properties of the
  // elements it reuses), and the execution tells no one which vertices it created. Giving every vertex
  // marked in this batch its mark back makes those plans skipped, instead of walking around a dead vertex.
  // (An undone surgery's created vertices are known: see execute().)
  void restore_marks()
  {
    for(const std::pair<vertex_descriptor, unsigned int>& m : marks_in_batch)
      if(get(op_stamp, m.first) < first_in_batch) put(op_stamp, m.first, m.second);
  }

  // whether v lies in the region of a surgery of this batch, other than those of the current pair
  bool operated_on(vertex_descriptor v) const
  {
    const unsigned int s = get(op_stamp, v);
    return s >= first_in_batch && s < first_of_pair;
  }

  // whether v is singular (the context's definition of the defect, on the mesh as it is now)
  bool is_singular_now(vertex_descriptor v) const
  {
    typedef typename Kernel_traits<Point>::Kernel Kernel;
    return internal::vertex_defect_info(v, pm, vpm, ecm, Kernel()).defect != 0;
  }

  // the vertices reached from `shell` without entering those stamped `outer_epoch` (see execute())
  std::vector<vertex_descriptor> region_within_outer(const std::vector<vertex_descriptor>& shell)
  {
    ++search_epoch;
    std::vector<int> level;
    return vertex_ball(shell, (std::numeric_limits<int>::max)(), pm, level, [this](vertex_descriptor v)
    {
      if(get(search_stamp, v) == search_epoch || get(outer_stamp, v) == outer_epoch) return false;
      put(search_stamp, v, search_epoch);
      return true;
    });
  }

  // the number of singular vertices within four edges of the path of a surgery just executed: the
  // vertices reached from the touched vertices and from `shell` (the vertices at distance four before
  // the surgery, never removed) without entering the vertices at distance five (stamped `outer_epoch`,
  // untouched, so they still enclose the region); `false` if a touched vertex lies outside.
  std::pair<bool, std::size_t> singular_in_region(const std::vector<vertex_descriptor>& touched,
                                                  const std::vector<vertex_descriptor>& shell)
  {
    ++search_epoch;
    std::vector<vertex_descriptor> queue;
    for(vertex_descriptor v : touched)
    {
      if(get(outer_stamp, v) == outer_epoch) return std::make_pair(false, std::size_t(0));
      if(get(search_stamp, v) != search_epoch) { put(search_stamp, v, search_epoch); queue.push_back(v); }
    }
    for(vertex_descriptor v : shell)
      if(get(search_stamp, v) != search_epoch) { put(search_stamp, v, search_epoch); queue.push_back(v); }
    std::size_t n = 0;
    for(std::size_t i = 0; i < queue.size(); ++i)
    {
      if(is_singular_now(queue[i])) ++n;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(queue[i], pm), pm))
      {
        const vertex_descriptor w = source(h, pm);
        if(get(search_stamp, w) == search_epoch || get(outer_stamp, w) == outer_epoch) continue;
        put(search_stamp, w, search_epoch);
        queue.push_back(w);
      }
    }
    return std::make_pair(true, n);
  }

  // An undone (or rolled back) surgery gives back the mesh it found, up to the descriptors of the vertices
  // it re-created, so a candidate whose path meets only regions of undone surgeries is still valid there,
  // with other descriptors: its sketch is found again by the positions it had at the start of the batch,
  // walking from a vertex of it that no surgery of the batch came near (alive, the same vertex), and
  // planned again with the same motion. Fails if a vertex is not found, if the new path meets the region
  // of a surgery kept in this batch (the mesh changed there), or if the new plan differs.
  template <typename NP>
  bool replan(const Scored& cand, const NP& plan_np, Surgery_plan<PolygonMesh>& out)
  {
    const std::vector<vertex_descriptor>& sketch = cand.plan.sketch;
    const std::vector<Point>& at = cand.sketch_points;
    if(at.size() != sketch.size() || sketch.empty()) return false;
    std::size_t anchor = 0;
    while(anchor < sketch.size() && operated_on(sketch[anchor])) ++anchor;
    if(anchor == sketch.size() || get(vpm, sketch[anchor]) != at[anchor]) return false;
    // the neighbour of v at p (null_vertex() if none, or if two are there)
    auto neighbour_at = [this](vertex_descriptor v, const Point& p)
    {
      vertex_descriptor hit = GT::null_vertex();
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        if(get(vpm, source(h, pm)) != p) continue;
        if(hit != GT::null_vertex()) return GT::null_vertex();
        hit = source(h, pm);
      }
      return hit;
    };
    std::vector<vertex_descriptor> found(sketch.size(), GT::null_vertex());
    found[anchor] = sketch[anchor];
    for(std::size_t i = anchor + 1; i < sketch.size(); ++i)
      if((found[i] = neighbour_at(found[i - 1], at[i])) == GT::null_vertex()) return false;
    for(std::size_t i = anchor; i-- > 0; )
      if((found[i] = neighbour_at(found[i + 1], at[i])) == GT::null_vertex()) return false;
    out = plan_qzip(pm, found, cand.plan.initial_operation, plan_np);
    if(!out.is_realizable() || out.path.size() != cand.plan.path.size() ||
       out.number_of_collapses() != cand.plan.number_of_collapses() ||
       out.number_of_splits() != cand.plan.number_of_splits()) return false;
    for(vertex_descriptor v : out.path) if(get(kept_stamp, v) == batch_epoch) return false;
    return true;
  }

  // executes the candidate unless its region was already operated on in this batch; keeps it if the
  // smoothed scar has no more inverted quads than before (and, if `require_decrease`, if the number of
  // singularities near its path dropped), else undoes it exactly
  // (`follows`: a surgery of the same pair as the previous one, see follow(), which may operate on the region
  // of the previous one; `moved`: where the pair is after a kept surgery)
  template <typename NP>
  Outcome execute(const Scored& cand, const NP& exec_np, bool require_decrease, bool follows = false,
                  std::pair<vertex_descriptor, vertex_descriptor>* moved = nullptr)
  {
    ++surgery_serial;
    if(!follows) first_of_pair = surgery_serial;
    // The region of the plan must not have been operated on in this batch. Only the path vertices are
    // read before the check: a vertex removed by an earlier surgery of the batch lies within three edges
    // of its path, which is marked, so no removed vertex is ever walked around. A path at four edges or
    // more from the earlier paths has its one-ring (what its operations touch) disjoint from theirs.
    // In a batch, a plan whose path meets only the regions of undone surgeries is planned again there.
    const Surgery_plan<PolygonMesh>* planned = &cand.plan;
    Surgery_plan<PolygonMesh> replanned;
    if(std::any_of(cand.plan.path.begin(), cand.plan.path.end(), [this](vertex_descriptor v) { return operated_on(v); }))
    {
      if(require_decrease || follows || !settings.replan_after_undos || !replan(cand, exec_np, replanned))
      {
        ++stats.number_of_skipped_surgeries;
        return SKIPPED;
      }
      planned = &replanned;
      ++stats.number_of_replanned_surgeries;
    }
    const Surgery_plan<PolygonMesh>& plan = *planned;
    if(!keeps_face_count(plan)) { ++stats.number_of_skipped_surgeries; return SKIPPED; }
    // read once the path is known to be alive (a skipped plan may name dead vertices), before the ends move
    const Surgery_key surgery_key = require_decrease ? cand.key : key(plan);
    // asked before the region is marked (which loses the partners in it)
    const std::size_t source_watched = watched_partner(plan.source), target_watched = watched_partner(plan.target);
    // A surgery only removes vertices within three edges of its path (the far corners of the clean-up);
    // the vertices at distance four (the shell) and five (stamped `outer_epoch`) are never touched: they
    // stay alive through an undo, and the region they enclose holds the re-created vertices, whose
    // descriptors are new (or recycled: with reset properties on Surface_mesh, with those of whatever
    // element had the address on Polyhedron_3).
    std::vector<int> level;
    std::vector<vertex_descriptor> region = ball(plan.path, 5, level);
    std::vector<vertex_descriptor> shell;
    std::size_t singular_before = 0;
    ++outer_epoch;
    std::size_t inside = 0;
    for(std::size_t i = 0; i < region.size(); ++i)
    {
      if(level[i] == 5) put(outer_stamp, region[i], outer_epoch);
      else
      {
        if(require_decrease && is_singular_now(region[i])) ++singular_before;
        region[inside] = region[i];
        level[inside++] = level[i];
      }
    }
    region.resize(inside);
    level.resize(inside);
    std::vector<vertex_descriptor> inner;
    for(std::size_t i = 0; i < region.size(); ++i)
    {
      if(level[i] < 4) inner.push_back(region[i]);
      else shell.push_back(region[i]);
    }
    mark(inner);
    // a watched partner at an end is lost now (the end is in `inner`) and, if the surgery is kept, found
    // again where it moved (see partner_moved()). The end's vertex must not carry its id any more: it may
    // stay, no longer singular, or be removed and its place taken by another vertex (on Polyhedron_3 at the
    // same address, with its properties), and a later surgery covering it would lose the moved partner.
    if(source_watched != no_partner) put(partner_id, plan.source, std::size_t(0));
    if(target_watched != no_partner) put(partner_id, plan.target, std::size_t(0));
    // the vertices of the region that lie in a scar of this batch, by position: an undo re-creates the
    // removed vertices at the same places, with new descriptors (which may be recycled, with or without
    // their former stamps, depending on the mesh type), and they must be in the scars as before
    // (and in the region of a surgery kept earlier in the batch, see replan())
    struct Stamps_at { Point point; bool in_scar, kept; };
    std::vector<Stamps_at> stamps;
    for(vertex_descriptor v : inner)
      stamps.push_back(Stamps_at{ get(vpm, v), get(scar_stamp, v) == batch_epoch, get(kept_stamp, v) == batch_epoch });
    auto by_point = [](const Stamps_at& a, const Stamps_at& b) { return point_less(a.point, b.point); };
    std::sort(stamps.begin(), stamps.end(), by_point);
    auto mark_after_undo = [&]()
    {
      mark(region);           // no walk: some of these descriptors may be dead
      // walks from vertices that are alive: four edges around the shell, and the whole region again (a
      // vertex inside a bend of the path may be more than four edges from the shell), so that every
      // re-created vertex gets its marks whatever its descriptor carried
      const std::vector<vertex_descriptor> enclosed = region_within_outer(shell);
      std::vector<vertex_descriptor> around = ball(shell, 4);
      for(vertex_descriptor v : enclosed)
        if(get(search_stamp, v) != search_epoch) around.push_back(v);
      mark(around);
      ctx.rows_edited(enclosed); // the shell and what it encloses: the undo changed no other row
      for(vertex_descriptor v : around)
      {
        const auto it = std::lower_bound(stamps.begin(), stamps.end(), Stamps_at{ get(vpm, v), false, false }, by_point);
        if(it == stamps.end() || it->point != get(vpm, v)) continue;
        put(scar_stamp, v, it->in_scar ? batch_epoch : 0u);
        put(kept_stamp, v, it->kept ? batch_epoch : 0u);
      }
    };

    std::vector<vertex_descriptor> near_path;
    for(std::size_t i = 0; i < region.size() && level[i] <= 2; ++i) near_path.push_back(region[i]);
    const std::pair<std::size_t, double> before = quality(near_path);
    Qzip_history<PolygonMesh, VertexPointMap> history(pm, vpm); // this surgery only
    ctx.may_remove(inner);
    Qzip_result<PolygonMesh> r = execute_qzip(pm, plan, history, exec_np);
    if(!r.is_done())
    {
      ++stats.number_of_failed_surgeries;
      restore_marks();
      mark_after_undo();
      reject(surgery_key, require_decrease);
      return FAILED;
    }

    std::vector<vertex_descriptor> scar = ball(r.touched_vertices, 1);
    sort_by_position(scar);
    std::vector<Point> saved;
    saved.reserve(scar.size());
    for(vertex_descriptor v : scar) saved.push_back(get(vpm, v));
    if(settings.smooth)
    {
      smoother.snap_to_surface(r.touched_vertices);
      smoother.smooth(scar, settings.smoothing_iterations);
    }
    // never worse: no more inverted quads than before, and no quad worse than the worst one before
    // unless it stays above the quality floor; and the number of faces the execution left within the
    // tolerance (or closer to the initial one)
    std::pair<std::size_t, double> after = quality(scar);
    auto shape_kept = [&]()
    { return after.first <= before.first && after.second >= (std::min)(before.second, settings.quality_floor); };
    // most failures leave a quad just below the floor, which untangling lifts (RESULTS.md, session 21)
    if(!shape_kept() && settings.smooth && settings.untangling_sweeps > 0 &&
       smoother.untangle(scar, settings.untangling_sweeps, settings.quality_floor) > 0)
      after = quality(scar);
    bool keep = shape_kept() && keeps_face_count(long(r.number_of_splits) - long(r.number_of_collapses));
    if(keep && require_decrease)
    {
      const std::pair<bool, std::size_t> singular_after = singular_in_region(r.touched_vertices, shell);
      keep = singular_after.first && singular_after.second < singular_before;
    }
    if(!keep)
    {
      for(std::size_t i = 0; i < scar.size(); ++i) put(vpm, scar[i], saved[i]);
      undo_qzip(history);
      // the vertices the surgery created are dead again, and their descriptors may have been those of
      // vertices removed earlier in the batch, which the plans of other candidates still name: marked (no
      // walk), those plans are skipped instead of walking around a dead vertex
      mark(r.touched_vertices);
      mark_after_undo();
      ++stats.number_of_undone_surgeries;
      visitor.on_undo(plan);
      reject(surgery_key, require_decrease);
      return UNDONE;
    }
    for(vertex_descriptor v : scar) put(scar_stamp, v, batch_epoch);
    edited_vertices.insert(edited_vertices.end(), scar.begin(), scar.end());
    ctx.rows_edited(scar);
    ctx.survived(region_within_outer(shell)); // the vertices of `inner` still alive
    // new vertices (all touched) may reuse the descriptors of removed ones, with their marks
    for(vertex_descriptor v : r.touched_vertices) put(op_stamp, v, surgery_serial);
    const std::vector<vertex_descriptor> near_touched = ball(r.touched_vertices, 2);
    mark(near_touched);
    for(vertex_descriptor v : inner) put(kept_stamp, v, batch_epoch); // some of them are dead: no walk
    for(vertex_descriptor v : near_touched) put(kept_stamp, v, batch_epoch);
    stats.number_of_faces = stats.number_of_faces + r.number_of_splits - r.number_of_collapses;
    ++stats.number_of_surgeries;
    ++stats.surgeries_in_last_batch;
    visitor.on_surgery(plan, cand.score, -cand.predicted_cancellations);
    if(moved != nullptr) *moved = std::make_pair(r.moved_source, r.moved_target);
    partner_moved(source_watched, r.moved_source);
    partner_moved(target_watched, r.moved_target);
    return KEPT;
  }

  // whether v is an interior vertex of valence 3 or 5 incident to no constrained edge and no protected
  // face (on the mesh as it is now)
  bool can_move_now(vertex_descriptor v) const
  {
    return (degree(v, pm) == 3 || degree(v, pm) == 5) && is_passable_now(v);
  }

  bool is_passable_now(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(blocks_passage_now(h)) return false;
    return true;
  }

  // whether the halfedge h, ending at a vertex, makes it impassable: its edge is on the border or
  // constrained, or its face is protected
  bool blocks_passage_now(halfedge_descriptor h) const
  {
    return is_border_edge(h, pm) || get(ecm, edge(h, pm)) || (!is_border(h, pm) && get(fcm, face(h, pm)));
  }

  // a shortest path from s to t through passable vertices on the mesh as it is now, if one has at most
  // `max_length` edges (empty otherwise): the path to t is known when t is discovered. One walk around each
  // vertex expanded both tells whether it is passable and lists its neighbors. With `in_pair_region`, only
  // through the vertices that the surgeries of the current pair covered first in this batch (see mark()).
  std::vector<vertex_descriptor> shortest_path_now(vertex_descriptor s, vertex_descriptor t, std::size_t max_length,
                                                   bool in_pair_region)
  {
    if(s == t) return std::vector<vertex_descriptor>(1, s);
    ++search_epoch;
    std::vector<vertex_descriptor> queue(1, s);
    std::vector<std::size_t> from(1, 0), level(1, 0);
    put(search_stamp, s, search_epoch);
    boost::container::small_vector<vertex_descriptor, 8> ring;
    for(std::size_t i = 0; i < queue.size(); ++i)
    {
      if(level[i] >= max_length) continue;
      ring.clear();
      bool passable = true;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(queue[i], pm), pm))
      {
        if(i > 0 && blocks_passage_now(h))
        {
          passable = false;
          break;
        }
        ring.push_back(source(h, pm));
      }
      if(!passable) continue;
      for(const vertex_descriptor w : ring)
      {
        if(get(search_stamp, w) == search_epoch) continue;
        if(in_pair_region && w != t && get(op_stamp, w) < first_of_pair) continue;
        if(w == t)
        {
          std::vector<vertex_descriptor> path(1, t);
          for(std::size_t j = i; ; j = from[j]) { path.push_back(queue[j]); if(j == 0) break; }
          std::reverse(path.begin(), path.end());
          return path;
        }
        put(search_stamp, w, search_epoch);
        queue.push_back(w);
        from.push_back(i);
        level.push_back(level[i] + 1);
      }
    }
    return std::vector<vertex_descriptor>();
  }

  // the index of p among the watched partners of the batch (added if needed), no_partner for null_vertex()
  std::size_t watch(vertex_descriptor p)
  {
    if(p == GT::null_vertex()) return no_partner;
    const std::size_t id = get(partner_id, p);
    if(id > partner_base) return id - partner_base - 1;
    partner_vertices.push_back(p);
    partner_lost.push_back(0);
    put(partner_id, p, partner_base + partner_vertices.size());
    return partner_vertices.size() - 1;
  }

  // the closest singularity of the opposite sign of each end of the candidate, the pair excluded (what
  // Pairing_term pulls towards), at the start of the batch, watched: once the region of a surgery covers
  // it (before the surgery, when all its vertices are alive), it may be gone and follow() stops, unless it
  // was an end of a kept surgery (see partner_moved())
  std::pair<std::size_t, std::size_t> watch_partners(const Scored& c)
  {
    const vertex_descriptor s = c.plan.source, t = c.plan.target;
    return std::make_pair(watch(ctx.closest_opposite_singularity(s, ctx.defect(s), s, t).vertex),
                          watch(ctx.closest_opposite_singularity(t, ctx.defect(t), s, t).vertex));
  }

  // the index of the watched partner at v, alive, if it is not lost (no_partner otherwise). A partner
  // that is not lost was never covered by the region of a surgery: its vertex is alive, and a vertex equal to
  // it is it (partner_id may be stale on a vertex that took the place of a removed one, on Polyhedron_3).
  std::size_t watched_partner(vertex_descriptor v) const
  {
    for(std::size_t i = 0; i < partner_vertices.size(); ++i)
      if(partner_vertices[i] == v && !partner_lost[i]) return i;
    return no_partner;
  }

  // after a kept surgery, one of whose ends was the watched partner `i` (no_partner: none): if the surgery
  // knows where that end went (`to`, not null_vertex()), the partner is there and no longer lost. On the
  // gargoyle's Catmull-Clark level 4, whose singularities are sparse, about half of the follow() calls that
  // stopped at once did so because a partner had been moved by an earlier surgery of the batch (RESULTS.md,
  // session 29).
  void partner_moved(std::size_t i, vertex_descriptor to)
  {
    if(i == no_partner || to == GT::null_vertex()) return;
    partner_vertices[i] = to;
    partner_lost[i] = 0;
    put(partner_id, to, partner_base + 1 + i);
  }

  // the distances from `from` to the vertices of `queries` on the mesh as it is now (-1 for those not
  // reached); the search stops at the discovery of the last of them
  std::vector<int> distances_now(vertex_descriptor from, const std::vector<vertex_descriptor>& queries)
  {
    std::vector<int> out(queries.size(), -1);
    std::size_t found = 0;
    auto meet = [&](vertex_descriptor v, int d)
    {
      for(std::size_t q = 0; q < queries.size(); ++q)
        if(queries[q] == v && out[q] < 0) { out[q] = d; ++found; }
      return found == queries.size();
    };
    if(meet(from, 0)) return out;
    ++search_epoch;
    std::vector<vertex_descriptor> queue(1, from);
    std::vector<int> level(1, 0);
    put(search_stamp, from, search_epoch);
    for(std::size_t i = 0; i < queue.size(); ++i)
    {
      for(halfedge_descriptor h : halfedges_around_target(halfedge(queue[i], pm), pm))
      {
        const vertex_descriptor w = source(h, pm);
        if(get(search_stamp, w) == search_epoch) continue;
        put(search_stamp, w, search_epoch);
        if(meet(w, level[i] + 1)) return out;
        queue.push_back(w);
        level.push_back(level[i] + 1);
      }
    }
    return out;
  }

  // After a kept Q-zip of a pair along a path of `length` edges, the pair now at `moved`, its ends pulled
  // towards their `partners` (see watch_partners()): Q-zips the pair again along a shortest path between its
  // new places (within the region of its earlier Q-zips if one is there, see below) while each end is still
  // more than `follow_min_distance` edges from its partner, no surgery came near the partners (but those that
  // moved them, see partner_moved()), a plan brings the ends closer to their partners in sum (of the four
  // motions, the one whose landings are closest to them, then the one that keeps the number of faces closest
  // to the initial one) and the surgery is kept (the same checks as in a batch, except that it may operate on
  // the region of the previous Q-zips of the pair). Far from their partners, singularities thus travel
  // several edges in one batch instead of one.
  template <typename NP>
  void follow(std::pair<vertex_descriptor, vertex_descriptor> moved, std::pair<std::size_t, std::size_t> partners,
              std::size_t length, const NP& plan_np)
  {
    if(partners.first == no_partner || partners.second == no_partner || partners.first == partners.second) return;
    int previous = (std::numeric_limits<int>::max)(); // the actual sum of the distances to the partners: it must drop
    for(;;)
    {
      const vertex_descriptor s = moved.first, t = moved.second;
      if(s == GT::null_vertex() || t == GT::null_vertex() || s == t) return;
      if(partner_lost[partners.first] || partner_lost[partners.second]) return;
      const std::pair<vertex_descriptor, vertex_descriptor> partner(partner_vertices[partners.first],
                                                                    partner_vertices[partners.second]);
      if(!can_move_now(s) || !can_move_now(t)) return;
      // The new ends lie in the region of the pair's last Q-zip, which holds a path between them as short as
      // any on the mesh in about 97-99% of the cases: searched there first (a few hundred vertices, instead of
      // a ball of the path's length around s), then on the whole mesh (RESULTS.md, session 30). A path in that
      // region is never skipped by execute(): the region of another surgery of the batch is not in it.
      std::vector<vertex_descriptor> path = shortest_path_now(s, t, length + 2, true);
      if(path.empty()) path = shortest_path_now(s, t, length + 2, false);
      if(path.empty()) return;
      length = path.size() - 1;
      std::vector<Surgery_plan<PolygonMesh> > plans;
      std::vector<vertex_descriptor> at_source(1, s), at_target(1, t);
      for(int m = 0; m < 4; ++m)
      {
        Surgery_plan<PolygonMesh> plan = plan_qzip(pm, path, Strip_operation(m), plan_np);
        if(!plan.is_realizable() || !keeps_face_count(plan)) continue;
        vertex_descriptor sl, tl;
        predict_landings(plan, pm, sl, tl);
        if(sl == GT::null_vertex() || tl == GT::null_vertex()) continue;
        plans.push_back(std::move(plan));
        at_source.push_back(sl);
        at_target.push_back(tl);
      }
      if(plans.empty()) return;
      const std::vector<int> ds = distances_now(partner.first, at_source);
      const std::vector<int> dt = distances_now(partner.second, at_target);
      if(ds[0] < 0 || dt[0] < 0 || ds[0] + dt[0] >= previous) return;
      if(ds[0] <= int(settings.follow_min_distance) || dt[0] <= int(settings.follow_min_distance)) return;
      previous = ds[0] + dt[0];
      std::size_t best = 0;
      long best_faces = 0;
      for(std::size_t k = 1; k <= plans.size(); ++k)
      {
        const Surgery_plan<PolygonMesh>& plan = plans[k - 1];
        const long faces_after = std::abs(long(stats.number_of_faces) + long(plan.number_of_splits()) -
                                          long(plan.number_of_collapses()) - long(stats.initial_number_of_faces));
        const int d = ds[k] + dt[k];
        if(ds[k] < 0 || dt[k] < 0 || d >= ds[0] + dt[0]) continue;
        if(best == 0 || d < ds[best] + dt[best] || (d == ds[best] + dt[best] && faces_after < best_faces))
        {
          best = k;
          best_faces = faces_after;
        }
      }
      if(best == 0) return;
      Scored step;
      step.score = double(ds[best] + dt[best] - ds[0] - dt[0]); // reported to the visitor: negative
      step.predicted_cancellations = 0;
      step.plan = std::move(plans[best - 1]);
      step.source_point = get(vpm, s);
      if(execute(step, plan_np, false, true, &moved) != KEPT) return;
    }
  }

  // One batch (Sec. 4.1), or one round of the end game: every singularity that can start a surgery and
  // has one of the opposite sign within two edges (a landing that cancels is next to the source or to
  // the target) tries all its improving candidates predicted to cancel singularities, best predictions
  // first, and a surgery is kept only if the singularities near its path are actually fewer. Returns the
  // number of surgeries executed (kept, undone or rolled back).
  std::size_t run_batch(bool end_game)
  {
    ++batch_epoch;
    first_in_batch = surgery_serial + 1;
    marks_in_batch.clear();
    partner_base += partner_vertices.size() + 1;
    partner_vertices.clear();
    partner_lost.clear();
    CGAL::Real_timer score_timer, exec_timer;
    score_timer.start();
    stats.surgeries_in_last_batch = 0;

    // the singularities that can start a surgery, in an order that does not depend on descriptors; a
    // random half of them in a batch
    std::vector<vertex_descriptor> sources;
    for(vertex_descriptor v : singular) if(is_endpoint(v)) sources.push_back(v);
    sort_by_position(sources);
    if(!end_game)
    {
      for(std::size_t i = sources.size(); i > 1; --i)
        std::swap(sources[i - 1], sources[std::size_t(rng.get_int(0, int(i)))]);
      sources.resize((sources.size() + 1) / 2);
    }

    // candidates are planned without simulating their execution (it costs about two executions, and a
    // chosen surgery whose execution fails is rolled back exactly by the executor)
    const auto plan_np = Qzip::parameters::simulate_chain(false, Qzip::parameters::face_is_constrained_map(fcm,
                           CGAL::parameters::edge_is_constrained_map(ecm).vertex_point_map(vpm)));
    // In a sparse batch, which executes every chosen candidate, a source that is the target of the candidate an
    // earlier source chose is not scored: its own candidate would start at a singularity that this one operates on,
    // so only one of the two could be executed (the other is skipped). The pair is moved from the earlier source,
    // and the time the target's scoring took goes to more batches (RESULTS.md, session 15).
    const bool skip_chosen_targets = !end_game && settings.skip_chosen_targets && is_sparse();
    std::vector<vertex_descriptor> chosen_targets;
    std::vector<Scored> chosen;
    for(vertex_descriptor s : sources)
    {
      if(end_game)
      {
        if(has_opposite_within(s, 2)) cancelling_candidates(s, plan_np, chosen);
        continue;
      }
      if(skip_chosen_targets && std::find(chosen_targets.begin(), chosen_targets.end(), s) != chosen_targets.end())
        continue;
      Scored best;
      if(!best_candidate(s, plan_np, best)) continue;
      chosen_targets.push_back(best.plan.target);
      chosen.push_back(std::move(best));
    }
    std::stable_sort(chosen.begin(), chosen.end(), [end_game](const Scored& a, const Scored& b)
    {
      if(end_game && a.predicted_cancellations != b.predicted_cancellations)
        return a.predicted_cancellations > b.predicted_cancellations;
      if(a.score != b.score) return a.score < b.score;
      return point_less(a.source_point, b.source_point);
    });
    if(!end_game)
    {
      stats.candidates_in_last_batch = chosen.size();
      // Far apart, the singularities have candidates whose regions rarely meet (a candidate whose region an
      // earlier surgery of the batch operated on is skipped anyway): the second half moves singularities as
      // well as the first, and a batch tries all of them.
      if(!is_sparse()) chosen.resize((chosen.size() + 1) / 2);
    }
    if(!end_game && settings.follow_min_distance > 0) // asked before the mesh changes
      for(Scored& c : chosen)
      {
        c.partners = watch_partners(c);
        for(Scored& a : c.alternatives) a.partners = watch_partners(a);
      }
    score_timer.stop();
    stats.scoring_seconds += score_timer.time();
    if(!end_game) visitor.on_batch_scored(stats, chosen.size());

    exec_timer.start();
    std::size_t executed = 0;
    for(const Scored& c : chosen)
    {
      const bool follows = !end_game && settings.follow_min_distance > 0;
      std::pair<vertex_descriptor, vertex_descriptor> moved;
      const Scored* done = &c;
      Outcome outcome = execute(c, plan_np, end_game, false, &moved);
      for(std::size_t a = 0; outcome == SKIPPED && a < c.alternatives.size(); ++a)
      {
        done = &c.alternatives[a];
        outcome = execute(*done, plan_np, end_game, false, &moved);
      }
      if(outcome != SKIPPED) ++executed;
      if(outcome == KEPT && follows) follow(moved, done->partners, done->plan.path.size() - 1, plan_np);
    }
    // an undone or rolled back surgery may give new descriptors to the vertices it re-created
    const bool edited = executed > 0;

    // smoothing near all the scars of the batch
    if(settings.smooth && stats.surgeries_in_last_batch > 0)
    {
      std::vector<vertex_descriptor> scars;
      for(vertex_descriptor v : vertices(pm)) if(get(scar_stamp, v) == batch_epoch) scars.push_back(v);
      sort_by_position(scars);
      smoother.smooth(scars, settings.smoothing_iterations);
    }
    exec_timer.stop();
    stats.execution_seconds += exec_timer.time();

    if(edited) // else the mesh, the context and the pairing distance are as they were
    {
      take_singular(ctx.begin_batch(edited_vertices));
      stats.pairing_distance = pairing_distance();
    }
    edited_vertices.clear();
    const std::size_t before = stats.number_of_singularities;
    stats.number_of_singularities = singular.size();
    stats.number_of_faces = faces(pm).size();
    stats.elapsed_seconds = timer.time();
    if(end_game)
    {
      ++stats.end_game_rounds;
      return executed;
    }
    stats.batches_without_improvement = singular.size() < before ? 0 : stats.batches_without_improvement + 1;
    if(singular.size() < before) undone_in_batches.clear();
    if(singular.size() < before || stats.pairing_distance < best_pairing_distance)
    {
      best_pairing_distance = stats.pairing_distance;
      stats.batches_without_progress = 0;
    }
    else ++stats.batches_without_progress;
    ++stats.batch;
    visitor.on_batch_finished(stats);
    return executed;
  }

  // the end game, once the batches stop: rounds (see run_batch()) as long as they try surgeries; a
  // surgery undone is not tried again (the surgeries skipped because an earlier one of the round
  // operated near them are tried in the next round). Returns whether it cancelled singularities.
  bool run_end_game()
  {
    const std::size_t initial = stats.number_of_singularities;
    std::set<Point, bool(*)(const Point&, const Point&)> failed(&point_less);
    for(std::size_t round = 0; round < settings.max_end_game_rounds && !out_of_time(); ++round)
    {
      const bool tried = run_batch(true) > 0;
      const bool kept = settings.look_ahead && !out_of_time() && look_ahead_round(failed);
      if(!tried && !kept) break;
    }
    best_pairing_distance = stats.pairing_distance;
    return stats.number_of_singularities < initial;
  }

  // one round of the look-ahead (see Look_ahead): each singularity that can start a Q-zip, in an order that
  // does not depend on descriptors, tries to cancel with one of the opposite sign nearby by a chain of
  // Q-zips, unless it failed before (`failed`, by position). The singularities that a chain tried before
  // them in the pass came near (whose descriptors may be gone) wait for the next pass, after the context
  // is refreshed. Returns whether it kept a chain.
  bool look_ahead_round(std::set<Point, bool(*)(const Point&, const Point&)>& failed)
  {
    typedef Look_ahead<PolygonMesh, VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap, Smoother> Chains;
    typename Chains::Settings chain_settings;
    chain_settings.max_distance = settings.look_ahead_distance;
    chain_settings.max_depth = settings.look_ahead_depth;
    chain_settings.smoothing_iterations = settings.smoothing_iterations;
    chain_settings.quality_floor = settings.quality_floor;
    chain_settings.smooth = settings.smooth;
    auto keeps_face_count = [this](long change) { return this->keeps_face_count(change); };

    bool kept = false;
    for(bool waiting = true; waiting; )
    {
      waiting = false;
      Chains chains(pm, vpm, ecm, fcm, smoother, chain_settings);
      std::vector<vertex_descriptor> sources;
      for(vertex_descriptor v : singular) if(is_endpoint(v)) sources.push_back(v);
      sort_by_position(sources);
      std::vector<Point> positions;
      for(vertex_descriptor s : sources) positions.push_back(get(vpm, s));
      for(std::size_t i = 0; i < sources.size(); ++i)
      {
        if(out_of_time()) { waiting = false; break; }
        const vertex_descriptor s = sources[i];
        if(failed.count(positions[i]) != 0) continue;
        if(chains.was_near_a_path(s)) { waiting = true; continue; }
        if(!chains.is_endpoint(s)) continue;
        const std::size_t executions = chains.number_of_executions();
        typename Chains::Chain chain;
        if(!chains.cancel(s, keeps_face_count, chain))
        {
          if(chains.number_of_executions() > executions) failed.insert(positions[i]);
          continue;
        }
        kept = true;
        stats.number_of_faces = std::size_t(long(stats.number_of_faces) + chain.face_change);
        stats.number_of_surgeries += chain.plans.size();
        for(std::size_t k = 0; k < chain.plans.size(); ++k) // not scored: score 0
          visitor.on_surgery(chain.plans[k], 0., -chain.predicted_cancellations[k]);
        edited_vertices.insert(edited_vertices.end(), chain.scar.begin(), chain.scar.end());
      }
      stats.number_of_undone_surgeries += chains.number_of_undos();
      if(chains.number_of_executions() > 0) // undone Q-zips may give new descriptors to re-created vertices
      {
        ctx.rows_changed_elsewhere(); // the chains undone tell no one where they were
        take_singular(ctx.begin_batch(edited_vertices));
        stats.pairing_distance = pairing_distance();
        stats.number_of_singularities = singular.size();
        stats.number_of_faces = faces(pm).size();
      }
      edited_vertices.clear();
    }
    return kept;
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_OPTIMIZER_BATCH_OPTIMIZER_H
