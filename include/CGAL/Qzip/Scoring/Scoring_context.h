// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_SCORING_CONTEXT_H
#define CGAL_QZIP_SCORING_SCORING_CONTEXT_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/internal/vertex_defect.h>
#include <CGAL/Qzip/internal/rotation.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/property_map.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
A singularity found near a vertex by `Scoring_context::nearest_singularities()`.
*/
template <typename PolygonMesh>
struct Nearby_singularity
{
  typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex; ///< the singular vertex
  int defect;    ///< its defect (negative: v3-like, positive: v5-like)
  int distance;  ///< graph distance in edges
};

/*!
\ingroup PkgQzipOptimizer

What a scoring functor may ask about the mesh while candidates are scored. The optimizer owns it and
refreshes it before each batch; all answers describe the mesh as it was at the start of the batch
(scoring never edits the mesh). Distances are graph distances in edges, found by breadth-first
searches bounded by a radius and memoized during the scoring of one singularity's candidates.

\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap the property maps of the optimizer
*/
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap>
class Scoring_context
{
public:
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef Nearby_singularity<PolygonMesh> Nearby;

  /// what `nearest_singularities()` returns
  struct Neighborhood
  {
    std::vector<Nearby> singularities; ///< the closest ones, by distance (at most `max_nearest()`)
    int feature_distance;              ///< distance to the closest border or feature vertex (`radius() + 1` if none)
  };

private:
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<int> >::type Int_map;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<unsigned int> >::type Stamp_map;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<vertex_descriptor> >::type Vertex_map;
  typedef boost::hash<vertex_descriptor> Hash;

  PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;

  Int_map defect_map;
  Stamp_map defect_stamp;
  unsigned int epoch = 0;

  Stamp_map bfs_stamp;
  Int_map bfs_dist;
  unsigned int bfs_epoch = 0;
  std::vector<vertex_descriptor> queue;

  Stamp_map sep_stamp;
  Vertex_map sep_owner; // null_vertex(): on separatrices of several singularities

  int m_radius = 10;
  std::size_t m_max_nearest = 5;
  int m_separatrix_length = 32;
  double m_mean_face_area = 1;

  Int_map feature_map; // 1 on border and feature vertices (valid with defect_stamp)

  std::unordered_map<vertex_descriptor, Neighborhood, Hash> nearest_cache;

