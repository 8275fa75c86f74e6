// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SURGERY_PLAN_H
#define CGAL_QZIP_SURGERY_PLAN_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/strip_operation.h>
#include <CGAL/Qzip/Named_function_parameters.h>
#include <CGAL/Qzip/internal/rotation.h>
#include <CGAL/Qzip/internal/endpoint_preparation.h>
#include <CGAL/Qzip/internal/vertex_defect.h>
#include <CGAL/Qzip/singularities.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipPrimitive
A Q-zip surgery plan: plain data, computed without touching the mesh by `plan_qzip()`.

`path` is the adjusted surgery path (after the end-point preparation of the paper's Sec. 2.6) and
`operations[i]` the strip operation performed at `path[i]` on the way to `path[i+1]`; `operations` has
one entry per vertex of `path`, the last one being `NO_OPERATION`. A reverse plan (`Qzip_result::reverse_plan`,
see `reverse_qzip()`) may also start with atomic operations (`prelude`) and name vertices of `path` that its
own execution creates (`created_vertices`).
*/
template <typename PolygonMesh>
struct Surgery_plan
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;

  vertex_descriptor source;                  ///< the initial singularity
  vertex_descriptor target;                  ///< the terminal singularity
  int source_valence = 0;                    ///< valence of the initial singularity before the Q-zip
  int target_valence = 0;                    ///< valence of the terminal singularity before the Q-zip
  Strip_operation initial_operation = Strip_operation::LEFT_SPLIT; ///< the motion: the compass at the source
  std::vector<vertex_descriptor> sketch;     ///< the path given to the planner, from `source` to `target`
  std::vector<vertex_descriptor> path;       ///< the adjusted path the surgery follows
  std::vector<Strip_operation> operations;   ///< one per vertex of `path`, the last is `NO_OPERATION`
  Plan_status status = Plan_status::INVALID_PATH; ///< whether the plan is realizable, or why not
  /// when `status` is `EXECUTION_WOULD_FAIL`: why the simulated execution failed (as `Qzip_result::failure`)
  Execution_failure predicted_failure = Execution_failure::NONE;
  /// when `status` is `EXECUTION_WOULD_FAIL`: the index in `path` of the vertex where it failed (as
  /// `Qzip_result::failed_step`)
  std::size_t predicted_failed_step = 0;

  /// an atomic operation named by vertices (see `prelude`)
  struct Atomic_operation
  {
    vertex_descriptor v; ///< the vertex the collapse keeps, or the vertex split
    vertex_descriptor b; ///< the collapse removes the quad on the left of `b->v`; the split delimits its fan by `b->v`
    vertex_descriptor d; ///< `null_vertex()` for a collapse; for a split, the other delimiter `d->v`
  };
  /// a vertex of `path` that the execution itself creates (see `created_vertices`)
  struct Created_vertex
  {
    std::size_t index; ///< its position in `path`, where `path[index]` is `null_vertex()`
    /// the split that makes it: the position in `path` of the vertex split by the chain (less than
    /// `index`), or `path.size() + m` for the split `prelude[m]`
    std::size_t split;
    /// `true` for the vertex the split creates (the copy on the left of the path edge
    /// `path[split] -> path[split + 1]` for a chain split), `false` for the split vertex itself
    /// (the copy on the right, which keeps its descriptor but now takes another part)
    bool new_vertex;
  };
  /// reverse plans only (see `reverse_qzip()`), empty otherwise: atomic operations performed before
  /// the chain, in this order (they undo the clean-up of the Q-zip that the plan reverses)
  std::vector<Atomic_operation> prelude;
  /// reverse plans only, empty otherwise: the vertices of `path` that do not exist before the
  /// execution (the Q-zip that the plan reverses merged them away), by increasing `index`
  std::vector<Created_vertex> created_vertices;
  /// reverse plans only, empty otherwise: the number of faces that border vertices should have, as the
  /// Q-zip that the plan reverses judged them (from the geometry before it); the execution judges their
  /// defects with these numbers, whatever the rough placement of that Q-zip did to the border angles
  std::vector<std::pair<vertex_descriptor, int> > expected_faces;

  /// `true` when `status` is `REALIZABLE`.
  bool is_realizable() const { return status == Plan_status::REALIZABLE; }
  /// the number of quad collapses the prelude and the chain perform (before any clean-up).
  std::size_t number_of_collapses() const
  {
    std::size_t n = 0;
    for(const Atomic_operation& a : prelude) if(a.d == boost::graph_traits<PolygonMesh>::null_vertex()) ++n;
    for(Strip_operation op : operations) if(is_collapse(op)) ++n;
    return n;
  }
  /// the number of vertex splits the prelude and the chain perform (before any clean-up).
  std::size_t number_of_splits() const
  {
    std::size_t n = 0;
    for(const Atomic_operation& a : prelude) if(a.d != boost::graph_traits<PolygonMesh>::null_vertex()) ++n;
    for(Strip_operation op : operations) if(is_split(op)) ++n;
    return n;
  }
};

