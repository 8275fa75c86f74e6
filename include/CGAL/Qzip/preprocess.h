// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_PREPROCESS_H
#define CGAL_QZIP_PREPROCESS_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Named_function_parameters.h>
#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/singularities.h>
#include <CGAL/Qzip/quad_quality.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <limits>
#include <vector>

namespace CGAL {
namespace Qzip {

/// \ingroup PkgQzipPreprocessing
/// What `preprocess_valences()` did.
struct Preprocess_result
{
  std::size_t removed_valence_2 = 0;   ///< interior valence-2 vertices removed (one quad collapse each)
  std::size_t vertex_splits = 0;       ///< vertex splits performed on vertices of valence 6 or more
  bool converged = true;               ///< no vertex is left to fix (interior valence 2 or >= 6, border defect >= 2)
};

namespace internal {

template <typename PolygonMesh, typename VPM, typename ECM>
bool is_free_interior_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                             const PolygonMesh& pm, const ECM& ecm)
{
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) return false;
  return true;
}

template <typename PolygonMesh, typename FCM>
bool touches_protected_face(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                            const PolygonMesh& pm, const FCM& fcm)
{
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    if(!is_border(h, pm) && get(fcm, face(h, pm))) return true;
  return false;
}

// moves `v` the fraction `t` of the way from `from` towards the centroid of `targets`.
template <typename PolygonMesh, typename VPM, typename VertexRange>
void move_towards_centroid(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                           const VertexRange& targets, const typename boost::property_traits<VPM>::value_type& from,
                           double t, VPM vpm)
{
  typedef typename boost::property_traits<VPM>::value_type Point;
  if(targets.empty()) return;
  double x = 0, y = 0, z = 0;
  for(auto w : targets) { const Point& p = get(vpm, w); x += p.x(); y += p.y(); z += p.z(); }
  const double n = double(targets.size());
  put(vpm, v, Point(from.x() + (x / n - from.x()) * t, from.y() + (y / n - from.y()) * t,
                    from.z() + (z / n - from.z()) * t));
}

// the smallest scaled Jacobian of the quads around `a` and `b`
template <typename PolygonMesh, typename VPM>
double worst_quad_around(typename boost::graph_traits<PolygonMesh>::vertex_descriptor a,
                         typename boost::graph_traits<PolygonMesh>::vertex_descriptor b,
                         const PolygonMesh& pm, VPM vpm)
{
  double worst = 1;
  for(auto v : { a, b })
    for(auto h : halfedges_around_target(halfedge(v, pm), pm))
      if(!is_border(h, pm) && is_quad(h, pm))
        worst = (std::min)(worst, quad_scaled_jacobian(face(h, pm), pm, CGAL::parameters::vertex_point_map(vpm)));
  return worst;
}

// removes the interior valence-2 vertex `v` by collapsing one of its two quads into the far corner.
template <typename PolygonMesh>
bool remove_valence_2_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, PolygonMesh& pm)
{
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
  {
    // with next(h) = v->b, the halfedge b->x ends at the corner x of face(h) opposite to v
    const auto to_far = next(next(h, pm), pm);
    if(!is_border(to_far, pm) && can_collapse_quad(to_far, pm))
    {
      quad_collapse(to_far, pm);
      return true;
    }
  }
  return false;
}

