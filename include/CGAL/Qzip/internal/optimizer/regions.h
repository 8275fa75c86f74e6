// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_OPTIMIZER_REGIONS_H
#define CGAL_QZIP_INTERNAL_OPTIMIZER_REGIONS_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/quad_quality.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// The vertices within `radius` edges of `seeds`, in breadth-first order (the seeds first, each once), and
// in `level` the distance of each to the seeds. `mark(v)` marks `v` as reached and says whether it was
// not reached before: the caller chooses the marks (a stamp property map, a hash set).
template <typename PolygonMesh, typename Mark>
std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>
vertex_ball(const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& seeds, int radius,
            const PolygonMesh& pm, std::vector<int>& level, Mark mark)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> out;
  level.clear();
  for(vertex_descriptor v : seeds)
    if(mark(v)) { out.push_back(v); level.push_back(0); }
  for(std::size_t i = 0; i < out.size(); ++i)
  {
    if(level[i] >= radius) continue;
    for(const auto h : halfedges_around_target(halfedge(out[i], pm), pm))
    {
      const vertex_descriptor w = source(h, pm);
      if(!mark(w)) continue;
      out.push_back(w);
      level.push_back(level[i] + 1);
    }
  }
  return out;
}

// The quads incident to the vertices of `region`, each once (in the order of their descriptors).
template <typename PolygonMesh>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>
quads_around(const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& region, const PolygonMesh& pm)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> quads;
  for(const auto v : region)
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(!is_border(h, pm) && is_quad(h, pm)) quads.push_back(face(h, pm));
  std::sort(quads.begin(), quads.end());
  quads.erase(std::unique(quads.begin(), quads.end()), quads.end());
  return quads;
}

// The number of inverted quads (scaled Jacobian <= 0) incident to the vertices of `region`, and the
// smallest scaled Jacobian among these quads (1 if none): what the optimizer's quality guard compares
// before and after a surgery.
template <typename PolygonMesh, typename VertexPointMap>
std::pair<std::size_t, double>
region_quality(const std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& region,
               const PolygonMesh& pm, const VertexPointMap& vpm)
{
  const auto quads = quads_around(region, pm);
  return quads_quality(quads.begin(), quads.end(), pm, vpm);
}

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_OPTIMIZER_REGIONS_H
