// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_QZIP_H
#define CGAL_QZIP_QZIP_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/surgery_plan.h>
#include <CGAL/Qzip/surgery_path.h>
#include <CGAL/Qzip/internal/operation_log.h>
#include <CGAL/Qzip/internal/chain_executor.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <memory>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipPrimitive
What `execute_qzip()` did.

The footprint of a Q-zip is what disappeared (`number_of_collapses` quads, and the edges split);
its scar is what appeared: `scar_faces`, the quads created by splits, and the vertices of
`touched_vertices`, every live vertex whose connectivity or position changed.
*/
template <typename PolygonMesh>
struct Qzip_result
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;

  Plan_status status = Plan_status::INVALID_PATH; ///< `REALIZABLE` when the Q-zip was carried out
  std::size_t number_of_collapses = 0;             ///< quad collapses of the chain and of the clean-up
  std::size_t number_of_splits = 0;                ///< vertex splits of the chain and of the clean-up
  std::size_t number_of_cleanups = 0;              ///< valence-2 removals and valence-6 splits (paper, Sec. 2.7)
  /// the moved initial and terminal singularities, when they can be told apart from the other
  /// singular vertices of the scar (`null_vertex()` otherwise, e.g. when a passed singularity moved too)
  vertex_descriptor moved_source = boost::graph_traits<PolygonMesh>::null_vertex();
  /// see `moved_source`
  vertex_descriptor moved_target = boost::graph_traits<PolygonMesh>::null_vertex();
  std::vector<face_descriptor> scar_faces;         ///< quads created by the surgery and still alive
  std::vector<vertex_descriptor> touched_vertices; ///< live vertices whose neighbourhood or position changed
  Execution_failure failure = Execution_failure::NONE; ///< why the execution was rolled back, if it was
  std::size_t failed_step = 0;                     ///< index in `plan.path` of the vertex where it was

  /// `true` when the Q-zip was carried out.
  bool is_done() const { return status == Plan_status::REALIZABLE; }
};

/*!
\ingroup PkgQzipPrimitive
The history of the Q-zips executed on a mesh through `execute_qzip(pm, plan, history, np)`, to undo
them exactly, most recent first, without storing any copy of the mesh: each Q-zip is recorded as its
chain of atomic operations, and undoing applies their inverses in reverse order. Connectivity and every
position come back exactly (elements re-created by an undo may have new descriptors).

\pre Between a Q-zip and its undo, the mesh is only modified by Q-zips recorded in this history
(and by undos of later ones).
*/
template <typename PolygonMesh,
          typename VertexPointMap = typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>
class Qzip_history
{
  std::shared_ptr<internal::Operation_log<PolygonMesh, VertexPointMap> > log;
public:
  /// an empty history of `pm`, whose positions are in `vpm`.
  explicit Qzip_history(PolygonMesh& pm, VertexPointMap vpm)
    : log(std::make_shared<internal::Operation_log<PolygonMesh, VertexPointMap> >(pm, vpm)) {}
  /// an empty history of `pm`, with its internal vertex point map.
  explicit Qzip_history(PolygonMesh& pm)
    : log(std::make_shared<internal::Operation_log<PolygonMesh, VertexPointMap> >(pm, get(CGAL::vertex_point, pm))) {}
  /// the number of recorded Q-zips.
  std::size_t size() const { return log->number_of_marks(); }
  /// `true` when there is nothing to undo.
  bool empty() const { return size() == 0; }
  /// undoes the most recent recorded Q-zip. \pre `!empty()`
  void undo_last() { CGAL_precondition(!empty()); log->rollback_to_mark(); }
  /// undoes every recorded Q-zip.
  void undo_all() { while(!empty()) undo_last(); }
  /// \cond SKIP_IN_MANUAL
  internal::Operation_log<PolygonMesh, VertexPointMap>& operation_log() { return *log; }
  /// \endcond
};

