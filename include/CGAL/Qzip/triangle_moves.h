// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_TRIANGLE_MOVES_H
#define CGAL_QZIP_TRIANGLE_MOVES_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/quad_operations.h>

#include <CGAL/Qzip/internal/triangle_journal.h>
#include <CGAL/Qzip/internal/rotation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/assertions.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipHybrid
The four moves of a triangle by one edge (paper, Sec. 3.2 and Fig. 14).

A triangle is given by its *base halfedge* `h = a->b` (`face(h)` is the triangle); its *tip* is the
third corner `t = target(next(h))`. In a regular region the tip has valence 5 and `a`, `b` valence 4,
and the triangle *points* from its base towards its tip; `a` is on its left, `b` on its right.
*/
enum class Triangle_move
{
  VERTEX_TO_EDGE = 0, ///< VE: the tip is split into an edge, the new base; the triangle moves one edge towards its tip
  EDGE_TO_VERTEX = 1, ///< EV: the base is collapsed into a vertex, the new tip; the triangle moves one edge towards its base
  LEFT_FLIP = 2,      ///< LE: the edge `t-a` is flipped in the pentagon made of the triangle and its left quad; the triangle moves one edge to the left
  RIGHT_FLIP = 3,     ///< RE: the edge `t-b` is flipped in the pentagon made of the triangle and its right quad; the triangle moves one edge to the right
  MIRRORED_VERTEX_TO_EDGE = 4 ///< VE': VE that cuts the new triangle from the face on the left of `w->t` instead of the one on its right (the mirror image of VE)
};

/// \ingroup PkgQzipHybrid
/// the short name of a triangle move: "VE", "EV", "LE", "RE" or "VE'".
inline const char* short_name(Triangle_move m)
{
  static const char* names[] = { "VE", "EV", "LE", "RE", "VE'" };
  return names[int(m)];
}

/// \ingroup PkgQzipHybrid
/// the move that undoes `m`, applied to the triangle `m` produced: VE and EV undo each other, and so do
/// LE and RE; EV also undoes VE' (see `move_triangle()` for the vertex to pass so that the inverse is exact).
inline Triangle_move inverse(Triangle_move m)
{
  static const Triangle_move inv[] = { Triangle_move::EDGE_TO_VERTEX, Triangle_move::VERTEX_TO_EDGE,
                                       Triangle_move::RIGHT_FLIP, Triangle_move::LEFT_FLIP,
                                       Triangle_move::EDGE_TO_VERTEX };
  return inv[int(m)];
}

/// \ingroup PkgQzipHybrid
/// the tip of the triangle whose base halfedge is `h`: `target(next(h, pm), pm)`.
template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::vertex_descriptor
triangle_tip(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  return target(next(h, pm), pm);
}

namespace internal {

template <typename PolygonMesh>
std::size_t face_degree(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  std::size_t n = 0;
  for(auto x : halfedges_around_face(h, pm)) { (void)x; ++n; }
  return n;
}

template <typename PolygonMesh>
bool is_triangle_face(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  return !is_border(h, pm) && face_degree(h, pm) == 3;
}

template <typename PolygonMesh>
bool is_quad_face(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  return !is_border(h, pm) && face_degree(h, pm) == 4;
}


template <typename PolygonMesh>
bool are_adjacent(typename boost::graph_traits<PolygonMesh>::vertex_descriptor u,
                  typename boost::graph_traits<PolygonMesh>::vertex_descriptor w, const PolygonMesh& pm)
{
  return halfedge(u, w, pm).second;
}

// whether the four corners of the face of `h` (a quad) are distinct
template <typename PolygonMesh>
bool has_distinct_corners(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor> vs;
  for(auto x : halfedges_around_face(h, pm)) vs.push_back(target(x, pm));
  std::sort(vs.begin(), vs.end());
  return std::adjacent_find(vs.begin(), vs.end()) == vs.end();
}

// whether `v` may lose one edge: an interior vertex keeps at least 3, a border one at least 2
template <typename PolygonMesh>
bool may_lose_an_edge(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm)
{
  return valence(v, pm) >= (is_border_vertex(v, pm) ? 3u : 4u);
}

// the default direction of VE: the neighbour of the tip `(d - 1) / 2` counterclockwise steps from t->b,
// the one opposite the triangle when the tip has valence d = 5.
template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::vertex_descriptor
default_ve_target(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  const auto tb = opposite(next(h, pm), pm);          // t->b
  const int d = int(valence(source(tb, pm), pm));
  return target(rotate_outgoing(tb, (d - 1) / 2, pm), pm);
}

// position helper: `from` moved a third of the way towards the centroid of the neighbours of `v`
template <typename PolygonMesh, typename VPM>
typename boost::property_traits<VPM>::value_type
relaxed_position(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm, VPM vpm)
{
  typedef typename boost::property_traits<VPM>::value_type Point;
  const Point from = get(vpm, v);
  double x = 0, y = 0, z = 0, n = 0;
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
  {
    const Point& p = get(vpm, source(h, pm));
    x += p.x(); y += p.y(); z += p.z(); n += 1;
  }
  if(n == 0) return from;
  return Point(from.x() + (x / n - from.x()) / 3., from.y() + (y / n - from.y()) / 3.,
               from.z() + (z / n - from.z()) / 3.);
}

// places the two copies of a split vertex (t and the new t2) a third of the way towards the centroids of
// their neighbours, both computed before either moves
template <typename PolygonMesh, typename Journal>
void relax_split_copies(typename boost::graph_traits<PolygonMesh>::vertex_descriptor t,
                        typename boost::graph_traits<PolygonMesh>::vertex_descriptor t2, Journal& J)
{
  const auto p2 = relaxed_position(t2, J.mesh(), J.vertex_point_map());
  const auto p1 = relaxed_position(t, J.mesh(), J.vertex_point_map());
  J.move_point(t2, p2);
  J.move_point(t, p1);
}

} // namespace internal

