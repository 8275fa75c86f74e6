// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_PAIRING_TERM_H
#define CGAL_QZIP_SCORING_PAIRING_TERM_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Scoring/Qzip_candidate.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipScoringFunctor`

A constant pull of each moved singularity towards its closest singularity of the opposite sign: the
change, in edges, of the distance from each of the two moved singularities to the closest singularity
of the opposite sign other than the pair (among the few closest ones, see
`Scoring_context::nearest_singularities()`), from its vertex to its predicted landing (see
`Qzip_candidate`); a landing on a singularity of the opposite sign brings that distance to 0. A
singularity with no such partner nearby adds nothing.

Unlike `Electric_term`, whose pull decreases as the inverse square of the distance, this pull does not
fade with the distance: singularities far apart (e.g. on a finely subdivided mesh) still travel towards
each other, one edge per Q-zip. It is the per-surgery change of `Optimizer_statistics::pairing_distance`.
*/
struct Pairing_term
{
  template <typename PolygonMesh, typename Context>
  double operator()(const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    typedef boost::graph_traits<PolygonMesh> GT;
    if(c.source_landing == GT::null_vertex() || c.target_landing == GT::null_vertex()) return 0;
    return double(moved(c.source, c.source_defect, c.source_landing, c, ctx) +
                  moved(c.target, c.target_defect, c.target_landing, c, ctx));
  }

private:
  // the distance from `at` to the closest singularity of sign opposite to `defect`, the pair excluded
  // (-1 if none is known)
  template <typename PolygonMesh, typename Context>
  static int partner_distance(typename boost::graph_traits<PolygonMesh>::vertex_descriptor at, int defect,
                              const Qzip_candidate<PolygonMesh>& c, const Context& ctx)
  {
    return ctx.opposite_singularity_distance(at, defect, c.source, c.target);
  }

  template <typename PolygonMesh, typename Context>
  static int moved(typename boost::graph_traits<PolygonMesh>::vertex_descriptor m, int defect,
                   typename boost::graph_traits<PolygonMesh>::vertex_descriptor landing,
                   const Qzip_candidate<PolygonMesh>& c, const Context& ctx)
  {
    const int before = partner_distance(m, defect, c, ctx);
    if(before < 0) return 0;
    if(landing != c.source && landing != c.target && ctx.defect(landing) * defect < 0) return -before; // cancellation
    const int after = partner_distance(landing, defect, c, ctx);
    return after < 0 ? 0 : after - before;
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_PAIRING_TERM_H
