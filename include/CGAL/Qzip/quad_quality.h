// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_QUAD_QUALITY_H
#define CGAL_QZIP_QUAD_QUALITY_H

#include <CGAL/license/Qzip.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipAnalysis

computes the scaled Jacobian of the quad `f`: the minimum over its four corners of
`((e1 x e2) . n) / (|e1| |e2|)`, where `e1` and `e2` are the edges leaving the corner towards the next and
the previous corner of `f`, and `n` is the unit Newell normal of `f`.

The value lies in `[-1, 1]`: 1 for a rectangle, less for sheared quads, and 0 or less for a quad with a
flat, reflex or folded corner (an *inverted* quad). A degenerate quad (a zero-length edge or a zero
Newell normal) gives 0.

\tparam PolygonMesh a model of `FaceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param f a quad face of `pm`
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
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\pre `f` is a quad: `CGAL::is_quad(halfedge(f, pm), pm)`
*/
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
double quad_scaled_jacobian(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                            const PolygonMesh& pm,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<PolygonMesh, NamedParameters>::type Geom_traits;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::const_type Vertex_point_map;
  typedef typename Geom_traits::Vector_3 Vector_3;

  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(vertex_point, pm));
  auto vector = gt.construct_vector_3_object();
  auto cross = gt.construct_cross_product_vector_3_object();
  auto dot = gt.compute_scalar_product_3_object();
  auto squared_length = gt.compute_squared_length_3_object();

  CGAL_precondition(is_quad(halfedge(f, pm), pm));
  auto h = halfedge(f, pm);
  const auto& p0 = get(vpm, target(h, pm)); h = next(h, pm);
  const auto& p1 = get(vpm, target(h, pm)); h = next(h, pm);
  const auto& p2 = get(vpm, target(h, pm)); h = next(h, pm);
  const auto& p3 = get(vpm, target(h, pm));

  // Newell normal of a quad: the cross product of its diagonals (twice the vector area)
  const Vector_3 n = cross(vector(p0, p2), vector(p1, p3));
  const double n_length = std::sqrt(CGAL::to_double(squared_length(n)));
  if(!(n_length > 0))
    return 0;

  const std::array<Vector_3, 4> e = {{ vector(p0, p1), vector(p1, p2), vector(p2, p3), vector(p3, p0) }};
  double result = 1;
  for(int i = 0; i < 4; ++i)
  {
    // corner p_{i+1}: the edge to the next corner is e[i+1], the edge to the previous corner is -e[i]
    const Vector_3& to_next = e[(i + 1) % 4];
    const Vector_3& to_prev = e[i];
    const double l = std::sqrt(CGAL::to_double(squared_length(to_next)) * CGAL::to_double(squared_length(to_prev)));
    if(!(l > 0))
      return 0;
    // (to_next x (-to_prev)) . n = (to_prev x to_next) . n
    const double j = CGAL::to_double(dot(cross(to_prev, to_next), n)) / (l * n_length);
    result = (std::min)(result, j);
  }
  return result;
}

namespace internal {

// The number of inverted quads (scaled Jacobian <= 0) among the quads [first, last) and their smallest scaled
// Jacobian (1 if none).
template <typename FaceIterator, typename PolygonMesh, typename VertexPointMap>
std::pair<std::size_t, double> quads_quality(FaceIterator first, FaceIterator last, const PolygonMesh& pm,
                                             const VertexPointMap& vpm)
{
  std::size_t inverted = 0;
  double worst = 1;
  for(; first != last; ++first)
  {
    const double j = quad_scaled_jacobian(*first, pm, CGAL::parameters::vertex_point_map(vpm));
    if(j <= 0) ++inverted;
    worst = (std::min)(worst, j);
  }
  return std::make_pair(inverted, worst);
}

} // namespace internal

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_QUAD_QUALITY_H