/*!
\ingroup PkgQzipHybrid
A property map telling which faces a Q-zip must stay away from in a hybrid mesh: every face that is not a
quad, and the faces `user_map` protects. Passed as `face_is_constrained_map` to `shortest_surgery_path()`,
`plan_qzip()` and `execute_qzip()`, it makes a surgery path treat the edges of every triangle as border
edges (paper, Sec. 3.2): no path vertex is incident to a triangle, so no collapse or split ever touches one
and every triangle stays a triangle.

\tparam PolygonMesh a model of `FaceGraph`
\tparam FaceIsConstrainedMap a readable property map from faces to `bool`
\cgalModels `ReadablePropertyMap`
*/
template <typename PolygonMesh,
          typename FaceIsConstrainedMap = Static_boolean_property_map<typename boost::graph_traits<PolygonMesh>::face_descriptor, false> >
struct Non_quad_face_map
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor key_type;
  typedef bool value_type;
  typedef bool reference;
  typedef boost::readable_property_map_tag category;

  const PolygonMesh* pm = nullptr;
  FaceIsConstrainedMap user_map;

  Non_quad_face_map() {}
  explicit Non_quad_face_map(const PolygonMesh& pm, FaceIsConstrainedMap m = FaceIsConstrainedMap())
    : pm(&pm), user_map(m) {}

  friend bool get(const Non_quad_face_map& m, key_type f)
  {
    return get(m.user_map, f) || internal::face_degree(halfedge(f, *m.pm), *m.pm) != 4;
  }
};

/// \ingroup PkgQzipHybrid
/// makes a `Non_quad_face_map` of `pm` (no user-protected face).
template <typename PolygonMesh>
Non_quad_face_map<PolygonMesh> make_non_quad_face_map(const PolygonMesh& pm)
{
  return Non_quad_face_map<PolygonMesh>(pm);
}

/*!
\ingroup PkgQzipHybrid

checks whether the triangle of base `h` can make the move `m` with the given `toward` vertex (see
`move_triangle()`) without breaking the mesh or changing the degree of any face but the triangle and the
one face that becomes the new triangle. Requires: `face(h)` is a triangle with three distinct corners and no
border edge, the face the move needs (below the base for EV, left of `t-a` for LE, right of `t-b` for RE, the
face on the right of `toward->t` for VE) is an interior quad with four distinct corners (when it is a triangle
the two triangles *collide*: see `merge_triangles()`), no edge would be doubled, and no vertex is
left with fewer than three edges (two on the border). EV also needs `a` and `b` to share no neighbour but `t`
and no face but the triangle and the quad below, and not to be both on the border; VE needs an interior tip.
*/
template <typename PolygonMesh>
bool can_move_triangle(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, Triangle_move m,
                       const PolygonMesh& pm,
                       typename boost::graph_traits<PolygonMesh>::vertex_descriptor toward =
                         boost::graph_traits<PolygonMesh>::null_vertex())
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  if(h == GT::null_halfedge() || !internal::is_triangle_face(h, pm)) return false;
  const halfedge_descriptor n = next(h, pm), p = prev(h, pm);
  const vertex_descriptor a = source(h, pm), b = target(h, pm), t = target(n, pm);
  if(a == b || a == t || b == t) return false;
  if(is_border(opposite(h, pm), pm) || is_border(opposite(n, pm), pm) || is_border(opposite(p, pm), pm))
    return false;

  switch(m)
  {
    case Triangle_move::EDGE_TO_VERTEX:
    {
      const halfedge_descriptor o = opposite(h, pm);
      if(!internal::is_quad_face(o, pm) || !internal::has_distinct_corners(o, pm)) return false;
      if(toward != GT::null_vertex() && toward != a && toward != b) return false;
      if(internal::is_border_vertex(a, pm) && internal::is_border_vertex(b, pm)) return false;
      if(!internal::may_lose_an_edge(t, pm)) return false;
      // the quad below may not contain the tip, and the faces across t-a and t-b must be two other faces
      for(auto x : halfedges_around_face(o, pm)) if(target(x, pm) == t) return false;
      {
        const auto fl = face(opposite(p, pm), pm), fr = face(opposite(n, pm), pm);
        if(fl == fr || fl == face(o, pm) || fr == face(o, pm)) return false;
      }
      // a and b lose the edge a-b and merge: they may share no neighbour but t, no face but the two
      for(auto ha : halfedges_around_target(a, pm))
      {
        const vertex_descriptor x = source(ha, pm);
        if(x == t || x == b) continue;
        if(internal::are_adjacent(x, b, pm)) return false;
      }
      const auto fT = face(h, pm), fQ = face(o, pm);
      for(auto ha : halfedges_around_target(a, pm))
      {
        if(is_border(ha, pm)) continue;
        const auto f = face(ha, pm);
        if(f == fT || f == fQ) continue;
        for(auto x : halfedges_around_face(ha, pm))
          if(target(x, pm) == b) return false;
      }
      // the merged vertex keeps at least 3 edges: deg(a) + deg(b) - 3
      if(internal::valence(a, pm) + internal::valence(b, pm) < 6) return false;
      return true;
    }
    case Triangle_move::LEFT_FLIP:
    case Triangle_move::RIGHT_FLIP:
    {
      const bool left = (m == Triangle_move::LEFT_FLIP);
      const halfedge_descriptor side = left ? p : n;   // t->a or b->t
      const halfedge_descriptor q = opposite(side, pm);
      if(!internal::is_quad_face(q, pm) || !internal::has_distinct_corners(q, pm)) return false;
      // the new edge joins a and tl (LE) or b and tr (RE)
      const vertex_descriptor end1 = left ? a : b;
      const vertex_descriptor end2 = left ? target(next(q, pm), pm) : source(prev(q, pm), pm);
      if(end2 == a || end2 == b || internal::are_adjacent(end1, end2, pm)) return false;
      // the quad across the flipped side may not contain the third corner of the triangle
      for(auto x : halfedges_around_face(q, pm)) if(target(x, pm) == (left ? b : a)) return false;
      if(toward != GT::null_vertex() && toward != end2) return false;
      if(!internal::may_lose_an_edge(t, pm)) return false;
      return true;
    }
    case Triangle_move::VERTEX_TO_EDGE:
    case Triangle_move::MIRRORED_VERTEX_TO_EDGE:
    {
      if(internal::is_border_vertex(t, pm)) return false;
      const vertex_descriptor w = (toward == GT::null_vertex()) ? internal::default_ve_target(h, pm) : toward;
      if(w == a || w == b) return false;
      const auto wt = halfedge(w, t, pm);
      if(!wt.second) return false;
      // w->t (VE) or t->w (VE'): its face becomes the new triangle and a quad
      const halfedge_descriptor q = (m == Triangle_move::VERTEX_TO_EDGE) ? wt.first : opposite(wt.first, pm);
      if(!internal::is_quad_face(q, pm) || !internal::has_distinct_corners(q, pm)) return false;
      for(auto x : halfedges_around_face(q, pm)) if(target(x, pm) == a || target(x, pm) == b) return false;
      return true;
    }
  }
  return false;
}