namespace internal {

template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap>
class Chain_simulation; // internal/chain_simulation.h, included at the end of this file

enum class Turn { LEFT = 1, STRAIGHT = 0, RIGHT = -1 };

// whether the border gap lies among the faces crossed turning counterclockwise from the outgoing
// halfedge `from` to `to` (same source)
template <typename PolygonMesh>
bool crosses_border(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor from,
                    typename boost::graph_traits<PolygonMesh>::halfedge_descriptor to, const PolygonMesh& pm)
{
  for(; from != to; from = ccw(from, pm))
    if(is_border(from, pm)) return true;
  return false;
}

// the compass transport through path vertex v (coming from u, leaving to w): the paper's Sec. 2.5 rule,
// with the counts taken in the mesh before execution. After LS or RC the rule counts the quads on the
// left of the path, after RS or LC those on its right: one is a turn towards that side, two is straight,
// three or more a turn away. At a vertex on the border the quads are counted on the side of the mesh,
// whatever the tag: the side of the border gap has no quads to count, and treating it as regular gives
// the same turn (at a regular vertex, interior or on the border, this is the geometric turn).
template <typename PolygonMesh>
Turn compass_turn(typename boost::graph_traits<PolygonMesh>::vertex_descriptor u,
                  typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                  typename boost::graph_traits<PolygonMesh>::vertex_descriptor w,
                  Strip_operation previous, const PolygonMesh& pm)
{
  const auto o = halfedge(v, w, pm).first;
  const auto i = halfedge(v, u, pm).first;
  const int q_left = ccw_steps(o, i, pm);
  const int q_right = int(valence(v, pm)) - q_left;
  bool count_left = previous == Strip_operation::LEFT_SPLIT || previous == Strip_operation::RIGHT_COLLAPSE;
  if(count_left ? crosses_border(o, i, pm) : crosses_border(i, o, pm)) count_left = !count_left;
  if(count_left)
    return q_left == 1 ? Turn::LEFT : (q_left == 2 ? Turn::STRAIGHT : Turn::RIGHT);
  return q_right == 1 ? Turn::RIGHT : (q_right == 2 ? Turn::STRAIGHT : Turn::LEFT);
}

// the halfedge whose face a collapse tag collapses at the path edge o = v->w, keeping w (see
// Chain_executor): RC the quad on the left of o (face(o)), LC the one on its right; its far corner
// target(next(next(h))) is the vertex merged away
template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
collapsed_quad(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor o, Strip_operation op,
               const PolygonMesh& pm)
{
  CGAL_precondition(is_collapse(op));
  return op == Strip_operation::RIGHT_COLLAPSE ? o : prev(opposite(o, pm), pm);
}

template <typename PolygonMesh>
void transport_compass(const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& path,
                       std::vector<Strip_operation>& ops, std::size_t from, const PolygonMesh& pm)
{
  for(std::size_t j = from; j + 1 < path.size(); ++j)
  {
    Strip_operation prev = ops[j - 1];
    if(prev == Strip_operation::NO_OPERATION) continue; // only at an adjusted start, already tagged
    const Turn t = compass_turn(path[j - 1], path[j], path[j + 1], prev, pm);
    ops[j] = rotate(prev, int(t));
  }
}

template <typename PolygonMesh>
bool is_simple_edge_path(const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& path,
                         const PolygonMesh& pm)
{
  if(path.size() < 2) return false;
  if(path.size() <= 32) // most paths: comparing every pair costs less than sorting a copy
  {
    for(std::size_t j = 1; j < path.size(); ++j)
      if(std::find(path.begin(), path.begin() + j, path[j]) != path.begin() + j) return false;
  }
  else
  {
    std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> sorted(path);
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  }
  for(std::size_t j = 0; j + 1 < path.size(); ++j)
    if(!halfedge(path[j], path[j + 1], pm).second) return false;
  return true;
}

// A split gives each of its two delimiters one more edge. Where the chain starts (S3) or ends (E2) with
// a split delimited by the vertex `e` at the end of the path, an interior v5 `e` becomes a valence-6
// vertex (two v5 merged), which the clean-up splits between two opposite neighbours, both interior of
// valence 4, which become the two v5 (Chain_executor::split_valence_6()). The ring of `e` after the
// chain is its ring before, r0 = `split_vertex`, r1, ..., r4 (in either rotation), in which r0 became
// two vertices (the copies of the split): whichever side of r0 the new copy lies on, the three pairs
// of opposite neighbours are (r1, r4) and two pairs containing r2 and r3 respectively. The split changes
// the valences of the split vertex and its two delimiters only; when none of r1..r4 is a path vertex or
// next to a path vertex other than `e` and `split_vertex`, the earlier operations do not reach them
// either, and the clean-up is impossible exactly when neither r2 nor r3 is an interior vertex of
// valence 4, and r1 and r4 are not both. (test_qzip forces every plan refused so through the executor:
// each one fails in the clean-up.)
template <typename PolygonMesh>
bool leaves_valence_6_without_cleanup(typename boost::graph_traits<PolygonMesh>::vertex_descriptor e,
                                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor split_vertex,
                                      const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& path,
                                      const PolygonMesh& pm)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  if(is_border_vertex(e, pm) || valence(e, pm) != 5) return false;
  std::vector<vertex_descriptor> ring; // r0 = split_vertex, then around e
  for(auto h : halfedges_around_target(halfedge(split_vertex, e, pm).first, pm)) ring.push_back(source(h, pm));
  for(std::size_t k = 1; k < ring.size(); ++k)
    for(vertex_descriptor p : path)
      if(p != e && (p == ring[k] || (p != split_vertex && halfedge(p, ring[k], pm).second))) return false;
  auto regular = [&pm](vertex_descriptor v) { return !is_border_vertex(v, pm) && valence(v, pm) == 4; };
  return !regular(ring[2]) && !regular(ring[3]) && !(regular(ring[1]) && regular(ring[4]));
}

