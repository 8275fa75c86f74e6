// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_ISOTROPY_TERM_H
#define CGAL_QZIP_SCORING_ISOTROPY_TERM_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Scoring/Qzip_candidate.h>

#include <cmath>

namespace CGAL {
namespace Qzip {

namespace internal {

// calls f(op, face, along, across, area) for each operation of the plan that acts on a quad next to the
// path: the quad on the left of the path edge for RC and LS, on its right for LC and RS; `along` is the
// length of the path edge, `across` the mean length of the two sides of the quad that leave the path and
// `area` the area of the quad (see `Scoring_context::strip_quads()`, which keeps them for the last plan).
template <typename PolygonMesh, typename Context, typename F>
void for_each_strip_quad(const Surgery_plan<PolygonMesh>& plan, const Context& ctx, F f)
{
  for(const auto& q : ctx.strip_quads(plan)) f(q.operation, q.face, q.along, q.across, q.area);
}

} // namespace internal

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipScoringFunctor`

The isotropy control of the paper's Sec. 4.1. A chain of collapses removes the strip of quads along
one side of the path, which widens the remaining quads across the path; a chain of splits inserts a
strip, which narrows them. For each operation, with `along` the length of the path edge and `across`
the length of the quad's sides that leave the path, the term adds `log(across / along)` for a collapse
(negative, i.e. good, when the quads are squeezed across the path) and `-log(across / along)` for a
split (good when they are stretched across it), and returns the mean over the operations: the change of
shape per quad the plan acts on, whatever the length of the path. (A sum would let a long path win by the
number of its terms alone; until session 25 the sum was divided by the square root of the number of
operations, which left the chance fluctuations of a sum of many small terms as large on a long path as on a
short one: far apart, where the electric term changes little from one candidate to the next, they decided
which Q-zips were chosen, and singularities tens of edges apart met late, see benchmark/Qzip/RESULTS.md.)
Only the plan is used.
*/
struct Isotropy_term
{
  template <typename PolygonMesh, typename Context>
  double operator()(const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    double s = 0;
    std::size_t n = 0;
    internal::for_each_strip_quad(*c.plan, ctx, [&](Strip_operation op, typename boost::graph_traits<PolygonMesh>::face_descriptor,
                                                    double along, double across, double)
    {
      const double r = std::log(across / along);
      s += is_collapse(op) ? r : -r;
      ++n;
    });
    return n > 0 ? s / double(n) : s;
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_ISOTROPY_TERM_H