/*!
\ingroup PkgQzipHybrid
The journal of the triangle moves and merges applied to a mesh through the functions that take it, to
undo them exactly, most recent first, without any copy of the mesh. Each move is recorded as the Euler
operations it is made of (`CGAL::Euler::join_face()`, `split_face()`, `join_vertex()`, `split_vertex()`)
and the position changes, and undoing applies their inverses in reverse order. Connectivity and every
position come back exactly (re-created elements may have new descriptors).

A *group* is what `undo_last()` undoes: one call of `move_triangle()`, `merge_triangles()` or
`move_triangle_along_path()`.

\pre Between a recorded operation and its undo, the mesh is only modified through this history.
*/
template <typename PolygonMesh,
          typename VertexPointMap = typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>
class Triangle_move_history
{
  std::shared_ptr<internal::Triangle_journal<PolygonMesh, VertexPointMap> > j;
public:
  /// an empty history of `pm`, whose positions are in `vpm`.
  Triangle_move_history(PolygonMesh& pm, VertexPointMap vpm)
    : j(std::make_shared<internal::Triangle_journal<PolygonMesh, VertexPointMap> >(pm, vpm)) {}
  /// an empty history of `pm`, with its internal vertex point map.
  explicit Triangle_move_history(PolygonMesh& pm)
    : j(std::make_shared<internal::Triangle_journal<PolygonMesh, VertexPointMap> >(pm, get(CGAL::vertex_point, pm))) {}
  /// the number of recorded groups.
  std::size_t size() const { return j->number_of_marks(); }
  /// `true` when there is nothing to undo.
  bool empty() const { return size() == 0; }
  /// undoes the most recent group. \pre `!empty()`
  void undo_last() { CGAL_precondition(!empty()); j->rollback_to_mark(); }
  /// undoes every recorded group.
  void undo_all() { while(!empty()) undo_last(); }
  /// \cond SKIP_IN_MANUAL
  internal::Triangle_journal<PolygonMesh, VertexPointMap>& journal() { return *j; }
  /// \endcond
};

namespace internal {

template <typename T> struct Is_triangle_move_history : std::false_type {};
template <typename PM, typename VPM>
struct Is_triangle_move_history<Triangle_move_history<PM, VPM> > : std::true_type {};

// the moves themselves, through a journal; preconditions checked by the caller.
template <typename PolygonMesh, typename VPM>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
apply_triangle_move(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, Triangle_move m,
                    typename boost::graph_traits<PolygonMesh>::vertex_descriptor toward,
                    Triangle_journal<PolygonMesh, VPM>& J)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  PolygonMesh& pm = J.mesh();
  const VPM vpm = J.vertex_point_map();

  const halfedge_descriptor n = next(h, pm), p = prev(h, pm);
  const vertex_descriptor a = source(h, pm), b = target(h, pm), t = target(n, pm);
  switch(m)
  {
    case Triangle_move::EDGE_TO_VERTEX:
    {
      // T = (t, a, b), Q = (a, ad, bd, b) below the base. join T with its left face across t-a
      // (the pentagon keeps the degree of the left face plus one), then join a and b: the left face gets
      // its degree back, Q becomes the triangle (m, ad, bd) with the merged vertex m as its tip.
      const halfedge_descriptor o = opposite(h, pm);               // b->a, in Q
      const halfedge_descriptor new_base = next(next(o, pm), pm);  // ad->bd
      const bool keep_b = (toward == b);
      const auto pa = get(vpm, a), pb = get(vpm, b);
      J.join_face(p);
      J.join_vertex(keep_b ? h : o);                               // removes a (keep b) or b (keep a)
      const vertex_descriptor kept = keep_b ? b : a;
      J.move_point(kept, CGAL::midpoint(pa, pb));
      return new_base;
    }
    case Triangle_move::LEFT_FLIP:
    {
      // pentagon (t, tl, al, a, b) = T + the left quad (a, t, tl, al); the diagonal t-a becomes tl-a.
      const halfedge_descriptor q = opposite(p, pm);               // a->t
      const halfedge_descriptor t_tl = next(q, pm), al_a = prev(q, pm);
      J.join_face(p);
      J.split_face(t_tl, al_a);                                    // tl->a, T keeps (t, tl, a, b)
      return al_a;                                                 // base of (tl, al, a)
    }
    case Triangle_move::RIGHT_FLIP:
    {
      // pentagon (t, a, b, br, tr) = T + the right quad (t, b, br, tr); the diagonal t-b becomes b-tr.
      const halfedge_descriptor q = opposite(n, pm);               // t->b
      const halfedge_descriptor b_br = next(q, pm), br_tr = next(b_br, pm);
      J.join_face(n);
      J.split_face(h, br_tr);                                      // b->tr, T keeps (t, a, b, tr)
      return b_br;                                                 // base of (tr, b, br)
    }
    case Triangle_move::VERTEX_TO_EDGE:
    {
      // split the tip t into t (keeping the edges from w to a) and t2 (the edges from b to w, exclusive):
      // T becomes the quad (t, a, b, t2) and the face F on the right of w->t gets the edge t->t2; then F
      // is split between t2 and w into the new triangle (w, t, t2) and a face of the degree F had.
      const vertex_descriptor w = (toward == GT::null_vertex()) ? default_ve_target(h, pm) : toward;
      const halfedge_descriptor wt = halfedge(w, t, pm).first;
      const halfedge_descriptor before_w = prev(wt, pm);
      const halfedge_descriptor hn = J.split_vertex(wt, n);        // t2->t, t2 new
      CGAL_USE(hn);
      const halfedge_descriptor t_t2 = next(wt, pm);
      J.split_face(t_t2, before_w);                                // t2->w closes (w, t, t2)
      relax_split_copies<PolygonMesh>(t, target(t_t2, pm), J);
      return t_t2;
    }
    case Triangle_move::MIRRORED_VERTEX_TO_EDGE:
    {
      // the mirror image of VE: the split gives the new edge to T and to the face L on the left of w->t
      // (split_vertex(b->t, x->t) with x->t in L): L = (.., x, t2, t, w, ..) is split between t2 and w into
      // the new triangle (t2, t, w) and a face of the degree L had.
      const vertex_descriptor w = (toward == GT::null_vertex()) ? default_ve_target(h, pm) : toward;
      const halfedge_descriptor xt = prev(opposite(halfedge(w, t, pm).first, pm), pm);
      J.split_vertex(n, xt);
      const halfedge_descriptor t2_t = next(xt, pm), t_w = next(t2_t, pm);
      CGAL_assertion(target(t_w, pm) == w);
      J.split_face(t_w, xt);                                       // w->t2 closes (t2, t, w)
      relax_split_copies<PolygonMesh>(t, source(t2_t, pm), J);
      return t2_t;
    }
  }
  return h;
}

} // namespace internal

