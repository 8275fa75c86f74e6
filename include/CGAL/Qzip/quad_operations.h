// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_QUAD_OPERATIONS_H
#define CGAL_QZIP_QUAD_OPERATIONS_H

#include <CGAL/license/Qzip.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/internal/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/assertions.h>

#include <boost/graph/graph_traits.hpp>

#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {

/// \ingroup PkgQzipAtomicOperations
/// The two incoming halfedges that delimit, around a vertex, the fan of a vertex split.
/// `quad_collapse()` returns it and `split_vertex_into_quad()` accepts it, so that the two
/// operations can be chained and undone.
template <typename PolygonMesh>
using Split_delimiters = std::pair<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor,
                                   typename boost::graph_traits<PolygonMesh>::halfedge_descriptor>;

namespace internal {

template <typename PolygonMesh>
std::size_t valence(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm)
{
  std::size_t n = 0;
  for(auto h : halfedges_around_target(halfedge(v, pm), pm)) { (void)h; ++n; }
  return n;
}

template <typename PolygonMesh>
bool is_border_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm)
{
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    if(is_border(h, pm)) return true;
  return false;
}

// appends the vertices adjacent to `v` to `out`.
template <typename PolygonMesh, typename OutputVector>
void collect_neighbors(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                       const PolygonMesh& pm, OutputVector& out)
{
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    out.push_back(source(h, pm));
}

} // namespace internal

/*!
\ingroup PkgQzipAtomicOperations

checks whether `quad_collapse(h, pm)` can be applied without breaking the mesh: `face(h, pm)` must be a
quad with four distinct corners; the kept corner `target(h, pm)` and the removed corner (the opposite one)
must not be adjacent, must not share a face other than `face(h, pm)` nor a neighbor other than the two
remaining corners, and must not both lie on the border; the two remaining corners must keep at least two
incident edges (an interior corner of valence 3 may become a valence-2 vertex: the Q-zip clean-up and
the preprocessing remove those).

\tparam PolygonMesh a model of `FaceGraph`
\param h a halfedge whose face is not the border face
\param pm the polygon mesh
*/
template <typename PolygonMesh>
bool can_collapse_quad(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                       const PolygonMesh& pm)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;

  if(is_border(h, pm) || !is_quad(h, pm)) return false;
  const vertex_descriptor a = target(h, pm);
  const vertex_descriptor b = target(next(h, pm), pm);
  const vertex_descriptor c = target(next(next(h, pm), pm), pm);
  const vertex_descriptor d = source(h, pm);
  if(a == b || a == c || a == d || b == c || b == d || c == d) return false;

  if(internal::is_border_vertex(a, pm) && internal::is_border_vertex(c, pm)) return false;

  // b and d lose one edge each: a border vertex needs 2 left, an interior one 2 as well
  // (a valence-1 vertex would dangle); valence 2 interior results are allowed: they are what
  // the v2/v6 clean-up and the preprocessing handle.
  if(internal::valence(b, pm) < 3 || internal::valence(d, pm) < 3) return false;

  // a and c may share no neighbor besides b and d, and no face besides face(h).
  std::vector<vertex_descriptor> na;
  internal::collect_neighbors(a, pm, na);
  for(auto hc : halfedges_around_target(halfedge(c, pm), pm))
  {
    const vertex_descriptor x = source(hc, pm);
    if(x == a) return false;
    if(x == b || x == d) continue;
    for(vertex_descriptor y : na)
      if(y == x) return false;
  }
  const auto f = face(h, pm);
  for(auto hc : halfedges_around_target(halfedge(c, pm), pm))
  {
    const auto fc = face(hc, pm);
    if(fc == GT::null_face() || fc == f) continue;
    for(auto hf : halfedges_around_face(halfedge(fc, pm), pm))
      if(target(hf, pm) == a) return false;
  }
  return true;
}

