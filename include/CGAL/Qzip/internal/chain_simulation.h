// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_CHAIN_SIMULATION_H
#define CGAL_QZIP_INTERNAL_CHAIN_SIMULATION_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/surgery_plan.h>
#include <CGAL/Qzip/Named_function_parameters.h>
#include <CGAL/Qzip/Qzip_visitor_base.h>
#include <CGAL/Qzip/internal/operation_log.h>
#include <CGAL/Qzip/internal/descriptor_hash_map.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {
// declared first: when chain_executor.h is included first, it includes surgery_plan.h, which includes
// this file, and so qzip.h below, before the executor is defined
template <typename PolygonMesh, typename VertexPointMap, typename ECM, typename FCM, typename Visitor> class Chain_executor;
} // namespace internal
} // namespace Qzip
} // namespace CGAL

#include <CGAL/Qzip/internal/chain_executor.h>
#include <CGAL/Qzip/qzip.h> // Qzip_result, what the executor returns

namespace CGAL {
namespace Qzip {

namespace internal {

// The constraint map of the local copy: a property of the copy when the input has one, the same
// constant map otherwise (nothing to copy).
template <typename InputMap, typename LocalKey, typename LocalMesh>
struct Local_constraint_map
{
  typedef typename LocalMesh::template Property_map<LocalKey, bool> type;
  static constexpr bool copied = true;
  static type make(LocalMesh& local, const char* name)
  { return local.template add_property_map<LocalKey, bool>(name, false).first; }
};

template <typename InputKey, typename LocalKey, typename LocalMesh>
struct Local_constraint_map<Static_boolean_property_map<InputKey, false>, LocalKey, LocalMesh>
{
  typedef Static_boolean_property_map<LocalKey, false> type;
  static constexpr bool copied = false;
  static type make(LocalMesh&, const char*) { return type(); }
};

// The named parameters of the executor on the local copy.
template <typename PointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap, typename Visitor>
auto local_executor_parameters(PointMap points, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm, Visitor& visitor)
{
  return Qzip::parameters::face_is_constrained_map(fcm, CGAL::parameters::vertex_point_map(points)
                                                          .edge_is_constrained_map(ecm).visitor(std::ref(visitor)));
}

// The result of a simulated execution: the failure the execution of the plan would meet (`NONE` when
// it would succeed) and the path position where it would.
struct Simulated_execution
{
  Execution_failure failure = Execution_failure::NONE;
  std::size_t failed_step = 0;
};

// Runs the executor (Chain_executor: the chain, the valence-2/6 clean-up and the singularity check) on a
// local copy of the neighbourhood of a plan's path, so that a plan whose execution would fail is refused
// before the mesh is touched.
//
// The copy holds every face incident to a vertex at most `radius` edges from the path, so those vertices
// are *complete*: their ring, border status, valence and defect (positions, constrained edges and
// protected faces are copied too) are those of the input, and an operation among complete vertices does
// on the copy what it does on the input. The copy has an artificial border (the cut) around them: its
// vertices have lost faces and must never be inspected. The executor reads the rings of the vertices of
// the operations it applies or attempts and of their neighbours (link condition, clean-up candidates,
// valence-6 split delimiters, singularity check); a watcher (the executor's visitor) checks that every
// vertex of an applied operation and each of its neighbours is complete, and the copy is made again with
// twice the radius when one is not (the chain merged vertices from farther away towards the path); past
// `maximal_radius` the simulation gives up and leaves the plan to the executor. The watcher does not see
// the operation whose check fails (the executor tells no visitor of it): a failure is only believed when a
// copy with twice the radius fails at the same step for the same reason. The watcher, not the radius,
// makes the simulation exact; the radius only decides how often a copy is made again. The first radius,
// 2, is the smallest at which the collapses along the path (whose quads have their corners at most one
// edge from it) have complete neighbours; the watcher asks for a second copy for a few plans in a hundred
// (2.3% of those of benchmark_qzip). A radius of 3 never needed one in the tests but makes the copy 40%
// larger; with a radius of 1 and no watcher, some plans refused by the simulation succeed when forced.
// test_qzip forces every plan refused by the simulation through the executor, where it fails at the same
// step for the same reason, and no plan accepted by the simulation is rolled back.
//
// The copy is a Surface_mesh built array by array (no face insertion), mirroring the input: the same
// first incoming halfedge at each complete vertex, so that the executor's clean-up, which turns around a
// vertex from there, makes the same choices on the copy. An object is meant to be reused from plan to
// plan: its buffers stay allocated (the hash maps, see Descriptor_hash_map; the arrays of the copy, which
// is resized rather than cleared; the executor, with its operation log), so that a simulation allocates
// little.
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap>
class Chain_simulation
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

