// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SMOOTHING_H
#define CGAL_QZIP_SMOOTHING_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/Named_function_parameters.h>
#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/quad_quality.h>
#include <CGAL/Qzip/internal/reference_surface.h>
#include <CGAL/Qzip/internal/vertex_defect.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>

#include <boost/container/small_vector.hpp>
#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// The valence-weighted Laplacian of the paper's Sec. 4.1 with projection onto a reference surface (the
// mesh as it was when the smoother was built, triangulated: see Reference_surface). Border vertices, vertices
// of protected faces and feature corners never move; the other feature vertices (on exactly two
// constrained edges that turn by at most `corner_angle`) slide along their feature curve: they move halfway towards
// the midpoint of their two feature neighbors, projected onto the feature polyline as it was when the
// smoother was built (surgeries never edit feature edges, so the curves keep their vertices). A move is
// kept if its incident quads stay above the quality floor, or else if the worst of them is no worse than
// before: so no quad gets inverted (scaled Jacobian <= 0) around a vertex whose quads were not inverted,
// but beside an inverted quad a move that improves it may invert another (manual, Limitations).
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap,
          typename FaceIsConstrainedMap, typename GeomTraits>
class Quad_smoother
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename GeomTraits::Point_3 Point;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type Hint_map;

  PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;
  Reference_surface<GeomTraits> surface;
  // per vertex, the triangle of the surface its last projection landed on (see Reference_surface)
  Hint_map hint;
  // feature vertices: their position when the smoother was built; for sliding ones, their two feature neighbors
  struct Feature_vertex { Point origin; bool slides; vertex_descriptor a, b; };
  std::unordered_map<vertex_descriptor, Feature_vertex, boost::hash<vertex_descriptor> > feature_vertices;
  // the region being smoothed (see gather_springs()): each free vertex, its feature curve if it slides along
  // one, and the end of its springs and of its quads in `springs` and `quads` (they start where those of the
  // previous one end)
  struct Sweep_vertex
  {
    vertex_descriptor v;
    const Feature_vertex* feature; // in feature_vertices, filled once by the constructor
    std::size_t springs_end, quads_end;
  };
  std::vector<Sweep_vertex> sweep;
  std::vector<std::pair<vertex_descriptor, double> > springs; // a neighbour and the stiffness of the edge to it
  std::vector<face_descriptor> quads;
  std::vector<Point> targets; // of a sweep