  // a few breadth-first balls kept for distance() (sources of the current candidates)
  static const std::size_t number_of_slots = 6;
  struct Slot { vertex_descriptor source; int radius; unsigned int epoch; Stamp_map stamp; Int_map dist; };
  std::vector<Slot> slots;
  std::size_t next_slot = 0;
  int m_distance_radius_hint = 0;

public:
  /// \cond SKIP_IN_MANUAL
  Scoring_context(PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm),
      defect_map(get(CGAL::dynamic_vertex_property_t<int>(), pm)),
      defect_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      bfs_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      bfs_dist(get(CGAL::dynamic_vertex_property_t<int>(), pm)),
      sep_stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      sep_owner(get(CGAL::dynamic_vertex_property_t<vertex_descriptor>(), pm)),
      feature_map(get(CGAL::dynamic_vertex_property_t<int>(), pm))
  {
    for(std::size_t i = 0; i < number_of_slots; ++i)
      slots.push_back(Slot{ GT::null_vertex(), -1, 0u, get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm),
                            get(CGAL::dynamic_vertex_property_t<int>(), pm) });
    for(vertex_descriptor v : vertices(pm))
    {
      put(defect_stamp, v, 0u);
      put(bfs_stamp, v, 0u);
      put(sep_stamp, v, 0u);
      for(Slot& sl : slots) put(sl.stamp, v, 0u);
    }
    double area = 0;
    std::size_t n = 0;
    for(face_descriptor f : faces(pm)) { area += face_area(f); ++n; }
    m_mean_face_area = n > 0 ? area / double(n) : 1.;
    if(!(m_mean_face_area > 0)) m_mean_face_area = 1.;
  }

  // refreshes the defects and separatrices; returns the singular vertices (any order).
  std::vector<vertex_descriptor> begin_batch()
  {
    ++epoch;
    clear_cache();
    std::vector<vertex_descriptor> singular;
    for(vertex_descriptor v : vertices(pm))
    {
      if(halfedge(v, pm) == GT::null_halfedge()) continue;
      int d;
      const bool cut = is_border_or_feature(v);
      if(cut)
        d = internal::vertex_defect_info(v, pm, vpm, ecm, Kernel()).defect;
      else
        d = int(internal::valence(v, pm)) - 4;
      put(defect_map, v, d);
      put(feature_map, v, cut ? 1 : 0);
      put(defect_stamp, v, epoch);
      if(d != 0) singular.push_back(v);
    }
    trace_separatrices(singular);
    return singular;
  }

  void clear_cache()
  {
    nearest_cache.clear();
    for(Slot& sl : slots) sl.source = GT::null_vertex();
  }
  // the radius the distance queries of the next candidates will need at most
  void set_distance_radius_hint(int r) { m_distance_radius_hint = r; }
  void set_radius(int r) { m_radius = r; }
  /// \endcond

  /// the mesh.
  const PolygonMesh& mesh() const { return pm; }
  /// the vertex point map.
  VertexPointMap vertex_point_map() const { return vpm; }
  /// the position of `v`.
  Point point(vertex_descriptor v) const { return get(vpm, v); }
  /// the defect of `v` at the start of the batch (see `vertex_defect()`).
  int defect(vertex_descriptor v) const { return get(defect_stamp, v) == epoch ? get(defect_map, v) : 0; }
  /// `true` if `v` lies on the border or on a constrained (feature) edge.
  bool is_border_or_feature(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) return true;
    return false;
  }
  /// `true` if `v` is a vertex of a protected face.
  bool is_protected(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(!is_border(h, pm) && get(fcm, face(h, pm))) return true;
    return false;
  }
  /// the radius of the searches of `nearest_singularities()`.
  int radius() const { return m_radius; }
  /// the number of singularities `nearest_singularities()` keeps.
  std::size_t max_nearest() const { return m_max_nearest; }
  /// the mean area of the faces of the mesh given to the optimizer (the uniform target size).
  double mean_face_area() const { return m_mean_face_area; }

  /// the area of face `f` (half the norm of the cross product of the diagonals of a quad, of a fan otherwise).
  double face_area(face_descriptor f) const
  {
    std::vector<Point> p;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm)) p.push_back(get(vpm, target(h, pm)));
    if(p.size() < 3) return 0;
    double x = 0, y = 0, z = 0;
    for(std::size_t i = 1; i + 1 < p.size(); ++i)
    {
      const auto n = CGAL::cross_product(p[i] - p[0], p[i + 1] - p[0]);
      x += n.x(); y += n.y(); z += n.z();
    }
    return 0.5 * std::sqrt(x * x + y * y + z * z);
  }

  /// the length of the edge from `a` to `b`.
  double length(vertex_descriptor a, vertex_descriptor b) const
  { return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, a), get(vpm, b)))); }

  /// the singularities closest to `v` (not `v` itself), at most `max_nearest()` of them within `radius()`
  /// edges, by distance (ties in breadth-first order), and the distance to the closest border or feature vertex.
  const Neighborhood& nearest_singularities(vertex_descriptor v)
  {
    auto it = nearest_cache.find(v);
    if(it != nearest_cache.end()) return it->second;
    Neighborhood nb;
    nb.feature_distance = m_radius + 1;
    int stop_level = m_radius;
    // up to the level where enough singularities are found; the feature distance within that level
    bfs(v, m_radius, [&](vertex_descriptor w, int d)
    {
      if(d > stop_level) return false;
      if(w != v)
      {
        const int dw = defect(w);
        if(dw != 0 && nb.singularities.size() < m_max_nearest)
        {
          nb.singularities.push_back(Nearby{ w, dw, d });
          if(nb.singularities.size() == m_max_nearest) stop_level = d;
        }
        if(nb.feature_distance > m_radius && is_cut(w)) nb.feature_distance = d;
      }
      return true;
    });
    return nearest_cache.emplace(v, nb).first->second;
  }

  /// the graph distance from `a` to `b`, or `max_radius + 1` if it is larger than `max_radius`.
  int distance(vertex_descriptor a, vertex_descriptor b, int max_radius)
  {
    if(a == b) return 0;
    Slot* slot = nullptr;
    for(Slot& sl : slots) if(sl.source == a && sl.radius >= max_radius) { slot = &sl; break; }
    if(slot == nullptr)
    {
      slot = &slots[next_slot];
      next_slot = (next_slot + 1) % slots.size();
      slot->source = a;
      slot->radius = (std::max)(max_radius, m_distance_radius_hint);
      ++slot->epoch;
      queue.clear();
      queue.push_back(a);
      put(slot->stamp, a, slot->epoch);
      put(slot->dist, a, 0);
      for(std::size_t i = 0; i < queue.size(); ++i)
      {
        const vertex_descriptor v = queue[i];
        const int d = get(slot->dist, v);
        if(d >= slot->radius) continue;
        for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
        {
          const vertex_descriptor w = source(h, pm);
          if(get(slot->stamp, w) == slot->epoch) continue;
          put(slot->stamp, w, slot->epoch);
          put(slot->dist, w, d + 1);
          queue.push_back(w);
        }
      }
    }
    if(get(slot->stamp, b) != slot->epoch) return max_radius + 1;
    const int d = get(slot->dist, b);
    return d > max_radius ? max_radius + 1 : d;
  }

  /// the distance from `v` to the closest vertex on a separatrix (a straight edge line leaving a
  /// singularity) of a singularity other than `x1` and `x2`, or `max_radius + 1` if there is none that close.
  int distance_to_separatrix(vertex_descriptor v, vertex_descriptor x1, vertex_descriptor x2, int max_radius)
  {
    int found = max_radius + 1;
    bfs(v, max_radius, [&](vertex_descriptor w, int d)
    {
      if(d >= found) return false;
      if(get(sep_stamp, w) == epoch)
      {
        const vertex_descriptor o = get(sep_owner, w);
        if(o == GT::null_vertex() || (o != x1 && o != x2)) found = d;
      }
      return true;
    });
    return found;
  }

