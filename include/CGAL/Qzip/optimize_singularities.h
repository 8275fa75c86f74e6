// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_OPTIMIZE_SINGULARITIES_H
#define CGAL_QZIP_OPTIMIZE_SINGULARITIES_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Named_function_parameters.h>
#include <CGAL/Qzip/Optimizer_visitor_base.h>
#include <CGAL/Qzip/stop_predicates.h>
#include <CGAL/Qzip/smoothing.h>
#include <CGAL/Qzip/Scoring/Default_scoring.h>
#include <CGAL/Qzip/internal/optimizer/Batch_optimizer.h>
#include <CGAL/Qzip/internal/optimizer/Triangle_pairing.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
What `optimize_singularities()` returns: the statistics of its batches of Q-zips (the final state of
`Optimizer_statistics`) and what its triangle pairing did on a hybrid triangle-quad mesh.
*/
struct Optimizer_result : Optimizer_statistics
{
  std::size_t initial_number_of_triangles = 0; ///< triangles of the input
  std::size_t number_of_triangles = 0;         ///< triangles left at the end
  std::size_t number_of_triangle_collisions = 0; ///< collisions kept by the pairing (each turns two triangles into quads)
  std::size_t number_of_undone_triangle_paths = 0; ///< triangle paths and collisions tried and undone
};