  typedef CGAL::Surface_mesh<Point> Local_mesh;
  typedef typename Local_mesh::Vertex_index Local_vertex;
  typedef typename Local_mesh::Halfedge_index Local_halfedge;
  typedef typename Local_mesh::Edge_index Local_edge;
  typedef typename Local_mesh::Face_index Local_face;
  typedef typename Local_mesh::template Property_map<Local_vertex, Point> Local_point_map;
  typedef Local_constraint_map<EdgeIsConstrainedMap, Local_edge, Local_mesh> Local_ecm;
  typedef Local_constraint_map<FaceIsConstrainedMap, Local_face, Local_mesh> Local_fcm;

  static constexpr int first_radius = 2;
  static constexpr int maximal_radius = 24;

  // the copy, made again for every plan and radius
  Local_mesh local;
  typename Local_ecm::type ecm_local;
  typename Local_fcm::type fcm_local;
  Descriptor_hash_map<vertex_descriptor, int> depth;                 // distance to the path, up to the radius
  Descriptor_hash_map<vertex_descriptor, Local_vertex> vertex_copy;
  Descriptor_hash_map<halfedge_descriptor, Local_halfedge> halfedge_copy;
  Descriptor_hash_map<face_descriptor, Local_face> face_copy;
  std::vector<vertex_descriptor> inner;      // the vertices up to the radius from the path, by distance
  std::vector<face_descriptor> faces_to_copy;     // local face k is faces_to_copy[k]
  std::vector<vertex_descriptor> vertices_to_copy; // local vertex i is vertices_to_copy[i]
  std::vector<std::pair<Local_halfedge, Local_vertex> > corners; // the halfedges of the copied faces, and their targets
  std::vector<std::size_t> face_begin;             // face k's corners start at face_begin[k]
  std::vector<Local_edge> constrained_edges;
  std::vector<halfedge_descriptor> outside;  // copied halfedges whose face may not be copied (border of the copy)
  std::vector<bool> complete;                // by local vertex index (later vertices are made by splits)
  Surgery_plan<Local_mesh> local_plan;

  // Checks, before each operation the executor applies to the copy, that its vertices and their
  // neighbours are complete (see above).
  struct Cut_watcher : Default_qzip_visitor<Local_mesh>
  {
    const std::vector<bool>& complete;
    bool reached_cut = false;
    explicit Cut_watcher(const std::vector<bool>& complete) : complete(complete) {}

    bool is_complete(Local_vertex v) const { return std::size_t(v) >= complete.size() || complete[std::size_t(v)]; }
    void check(Local_vertex v, const Local_mesh& m)
    {
      if(!is_complete(v)) { reached_cut = true; return; }
      for(Local_halfedge h : halfedges_around_target(halfedge(v, m), m))
        if(!is_complete(source(h, m))) { reached_cut = true; return; }
    }
    void on_collapse(Local_halfedge h, const Local_mesh& m)
    {
      check(target(h, m), m); check(target(next(h, m), m), m);
      check(target(next(next(h, m), m), m), m); check(source(h, m), m);
    }
    void on_split(Local_halfedge h1, Local_halfedge h2, const Local_mesh& m)
    {
      check(target(h1, m), m); check(source(h1, m), m); check(source(h2, m), m);
    }
  };

