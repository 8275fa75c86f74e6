// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_VERTEX_DEFECT_H
#define CGAL_QZIP_INTERNAL_VERTEX_DEFECT_H

#include <CGAL/license/Qzip.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Qzip {
namespace internal {

// What one walk around a vertex tells: its valence, whether it lies on the border, and its defect.
struct Vertex_defect_info
{
  std::size_t valence = 0;
  bool on_border = false;
  int defect = 0;
  int faces = 0;          // faces around the vertex (the valence for an interior vertex away from features)
  int expected_faces = 4; // what a regular vertex has there: 4 inside, the sum of the sectors' ideals on a cut
  bool cut = false;          // whether border or constrained edges cut the fan into sectors
  int irregular_sectors = 0; // on a cut: the sectors whose number of faces is not their ideal one
};

// Whether `v` is incident to a constrained edge (a feature vertex, or the end of a feature curve).
template <typename PolygonMesh, typename EdgeIsConstrainedMap>
bool is_on_constrained_edge(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm,
                            const EdgeIsConstrainedMap& ecm)
{
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    if(get(ecm, edge(h, pm))) return true;
  return false;
}

// The number of constrained edges incident to `v` (one at the end of a feature curve).
template <typename PolygonMesh, typename EdgeIsConstrainedMap>
std::size_t number_of_constrained_edges(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                                        const PolygonMesh& pm, const EdgeIsConstrainedMap& ecm)
{
  std::size_t n = 0;
  for(auto h : halfedges_around_target(halfedge(v, pm), pm))
    if(get(ecm, edge(h, pm))) ++n;
  return n;
}

// Angle (radians, in [0, pi]) at `target(h, pm)` between the two edges of `face(h, pm)` incident to it,
// i.e. between `h` (reversed) and `next(h, pm)`. A zero-length edge gives 0.
template <typename PolygonMesh, typename VertexPointMap, typename GeomTraits>
double corner_angle(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                    const PolygonMesh& pm, const VertexPointMap& vpm, const GeomTraits& gt)
{
  typedef typename GeomTraits::Vector_3 Vector_3;
  const auto& pv = get(vpm, target(h, pm));
  const Vector_3 a = gt.construct_vector_3_object()(pv, get(vpm, source(h, pm)));
  const Vector_3 b = gt.construct_vector_3_object()(pv, get(vpm, target(next(h, pm), pm)));
  const Vector_3 c = gt.construct_cross_product_vector_3_object()(a, b);
  const double sin_part = std::sqrt(CGAL::to_double(gt.compute_squared_length_3_object()(c)));
  const double cos_part = CGAL::to_double(gt.compute_scalar_product_3_object()(a, b));
  return std::atan2(sin_part, cos_part);
}

// Number of quads that ideally fill a sector of angle `theta`: the closest multiple of pi/2, at least one.
// This is the paper's ideal boundary "valence" max(2, floor(theta/(pi/2) + 1/2)) (Sec. 4.1) read as a count of
// quads, with the clamp lowered to 1: read as a valence it would be off by one on a straight border, where a
// regular vertex has valence 3 and 2 quads (and at a 270 degree corner, valence 4 and 3 quads).
inline int ideal_number_of_faces(double theta)
{
  const double half_pi = 1.5707963267948966;
  return (std::max)(1, static_cast<int>(std::floor(theta / half_pi + 0.5)));
}

// One walk around `v`: see `CGAL::Qzip::vertex_defect()` for the definition of the defect.
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename GeomTraits>
Vertex_defect_info
vertex_defect_info(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v,
                   const PolygonMesh& pm, const VertexPointMap& vpm,
                   const EdgeIsConstrainedMap& ecm, const GeomTraits& gt)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  Vertex_defect_info info;
  const halfedge_descriptor hv = halfedge(v, pm);
  if(hv == GT::null_halfedge())
    return info; // isolated vertex

  auto is_cut = [&](halfedge_descriptor h) -> bool
  {
    return is_border_edge(h, pm) || get(ecm, edge(h, pm));
  };

