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

#include <CGAL/Qzip/quad_operations.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <map>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// The atomic operations of one Q-zip, applied through this log so that they can be rolled back exactly
// (connectivity and positions) in reverse order, without any copy of the mesh.
//
// Rolling back a collapse re-creates the removed vertex, face and edges under new descriptors; older
// entries may still name the removed ones, so the re-created elements are recorded in a map from the
// descriptor an entry knew to the live one. Lookups are single-step: an entry's descriptors denote
// elements alive when the entry was written, and whenever an element is re-created the map entry of
// its old descriptor is overwritten, so a lookup always yields the element the entry meant even when
// descriptors are recycled by the mesh.
template <typename PolygonMesh, typename VertexPointMap>
class Operation_log
{
public:
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

private:
  struct Entry
  {
    bool collapse;
    // collapse: the returned delimiters; split: the returned halfedge (first) of the new quad
    halfedge_descriptor first, second;
    // collapse: the removed vertex and the halfedges b->c, c->d and their opposites; split: the new vertex
    vertex_descriptor removed_vertex;
    halfedge_descriptor removed_bc, removed_cd, removed_cb, removed_dc;
    // positions before the operation: the kept/split vertex and the removed vertex
    vertex_descriptor moved;
    Point moved_from, removed_at;
  };

  PolygonMesh& pm;
  VertexPointMap vpm;
  std::vector<Entry> entries;

public:
  Operation_log(PolygonMesh& pm, VertexPointMap vpm) : pm(pm), vpm(vpm) {}

  VertexPointMap vertex_point_map() const { return vpm; }
  std::size_t size() const { return entries.size(); }
  bool empty() const { return entries.empty(); }
  void clear() { entries.clear(); }

  // collapses face(h), keeping target(h), and puts the kept vertex at the midpoint of the two merged ones.
  Split_delimiters<PolygonMesh> collapse(halfedge_descriptor h)
  {
    Entry e;
    e.collapse = true;
    e.removed_bc = next(next(h, pm), pm);
    e.removed_cd = next(e.removed_bc, pm);
    e.removed_cb = opposite(e.removed_bc, pm);
    e.removed_dc = opposite(e.removed_cd, pm);
    e.removed_vertex = target(e.removed_bc, pm);
    e.moved = target(h, pm);
    e.moved_from = get(vpm, e.moved);
    e.removed_at = get(vpm, e.removed_vertex);
    const Split_delimiters<PolygonMesh> d = quad_collapse(h, pm);
    e.first = d.first;
    e.second = d.second;
    put(vpm, e.moved, CGAL::midpoint(e.moved_from, e.removed_at));
    entries.push_back(e);
    return d;
  }

  // splits target(h1) (see split_vertex_into_quad()) and moves both copies a third of the way towards
  // the centroids of their own neighbours.
  halfedge_descriptor split(halfedge_descriptor h1, halfedge_descriptor h2)
  {
    Entry e;
    e.collapse = false;
    e.moved = target(h1, pm);
    e.moved_from = get(vpm, e.moved);
    const halfedge_descriptor q = split_vertex_into_quad(h1, h2, pm);
    e.first = q;
    e.removed_vertex = target(next(next(q, pm), pm), pm); // the new vertex
    put(vpm, e.removed_vertex, e.moved_from);
    relax(e.removed_vertex, e.moved_from);
    relax(e.moved, e.moved_from);
    entries.push_back(e);
    return q;
  }

  // undoes every logged operation, most recent first, restoring connectivity and positions.
  void rollback()
  {
    std::map<vertex_descriptor, vertex_descriptor> vmap;
    std::map<halfedge_descriptor, halfedge_descriptor> hmap;
    auto rv = [&vmap](vertex_descriptor v) { auto it = vmap.find(v); return it == vmap.end() ? v : it->second; };
    auto rh = [&hmap](halfedge_descriptor h) { auto it = hmap.find(h); return it == hmap.end() ? h : it->second; };
    for(auto it = entries.rbegin(); it != entries.rend(); ++it)
    {
      const Entry& e = *it;
      if(e.collapse)
      {
        const halfedge_descriptor q = split_vertex_into_quad(rh(e.first), rh(e.second), pm);
        const halfedge_descriptor bc = next(next(q, pm), pm), cd = next(bc, pm);
        const vertex_descriptor c = target(bc, pm);
        vmap[e.removed_vertex] = c;
        hmap[e.removed_bc] = bc;
        hmap[e.removed_cd] = cd;
        hmap[e.removed_cb] = opposite(bc, pm);
        hmap[e.removed_dc] = opposite(cd, pm);
        put(vpm, c, e.removed_at);
        put(vpm, rv(e.moved), e.moved_from);
      }
      else
      {
        quad_collapse(rh(e.first), pm);
        put(vpm, rv(e.moved), e.moved_from);
      }
    }
    entries.clear();
  }

private:
  void relax(vertex_descriptor v, const Point& from)
  {
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