/*!
\ingroup PkgQzipPrimitive

executes a surgery plan: the chain of quad collapses and vertex splits the compass tags prescribe,
then the clean-up of the paper's Sec. 2.7 (a valence-2 vertex left where two v3 merged is removed,
introducing two v3; a valence-6 vertex left where two v5 merged is split into two regular vertices,
introducing two v5).

Every operation is checked before it is applied (link condition, border, constrained edges and
protected faces); afterwards the valences of every vertex the surgery touched are compared with the
ones before: the irregular valences after must form a sub-multiset of those before (no singularity is
created; a path passing other singularities may cancel complementary pairs of them) and no border
vertex may change valence. If an operation cannot be applied or the check fails, everything done is rolled back and
the mesh is combinatorially and geometrically as before (re-created elements may have new descriptors).

\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the polygon mesh the plan was computed on, unchanged since
\param plan a plan from `plan_qzip()`
\param np optional named parameters among `vertex_point_map`, `edge_is_constrained_map` and
          `face_is_constrained_map` (see `plan_qzip()`), and
\cgalNamedParamsBegin
  \cgalParamNBegin{visitor}
    \cgalParamDescription{a visitor (see `Default_qzip_visitor`) told of each atomic operation}
    \cgalParamDefault{no visitor}
  \cgalParamNEnd
\cgalNamedParamsEnd
\returns what was done; `result.status` is `REALIZABLE` on success.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Qzip_result<PolygonMesh> execute_qzip(PolygonMesh& pm, const Surgery_plan<PolygonMesh>& plan,
                                      const NamedParameters& np = parameters::default_values())
{
  auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_property_map(vertex_point, pm));
  internal::Operation_log<PolygonMesh, decltype(vpm)> log(pm, vpm);
  internal::Chain_executor<PolygonMesh, decltype(vpm), NamedParameters> exec(pm, log, np);
  return exec.run(plan);
}

/*!
\ingroup PkgQzipPrimitive
same as `execute_qzip()`, and records the Q-zip in `history` (when it is done) so that
`undo_qzip(history)` undoes it exactly. The positions are those of the history's vertex point map.
*/
template <typename PolygonMesh, typename VertexPointMap, typename NamedParameters = parameters::Default_named_parameters>
Qzip_result<PolygonMesh> execute_qzip(PolygonMesh& pm, const Surgery_plan<PolygonMesh>& plan,
                                      Qzip_history<PolygonMesh, VertexPointMap>& history,
                                      const NamedParameters& np = parameters::default_values())
{
  internal::Chain_executor<PolygonMesh, VertexPointMap, NamedParameters> exec(pm, history.operation_log(), np);
  return exec.run(plan);
}

/*!
\ingroup PkgQzipPrimitive
undoes the most recent Q-zip recorded in `history`: the inverse atomic operations in reverse order.
\pre `!history.empty()`
*/
template <typename PolygonMesh, typename VertexPointMap>
void undo_qzip(Qzip_history<PolygonMesh, VertexPointMap>& history)
{
  history.undo_last();
}

/*!
\ingroup PkgQzipPrimitive

moves the pair of singularities `s` and `t` by one Q-zip: finds a surgery path with
`shortest_surgery_path()`, plans the motion `initial_operation` with `plan_qzip()` and executes it
with `execute_qzip()`. Takes the named parameters of those three functions.

\returns the result of the execution; when no path exists or the plan is not realizable, its status
         says why and the mesh is untouched.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Qzip_result<PolygonMesh> qzip(PolygonMesh& pm,
                              typename boost::graph_traits<PolygonMesh>::vertex_descriptor s,
                              typename boost::graph_traits<PolygonMesh>::vertex_descriptor t,
                              Strip_operation initial_operation,
                              const NamedParameters& np = parameters::default_values())
{
  Qzip_result<PolygonMesh> r;
  const auto path = shortest_surgery_path(pm, s, t, np);
  if(path.empty()) { r.status = Plan_status::INVALID_PATH; return r; }
  const Surgery_plan<PolygonMesh> plan = plan_qzip(pm, path, initial_operation, np);
  if(!plan.is_realizable()) { r.status = plan.status; return r; }
  return execute_qzip(pm, plan, np);
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_QZIP_H
