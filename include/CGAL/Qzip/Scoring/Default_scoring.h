// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_DEFAULT_SCORING_H
#define CGAL_QZIP_SCORING_DEFAULT_SCORING_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Scoring/Qzip_candidate.h>
#include <CGAL/Qzip/Scoring/Scoring_context.h>
#include <CGAL/Qzip/Scoring/Electric_term.h>
#include <CGAL/Qzip/Scoring/Isotropy_term.h>
#include <CGAL/Qzip/Scoring/Sizing_term.h>
#include <CGAL/Qzip/Scoring/Separatrix_term.h>
#include <CGAL/Qzip/Scoring/Pairing_term.h>

#include <algorithm>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipScoringFunctor`

The default scoring of `optimize_singularities()`: the weighted sum of the paper's four terms (Sec. 4.1),
`Electric_term`, `Isotropy_term`, `Sizing_term` and `Separatrix_term`, and of `Pairing_term`, a pull
towards the closest singularity of the opposite sign that does not fade with the distance (without it,
singularities a few tens of edges apart, as on finely subdivided meshes, hardly move towards each other).

<b>The concept `QzipScoringFunctor`.</b> A scoring functor is a copyable function object with
\code
template <typename PolygonMesh, typename Context>
double operator()(const Qzip_candidate<PolygonMesh>& candidate, Context& context) const;
\endcode
returning the change of the mesh score the candidate surgery would bring: negative is an improvement.
For each picked singularity the optimizer keeps the candidate with the lowest value among those with a
negative value. `Context` is a `Scoring_context`: it answers questions about the mesh as it was at the
start of the batch (defects, closest singularities, graph distances, separatrices, areas). The functor
must not edit the mesh. A user functor can replace this one or extend it by calling it
(`return Default_scoring()(c, ctx) + my_term(c, ctx);`); pass it with the named parameter `scoring_functor`.
*/
struct Default_scoring
{
  double electric_weight = 1.;    ///< weight of `Electric_term`
  double isotropy_weight = 0.02;  ///< weight of `Isotropy_term`
  double sizing_weight = 0.02;    ///< weight of `Sizing_term`
  double separatrix_weight = 0.02;///< weight of `Separatrix_term`
  double pairing_weight = 0.3;    ///< weight of `Pairing_term`
  /// The weight of `Electric_term` is multiplied by `max(1, F / (electric_spacing * N))`, with `F` faces and `N`
  /// singularities at the start of the batch (0: not multiplied). Far apart, the electric pull fades as the
  /// inverse square of the distance while the candidates of a source tie on the pairing term (whole edges):
  /// without this factor the quality terms break the ties, and singularities tens of edges apart wander before
  /// they meet (benchmark/Qzip/RESULTS.md, session 25).
  double electric_spacing = 100.;
  Electric_term electric;         ///< the electric term and its parameters
  Isotropy_term isotropy;         ///< the isotropy term
  Sizing_term sizing;             ///< the sizing term
  Separatrix_term separatrix;     ///< the separatrix term and its parameters
  Pairing_term pairing;           ///< the pairing term

  template <typename PolygonMesh, typename Context>
  double operator()(const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    double s = 0;
    double ew = electric_weight;
    if(electric_spacing > 0 && ctx.number_of_singularities() > 0)
      ew *= (std::max)(1., double(ctx.number_of_faces()) / (electric_spacing * double(ctx.number_of_singularities())));
    if(ew != 0) s += ew * electric(c, ctx);
    if(isotropy_weight != 0) s += isotropy_weight * isotropy(c, ctx);
    if(sizing_weight != 0) s += sizing_weight * sizing(c, ctx);
    if(separatrix_weight != 0) s += separatrix_weight * separatrix(c, ctx);
    if(pairing_weight != 0) s += pairing_weight * pairing(c, ctx);
    return s;
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_DEFAULT_SCORING_H
