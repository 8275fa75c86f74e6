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

#include <algorithm>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipPrimitive
Whether a done Q-zip can be undone by its reverse Q-zip (`reverse_qzip()`), or why not.
*/
enum class Reverse_qzip_status
{
  AVAILABLE,               ///< `Qzip_result::reverse_plan` undoes the Q-zip
  NOT_DONE,                ///< the Q-zip was not carried out: there is nothing to undo
  SINGULARITIES_CANCELLED, ///< the Q-zip cancelled singularities, and a Q-zip never creates any
  /// the clean-up (valence-2 removal, valence-6 split) cannot be undone before the reverse chain: one of
  /// its operations involves a vertex that a later one removed; or, for the reverse of a reverse plan,
  /// the valence-6 vertex its prelude re-created has several admissible splits, and the executor's
  /// clean-up might not choose the one undone
  CLEANED_UP,
  GUIDE_NOT_RESTORABLE     ///< two consecutive collapses of the chain share no corner the reverse split can be guided by
};

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
  /// whether `reverse_plan` is available, or why not
  Reverse_qzip_status reverse_status = Reverse_qzip_status::NOT_DONE;
  /// the reverse Q-zip (see `reverse_qzip()`): a plan on the mesh after this Q-zip whose execution gives
  /// back the mesh before it, up to isomorphism; meaningful when `reverse_status` is `AVAILABLE`.
  /// Its `source` and `target` are the ends of its path, which need not be singular (`null_vertex()` when
  /// the reverse itself re-creates them, see `Surgery_plan::created_vertices`).
  Surgery_plan<PolygonMesh> reverse_plan;

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

namespace internal {

// The reverse Q-zip (paper, Sec. 2.8), derived from the executor (see Chain_executor and the user manual,
// section "Undo by a Reverse Q-zip"). Step j of the chain works at v = path[j] towards w = path[j+1] and
// takes the mesh M_j to M_{j+1}; its inverse is a step of the reverse chain at w towards v:
//   LS/RS: v was split into the quad (v, w, c, y), y the guide's end; the inverse collapses that quad
//          keeping v: LC at w, which leaves the guide v->y, the one step j received.
//   RC/LC: the corner z of the quad beside v->w was merged into w, leaving the guide w->x (x the other
//          kept corner); the inverse splits w between v and x: a split at w guided by w->x (after RC the
//          executor gives the new vertex w's fan and w keeps z's, the same mesh up to naming). Its tag only
//          decides the guide it leaves at v, which matters when step j-1 was a collapse too: the next
//          reverse step splits v and needs v->x', x' the corner kept by step j-1. x' is z (RS after RC,
//          LS after LC: the compass rotated by pi) or w (LS after RC, RS after LC); both are recorded.
//   NOOP: nothing to undo.
// The reverse chain thus walks the path backwards; when it starts with a split, it starts one vertex
// earlier, at the corner kept by the last collapse, with a no-operation that provides the guide.
// A path vertex that a collapse of step j merged away (z, or in a reverse plan a second name of w) is
// re-created by the reverse split at w: the reverse plan names it as one of the two copies of that split
// (Surgery_plan::created_vertices): z took the side of the collapsed quad, on the left of w->v after LC,
// on its right after RC (the split vertex itself). The clean-up (a valence-2 vertex merged into its far
// corner, a valence-6 vertex split) is undone first, by the inverse atomic operations in reverse order
// (Surgery_plan::prelude), named by vertices of the mesh after the Q-zip; a path vertex the clean-up merged
// away is the vertex created by the inverse split. A Q-zip that moved a border defect ends with the split
// of the border target t along the border edge t->e; only one copy of t keeps the border gap, so the
// inverse collapse never merges two border vertices (a border copy merged into the interior one gives it
// its place on the border, see Chain_executor::collapse()). Refused: Q-zips that cancelled singularities
// (a Q-zip never creates one), clean-ups whose operations involve a vertex a later clean-up removed, and
// redos whose clean-up would have a choice (check_valence_6()).
// The recorder watches the execution as a visitor and forwards every call to the user's visitor; it
// costs a few vectors of the path's length, and a search of the path per collapse.
template <typename PolygonMesh, typename UserVisitor>
class Reverse_recorder
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef Surgery_plan<PolygonMesh> Plan;
  typedef typename Plan::Atomic_operation Atomic_operation;
  typedef typename Plan::Created_vertex Created_vertex;
  static constexpr std::size_t npos = std::size_t(-1);

