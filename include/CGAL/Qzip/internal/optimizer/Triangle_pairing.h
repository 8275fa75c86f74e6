// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_OPTIMIZER_TRIANGLE_PAIRING_H
#define CGAL_QZIP_INTERNAL_OPTIMIZER_TRIANGLE_PAIRING_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/quad_quality.h>
#include <CGAL/Qzip/triangle_moves.h>
#include <CGAL/Qzip/internal/vertex_defect.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// What the triangle pairing pass did.
struct Triangle_pairing_statistics
{
  std::size_t collisions = 0;    // collisions kept (each removes two triangles)
  std::size_t attempts = 0;      // paths and collisions tried
  std::size_t undone = 0;        // tried and undone: the sum of the three below
  std::size_t blocked = 0;       // refused by move_triangle_along_path() or collide_triangles() (nothing done)
  std::size_t no_collision = 0;  // the path ended without a collision
  std::size_t rejected = 0;      // collided, but the score is not lower or a quad was inverted
};

// The pairing of triangles of the optimizer (paper, Sec. 3.2 and 4.1): each triangle is moved along the
// shortest edge paths from its tip to the corners of the closest other triangles (move_triangle_along_path(),
// the hybrid compass); when the path ends in a collision (collide_triangles(), or a VE into a triangle that
// shares the tip), the two triangles become quads. Adjacent triangles are collided directly. An attempt is
// kept only if it removes triangles, lowers the score `2 #triangles + sum |defect|` (with the tip of a
// canonical triangle counted as regular, as in Mesh_report) and adds no inverted quad; otherwise it is undone
// exactly through the Triangle_move_history. Paths run only through interior vertices whose one-ring has no
// border, constrained edge nor protected face, so no move reaches the border, a feature or a protected face.
//
// Attempts are identified by the positions of the tip and of the target corner, which an undo restores
// bit for bit, because undone operations may re-create elements under new descriptors; after an undo the
// triangles are collected again.
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap,
          typename GeomTraits>
class Triangle_pairing
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef std::array<double, 3> Key;

  struct Score
  {
    long triangles = 0;
    long defect = 0;
    std::size_t inverted = 0;
    long value() const { return 2 * triangles + defect; }
  };

  PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;
  GeomTraits gt;
  std::size_t max_distance;
  std::size_t targets_per_triangle;
  Triangle_move_history<PolygonMesh, VertexPointMap> history;
  std::set<std::pair<Key, Key> > tried;   // (tip, target corner) of the paths tried, (source, target) of the collided edges
  std::set<Key> exhausted;                // tips of the triangles with nothing left to try (until the next kept collision)
  Triangle_pairing_statistics stats;

public:
  Triangle_pairing(PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm,
                   const GeomTraits& gt, std::size_t max_distance = 12, std::size_t targets_per_triangle = 6)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm), gt(gt), max_distance(max_distance),
      targets_per_triangle(targets_per_triangle), history(pm, vpm)
  {}

  Triangle_pairing_statistics run()
  {
    Score current = score();
    // each pass ends at the first attempt (kept or undone: descriptors may have changed); the loop ends when
    // a whole pass finds nothing left to try
    while(current.triangles > 1 && attempt_one(current)) {}
    return stats;
  }

  static std::size_t number_of_triangles(const PolygonMesh& pm)
  {
    std::size_t n = 0;
    for(face_descriptor f : faces(pm))
      if(face_degree(halfedge(f, pm), pm) == 3) ++n;
    return n;
  }