  // the executor, its operation log and its watcher, kept from plan to plan for their buffers
  Operation_log<Local_mesh, Local_point_map> log;
  Cut_watcher watcher;
  Chain_executor<Local_mesh, Local_point_map, typename Local_ecm::type, typename Local_fcm::type, Cut_watcher&> executor;

  bool is_copied(face_descriptor f) const { return f != GT::null_face() && face_copy.find(f) != nullptr; }

  // copies the faces incident to the vertices at most `radius` edges from `path`
  void copy_neighbourhood(const std::vector<vertex_descriptor>& path, int radius, const PolygonMesh& pm,
                          const VertexPointMap& vpm, const EdgeIsConstrainedMap& ecm, const FaceIsConstrainedMap& fcm)
  {
    // The copy is not cleared (Surface_mesh::clear_without_removing_property_maps() frees the arrays, and
    // allocating them again is a good part of the cost between plans) but resized below, and every value
    // is written again; the elements the last execution removed are first taken back (add_vertex() and
    // the like reuse removed elements and reset their properties), and the last constraints are lifted.
    while(local.number_of_removed_vertices() != 0) local.add_vertex();
    while(local.number_of_removed_edges() != 0) local.add_edge();
    while(local.number_of_removed_faces() != 0) local.add_face();
    for(Local_edge e : constrained_edges) put(ecm_local, e, false);
    depth.clear(); vertex_copy.clear(); halfedge_copy.clear(); face_copy.clear();
    inner.clear(); faces_to_copy.clear(); outside.clear(); vertices_to_copy.clear(); corners.clear();
    face_begin.clear(); constrained_edges.clear();
    for(vertex_descriptor v : path)
      if(depth.insert(v, 0).second) inner.push_back(v);
    for(std::size_t i = 0; i < inner.size(); ++i)
    {
      const vertex_descriptor v = inner[i];
      const int d = *depth.find(v);
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        if(d < radius && depth.insert(source(h, pm), d + 1).second) inner.push_back(source(h, pm));
        if(!is_border(h, pm) && face_copy.insert(face(h, pm), Local_face(faces_to_copy.size())).second)
          faces_to_copy.push_back(face(h, pm));
      }
    }
    // the local indices, in the order of Surface_mesh (the halfedges of edge e are 2e and 2e + 1)
    std::size_t edges = 0;
    for(face_descriptor f : faces_to_copy)
    {
      face_begin.push_back(corners.size());
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
      {
        Local_halfedge lh(2 * edges);
        const auto hi = halfedge_copy.insert(h, lh);
        if(hi.second)
        {
          halfedge_copy.insert(opposite(h, pm), Local_halfedge(2 * edges + 1));
          outside.push_back(opposite(h, pm)); // until its face is copied
          if constexpr(Local_ecm::copied) if(get(ecm, edge(h, pm))) constrained_edges.push_back(Local_edge(edges));
          ++edges;
        }
        else lh = *hi.first;
        const auto vi = vertex_copy.insert(target(h, pm), Local_vertex(vertices_to_copy.size()));
        if(vi.second) vertices_to_copy.push_back(target(h, pm));
        corners.emplace_back(lh, *vi.first);
      }
    }
    face_begin.push_back(corners.size());
    local.resize(vertices_to_copy.size(), edges, faces_to_copy.size());
    Local_point_map points = local.points();
    for(std::size_t i = 0; i < vertices_to_copy.size(); ++i) put(points, Local_vertex(i), get(vpm, vertices_to_copy[i]));
    for(std::size_t k = 0; k < faces_to_copy.size(); ++k)
    {
      const Local_face lf(k);
      const std::size_t begin = face_begin[k], end = face_begin[k + 1];
      local.set_halfedge(lf, corners[begin].first);
      for(std::size_t j = begin; j < end; ++j)
      {
        const Local_halfedge lh = corners[j].first;
        local.set_target(lh, corners[j].second);
        local.set_halfedge(corners[j].second, lh); // replaced by a border halfedge, or the input's, below
        local.set_face(lh, lf);
        local.set_next(lh, corners[j + 1 == end ? begin : j + 1].first);
      }
      if constexpr(Local_fcm::copied) put(fcm_local, lf, get(fcm, faces_to_copy[k]));
    }
    for(Local_edge e : constrained_edges) put(ecm_local, e, true);
    // the border of the copy: the real border, and the cut. Its cycles turn around each vertex through
    // the faces that are not copied, to the next copied edge.
    for(halfedge_descriptor g : outside)
    {
      if(is_copied(face(g, pm))) continue;
      const Local_halfedge lg = *halfedge_copy.find(g);
      const Local_vertex lv = *vertex_copy.find(target(g, pm));
      local.set_target(lg, lv);
      local.set_face(lg, Local_mesh::null_face());
      halfedge_descriptor x = next(g, pm);
      while(halfedge_copy.find(x) == nullptr) x = next(opposite(x, pm), pm);
      local.set_next(lg, *halfedge_copy.find(x));
      local.set_halfedge(lv, lg);
    }
    complete.assign(vertices_to_copy.size(), false);
    for(vertex_descriptor v : inner)
    {
      const Local_vertex lv = *vertex_copy.find(v);
      complete[std::size_t(lv)] = true;
      // the same first incoming halfedge as in the input: the executor's clean-up turns around a vertex
      // from there, and so makes the same choices on the copy
      local.set_halfedge(lv, *halfedge_copy.find(halfedge(v, pm)));
    }
  }