  // the incoming halfedges h_0, h_1 = opposite(next(h_0)), ...: face(h_i) lies between edge(h_i)
  // and edge(h_{i+1}) = edge(next(h_i)).
  halfedge_descriptor start = GT::null_halfedge();
  for(halfedge_descriptor h : halfedges_around_target(hv, pm))
  {
    ++info.valence;
    if(is_border(h, pm)) // a border cycle through v enters it with a border halfedge
      info.on_border = true;
    if(start == GT::null_halfedge() && is_cut(h))
      start = h;
  }

  if(start == GT::null_halfedge())
  {
    info.faces = static_cast<int>(info.valence);
    info.defect = info.faces - info.expected_faces;
    return info;
  }

  // Walk the fan from a cut edge; border and constrained edges cut it into sectors.
  info.cut = true;
  double theta = 0;
  int q = 0;
  info.expected_faces = 0;
  for(halfedge_descriptor h : halfedges_around_target(start, pm))
  {
    if(!is_border(h, pm))
    {
      theta += corner_angle(h, pm, vpm, gt);
      ++q;
    }
    if(is_cut(next(h, pm)) && q > 0) // the sector ends at edge(next(h)); the walk ends at edge(start)
    {
      const int ideal = ideal_number_of_faces(theta);
      info.faces += q;
      info.expected_faces += ideal;
      if(q != ideal) ++info.irregular_sectors;
      theta = 0;
      q = 0;
    }
  }
  info.defect = info.faces - info.expected_faces;
  return info;
}

// The sector of a vertex that contains a face: the faces between the two cut edges (border or constrained)
// that bound it around the vertex, and the number of quads a regular vertex has there.
struct Sector_info
{
  int faces = 0;
  int expected_faces = 0;
  bool bounded = false; // false when no cut edge bounds the fan (the whole fan, `faces` and `expected_faces` are 0)
};

// The sector of `target(h, pm)` that contains `face(h, pm)` (`h` is not a border halfedge), walked as in
// vertex_defect_info(): `face(h_i)` lies between `edge(h_i)` and `edge(next(h_i))`, the next incoming halfedge
// is `opposite(next(h_i))` and the previous one `prev(opposite(h_i))`. When `in_sector` is not null, it
// receives the faces of the sector.
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename GeomTraits,
          typename FaceOutput>
Sector_info sector_info(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                        const PolygonMesh& pm, const VertexPointMap& vpm,
                        const EdgeIsConstrainedMap& ecm, const GeomTraits& gt, FaceOutput in_sector)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  auto is_cut = [&](halfedge_descriptor x) -> bool { return is_border_edge(x, pm) || get(ecm, edge(x, pm)); };
  Sector_info info;
  halfedge_descriptor first = h;
  while(!is_cut(first))
  {
    first = prev(opposite(first, pm), pm);
    if(first == h) return info;
  }
  info.bounded = true;
  double theta = 0;
  for(halfedge_descriptor x = first;; x = opposite(next(x, pm), pm))
  {
    theta += corner_angle(x, pm, vpm, gt);
    ++info.faces;
    in_sector(face(x, pm));
    if(is_cut(next(x, pm))) break;
  }
  info.expected_faces = ideal_number_of_faces(theta);
  return info;
}

// Whether `target(h, pm)` becomes regular when it loses `face(h, pm)` (`h` is not a border halfedge): it has one
// face too many, and on a feature away from the border (where the executor also checks each sector) it has it
// in the sector of that face.
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename GeomTraits>
bool loses_a_face_to_regular(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                             const PolygonMesh& pm, const VertexPointMap& vpm,
                             const EdgeIsConstrainedMap& ecm, const GeomTraits& gt)
{
  const Vertex_defect_info info = vertex_defect_info(target(h, pm), pm, vpm, ecm, gt);
  if(info.defect != 1) return false;
  if(info.on_border || !info.cut) return true;
  const Sector_info sector = sector_info(h, pm, vpm, ecm, gt, [](auto) {});
  return sector.faces - sector.expected_faces == 1;
}

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_VERTEX_DEFECT_H