private:
  Key key(vertex_descriptor v) const
  {
    const Point& p = get(vpm, v);
    return Key{{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
  }

  // interior, no incident constrained edge nor protected face
  bool is_free(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) return false;
      if(get(fcm, face(h, pm))) return false;
    }
    return true;
  }

  // a move may edit the faces around v and around its neighbours
  bool is_passable(vertex_descriptor v) const
  {
    if(!is_free(v)) return false;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(!is_free(source(h, pm))) return false;
    return true;
  }

  bool is_passable_triangle(halfedge_descriptor h) const
  {
    for(halfedge_descriptor x : halfedges_around_face(h, pm))
      if(!is_passable(target(x, pm))) return false;
    return true;
  }

  Score score() const
  {
    Score s;
    std::vector<vertex_descriptor> tips;
    const auto np = CGAL::parameters::vertex_point_map(vpm).geom_traits(gt);
    for(face_descriptor f : faces(pm))
    {
      const std::size_t d = face_degree(halfedge(f, pm), pm);
      if(d == 3)
      {
        ++s.triangles;
        const auto c = classify_triangle(f, pm);
        if(c.configuration == Triangle_configuration::CANONICAL) tips.push_back(triangle_tip(c.base, pm));
      }
      else if(d == 4 && quad_scaled_jacobian(f, pm, np) <= 0)
        ++s.inverted;
    }
    for(vertex_descriptor v : vertices(pm))
      s.defect += std::abs(vertex_defect_info(v, pm, vpm, ecm, gt).defect);
    // the tip of a canonical triangle: one unit of its defect is the triangle's
    std::sort(tips.begin(), tips.end());
    for(auto it = tips.begin(); it != tips.end(); )
    {
      const auto end = std::upper_bound(it, tips.end(), *it);
      const int d = vertex_defect_info(*it, pm, vpm, ecm, gt).defect;
      s.defect += std::abs(d - int(end - it)) - std::abs(d);
      it = end;
    }
    return s;
  }

  // whether the state reached (from `current`) removed triangles, lowered the score and inverted no quad;
  // if so it becomes `current`
  bool accept(Score& current)
  {
    const Score after = score();
    if(after.triangles < current.triangles && after.value() < current.value() && after.inverted <= current.inverted)
    {
      current = after;
      ++stats.collisions;
      exhausted.clear();
      return true;
    }
    return false;
  }

  // the triangle whose base goes from the corner at c[0] to the one at c[1] and whose tip is at c[2]
  halfedge_descriptor find_triangle(const std::array<Key, 3>& c) const
  {
    for(face_descriptor f : faces(pm))
    {
      if(face_degree(halfedge(f, pm), pm) != 3) continue;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
        if(key(source(h, pm)) == c[0] && key(target(h, pm)) == c[1] && key(triangle_tip(h, pm)) == c[2]) return h;
    }
    CGAL_assertion_msg(false, "an undo restores every position");
    return GT::null_halfedge();
  }

  // After a path that brought the tip of the triangle of base `base` to a corner of another triangle
  // without a collision: the collisions it can make from there (with a triangle across one of its sides,
  // or a VE into a triangle that shares its tip), tried one after the other, each undone unless accepted.
  bool finish_with_collision(halfedge_descriptor base, Score& current)
  {
    const std::array<Key, 3> corners = {{ key(source(base, pm)), key(target(base, pm)), key(triangle_tip(base, pm)) }};
    std::vector<std::pair<bool, Key> > actions; // (collide across a side, key of the other triangle's far corner) or (VE, key of w)
    for(halfedge_descriptor x : halfedges_around_face(base, pm))
    {
      const halfedge_descriptor o = opposite(x, pm);
      if(!is_border(o, pm) && face_degree(o, pm) == 3 && is_passable_triangle(o))
        actions.emplace_back(true, key(target(next(o, pm), pm)));
    }
    for(halfedge_descriptor y : halfedges_around_target(halfedge(triangle_tip(base, pm), pm), pm)) // y = w->t
      if(!is_border(y, pm) && face(y, pm) != face(base, pm) && face_degree(y, pm) == 3 && is_passable(source(y, pm)))
        actions.emplace_back(false, key(source(y, pm)));
    for(std::size_t i = 0; i < actions.size(); ++i)
    {
      if(i > 0) base = find_triangle(corners); // the undo of the previous action may have re-created it
      ++stats.attempts;
      bool collided = false;
      if(actions[i].first)
      {
        for(halfedge_descriptor x : halfedges_around_face(base, pm))
        {
          const halfedge_descriptor o = opposite(x, pm);
          if(is_border(o, pm) || face_degree(o, pm) != 3 || key(target(next(o, pm), pm)) != actions[i].second) continue;
          collided = (collide_triangles(x, history) != Collision_resolution::NONE);
          break;
        }
      }
      else
      {
        const vertex_descriptor t = triangle_tip(base, pm);
        for(halfedge_descriptor y : halfedges_around_target(halfedge(t, pm), pm))
        {
          if(key(source(y, pm)) != actions[i].second) continue;
          const Triangle_path_result<PolygonMesh> r = move_triangle_along_path(pm, base, { t, source(y, pm) }, history);
          if(r.status == Triangle_path_status::DONE) history.undo_last();
          collided = (r.status == Triangle_path_status::COLLIDED);
          break;
        }
      }
      if(!collided) { ++stats.undone; ++stats.blocked; continue; }
      if(accept(current)) return true;
      history.undo_last();
      ++stats.undone;
      ++stats.rejected;
    }
    return false;
  }

  // the corners of other triangles closest to the tip of the triangle of base h (breadth-first, through
  // passable vertices not incident to another triangle), with the paths to them
  std::vector<std::vector<vertex_descriptor> > paths_to_other_triangles(halfedge_descriptor h) const
  {
    const face_descriptor fx = face(h, pm);
    const vertex_descriptor t = triangle_tip(h, pm);
    std::vector<std::vector<vertex_descriptor> > paths;
    std::vector<vertex_descriptor> order = { t };
    std::vector<std::size_t> pred = { 0 }, depth = { 0 };
    std::set<vertex_descriptor> seen = { t };
    for(std::size_t i = 0; i < order.size() && paths.size() < targets_per_triangle; ++i)
    {
      if(depth[i] >= max_distance) continue;
      const vertex_descriptor v = order[i];
      for(halfedge_descriptor x : halfedges_around_target(halfedge(v, pm), pm))
      {
        const vertex_descriptor w = source(x, pm);
        if(seen.count(w) || !is_passable(w)) continue;
        seen.insert(w);
        bool other_triangle = false;
        for(halfedge_descriptor y : halfedges_around_target(halfedge(w, pm), pm))
          if(!is_border(y, pm) && face(y, pm) != fx && face_degree(y, pm) == 3) other_triangle = true;
        order.push_back(w);
        pred.push_back(i);
        depth.push_back(depth[i] + 1);
        if(!other_triangle) continue;
        std::vector<vertex_descriptor> p;
        for(std::size_t k = order.size() - 1; ; k = pred[k]) { p.push_back(order[k]); if(k == 0) break; }
        std::reverse(p.begin(), p.end());
        paths.push_back(p);
        depth.back() = max_distance; // a path does not go through another triangle
        if(paths.size() == targets_per_triangle) break;
      }
    }
    return paths;
  }

  // the triangles, each with its base (the canonical one, or the one classify_triangle() chose), in an
  // order that depends on positions only
  std::vector<halfedge_descriptor> movable_triangles() const
  {
    std::vector<std::pair<Key, halfedge_descriptor> > ts;
    for(face_descriptor f : faces(pm))
    {
      if(face_degree(halfedge(f, pm), pm) != 3) continue;
      const auto c = classify_triangle(f, pm);
      halfedge_descriptor h = c.base;
      if(c.configuration == Triangle_configuration::ON_BORDER) continue;
      if(c.configuration == Triangle_configuration::ADJACENT) h = halfedge(f, pm);
      if(!is_passable_triangle(h)) continue;
      ts.emplace_back(key(triangle_tip(h, pm)), h);
    }
    std::sort(ts.begin(), ts.end(), [](const std::pair<Key, halfedge_descriptor>& a,
                                       const std::pair<Key, halfedge_descriptor>& b) { return a.first < b.first; });
    std::vector<halfedge_descriptor> hs;
    for(const auto& kh : ts) hs.push_back(kh.second);
    return hs;
  }

  // one attempt not tried yet; false when there is none
  bool attempt_one(Score& current)
  {
    for(halfedge_descriptor h : movable_triangles())
    {
      const Key tip = key(triangle_tip(h, pm));
      if(exhausted.count(tip)) continue;
      // adjacent triangles collide directly
      for(halfedge_descriptor x : halfedges_around_face(h, pm))
      {
        const halfedge_descriptor o = opposite(x, pm);
        if(is_border(o, pm) || face_degree(o, pm) != 3 || !is_passable_triangle(o)) continue;
        if(!tried.insert(std::make_pair(key(target(next(x, pm), pm)), key(target(next(o, pm), pm)))).second) continue;
        ++stats.attempts;
        if(collide_triangles(x, history) == Collision_resolution::NONE) { ++stats.undone; ++stats.blocked; return true; }
        if(!accept(current)) { history.undo_last(); ++stats.undone; ++stats.rejected; }
        return true;
      }
      for(const std::vector<vertex_descriptor>& path : paths_to_other_triangles(h))
      {
        if(!tried.insert(std::make_pair(key(path.front()), key(path.back()))).second) continue;
        ++stats.attempts;
        const Triangle_path_result<PolygonMesh> r = move_triangle_along_path(pm, h, path, history);
        if(!r.is_done()) { ++stats.undone; ++stats.blocked; return true; } // rolled back already
        if(r.status == Triangle_path_status::COLLIDED)
        {
          if(!accept(current)) { history.undo_last(); ++stats.undone; ++stats.rejected; }
          return true;
        }
        if(finish_with_collision(r.base, current)) return true; // the path and the collision are kept
        history.undo_last();                                    // the path ended without a collision
        ++stats.undone;
        ++stats.no_collision;
        return true;
      }
      exhausted.insert(tip);
    }
    return false;
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_OPTIMIZER_TRIANGLE_PAIRING_H
