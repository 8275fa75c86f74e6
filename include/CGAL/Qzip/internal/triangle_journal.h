// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_TRIANGLE_JOURNAL_H
#define CGAL_QZIP_INTERNAL_TRIANGLE_JOURNAL_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/internal/entity_ids.h>
#include <CGAL/Qzip/internal/undo_groups.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/internal/helpers.h>
#include <CGAL/assertions.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// A journal of the four Euler operations the triangle moves are made of (join_face / split_face,
// join_vertex / split_vertex) and of position changes, undone exactly (connectivity and positions),
// most recent first, without any copy of the mesh.
//
// As in Operation_log, entries name halfedges and vertices by entity ids, because an undo re-creates
// removed elements under new descriptors and meshes recycle the descriptors of removed elements: an id is
// bound when an element is first named, unbound when it is removed, and re-bound when an undo re-creates it.
//
// The inverse pairs (CGAL 5.5 Euler_operations.h):
//   join_face(h)  [keeps face(h), removes edge(h) and face(opposite(h)), returns hp = prev(h)]
//       is undone by split_face(hp, gp) with gp = prev(opposite(h)) taken before the join; the new
//       halfedge next(hp) plays h again and the new face is face(opposite(h)) again.
//   split_face(h1, h2) [returns h3 = next(h1), the new face is face(opposite(h3))] is undone by join_face(h3).
//   join_vertex(h) [removes source(h) and edge(h), returns hp = prev(opposite(h))] is undone by
//       split_vertex(hp, gp) with gp = prev(h) taken before the join; the returned halfedge plays h again.
//   split_vertex(h1, h2) [returns hnew, whose source is the new vertex] is undone by join_vertex(hnew).
template <typename PolygonMesh, typename VertexPointMap>
class Triangle_journal
{
public:
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

private:
  typedef typename Entity_ids<vertex_descriptor>::Id Id;


  enum Kind { JOIN_FACE, SPLIT_FACE, JOIN_VERTEX, SPLIT_VERTEX, MOVE_POINT };

  struct Entry
  {
    Kind kind;
    Id h1 = 0, h2 = 0;          // JOIN_*: the two halfedges of the inverse split; SPLIT_*: the returned halfedge
    Id removed_h = 0, removed_o = 0; // JOIN_*: the removed halfedge and its opposite
    Id vertex = 0;              // JOIN_VERTEX: the removed vertex; MOVE_POINT: the moved vertex
    Point point;                // JOIN_VERTEX: position of the removed vertex; MOVE_POINT: position before
  };

  PolygonMesh& pm;
  VertexPointMap vpm;
  Undo_groups<Entry> entries;
  Entity_ids<halfedge_descriptor> hid;
  Entity_ids<vertex_descriptor> vid;

public:
  Triangle_journal(PolygonMesh& pm, VertexPointMap vpm) : pm(pm), vpm(vpm) {}

  PolygonMesh& mesh() { return pm; }
  VertexPointMap vertex_point_map() const { return vpm; }
  std::size_t number_of_marks() const { return entries.number_of_marks(); }
  std::size_t number_of_entries() const { return entries.size(); }

  void mark() { entries.mark(); }
  void drop_mark() { entries.drop_mark(); }

  // Euler::join_face(h), journaled
  halfedge_descriptor join_face(halfedge_descriptor h)
  {
    Entry e;
    e.kind = JOIN_FACE;
    e.h2 = hid.name(prev(opposite(h, pm), pm));
    e.removed_h = hid.name(h);
    e.removed_o = hid.name(opposite(h, pm));
    const halfedge_descriptor o = opposite(h, pm);
    const vertex_descriptor u = source(h, pm), w = target(h, pm);
    const halfedge_descriptor hp = CGAL::Euler::join_face(h, pm);
    adjust(u); adjust(w);
    hid.unbind(h);
    hid.unbind(o);
    e.h1 = hid.name(hp);
    entries.push(e);
    return hp;
  }

  // Euler::split_face(h1, h2), journaled
  halfedge_descriptor split_face(halfedge_descriptor h1, halfedge_descriptor h2)
  {
    Entry e;
    e.kind = SPLIT_FACE;
    const halfedge_descriptor h3 = CGAL::Euler::split_face(h1, h2, pm);
    adjust(h3);
    e.h1 = hid.name(h3);
    entries.push(e);
    return h3;
  }