  // a path vertex merged away by the chain: re-created by the reverse split at path[step + 1]
  struct Merge { std::size_t step = npos; bool new_vertex = false; };
  // a clean-up operation: its inverse, and the vertex it removed (collapse) or null_vertex() (split)
  struct Cleanup { Atomic_operation inverse; vertex_descriptor removed; };

  const PolygonMesh& pm;
  const Plan& plan;
  UserVisitor user;
  std::size_t next_step = 0;                 // the position in plan.path of the chain's next operation
  std::vector<vertex_descriptor> created_names; // plan.path with the vertices the execution created (if any)
  const std::vector<vertex_descriptor>& names;  // plan.path, or created_names
  std::vector<Strip_operation> reverse_ops;  // the reverse tag of each step, indexed like plan.path
  std::vector<Merge> merged;                 // indexed like plan.path (empty until a path vertex is merged)
  std::vector<Cleanup> cleanups;
  std::size_t operations_seen = 0;
  vertex_descriptor kept_corner = GT::null_vertex(); // x of the last chain collapse
  Reverse_qzip_status refusal = Reverse_qzip_status::AVAILABLE;
  // the last split (its returned halfedge is known after it) and the position that names its copies
  halfedge_descriptor last_split = GT::null_halfedge();
  vertex_descriptor last_split_vertex = GT::null_vertex();
  std::size_t last_split_position = npos;
  bool last_split_complement = false; // the new vertex took the fan on the right of the path (Chain_executor::run_chain())
  vertex_descriptor valence_6 = GT::null_vertex(); // made by the last prelude collapse, checked after it

  // names the copies of the previous split, once it is done: it returned h2 = d->v on the new quad
  // (v, b, c, d), c the new vertex
  void settle()
  {
    if(last_split == GT::null_halfedge()) return;
    const vertex_descriptor made = target(next(next(last_split, pm), pm), pm);
    for(const Created_vertex& cv : plan.created_vertices)
      if(cv.split == last_split_position)
        created_names[cv.index] = cv.new_vertex != last_split_complement ? made : last_split_vertex;
    last_split = GT::null_halfedge();
  }

  // The redo (the reverse of a reverse plan whose prelude re-created a valence-6 vertex) relies on the
  // executor's clean-up splitting it again as before; refused when the clean-up has a choice: more than
  // one pair of opposite neighbours that are interior and regular (Chain_executor::split_valence_6).
  void check_valence_6()
  {
    if(valence_6 == GT::null_vertex()) return;
    std::vector<vertex_descriptor> ring;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(valence_6, pm), pm)) ring.push_back(source(h, pm));
    valence_6 = GT::null_vertex();
    if(ring.size() != 6) return;
    int choices = 0;
    for(std::size_t i = 0; i < 3; ++i)
    {
      const vertex_descriptor b = ring[i], d = ring[i + 3];
      if(valence(b, pm) == 4 && valence(d, pm) == 4 && !is_border_vertex(b, pm) && !is_border_vertex(d, pm)) ++choices;
    }
    if(choices > 1 && refusal == Reverse_qzip_status::AVAILABLE) refusal = Reverse_qzip_status::CLEANED_UP;
  }

  void merge(std::size_t i, std::size_t step, bool new_vertex)
  {
    if(merged.empty()) merged.resize(names.size());
    if(merged[i].step == npos) { merged[i].step = step; merged[i].new_vertex = new_vertex; }
  }

  // the position of the chain step the k-th atomic operation belongs to, or npos for the prelude and
  // the clean-up (the chain's operations come in path order, after the prelude)
  std::size_t chain_step(std::size_t k)
  {
    if(k < plan.prelude.size()) return npos;
    while(next_step + 1 < plan.path.size() && plan.operations[next_step] == Strip_operation::NO_OPERATION) ++next_step;
    return next_step + 1 < plan.path.size() ? next_step++ : npos;
  }

  bool is_merged(std::size_t i) const { return !merged.empty() && merged[i].step != npos; }

  // the clean-up collapse that removed the live path vertex named v, or npos
  std::size_t removed_by_cleanup(vertex_descriptor v, std::size_t after = 0) const
  {
    for(std::size_t m = after; m < cleanups.size(); ++m) if(cleanups[m].removed == v) return m;
    return npos;
  }

