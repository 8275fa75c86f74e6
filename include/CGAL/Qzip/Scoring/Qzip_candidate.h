// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_QZIP_CANDIDATE_H
#define CGAL_QZIP_SCORING_QZIP_CANDIDATE_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/surgery_plan.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
A candidate surgery as a scoring functor sees it (the analog of SMS's `Edge_profile`): a realizable
plan of the current mesh and what the optimizer predicts from it without executing it.

The landings are vertices of the current mesh where the moved singularities are expected after the
Q-zip (the paper's Sec. 2.6 end-point rules): for the source, the first vertex of the adjusted path
when the preparation prepended one, else the second; for the target, the last vertex of the adjusted
path when the preparation appended one, else (v3 end) the far corner of the last collapsed quad or
the last split vertex. A landing on a singularity of the opposite type predicts that both cancel.
*/
template <typename PolygonMesh>
struct Qzip_candidate
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;

  const Surgery_plan<PolygonMesh>* plan = nullptr; ///< the realizable plan
  vertex_descriptor source;          ///< the singularity the batch picked
  vertex_descriptor target;          ///< its partner
  int source_defect = 0;             ///< -1 for a v3, +1 for a v5
  int target_defect = 0;
  int sketch_length = 0;             ///< number of edges of the surgery sketch (graph distance of the pair)
  vertex_descriptor source_landing = boost::graph_traits<PolygonMesh>::null_vertex(); ///< predicted new place of the source
  vertex_descriptor target_landing = boost::graph_traits<PolygonMesh>::null_vertex(); ///< predicted new place of the target
  int predicted_cancellations = 0;   ///< number of singularities the landings predict to cancel (0, 2 or 4)
};

namespace internal {

// the landings of a plan (see Qzip_candidate).
template <typename PolygonMesh>
void predict_landings(const Surgery_plan<PolygonMesh>& plan, const PolygonMesh& pm,
                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor& source_landing,
                      typename boost::graph_traits<PolygonMesh>::vertex_descriptor& target_landing)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  const std::size_t n = plan.path.size();
  source_landing = GT::null_vertex();
  target_landing = GT::null_vertex();
  if(n < 2) return;
  source_landing = plan.path[0] != plan.source ? plan.path[0] : plan.path[1];
  if(plan.path[n - 1] != plan.target) { target_landing = plan.path[n - 1]; return; }
  const auto u = plan.path[n - 2];
  const auto uo = halfedge(u, plan.target, pm);
  if(!uo.second) return;
  const auto o = uo.first;
  switch(plan.operations[n - 2])
  {
    case Strip_operation::RIGHT_COLLAPSE:
      if(!is_border(o, pm)) target_landing = target(next(o, pm), pm);
      break;
    case Strip_operation::LEFT_COLLAPSE:
      if(!is_border(opposite(o, pm), pm)) target_landing = target(next(next(opposite(o, pm), pm), pm), pm);
      break;
    default:
      target_landing = u;
  }
}

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_QZIP_CANDIDATE_H
