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
#include <limits>
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
(scoring never edits the mesh). Distances are graph distances in edges.

At the start of each batch the context computes, in time linear in the size of the mesh, the
`max_nearest()` closest singularities of every vertex (a breadth-first search from all singularities
at once in which each vertex keeps the first `max_nearest()` distinct sources that reach it: these are
exactly its closest ones, up to ties), the distance of every vertex to the border and the features, and
the closest separatrices; `nearest_singularities()` and `distance_to_separatrix()` are then lookups.
`distance()` runs bounded breadth-first searches, a few of which are kept.

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

  /// the number of closest singularities known at each vertex
  static const std::size_t max_nearest_singularities = 6;

  /// what `nearest_singularities()` returns: a range of `Nearby_singularity` by increasing distance
  struct Neighborhood
  {
    Nearby items[max_nearest_singularities];
    std::size_t size = 0;
    int feature_distance = (std::numeric_limits<int>::max)(); ///< distance to the closest border or feature vertex (`INT_MAX` if none)
    const Nearby* begin() const { return items; }
    const Nearby* end() const { return items + size; }
  };

private:
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<int> >::type Int_map;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<unsigned int> >::type Stamp_map;

  struct Label { vertex_descriptor source; int distance; };

  PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;

  // per batch: index of each vertex, its defect, whether it is a border/feature vertex
  Stamp_map stamp;
  Int_map index_map;
  unsigned int epoch = 0;
  std::vector<vertex_descriptor> by_index;
  std::vector<int> defects;
  std::vector<unsigned char> cut;
  std::vector<int> feature_dist;
  std::vector<Label> near_labels, sep_labels;
  std::vector<unsigned char> near_count, sep_count;

  int m_separatrix_length = 32;
  int m_separatrix_radius = 3;
  double m_mean_face_area = 1;

  // a few breadth-first balls kept for distance()
  struct Slot { vertex_descriptor source; int radius; unsigned int epoch; Stamp_map stamp; Int_map dist; };
  std::vector<Slot> slots;
  std::size_t next_slot = 0;
  int m_distance_radius_hint = 0;
  std::vector<vertex_descriptor> queue;

