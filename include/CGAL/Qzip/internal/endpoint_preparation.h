// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_ENDPOINT_PREPARATION_H
#define CGAL_QZIP_INTERNAL_ENDPOINT_PREPARATION_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/strip_operation.h>
#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/internal/rotation.h>

#include <boost/graph/graph_traits.hpp>

#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// The end-point adjustments of the paper's Sec. 2.6, at halfedge level (see the user manual for the
// diagrams). `path` is the sketch and `ops[j]` the transported compass tag at `path[j]`; both are
// rewritten in place. Adjustment vertices must be interior vertices. Returns REALIZABLE or
// the reason for refusing.
template <typename PolygonMesh>
class Endpoint_preparation
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef std::vector<vertex_descriptor> Path;
  typedef std::vector<Strip_operation> Operations;

  const PolygonMesh& pm;

  // adjustment vertices may be singular (the surgery may then cancel that singularity, which the
  // executor accepts) but must be interior
  bool is_usable(vertex_descriptor v) const { return !is_border_vertex(v, pm); }

  halfedge_descriptor out(vertex_descriptor a, vertex_descriptor b) const { return halfedge(a, b, pm).first; }

  // the two other corners of the quad on the left (or right) of the edge a->b: `near_b` next to b and
  // `near_a` next to a (left: face(a->b) = (a, b, near_b, near_a); right: face(b->a) = (b, a, near_a, near_b));
  // false when that face is the border or not a quad
  bool side_quad_corners(halfedge_descriptor ab, bool left, vertex_descriptor& near_b, vertex_descriptor& near_a) const
  {
    const halfedge_descriptor side = left ? ab : opposite(ab, pm);
    if(is_border(side, pm) || !is_quad(side, pm)) return false;
    const halfedge_descriptor h = next(side, pm);
    near_b = left ? target(h, pm) : target(next(h, pm), pm);
    near_a = left ? target(next(h, pm), pm) : target(h, pm);
    return true;
  }