// plan_qzip() with its parameters read: a template on their types, not on the pack, so that packs that
// differ in other parameters share one planner
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap,
          typename GeomTraits>
Surgery_plan<PolygonMesh>
plan_qzip_with(const PolygonMesh& pm,
               const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& sketch,
               Strip_operation initial_operation, const VertexPointMap& vpm, const EdgeIsConstrainedMap& ecm,
               const FaceIsConstrainedMap& fcm, const GeomTraits& gt, bool simulate)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  CGAL_precondition(initial_operation != Strip_operation::NO_OPERATION);

  Surgery_plan<PolygonMesh> plan;
  plan.sketch = sketch;
  plan.initial_operation = initial_operation;
  if(!internal::is_simple_edge_path(sketch, pm)) { plan.status = Plan_status::INVALID_PATH; return plan; }
  auto on_feature = [&](vertex_descriptor v) { return internal::is_on_constrained_edge(v, pm, ecm); };
  auto on_cut = [&](vertex_descriptor v) { return internal::is_border_vertex(v, pm) || on_feature(v); };
  // a border (or feature) source: the chain starts inside, so this is the plan of the reversed sketch, and
  // `initial_operation` is the compass at its start, the interior singularity sketch.back()
  if(on_cut(sketch.front()) && !on_cut(sketch.back()))
    return plan_qzip_with(pm, std::vector<vertex_descriptor>(sketch.rbegin(), sketch.rend()), initial_operation, vpm, ecm,
                          fcm, gt, simulate);
  plan.source = sketch.front();
  plan.target = sketch.back();
  plan.source_valence = int(internal::valence(plan.source, pm));
  plan.target_valence = int(internal::valence(plan.target, pm));
  if((plan.source_valence != 3 && plan.source_valence != 5) || on_cut(plan.source))
  { plan.status = Plan_status::UNSUPPORTED_ENDPOINT; return plan; }
  // a border target is supported on a straight piece of border (two quads expected, three present);
  // its defect moves to a border neighbour on a straight piece too, or cancels the defect of a
  // neighbour with one quad (checked after the preparation)
  auto defect_and_expected_faces = [&](vertex_descriptor v)
  {
    const internal::Vertex_defect_info info = internal::vertex_defect_info(v, pm, vpm, ecm, gt);
    return std::make_pair(info.defect, info.expected_faces);
  };
  const bool border_target = internal::is_border_vertex(plan.target, pm);
  // a feature target (interior, on a constrained edge) is judged in the sector its last sketch edge
  // arrives in (see `feature_end_sector` below): the other sectors must be regular
  const bool feature_target = !border_target && on_feature(plan.target);
  const std::pair<int, int> target_defect = border_target ? defect_and_expected_faces(plan.target) : std::make_pair(0, 0);
  bool quad_too_few = target_defect.first == -1;
  const bool target_supported = border_target ? internal::Endpoint_preparation<PolygonMesh>::is_supported_border_end(
                                                  target_defect.first, target_defect.second)
                                              : (feature_target || plan.target_valence == 3 || plan.target_valence == 5);
  if(!target_supported) { plan.status = Plan_status::UNSUPPORTED_ENDPOINT; return plan; }
  // the faces of the sector of the feature target that the path arrives in, and the defect of that sector
  // (faces, expected faces); the path may not arrive along a constrained edge
  std::vector<face_descriptor> feature_end_sector;
  auto sector_of_feature_end = [&](vertex_descriptor u, vertex_descriptor t, std::pair<int, int>& defect)
  {
    const auto ut = halfedge(u, t, pm).first;
    if(get(ecm, edge(ut, pm))) return Plan_status::ENDPOINT_ADJUSTMENT;
    feature_end_sector.clear();
    const internal::Sector_info sector = internal::sector_info(ut, pm, vpm, ecm, gt,
                                                               [&](face_descriptor f) { feature_end_sector.push_back(f); });
    defect = std::make_pair(sector.faces - sector.expected_faces, sector.expected_faces);
    if(!sector.bounded || defect_and_expected_faces(t).first != defect.first ||
       !internal::Endpoint_preparation<PolygonMesh>::is_supported_border_end(defect.first, defect.second))
      return Plan_status::UNSUPPORTED_ENDPOINT;
    return Plan_status::REALIZABLE;
  };

  plan.path = sketch;
  plan.operations.assign(sketch.size(), Strip_operation::NO_OPERATION);
  plan.operations[0] = initial_operation;
  internal::transport_compass(plan.path, plan.operations, 1, pm);

  // Start first: a v3 start with a collapse re-routes the first edges (n, d, v1), which may fold back
  // (d -> v1 -> d when the sketch turns towards the collapse); folds are removed and the compass is
  // transported again after them, on the new incoming edges (this matters where a vertex is irregular).
  // Then the end, with the tag that reaches it. On a one-edge path the end rule may turn the start tag
  // into a split (v5 end with a collapse), and the start rule for splits applies then.
  internal::Endpoint_preparation<PolygonMesh> prep(pm);
  auto transport = [&pm](vertex_descriptor u, vertex_descriptor v, vertex_descriptor w, Strip_operation prev)
  { return rotate(prev, int(internal::compass_turn(u, v, w, prev, pm))); };
  std::size_t retransport_from = 0, first_fold = 0;
  Plan_status st = prep.prepare_start(plan.path, plan.operations, retransport_from);
  if(st == Plan_status::REALIZABLE) st = prep.remove_folds(plan.path, plan.operations, first_fold);
  if(st == Plan_status::REALIZABLE && retransport_from > 0)
    internal::transport_compass(plan.path, plan.operations, (std::min)(retransport_from, first_fold + 1), pm);
  const Strip_operation start_tag = plan.operations[0];
  if(st == Plan_status::REALIZABLE && feature_target)
  {
    std::pair<int, int> sector_defect;
    st = sector_of_feature_end(plan.path[plan.path.size() - 2], plan.target, sector_defect);
    quad_too_few = sector_defect.first == -1;
    auto outside_sector = [&](auto h)
    {
      return is_border(h, pm) ||
             std::find(feature_end_sector.begin(), feature_end_sector.end(), face(h, pm)) == feature_end_sector.end();
    };
    if(st == Plan_status::REALIZABLE)
      st = prep.prepare_sector_end(plan.path, plan.operations, quad_too_few, sector_defect.second, outside_sector);
  }
  else if(st == Plan_status::REALIZABLE)
    st = border_target ? prep.prepare_border_end(plan.path, plan.operations, quad_too_few, target_defect.second)
                       : prep.prepare_end(plan.path, plan.operations, initial_operation, transport);
  if(st == Plan_status::REALIZABLE && plan.path[0] == plan.source && plan.operations[0] != start_tag &&
     is_split(plan.operations[0]))
    st = prep.prepare_start(plan.path, plan.operations, retransport_from);
  if(st == Plan_status::REALIZABLE) st = prep.remove_folds(plan.path, plan.operations, first_fold);
  if(st == Plan_status::REALIZABLE && (border_target || feature_target) && !quad_too_few)
  {
    const std::pair<int, int> e = defect_and_expected_faces(plan.path.back()); // regular, or one quad short: cancels
    if(e.first != 0 && e.first != -1) st = Plan_status::ENDPOINT_ADJUSTMENT;
  }
  if(st == Plan_status::REALIZABLE && !internal::is_simple_edge_path(plan.path, pm))
    st = Plan_status::NOT_SIMPLE_AFTER_ADJUSTMENT;
  // a split is delimited by the guide that the operation before it leaves (Chain_executor): the first
  // operation has none, and the execution would stop there. The start rules give the first vertex a
  // collapse or a no-operation, but its tag may be rotated into a split afterwards: by the removal of a
  // fold at the start of a re-routed path (n -> d -> n) or by the end rule of a short path.
  if(st == Plan_status::REALIZABLE && is_split(plan.operations[0]))
    st = Plan_status::SPLIT_WITHOUT_GUIDE;
  if(st != Plan_status::REALIZABLE) { plan.status = st; return plan; }

  // every vertex the chain operates on is a path vertex or one of its neighbours: keep the path away
  // from features and protected faces. Inner path vertices may lie on the border (a path along the
  // border); the ends and the adjustment vertices are interior, apart from a border target and its
  // continuation.
  // (faces that are not quads may be next to the path: no collapse is ever attempted on them, splits
  // keep their degree, and the executor checks every operation)
  // A feature target and its continuation lie on constrained edges (the executor keeps every constrained
  // edge whole, on one copy of a split vertex).
  for(vertex_descriptor v : plan.path)
  {
    const bool feature_end = feature_target && (v == plan.target || v == plan.path.back());
    for(auto h : halfedges_around_target(halfedge(v, pm), pm))
      if((!feature_end && get(ecm, edge(h, pm))) || (!is_border(h, pm) && get(fcm, face(h, pm))))
      { plan.status = Plan_status::BORDER_OR_CONSTRAINED; return plan; }
  }
  // each collapse, as far as the mesh before execution tells (the executor refuses these collapses
  // anyway, but only after the chain has started): at a path vertex on the border it must be on the side
  // of the mesh; its far corner (the vertex merged away) may not be a vertex the path has still to visit
  // (most such plans come from the S2 re-routing of a v3 start), nor touch a constrained edge or a
  // protected face; it may lie on the border only where the path leaves the border (path[j] on the
  // border, the kept path[j + 1] inside: the merged vertex takes the place of the far corner there).
  // Elsewhere, e.g. a collapse towards the border along a path one edge away from it, the collapses would
  // pull the border onto the path and leave border defects.
  for(std::size_t j = 0; j + 1 < plan.path.size(); ++j)
  {
    if(!is_collapse(plan.operations[j])) continue;
    const auto h = internal::collapsed_quad(halfedge(plan.path[j], plan.path[j + 1], pm).first, plan.operations[j], pm);
    if(is_border(h, pm)) { plan.status = Plan_status::BORDER_FACE_COLLAPSE; return plan; }
    const vertex_descriptor far_corner = target(next(next(h, pm), pm), pm);
    if(std::find(plan.path.begin() + std::ptrdiff_t(j + 1), plan.path.end(), far_corner) != plan.path.end())
    { plan.status = Plan_status::PATH_WOULD_COLLAPSE; return plan; }
    bool far_on_border = false;
    for(auto hc : halfedges_around_target(halfedge(far_corner, pm), pm))
    {
      if(is_border(hc, pm)) far_on_border = true;
      else if(get(ecm, edge(hc, pm)) || get(fcm, face(hc, pm)))
      { plan.status = Plan_status::BORDER_OR_CONSTRAINED; return plan; }
    }
    if(far_on_border && (!internal::is_border_vertex(plan.path[j], pm) || internal::is_border_vertex(plan.path[j + 1], pm)))
    { plan.status = Plan_status::BORDER_OR_CONSTRAINED; return plan; }
  }
  // E1: the last operation gives an interior v3 target one more edge, and the last guide's target is the moved
  // v3. After a split or a no-operation that is a path vertex (checked above); after a collapse it is the near
  // corner of the collapsed quad, the one next to `t` but `u`, which loses a face. On a feature it takes the -1:
  // the executor refuses that, unless it cancels a +1 in that sector. (A moved v3 on the border is left to the
  // simulation: refusing it here changed the optimizer's results on a mesh with borders, untested.)
  const std::size_t n = plan.path.size();
  if(!border_target && !feature_target && plan.target_valence == 3 && plan.path.back() == plan.target &&
     is_collapse(plan.operations[n - 2]))
  {
    const auto h = internal::collapsed_quad(halfedge(plan.path[n - 2], plan.target, pm).first, plan.operations[n - 2], pm);
    const auto into_moved_v3 = plan.operations[n - 2] == Strip_operation::RIGHT_COLLAPSE ? next(h, pm) : prev(h, pm);
    const vertex_descriptor moved_v3 = target(into_moved_v3, pm);
    if(on_feature(moved_v3) && !internal::is_border_vertex(moved_v3, pm) &&
       !internal::loses_a_face_to_regular(into_moved_v3, pm, vpm, ecm, gt))
    { plan.status = Plan_status::BORDER_OR_CONSTRAINED; return plan; }
  }
  // a feature target at the end of its curve (one constrained edge): its one sector is bounded on both sides by
  // that edge, the border rules read in it find no gap, and the chain would leave `t` singular and create an
  // interior v3 (refused once prepared, so that the plan shows what the executor would be given)
  if(feature_target && internal::number_of_constrained_edges(plan.target, pm, ecm) == 1)
  { plan.status = Plan_status::UNSUPPORTED_ENDPOINT; return plan; }
  // a v5 at an end of the path that a split delimits and that the clean-up could not split again
  if(n >= 3 && plan.operations[0] == Strip_operation::NO_OPERATION && is_split(plan.operations[1]) &&
     internal::leaves_valence_6_without_cleanup(plan.path[0], plan.path[1], plan.path, pm))
  { plan.status = Plan_status::VALENCE_6_LEFT; return plan; }
  if(n >= 2 && is_split(plan.operations[n - 2]) &&
     internal::leaves_valence_6_without_cleanup(plan.path[n - 1], plan.path[n - 2], plan.path, pm))
  { plan.status = Plan_status::VALENCE_6_LEFT; return plan; }
  if(plan.number_of_collapses() + plan.number_of_splits() == 0) { plan.status = Plan_status::NOTHING_TO_DO; return plan; }
  plan.status = Plan_status::REALIZABLE;
  if(simulate)
  {
    // the copy's buffers are kept from plan to plan
    static thread_local Chain_simulation<PolygonMesh, VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap> simulation;
    const auto s = simulation.run(pm, plan, vpm, ecm, fcm);
    if(s.failure != Execution_failure::NONE)
    {
      plan.status = Plan_status::EXECUTION_WOULD_FAIL;
      plan.predicted_failure = s.failure;
      plan.predicted_failed_step = s.failed_step;
    }
  }
  return plan;
}

} // namespace internal