public:
  /// \cond SKIP_IN_MANUAL
  Scoring_context(PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm),
      stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      index_map(get(CGAL::dynamic_vertex_property_t<int>(), pm))
  {
    for(std::size_t i = 0; i < 4; ++i)
      slots.push_back(Slot{ GT::null_vertex(), -1, 0u, get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm),
                            get(CGAL::dynamic_vertex_property_t<int>(), pm) });
    for(vertex_descriptor v : vertices(pm))
    {
      put(stamp, v, 0u);
      for(Slot& sl : slots) put(sl.stamp, v, 0u);
    }
    // geometric mean: the log-ratios of the sizing term then average to zero over the input
    double log_area = 0;
    std::size_t n = 0;
    for(face_descriptor f : faces(pm))
    {
      const double a = face_area(f);
      if(a > 0) { log_area += std::log(a); ++n; }
    }
    m_mean_face_area = n > 0 ? std::exp(log_area / double(n)) : 1.;
    if(!(m_mean_face_area > 0) || !std::isfinite(m_mean_face_area)) m_mean_face_area = 1.;
  }

  // refreshes everything; returns the singular vertices sorted by position.
  std::vector<vertex_descriptor> begin_batch()
  {
    ++epoch;
    clear_cache();
    by_index.clear(); defects.clear(); cut.clear();
    std::vector<vertex_descriptor> singular;
    for(vertex_descriptor v : vertices(pm))
    {
      if(halfedge(v, pm) == GT::null_halfedge()) continue;
      const bool c = is_border_or_feature(v);
      const int d = c ? internal::vertex_defect_info(v, pm, vpm, ecm, Kernel()).defect
                      : int(internal::valence(v, pm)) - 4;
      put(stamp, v, epoch);
      put(index_map, v, int(by_index.size()));
      by_index.push_back(v);
      defects.push_back(d);
      cut.push_back(c ? 1 : 0);
      if(d != 0) singular.push_back(v);
    }
    // an order that does not depend on descriptors (the seeds' order breaks ties)
    std::sort(singular.begin(), singular.end(), [this](vertex_descriptor a, vertex_descriptor b)
    {
      const Point& pa = get(vpm, a);
      const Point& pb = get(vpm, b);
      if(pa.x() != pb.x()) return pa.x() < pb.x();
      if(pa.y() != pb.y()) return pa.y() < pb.y();
      return pa.z() < pb.z();
    });
    // closest singularities
    std::vector<std::pair<vertex_descriptor, vertex_descriptor> > seeds;
    for(vertex_descriptor v : singular) seeds.emplace_back(v, v);
    label_bfs(seeds, max_nearest_singularities, (std::numeric_limits<int>::max)(), near_labels, near_count);
    // distance to the border and the features
    feature_dist.assign(by_index.size(), (std::numeric_limits<int>::max)());
    queue.clear();
    for(std::size_t i = 0; i < by_index.size(); ++i) if(cut[i]) { feature_dist[i] = 0; queue.push_back(by_index[i]); }
    for(std::size_t i = 0; i < queue.size(); ++i)
    {
      const int d = feature_dist[std::size_t(get(index_map, queue[i]))];
      for(halfedge_descriptor h : halfedges_around_target(halfedge(queue[i], pm), pm))
      {
        const std::size_t j = std::size_t(get(index_map, source(h, pm)));
        if(feature_dist[j] <= d + 1) continue;
        feature_dist[j] = d + 1;
        queue.push_back(source(h, pm));
      }
    }
    // separatrices
    seeds.clear();
    trace_separatrices(singular, seeds);
    label_bfs(seeds, 3, m_separatrix_radius, sep_labels, sep_count);
    return singular;
  }

  void clear_cache() { for(Slot& sl : slots) sl.source = GT::null_vertex(); }
  // the radius the distance queries of the next candidates will need at most
  void set_distance_radius_hint(int r) { m_distance_radius_hint = r; }
  /// \endcond

  /// the mesh.
  const PolygonMesh& mesh() const { return pm; }
  /// the vertex point map.
  VertexPointMap vertex_point_map() const { return vpm; }
  /// the position of `v`.
  Point point(vertex_descriptor v) const { return get(vpm, v); }
  /// the defect of `v` at the start of the batch (see `vertex_defect()`).
  int defect(vertex_descriptor v) const { const int i = index(v); return i < 0 ? 0 : defects[std::size_t(i)]; }
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
  /// the geometric mean of the areas of the faces of the mesh given to the optimizer (the uniform target size).
  double mean_face_area() const { return m_mean_face_area; }

  /// the area of face `f` (half the norm of the sum of the cross products of a fan).
  double face_area(face_descriptor f) const
  {
    Point p[3];
    int k = 0;
    double x = 0, y = 0, z = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
    {
      const Point q = get(vpm, target(h, pm));
      if(k < 2) { p[k++] = q; continue; }
      const auto n = CGAL::cross_product(p[1] - p[0], q - p[0]);
      x += n.x(); y += n.y(); z += n.z();
      p[1] = q;
    }
    return 0.5 * std::sqrt(x * x + y * y + z * z);
  }

  /// the length of the edge (or the distance) from `a` to `b`.
  double length(vertex_descriptor a, vertex_descriptor b) const
  { return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, a), get(vpm, b)))); }

  /// the (at most `max_nearest_singularities`) singularities closest to `v`, `v` excluded, by distance, and
  /// the distance from `v` to the closest border or feature vertex.
  Neighborhood nearest_singularities(vertex_descriptor v) const
  {
    Neighborhood nb;
    const int i = index(v);
    if(i < 0) return nb;
    nb.feature_distance = feature_dist[std::size_t(i)];
    const std::size_t K = max_nearest_singularities;
    for(std::size_t k = 0; k < near_count[std::size_t(i)]; ++k)
    {
      const Label& l = near_labels[std::size_t(i) * K + k];
      if(l.source == v) continue;
      nb.items[nb.size++] = Nearby{ l.source, defect(l.source), l.distance };
    }
    return nb;
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
  /// singularity) of a singularity other than `x1` and `x2`, or `max_radius + 1` if there is none
  /// within `min(max_radius, 3)` edges.
  int distance_to_separatrix(vertex_descriptor v, vertex_descriptor x1, vertex_descriptor x2, int max_radius) const
  {
    const int i = index(v);
    if(i >= 0)
      for(std::size_t k = 0; k < sep_count[std::size_t(i)]; ++k)
      {
        const Label& l = sep_labels[std::size_t(i) * 3 + k];
        if(l.source == x1 || l.source == x2) continue;
        return l.distance <= max_radius ? l.distance : max_radius + 1;
      }
    return max_radius + 1;
  }

private:
  int index(vertex_descriptor v) const { return get(stamp, v) == epoch ? get(index_map, v) : -1; }

  // breadth-first search from all seeds (vertex, label) at once, level by level, in which each vertex keeps
  // the first K distinct labels that reach it (with their distances), up to `max_distance`.
  void label_bfs(const std::vector<std::pair<vertex_descriptor, vertex_descriptor> >& seeds, std::size_t K, int max_distance,
                 std::vector<Label>& labels, std::vector<unsigned char>& count)
  {
    labels.assign(by_index.size() * K, Label{ GT::null_vertex(), 0 });
    count.assign(by_index.size(), 0);
    auto add = [&](std::size_t i, vertex_descriptor l, int d)
    {
      const std::size_t c = count[i];
      if(c == K) return false;
      for(std::size_t k = 0; k < c; ++k) if(labels[i * K + k].source == l) return false;
      labels[i * K + c] = Label{ l, d };
      ++count[i];
      return true;
    };
    std::vector<std::pair<vertex_descriptor, vertex_descriptor> > frontier, next_frontier;
    for(const auto& s : seeds)
    {
      const int i = index(s.first);
      if(i >= 0 && add(std::size_t(i), s.second, 0)) frontier.push_back(s);
    }
    for(int d = 0; !frontier.empty() && d < max_distance; ++d)
    {
      next_frontier.clear();
      for(const auto& f : frontier)
        for(halfedge_descriptor h : halfedges_around_target(halfedge(f.first, pm), pm))
        {
          const vertex_descriptor u = source(h, pm);
          if(add(std::size_t(get(index_map, u)), f.second, d + 1)) next_frontier.emplace_back(u, f.second);
        }
      frontier.swap(next_frontier);
    }
  }

  // straight edge lines from every interior singularity, through regular interior vertices, until a
  // singular, border or feature vertex or `m_separatrix_length` edges; (vertex, owner) pairs.
  void trace_separatrices(const std::vector<vertex_descriptor>& singular,
                          std::vector<std::pair<vertex_descriptor, vertex_descriptor> >& out) const
  {
    for(vertex_descriptor s : singular)
    {
      if(cut[std::size_t(index(s))]) continue;
      for(halfedge_descriptor h0 : halfedges_around_target(halfedge(s, pm), pm))
      {
        halfedge_descriptor o = opposite(h0, pm); // s -> w
        for(int len = 0; len < m_separatrix_length; ++len)
        {
          const vertex_descriptor w = target(o, pm);
          if(w == s) break;
          out.emplace_back(w, s);
          const std::size_t iw = std::size_t(index(w));
          if(defects[iw] != 0 || cut[iw] || internal::valence(w, pm) != 4) break;
          o = internal::rotate_outgoing(opposite(o, pm), 2, pm);
        }
      }
    }
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_SCORING_CONTEXT_H
