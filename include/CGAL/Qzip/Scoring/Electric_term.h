// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_ELECTRIC_TERM_H
#define CGAL_QZIP_SCORING_ELECTRIC_TERM_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Scoring/Qzip_candidate.h>

#include <algorithm>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipScoringFunctor`

The electric push and pull of the paper's Sec. 4.1. Singularities carry their defect as a charge
(v3: -1, v5: +1, boundary and feature defects likewise); the energy of a singularity `m` at vertex `x`
is the sum of `q_m q_j / d(x, j)` over the `number_of_neighbors` closest other singularities `j`
(opposite charges attract: negative energy; like charges repel), plus `feature_weight / d` for the
closest border or feature vertex (a weak push away from boundaries and features). Distances are in edges.

The term is the change of the energies of the two moved singularities from their vertices to their
predicted landings (see `Qzip_candidate`), plus the change of their mutual interaction, whose distance
after the move is measured along the path of the plan (the landings lie on it or next to its end: the
distance the pair still has to travel). A landing on a singularity of the opposite charge is a
cancellation: the pair is given the distance `merge_distance`. Only the plan is used; the mesh is not
edited, and no search runs (the energies are lookups in the context).
*/
struct Electric_term
{
  double feature_weight = 0.25;       ///< weight of the push away from the closest border/feature vertex
  double merge_distance = 0.5;        ///< distance given to a cancelled pair
  std::size_t number_of_neighbors = 3; ///< how many closest singularities interact with a singularity

  template <typename PolygonMesh, typename Context>
  double operator()(const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    typedef boost::graph_traits<PolygonMesh> GT;
    if(c.source_landing == GT::null_vertex() || c.target_landing == GT::null_vertex()) return 0;
    double delta = moved(c.source, c.source_defect, c.source_landing, c, ctx)
                 + moved(c.target, c.target_defect, c.target_landing, c, ctx);
    const double q = double(charge(c.source_defect) * charge(c.target_defect));
    const int before = (std::max)(1, c.sketch_length);
    const int after = distance_along_path(c);
    delta += q / (after == 0 ? merge_distance : double(after)) - q / double(before);
    return delta;
  }

private:
  // the number of path edges between the landings; the source landing is the first or second path vertex,
  // the target landing is a path vertex or a neighbor of the last one (see `Qzip_candidate`)
  template <typename PolygonMesh>
  static int distance_along_path(const Qzip_candidate<PolygonMesh>& c)
  {
    const auto& path = c.plan->path;
    const std::ptrdiff_t i = c.source_landing == path[0] ? 0 : 1;
    const auto j = std::find(path.begin() + i, path.end(), c.target_landing);
    return j != path.end() ? int(j - path.begin() - i) : int(std::ptrdiff_t(path.size()) - i);
  }

  static int charge(int defect) { return (std::max)(-2, (std::min)(2, defect)); }

  template <typename PolygonMesh, typename Context>
  double energy(int q, typename boost::graph_traits<PolygonMesh>::vertex_descriptor at,
                const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    typedef boost::graph_traits<PolygonMesh> GT;
    // the first number_of_neighbors of the closest singularities to `at` other than the pair, taken from the
    // first number_of_neighbors + 2 of them (the context's list of the closest singularities of a vertex is
    // the same whatever a query excludes): one search around `at` then answers every pair that lands there
    // (and most of Pairing_term's queries at the same vertex), instead of one search per pair; when the
    // context keeps fewer than number_of_neighbors + 2, the query excludes the pair itself
    const bool wide = number_of_neighbors + 2 <= Context::max_nearest_singularities;
    const auto nb = wide ? ctx.nearest_singularities(at, GT::null_vertex(), GT::null_vertex(), number_of_neighbors + 2)
                         : ctx.nearest_singularities(at, c.source, c.target, number_of_neighbors);
    double e = 0;
    std::size_t used = 0;
    for(const auto& j : nb)
    {
      if(j.vertex == c.source || j.vertex == c.target) continue;
      if(used++ == number_of_neighbors) break;
      e += double(q * charge(j.defect)) / double(j.distance);
    }
    if(nb.feature_distance > 0 && nb.feature_distance < (std::numeric_limits<int>::max)())
      e += feature_weight / double(nb.feature_distance);
    return e;
  }

  template <typename PolygonMesh, typename Context>
  double moved(typename boost::graph_traits<PolygonMesh>::vertex_descriptor m, int defect,
               typename boost::graph_traits<PolygonMesh>::vertex_descriptor landing,
               const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    const int q = charge(defect);
    const double before = energy(q, m, c, ctx);
    const int dl = ctx.defect(landing);
    double after;
    if(landing != c.source && landing != c.target && dl * q < 0)
      after = double(q * charge(dl)) / merge_distance; // cancellation
    else
      after = energy(q, landing, c, ctx);
    return after - before;
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_ELECTRIC_TERM_H