public:
  double step = 0.5; // fraction of the way towards the weighted centroid
  double quality_floor = 0; // a move is kept if the incident quads stay above min(floor, their quality before)
  double corner_angle = 45; // degrees: a feature curve turning more than this at a vertex has a corner there

  Quad_smoother(PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm,
                bool project)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm), hint(get(CGAL::dynamic_vertex_property_t<std::size_t>(), pm))
  {
    collect_feature_vertices();
    if(!project) return;
    for(vertex_descriptor v : vertices(pm)) put(hint, v, 0);
    std::vector<vertex_descriptor> fv;
    for(face_descriptor f : faces(pm))
    {
      fv.clear();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm)) fv.push_back(target(h, pm));
      for(std::size_t i = 1; i + 1 < fv.size(); ++i)
      {
        const std::size_t t = surface.add(get(vpm, fv[0]), get(vpm, fv[i]), get(vpm, fv[i + 1]));
        if(t != 0) for(vertex_descriptor v : { fv[0], fv[i], fv[i + 1] }) put(hint, v, t);
      }
    }
    surface.build();
  }

  // on the border, on a protected face, or a feature vertex that does not slide
  bool is_fixed(vertex_descriptor v) const
  {
    bool feature = false;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      if(is_border_edge(h, pm)) return true;
      if(get(fcm, face(h, pm))) return true; // h is not a border halfedge here
      if(get(ecm, edge(h, pm))) feature = true;
    }
    return feature && sliding_feature(v) == nullptr;
  }

  // the record of v if v slides along the feature curve it was on when the smoother was built: its
  // constrained edges are still exactly the two to its recorded neighbours (a Q-zip may since have given
  // a constrained edge to the other copy of a split vertex, or `Surface_mesh` may have given the
  // descriptor of a removed vertex to a new one); null otherwise
  const Feature_vertex* sliding_feature(vertex_descriptor v) const
  {
    const auto it = feature_vertices.find(v);
    if(it == feature_vertices.end() || !it->second.slides) return nullptr;
    int constrained = 0;
    bool to_a = false, to_b = false;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      if(!get(ecm, edge(h, pm))) continue;
      ++constrained;
      to_a = to_a || source(h, pm) == it->second.a;
      to_b = to_b || source(h, pm) == it->second.b;
    }
    return constrained == 2 && to_a && to_b ? &it->second : nullptr;
  }

  // where the feature vertex x was when the smoother was built (where it is, if it was not one then)
  Point feature_origin(vertex_descriptor x) const
  {
    const auto it = feature_vertices.find(x);
    return it == feature_vertices.end() ? get(vpm, x) : it->second.origin;
  }

  // records the vertices of constrained edges and which of them slide (not on the border, not on a
  // protected face, exactly two constrained edges, no corner)
  void collect_feature_vertices()
  {
    for(vertex_descriptor v : vertices(pm))
    {
      std::vector<vertex_descriptor> nb;
      bool fixed = false;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      {
        if(is_border_edge(h, pm) || get(fcm, face(h, pm))) fixed = true;
        else if(get(ecm, edge(h, pm))) nb.push_back(source(h, pm));
      }
      if(nb.empty()) continue;
      Feature_vertex fv{ get(vpm, v), false, GT::null_vertex(), GT::null_vertex() };
      if(!fixed && nb.size() == 2)
      {
        const auto u = get(vpm, v) - get(vpm, nb[0]);
        const auto w = get(vpm, nb[1]) - get(vpm, v);
        const double uu = CGAL::to_double(u * u), ww = CGAL::to_double(w * w), uw = CGAL::to_double(u * w);
        // the curve turns by at most corner_angle: cos(turn) = uw / (|u||w|)
        const double c = std::cos(corner_angle * CGAL_PI / 180.);
        if(uu > 0 && ww > 0 && uw > 0 && uw * uw >= c * c * uu * ww) { fv.slides = true; fv.a = nb[0]; fv.b = nb[1]; }
      }
      feature_vertices.emplace(v, fv);
    }
  }

  // the closest point to p on the feature polyline around the sliding vertex v, as it was when the smoother
  // was built: the edges v-a, v-b, and the next feature edges beyond a and b
  Point project_on_feature(vertex_descriptor v, const Point& p) const
  {
    const Feature_vertex& fv = *sliding_feature(v);
    std::vector<std::pair<Point, Point> > segments;
    segments.emplace_back(fv.origin, feature_origin(fv.a));
    segments.emplace_back(fv.origin, feature_origin(fv.b));
    for(vertex_descriptor x : { fv.a, fv.b })
    {
      const Feature_vertex* fx = sliding_feature(x);
      if(fx == nullptr) continue;
      const vertex_descriptor y = fx->a == v ? fx->b : fx->a;
      segments.emplace_back(fx->origin, feature_origin(y));
    }
    Point best = fv.origin;
    double best_d = (std::numeric_limits<double>::max)();
    for(const auto& sg : segments)
    {
      const auto d = sg.second - sg.first;
      const double dd = CGAL::to_double(d * d);
      double t = dd > 0 ? CGAL::to_double((p - sg.first) * d) / dd : 0;
      t = (std::max)(0., (std::min)(1., t));
      const Point q = sg.first + typename GeomTraits::FT(t) * d;
      const double e = CGAL::to_double(CGAL::squared_distance(p, q));
      if(e < best_d) { best_d = e; best = q; }
    }
    return best;
  }

  // the valence used for the spring stiffness: the valence of an interior vertex, 4 + defect on the border/features,
  // on the mesh as it is (a Q-zip may move a border or feature defect, and a vertex it creates may get the
  // descriptor of a removed one: nothing is cached by descriptor)
  int effective_valence(vertex_descriptor v) const
  {
    bool cut = false;
    int n = 0;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      ++n;
      if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) cut = true;
    }
    if(!cut) return n;
    return 4 + vertex_defect_info(v, pm, vpm, ecm, GeomTraits()).defect;
  }

  // the number of inverted quads around v and the smallest scaled Jacobian among its quads (1 if none)
  std::pair<std::size_t, double> incident_quality(vertex_descriptor v) const
  {
    boost::container::small_vector<face_descriptor, 8> ring;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(!is_border(h, pm) && is_quad(h, pm)) ring.push_back(face(h, pm));
    return quads_quality(ring.begin(), ring.end(), pm, vpm);
  }

  // whether the quads around v have no more inverted quads than `bound.first` and all a scaled Jacobian above
  // `bound.second`; if so, `quality` is incident_quality(v). Stops at the first quad that fails.
  bool incident_quality_beats(vertex_descriptor v, const std::pair<std::size_t, double>& bound,
                              std::pair<std::size_t, double>& quality) const
  {
    std::size_t inverted = 0;
    double worst = 1;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      if(is_border(h, pm) || !is_quad(h, pm)) continue;
      const double j = quad_scaled_jacobian(face(h, pm), pm, CGAL::parameters::vertex_point_map(vpm));
      if(j <= bound.second || (j <= 0 && ++inverted > bound.first)) return false;
      worst = (std::min)(worst, j);
    }
    if(!(worst > bound.second)) return false; // no quad: worst is 1
    quality = std::make_pair(inverted, worst);
    return true;
  }

  // the closest point to p on the reference surface, searched from the triangle of the last projection of v
  // (or of a neighbor, for a vertex created since). Always a point of the surface: a vertex off it (one a
  // Q-zip created or merged at a midpoint) goes back onto it at its next move, however small
  Point project(vertex_descriptor v, const Point& p)
  {
    if(surface.empty()) return p;
    std::size_t t = get(hint, v);
    if(t == 0) // a vertex created since: the hint of a neighbor
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
        if((t = get(hint, source(h, pm))) != 0) break;
    const Point q = surface.closest_point(p, t);
    put(hint, v, t);
    return q;
  }

  // puts the free vertices of `vs` that do not slide along a feature curve at their closest point on the
  // reference surface, whatever that does to their quads (the smoothing and the caller's quality guard
  // judge the result): a Q-zip places the vertices it creates or merges at midpoints, off a curved surface,
  // where a vertex whose smoothing moves are all refused would otherwise stay
  void snap_to_surface(const std::vector<vertex_descriptor>& vs)
  {
    if(surface.empty()) return;
    for(vertex_descriptor v : vs)
      if(!is_fixed(v) && sliding_feature(v) == nullptr) put(vpm, v, project(v, get(vpm, v)));
  }

  // moves each free vertex of `vs` that does not slide along a feature curve to its closest point on the
  // reference surface if its quads accept it as they accept a smoothing move (no new inverted quad, and above
  // the quality floor or no worse than before); returns the number of vertices moved. For vertices another
  // operation placed off the surface (the triangle pairing of the optimizer), outside any quality guard.
  std::size_t settle_on_surface(const std::vector<vertex_descriptor>& vs)
  {
    if(surface.empty()) return 0;
    std::size_t moved = 0;
    for(vertex_descriptor v : vs)
    {
      if(is_fixed(v) || sliding_feature(v) != nullptr) continue;
      const Point old = get(vpm, v);
      const Point on = project(v, old);
      if(on == old) continue;
      const std::pair<std::size_t, double> before = incident_quality(v);
      put(vpm, v, on);
      const std::pair<std::size_t, double> after = incident_quality(v);
      if(after.first <= before.first && ((after.second > 0 && after.second >= quality_floor) || after.second >= before.second))
        ++moved;
      else
        put(vpm, v, old);
    }
    return moved;
  }

  // the free vertices of `region` with their springs (the stiffness of each incident edge, by the
  // valences at its ends) and their incident quads: smoothing moves vertices but changes no valence and
  // no face
  void gather_springs(const std::vector<vertex_descriptor>& region)
  {
    sweep.clear();
    springs.clear();
    quads.clear();
    for(vertex_descriptor v : region)
    {
      if(is_fixed(v)) continue;
      const Feature_vertex* feature = sliding_feature(v);
      if(feature == nullptr)
      {
        const int dv = effective_valence(v);
        for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
        {
          const vertex_descriptor u = source(h, pm);
          const int s = dv + effective_valence(u);
          springs.emplace_back(u, s == 8 ? 1. : (s < 8 ? 0.5 : 2.));
        }
      }
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
        if(!is_border(h, pm) && is_quad(h, pm)) quads.push_back(face(h, pm));
      sweep.push_back(Sweep_vertex{ v, feature, springs.size(), quads.size() });
    }
  }

  // the smallest scaled Jacobian among quads[first, last) (1 if none)
  double worst_quad(std::size_t first, std::size_t last) const
  {
    return quads_quality(quads.begin() + std::ptrdiff_t(first), quads.begin() + std::ptrdiff_t(last), pm, vpm).second;
  }

  // `iterations` Jacobi sweeps over the free vertices of `region` (in the given order); returns the
  // number of accepted moves. Sliding feature vertices are projected onto their feature curve, the others
  // onto the surface.
  std::size_t smooth(const std::vector<vertex_descriptor>& region, int iterations)
  {
    gather_springs(region);
    targets.resize(sweep.size());
    std::size_t accepted = 0;
    for(int it = 0; it < iterations; ++it)
    {
      for(std::size_t i = 0; i < sweep.size(); ++i)
      {
        const Sweep_vertex& sv = sweep[i];
        const Point& p = get(vpm, sv.v);
        if(sv.feature != nullptr)
        {
          const Point m = CGAL::midpoint(get(vpm, sv.feature->a), get(vpm, sv.feature->b));
          targets[i] = project_on_feature(sv.v, p + typename GeomTraits::FT(step) * (m - p));
          continue;
        }
        double x = 0, y = 0, z = 0, w = 0;
        for(std::size_t k = (i == 0 ? 0 : sweep[i - 1].springs_end); k < sv.springs_end; ++k)
        {
          const double s = springs[k].second;
          const Point& q = get(vpm, springs[k].first);
          x += s * CGAL::to_double(q.x()); y += s * CGAL::to_double(q.y()); z += s * CGAL::to_double(q.z());
          w += s;
        }
        if(w == 0) { targets[i] = p; continue; }
        targets[i] = Point(p.x() + step * (x / w - p.x()), p.y() + step * (y / w - p.y()), p.z() + step * (z / w - p.z()));
      }
      for(std::size_t i = 0; i < sweep.size(); ++i)
      {
        const Sweep_vertex& sv = sweep[i];
        const Point old = get(vpm, sv.v);
        const Point np = sv.feature == nullptr ? project(sv.v, targets[i]) : targets[i];
        if(np == old) continue;
        // kept if the incident quads stay above the floor, or else are not worse than before
        const std::size_t first_quad = i == 0 ? 0 : sweep[i - 1].quads_end;
        put(vpm, sv.v, np);
        const double after = worst_quad(first_quad, sv.quads_end);
        if(after > 0 && after >= quality_floor) { ++accepted; continue; }
        put(vpm, sv.v, old);
        if(after >= worst_quad(first_quad, sv.quads_end)) { put(vpm, sv.v, np); ++accepted; }
      }
    }
    return accepted;
  }

  // Untangling: at most `sweeps` Gauss-Seidel sweeps (until one moves nothing) over the free vertices of
  // `region` that are not on a feature curve and have an incident quad below `floor` (scaled Jacobian). Each
  // moves, if that raises the smallest scaled Jacobian of its quads without inverting one more of them, to
  // the best of a few positions projected onto the surface: towards the point that would make one of its
  // quads a parallelogram, towards the mean of these points, and steps in eight directions of its tangent
  // plane. The smallest scaled Jacobian of the quads around `region` never decreases. Returns the number of
  // moves. A vertex that stayed is tried again only once a vertex of one of its faces moved (its trials
  // depend on nothing else, so they would give the same result).
  std::size_t untangle(const std::vector<vertex_descriptor>& region, int sweeps, double floor)
  {
    typedef typename GeomTraits::Vector_3 Vector;
    typedef typename GeomTraits::FT FT;
    std::size_t moved = 0;
    std::vector<Point> goals, trials;
    std::unordered_set<vertex_descriptor, boost::hash<vertex_descriptor> > stuck; // tried, stayed, nothing moved around since
    for(int sweep = 0; sweep < sweeps; ++sweep)
    {
      std::size_t moved_in_sweep = 0;
      for(vertex_descriptor v : region)
      {
        if(is_fixed(v) || sliding_feature(v) != nullptr || stuck.count(v) != 0) continue;
        const std::pair<std::size_t, double> before = incident_quality(v);
        if(before.second >= floor) continue;
        const Point old = get(vpm, v);
        // the parallelogram points (v = a + b - c in the quad (a, v, b, c)), their mean, the quads' normal
        // and the mean edge length
        goals.clear();
        Vector mean = NULL_VECTOR, normal = NULL_VECTOR;
        double length = 0;
        int edges = 0;
        for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
        {
          length += std::sqrt(CGAL::to_double(CGAL::squared_distance(old, get(vpm, source(h, pm)))));
          ++edges;
          if(is_border(h, pm) || !is_quad(h, pm)) continue;
          const Point& a = get(vpm, source(h, pm));
          const Point& b = get(vpm, target(next(h, pm), pm));
          const Point& c = get(vpm, source(prev(h, pm), pm));
          goals.push_back(a + (b - c));
          mean = mean + (goals.back() - old);
          normal = normal + CGAL::cross_product(b - a, c - old);
        }
        if(goals.empty()) continue;
        goals.push_back(old + mean / FT(goals.size()));
        length /= edges;
        trials.clear();
        for(const Point& g : goals)
          for(double t : { 1., 0.5, 0.25 }) trials.push_back(old + FT(t) * (g - old));
        // steps of 0.3 and 0.1 mean edge lengths in eight directions of the tangent plane
        const double nn = CGAL::to_double(normal * normal);
        if(nn > 0)
        {
          Vector t1 = CGAL::cross_product(normal, Vector(1, 0, 0));
          if(CGAL::to_double(t1 * t1) < 1e-6 * nn) t1 = CGAL::cross_product(normal, Vector(0, 1, 0));
          Vector t2 = CGAL::cross_product(normal, t1);
          t1 = t1 / FT(std::sqrt(CGAL::to_double(t1 * t1)));
          t2 = t2 / FT(std::sqrt(CGAL::to_double(t2 * t2)));
          for(double step : { 0.3, 0.1 })
            for(int k = 0; k < 8; ++k)
              trials.push_back(old + FT(step * length * std::cos(k * CGAL_PI / 4)) * t1
                                   + FT(step * length * std::sin(k * CGAL_PI / 4)) * t2);
        }
        Point best = old;
        std::pair<std::size_t, double> best_quality = before;
        // every trial is projected from the triangle of `old` (the trials lie around it), and v keeps the
        // triangle of the position it takes
        const std::size_t old_hint = get(hint, v);
        std::size_t best_hint = old_hint;
        for(const Point& trial : trials)
        {
          put(hint, v, old_hint);
          const Point candidate = project(v, trial);
          put(vpm, v, candidate);
          std::pair<std::size_t, double> q;
          if(incident_quality_beats(v, best_quality, q))
          {
            best = candidate;
            best_quality = q;
            best_hint = get(hint, v);
          }
        }
        put(vpm, v, best);
        put(hint, v, best_hint);
        if(best == old) { stuck.insert(v); continue; }
        ++moved;
        ++moved_in_sweep;
        for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
          if(!is_border(h, pm))
            for(halfedge_descriptor g : halfedges_around_face(h, pm)) stuck.erase(target(g, pm));
      }
      if(moved_in_sweep == 0) break;
    }
    return moved;
  }
};

} // namespace internal

