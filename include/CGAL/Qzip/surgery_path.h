// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SURGERY_PATH_H
#define CGAL_QZIP_SURGERY_PATH_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Named_function_parameters.h>
#include <CGAL/Qzip/internal/lazy_property_map.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace Qzip {

namespace internal {

struct Target_reached {};

template <typename Vertex>
struct Stop_at_target : public boost::default_dijkstra_visitor
{
  Vertex t;
  explicit Stop_at_target(Vertex t) : t(t) {}
  template <typename Graph>
  void examine_vertex(Vertex v, const Graph&) const { if(v == t) throw Target_reached(); }
};

// breadth-first search recording predecessors, stopping when the target is discovered
template <typename Vertex, typename PredecessorMap>
struct Record_until_target : public boost::default_bfs_visitor
{
  Vertex t;
  PredecessorMap predecessor;
  Record_until_target(Vertex t, PredecessorMap p) : t(t), predecessor(p) {}
  template <typename Edge, typename Graph>
  void tree_edge(const Edge& e, const Graph& g) const
  {
    put(predecessor, target(e, g), source(e, g));
    if(target(e, g) == t) throw Target_reached();
  }
};

// whether a surgery path may pass through `v`: interior, not on a constrained edge, not on a protected
// face, not on a face that is not a quad (the edges of a triangle count as border edges, paper Sec. 3.2).
template <typename PolygonMesh, typename ECM, typename FCM>
bool is_passable(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm,
                 const ECM& ecm, const FCM& fcm)
{
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
  {
    if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) return false;
    if(get(fcm, face(h, pm)) || !is_quad(h, pm)) return false; // h is not a border halfedge here
  }
  return true;
}

} // namespace internal

/*!
\ingroup PkgQzipPrimitive

computes a surgery path (paper, Sec. 2.4): a shortest simple edge path from `s` to `t` whose inner
vertices are interior vertices incident only to quads that are not protected, and to no constrained
edge (a path meeting a triangle treats its edges as border edges and winds around it), found on the
mesh seen as a Boost graph with `boost::breadth_first_visit()` (unit weights: the fewest edges, hence the
fewest operations) or, with `edge_weight_map`, `boost::dijkstra_shortest_paths_no_init()`. The search
stops at `t` and only touches the vertices it visits (for `Polyhedron_3` without ids, building the vertex index map
costs one pass over the vertices).

\tparam PolygonMesh a model of `FaceGraph` and of `boost::IncidenceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the polygon mesh
\param s, t the two singularities
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{edge_weight_map}
    \cgalParamDescription{a readable property map giving a non-negative `double` weight to each edge}
    \cgalParamDefault{1 for every edge: the path with the fewest edges, hence the fewest operations}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_constrained_map}
    \cgalParamDescription{feature edges; the path never passes through their vertices}
    \cgalParamDefault{no edge is constrained}
  \cgalParamNEnd
  \cgalParamNBegin{face_is_constrained_map}
    \cgalParamDescription{protected faces; the path never passes through their vertices}
    \cgalParamDefault{no face is protected}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex an index from 0 to `num_vertices(pm) - 1`}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
\cgalNamedParamsEnd
\returns the vertices of the path from `s` to `t`, or an empty vector when there is none.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>
shortest_surgery_path(const PolygonMesh& pm,
                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor s,
                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor t,
                      const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  using parameters::choose_parameter;
  using parameters::get_parameter;

  std::vector<vertex_descriptor> path;
  if(s == t) return path;

  const auto weight = choose_parameter(get_parameter(np, Qzip::internal_np::edge_weight),
                                       Constant_property_map<edge_descriptor, double>(1.));
  const auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                    Static_boolean_property_map<edge_descriptor, false>());
  const auto fcm = choose_parameter(get_parameter(np, Qzip::internal_np::face_is_constrained),
                                    Static_boolean_property_map<face_descriptor, false>());
  const auto vim = CGAL::get_initialized_vertex_index_map(pm, np);

  auto passable = [&](vertex_descriptor v) { return v == t || internal::is_passable(v, pm, ecm, fcm); };
  internal::Lazy_property_map<vertex_descriptor, vertex_descriptor> predecessor(GT::null_vertex());
  internal::Blocking_color_map<vertex_descriptor, decltype(passable)> color(passable);
  put(predecessor, s, s);
  try
  {
    if(parameters::is_default_parameter<NamedParameters, Qzip::internal_np::edge_weight_t>::value)
    {
      // unit weights: a breadth-first search finds a path with the fewest edges
      boost::queue<vertex_descriptor> queue;
      put(color, s, boost::gray_color);
      queue.push(s);
      boost::breadth_first_visit(pm, s, queue,
                                 internal::Record_until_target<vertex_descriptor, decltype(predecessor)>(t, predecessor),
                                 color);
    }
    else
    {
      internal::Lazy_property_map<vertex_descriptor, double> distance((std::numeric_limits<double>::max)());
      put(distance, s, 0.);
      boost::dijkstra_shortest_paths_no_init(pm, s, predecessor, distance, weight, vim,
                                             std::less<double>(), boost::closed_plus<double>(), 0.,
                                             internal::Stop_at_target<vertex_descriptor>(t), color);
    }
    return path; // exhausted without reaching t
  }
  catch(const internal::Target_reached&) {}

  for(vertex_descriptor v = t; ; v = get(predecessor, v))
  {
    path.push_back(v);
    if(v == s) break;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SURGERY_PATH_H