/*!
\ingroup PkgQzipHybrid

moves the triangle whose base halfedge is `h` by one edge (paper, Fig. 14). With `T = (t, a, b)`,
`h = a->b` and `t` the tip:

- `EDGE_TO_VERTEX` (EV) collapses the base `a-b` into one vertex `m`, which becomes the tip of the new
  triangle: the quad `(a, ad, bd, b)` below the base becomes the triangle `(m, ad, bd)` and `T` vanishes
  (its two sides become one edge `t-m`). Made of `join_face(t->a)` and `join_vertex()`. `toward` says which of
  `a` and `b` is kept as `m` (default `a`); `m` is put at the midpoint of the base.
  Valences: `deg(t) -= 1`, `deg(m) = deg(a) + deg(b) - 3`.
- `VERTEX_TO_EDGE` (VE) splits the tip `t` into an edge `t-t2`, the base of the new triangle `(w, t, t2)`,
  whose tip is `w = toward` (default: the neighbour of `t` opposite `T` when `t` has valence 5); `T` becomes
  the quad `(t, a, b, t2)`, and the quad on the right of `w->t` gives up the new triangle.
  Made of `split_vertex()` and `split_face()`. Valences: `deg(w) += 1`, and with `k` the number of
  counterclockwise steps from `t->b` to `t->w`: `deg(t2) = k + 2`, `deg(t) = deg_before(t) - k + 1`.
  EV of the new triangle towards `t` is the exact inverse.
- `MIRRORED_VERTEX_TO_EDGE` (VE') does the same with the face on the left of `w->t`: the new triangle is
  `(t2, t, w)`, with `t2` on the other side of `t`. In a regular region VE and VE' give isomorphic meshes;
  VE' is the way forward when the face on the right of `w->t` cannot be used (see `move_triangle_along_path()`).
  EV of the new triangle towards `t` is its inverse too.
- `LEFT_FLIP` (LE) and `RIGHT_FLIP` (RE) flip the side `t-a` (resp. `t-b`) inside the pentagon made of
  `T` and the quad across that side: the new triangle is `(tl, al, a)` (resp. `(tr, b, br)`) and `T` becomes
  a quad. Made of `join_face()` and `split_face()`. Valences: `deg(t) -= 1`, `deg(tl) += 1` (resp. `tr`).
  RE (resp. LE) of the new triangle is the exact inverse.

In each move the tip moves by one edge and no face but the old and the new triangle changes its degree;
in a regular region a canonical triangle (tip of valence 5, base corners of valence 4) stays canonical and no
singularity appears. `toward`, when given, must be the vertex the tip moves to (for EV: `a` or `b`).

\tparam PolygonMesh a model of `MutableFaceGraph`
\param h the base halfedge
\param m the move
\param history the history recording the move (as one group)
\param toward the vertex the tip moves to, or `null_vertex()`
\pre `can_move_triangle(h, m, pm, toward)`
\returns the base halfedge of the moved triangle
*/
template <typename PolygonMesh, typename VertexPointMap>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
move_triangle(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, Triangle_move m,
              Triangle_move_history<PolygonMesh, VertexPointMap>& history,
              typename boost::graph_traits<PolygonMesh>::vertex_descriptor toward =
                boost::graph_traits<PolygonMesh>::null_vertex())
{
  CGAL_precondition(can_move_triangle(h, m, history.journal().mesh(), toward));
  history.journal().mark();
  return internal::apply_triangle_move(h, m, toward, history.journal());
}

/*!
\ingroup PkgQzipHybrid
same as the other overload, without recording the move; the positions are those of the internal vertex
point map of `pm`.
*/
template <typename PolygonMesh
#ifndef DOXYGEN_RUNNING
          , typename = typename std::enable_if<!internal::Is_triangle_move_history<PolygonMesh>::value>::type
#endif
          >
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
move_triangle(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, Triangle_move m,
              PolygonMesh& pm,
              typename boost::graph_traits<PolygonMesh>::vertex_descriptor toward =
                boost::graph_traits<PolygonMesh>::null_vertex())
{
  CGAL_precondition(can_move_triangle(h, m, pm, toward));
  auto vpm = get(CGAL::vertex_point, pm);
  internal::Triangle_journal<PolygonMesh, decltype(vpm)> J(pm, vpm);
  return internal::apply_triangle_move(h, m, toward, J);
}

/*!
\ingroup PkgQzipHybrid
checks whether the two faces of `h` are distinct interior triangles that `merge_triangles()` can join
into a quad with four distinct corners, leaving both ends of `edge(h)` with at least three edges (two on
the border).
*/
template <typename PolygonMesh>
bool can_merge_triangles(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  const auto o = opposite(h, pm);
  if(!internal::is_triangle_face(h, pm) || !internal::is_triangle_face(o, pm)) return false;
  if(face(h, pm) == face(o, pm)) return false;
  const auto x = target(next(h, pm), pm), y = target(next(o, pm), pm);
  if(x == y || x == source(h, pm) || x == target(h, pm) || y == source(h, pm) || y == target(h, pm)) return false;
  return internal::may_lose_an_edge(source(h, pm), pm) && internal::may_lose_an_edge(target(h, pm), pm);
}

