// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_SIZING_TERM_H
#define CGAL_QZIP_SCORING_SIZING_TERM_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Scoring/Isotropy_term.h>

#include <cmath>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipScoringFunctor`

The uniform sizing control of the paper's Sec. 4.1: no collapse where quads are already large, no
split where they are already small. For each operation of the plan, with `a` the area of the quad it
acts on (see `Isotropy_term`) divided by the geometric mean of the face areas of the input, the term adds `log(a)` for
a collapse and `-log(a)` for a split, and returns the mean over the operations (see `Isotropy_term`). Only
the plan is used.
*/
struct Sizing_term
{
  template <typename PolygonMesh, typename Context>
  double operator()(const Qzip_candidate<PolygonMesh>& c, Context& ctx) const
  {
    double s = 0;
    std::size_t n = 0;
    const double mean = ctx.mean_face_area();
    internal::for_each_strip_quad(*c.plan, ctx, [&](Strip_operation op, typename boost::graph_traits<PolygonMesh>::face_descriptor,
                                                    double, double, double area)
    {
      const double a = area / mean;
      if(!(a > 0)) return;
      const double r = std::log(a);
      s += is_collapse(op) ? r : -r;
      ++n;
    });
    return n > 0 ? s / double(n) : s;
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_SIZING_TERM_H