public:
  Reverse_recorder(const PolygonMesh& pm, const Plan& plan, UserVisitor user)
    : pm(pm), plan(plan), user(user),
      created_names(plan.created_vertices.empty() ? std::vector<vertex_descriptor>() : plan.path),
      names(plan.created_vertices.empty() ? plan.path : created_names),
      reverse_ops(plan.path.size(), Strip_operation::NO_OPERATION)
  {}

  void on_qzip_started(const Plan& p) { user.on_qzip_started(p); }

  void on_collapse(halfedge_descriptor h, const PolygonMesh& pm)
  {
    settle();
    check_valence_6();
    // face(h) = (d, a, b, c): c is merged into a; RC: h = v->w, so a = w, b = x, d = v; LC: h = x->w, b = v, d = x
    const vertex_descriptor a = target(h, pm), b = target(next(h, pm), pm);
    const vertex_descriptor c = target(next(next(h, pm), pm), pm), d = source(h, pm);
    const std::size_t k = operations_seen++;
    const std::size_t j = chain_step(k);
    if(j != npos)
    {
      const Strip_operation op = plan.operations[j];
      // the path vertices merged away: those named c (on the side of the collapsed quad), and in a
      // reverse plan, other names of w = a (on the other side)
      for(std::size_t i = 0; i <= j; ++i)
        if(!is_merged(i) && (names[i] == c || names[i] == a))
          merge(i, j, (names[i] == c) == (op == Strip_operation::LEFT_COLLAPSE));
      if(j == 0 || !is_collapse(plan.operations[j - 1]) || kept_corner == c) reverse_ops[j] = rotate(op, 2);
      else if(kept_corner == a)
        reverse_ops[j] = op == Strip_operation::RIGHT_COLLAPSE ? Strip_operation::LEFT_SPLIT : Strip_operation::RIGHT_SPLIT;
      else if(refusal == Reverse_qzip_status::AVAILABLE) refusal = Reverse_qzip_status::GUIDE_NOT_RESTORABLE;
      kept_corner = b == names[j] ? d : b;
    }
    else if(k >= plan.prelude.size()) // clean-up: undone by the split of a between b->a and d->a
      cleanups.push_back(Cleanup{ Atomic_operation{ a, b, d }, c });
    else
      valence_6 = a;
    user.on_collapse(h, pm);
  }

  void on_split(halfedge_descriptor h1, halfedge_descriptor h2, const PolygonMesh& pm)
  {
    settle();
    check_valence_6();
    const std::size_t k = operations_seen++;
    const std::size_t j = chain_step(k);
    // the inverse collapses the new quad keeping path[j]: it lies on the right of path[j+1] -> path[j]
    // (LC), or on its left after a complementary split at a feature vertex (Chain_executor::run_chain()),
    // which splits between the guide and the path edge
    const bool complement = j != npos && names[j + 1] != GT::null_vertex() && source(h1, pm) != names[j + 1];
    if(j != npos) reverse_ops[j] = complement ? Strip_operation::RIGHT_COLLAPSE : Strip_operation::LEFT_COLLAPSE;
    if(k < plan.prelude.size() || j != npos)
    {
      if(!plan.created_vertices.empty())
      {
        last_split = h2;
        last_split_vertex = target(h1, pm);
        last_split_complement = complement;
        last_split_position = k < plan.prelude.size() ? plan.path.size() + k : j;
      }
    }
    else // clean-up: undone by the collapse of the new quad, on the left of h2 = d->v, keeping v
      cleanups.push_back(Cleanup{ Atomic_operation{ target(h1, pm), source(h2, pm), GT::null_vertex() },
                                  GT::null_vertex() });
    user.on_split(h1, h2, pm);
  }

  void on_qzip_finished(const Plan& p, bool done)
  {
    if(done) { settle(); check_valence_6(); }
    last_split = GT::null_halfedge();
    valence_6 = GT::null_vertex();
    user.on_qzip_finished(p, done);
  }

  // fills r.reverse_status and r.reverse_plan after the execution; `cancelled`: the executor saw
  // singularities cancelled (interior valences or border defects); `expected_faces`: the numbers of faces
  // the executor judged the live border vertices by, which the reverse judges them by too
  void make_reverse(Qzip_result<PolygonMesh>& r, bool cancelled,
                    std::vector<std::pair<vertex_descriptor, int> > expected_faces) const
  {
    if(!r.is_done()) return;
    if(cancelled) { r.reverse_status = Reverse_qzip_status::SINGULARITIES_CANCELLED; return; }
    if(refusal != Reverse_qzip_status::AVAILABLE) { r.reverse_status = refusal; return; }
    // the inverse of a clean-up operation is named by vertices of the final mesh: none may have been
    // removed by a later clean-up
    for(std::size_t m = 0; m < cleanups.size(); ++m)
    {
      const Atomic_operation& o = cleanups[m].inverse;
      for(vertex_descriptor v : { o.v, o.b, o.d })
        if(v != GT::null_vertex() && removed_by_cleanup(v, m + 1) != npos)
        { r.reverse_status = Reverse_qzip_status::CLEANED_UP; return; }
    }

    const std::size_t n = names.size();
    const std::size_t offset = is_split(reverse_ops[n - 2]) ? 1 : 0; // starts at the last kept corner
    const std::size_t size = n + offset;
    Plan& rev = r.reverse_plan;
    rev.path.assign(size, GT::null_vertex());
    rev.operations.assign(size, Strip_operation::NO_OPERATION);
    for(std::size_t j = 0; j + 1 < n; ++j) rev.operations[offset + n - 2 - j] = reverse_ops[j];
    rev.prelude.clear();
    for(std::size_t m = cleanups.size(); m-- > 0; ) rev.prelude.push_back(cleanups[m].inverse);
    rev.created_vertices.clear();
    rev.expected_faces = std::move(expected_faces);
    // names the reverse path vertex at position p, which is `v` at the end of the Q-zip
    auto name = [&](std::size_t p, vertex_descriptor v, const Merge* by_chain)
    {
      if(by_chain != nullptr)
        rev.created_vertices.push_back(Created_vertex{ p, offset + n - 2 - by_chain->step, by_chain->new_vertex });
      else if(const std::size_t m = removed_by_cleanup(v); m != npos)
        rev.created_vertices.push_back(Created_vertex{ p, size + cleanups.size() - 1 - m, true });
      else
        rev.path[p] = v;
    };
    if(offset == 1) name(0, kept_corner, nullptr);
    for(std::size_t i = n; i-- > 0; )
      name(offset + n - 1 - i, names[i], is_merged(i) ? &merged[i] : nullptr);
    CGAL_assertion(std::is_sorted(rev.created_vertices.begin(), rev.created_vertices.end(),
                                  [](const Created_vertex& x, const Created_vertex& y) { return x.index < y.index; }));
    rev.sketch = rev.path;
    rev.source = rev.path.front();
    rev.target = rev.path.back();
    rev.source_valence = plan.target_valence; // the reverse moves the pair back: t' first, then s'
    rev.target_valence = plan.source_valence;
    rev.initial_operation = *std::find_if(rev.operations.begin(), rev.operations.end(),
                                          [](Strip_operation op) { return op != Strip_operation::NO_OPERATION; });
    rev.status = Plan_status::REALIZABLE;
    r.reverse_status = Reverse_qzip_status::AVAILABLE;
  }
};

