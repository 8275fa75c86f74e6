// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_CHAIN_EXECUTOR_H
#define CGAL_QZIP_INTERNAL_CHAIN_EXECUTOR_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/surgery_plan.h>
#include <CGAL/Qzip/Qzip_visitor_base.h>
#include <CGAL/Qzip/internal/descriptor_hash_map.h>
#include <CGAL/Qzip/internal/operation_log.h>
#include <CGAL/Qzip/internal/rotation.h>
#include <CGAL/Qzip/internal/vertex_defect.h>

#include <CGAL/Kernel_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Qzip {

template <typename PolygonMesh> struct Qzip_result;

namespace internal {

// Executes a surgery plan through an operation log (paper, Sec. 2.7), checks every operation before
// applying it and the valences after the chain, and rolls everything back on failure.
//
// The state carried along the path is the guide g = v->y: y is the transient v3 created by the
// previous operation (the paper's "edge right before"). With o = v->w the next path edge:
//   RC: collapse face(o) = (v, w, x, z), merging z into w; new guide w->x.
//   LC: collapse face(w->v) = (w, v, z, x), merging z into w; new guide w->x.
//   LS: split v between o and g (the new vertex takes the edges strictly counterclockwise from o to g,
//       the new quad is (v, w, c, y)); new guide w->c.
//   RS: the same split; new guide w->v.
//   NOOP: new guide w->v.
//
// An executor can run plan after plan (a simulation runs one on copy after copy): its bookkeeping is
// reset at every run and keeps its buffers (Descriptor_hash_map), so that a run allocates little besides
// the operation log's entries and the result.
//
// It is a template on what it reads of the named parameters (see Chain_executor_of), not on their pack:
// packs that differ only in other parameters share one executor, compiled once.
template <typename PolygonMesh, typename VertexPointMap, typename ECM, typename FCM, typename Visitor>
class Chain_executor
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

  typedef typename Kernel_traits<Point>::Kernel Geom_traits;

  // a touched vertex before the surgery: whether it was on the border, and its singularity code (see
  // singularity_code())
  struct Before { bool border; int code; };
  // what the run knows of a vertex descriptor; a descriptor recycled by the mesh keeps what was known of
  // the removed vertex (its state before the surgery is that vertex's)
  struct Vertex_state
  {
    bool touched = false;      // `before` is known: the vertex existed before the surgery
    Before before = { false, 0 };
    bool has_ideal = false;    // `ideal` is known (see ideal_number_of_faces())
    int ideal = 0;
    bool alive = false;        // touched or created, and not removed since
    bool created = false;      // made by a split of this run
    bool took_border = false;  // an interior vertex merged with a border vertex
    bool listed = false;       // in vertex_order
  };
  struct Face_state
  {
    bool scar = false;         // made by a split of this run, and not removed since
    bool listed = false;       // in face_order
  };
  // what one turn around a vertex tells
  struct Around { int valence = 0; int faces = 0; bool border = false; bool on_feature = false; };

  PolygonMesh& pm;
  Operation_log<PolygonMesh, VertexPointMap>& log;
  ECM ecm;
  FCM fcm;
  Default_qzip_visitor<PolygonMesh> default_visitor;
  Visitor visitor;