public:
  explicit Endpoint_preparation(const PolygonMesh& pm) : pm(pm) {}

  // E1-E3: v3 end: nothing; v5 end with a split: one more edge to the farthest neighbour on the
  // other side (ccw index 2 or 3 from the incoming edge), t becomes a split vertex; v5 end with a
  // collapse: the last edge u->t is replaced by u->n->x around the quad on that side.
  // `start_compass` is the compass at the start, used when a one-edge path starts with a no-operation.
  template <typename TransportTurn>
  Plan_status prepare_end(Path& path, Operations& ops, Strip_operation start_compass,
                          const TransportTurn& transport) const
  {
    const std::size_t n = path.size();
    const vertex_descriptor t = path[n - 1], u = path[n - 2];
    const Strip_operation last = (n == 2 && ops[0] == Strip_operation::NO_OPERATION) ? start_compass : ops[n - 2];
    if(valence(t, pm) == 3) return Plan_status::REALIZABLE;
    const halfedge_descriptor ut = out(u, t);
    switch(last)
    {
      case Strip_operation::LEFT_SPLIT:
      case Strip_operation::RIGHT_SPLIT:
      {
        const vertex_descriptor e =
          target(rotate_outgoing(out(t, u), last == Strip_operation::LEFT_SPLIT ? 2 : 3, pm), pm);
        if(!is_usable(e)) return Plan_status::ENDPOINT_ADJUSTMENT;
        path.push_back(e);
        ops.push_back(Strip_operation::NO_OPERATION); // the new end: no operation
        ops[n - 1] = transport(u, t, e, last);
        return Plan_status::REALIZABLE;
      }
      case Strip_operation::LEFT_COLLAPSE:
      case Strip_operation::RIGHT_COLLAPSE:
      {
        const bool left = last == Strip_operation::LEFT_COLLAPSE;
        // LC: face(u->t) = (u, t, x, n); RC: face(t->u) = (t, u, n, x)
        vertex_descriptor x, nb;
        if(!side_quad_corners(ut, left, x, nb)) return Plan_status::BORDER_OR_CONSTRAINED;
        if(!is_usable(x) || !is_usable(nb)) return Plan_status::ENDPOINT_ADJUSTMENT;
        if(n >= 4 && path[n - 3] == nb && path[n - 4] == x)
          return prepare_end_without_u_turn(path, ops, start_compass, transport);
        path.back() = nb;
        path.push_back(x);
        ops[n - 2] = left ? Strip_operation::RIGHT_SPLIT : Strip_operation::LEFT_SPLIT;
        ops.push_back(Strip_operation::NO_OPERATION);
        ops[n - 1] = last;
        return Plan_status::REALIZABLE;
      }
      default:
        return Plan_status::INVALID_PATH;
    }
  }

  // The sketch arrives at t around the quad G that E3 collapses, x -> nb -> u -> t: the continuation
  // u -> nb -> x would walk back along the path, and the folds it makes would take t off the chain. The
  // arrival x -> t over G is homotopic to it (G lies between them): the U-turn is replaced by that edge,
  // the compass is transported to it, and the end is prepared again. When the compass cannot be carried
  // to x -> t (x follows a no-operation and is not regular) the plan is refused.
  template <typename TransportTurn>
  Plan_status prepare_end_without_u_turn(Path& path, Operations& ops, Strip_operation start_compass,
                                         const TransportTurn& transport) const
  {
    const std::size_t i = path.size() - 4; // path[i] = x
    const vertex_descriptor x = path[i], nb = path[i + 1], t = path.back();
    path.erase(path.begin() + long(i) + 1, path.begin() + long(i) + 3);
    ops.erase(ops.begin() + long(i) + 1, ops.begin() + long(i) + 3);
    if(i > 0 && ops[i - 1] != Strip_operation::NO_OPERATION)
      ops[i] = transport(path[i - 1], x, t, ops[i - 1]);
    else if(ops[i] != Strip_operation::NO_OPERATION && valence(x, pm) == 4 && is_usable(x))
      ops[i] = rotate(ops[i], ccw_steps(out(x, nb), out(x, t), pm)); // the compass at x keeps its orientation
    else
      return Plan_status::ENDPOINT_ADJUSTMENT;
    return prepare_end(path, ops, start_compass, transport);
  }

  // The border ends supported: a border vertex with one quad too many or too few, on a straight piece of
  // border (two quads expected) or at a concave corner (three quads expected), or with one quad too many
  // at a convex corner (one quad expected; it cannot have one too few).
  static bool is_supported_border_end(int defect, int expected_faces)
  {
    return (defect == 1 && expected_faces >= 1 && expected_faces <= 3) ||
           (defect == -1 && (expected_faces == 2 || expected_faces == 3));
  }

  // A border end t with one quad too many (defect +1; a border end with one quad too few cannot be
  // reached through interior vertices). The chain goes on by one border edge t->e and t becomes a
  // split vertex, which hands the defect to e. After LS or RC (the tags that count quads on the left),
  // e is the border neighbour such that t->e has no face; after LC or RS, the one such that e->t has no
  // face. And the path must arrive at t next to that border edge after a collapse (e is the first
  // neighbour counterclockwise from u after RC, the last one after LC), with one edge between them
  // after a split. Rules found by enumerating every one-edge continuation and every tag on planted grids
  // and real meshes (user manual, "Border End Points"); other arrivals are refused.
  //
  // Arriving along the border (u->t a border edge), the chain goes on straight along the border to the
  // other border neighbour e of t, and only after the split that inserts its strip on the side of the
  // mesh (LS with the mesh on the left of u->t, RS with it on the right): t gets the same split, which
  // hands the defect to e. After the other tags no continuation moved the defect (enumerated likewise).
  //
  // A border end t with one quad too few (defect -1, a single quad) is reached along the border only;
  // the path ends there, as at an interior v3 (E1), after the split that inserts its strip on the side
  // of the border (RS with the mesh on the left of u->t, LS with it on the right). Found by enumeration
  // too: after the two collapses the chain often fails, after the other split it mostly does.
  //
  // At a concave corner (`expected_faces` 3, found by the same enumeration on L-shaped grids): with one
  // quad too many (four quads, valence 5), the collapses are handled as on a straight border, and after
  // a split e is the neighbour two steps from u on the side of the split (counterclockwise index 2 after
  // LS, valence - 2 after RS), whichever side of it the gap lies, and t repeats the split, which hands its
  // extra quad to e: e is a border neighbour (the defect moves or cancels), or an interior vertex of
  // valence 3 (it becomes regular: the defects cancel; an interior e of another valence would become
  // singular and is refused); with one quad too few (two quads, valence 3), the path arrives from the
  // interior neighbour after a collapse and ends at t (E1), or along the border as on a straight border
  // (after the split on the side of the gap). Arrivals along the border at a concave +1, and from the
  // interior neighbour after a split at a concave -1, are refused.
  // At a convex corner with one quad too many (two quads, valence 3) the path arrives from the interior
  // neighbour after a collapse, and the rule of a straight border applies; or along the border after the
  // split on the side of the border gap (RS with the mesh on the left of u->t, LS with it on the right: the
  // opposite of a straight border; after the split on the side of the mesh the chain always leaves a new
  // singularity), and goes on along the border to e as on a straight border. After a split from the
  // interior neighbour no continuation moved the defect: refused.
  //
  // A feature end (a vertex of a constrained edge) is prepared by the same rules in the sector of its fan
  // that the path arrives in (prepare_sector_end()): the other sectors play the part of the border gap,
  // and the constrained edges that bound the sector that of the border edges. plan_qzip() refuses feature
  // ends reached along a constrained edge, so only the rules for arrivals from the inside apply there.
  Plan_status prepare_border_end(Path& path, Operations& ops, bool quad_too_few, int expected_faces) const
  {
    return prepare_sector_end(path, ops, quad_too_few, expected_faces,
                              [this](halfedge_descriptor h) { return is_border(h, pm); });
  }

  // the same, where `gap(h)` tells whether `face(h)` lies outside the fan of the end (the border face, or a
  // face of another sector)
  template <typename Gap>
  Plan_status prepare_sector_end(Path& path, Operations& ops, bool quad_too_few, int expected_faces,
                                 const Gap& gap) const
  {
    auto is_cut = [&](halfedge_descriptor h) { return gap(h) || gap(opposite(h, pm)); };
    const std::size_t n = path.size();
    const vertex_descriptor t = path[n - 1], u = path[n - 2];
    const Strip_operation last = ops[n - 2];
    if(last == Strip_operation::NO_OPERATION) return Plan_status::ENDPOINT_ADJUSTMENT;
    const halfedge_descriptor ut = out(u, t);
    const bool concave = expected_faces == 3, convex = expected_faces == 1;
    if(concave && is_cut(ut) && !quad_too_few) return Plan_status::ENDPOINT_ADJUSTMENT;
    if(convex && !is_cut(ut) && is_split(last)) return Plan_status::ENDPOINT_ADJUSTMENT;
    if(quad_too_few)
    {
      if(concave && !is_cut(ut)) return is_collapse(last) ? Plan_status::REALIZABLE : Plan_status::ENDPOINT_ADJUSTMENT;
      if(!is_cut(ut)) return Plan_status::ENDPOINT_ADJUSTMENT;
      // along the border, on a straight piece or at a concave corner: the split on the side of the gap
      const bool mesh_on_left = !gap(ut);
      return last == (mesh_on_left ? Strip_operation::RIGHT_SPLIT : Strip_operation::LEFT_SPLIT)
               ? Plan_status::REALIZABLE : Plan_status::ENDPOINT_ADJUSTMENT;
    }
    if(is_cut(ut))
    {
      // on a straight piece of border the split on the side of the mesh, at a convex corner the one on the
      // side of the border gap
      const bool mesh_on_left = !gap(ut), split_on_left = mesh_on_left != convex;
      if(last != (split_on_left ? Strip_operation::LEFT_SPLIT : Strip_operation::RIGHT_SPLIT))
        return Plan_status::ENDPOINT_ADJUSTMENT;
      // the other border edge at t, across the border gap from t->u
      const halfedge_descriptor te = mesh_on_left ? ccw(opposite(ut, pm), pm) : cw(opposite(ut, pm), pm);
      path.push_back(target(te, pm));
      ops[n - 1] = last;
      ops.push_back(Strip_operation::NO_OPERATION);
      return Plan_status::REALIZABLE;
    }
    const bool counts_left = last == Strip_operation::LEFT_SPLIT || last == Strip_operation::RIGHT_COLLAPSE;
    // the rotations around t count the faces of its fan and the gap as one step each: turning
    // counterclockwise from the outgoing halfedge h across the gap (a feature end: the other sectors)
    // leads to the first halfedge whose face is in the fan again
    int deg = 1;
    for(halfedge_descriptor h : halfedges_around_source(t, pm)) if(!gap(h)) ++deg;
    auto ccw_in_fan = [&](halfedge_descriptor h)
    {
      const bool across_gap = gap(h);
      h = ccw(h, pm);
      while(across_gap && gap(h)) h = ccw(h, pm);
      return h;
    };
    const int k = last == Strip_operation::RIGHT_COLLAPSE ? 1
                : last == Strip_operation::LEFT_COLLAPSE ? deg - 1
                : (concave && last == Strip_operation::RIGHT_SPLIT ? deg - 2 : 2);
    halfedge_descriptor te = opposite(ut, pm);
    for(int step = 0; step < k; ++step) te = ccw_in_fan(te);
    // at a concave corner the split of t hands its extra quad to e even when e is inside: an interior e of
    // valence 3 becomes regular with t (the two defects cancel); any other interior e would become singular
    const bool cancels_inside = concave && is_split(last) && !is_cut(te) && is_usable(target(te, pm)) &&
                                valence(target(te, pm), pm) == 3;
    if(concave && is_split(last) ? !is_cut(te) && !cancels_inside : !gap(counts_left ? te : opposite(te, pm)))
      return Plan_status::ENDPOINT_ADJUSTMENT;
    path.push_back(target(te, pm));
    ops[n - 1] = is_collapse(last) ? rotate(last, 2) : last;
    ops.push_back(Strip_operation::NO_OPERATION);
    return Plan_status::REALIZABLE;
  }

  // S1-S4: v3 start with a split: no operation at s; v3 start with a collapse: start from the
  // neighbour n on that side and turn along the quad (n, d) towards v1; v5 start with a split: start
  // from the back neighbour n on that side (ccw index 2 or 3 from v1) with no operation; v5 start
  // with a collapse: nothing.
  // `retransport_from` is set to the first index whose tag must be transported again (0: none).
  Plan_status prepare_start(Path& path, Operations& ops, std::size_t& retransport_from) const
  {
    retransport_from = 0;
    const vertex_descriptor s = path[0], v1 = path[1];
    const Strip_operation first = ops[0];
    const halfedge_descriptor sv = out(s, v1);
    if(valence(s, pm) == 3)
    {
      if(is_split(first)) { ops[0] = Strip_operation::NO_OPERATION; return Plan_status::REALIZABLE; }
      const bool left = first == Strip_operation::LEFT_COLLAPSE;
      // LC: face(s->v1) = (s, v1, d, n); RC: face(v1->s) = (v1, s, n, d)
      vertex_descriptor d, nb;
      if(!side_quad_corners(sv, left, d, nb)) return Plan_status::BORDER_OR_CONSTRAINED;
      if(!is_usable(d) || !is_usable(nb)) return Plan_status::ENDPOINT_ADJUSTMENT;
      path[0] = d;
      path.insert(path.begin(), nb);
      ops.insert(ops.begin(), first);
      ops[1] = left ? Strip_operation::RIGHT_COLLAPSE : Strip_operation::LEFT_COLLAPSE;
      retransport_from = 2;
      return Plan_status::REALIZABLE;
    }
    if(is_split(first))
    {
      const vertex_descriptor nb =
        target(rotate_outgoing(sv, first == Strip_operation::LEFT_SPLIT ? 2 : 3, pm), pm);
      if(!is_usable(nb)) return Plan_status::ENDPOINT_ADJUSTMENT;
      path.insert(path.begin(), nb);
      ops.insert(ops.begin(), Strip_operation::NO_OPERATION);
    }
    return Plan_status::REALIZABLE;
  }

  // removes folds a -> b -> a; the compass at a keeps its orientation, so its tag rotates by the
  // number of counterclockwise steps from a->b to the new next edge. a must be regular. `first_fold`
  // is set to the index of the first a (path.size() when there is no fold).
  Plan_status remove_folds(Path& path, Operations& ops, std::size_t& first_fold) const
  {
    first_fold = path.size();
    for(std::size_t j = 0; j + 2 < path.size();)
    {
      if(path[j] != path[j + 2]) { ++j; continue; }
      const vertex_descriptor a = path[j], b = path[j + 1];
      if(valence(a, pm) != 4 || ops[j] == Strip_operation::NO_OPERATION) return Plan_status::NOT_SIMPLE_AFTER_ADJUSTMENT;
      first_fold = (std::min)(first_fold, j);
      path.erase(path.begin() + long(j) + 1, path.begin() + long(j) + 3);
      ops.erase(ops.begin() + long(j) + 1, ops.begin() + long(j) + 3);
      if(j + 1 < path.size())
        ops[j] = rotate(ops[j], ccw_steps(out(a, b), out(a, path[j + 1]), pm));
      else
        ops[j] = Strip_operation::NO_OPERATION;
      if(j > 0) --j;
    }
    return Plan_status::REALIZABLE;
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_ENDPOINT_PREPARATION_H