// splits the high-valence vertex `v` once: the new vertex takes a fan of k edges, chosen so that the two
// copies are as regular as possible and the two delimiting neighbours (which gain one edge) are the
// least loaded ones. A border vertex (`border_defect` is its defect) keeps the border: the fan of the
// new, interior vertex contains no border face, and k is chosen to bring the defect closest to 0.
template <typename PolygonMesh, typename VPM>
bool split_high_valence_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                               PolygonMesh& pm, VPM vpm, bool border = false, int border_defect = 0)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  std::vector<halfedge_descriptor> in; // incoming halfedges, clockwise order (halfedges_around_target)
  for(auto h : halfedges_around_target(halfedge(v, pm), pm)) in.push_back(h);
  const int deg = int(in.size());
  long best_cost = (std::numeric_limits<long>::max)();
  halfedge_descriptor best1 = in[0], best2 = in[0];
  for(int i = 0; i < deg; ++i)
    for(int k = 1; k <= 3 && k < deg - 1; ++k)
    {
      // the fan of the new vertex lies counterclockwise from in[i]: that is clockwise order reversed,
      // so the second delimiter is k+1 steps back in `in`.
      const halfedge_descriptor h1 = in[i], h2 = in[(i - (k + 1) + 2 * deg) % deg];
      if(!can_split_vertex_into_quad(h1, h2, pm)) continue;
      if(border)
      {
        bool interior_fan = true;
        halfedge_descriptor o = opposite(h1, pm);
        for(int f = 0; f <= k; ++f, o = opposite(prev(o, pm), pm))
          if(is_border(o, pm)) interior_fan = false;
        if(!interior_fan) continue;
      }
      const long dc = k + 2, dv = deg - k;
      const long db = long(valence(source(h1, pm), pm)) + 1, dd = long(valence(source(h2, pm), pm)) + 1;
      auto irr = [](long d) { return d == 4 ? 0L : (d >= 6 || d <= 2 ? 100L * (d > 4 ? d - 4 : 4 - d) : 1L); };
      const long v_cost = border ? 10L * std::abs(long(border_defect) - k) : irr(dv);
      const long cost = 10 * (irr(dc) + v_cost) + irr(db) + irr(dd);
      if(cost < best_cost) { best_cost = cost; best1 = h1; best2 = h2; }
    }
  if(best1 == best2) return false;
  const auto from = get(vpm, v);
  const halfedge_descriptor q = split_vertex_into_quad(best1, best2, pm);
  const vertex_descriptor c = target(next(next(q, pm), pm), pm);
  std::vector<vertex_descriptor> nc, nv;
  for(auto h : halfedges_around_target(halfedge(c, pm), pm)) nc.push_back(source(h, pm));
  for(auto h : halfedges_around_target(halfedge(v, pm), pm)) nv.push_back(source(h, pm));
  // both copies move towards the centroids of their own neighbours, by the fraction that gives the best
  // worst quad around them (a fixed fraction can invert a quad on a curved or stretched fan)
  double best_t = 0.5, best_quality = -2;
  for(double t : { 1., 0.75, 0.5, 1. / 3., 0.25, 1. / 6., 0.1 })
  {
    move_towards_centroid<PolygonMesh>(c, nc, from, t, vpm);
    move_towards_centroid<PolygonMesh>(v, nv, from, t, vpm);
    const double quality = worst_quad_around(c, v, pm, vpm);
    if(quality > best_quality) { best_quality = quality; best_t = t; }
  }
  move_towards_centroid<PolygonMesh>(c, nc, from, best_t, vpm);
  move_towards_centroid<PolygonMesh>(v, nv, from, best_t, vpm);
  return true;
}

} // namespace internal