private:
  bool is_cut(vertex_descriptor v) const { return get(defect_stamp, v) == epoch && get(feature_map, v) != 0; }

  // breadth-first search from s up to `radius`; f(w, d) is called once per reached vertex in
  // breadth-first order and returns false to stop the search.
  template <typename F>
  void bfs(vertex_descriptor s, int radius, F f)
  {
    ++bfs_epoch;
    queue.clear();
    queue.push_back(s);
    put(bfs_stamp, s, bfs_epoch);
    put(bfs_dist, s, 0);
    for(std::size_t i = 0; i < queue.size(); ++i)
    {
      const vertex_descriptor v = queue[i];
      const int d = get(bfs_dist, v);
      if(!f(v, d)) return;
      if(d >= radius) continue;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        const vertex_descriptor w = source(h, pm);
        if(get(bfs_stamp, w) == bfs_epoch) continue;
        put(bfs_stamp, w, bfs_epoch);
        put(bfs_dist, w, d + 1);
        queue.push_back(w);
      }
    }
  }

  void mark_separatrix(vertex_descriptor w, vertex_descriptor owner)
  {
    if(get(sep_stamp, w) == epoch)
    {
      if(get(sep_owner, w) != owner) put(sep_owner, w, GT::null_vertex());
      return;
    }
    put(sep_stamp, w, epoch);
    put(sep_owner, w, owner);
  }

  // straight edge lines from every interior singularity, through regular interior vertices, until a
  // singular, border or feature vertex or `m_separatrix_length` edges.
  void trace_separatrices(const std::vector<vertex_descriptor>& singular)
  {
    for(vertex_descriptor s : singular)
    {
      if(is_border_or_feature(s)) continue;
      for(halfedge_descriptor h0 : halfedges_around_target(halfedge(s, pm), pm))
      {
        halfedge_descriptor o = opposite(h0, pm); // s -> w
        for(int len = 0; len < m_separatrix_length; ++len)
        {
          const vertex_descriptor w = target(o, pm);
          if(w == s) break;
          mark_separatrix(w, s);
          if(defect(w) != 0 || internal::valence(w, pm) != 4 || is_cut(w)) break;
          o = internal::rotate_outgoing(opposite(o, pm), 2, pm);
        }
      }
    }
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_SCORING_CONTEXT_H
