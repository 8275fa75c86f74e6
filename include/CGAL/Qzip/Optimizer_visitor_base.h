// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_OPTIMIZER_VISITOR_BASE_H
#define CGAL_QZIP_OPTIMIZER_VISITOR_BASE_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/stop_predicates.h>

namespace CGAL {
namespace Qzip {

template <typename PolygonMesh> struct Surgery_plan;

/*!
\ingroup PkgQzipOptimizer
A visitor of `optimize_singularities()` with no-op callbacks: derive from it, override what you need
and pass it with the named parameter `visitor` (by `std::ref` to keep its state). It is not forwarded
to the Q-zip primitive.
*/
template <typename PolygonMesh>
struct Default_optimizer_visitor
{
  /// called once before the first batch.
  void on_started(const Optimizer_statistics&) {}
  /// called after the candidates of a batch are scored, with the number of candidates to execute.
  void on_batch_scored(const Optimizer_statistics&, std::size_t /*number_of_chosen_candidates*/) {}
  /// called after each executed surgery that was kept, with its score change (negative: better) and the
  /// change in the number of singularities predicted from the plan (see `Qzip_candidate`; compare it with
  /// a recount to measure the prediction). The Q-zips that follow a pair within a batch report as score the
  /// (negative) change of the summed distance of the pair to its partners; those of the end game's look-ahead
  /// are not scored (0). Some vertices of the plan may no longer exist: read only its plain data (sizes,
  /// operations, status).
  void on_surgery(const Surgery_plan<PolygonMesh>&, double /*score*/, int /*predicted_change*/) {}
  /// called after a surgery was executed and then undone because no valid quad shape was found.
  void on_undo(const Surgery_plan<PolygonMesh>&) {}
  /// called after each batch (and its smoothing): `s.batch`, `s.number_of_singularities`, `s.elapsed_seconds`;
  /// not after the rounds of the end game (whose kept surgeries are reported by `on_surgery()`).
  void on_batch_finished(const Optimizer_statistics&) {}
  /// called once at the end.
  void on_finished(const Optimizer_statistics&) {}
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_OPTIMIZER_VISITOR_BASE_H