/*!
\ingroup PkgQzipAtomicOperations

collapses the quad `face(h, pm)` by merging its corner opposite to `target(h, pm)` into `target(h, pm)`.

With the face cycle `h = d->a`, `a->b`, `b->c`, `c->d`, vertex `c` is removed and its edges are
re-attached to `a`; the edges `b-c` and `c-d` disappear (each merged with `a-b` and `d-a`), as do
the face and vertex `c`. The mesh loses one face, one vertex and two edges, so its Euler characteristic
is unchanged, and every other face keeps its degree. Valences change as
`deg(a) += deg(c) - 2`, `deg(b) -= 1`, `deg(d) -= 1`. Point positions are not changed.

\tparam PolygonMesh a model of `MutableFaceGraph`
\param h a halfedge of the quad to collapse; its target is kept
\param pm the polygon mesh
\pre `can_collapse_quad(h, pm)`
\returns the two halfedges `b->a` and `d->a` (in this order) that delimit the fan that `c`
         brought to `a`: `split_vertex_into_quad(r.first, r.second, pm)` undoes the collapse.
*/
template <typename PolygonMesh>
Split_delimiters<PolygonMesh>
quad_collapse(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, PolygonMesh& pm)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  CGAL_precondition(can_collapse_quad(h, pm));

  const halfedge_descriptor h3 = h;                  // d->a, kept
  const halfedge_descriptor h0 = next(h3, pm);       // a->b, kept
  const halfedge_descriptor h1 = next(h0, pm);       // b->c, removed
  const halfedge_descriptor h2 = next(h1, pm);       // c->d, removed
  const halfedge_descriptor t1 = opposite(h1, pm);   // c->b, replaced by h0
  const halfedge_descriptor t2 = opposite(h2, pm);   // d->c, replaced by h3
  const vertex_descriptor a = target(h3, pm);
  const vertex_descriptor b = target(h0, pm);
  const vertex_descriptor c = target(h1, pm);
  const vertex_descriptor d = target(h2, pm);
  const face_descriptor f = face(h0, pm);
  const face_descriptor f1 = face(t1, pm);
  const face_descriptor f2 = face(t2, pm);

  // Re-root at a every halfedge that points to c, collected before any change.
  std::vector<halfedge_descriptor> into_c;
  for(halfedge_descriptor hc : halfedges_around_target(h1, pm))
    if(hc != h1 && hc != t2) into_c.push_back(hc);

  // Neighbours of t1 and t2 in their cycles, with the substitutions t1 -> h0 and t2 -> h3
  // (t2 directly precedes t1 when c has valence 2).
  halfedge_descriptor pred1 = prev(t1, pm), succ1 = next(t1, pm);
  halfedge_descriptor pred2 = prev(t2, pm), succ2 = next(t2, pm);
  if(pred1 == t2) pred1 = h3;
  if(succ2 == t1) succ2 = h0;

  for(halfedge_descriptor hc : into_c) set_target(hc, a, pm);

  set_next(pred1, h0, pm); set_next(h0, succ1, pm); set_face(h0, f1, pm);
  set_next(pred2, h3, pm); set_next(h3, succ2, pm); set_face(h3, f2, pm);
  if(f1 != GT::null_face()) set_halfedge(f1, h0, pm);
  if(f2 != GT::null_face()) set_halfedge(f2, h3, pm);

  set_halfedge(a, h3, pm);
  set_halfedge(b, h0, pm);                // a->b
  set_halfedge(d, opposite(h3, pm), pm);  // a->d

  remove_edge(edge(h1, pm), pm);
  remove_edge(edge(h2, pm), pm);
  remove_face(f, pm);
  remove_vertex(c, pm);

  CGAL::internal::adjust_incoming_halfedge(a, pm);
  CGAL::internal::adjust_incoming_halfedge(b, pm);
  CGAL::internal::adjust_incoming_halfedge(d, pm);

  return std::make_pair(opposite(h0, pm), h3);
}

/*!
\ingroup PkgQzipAtomicOperations

checks whether `split_vertex_into_quad(h1, h2, pm)` applies: `h1` and `h2` are distinct halfedges
with the same target and distinct sources.
*/
template <typename PolygonMesh>
bool can_split_vertex_into_quad(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h1,
                                typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h2,
                                const PolygonMesh& pm)
{
  return h1 != h2 && target(h1, pm) == target(h2, pm) && source(h1, pm) != source(h2, pm);
}

