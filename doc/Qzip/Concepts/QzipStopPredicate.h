/*!
\ingroup PkgQzipConcepts
\cgalConcept

The concept `QzipStopPredicate` describes when `CGAL::Qzip::optimize_singularities()` stops. The predicate
is called before each batch of Q-zips (also before the first one) with the statistics of the run so far;
the optimization stops as soon as it returns `true`. The current batch is always finished. It plays the
role that `StopPredicate` plays in `CGAL::Surface_mesh_simplification::edge_collapse()`.

A model is a copyable function object, passed with the named parameter `stop_predicate`.

\cgalHasModel `CGAL::Qzip::Default_stop_predicate`
\cgalHasModel `CGAL::Qzip::Batch_count_stop_predicate`
\cgalHasModel `CGAL::Qzip::No_improvement_stop_predicate`
\cgalHasModel `CGAL::Qzip::Time_budget_stop_predicate`
\cgalHasModel `CGAL::Qzip::Or_stop_predicate`

\sa `CGAL::Qzip::stop_when_either()`
*/
class QzipStopPredicate
{
public:
  /// \name Operations
  /// @{

  /*!
  returns `true` if the optimization must stop, given the statistics `s` of the batches done so far
  (`s.batch == 0` before the first batch).
  */
  bool operator()(const CGAL::Qzip::Optimizer_statistics& s) const;

  /// @}
};
