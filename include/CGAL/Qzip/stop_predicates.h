// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_STOP_PREDICATES_H
#define CGAL_QZIP_STOP_PREDICATES_H

#include <CGAL/license/Qzip.h>

#include <cstddef>
#include <limits>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
The state of `optimize_singularities()` after a batch of Q-zips: what stop predicates decide on, what
visitors are told, and (its final value) what `optimize_singularities()` returns.

Singularities are counted as vertices with a non-zero defect (`vertex_defect()`, boundary and feature
defects included); since a Q-zip never creates a singularity, `number_of_singularities` never grows.
*/
struct Optimizer_statistics
{
  std::size_t batch = 0;                        ///< number of batches done
  std::size_t initial_number_of_singularities = 0;
  std::size_t number_of_singularities = 0;      ///< now
  /// the number of faces of the mesh given to `optimize_singularities()` (before the collisions of its
  /// triangles): `face_count_tolerance` is a fraction of it
  std::size_t initial_number_of_faces = 0;
  std::size_t number_of_faces = 0;              ///< now
  std::size_t batches_without_improvement = 0;  ///< batches since `number_of_singularities` last decreased
  /// the sum, over the singularities, of the graph distance (in edges) to the closest singularity of the
  /// opposite sign among the few closest ones (see `Scoring_context::nearest_singularities()`; a singularity
  /// with none among them counts for 0): how far the singularities still are from a cancellation
  std::size_t pairing_distance = 0;
  /// batches since `number_of_singularities` last decreased or `pairing_distance` last reached a new
  /// minimum (for the current number of singularities)
  std::size_t batches_without_progress = 0;
  std::size_t surgeries_in_last_batch = 0;      ///< Q-zips kept in the last batch (or round of the end game)
  /// singularities that had an improving candidate in the last batch (after an end game that cancelled
  /// singularities: the number of its Q-zips)
  std::size_t candidates_in_last_batch = 0;
  std::size_t number_of_surgeries = 0;          ///< Q-zips kept so far
  std::size_t number_of_undone_surgeries = 0;   ///< Q-zips executed and undone (no valid smoothed shape)
  std::size_t number_of_failed_surgeries = 0;   ///< realizable plans that `execute_qzip()` rolled back
  std::size_t number_of_skipped_surgeries = 0;  ///< chosen plans skipped because their region was already operated on
  /// chosen plans whose path met only regions of undone (or rolled back) surgeries of the batch, planned
  /// again there and tried (see `optimize_singularities()`)
  std::size_t number_of_replanned_surgeries = 0;
  std::size_t end_game_rounds = 0;              ///< rounds of the end game (see `optimize_singularities()`), not counted in `batch`
  /// whether the optimization stopped because its time limit (`maximum_running_time`) was reached: the
  /// batches (or the end game) would have gone on
  bool reached_time_limit = false;
  double elapsed_seconds = 0;                   ///< wall-clock time since the start of the optimization
  double scoring_seconds = 0;                   ///< part of it spent finding and scoring candidates
  double execution_seconds = 0;                 ///< part of it spent executing, smoothing and checking surgeries
};

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipStopPredicate`

stops after a fixed number of batches.

A stop predicate is any function object with `bool operator()(const Optimizer_statistics&) const`,
called before each batch; the optimization stops as soon as it returns `true`
(compare `CGAL::Surface_mesh_simplification::Count_stop_predicate`).
*/
struct Batch_count_stop_predicate
{
  std::size_t max_batches;
  explicit Batch_count_stop_predicate(std::size_t max_batches) : max_batches(max_batches) {}
  bool operator()(const Optimizer_statistics& s) const { return s.batch >= max_batches; }
};

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipStopPredicate`

stops when the number of singularities has not decreased during the last `patience` batches, or when a
batch kept no surgery at all (nothing improves the score any more: the plateau).
*/
struct No_improvement_stop_predicate
{
  std::size_t patience;
  explicit No_improvement_stop_predicate(std::size_t patience = 10) : patience(patience) {}
  bool operator()(const Optimizer_statistics& s) const
  {
    if(s.batch == 0) return false;
    return s.batches_without_improvement >= patience || s.candidates_in_last_batch == 0;
  }
};

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipStopPredicate`

stops when the optimization has made no progress during the last `patience` batches: the number of
singularities did not decrease and the singularities did not get closer to opposite-sign partners
(`Optimizer_statistics::pairing_distance` reached no new minimum), or when a batch kept no surgery at all.
Unlike `No_improvement_stop_predicate`, it lets singularities that are far apart travel towards each
other, one edge per Q-zip, over many batches before they cancel (e.g. on finely subdivided meshes).
*/
struct No_progress_stop_predicate
{
  std::size_t patience;
  explicit No_progress_stop_predicate(std::size_t patience = 20) : patience(patience) {}
  bool operator()(const Optimizer_statistics& s) const
  {
    if(s.batch == 0) return false;
    return s.batches_without_progress >= patience || s.candidates_in_last_batch == 0;
  }
};

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipStopPredicate`

stops when the elapsed time exceeds a budget (in seconds). The current batch is always finished. Like every
stop predicate it is only asked before a batch: the end game of `optimize_singularities()` still runs after it
says stop. To bound the whole run, end game included, pass the named parameter `maximum_running_time`.
*/
struct Time_budget_stop_predicate
{
  double seconds;
  explicit Time_budget_stop_predicate(double seconds) : seconds(seconds) {}
  bool operator()(const Optimizer_statistics& s) const { return s.elapsed_seconds >= seconds; }
};

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipStopPredicate`

stops as soon as one of two stop predicates does.
*/
template <typename StopPredicate1, typename StopPredicate2>
struct Or_stop_predicate
{
  StopPredicate1 first;
  StopPredicate2 second;
  Or_stop_predicate(const StopPredicate1& a, const StopPredicate2& b) : first(a), second(b) {}
  bool operator()(const Optimizer_statistics& s) const { return first(s) || second(s); }
};

/// \ingroup PkgQzipOptimizer
/// makes an `Or_stop_predicate`.
template <typename StopPredicate1, typename StopPredicate2>
Or_stop_predicate<StopPredicate1, StopPredicate2> stop_when_either(const StopPredicate1& a, const StopPredicate2& b)
{
  return Or_stop_predicate<StopPredicate1, StopPredicate2>(a, b);
}

/*!
\ingroup PkgQzipOptimizer
\cgalModels `QzipStopPredicate`

the default stop predicate of `optimize_singularities()`: at most `max_batches` batches (default 200),
and stop when the batches make no progress (`No_progress_stop_predicate` with patience `patience`,
default 20: neither fewer singularities nor singularities closer to a partner of the opposite sign).
*/
struct Default_stop_predicate
{
  std::size_t max_batches;
  std::size_t patience;
  explicit Default_stop_predicate(std::size_t max_batches = 200, std::size_t patience = 20)
    : max_batches(max_batches), patience(patience) {}
  bool operator()(const Optimizer_statistics& s) const
  {
    return Batch_count_stop_predicate(max_batches)(s) || No_progress_stop_predicate(patience)(s);
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_STOP_PREDICATES_H