  // runs the executor on the copy; `reached_cut` tells whether the watcher saw an incomplete vertex
  Simulated_execution run_on_copy(const Surgery_plan<PolygonMesh>& plan, bool& reached_cut)
  {
    local_plan.source = *vertex_copy.find(plan.source);
    local_plan.target = *vertex_copy.find(plan.target);
    local_plan.source_valence = plan.source_valence;
    local_plan.target_valence = plan.target_valence;
    local_plan.initial_operation = plan.initial_operation;
    local_plan.operations = plan.operations;
    local_plan.status = Plan_status::REALIZABLE;
    local_plan.path.clear();
    for(vertex_descriptor v : plan.path) local_plan.path.push_back(*vertex_copy.find(v));

    log.clear(); // the copy was made again
    watcher.reached_cut = false;
    Simulated_execution s;
    s.failure = executor.apply(local_plan);
    if(s.failure != Execution_failure::NONE) s.failed_step = executor.failed_position();
    reached_cut = watcher.reached_cut;
    return s;
  }

public:
  Chain_simulation()
    : ecm_local(Local_ecm::make(local, "e:qzip_constrained")), fcm_local(Local_fcm::make(local, "f:qzip_constrained")),
      log(local, local.points()), watcher(complete),
      executor(local, log, local_executor_parameters(local.points(), ecm_local, fcm_local, watcher))
  {}
  Chain_simulation(const Chain_simulation&) = delete; // the log and the executor refer to the copy
  Chain_simulation& operator=(const Chain_simulation&) = delete;

  // what the execution of `plan` (a forward plan: no prelude, no created vertex) on `pm` would do
  Simulated_execution run(const PolygonMesh& pm, const Surgery_plan<PolygonMesh>& plan, const VertexPointMap& vpm,
                          const EdgeIsConstrainedMap& ecm, const FaceIsConstrainedMap& fcm)
  {
    CGAL_precondition(plan.prelude.empty() && plan.created_vertices.empty());
    Simulated_execution first_failure;
    for(int radius = first_radius; radius <= maximal_radius; radius *= 2)
    {
      copy_neighbourhood(plan.path, radius, pm, vpm, ecm, fcm);
      bool reached_cut = false;
      const Simulated_execution s = run_on_copy(plan, reached_cut);
      if(reached_cut) continue;
      if(s.failure == Execution_failure::NONE) return s;
      // the watcher does not see the operation whose check failed: a failure is confirmed on a copy
      // twice as large, where the cut is farther from it
      if(s.failure == first_failure.failure && s.failed_step == first_failure.failed_step) return s;
      first_failure = s;
    }
    return Simulated_execution(); // undecided: left to the executor, which rolls back if it fails
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_CHAIN_SIMULATION_H
