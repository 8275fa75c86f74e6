// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_QZIP_VISITOR_BASE_H
#define CGAL_QZIP_QZIP_VISITOR_BASE_H

#include <CGAL/license/Qzip.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Qzip {

template <typename PolygonMesh> struct Surgery_plan;

/*!
\ingroup PkgQzipPrimitive
A visitor with no-op callbacks: derive from it and override what you need, then pass it (by
`std::ref` to keep its state) with the named parameter `visitor`. The atomic callbacks come before
the operation is applied, so that `h` still describes the mesh as it is.
*/
template <typename PolygonMesh>
struct Default_qzip_visitor
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;

  /// called before the chain of a plan starts.
  void on_qzip_started(const Surgery_plan<PolygonMesh>&) {}
  /// called before `quad_collapse(h, pm)`.
  void on_collapse(halfedge_descriptor /*h*/, const PolygonMesh&) {}
  /// called before `split_vertex_into_quad(h1, h2, pm)`.
  void on_split(halfedge_descriptor /*h1*/, halfedge_descriptor /*h2*/, const PolygonMesh&) {}
  /// called at the end, with `done == false` when the Q-zip was rolled back.
  void on_qzip_finished(const Surgery_plan<PolygonMesh>&, bool /*done*/) {}
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_QZIP_VISITOR_BASE_H