// runs `plan` through a Chain_executor on `log`, recording its reverse Q-zip
template <typename PolygonMesh, typename VertexPointMap, typename NamedParameters>
Qzip_result<PolygonMesh> run_qzip(PolygonMesh& pm, Operation_log<PolygonMesh, VertexPointMap>& log,
                                  const Surgery_plan<PolygonMesh>& plan, const NamedParameters& np)
{
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::visitor_t, NamedParameters,
            Default_qzip_visitor<PolygonMesh> >::reference User_visitor;
  Default_qzip_visitor<PolygonMesh> default_visitor;
  User_visitor user = parameters::choose_parameter(parameters::get_parameter_reference(np, CGAL::internal_np::visitor),
                                                   default_visitor);
  Reverse_recorder<PolygonMesh, User_visitor> recorder(pm, plan, user);
  const auto np_recording = np.visitor(std::ref(recorder));
  Chain_executor_of<PolygonMesh, VertexPointMap, std::decay_t<decltype(np_recording)> > exec(pm, log, np_recording);
  Qzip_result<PolygonMesh> r = exec.run(plan);
  recorder.make_reverse(r, exec.cancelled_singularities(), exec.expected_faces_of_live_vertices());
  return r;
}

} // namespace internal

/*!
\ingroup PkgQzipPrimitive

executes a surgery plan: the chain of quad collapses and vertex splits the compass tags prescribe,
then the clean-up of the paper's Sec. 2.7 (a valence-2 vertex left where two v3 merged is removed,
introducing two v3; a valence-6 vertex left where two v5 merged is split into two regular vertices,
introducing two v5).

Every operation is checked before it is applied (link condition, border, constrained edges and
protected faces: a collapse never removes a constrained edge nor merges two vertices that are each on a
feature or on the border, a split keeps all the constrained edges of a vertex on one of its copies, so that
every feature curve keeps its number of edges; a vertex on a feature keeps its place, or takes exactly the
place of the feature vertex it replaces); afterwards the valences of every vertex the surgery touched are compared with the
ones before: the irregular valences after must form a sub-multiset of those before (no singularity is
created; a path passing other singularities may cancel complementary pairs of them), border and feature
vertices are compared by their defect (the number of quads each should have is frozen before the chain; feature
vertices also sector by sector, between consecutive constrained edges), and
no interior vertex may reach the border unless a border vertex was merged into it. If an operation cannot be
applied or the check fails, everything done is rolled back and
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
\returns what was done; `result.status` is `REALIZABLE` on success. A done Q-zip also carries its
         reverse Q-zip (`result.reverse_plan`, see `reverse_qzip()`) or the reason why there is none.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Qzip_result<PolygonMesh> execute_qzip(PolygonMesh& pm, const Surgery_plan<PolygonMesh>& plan,
                                      const NamedParameters& np = parameters::default_values())
{
  auto vpm = parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                          get_property_map(vertex_point, pm));
  internal::Operation_log<PolygonMesh, decltype(vpm)> log(pm, vpm);
  return internal::run_qzip(pm, log, plan, np);
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
  return internal::run_qzip(pm, history.operation_log(), plan, np);
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

undoes the Q-zip that produced `done` by its reverse Q-zip (paper, Sec. 2.8), without any record of its
atomic operations: `done.reverse_plan` walks the adjusted path of the Q-zip backwards, from the moved
terminal singularity towards the moved initial one, with the inverse strip operations, and is executed
with `execute_qzip()`. The mesh comes back up to isomorphism: the connectivity is the one before the
Q-zip (the elements re-created have new descriptors), the positions are not restored (the atomic
operations place the vertices as usual). The result carries in turn the reverse of the reverse, which
redoes the Q-zip.

When the Q-zip needed the valence-2/valence-6 clean-up, the reverse plan first undoes it
(`Surgery_plan::prelude`); when a collapse of the Q-zip merged away a vertex of the path it had already
visited, the reverse plan names that vertex as the one a split of its own chain re-creates
(`Surgery_plan::created_vertices`). A Q-zip that moved a border defect is reversed like any other: the
reverse starts at the border end of its path. Border defects depend on the corner angles, which the
placement of the Q-zip may have changed: the reverse plan judges them with the numbers of faces the Q-zip
judged them by (`Surgery_plan::expected_faces`). A Q-zip has no reverse Q-zip (see
`Reverse_qzip_status`) when it cancelled singularities (a Q-zip never creates any), or in the rare
clean-ups that cannot be undone first; `done.reverse_status` says which. Like every execution the
reverse is transactional: if it cannot be completed the mesh is restored.

\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the polygon mesh, unchanged since the Q-zip that returned `done`
\param done the result of that Q-zip
\param np the named parameters of `execute_qzip()`
\returns the result of the execution; when `done.reverse_status` is not `AVAILABLE`, the mesh is not
         touched and the status is `Plan_status::INVALID_PATH`.
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Qzip_result<PolygonMesh> reverse_qzip(PolygonMesh& pm, const Qzip_result<PolygonMesh>& done,
                                      const NamedParameters& np = parameters::default_values())
{
  if(done.reverse_status != Reverse_qzip_status::AVAILABLE) return Qzip_result<PolygonMesh>();
  return execute_qzip(pm, done.reverse_plan, np);
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