  // Euler::join_vertex(h), journaled: removes source(h); the kept vertex does not move.
  halfedge_descriptor join_vertex(halfedge_descriptor h)
  {
    Entry e;
    e.kind = JOIN_VERTEX;
    const vertex_descriptor gone = source(h, pm);
    e.h2 = hid.name(prev(h, pm));
    e.removed_h = hid.name(h);
    e.removed_o = hid.name(opposite(h, pm));
    e.vertex = vid.name(gone);
    e.point = get(vpm, gone);
    const halfedge_descriptor o = opposite(h, pm);
    const halfedge_descriptor hp = CGAL::Euler::join_vertex(h, pm);
    adjust(hp);
    hid.unbind(h);
    hid.unbind(o);
    vid.unbind(gone);
    e.h1 = hid.name(hp);
    entries.push(e);
    return hp;
  }

  // Euler::split_vertex(h1, h2), journaled; the new vertex gets the position of the split one.
  halfedge_descriptor split_vertex(halfedge_descriptor h1, halfedge_descriptor h2)
  {
    Entry e;
    e.kind = SPLIT_VERTEX;
    const Point p = get(vpm, target(h1, pm));
    const halfedge_descriptor hn = CGAL::Euler::split_vertex(h1, h2, pm);
    adjust(hn);
    put(vpm, source(hn, pm), p);
    e.h1 = hid.name(hn);
    entries.push(e);
    return hn;
  }

  void move_point(vertex_descriptor v, const Point& p)
  {
    Entry e;
    e.kind = MOVE_POINT;
    e.vertex = vid.name(v);
    e.point = get(vpm, v);
    put(vpm, v, p);
    entries.push(e);
  }

  // undoes everything since the last mark (everything when there is none) and removes the mark.
  void rollback_to_mark()
  {
    entries.rollback_to_mark([this](const Entry& e) { undo(e); });
    if(entries.empty()) { hid.clear(); vid.clear(); }
  }

private:
  // Euler operations set vertex halfedges to interior halfedges: restore the border convention.
  void adjust(vertex_descriptor v) { CGAL::internal::adjust_incoming_halfedge(v, pm); }
  void adjust(halfedge_descriptor h)
  {
    CGAL::internal::adjust_incoming_halfedge(target(h, pm), pm);
    CGAL::internal::adjust_incoming_halfedge(source(h, pm), pm);
  }

  void undo(const Entry& e)
  {
    switch(e.kind)
    {
      case JOIN_FACE:
      {
        const halfedge_descriptor h3 = CGAL::Euler::split_face(hid[e.h1], hid[e.h2], pm);
        adjust(h3);
        hid.rebind(e.removed_h, h3);
        hid.rebind(e.removed_o, opposite(h3, pm));
        break;
      }
      case SPLIT_FACE:
      {
        const halfedge_descriptor h3 = hid[e.h1];
        hid.unbind(h3);
        hid.unbind(opposite(h3, pm));
        const vertex_descriptor u = source(h3, pm), w = target(h3, pm);
        CGAL::Euler::join_face(h3, pm);
        adjust(u); adjust(w);
        break;
      }
      case JOIN_VERTEX:
      {
        const halfedge_descriptor hn = CGAL::Euler::split_vertex(hid[e.h1], hid[e.h2], pm);
        adjust(hn);
        hid.rebind(e.removed_h, hn);
        hid.rebind(e.removed_o, opposite(hn, pm));
        vid.rebind(e.vertex, source(hn, pm));
        put(vpm, source(hn, pm), e.point);
        break;
      }
      case SPLIT_VERTEX:
      {
        const halfedge_descriptor hn = hid[e.h1];
        const vertex_descriptor gone = source(hn, pm);
        hid.unbind(hn);
        hid.unbind(opposite(hn, pm));
        vid.unbind(gone);
        adjust(CGAL::Euler::join_vertex(hn, pm));
        break;
      }
      case MOVE_POINT:
        put(vpm, vid[e.vertex], e.point);
        break;
    }
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_TRIANGLE_JOURNAL_H