  Descriptor_hash_map<vertex_descriptor, Vertex_state> vertex_states;
  Descriptor_hash_map<face_descriptor, Face_state> face_states;
  // the same vertices and faces in the order they first appeared, so that every decision and every output
  // follows the surgery, not the hash order of descriptors (which differs between mesh types)
  std::vector<vertex_descriptor> vertex_order;
  std::vector<face_descriptor> face_order;
  std::vector<vertex_descriptor> candidates; // of the clean-up
  std::vector<int> codes_before, codes_after; // of the singularity check
  // the sectors of feature vertices (see sector_codes()): their frozen numbers of quads, named by the
  // constrained halfedge that starts them, and the codes of the irregular ones before and after
  Descriptor_hash_map<halfedge_descriptor, int> sector_ideals;
  std::vector<int> sector_codes_before, sector_codes_after;
  std::size_t collapses = 0, splits = 0, cleanups = 0;

public:
  template <typename NamedParameters>
  Chain_executor(PolygonMesh& pm, Operation_log<PolygonMesh, VertexPointMap>& log, const NamedParameters& np)
    : pm(pm), log(log),
      ecm(parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                       Static_boolean_property_map<edge_descriptor, false>())),
      fcm(parameters::choose_parameter(parameters::get_parameter(np, Qzip::internal_np::face_is_constrained),
                                       Static_boolean_property_map<face_descriptor, false>())),
      visitor(parameters::choose_parameter(parameters::get_parameter_reference(np, CGAL::internal_np::visitor),
                                           default_visitor))
  {}

  Qzip_result<PolygonMesh> run(const Surgery_plan<PolygonMesh>& plan)
  {
    Qzip_result<PolygonMesh> r;
    r.status = plan.status;
    if(!plan.is_realizable()) return r;
    // the ends of a reverse plan may be created by the execution (Surgery_plan::created_vertices)
    const bool ends_exist = plan.source != GT::null_vertex() && plan.target != GT::null_vertex();
    const Point source_at = ends_exist ? get(log_vpm(), plan.source) : Point();
    const Point target_at = ends_exist ? get(log_vpm(), plan.target) : Point();
    r.failure = apply(plan);
    if(r.failure != Execution_failure::NONE)
    {
      r.failed_step = failed_step;
      r.status = Plan_status::EXECUTION_FAILED;
      return r;
    }
    r.status = Plan_status::REALIZABLE;
    r.number_of_collapses = collapses;
    r.number_of_splits = splits;
    r.number_of_cleanups = cleanups;
    r.touched_vertices = live_vertices_in_order();
    for(face_descriptor f : face_order)
      if(face_states.find(f)->scar) r.scar_faces.push_back(f);
    if(ends_exist) locate_moved_pair(source_at, target_at, r);
    return r;
  }

  // executes a realizable plan and returns `NONE`, or rolls it back and returns why it failed (at path
  // position `failed_position()`): what run() does, without describing the result (for a simulation, which
  // only needs the decision)
  Execution_failure apply(const Surgery_plan<PolygonMesh>& plan)
  {
    CGAL_precondition(plan.is_realizable());
    reset();
    for(const auto& vf : plan.expected_faces) set_ideal(vf.first, vf.second); // a reverse plan's frozen numbers
    const bool ends_exist = plan.source != GT::null_vertex() && plan.target != GT::null_vertex();
    source_code = ends_exist ? singularity_code(plan.source) : 0;
    target_code = ends_exist ? singularity_code(plan.target) : 0;
    visitor.on_qzip_started(plan);
    log.mark();
    Execution_failure failure = Execution_failure::NONE;
    path = &plan.path;
    if(!plan.created_vertices.empty()) { named_path = plan.path; path = &named_path; }
    if(!run_prelude(plan, failure) || !run_chain(plan, failure)) {}
    else if(!clean_up()) failure = Execution_failure::CLEANUP_IMPOSSIBLE;
    else if(!valences_preserved()) failure = Execution_failure::SINGULARITY_CREATED;
    if(failure != Execution_failure::NONE) log.rollback_to_mark();
    visitor.on_qzip_finished(plan, failure == Execution_failure::NONE);
    return failure;
  }

  // after a failed apply(): the position in the path where the execution failed
  std::size_t failed_position() const { return failed_step; }

  // after a done run: whether the surgery cancelled singularities (interior valences or border defects)
  bool cancelled_singularities() const { return cancelled; }

  // after a done run: the number of faces that the live vertices judged as border (or feature) vertices
  // should have, frozen from the geometry before the surgery (see Surgery_plan::expected_faces)
  std::vector<std::pair<vertex_descriptor, int> > expected_faces_of_live_vertices() const
  {
    std::vector<std::pair<vertex_descriptor, int> > out;
    for(vertex_descriptor v : live_vertices_in_order())
      if(const Vertex_state& s = known(v); s.has_ideal) out.emplace_back(v, s.ideal);
    return out;
  }

