// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_SEPARATRIX_TERM_H
#define CGAL_QZIP_SCORING_SEPARATRIX_TERM_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Scoring/Qzip_candidate.h>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipScoringFunctor`

The separatrix control of the paper's Sec. 4.1: a singularity at distance `d` (in edges, `1 <= d <=
max_distance`) from the closest separatrix of another singularity (a straight edge line leaving it)
scores `1 / d^2`; on a separatrix (aligned) or farther away it scores 0. The term is the change of
the scores of the two moved singularities from their vertices to their predicted landings, which
favors closing "near misses". Separatrices are traced at the start of each batch.
*/
struct Separatrix_term
{
  int max_distance = 3; ///< beyond this distance a separatrix is ignored

  template <typename PolygonMesh, typename Context>
  double operator()(const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    typedef boost::graph_traits<PolygonMesh> GT;
    if(c.source_landing == GT::null_vertex() || c.target_landing == GT::null_vertex()) return 0;
    auto score = [&](typename GT::vertex_descriptor v)
    {
      const int d = ctx.distance_to_separatrix(v, c.source, c.target, max_distance);
      return (d == 0 || d > max_distance) ? 0. : 1. / double(d * d);
    };
    return score(c.source_landing) - score(c.source) + score(c.target_landing) - score(c.target);
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_SEPARATRIX_TERM_H