/*!
\ingroup PkgQzipOptimizer

smooths the vertices of `vertex_range` with the valence-weighted Laplacian of the paper's Sec. 4.1:
each edge is a spring whose stiffness is 1, 0.5 or 2 when the valences of its two vertices sum to 8,
less than 8 or more than 8 (border and feature vertices count as `4 + defect`), and each vertex moves
halfway towards the equilibrium of its springs, then back onto the surface as it was before the call
(closest point in a `CGAL::AABB_tree` of its triangulated faces). Vertices of constrained (feature) edges slide along their feature curve: a vertex on exactly two
constrained edges, where the curve turns by at most 45 degrees, moves halfway towards the midpoint of its
two feature neighbors and is put back onto the feature polyline as it was before the call, so feature
curves keep their shape and their edges; feature corners (one, three or more constrained edges, or a
sharper turn), border vertices and vertices of protected faces do not move (protected regions and the
border are kept bit for bit). A move is kept if the incident quads stay valid (scaled Jacobian `> 0`, see
`quad_scaled_jacobian()`) and at least `quality_floor`, or else if the smallest of their scaled Jacobians does not
decrease: no quad gets inverted (nor taken below the floor) around a vertex whose quads were all valid (and at least
the floor), but beside an inverted quad a move that improves it may invert another one.

\tparam PolygonMesh a model of `FaceListGraph`
\tparam VertexRange a range of vertex descriptors of `pm`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
\param pm the polygon mesh
\param vertex_range the vertices to smooth (in this order within a sweep)
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `pm`}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_constrained_map}
    \cgalParamDescription{feature edges; their vertices slide along the feature curves, corners are fixed}
    \cgalParamDefault{no edge is constrained}
  \cgalParamNEnd
  \cgalParamNBegin{face_is_constrained_map}
    \cgalParamDescription{protected faces (Qzip's parameter); their vertices are fixed}
    \cgalParamDefault{no face is protected}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the number of sweeps}
    \cgalParamDefault{5}
  \cgalParamNEnd
  \cgalParamNBegin{do_project}
    \cgalParamDescription{whether moved vertices are projected back onto the surface}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{quality_floor}
    \cgalParamDescription{(Qzip) the scaled Jacobian below which a move may not take a quad, unless the worst quad
                          around the vertex was already lower and does not get worse (as in `optimize_singularities()`)}
    \cgalParamType{`double`, in `[0, 1)`}
    \cgalParamDefault{0: moves are only kept valid}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamDefault{a \cgal Kernel deduced from the point type}
  \cgalParamNEnd
\cgalNamedParamsEnd
\returns the number of accepted vertex moves
\pre `quality_floor`, if given, is in `[0, 1)`
*/
template <typename PolygonMesh, typename VertexRange,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t smooth_quad_mesh(PolygonMesh& pm, const VertexRange& vertex_range,
                             const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetGeomTraits<PolygonMesh, NamedParameters>::type Geom_traits;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, pm));
  auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                              Static_boolean_property_map<edge_descriptor, false>());
  auto fcm = choose_parameter(get_parameter(np, Qzip::internal_np::face_is_constrained),
                              Static_boolean_property_map<face_descriptor, false>());
  const int iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 5);
  const bool project = choose_parameter(get_parameter(np, CGAL::internal_np::do_project), true);
  const double quality_floor = choose_parameter(get_parameter(np, Qzip::internal_np::quality_floor), 0.);
  CGAL_precondition(quality_floor >= 0 && quality_floor < 1);
  internal::Quad_smoother<PolygonMesh, decltype(vpm), decltype(ecm), decltype(fcm), Geom_traits>
    smoother(pm, vpm, ecm, fcm, project);
  smoother.quality_floor = quality_floor;
  std::vector<typename GT::vertex_descriptor> region(std::begin(vertex_range), std::end(vertex_range));
  return smoother.smooth(region, iterations);
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SMOOTHING_H