private:
  VertexPointMap log_vpm() const { return log.vertex_point_map(); }

  void reset()
  {
    vertex_states.clear();
    face_states.clear();
    vertex_order.clear();
    face_order.clear();
    sector_ideals.clear();
    sector_codes_before.clear();
    collapses = splits = cleanups = 0;
    cancelled = false;
  }

  // the state of `v` or `f`, made blank when there is none (the reference lasts until the next insertion)
  Vertex_state& state(vertex_descriptor v) { return *vertex_states.insert(v, Vertex_state()).first; }
  Face_state& face_state(face_descriptor f) { return *face_states.insert(f, Face_state()).first; }
  // the state of a vertex that has one
  const Vertex_state& known(vertex_descriptor v) const { return *vertex_states.find(v); }

  void set_ideal(vertex_descriptor v, int n)
  {
    Vertex_state& s = state(v);
    s.has_ideal = true;
    s.ideal = n;
  }

  void list(vertex_descriptor v)
  {
    Vertex_state& s = state(v);
    if(!s.listed) { s.listed = true; vertex_order.push_back(v); }
  }
  void list(face_descriptor f)
  {
    Face_state& s = face_state(f);
    if(!s.listed) { s.listed = true; face_order.push_back(f); }
  }

  void touch(vertex_descriptor v)
  {
    if(const Vertex_state* s = vertex_states.find(v); s != nullptr && (s->touched || s->created)) return;
    const Around a = around(v);
    const int code = singularity_code(v, a);
    Vertex_state& s = state(v);
    s.touched = true;
    s.before = Before{ a.border, code };
    s.alive = true;
    list(v);
    if(!a.border) sector_codes(v, sector_codes_before);
  }

  // A vertex on a feature, away from the border, is also judged sector by sector (its defect is the sum of
  // its sectors'; a surgery must not trade a quad of one sector for a quad of another): the codes
  // 100 + defect of its irregular sectors. A sector is named by the incoming halfedge of the constrained
  // edge that starts it counterclockwise (constrained edges keep their halfedges through every operation),
  // and its number of quads is frozen from the geometry at the first look, as the vertex's.
  void sector_codes(vertex_descriptor v, std::vector<int>& out)
  {
    if constexpr(std::is_same<ECM, Static_boolean_property_map<edge_descriptor, false> >::value) return;
    halfedge_descriptor start = GT::null_halfedge();
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(get(ecm, edge(h, pm))) { start = h; break; }
    if(start == GT::null_halfedge()) return;
    halfedge_descriptor first = start;
    int faces = 0;
    double theta = 0;
    for(halfedge_descriptor h : halfedges_around_target(start, pm)) // face(h) between edge(h) and edge(next(h))
    {
      theta += corner_angle(h, pm, log_vpm(), Geom_traits());
      ++faces;
      if(!get(ecm, edge(next(h, pm), pm))) continue;
      const int ideal = *sector_ideals.insert(first, internal::ideal_number_of_faces(theta)).first;
      if(faces != ideal) out.push_back(100 + faces - ideal);
      first = opposite(next(h, pm), pm);
      faces = 0;
      theta = 0;
    }
  }

  std::vector<vertex_descriptor> live_vertices_in_order() const
  {
    std::vector<vertex_descriptor> out;
    collect_live_vertices(out);
    return out;
  }
  // the same, into a buffer
  void collect_live_vertices(std::vector<vertex_descriptor>& out) const
  {
    out.clear();
    for(vertex_descriptor v : vertex_order)
      if(known(v).alive) out.push_back(v);
  }

  bool protected_around(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(!is_border(h, pm) && get(fcm, face(h, pm))) return true;
    return false;
  }

  bool on_feature(vertex_descriptor v) const { return is_on_constrained_edge(v, pm, ecm); }

  // Constrained edges stay whole, and feature curves keep their number of edges: a collapse may not remove
  // one (b-c, c-d) nor merge two vertices that are each on a feature or on the border (the constrained
  // edges of the removed vertex move to the kept one, which takes its place on the feature); a split moves
  // all the constrained edges of the split vertex to the new one, or none, and may not split a vertex that
  // is on a feature and on the border. A feature vertex that is kept, or that takes the place of another,
  // stays where that one was (as on the border, see Operation_log): the feature curves keep their shape.

  // collapses face(h), keeping target(h); checks everything first.
  bool collapse(halfedge_descriptor h)
  {
    if(is_border(h, pm) || !can_collapse_quad(h, pm)) return false;
    const vertex_descriptor a = target(h, pm), b = target(next(h, pm), pm);
    const halfedge_descriptor bc = next(next(h, pm), pm);
    const vertex_descriptor c = target(bc, pm), d = source(h, pm);
    if(protected_around(a) || protected_around(c)) return false;
    const bool a_on_feature = on_feature(a), c_on_feature = on_feature(c);
    if(get(ecm, edge(bc, pm)) || get(ecm, edge(next(bc, pm), pm)) ||
       ((a_on_feature || is_border_vertex(a, pm)) && (c_on_feature || is_border_vertex(c, pm))))
      return false;
    touch(a); touch(b); touch(c); touch(d);
    visitor.on_collapse(h, pm);
    face_state(face(h, pm)).scar = false;
    // a border c merged into an interior a (can_collapse_quad() refuses two border vertices): the merged
    // vertex takes the place of c on the border, with the number of quads c should have; likewise on a feature
    if(is_border_vertex(c, pm) && !is_border_vertex(a, pm))
    {
      set_ideal(a, ideal_number_of_faces(c));
      state(a).took_border = true;
    }
    if(c_on_feature) set_ideal(a, ideal_number_of_faces(c));
    const Point kept_at = get(log_vpm(), a), removed_at = get(log_vpm(), c);
    Vertex_state& removed = state(c);
    removed.alive = false;
    removed.created = false;
    last_delimiters = log.collapse(h);
    if(c_on_feature) put(log_vpm(), a, removed_at);
    else if(a_on_feature) put(log_vpm(), a, kept_at);
    ++collapses;
    return true;
  }

  // the number of constrained edges of target(h1) that its split between h1 and h2 moves to the new vertex
  // (those strictly counterclockwise between v->b and v->d), and the number of all its constrained edges
  std::pair<int, int> constrained_edges_moved(halfedge_descriptor h1, halfedge_descriptor h2) const
  {
    int constrained = 0, moving = 0;
    for(halfedge_descriptor h : halfedges_around_target(h1, pm)) if(get(ecm, edge(h, pm))) ++constrained;
    for(halfedge_descriptor o = ccw(opposite(h1, pm), pm); o != opposite(h2, pm); o = ccw(o, pm))
      if(get(ecm, edge(o, pm))) ++moving;
    return std::make_pair(moving, constrained);
  }

  bool keeps_constraints_whole(halfedge_descriptor h1, halfedge_descriptor h2) const
  {
    const std::pair<int, int> m = constrained_edges_moved(h1, h2);
    return m.first == 0 || m.first == m.second;
  }

  // splits target(h1) between h1 and h2 (see split_vertex_into_quad()); checks everything first.
  bool split(halfedge_descriptor h1, halfedge_descriptor h2)
  {
    if(!can_split_vertex_into_quad(h1, h2, pm)) return false;
    const vertex_descriptor v = target(h1, pm);
    if(protected_around(v)) return false;
    const std::pair<int, int> constrained_moved = constrained_edges_moved(h1, h2);
    const int moving = constrained_moved.first, constrained = constrained_moved.second;
    if((moving != 0 && moving != constrained) || (constrained != 0 && is_border_vertex(v, pm))) return false;
    touch(v); touch(source(h1, pm)); touch(source(h2, pm));
    visitor.on_split(h1, h2, pm);
    const Point split_at = get(log_vpm(), v);
    last_quad = log.split(h1, h2);
    const vertex_descriptor c = target(next(next(last_quad, pm), pm), pm);
    {
      Vertex_state& s = state(c);
      s.alive = true;
      s.created = true;
    }
    // a copy on the border (or on a feature) takes the place of v there, with its number of quads
    if(is_border_vertex(c, pm) || moving != 0) set_ideal(c, ideal_number_of_faces(v));
    if(constrained != 0) put(log_vpm(), moving != 0 ? c : v, split_at);
    list(c);
    face_state(face(last_quad, pm)).scar = true;
    list(face(last_quad, pm));
    ++splits;
    return true;
  }

  // names the vertices of the path created by the split at `split` (a position in the path, or
  // path size + m for prelude[m]); `kept` is the split vertex, `made` the new one
  void name_created(const Surgery_plan<PolygonMesh>& plan, std::size_t split, vertex_descriptor kept, vertex_descriptor made)
  {
    for(const auto& cv : plan.created_vertices)
      if(cv.split == split) named_path[cv.index] = cv.new_vertex ? made : kept;
  }

  // the atomic operations of a reverse plan performed before its chain (Surgery_plan::prelude)
  bool run_prelude(const Surgery_plan<PolygonMesh>& plan, Execution_failure& failure)
  {
    for(std::size_t m = 0; m < plan.prelude.size(); ++m)
    {
      failed_step = 0;
      const auto& op = plan.prelude[m];
      const auto bv = halfedge(op.b, op.v, pm);
      if(op.d == GT::null_vertex())
      {
        if(!bv.second || !collapse(bv.first)) { failure = Execution_failure::COLLAPSE_REFUSED; return false; }
        continue;
      }
      const auto dv = halfedge(op.d, op.v, pm);
      if(!bv.second || !dv.second || !split(bv.first, dv.first)) { failure = Execution_failure::SPLIT_REFUSED; return false; }
      if(!plan.created_vertices.empty())
        name_created(plan, plan.path.size() + m, op.v, target(next(next(last_quad, pm), pm), pm));
    }
    return true;
  }

  bool run_chain(const Surgery_plan<PolygonMesh>& plan, Execution_failure& failure)
  {
    const std::vector<vertex_descriptor>& P = *path;
    halfedge_descriptor guide = GT::null_halfedge();
    for(std::size_t j = 0; j + 1 < P.size(); ++j)
    {
      failed_step = j;
      if(P[j] == GT::null_vertex() || P[j + 1] == GT::null_vertex()) { failure = Execution_failure::PATH_EDGE_MISSING; return false; }
      const auto vw = halfedge(P[j], P[j + 1], pm);
      if(!vw.second) { failure = Execution_failure::PATH_EDGE_MISSING; return false; }
      const halfedge_descriptor o = vw.first;
      // a collapse may not remove a vertex the path has still to visit (e.g. on a cube, where the path
      // can run along two sides of the collapsed quad): its descriptor would dangle
      auto removes_path_vertex = [&](halfedge_descriptor h)
      {
        const vertex_descriptor c = target(next(next(h, pm), pm), pm);
        return std::find(P.begin() + std::ptrdiff_t(j + 1), P.end(), c) != P.end();
      };
      switch(plan.operations[j])
      {
        case Strip_operation::NO_OPERATION:
          guide = opposite(o, pm);
          break;
        case Strip_operation::RIGHT_COLLAPSE:
        case Strip_operation::LEFT_COLLAPSE:
        {
          const halfedge_descriptor h = collapsed_quad(o, plan.operations[j], pm);
          if(is_border(h, pm) || removes_path_vertex(h) || !collapse(h))
          { failure = Execution_failure::COLLAPSE_REFUSED; return false; }
          guide = opposite(plan.operations[j] == Strip_operation::RIGHT_COLLAPSE ? last_delimiters.first
                                                                                  : last_delimiters.second, pm);
          break;
        }
        case Strip_operation::LEFT_SPLIT:
        case Strip_operation::RIGHT_SPLIT:
          if(guide == GT::null_halfedge() || guide == o || source(guide, pm) != P[j])
          { failure = Execution_failure::NO_GUIDE_FOR_SPLIT; return false; }
        {
          halfedge_descriptor h1 = opposite(o, pm), h2 = opposite(guide, pm);
          // At a feature vertex (the feature target of a chain, or a vertex of a reverse Q-zip that moved a
          // feature defect) the split may have to be done the other way round. Its two copies are the same
          // whichever of them keeps the descriptor and the old edges v-w and v-y (w = P[j+1], y the end of the
          // guide), but only that one can keep a constrained edge among them. The direct split moves the fan
          // strictly counterclockwise from v->w to v->y (on the left of the path) to the new vertex c, the
          // complementary one the fan from v->y to v->w (on its right):
          //
          //               other sector
          //      x ========== v ========== w      direct: the fan from v->w to v->y, with v-x, moves to c:
          //                   |\                          x == c and v == w, the curve is cut
          //                   | \  the fan from    complementary: x == v == w, the new quad (v, y, c, w)
          //                   y    v->y to v->w             lies in the sector of y
          //
          // Both give the same mesh; the guide left is the same edge of it: w->(left copy) after LS,
          // w->(right copy) after RS.
          const bool complement = !keeps_constraints_whole(h1, h2) && keeps_constraints_whole(h2, h1);
          if(complement) std::swap(h1, h2);
          if(!split(h1, h2)) { failure = Execution_failure::SPLIT_REFUSED; return false; }
          // the new vertex took the fan on the left of the path (on its right after the complementary
          // split, where P[j] keeps the left one)
          const vertex_descriptor made = target(next(next(last_quad, pm), pm), pm);
          if(!plan.created_vertices.empty()) name_created(plan, j, complement ? made : P[j], complement ? P[j] : made);
          const bool left = plan.operations[j] == Strip_operation::LEFT_SPLIT;
          if(!complement) guide = left ? next(next(last_quad, pm), pm) : opposite(o, pm);
          else guide = left ? opposite(o, pm) : opposite(prev(last_quad, pm), pm);
          break;
        }
      }
    }
    return true;
  }

  // Sec. 2.7: a valence-2 vertex (two v3 merged) is removed, which leaves two v3; a valence-6 vertex
  // (two v5 merged) is split into two regular vertices, which leaves two v5.
  bool clean_up()
  {
    collect_live_vertices(candidates);
    for(vertex_descriptor v : candidates)
    {
      if(!known(v).alive || is_border_vertex(v, pm) || on_feature(v)) continue;
      const std::size_t d = valence(v, pm);
      if(d == 2 && !remove_valence_2(v)) return false;
      if(d == 6 && !split_valence_6(v)) return false;
    }
    return true;
  }

  bool remove_valence_2(vertex_descriptor v)
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(collapse(next(next(h, pm), pm))) { ++cleanups; return true; }
    return false;
  }

  bool split_valence_6(vertex_descriptor v)
  {
    std::vector<halfedge_descriptor> in;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm)) in.push_back(h);
    // halfedges_around_target turns clockwise: the fan strictly counterclockwise between in[i] and
    // in[i-3] has two edges, so both copies get valence 4 and the two delimiters one more edge: they must
    // be regular interior vertices off the features (a feature vertex would get a quad too many in one
    // of its sectors, a new singularity that the final check refuses).
    for(std::size_t i = 0; i < in.size(); ++i)
    {
      const halfedge_descriptor h1 = in[i], h2 = in[(i + in.size() - 3) % in.size()];
      const vertex_descriptor b = source(h1, pm), d = source(h2, pm);
      if(valence(b, pm) != 4 || valence(d, pm) != 4 || is_border_vertex(b, pm) || is_border_vertex(d, pm) ||
         on_feature(b) || on_feature(d))
        continue;
      if(split(h1, h2)) { ++cleanups; return true; }
    }
    return false;
  }

  Around around(vertex_descriptor v) const
  {
    Around a;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      ++a.valence;
      if(is_border(h, pm)) a.border = true;
      else ++a.faces;
      if(get(ecm, edge(h, pm)) || (!is_border(h, pm) && get(fcm, face(h, pm)))) a.on_feature = true;
    }
    return a;
  }

  // the number of faces a border or feature vertex should have, from the geometry before the surgery
  // (frozen at the first look: the chain moves vertices, and a defect is a matter of connectivity); a
  // border vertex created by a split sits on a straight piece of border and should have two
  int ideal_number_of_faces(vertex_descriptor v)
  {
    if(const Vertex_state* s = vertex_states.find(v); s != nullptr && s->has_ideal) return s->ideal;
    const int n = vertex_defect_info(v, pm, log_vpm(), ecm, Geom_traits()).expected_faces;
    set_ideal(v, n);
    return n;
  }

  // what a vertex is as a singularity: 0 when regular, its valence when it is an interior vertex away
  // from features and protected faces, 100 + its defect (paper's sector rule) otherwise
  int singularity_code(vertex_descriptor v, const Around& a)
  {
    if(a.border || a.on_feature)
    {
      const int defect = a.faces - ideal_number_of_faces(v);
      return defect == 0 ? 0 : 100 + defect;
    }
    return a.valence == 4 ? 0 : a.valence;
  }

  int singularity_code(vertex_descriptor v) { return singularity_code(v, around(v)); }

  // no singularity was created: the singularity codes of the touched vertices after the surgery form
  // a sub-multiset of those before (a Q-zip whose path passes other singularities may cancel some of
  // them in complementary pairs, never add one), and no interior vertex reached the border.
  bool valences_preserved()
  {
    std::vector<int>& was = codes_before;
    std::vector<int>& is = codes_after;
    was.clear();
    is.clear();
    for(vertex_descriptor v : vertex_order)
      if(const Vertex_state& s = known(v); s.touched && s.before.code != 0) was.push_back(s.before.code);
    for(vertex_descriptor v : vertex_order)
    {
      const Vertex_state s = known(v); // a copy: singularity_code() may add states
      if(!s.alive) continue;
      const Around a = around(v);
      if(a.border && s.touched && !s.created && !s.before.border && !s.took_border) return false;
      const int c = singularity_code(v, a);
      if(c != 0) is.push_back(c);
    }
    std::sort(was.begin(), was.end());
    std::sort(is.begin(), is.end());
    cancelled = is.size() < was.size();
    if(!std::includes(was.begin(), was.end(), is.begin(), is.end())) return false;
    // and the sectors of the feature vertices
    sector_codes_after.clear();
    for(vertex_descriptor v : vertex_order)
      if(known(v).alive && !is_border_vertex(v, pm)) sector_codes(v, sector_codes_after);
    std::sort(sector_codes_before.begin(), sector_codes_before.end());
    std::sort(sector_codes_after.begin(), sector_codes_after.end());
    return std::includes(sector_codes_before.begin(), sector_codes_before.end(),
                         sector_codes_after.begin(), sector_codes_after.end());
  }

  // the singular vertices of the scar that are new or changed, assigned to the source and the target
  // by type, or by distance to their old positions for pairs of the same type.
  void locate_moved_pair(const Point& source_at, const Point& target_at, Qzip_result<PolygonMesh>& r)
  {
    std::vector<vertex_descriptor> moved;
    for(vertex_descriptor v : live_vertices_in_order())
    {
      const int c = singularity_code(v);
      if(c == 0) continue;
      const Vertex_state& s = known(v);
      if(!s.touched || s.created || s.before.code != c) moved.push_back(v);
    }
    if(moved.size() != 2) return;
    bool swap = false;
    if(source_code != target_code) swap = singularity_code(moved[0]) != source_code;
    else
    {
      auto dist = [this](vertex_descriptor v, const Point& p) { return CGAL::squared_distance(get(log_vpm(), v), p); };
      swap = dist(moved[0], source_at) + dist(moved[1], target_at) > dist(moved[1], source_at) + dist(moved[0], target_at);
    }
    if(swap) std::swap(moved[0], moved[1]);
    if(singularity_code(moved[0]) != source_code || singularity_code(moved[1]) != target_code) return;
    r.moved_source = moved[0];
    r.moved_target = moved[1];
  }

  int source_code = 0, target_code = 0;
  bool cancelled = false;
  const std::vector<vertex_descriptor>* path = nullptr; // the plan's path, or named_path
  std::vector<vertex_descriptor> named_path;             // with the vertices the execution created
  Split_delimiters<PolygonMesh> last_delimiters;
  halfedge_descriptor last_quad;
  std::size_t failed_step = 0;
};

// the executor of the named parameters `NamedParameters`: their constrained edges and faces, and their visitor
template <typename PolygonMesh, typename VertexPointMap, typename NamedParameters>
using Chain_executor_of = Chain_executor<PolygonMesh, VertexPointMap,
  typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::edge_is_constrained_t, NamedParameters,
    Static_boolean_property_map<typename boost::graph_traits<PolygonMesh>::edge_descriptor, false> >::type,
  typename CGAL::internal_np::Lookup_named_param_def<Qzip::internal_np::face_is_constrained_t, NamedParameters,
    Static_boolean_property_map<typename boost::graph_traits<PolygonMesh>::face_descriptor, false> >::type,
  typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::visitor_t, NamedParameters,
    Default_qzip_visitor<PolygonMesh> >::reference>;

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_CHAIN_EXECUTOR_H