/*!
\ingroup PkgQzipHybrid
merges the two triangles on either side of `h` into one quad (`CGAL::Euler::join_face()`), recorded in
`history` as one group; this is how colliding triangles end (paper, Fig. 15). Both ends of `edge(h)` lose one edge.
\pre `can_merge_triangles(h, pm)`
\returns a halfedge of the quad
*/
template <typename PolygonMesh, typename VertexPointMap>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
merge_triangles(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                Triangle_move_history<PolygonMesh, VertexPointMap>& history)
{
  CGAL_precondition(can_merge_triangles(h, history.journal().mesh()));
  history.journal().mark();
  return history.journal().join_face(h);
}

/*!
\ingroup PkgQzipHybrid
checks whether `annihilate_triangles(h, history)` applies: the two faces of `h` are distinct interior
triangles `(t1, a, b)` and `(t2, b, a)` with `t1 != t2`, `a` and `b` are interior, share no neighbour but
`t1` and `t2` and no face but the two triangles, `t1` and `t2` may lose an edge, and the faces across
`t1-a` and `t2-b` are two other faces.
*/
template <typename PolygonMesh>
bool can_annihilate_triangles(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const auto o = opposite(h, pm);
  if(!internal::is_triangle_face(h, pm) || !internal::is_triangle_face(o, pm) || face(h, pm) == face(o, pm)) return false;
  const vertex_descriptor a = source(h, pm), b = target(h, pm);
  const vertex_descriptor t1 = target(next(h, pm), pm), t2 = target(next(o, pm), pm);
  if(t1 == t2 || t1 == a || t1 == b || t2 == a || t2 == b) return false;
  if(internal::is_border_vertex(a, pm) || internal::is_border_vertex(b, pm)) return false;
  if(!internal::may_lose_an_edge(t1, pm) || !internal::may_lose_an_edge(t2, pm)) return false;
  if(internal::valence(a, pm) + internal::valence(b, pm) < 7) return false;
  const auto ql = opposite(prev(h, pm), pm), qr = opposite(prev(o, pm), pm);
  if(is_border(ql, pm) || is_border(qr, pm)) return false;
  const auto fl = face(ql, pm), fr = face(qr, pm);
  if(fl == fr || fl == face(h, pm) || fl == face(o, pm) || fr == face(h, pm) || fr == face(o, pm)) return false;
  for(auto ha : halfedges_around_target(a, pm))
  {
    const vertex_descriptor x = source(ha, pm);
    if(x == t1 || x == t2 || x == b) continue;
    if(internal::are_adjacent(x, b, pm)) return false;
    if(is_border(ha, pm)) continue;
    const auto f = face(ha, pm);
    if(f == face(h, pm) || f == face(o, pm)) continue;
    for(auto y : halfedges_around_face(ha, pm))
      if(target(y, pm) == b) return false;
  }
  return true;
}

/*!
\ingroup PkgQzipHybrid
collapses the edge shared by the two triangles `(t1, a, b) = face(h)` and `(t2, b, a) = face(opposite(h))`:
both triangles vanish and `a` and `b` become one vertex (kept: `b`, put at the midpoint). This is how two
oppositely oriented triangles that meet base to base (head-on) end (paper, Sec. 3.2): with canonical
triangles in a regular region, every vertex is regular afterwards (`deg(t1)`, `deg(t2)` lose one edge,
the merged vertex has `deg(a) + deg(b) - 4`). Made of two `join_face()` (each triangle with its neighbour
across `t1-a`, resp. `t2-b`) and one `join_vertex()`; recorded in `history` as one group.
\pre `can_annihilate_triangles(h, pm)`
\returns a halfedge whose target is the merged vertex
*/
template <typename PolygonMesh, typename VertexPointMap>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
annihilate_triangles(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                     Triangle_move_history<PolygonMesh, VertexPointMap>& history)
{
  auto& J = history.journal();
  PolygonMesh& pm = J.mesh();
  CGAL_precondition(can_annihilate_triangles(h, pm));
  J.mark();
  const auto pa = get(J.vertex_point_map(), source(h, pm)), pb = get(J.vertex_point_map(), target(h, pm));
  const auto b = target(h, pm);
  J.join_face(prev(h, pm));
  J.join_face(prev(opposite(h, pm), pm));
  const auto r = J.join_vertex(h);
  J.move_point(b, CGAL::midpoint(pa, pb));
  return r;
}

namespace internal {

// the local irregularity sum |deg - 4| of the interior vertices among `vs`, with `delta` added to their valences
template <typename PolygonMesh>
int irregularity_after(const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& vs,
                       const std::vector<int>& delta, const PolygonMesh& pm)
{
  int s = 0;
  for(std::size_t i = 0; i < vs.size(); ++i)
  {
    if(is_border_vertex(vs[i], pm)) continue;
    s += std::abs(int(valence(vs[i], pm)) + delta[i] - 4);
  }
  return s;
}

} // namespace internal

/// \ingroup PkgQzipHybrid
/// How two colliding triangles were resolved (see `collide_triangles()`).
enum class Collision_resolution
{
  NONE,       ///< nothing could be done
  MERGED,     ///< `merge_triangles()`: the two triangles became one quad
  ANNIHILATED, ///< `annihilate_triangles()`: the shared edge was collapsed and both triangles vanished
  TIP_SPLIT   ///< a VE (or VE') ran into a triangle that shares the tip (see `move_triangle_along_path()`): the tip was split into an edge, both triangles became quads
};