/*!
\ingroup PkgQzipAtomicOperations

splits the vertex `v = target(h1, pm)` into two vertices joined by a new quad; the exact inverse of
`quad_collapse()`.

Let `b = source(h1, pm)` and `d = source(h2, pm)`. Turning counterclockwise around `v` from the
edge `v-b` to the edge `v-d`, the edges met strictly in between move to a new vertex `c`, which is
also joined to `b` and `d` by two new edges; `v` keeps `v-b`, `v-d` and the other edges. The new face
is the quad `(v, b, c, d)`. One vertex, one face and two edges are added; every other face keeps
its degree. If `k` edges lie strictly between, `deg(c) = k + 2`, `deg(v) -= k`, and `deg(b)` and
`deg(d)` grow by one. The new vertex gets no point: its position is the caller's choice.

\tparam PolygonMesh a model of `MutableFaceGraph`
\pre `can_split_vertex_into_quad(h1, h2, pm)`
\returns `h2`, which now lies on the new quad with `v` as target, so that `quad_collapse(h2, pm)`
         undoes the split.
*/
template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
split_vertex_into_quad(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h1,
                       typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h2,
                       PolygonMesh& pm)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  CGAL_precondition(can_split_vertex_into_quad(h1, h2, pm));

  const vertex_descriptor v = target(h1, pm);
  const vertex_descriptor b = source(h1, pm);
  const vertex_descriptor d = source(h2, pm);
  const halfedge_descriptor g0 = opposite(h1, pm);   // v->b, will lie on the new quad
  const halfedge_descriptor gm_opp = h2;             // d->v, will lie on the new quad

  // Outgoing halfedges strictly counterclockwise between v->b and v->d move to c; the
  // counterclockwise successor of an outgoing halfedge o is opposite(prev(o)).
  std::vector<halfedge_descriptor> to_c;
  for(halfedge_descriptor o = opposite(prev(g0, pm), pm); o != opposite(h2, pm);
      o = opposite(prev(o, pm), pm))
    to_c.push_back(opposite(o, pm));

  const face_descriptor f0 = face(g0, pm);     // first face of the fan
  const face_descriptor fm = face(gm_opp, pm); // last face of the fan
  halfedge_descriptor pred0 = prev(g0, pm), succ0 = next(g0, pm);
  halfedge_descriptor predm = prev(gm_opp, pm), succm = next(gm_opp, pm);

  const vertex_descriptor c = add_vertex(pm);
  const face_descriptor q = add_face(pm);
  const halfedge_descriptor nb = halfedge(add_edge(pm), pm);   // b->c on q; opposite c->b replaces g0
  const halfedge_descriptor nd = halfedge(add_edge(pm), pm);   // c->d on q; opposite d->c replaces gm_opp
  const halfedge_descriptor nb_o = opposite(nb, pm);
  const halfedge_descriptor nd_o = opposite(nd, pm);

  // With a fan of a single face, g0 directly follows gm_opp in that face.
  if(pred0 == gm_opp) pred0 = nd_o;
  if(succm == g0) succm = nb_o;

  for(halfedge_descriptor x : to_c) set_target(x, c, pm);
  set_target(nb, c, pm);  set_target(nb_o, b, pm);
  set_target(nd, d, pm);  set_target(nd_o, c, pm);

  set_next(pred0, nb_o, pm); set_next(nb_o, succ0, pm); set_face(nb_o, f0, pm);
  set_next(predm, nd_o, pm); set_next(nd_o, succm, pm); set_face(nd_o, fm, pm);
  if(f0 != GT::null_face()) set_halfedge(f0, nb_o, pm);
  if(fm != GT::null_face()) set_halfedge(fm, nd_o, pm);

  set_next(g0, nb, pm); set_next(nb, nd, pm); set_next(nd, gm_opp, pm); set_next(gm_opp, g0, pm);
  set_face(g0, q, pm); set_face(nb, q, pm); set_face(nd, q, pm); set_face(gm_opp, q, pm);
  set_halfedge(q, g0, pm);

  set_halfedge(c, nb, pm);
  set_halfedge(v, gm_opp, pm);
  set_halfedge(b, nb_o, pm);
  set_halfedge(d, nd, pm);

  CGAL::internal::adjust_incoming_halfedge(v, pm);
  CGAL::internal::adjust_incoming_halfedge(c, pm);
  CGAL::internal::adjust_incoming_halfedge(b, pm);
  CGAL::internal::adjust_incoming_halfedge(d, pm);
  return h2;
}

/*!
\ingroup PkgQzipAtomicOperations
same as `split_vertex_into_quad(d.first, d.second, pm)`.
*/
template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
split_vertex_into_quad(const Split_delimiters<PolygonMesh>& d, PolygonMesh& pm)
{
  return split_vertex_into_quad(d.first, d.second, pm);
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_QUAD_OPERATIONS_H
