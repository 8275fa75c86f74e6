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
#include <CGAL/Qzip/qzip.h> // Qzip_result, what the executor returns
#include <CGAL/Qzip/internal/chain_executor.h>
#include <CGAL/Qzip/Named_function_parameters.h>
#include <CGAL/Qzip/Qzip_visitor_base.h>
#include <CGAL/Qzip/internal/operation_log.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <functional>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {

namespace internal {

// declared for the case where chain_executor.h is included first: it includes surgery_plan.h, which
// includes this file before the executor is defined
template <typename PolygonMesh, typename VertexPointMap, typename NamedParameters> class Chain_executor;

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

// The result of a simulated execution: the failure the execution of the plan would meet (`NONE` when
// it would succeed) and the path position where it would; `decided` is false when the neighbourhood
// could not be copied (the plan is then left to the executor).
struct Simulated_execution
{
  Execution_failure failure = Execution_failure::NONE;
  std::size_t failed_step = 0;
  bool decided = true;
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
// twice the radius when one is not (the chain merged vertices from farther away towards the path). The
// default radius, 3, leaves a margin of one ring over what the chain and its clean-up reach in every
// test case (test_qzip forces every plan refused by the simulation through the executor: it fails; and no
// plan accepted by the simulation is rolled back).
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap>
class Chain_simulation
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
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

  static constexpr int default_radius = 3;
  static constexpr int maximal_radius = 24;

  const PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;

  // the copy, made again for every radius
  Local_mesh local;
  typename Local_ecm::type ecm_local;
  typename Local_fcm::type fcm_local;
  std::unordered_map<vertex_descriptor, Local_vertex, boost::hash<vertex_descriptor> > to_local;
  std::unordered_map<vertex_descriptor, int, boost::hash<vertex_descriptor> > depth; // distance to the path, up to radius
  std::unordered_set<face_descriptor, boost::hash<face_descriptor> > copied_faces;
  std::vector<vertex_descriptor> inner;  // the vertices up to `radius` edges from the path, by distance
  std::vector<face_descriptor> faces_to_copy;
  std::vector<bool> complete;            // by local vertex index; later vertices are made by splits of complete ones
  std::vector<Local_vertex> corners;

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

  // copies the faces incident to the vertices at most `radius` edges from `path`; false when the copy
  // cannot be made (a face the local mesh refuses)
  bool copy_neighbourhood(const std::vector<vertex_descriptor>& path, int radius)
  {
    local.clear_without_removing_property_maps();
    to_local.clear(); depth.clear(); copied_faces.clear(); inner.clear(); faces_to_copy.clear();
    for(vertex_descriptor v : path)
      if(depth.emplace(v, 0).second) inner.push_back(v);
    for(std::size_t i = 0; i < inner.size(); ++i)
    {
      const vertex_descriptor v = inner[i];
      const int d = depth[v];
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        if(d < radius && depth.emplace(source(h, pm), d + 1).second) inner.push_back(source(h, pm));
        if(!is_border(h, pm) && copied_faces.insert(face(h, pm)).second) faces_to_copy.push_back(face(h, pm));
      }
    }
    local.reserve(4 * faces_to_copy.size(), 4 * faces_to_copy.size(), faces_to_copy.size());
    for(face_descriptor f : faces_to_copy)
    {
      corners.clear();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
      {
        const auto ins = to_local.emplace(target(h, pm), Local_vertex());
        if(ins.second) ins.first->second = local.add_vertex(get(vpm, target(h, pm)));
        corners.push_back(ins.first->second);
      }
      const Local_face lf = local.add_face(corners);
      if(lf == Local_mesh::null_face()) return false;
      if constexpr(Local_fcm::copied) if(get(fcm, f)) put(fcm_local, lf, true);
      if constexpr(Local_ecm::copied)
        for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
          if(get(ecm, edge(h, pm))) put(ecm_local, edge(local_halfedge(h), local), true);
    }
    complete.assign(local.number_of_vertices(), false);
    for(vertex_descriptor v : inner)
    {
      const Local_vertex lv = to_local.at(v);
      complete[std::size_t(lv)] = true;
      // the same first incoming halfedge as in the input: the executor's clean-up turns around a vertex
      // from there, and so makes the same choices on the copy
      local.set_halfedge(lv, local_halfedge(halfedge(v, pm)));
    }
    return true;
  }

  Local_halfedge local_halfedge(halfedge_descriptor h) const
  {
    return halfedge(to_local.at(source(h, pm)), to_local.at(target(h, pm)), local).first;
  }

  Simulated_execution run_on_copy(const Surgery_plan<PolygonMesh>& plan, bool& reached_cut)
  {
    Surgery_plan<Local_mesh> copy;
    copy.source = to_local.at(plan.source);
    copy.target = to_local.at(plan.target);
    copy.source_valence = plan.source_valence;
    copy.target_valence = plan.target_valence;
    copy.initial_operation = plan.initial_operation;
    copy.operations = plan.operations;
    copy.status = Plan_status::REALIZABLE;
    for(vertex_descriptor v : plan.path) copy.path.push_back(to_local.at(v));

    Local_point_map points = local.points();
    Operation_log<Local_mesh, Local_point_map> log(local, points);
    Cut_watcher watcher(complete);
    const auto np = Qzip::parameters::face_is_constrained_map(fcm_local,
                      CGAL::parameters::vertex_point_map(points).edge_is_constrained_map(ecm_local).visitor(std::ref(watcher)));
    Chain_executor<Local_mesh, Local_point_map, std::decay_t<decltype(np)> > executor(local, log, np);
    const Qzip_result<Local_mesh> r = executor.run(copy);
    reached_cut = watcher.reached_cut;
    Simulated_execution s;
    s.failure = r.failure;
    s.failed_step = r.failed_step;
    return s;
  }

public:
  Chain_simulation(const PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm),
      ecm_local(Local_ecm::make(local, "e:qzip_constrained")), fcm_local(Local_fcm::make(local, "f:qzip_constrained"))
  {}

  // what the execution of `plan` (a forward plan: no prelude, no created vertex) would do
  Simulated_execution run(const Surgery_plan<PolygonMesh>& plan)
  {
    CGAL_precondition(plan.prelude.empty() && plan.created_vertices.empty());
    for(int radius = default_radius; radius <= maximal_radius; radius *= 2)
    {
      if(!copy_neighbourhood(plan.path, radius)) break;
      bool reached_cut = false;
      const Simulated_execution s = run_on_copy(plan, reached_cut);
      if(!reached_cut) return s;
    }
    Simulated_execution undecided;
    undecided.decided = false;
    return undecided;
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_CHAIN_SIMULATION_H