/*!
\ingroup PkgQzipHybrid
resolves the collision of the two triangles on either side of `h` (paper, Fig. 15), recorded in `history`
as one group: either merges them into a quad or collapses their common edge, whichever leaves the ends of
`h` and the two opposite corners closer to valence 4 (a merge when both are equal). With canonical triangles
in a regular region this gives: oppositely oriented triangles side by side, merged, and head-on (base to base),
annihilated: no singularity; orthogonal triangles: an adjacent 3-5 pair; triangles of the same direction:
a v3 and a v5 at opposite corners of a quad.
*/
template <typename PolygonMesh, typename VertexPointMap>
Collision_resolution collide_triangles(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                                       Triangle_move_history<PolygonMesh, VertexPointMap>& history)
{
  const PolygonMesh& pm = history.journal().mesh();
  const bool can_m = can_merge_triangles(h, pm), can_a = can_annihilate_triangles(h, pm);
  if(!can_m && !can_a) return Collision_resolution::NONE;
  const auto o = opposite(h, pm);
  const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>
    vs = { source(h, pm), target(h, pm), target(next(h, pm), pm), target(next(o, pm), pm) };
  const int cost_m = internal::irregularity_after(vs, { -1, -1, 0, 0 }, pm);
  int cost_a = 1 << 20;
  if(can_a)
  {
    // the merged vertex: deg(a) + deg(b) - 4; counted once
    const int dm = int(internal::valence(vs[0], pm) + internal::valence(vs[1], pm)) - 4;
    cost_a = std::abs(dm - 4) + internal::irregularity_after(
               std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>{ vs[2], vs[3] }, { -1, -1 }, pm);
  }
  if(can_m && cost_m <= cost_a) { merge_triangles(h, history); return Collision_resolution::MERGED; }
  if(can_a) { annihilate_triangles(h, history); return Collision_resolution::ANNIHILATED; }
  merge_triangles(h, history);
  return Collision_resolution::MERGED;
}

namespace internal {

// A VE of the triangle of base `h` towards `w` whose new triangle would be cut from the face `F` of `w->t`
// (t the tip; for VE', the face of `t->w`), when `F` is itself a triangle: the two triangles collide at the
// tip. Splitting the tip as VE (VE') does gives each of them the new edge t-t2: both become quads.
template <typename PolygonMesh>
bool can_split_shared_tip(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                          typename boost::graph_traits<PolygonMesh>::vertex_descriptor w, bool mirrored,
                          const PolygonMesh& pm)
{
  const auto n = next(h, pm);
  const auto a = source(h, pm), b = target(h, pm), t = target(n, pm);
  if(w == a || w == b || is_border_vertex(t, pm)) return false;
  const auto wt = halfedge(w, t, pm);
  if(!wt.second) return false;
  const auto q = mirrored ? opposite(wt.first, pm) : wt.first;
  if(!is_triangle_face(q, pm) || face(q, pm) == face(h, pm)) return false;
  const auto x = target(next(q, pm), pm);                  // the third corner of F
  return x != w && x != t && x != a && x != b;
}

template <typename PolygonMesh, typename VPM>
void split_shared_tip(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor w, bool mirrored,
                      Triangle_journal<PolygonMesh, VPM>& J)
{
  PolygonMesh& pm = J.mesh();
  const auto n = next(h, pm);
  const auto t = target(n, pm);
  const auto wt = halfedge(w, t, pm).first;
  const auto hn = mirrored ? J.split_vertex(n, prev(opposite(wt, pm), pm)) : J.split_vertex(wt, n); // t2->t
  relax_split_copies<PolygonMesh>(t, source(hn, pm), J);
}

} // namespace internal

/// \ingroup PkgQzipHybrid
/// Result status of `move_triangle_along_path()`.
enum class Triangle_path_status
{
  DONE,          ///< the tip reached the end of the path
  COLLIDED,      ///< the next move met another triangle, and the collision was resolved by `collide_triangles()` (the path ends there)
  INVALID_PATH,  ///< the path does not start at the tip, is not a simple edge path, or the tip cannot move along it (e.g. EV would remove a later path vertex)
  BLOCKED        ///< a move is not possible (see `can_move_triangle()`); everything was rolled back
};

/// \ingroup PkgQzipHybrid
/// What `move_triangle_along_path()` did.
template <typename PolygonMesh>
struct Triangle_path_result
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  Triangle_path_status status = Triangle_path_status::INVALID_PATH;
  std::vector<Triangle_move> moves;   ///< the moves done, one per path edge (before a collision)
  halfedge_descriptor base = boost::graph_traits<PolygonMesh>::null_halfedge(); ///< base halfedge of the moved triangle (`DONE`)
  Collision_resolution collision = Collision_resolution::NONE; ///< how the collision was resolved (`COLLIDED`)
  bool is_done() const { return status == Triangle_path_status::DONE || status == Triangle_path_status::COLLIDED; }
};

/*!
\ingroup PkgQzipHybrid

the move that brings the tip of the triangle of base `h` to its neighbour `w`, given by the hybrid compass
(paper, Fig. 14): with `k` the number of counterclockwise steps from `t->b` to `t->w` around the tip `t` of
valence `d`, `w = b` or `w = a` (`k = 0`, `k = d - 1`) is EV (the base collapses into `w`), `k = 1` is RE,
`k = d - 2` is LE, and any other neighbour is VE (the tip is split into the new base behind it).
\pre `w` is a neighbour of the tip
*/
template <typename PolygonMesh>
Triangle_move triangle_move_toward(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                                   typename boost::graph_traits<PolygonMesh>::vertex_descriptor w,
                                   const PolygonMesh& pm)
{
  const auto tb = opposite(next(h, pm), pm);
  const auto tw = halfedge(triangle_tip(h, pm), w, pm);
  CGAL_precondition(tw.second);
  const int d = int(internal::valence(source(tb, pm), pm));
  const int k = internal::ccw_steps(tb, tw.first, pm);
  if(k == 0 || k == d - 1) return Triangle_move::EDGE_TO_VERTEX;
  if(k == 1) return Triangle_move::RIGHT_FLIP;
  if(k == d - 2) return Triangle_move::LEFT_FLIP;
  return Triangle_move::VERTEX_TO_EDGE;
}