/*!
\ingroup PkgQzipPreprocessing

brings every interior vertex of `pm` to valence 3, 4 or 5, as the Q-zip primitive assumes (paper, Sec. 2.1):
interior valence-2 vertices are removed by collapsing one of their two quads (their two neighbours lose
one edge each), and interior vertices of valence 6 or more are split into two vertices joined by a new
quad until every copy has valence at most 5. The operations are repeated until nothing is left to do.
Only quad collapses and vertex splits are used, so no face changes its degree and the Euler
characteristic is preserved. Vertices on a constrained edge are left untouched. A border vertex whose
defect (measured against its angle, `vertex_defect()`) is 2 or more is split likewise, the new vertex
taking a fan of interior faces, so that the border keeps its vertices and the defect drops; border
defects of -1 and +1 are left to the Q-zip pairing, and negative border defects of -2 or less (a
reflex corner with a single quad) are not changed.

The two copies of a split vertex are moved from its position towards the centroids of their own neighbours, by
the fraction (from 0.1 to 1) that gives the best worst quad around them.

\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the polygon mesh
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `pm`}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_constrained_map}
    \cgalParamDescription{a property map telling which edges are feature edges; their vertices are not touched}
    \cgalParamDefault{no edge is constrained}
  \cgalParamNEnd
  \cgalParamNBegin{face_is_constrained_map}
    \cgalParamDescription{a property map telling which faces are protected; their vertices are not touched}
    \cgalParamDefault{no face is protected}
  \cgalParamNEnd
\cgalNamedParamsEnd
\returns the numbers of operations performed and whether every interior free vertex has valence 3 to 5
and every free border vertex a defect below 2.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Preprocess_result preprocess_valences(PolygonMesh& pm, const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::edge_descriptor edge_descriptor;
  using parameters::choose_parameter;
  using parameters::get_parameter;

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(vertex_point, pm));
  auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                              Static_boolean_property_map<edge_descriptor, false>());
  auto fcm = choose_parameter(get_parameter(np, Qzip::internal_np::face_is_constrained),
                              Static_boolean_property_map<typename boost::graph_traits<PolygonMesh>::face_descriptor, false>());
  typedef decltype(vpm) VPM;

  enum Action { NOTHING, REMOVE_VALENCE_2, SPLIT_INTERIOR, SPLIT_BORDER };
  auto defect_of = [&](vertex_descriptor v)
  { return vertex_defect(v, pm, CGAL::parameters::vertex_point_map(vpm).edge_is_constrained_map(ecm)); };
  auto action = [&](vertex_descriptor v) -> Action
  {
    if(halfedge(v, pm) == boost::graph_traits<PolygonMesh>::null_halfedge()) return NOTHING;
    if(internal::touches_protected_face(v, pm, fcm)) return NOTHING;
    const std::size_t d = internal::valence(v, pm);
    if(internal::is_free_interior_vertex<PolygonMesh, VPM>(v, pm, ecm))
      return d == 2 ? REMOVE_VALENCE_2 : (d >= 6 ? SPLIT_INTERIOR : NOTHING);
    bool constrained = false;
    for(auto h : halfedges_around_target(halfedge(v, pm), pm)) if(get(ecm, edge(h, pm))) constrained = true;
    if(constrained || !is_border(v, pm) || d < 4) return NOTHING;
    return defect_of(v) >= 2 ? SPLIT_BORDER : NOTHING;
  };

  Preprocess_result result;
  // each pass handles every offending vertex once; a split may push a neighbour to 6, handled next pass.
  const std::size_t max_passes = 64;
  for(std::size_t pass = 0; pass < max_passes; ++pass)
  {
    std::vector<vertex_descriptor> todo;
    for(vertex_descriptor v : vertices(pm))
      if(action(v) != NOTHING) todo.push_back(v);
    if(todo.empty()) { result.converged = true; return result; }
    bool progress = false;
    for(vertex_descriptor v : todo)
    {
      switch(action(v))
      {
        case REMOVE_VALENCE_2:
          if(internal::remove_valence_2_vertex(v, pm)) { ++result.removed_valence_2; progress = true; }
          break;
        case SPLIT_INTERIOR:
          if(internal::split_high_valence_vertex(v, pm, vpm)) { ++result.vertex_splits; progress = true; }
          break;
        case SPLIT_BORDER:
          if(internal::split_high_valence_vertex(v, pm, vpm, true, defect_of(v))) { ++result.vertex_splits; progress = true; }
          break;
        case NOTHING:
          break;
      }
    }
    if(!progress) break;
  }
  result.converged = true;
  for(vertex_descriptor v : vertices(pm))
    if(action(v) != NOTHING) result.converged = false;
  return result;
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_PREPROCESS_H
