// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_OPERATION_LOG_H
#define CGAL_QZIP_INTERNAL_OPERATION_LOG_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/internal/entity_ids.h>
#include <CGAL/Qzip/internal/undo_groups.h>

#include <CGAL/Qzip/quad_operations.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// A journal of atomic operations that can be rolled back exactly (connectivity and positions), most
// recent first, without any copy of the mesh.
//
// Entries name halfedges and vertices by entity ids (see Entity_ids), not by descriptors.
template <typename PolygonMesh, typename VertexPointMap>
class Operation_log
{
public:
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

private:
  typedef typename Entity_ids<vertex_descriptor>::Id Id;


  struct Entry
  {
    bool collapse;
    // collapse: the returned delimiters b->a and d->a; split: the returned halfedge d->v of the new quad
    Id first, second;
    // collapse: the removed vertex c and halfedges b->c, c->d, c->b, d->c
    Id removed_vertex;
    Id removed[4];
    // the kept (collapse) or split vertex, with its position before; the removed vertex's position
    Id moved;
    Point moved_from, removed_at;
  };

  PolygonMesh& pm;
  VertexPointMap vpm;
  Undo_groups<Entry> entries;
  Entity_ids<halfedge_descriptor> halfedge_ids;
  Entity_ids<vertex_descriptor> vertex_ids;

public:
  Operation_log(PolygonMesh& pm, VertexPointMap vpm) : pm(pm), vpm(vpm) {}

  VertexPointMap vertex_point_map() const { return vpm; }
  bool empty() const { return entries.empty(); }
  std::size_t number_of_marks() const { return entries.number_of_marks(); }

  // starts a group of operations that `rollback_to_mark()` undoes as a whole
  void mark() { entries.mark(); }
  // forgets the last mark, keeping its operations in the previous group
  void drop_mark() { entries.drop_mark(); }
  // forgets every operation without undoing it, for a log reused on a mesh rebuilt since
  void clear() { entries.clear(); halfedge_ids.clear(); vertex_ids.clear(); }

  // collapses face(h), keeping target(h), and puts the kept vertex at the midpoint of the two merged ones
  // (a border vertex stays where it is; a kept vertex that takes the border from the removed one takes its
  // place too, so that the border keeps its shape).
  Split_delimiters<PolygonMesh> collapse(halfedge_descriptor h)
  {
    Entry e;
    e.collapse = true;
    const halfedge_descriptor bc = next(next(h, pm), pm), cd = next(bc, pm);
    const halfedge_descriptor removed[4] = { bc, cd, opposite(bc, pm), opposite(cd, pm) };
    const vertex_descriptor a = target(h, pm), c = target(bc, pm);
    for(int i = 0; i < 4; ++i) e.removed[i] = halfedge_ids.name(removed[i]);
    e.removed_vertex = vertex_ids.name(c);
    e.moved = vertex_ids.name(a);
    e.moved_from = get(vpm, a);
    e.removed_at = get(vpm, c);
    const bool kept_on_border = is_border_vertex(a, pm), removed_on_border = is_border_vertex(c, pm);
    const Split_delimiters<PolygonMesh> d = quad_collapse(h, pm);
    for(int i = 0; i < 4; ++i) halfedge_ids.unbind(removed[i]);
    vertex_ids.unbind(c);
    e.first = halfedge_ids.name(d.first);
    e.second = halfedge_ids.name(d.second);
    if(removed_on_border && !kept_on_border) put(vpm, a, e.removed_at);
    else if(!kept_on_border) put(vpm, a, CGAL::midpoint(e.moved_from, e.removed_at));
    entries.push(e);
    return d;
  }

  // splits target(h1) (see split_vertex_into_quad()) and moves both copies a third of the way towards
  // the centroids of their own neighbours; a copy on the border stays where the split vertex was.
  halfedge_descriptor split(halfedge_descriptor h1, halfedge_descriptor h2)
  {
    Entry e;
    e.collapse = false;
    const vertex_descriptor v = target(h1, pm);
    e.moved = vertex_ids.name(v);
    e.moved_from = get(vpm, v);
    const halfedge_descriptor q = split_vertex_into_quad(h1, h2, pm);
    e.first = halfedge_ids.name(q);
    const vertex_descriptor c = target(next(next(q, pm), pm), pm);
    relax(c, e.moved_from);
    relax(v, e.moved_from);
    entries.push(e);
    return q;
  }

  // undoes the operations since the last mark, most recent first, and removes the mark.
  void rollback_to_mark()
  {
    entries.rollback_to_mark([this](const Entry& e) { undo(e); });
    if(entries.empty()) { halfedge_ids.clear(); vertex_ids.clear(); }
  }

private:
  void undo(const Entry& e)
  {
    if(e.collapse)
    {
      const halfedge_descriptor q = split_vertex_into_quad(halfedge_ids[e.first], halfedge_ids[e.second], pm);
      const halfedge_descriptor bc = next(next(q, pm), pm), cd = next(bc, pm);
      const halfedge_descriptor recreated[4] = { bc, cd, opposite(bc, pm), opposite(cd, pm) };
      for(int i = 0; i < 4; ++i) halfedge_ids.rebind(e.removed[i], recreated[i]);
      const vertex_descriptor c = target(bc, pm);
      vertex_ids.rebind(e.removed_vertex, c);
      put(vpm, c, e.removed_at);
    }
    else
    {
      const halfedge_descriptor q = halfedge_ids[e.first];
      const halfedge_descriptor bc = next(next(q, pm), pm), cd = next(bc, pm);
      const vertex_descriptor c = target(bc, pm);
      for(halfedge_descriptor h : { bc, cd, opposite(bc, pm), opposite(cd, pm) }) halfedge_ids.unbind(h);
      vertex_ids.unbind(c);
      quad_collapse(q, pm);
    }
    put(vpm, vertex_ids[e.moved], e.moved_from);
  }

  // a copy on the border takes the place of the split vertex exactly: moving it along the border would cut
  // a corner off, and the border defects are judged from the corner angles
  void relax(vertex_descriptor v, const Point& from)
  {
    if(is_border_vertex(v, pm)) { put(vpm, v, from); return; }
    double x = 0, y = 0, z = 0, n = 0;
    for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    {
      const Point& p = get(vpm, source(h, pm));
      x += p.x(); y += p.y(); z += p.z(); n += 1;
    }
    if(n == 0) return;
    put(vpm, v, Point(from.x() + (x / n - from.x()) / 3., from.y() + (y / n - from.y()) / 3.,
                      from.z() + (z / n - from.z()) / 3.));
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_OPERATION_LOG_H