/*!
\ingroup PkgQzipHybrid

moves the triangle of base `h` along `path`, a simple edge path starting at its tip: a Q-zip of a triangle
(paper, Sec. 3.2). At each vertex, the move that brings the tip to the next path vertex is chosen by
`triangle_move_toward()`: this is the hybrid compass. The compass carries the direction of the base edge
along the path: after VE, EV points back along the edge just travelled, at the vertex that was split into
the base; after EV, LE or RE, it points into the face corner the base was made from.

When the move to make needs a face that is a triangle (the two triangles collide), the collision is
resolved by `collide_triangles()` across the edge the move would have flipped or collapsed, and the path
ends there (status `COLLIDED`). Where the compass says VE and VE cannot be made, VE' (its mirror image)
is made instead. A VE (VE') whose new triangle would be cut from a triangle `F` (the face of `w->t`, resp.
`t->w`, which shares the tip `t`) collides too: the tip is split into an edge as VE (VE') does, which
turns both triangles into quads, and no face is cut (`Collision_resolution::TIP_SPLIT`). If a move cannot
be made, everything done is rolled back (status `BLOCKED`). The whole path is recorded in `history` as one group.

\tparam PolygonMesh a model of `MutableFaceGraph`
\param pm the polygon mesh
\param h the base halfedge of the triangle
\param path the vertices of the path, `path.front() == triangle_tip(h, pm)`
\param history the history recording the path
\returns what was done
*/
template <typename PolygonMesh, typename VertexPointMap>
Triangle_path_result<PolygonMesh>
move_triangle_along_path(PolygonMesh& pm, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                         const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& path,
                         Triangle_move_history<PolygonMesh, VertexPointMap>& history)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  Triangle_path_result<PolygonMesh> r;
  if(path.empty() || !internal::is_triangle_face(h, pm) || path.front() != triangle_tip(h, pm)) return r;
  {
    std::vector<vertex_descriptor> sorted(path);
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return r;
  }
  auto& J = history.journal();
  J.mark();
  auto fail = [&](Triangle_path_status s)
  {
    J.rollback_to_mark();
    r.status = s;
    r.moves.clear();
    r.base = GT::null_halfedge();
    return r;
  };
  halfedge_descriptor base = h;
  for(std::size_t j = 0; j + 1 < path.size(); ++j)
  {
    const vertex_descriptor t = triangle_tip(base, pm), w = path[j + 1];
    if(t != path[j] || !halfedge(t, w, pm).second) return fail(Triangle_path_status::INVALID_PATH);
    Triangle_move m = triangle_move_toward(base, w, pm);
    if(m == Triangle_move::VERTEX_TO_EDGE)
    {
      // VE cuts the new triangle from the face on the right of w->t, VE' (when VE cannot) from the one on its
      // left; a triangle there shares the tip: collision
      bool found = false;
      for(int side = 0; side < 2 && !found; ++side)
      {
        const bool mirrored = (side == 1);
        const halfedge_descriptor wt = halfedge(w, t, pm).first;
        if(internal::is_triangle_face(mirrored ? opposite(wt, pm) : wt, pm))
        {
          if(!internal::can_split_shared_tip(base, w, mirrored, pm)) continue;
          internal::split_shared_tip(base, w, mirrored, J);
          r.collision = Collision_resolution::TIP_SPLIT;
          r.status = Triangle_path_status::COLLIDED;
          return r;
        }
        const Triangle_move mm = mirrored ? Triangle_move::MIRRORED_VERTEX_TO_EDGE : Triangle_move::VERTEX_TO_EDGE;
        if(can_move_triangle(base, mm, pm, w)) { m = mm; found = true; }
      }
      if(!found) return fail(Triangle_path_status::BLOCKED);
    }
    // the face the move needs; a triangle there is a collision
    halfedge_descriptor partner = GT::null_halfedge();
    switch(m)
    {
      case Triangle_move::EDGE_TO_VERTEX: partner = base; break;
      case Triangle_move::LEFT_FLIP: partner = prev(base, pm); break;
      case Triangle_move::RIGHT_FLIP: partner = next(base, pm); break;
      case Triangle_move::VERTEX_TO_EDGE:
      case Triangle_move::MIRRORED_VERTEX_TO_EDGE: break; // handled above
    }
    if(partner != GT::null_halfedge() && internal::is_triangle_face(opposite(partner, pm), pm))
    {
      const std::size_t marks = J.number_of_marks();
      r.collision = collide_triangles(partner, history);
      if(r.collision == Collision_resolution::NONE) return fail(Triangle_path_status::BLOCKED);
      J.drop_mark(); // the collision belongs to the group of the path
      CGAL_assertion(J.number_of_marks() == marks); CGAL_USE(marks);
      r.status = Triangle_path_status::COLLIDED;
      return r;
    }
    if(m == Triangle_move::EDGE_TO_VERTEX)
    {
      // the other base vertex disappears: it may not be a later path vertex
      const vertex_descriptor gone = (w == source(base, pm)) ? target(base, pm) : source(base, pm);
      if(std::find(path.begin() + std::ptrdiff_t(j + 2), path.end(), gone) != path.end())
        return fail(Triangle_path_status::INVALID_PATH);
    }
    if(!can_move_triangle(base, m, pm, w)) return fail(Triangle_path_status::BLOCKED);
    base = internal::apply_triangle_move(base, m, w, J);
    r.moves.push_back(m);
  }
  r.base = base;
  r.status = Triangle_path_status::DONE;
  return r;
}

/// \ingroup PkgQzipHybrid
/// How a triangle of a hybrid mesh sits in it (see `classify_triangle()`).
enum class Triangle_configuration
{
  CANONICAL,        ///< isolated, interior, one corner of valence 5 (the tip) and two of valence 4: movable, no singularity
  SINGULAR_CORNERS, ///< isolated and interior, but its corners are not (5, 4, 4): a canonical triangle with singularities at its corners
  ADJACENT,         ///< it shares an edge with another triangle (e.g. a triangle fan): merge pairs with `merge_triangles()`
  ON_BORDER         ///< one of its edges or corners is on the border
};

/// \ingroup PkgQzipHybrid
/// the class of a triangle, with its base halfedge (`null_halfedge()` for `ADJACENT` and `ON_BORDER`).
template <typename PolygonMesh>
struct Triangle_classification
{
  Triangle_configuration configuration = Triangle_configuration::ON_BORDER;
  /// the base halfedge: the one opposite the tip for `CANONICAL`; for `SINGULAR_CORNERS`, the one
  /// opposite the corner of highest valence (so that the corner defects `deg - 5` at the tip and `deg - 4`
  /// at the base corners are as small as possible)
  typename boost::graph_traits<PolygonMesh>::halfedge_descriptor base =
    boost::graph_traits<PolygonMesh>::null_halfedge();
  int tip_defect = 0;       ///< `deg(tip) - 5`
  int base_defects[2] = { 0, 0 }; ///< `deg(a) - 4`, `deg(b) - 4`
};