/*!
\ingroup PkgQzipOptimizer

reduces the number of singularities of a quad mesh by batches of Q-zips (paper, Sec. 4.1), while keeping
its quads valid, its size roughly constant, its features and protected regions intact.

In a hybrid mesh of quads and triangles, the triangles are paired first (paper, Sec. 3.2): each triangle is
moved along the shortest edge paths from its tip towards the corners of the closest other triangles
(`move_triangle_along_path()`, at most 12 edges, through interior vertices whose one-ring has no border,
constrained edge nor protected face) and adjacent triangles are collided directly (`collide_triangles()`).
A path or collision is kept only when it turns triangles into quads, lowers `2 #triangles + sum |defect|`
(the tip of a canonical triangle counted as regular, see `Mesh_report`) and inverts no quad; otherwise it
is undone exactly. The batches of Q-zips then never touch a triangle (their edges count as border edges,
see `Non_quad_face_map`). Faces of degree 5 or more are not supported by the pairing (they are left as they
are, and the Q-zips avoid them like triangles).

Each batch picks at random half of the singularities that can start a Q-zip (interior vertices of valence 3
or 5 not on a feature nor a protected face). For each, the three closest v3-like and the three closest
v5-like singularities (graph distance through passable vertices; boundary and feature defects met on the
way are also tried) are joined by a shortest surgery path, and the four motions of each pair are planned
(24 candidate surgeries). Every realizable plan is scored from the plan alone (no execution) by the
scoring functor; each singularity keeps its best improving candidate (and its next twelve, in order). The
candidates are sorted and the best half is executed serially (all of them, best first, when the
singularities are sparse: `Optimizer_statistics::pairing_distance` at least 25 times their number, as on
fine subdivisions), skipping any surgery whose path comes within
three edges of a path already operated on in this batch (a singularity whose best candidate is skipped
tries its next ones instead), unless all those surgeries were undone: then the mesh there is as it was, and
the candidate is found again by its positions and planned again. After each surgery its scar is smoothed (see `smooth_quad_mesh()`); if the
surgery leaves more inverted quads (scaled Jacobian `<= 0`) near its path than there were, or a quad worse
than both the worst one before and `quality_floor` (0.1 by default), the scar is untangled (each vertex with a
quad below the floor moves to the best of a few positions on the surface, at most `number_of_untangling_sweeps`
sweeps) and checked again; if it still fails (or the number
of faces is outside `face_count_tolerance`), the smoothing
and the surgery are undone exactly, and the same surgery (same positions of its ends, same motion) is not
a candidate again until a batch lowers the number of singularities. A kept Q-zip moves its pair by about
one edge; while each end of the pair is still more than three edges from the singularity of the opposite
sign it is pulled towards (its closest one other than the pair, at the start of the batch, as
`Pairing_term` sees it) and no surgery of the batch came near those, the pair is Q-zipped again along a
shortest path between its new places, with the motion whose predicted landings are closest to them,
under the same checks: far apart singularities travel several edges in one batch. After the batch the
union of its scars is smoothed again. The stop predicate is asked before every batch (by default: at
most 200 batches, and stop when 20 batches in a row neither lowered the number of singularities nor
brought them closer to partners of the opposite sign, see `Default_stop_predicate`).

When the stop predicate says stop, an end game follows: in rounds, every singularity that can start a
Q-zip and has a singularity of the opposite sign within two edges (not a random half) tries all its
improving candidates whose predicted landings cancel singularities (see `Qzip_candidate`), those
predicting the most cancellations first. Each is executed and smoothed as above and kept only if, in
addition, the number of singular vertices within four edges of its path dropped; otherwise it is undone
exactly and not tried again. Rounds go on while they try surgeries (at most 10). If the end game cancelled singularities, the
batches resume when the stop predicate agrees (it is asked as after a batch that made progress), so a
`Batch_count_stop_predicate` still bounds the number of batches; end-game rounds are counted apart
(`Optimizer_statistics::end_game_rounds`) and not reported to the visitor's `on_batch_finished()`.

Since a Q-zip never creates a singularity (`execute_qzip()` rolls back otherwise), the number of
singularities never grows. No surgery touches a constrained edge or a protected face, and the border only
where a Q-zip moves a border defect along a straight piece of it (see `plan_qzip()`: a border vertex is
split there, and both copies move a third of the way towards the midpoint of their border neighbours);
smoothing moves no border vertex, slides the vertices of feature curves along the input feature polylines
and keeps feature corners and the vertices of protected faces in place. So feature curves keep their
vertices and edges, feature corners and protected faces keep their positions bit for bit; since surgeries
and smoothing are both guarded, no inverted quad appears when the input has none, and when no quad of a
pure quad input is below `quality_floor`, none of the result is either. A higher floor keeps better quads
and undoes more surgeries: over the benchmark's corpus (21 meshes, two seeds) floor 0.3 ends with 8% more
singularities in 51% more time than 0.1, floor 0.05 with 2% fewer in 6% less time (`benchmark/Qzip/RESULTS.md`,
session 28). When smoothing is on,
the vertices stay on the input surface (`pm` as given, its faces triangulated): the vertices a surgery
touched are put at their closest point on it before its scar is smoothed, every smoothing move is projected
onto it, and the vertices the pairing of triangles placed are put onto it when their quads accept it (a vertex
whose quads refuse stays off the surface until a smoothing move of it is accepted). The result depends only
on the input, the parameters and the seed, not on the mesh data structure.

Interior vertices of valence 2 or 6 and more cannot move: call `preprocess_valences()` first.

\tparam PolygonMesh a model of `MutableFaceGraph` and `FaceListGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the quad mesh
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `pm`}
    \cgalParamType{a class model of `ReadWritePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
                   as key type and `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class (a \cgal kernel)}
    \cgalParamDefault{deduced from the point type}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_constrained_map}
    \cgalParamDescription{feature edges: never crossed nor edited; they also cut the fans of their vertices into
                          sectors for the defects (see `vertex_defect()`)}
    \cgalParamDefault{no edge is constrained}
  \cgalParamNEnd
  \cgalParamNBegin{face_is_constrained_map}
    \cgalParamDescription{(Qzip) protected faces: no surgery reaches them, smoothing does not move their vertices}
    \cgalParamDefault{no face is protected}
  \cgalParamNEnd
  \cgalParamNBegin{scoring_functor}
    \cgalParamDescription{(Qzip) a model of `QzipScoringFunctor` (see `Default_scoring`)}
    \cgalParamDefault{`Default_scoring()`}
  \cgalParamNEnd
  \cgalParamNBegin{stop_predicate}
    \cgalParamDescription{(Qzip) a model of `QzipStopPredicate`, asked before each batch}
    \cgalParamDefault{`Default_stop_predicate()`: at most 200 batches, stop when they make no progress}
  \cgalParamNEnd
  \cgalParamNBegin{do_smooth}
    \cgalParamDescription{(Qzip) whether scars are smoothed; without smoothing, surgeries whose rough vertex
                          placement inverts a quad are undone}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{do_end_game}
    \cgalParamDescription{(Qzip) whether the end game runs when the stop predicate says stop: rounds that try every
                          improving candidate predicted to cancel singularities next to an opposite one, keeping
                          those that lower the number of singularities near their path (see the user manual)}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{do_look_ahead}
    \cgalParamDescription{(Qzip) whether the end game also tries chains of Q-zips that bring a singularity onto
                          one of the opposite sign up to fourteen edges away, keeping only chains that cancel them and
                          pass the quality guard (see the user manual)}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_relaxation_steps}
    \cgalParamDescription{the number of smoothing sweeps after each surgery and after each batch}
    \cgalParamDefault{5}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_untangling_sweeps}
    \cgalParamDescription{(Qzip) a surgery whose smoothed scar has more inverted quads than before, or a quad worse
                          than both the worst one before and `quality_floor`, is untangled with at most this many
                          sweeps and checked again before it is undone (0: undone at once; ignored without smoothing)}
    \cgalParamDefault{20}
  \cgalParamNEnd
  \cgalParamNBegin{quality_floor}
    \cgalParamDescription{(Qzip) the scaled Jacobian (see `quad_scaled_jacobian()`) below which no surgery, chain of
                          the end game nor smoothing move takes a quad, unless the worst quad around it was already
                          lower and does not get worse: a surgery is undone if its scar ends with a quad below both}
    \cgalParamType{`double`, in `(0, 1)`}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{face_count_tolerance}
    \cgalParamDescription{(Qzip) a candidate that would take the number of faces farther than this fraction
                          of the number of faces of `pm` (as given, before the collisions of its triangles)
                          away from it is not considered}
    \cgalParamDefault{0.1}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_running_time}
    \cgalParamDescription{a time limit in seconds (wall clock, from the call): once it is reached, no batch,
                          end-game round nor look-ahead chain starts (the one under way finishes, so the run
                          may exceed the limit by about one batch), and `Optimizer_statistics::reached_time_limit`
                          is set. The result is that of the run without a limit cut after its last batch or
                          chain: valid, with no more singularities than the input. The pairing of the
                          triangles of a hybrid mesh, before the batches, is not cut.}
    \cgalParamType{`double`}
    \cgalParamDefault{no limit}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the `CGAL::Random` that picks the singularities of each batch}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{visitor}
    \cgalParamDescription{a visitor (see `Default_optimizer_visitor`), passed by `std::ref` to keep its state}
    \cgalParamDefault{no visitor}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the statistics of the run (see `Optimizer_result`)
\pre `pm` is a valid polygon mesh
\pre `quality_floor`, if given, is in `(0, 1)`
\sa `execute_qzip()`, `smooth_quad_mesh()`, `preprocess_valences()`
*/
template <typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Optimizer_result optimize_singularities(PolygonMesh& pm, const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::get_parameter_reference;
  CGAL::Real_timer timer; // for the time limit
  timer.start();

  typedef typename GetGeomTraits<PolygonMesh, NamedParameters>::type Geom_traits;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::type VPM;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::edge_is_constrained_t, NamedParameters,
            Static_boolean_property_map<edge_descriptor, false> >::type ECM;
  typedef typename CGAL::internal_np::Lookup_named_param_def<Qzip::internal_np::face_is_constrained_t, NamedParameters,
            Static_boolean_property_map<face_descriptor, false> >::type FCM;
  typedef typename CGAL::internal_np::Lookup_named_param_def<Qzip::internal_np::scoring_functor_t, NamedParameters,
            Default_scoring>::type Scoring;
  typedef typename CGAL::internal_np::Lookup_named_param_def<Qzip::internal_np::stop_predicate_t, NamedParameters,
            Default_stop_predicate>::type Stop;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::visitor_t, NamedParameters,
            Default_optimizer_visitor<PolygonMesh> >::reference Visitor;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, pm));
  const ECM ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                   Static_boolean_property_map<edge_descriptor, false>());
  const FCM fcm = choose_parameter(get_parameter(np, Qzip::internal_np::face_is_constrained),
                                   Static_boolean_property_map<face_descriptor, false>());
  const Scoring scoring = choose_parameter<Default_scoring>(get_parameter(np, Qzip::internal_np::scoring_functor));
  const Stop stop = choose_parameter<Default_stop_predicate>(get_parameter(np, Qzip::internal_np::stop_predicate));
  Default_optimizer_visitor<PolygonMesh> default_visitor;
  Visitor visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);

  internal::Optimizer_settings settings; // the defaults of the named parameters
  settings.smooth = choose_parameter(get_parameter(np, Qzip::internal_np::smoothing), settings.smooth);
  settings.end_game = choose_parameter(get_parameter(np, Qzip::internal_np::end_game), settings.end_game);
  settings.look_ahead = choose_parameter(get_parameter(np, Qzip::internal_np::look_ahead), settings.look_ahead);
  settings.smoothing_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxation_steps),
                                                   settings.smoothing_iterations);
  settings.untangling_sweeps = choose_parameter(get_parameter(np, Qzip::internal_np::untangling_sweeps),
                                                settings.untangling_sweeps);
  settings.face_count_tolerance = choose_parameter(get_parameter(np, Qzip::internal_np::face_count_tolerance),
                                                   settings.face_count_tolerance);
  settings.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), settings.seed);
  settings.quality_floor = choose_parameter(get_parameter(np, Qzip::internal_np::quality_floor),
                                            settings.quality_floor);
  CGAL_precondition(settings.quality_floor > 0 && settings.quality_floor < 1);

  settings.input_number_of_faces = faces(pm).size();

  typedef internal::Triangle_pairing<PolygonMesh, VPM, ECM, FCM, Geom_traits> Pairing;
  typedef internal::Quad_smoother<PolygonMesh, VPM, ECM, FCM, Geom_traits> Smoother;
  typedef typename boost::property_traits<VPM>::value_type Point;
  // the reference surface of the projections: `pm` as given, before the pairing of its triangles
  Smoother smoother(pm, vpm, ecm, fcm, settings.smooth);
  smoother.quality_floor = settings.quality_floor;
  Optimizer_result result;
  result.initial_number_of_triangles = Pairing::number_of_triangles(pm);
  if(result.initial_number_of_triangles > 1)
  {
    const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits));
    const auto less = gt.less_xyz_3_object();
    std::vector<Point> input_points;
    for(typename GT::vertex_descriptor v : vertices(pm)) input_points.push_back(get(vpm, v));
    std::sort(input_points.begin(), input_points.end(), less);
    const internal::Triangle_pairing_statistics ps = Pairing(pm, vpm, ecm, fcm, gt).run();
    result.number_of_triangle_collisions = ps.collisions;
    result.number_of_undone_triangle_paths = ps.undone;
    // the vertices the kept collisions placed off the surface (an undone attempt restores every position)
    std::vector<typename GT::vertex_descriptor> placed;
    for(typename GT::vertex_descriptor v : vertices(pm))
      if(!std::binary_search(input_points.begin(), input_points.end(), get(vpm, v), less)) placed.push_back(v);
    if(settings.smooth) smoother.settle_on_surface(placed);
  }

  settings.time_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                         settings.time_limit) - timer.time();
  internal::Batch_optimizer<PolygonMesh, VPM, ECM, FCM, Geom_traits>
    optimizer(pm, vpm, ecm, fcm, smoother, scoring, stop, visitor, settings);
  static_cast<Optimizer_statistics&>(result) = optimizer.run();
  result.number_of_triangles = Pairing::number_of_triangles(pm);
  return result;
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_OPTIMIZE_SINGULARITIES_H