/*!
\ingroup PkgQzipPrimitive

plans a Q-zip along `sketch`, a simple edge path from the initial singularity `sketch.front()` (an
interior vertex of valence 3 or 5) to the terminal singularity `sketch.back()` (the same, or a border
vertex with one quad too many on a straight piece of border or at a corner, whose defect then moves by
one border edge, or with one quad too few on a straight piece of border, reached along the border, or at
a concave corner; see the user manual, "Border End Points"; or a feature defect: a vertex of a constrained edge,
away from the border and not at the end of its curve (a single constrained edge), with one quad too many or too few in the sector between two constrained edges that the
last edge of the sketch arrives in, its other sectors regular, prepared like a border end in that sector, see
the user manual, "Feature End Points"), with `initial_operation` as the compass at
the initial singularity (one of the four motions of the pair). When `sketch.front()` is such a border
(or feature) vertex and `sketch.back()` an interior one, the plan is that of the reversed sketch: the chain starts at
the interior singularity (`plan.source == sketch.back()`), and `initial_operation` is the compass there.

The compass is parallel-transported along the path (paper, Sec. 2.5): straight keeps the tag, a left
(right) turn takes the next counterclockwise (clockwise) tag, and at an irregular vertex the turn is
decided by the number of quads on the left of the path (after LS or RC) or on its right (after RS or LC):
one is a turn towards that side, two is straight, three or more a turn away; at a path vertex on the
border the quads are counted on the side of the mesh (the inner vertices of `sketch` may lie on the
border: see the user manual, "Paths Along the Border"). The ends are then prepared within the one-rings
of the two singularities (Sec. 2.6; for a border target, see the user manual, "Border End Points"), folds
created by the preparation are removed, and the plan is checked against the border (no collapse on the
side of the border), constrained edges and protected faces. Finally the execution itself (the chain, the
clean-up of Sec. 2.7 and the check that no singularity was created, exactly as `execute_qzip()` does it)
is simulated on a copy of the neighbourhood of the path (the faces around the vertices at most three
edges away from it): a plan whose execution would fail is refused (`EXECUTION_WOULD_FAIL`, with the reason in
`plan.predicted_failure`), so that a realizable plan is one that `execute_qzip()` carries out.
The mesh is not modified.

\tparam PolygonMesh a model of `FaceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the polygon mesh
\param sketch the path, as the sequence of its vertices
\param initial_operation the compass tag at the initial singularity
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{edge_is_constrained_map}
    \cgalParamDescription{feature edges: no path vertex may be incident to one, but a feature target and its
                          continuation along the feature}
    \cgalParamDefault{no edge is constrained}
  \cgalParamNEnd
  \cgalParamNBegin{face_is_constrained_map}
    \cgalParamDescription{protected faces: no path vertex may be incident to one}
    \cgalParamDefault{no face is protected}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{the positions, used for the defect of a border target (see `vertex_defect()`) and
                          copied for the simulation}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
  \cgalParamNEnd
  \cgalParamNBegin{simulate_chain}
    \cgalParamDescription{whether a plan that passes the local checks is also simulated on a copy of the
                          neighbourhood of its path. The simulation costs about two executions of the plan;
                          without it, `plan_qzip()` costs about a microsecond, and a few plans it calls
                          realizable are rolled back by `execute_qzip()` (with new descriptors for the elements
                          the roll-back re-creates).}
    \cgalParamType{Boolean}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
\cgalNamedParamsEnd
\returns the plan; `plan.status` says whether it is realizable, or why not (`execute_qzip()` still checks
         every operation before applying it, and rolls back what it did when one fails).
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Surgery_plan<PolygonMesh>
plan_qzip(const PolygonMesh& pm,
          const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& sketch,
          Strip_operation initial_operation,
          const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  const auto fcm = choose_parameter(get_parameter(np, Qzip::internal_np::face_is_constrained),
                                    Static_boolean_property_map<face_descriptor, false>());
  const bool simulate = choose_parameter(get_parameter(np, Qzip::internal_np::chain_simulation), true);
  return internal::with_defect_parameters(pm, np, [&](const auto& vpm, const auto& ecm, const auto& gt)
  {
    return internal::plan_qzip_with(pm, sketch, initial_operation, vpm, ecm, fcm, gt, simulate);
  });
}

/*!
\ingroup PkgQzipPrimitive
plans a Q-zip along a path given by its halfedges: `path[i]` goes from the `i`-th vertex of the path to
the next one, so the initial singularity is `source(path.front(), pm)` and the terminal one
`target(path.back(), pm)`. Same as `plan_qzip()` on the vertices of the path; a sequence of halfedges that
do not follow each other gives a plan with status `INVALID_PATH`.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Surgery_plan<PolygonMesh>
plan_qzip(const PolygonMesh& pm,
          const std::vector<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>& path,
          Strip_operation initial_operation,
          const NamedParameters& np = parameters::default_values())
{
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vertices;
  for(std::size_t i = 0; i < path.size(); ++i)
  {
    if(i > 0 && source(path[i], pm) != target(path[i - 1], pm))
    {
      Surgery_plan<PolygonMesh> plan;
      plan.initial_operation = initial_operation;
      return plan; // INVALID_PATH
    }
    if(i == 0) vertices.push_back(source(path[i], pm));
    vertices.push_back(target(path[i], pm));
  }
  return plan_qzip(pm, vertices, initial_operation, np);
}

/*!
\ingroup PkgQzipPrimitive
plans the four motions of the pair joined by `sketch`: one plan per initial operation, in the order
`LEFT_SPLIT`, `RIGHT_COLLAPSE`, `LEFT_COLLAPSE`, `RIGHT_SPLIT`. Same parameters as `plan_qzip()`.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
std::array<Surgery_plan<PolygonMesh>, 4>
plan_qzip_motions(const PolygonMesh& pm,
                  const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& sketch,
                  const NamedParameters& np = parameters::default_values())
{
  std::array<Surgery_plan<PolygonMesh>, 4> plans;
  for(int m = 0; m < 4; ++m)
    plans[std::size_t(m)] = plan_qzip(pm, sketch, Strip_operation(m), np);
  return plans;
}

} // namespace Qzip
} // namespace CGAL

#include <CGAL/Qzip/internal/chain_simulation.h> // after the plan: the simulation runs the executor on it

#endif // CGAL_QZIP_SURGERY_PLAN_H
