// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_ROTATION_H
#define CGAL_QZIP_INTERNAL_ROTATION_H

#include <CGAL/license/Qzip.h>

#include <CGAL/assertions.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Qzip {
namespace internal {

// Rotations of outgoing halfedges around their source. Faces are counterclockwise, face(h) is on the
// left of h; turning counterclockwise from the outgoing halfedge o crosses face(o).

template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
ccw(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor o, const PolygonMesh& pm)
{ return opposite(prev(o, pm), pm); }

template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
cw(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor o, const PolygonMesh& pm)
{ return next(opposite(o, pm), pm); }

// the outgoing halfedge `k` counterclockwise steps from `o` (clockwise if `k` < 0).
template <typename PolygonMesh>
typename boost::graph_traits<PolygonMesh>::halfedge_descriptor
rotate_outgoing(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor o, int k, const PolygonMesh& pm)
{
  for(; k > 0; --k) o = ccw(o, pm);
  for(; k < 0; ++k) o = cw(o, pm);
  return o;
}

// number of counterclockwise steps from the outgoing halfedge `from` to the outgoing halfedge `to`
// (same source); this is the number of faces crossed, the border gap counting as one.
template <typename PolygonMesh>
int ccw_steps(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor from,
              typename boost::graph_traits<PolygonMesh>::halfedge_descriptor to, const PolygonMesh& pm)
{
  int k = 0;
  for(auto o = from; o != to; o = ccw(o, pm))
  {
    ++k;
    CGAL_assertion_msg(o != from || k == 1, "the two halfedges do not leave the same vertex");
    if(k > 1 && o == from) return 0; // not found around the vertex: a caller error, do not loop forever
  }
  return k;
}

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_ROTATION_H
