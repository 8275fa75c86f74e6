/*!
\ingroup PkgQzipConcepts
\cgalConcept

The concept `QzipScoringFunctor` describes how `CGAL::Qzip::optimize_singularities()` rates a candidate
surgery (a realizable `CGAL::Qzip::Surgery_plan`) before executing anything. It plays the role that
`GetCost` plays in `CGAL::Surface_mesh_simplification::edge_collapse()`.

The returned value is the change of the mesh score the surgery would bring: negative is an improvement.
For each singularity picked in a batch, the optimizer keeps the candidate with the lowest value among the
candidates with a negative value; the kept candidates are sorted by value and the best half is executed.

A model is a copyable function object. It must not modify the mesh; everything it may ask about the mesh
is available from the context, which describes the mesh as it was at the start of the batch.
A model can extend the default model by calling it: `return CGAL::Qzip::Default_scoring()(c, ctx) + my_term(c, ctx);`.
It is passed to `optimize_singularities()` with the named parameter `scoring_functor`.

\cgalHasModel `CGAL::Qzip::Default_scoring`
\cgalHasModel `CGAL::Qzip::Electric_term`
\cgalHasModel `CGAL::Qzip::Isotropy_term`
\cgalHasModel `CGAL::Qzip::Sizing_term`
\cgalHasModel `CGAL::Qzip::Separatrix_term`

\sa `CGAL::Qzip::Qzip_candidate`
\sa `CGAL::Qzip::Scoring_context`
*/
class QzipScoringFunctor
{
public:
  /// \name Operations
  /// @{

  /*!
  returns the change of score (negative: better) that the candidate surgery `c` would bring.
  `PolygonMesh` is the mesh type given to `optimize_singularities()` and `Context` is a
  `CGAL::Qzip::Scoring_context` of that mesh.
  */
  template <typename PolygonMesh, typename Context>
  double operator()(const CGAL::Qzip::Qzip_candidate<PolygonMesh>& c, Context& ctx) const;

  /// @}
};
