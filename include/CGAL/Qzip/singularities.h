// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SINGULARITIES_H
#define CGAL_QZIP_SINGULARITIES_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/internal/vertex_defect.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>

namespace CGAL {
namespace Qzip {

namespace internal {

// Reads `vertex_point_map`, `edge_is_constrained_map` and `geom_traits` from `np` once and calls `f(vpm, ecm, gt)`.
template <typename PolygonMesh, typename NamedParameters, typename Function>
auto with_defect_parameters(const PolygonMesh& pm, const NamedParameters& np, Function f)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::edge_descriptor edge_descriptor;
  typedef typename GetGeomTraits<PolygonMesh, NamedParameters>::type Geom_traits;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::const_type Vertex_point_map;
  typedef Static_boolean_property_map<edge_descriptor, false> Default_ECM;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::edge_is_constrained_t, NamedParameters,
                                                       Default_ECM>::type Edge_is_constrained_map;

  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(vertex_point, pm));
  const Edge_is_constrained_map ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                                       Default_ECM());
  return f(vpm, ecm, gt);
}

} // namespace internal

/*!
\ingroup PkgQzipAnalysis

returns the valence of `v`, i.e. the number of edges incident to `v` (0 for an isolated vertex).

\tparam PolygonMesh a model of `HalfedgeGraph`
*/
template <typename PolygonMesh>
std::size_t vertex_valence(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                           const PolygonMesh& pm)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  if(halfedge(v, pm) == GT::null_halfedge())
    return 0;
  std::size_t n = 0;
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
  {
    CGAL_USE(h);
    ++n;
  }
  return n;
}

/*!
\ingroup PkgQzipAnalysis

the kind of singularity a vertex is, as given by the sign of its defect (see `vertex_defect()`).
*/
enum class Singularity_type
{
  REGULAR,        ///< defect 0
  VALENCE_3_LIKE, ///< negative defect: a valence-3 vertex or anything that lacks faces (e.g. valence 2)
  VALENCE_5_LIKE  ///< positive defect: a valence-5 vertex or anything that has too many faces (e.g. valence 6)
};

/*!
\ingroup PkgQzipAnalysis

computes the topological defect of `v`, the signed number of faces by which the fan of `v` differs
from a regular quad grid (Feng, Tong and Desbrun 2021, Sec. 2.1 and Sec. 4.1 "Boundary defects").

- An interior vertex with no incident constrained edge has defect `valence - 4`.
- Otherwise the fan of faces around `v` is cut into sectors by the border edges and the constrained
  edges incident to `v`. For a sector made of `q` faces whose corner angles at `v` sum to `theta`
  (the corner angle of a face at `v` is the angle between the two edges of the face incident to `v`),
  the ideal number of quads is `max(1, round(theta / (pi/2)))`; the sector defect is
  `q - max(1, round(theta / (pi/2)))`, and the defect of `v` is the sum of its sector defects.

So a regular boundary vertex has 1 face at a convex 90 degree corner, 2 faces on a straight border, 3
faces at a 270 degree concave corner, and a vertex inside a constrained (feature) curve is regular when each
side of the curve looks like half a regular vertex. An interior vertex incident to exactly one constrained
edge (the end of a feature curve) has one sector of about 2 pi and the defect is again `valence - 4`.

The paper (Sec. 4.1) writes the ideal *valence* of a boundary vertex as `max(2, floor(theta/(pi/2) + 1/2))`.
Read literally as a valence it is off by one on a straight border (it gives 2, but a regular vertex there
has valence 3 and 2 quads) and at a 270 degree corner (3 instead of 4); it only matches at a convex 90
degree corner, through the clamp. Read as a number of quads it is right at every angle once the clamp is
`max(1, .)`, and this is the reading used here.

Triangles and other polygons are faces like quads: a vertex of a hybrid mesh is measured with the same rule.
So the tip of a canonical triangle (valence 5, see `classify_triangle()`) has defect `+1` here;
`compute_mesh_report()` counts that unit as the triangle's own, not as a singularity.
A negative defect means that `v` behaves as a valence-3 vertex (`Singularity_type::VALENCE_3_LIKE`),
a positive one as a valence-5 vertex. An isolated vertex has defect 0.

\tparam PolygonMesh a model of `FaceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param v a vertex of `pm`
\param pm the polygon mesh
\param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `pm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
                   as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
    \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
                    must be available in `PolygonMesh`.}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_constrained_map}
    \cgalParamDescription{a property map telling which edges are constrained (feature curves); they cut
                          the fans into sectors like border edges do}
    \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<PolygonMesh>::%edge_descriptor`
                   as key type and `bool` as value type}
    \cgalParamDefault{a constant property map returning `false` for any edge}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the defect of `v`
\sa `singularity_type()`, `compute_vertex_defects()`
*/
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
int vertex_defect(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                  const PolygonMesh& pm,
                  const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::with_defect_parameters(pm, np, [&](const auto& vpm, const auto& ecm, const auto& gt)
  {
    return internal::vertex_defect_info(v, pm, vpm, ecm, gt).defect;
  });
}

/*!
\ingroup PkgQzipAnalysis

returns the singularity type of `v` given by the sign of `vertex_defect(v, pm, np)`.

\tparam PolygonMesh a model of `FaceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param v a vertex of `pm`
\param pm the polygon mesh
\param np the same named parameters as `vertex_defect()`
*/
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Singularity_type singularity_type(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                                  const PolygonMesh& pm,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  const int d = vertex_defect(v, pm, np);
  return d < 0 ? Singularity_type::VALENCE_3_LIKE
               : (d > 0 ? Singularity_type::VALENCE_5_LIKE : Singularity_type::REGULAR);
}

/*!
\ingroup PkgQzipAnalysis

computes `vertex_defect(v, pm, np)` for every vertex `v` of `pm` in one pass and stores it with `put(defect_map, v, d)`.

\tparam PolygonMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam VertexDefectMap a model of `WritablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
        as key type and `int` as value type (e.g. `get(CGAL::dynamic_vertex_property_t<int>(), pm)`)
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the polygon mesh
\param defect_map the property map that receives the defect of every vertex
\param np the same named parameters as `vertex_defect()`
\returns the number of vertices with a non-zero defect
*/
template <typename PolygonMesh, typename VertexDefectMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t compute_vertex_defects(const PolygonMesh& pm, VertexDefectMap defect_map,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::with_defect_parameters(pm, np, [&](const auto& vpm, const auto& ecm, const auto& gt)
  {
    std::size_t n = 0;
    for(auto v : vertices(pm))
    {
      const int d = internal::vertex_defect_info(v, pm, vpm, ecm, gt).defect;
      put(defect_map, v, d);
      if(d != 0) ++n;
    }
    return n;
  });
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SINGULARITIES_H