/*!
\ingroup PkgQzipHybrid
classifies the triangle `f` of `pm` (see `Triangle_configuration`). Valences count all incident edges.
\pre `f` is a triangle
*/
template <typename PolygonMesh>
Triangle_classification<PolygonMesh>
classify_triangle(typename boost::graph_traits<PolygonMesh>::face_descriptor f, const PolygonMesh& pm)
{
  Triangle_classification<PolygonMesh> c;
  const auto h0 = halfedge(f, pm);
  CGAL_precondition(internal::face_degree(h0, pm) == 3);
  for(auto h : halfedges_around_face(h0, pm))
    if(is_border(opposite(h, pm), pm) || internal::is_border_vertex(target(h, pm), pm))
    { c.configuration = Triangle_configuration::ON_BORDER; return c; }
  for(auto h : halfedges_around_face(h0, pm))
    if(internal::is_triangle_face(opposite(h, pm), pm))
    { c.configuration = Triangle_configuration::ADJACENT; return c; }
  auto best = h0;
  for(auto h : halfedges_around_face(h0, pm))
    if(internal::valence(triangle_tip(h, pm), pm) > internal::valence(triangle_tip(best, pm), pm)) best = h;
  c.base = best;
  c.tip_defect = int(internal::valence(triangle_tip(best, pm), pm)) - 5;
  c.base_defects[0] = int(internal::valence(source(best, pm), pm)) - 4;
  c.base_defects[1] = int(internal::valence(target(best, pm), pm)) - 4;
  c.configuration = (c.tip_defect == 0 && c.base_defects[0] == 0 && c.base_defects[1] == 0)
                    ? Triangle_configuration::CANONICAL : Triangle_configuration::SINGULAR_CORNERS;
  return c;
}

/// \ingroup PkgQzipHybrid
/// What `prepare_triangles()` did and found.
struct Triangle_preparation_result
{
  std::size_t merged_pairs = 0;      ///< pairs of adjacent triangles merged into quads
  std::size_t separated = 0;         ///< triangles made canonical by one move away from a singular corner
  std::size_t canonical = 0;         ///< canonical triangles at the end
  std::size_t singular_corners = 0;  ///< isolated interior triangles still with singular corners
  std::size_t adjacent = 0;          ///< triangles still adjacent to another triangle
  std::size_t on_border = 0;         ///< triangles touching the border (left as they are)
};

/*!
\ingroup PkgQzipHybrid

brings the triangles of a hybrid mesh to the configuration the hybrid Q-zip supports, recording everything
in `history` (one group per operation):

1. pairs of adjacent interior triangles are merged into quads (`merge_triangles()`), greedily, as long as
   `can_merge_triangles()` holds; this is the collision rule applied to the input, and it removes triangle
   fans (e.g. at the poles of a UV sphere: the high-valence pole is left to `preprocess_valences()`);
2. an isolated interior triangle whose corners are not (5, 4, 4) is a canonical triangle with singular
   vertices at its corners: the one move (tip choice and direction) after which it is canonical is applied,
   which leaves the singularity behind as a quad-mesh singularity, if there is such a move.

Triangles on the border are left untouched and reported; they are never moved (every move requires an
interior triangle) and Q-zips avoid them through `Non_quad_face_map`.
*/
template <typename PolygonMesh, typename VertexPointMap>
Triangle_preparation_result prepare_triangles(PolygonMesh& pm, Triangle_move_history<PolygonMesh, VertexPointMap>& history)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  Triangle_preparation_result r;

  auto triangles = [&pm]()
  {
    std::vector<face_descriptor> ts;
    for(face_descriptor f : faces(pm))
      if(internal::face_degree(halfedge(f, pm), pm) == 3) ts.push_back(f);
    return ts;
  };

  // 1. merge adjacent pairs (the list of triangles is collected again after each merge: a merge removes a
  //    face, whose descriptor may dangle)
  for(bool progress = true; progress; )
  {
    progress = false;
    for(face_descriptor f : triangles())
    {
      if(classify_triangle(f, pm).configuration != Triangle_configuration::ADJACENT) continue;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
        if(!internal::is_border_vertex(source(h, pm), pm) && !internal::is_border_vertex(target(h, pm), pm) &&
           can_merge_triangles(h, pm))
        {
          merge_triangles(h, history);
          ++r.merged_pairs;
          progress = true;
          break;
        }
      if(progress) break;
    }
  }

  // 2. separate singular corners
  for(face_descriptor f : triangles())
  {
    const auto c = classify_triangle(f, pm);
    if(c.configuration != Triangle_configuration::SINGULAR_CORNERS) continue;
    bool done = false;
    // the corners, by vertex, in the order of the face: an undone move may re-create the halfedges of the
    // triangle under new descriptors, and an undone EV of base c[i] -> c[i+1] re-creates the vertex c[i+1]
    // it removed, under a new descriptor (with Polyhedron_3 the old one dangles)
    std::vector<typename GT::vertex_descriptor> corners;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm)) corners.push_back(target(h, pm));
    for(std::size_t i = 0; i < 3 && !done; ++i)
    {
      for(int mi = 0; mi < 4 && !done; ++mi)
      {
        const Triangle_move m = Triangle_move(mi);
        const halfedge_descriptor h = halfedge(corners[i], corners[(i + 1) % 3], pm).first;
        CGAL_assertion(internal::is_triangle_face(h, pm));
        if(!can_move_triangle(h, m, pm)) continue;
        const halfedge_descriptor nb = move_triangle(h, m, history);
        const auto c2 = classify_triangle(face(nb, pm), pm);
        if(c2.configuration == Triangle_configuration::CANONICAL) { done = true; ++r.separated; continue; }
        history.undo_last();
        // c[i+2] -> c[i] is a side of the restored triangle; its next one ends at the (re-created) c[i+1]
        const auto side = halfedge(corners[(i + 2) % 3], corners[i], pm);
        CGAL_assertion(side.second && internal::is_triangle_face(side.first, pm));
        corners[(i + 1) % 3] = target(next(side.first, pm), pm);
      }
    }
  }

  for(face_descriptor f : triangles())
  {
    switch(classify_triangle(f, pm).configuration)
    {
      case Triangle_configuration::CANONICAL: ++r.canonical; break;
      case Triangle_configuration::SINGULAR_CORNERS: ++r.singular_corners; break;
      case Triangle_configuration::ADJACENT: ++r.adjacent; break;
      case Triangle_configuration::ON_BORDER: ++r.on_border; break;
    }
  }
  return r;
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_TRIANGLE_MOVES_H
