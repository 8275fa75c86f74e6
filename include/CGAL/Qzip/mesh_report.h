// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_MESH_REPORT_H
#define CGAL_QZIP_MESH_REPORT_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/quad_quality.h>
#include <CGAL/Qzip/singularities.h>
#include <CGAL/Qzip/triangle_moves.h>
#include <CGAL/Qzip/internal/vertex_defect.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <map>
#include <ostream>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipAnalysis

statistics of a polygon mesh, filled by `compute_mesh_report()`: element counts, topology, valences,
triangles, singularities (see `vertex_defect()`) and the quality of its quads (see `quad_scaled_jacobian()`).

In a hybrid mesh, a canonical triangle (see `classify_triangle()`: isolated, interior, tip of valence 5 and
base corners of valence 4) is counted as a triangle, not as a singularity: the `+1` its tip has in
`vertex_defect()` is the triangle's own defect, so the singularity fields below take one unit off the
defect of the tip of each canonical triangle. On a mesh without canonical triangles (e.g. any pure-quad
mesh) every field is given by `vertex_defect()` alone.
*/
struct Mesh_report
{
  /// \name Elements
  /// @{
  std::size_t number_of_vertices = 0;
  std::size_t number_of_edges = 0;
  std::size_t number_of_faces = 0;
  std::map<std::size_t, std::size_t> faces_by_degree; ///< face degree -> number of faces
  /// @}

  /// \name Topology
  /// @{
  long euler_characteristic = 0;           ///< `V - E + F`
  std::size_t number_of_border_edges = 0;
  std::size_t number_of_boundary_loops = 0; ///< number of cycles of border halfedges
  /// number of connected components made of faces (two faces are connected when they share an edge
  /// or a vertex); isolated vertices are not components
  std::size_t number_of_connected_components = 0;
  std::size_t number_of_isolated_vertices = 0;
  /// sum over the components of their genus, `(2 * components - boundary loops - (chi - isolated vertices)) / 2`
  long genus = 0;
  /// @}

  /// \name Valences
  /// @{
  std::map<std::size_t, std::size_t> interior_valence_histogram; ///< valence -> number of interior vertices
  std::map<std::size_t, std::size_t> boundary_valence_histogram; ///< valence -> number of border vertices
  /// @}

  /// \name Triangles (hybrid meshes)
  /// @{
  std::size_t number_of_triangles = 0;
  /// triangles classified `Triangle_configuration::CANONICAL` by `classify_triangle()`; their tips are not singularities
  std::size_t number_of_canonical_triangles = 0;
  /// @}

  /// \name Singularities (defects as given by `vertex_defect()`, less one at the tip of each canonical triangle)
  /// @{
  std::size_t number_of_interior_valence_3_like = 0; ///< interior vertices with a negative defect
  std::size_t number_of_interior_valence_5_like = 0; ///< interior vertices with a positive defect
  std::size_t number_of_boundary_negative_defects = 0; ///< border vertices with a negative defect
  std::size_t number_of_boundary_positive_defects = 0; ///< border vertices with a positive defect
  long interior_defect_sum = 0;                     ///< sum of the defects of the interior vertices
  long boundary_defect_sum = 0;                     ///< sum of the defects of the border vertices
  std::size_t total_absolute_defect = 0;            ///< sum of `|defect|` over all vertices
  /// the singularities counted by sector: each interior vertex away from features with a non-zero defect
  /// once, and each sector of a border or feature vertex (the faces between two consecutive border or
  /// constrained edges around it) whose number of faces is not its ideal one (see `vertex_defect()`) once.
  /// The fields above judge a vertex by its defect, the sum over its sectors: a feature vertex with one quad
  /// too many in one sector and one too few in another counts as regular there, and twice here. Without
  /// constrained edges it equals `number_of_singularities()` (a border vertex has one sector).
  std::size_t number_of_singularities_by_sector = 0;
  /// `true` for a closed pure-quad mesh, the only case where `singularity_lower_bound` is defined.
  bool has_singularity_lower_bound = false;
  /// `|4 chi|` when `has_singularity_lower_bound`, 0 otherwise. On a closed quad mesh `2E = 4F`, so the sum of
  /// `valence - 4` over all vertices is `2E - 4V = -4 chi`: `total_absolute_defect` (without constrained
  /// edges) is at least `|4 chi|`, and so is the number of singularities when every valence is 3, 4 or 5,
  /// since each of them carries one unit. (With triangles the sum becomes `-4 chi + #triangles`, no bound.)
  std::size_t singularity_lower_bound = 0;
  /// @}

  /// \name Quad quality (see `quad_scaled_jacobian()`)
  /// @{
  std::size_t number_of_quads = 0;
  double min_scaled_jacobian = 0;   ///< 0 when there is no quad
  double mean_scaled_jacobian = 0;  ///< 0 when there is no quad
  std::size_t number_of_inverted_quads = 0; ///< quads with scaled Jacobian `<= 0` (degenerate ones included)
  /// @}

  /// the number of singular vertices: interior v3-like and v5-like, border negative and positive defects.
  std::size_t number_of_singularities() const
  {
    return number_of_interior_valence_3_like + number_of_interior_valence_5_like +
           number_of_boundary_negative_defects + number_of_boundary_positive_defects;
  }
  /// `true` if the mesh has no border edge.
  bool is_closed() const { return number_of_border_edges == 0; }
  /// `true` if the mesh has faces and all of them are quads.
  bool is_pure_quad() const { return number_of_faces > 0 && number_of_quads == number_of_faces; }
};

/*!
\ingroup PkgQzipAnalysis

computes the statistics of `pm` in a few linear passes.

\tparam PolygonMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
\tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

\param pm the polygon mesh
\param np the named parameters of `vertex_defect()` (`vertex_point_map`, `edge_is_constrained_map`,
          `geom_traits`); the constrained edges only change the defects, not the valence histograms
          nor `singularity_lower_bound`.
*/
template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_report compute_mesh_report(const PolygonMesh& pm,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  Mesh_report r;
  std::vector<vertex_descriptor> canonical_tips;
  r.number_of_vertices = vertices(pm).size();
  r.number_of_edges = edges(pm).size();
  r.number_of_faces = faces(pm).size();
  r.euler_characteristic = static_cast<long>(r.number_of_vertices) - static_cast<long>(r.number_of_edges)
                         + static_cast<long>(r.number_of_faces);

  // faces and quad quality
  double sj_sum = 0;
  r.min_scaled_jacobian = (std::numeric_limits<double>::max)();
  for(auto f : faces(pm))
  {
    std::size_t d = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
    {
      CGAL_USE(h);
      ++d;
    }
    ++r.faces_by_degree[d];
    if(d == 3)
    {
      ++r.number_of_triangles;
      const Triangle_classification<PolygonMesh> c = classify_triangle(f, pm);
      if(c.configuration == Triangle_configuration::CANONICAL)
      {
        ++r.number_of_canonical_triangles;
        canonical_tips.push_back(triangle_tip(c.base, pm));
      }
    }
    if(d != 4)
      continue;
    const double sj = quad_scaled_jacobian(f, pm, np);
    ++r.number_of_quads;
    sj_sum += sj;
    r.min_scaled_jacobian = (std::min)(r.min_scaled_jacobian, sj);
    if(sj <= 0)
      ++r.number_of_inverted_quads;
  }
  if(r.number_of_quads > 0)
    r.mean_scaled_jacobian = sj_sum / static_cast<double>(r.number_of_quads);
  else
    r.min_scaled_jacobian = 0;

  // border edges and boundary loops
  {
    auto visited = get(CGAL::dynamic_halfedge_property_t<bool>(), pm);
    for(halfedge_descriptor h : halfedges(pm))
      put(visited, h, false);
    for(halfedge_descriptor h : halfedges(pm))
    {
      if(!is_border(h, pm))
        continue;
      ++r.number_of_border_edges;
      if(get(visited, h))
        continue;
      ++r.number_of_boundary_loops;
      for(halfedge_descriptor hb : halfedges_around_face(h, pm))
        put(visited, hb, true);
    }
  }

  // connected components: vertex graph search from each unvisited non-isolated vertex
  {
    auto visited = get(CGAL::dynamic_vertex_property_t<bool>(), pm);
    for(vertex_descriptor v : vertices(pm))
      put(visited, v, false);
    std::vector<vertex_descriptor> stack;
    for(vertex_descriptor v : vertices(pm))
    {
      if(halfedge(v, pm) == GT::null_halfedge())
      {
        ++r.number_of_isolated_vertices;
        continue;
      }
      if(get(visited, v))
        continue;
      ++r.number_of_connected_components;
      put(visited, v, true);
      stack.push_back(v);
      while(!stack.empty())
      {
        const vertex_descriptor w = stack.back();
        stack.pop_back();
        for(halfedge_descriptor h : halfedges_around_target(halfedge(w, pm), pm))
        {
          const vertex_descriptor u = source(h, pm);
          if(!get(visited, u))
          {
            put(visited, u, true);
            stack.push_back(u);
          }
        }
      }
    }
  }
  r.genus = (2 * static_cast<long>(r.number_of_connected_components) - static_cast<long>(r.number_of_boundary_loops)
             - (r.euler_characteristic - static_cast<long>(r.number_of_isolated_vertices))) / 2;

  // valences and defects; the tip of a canonical triangle gives one unit of its defect to the triangle
  auto tip_of = get(CGAL::dynamic_vertex_property_t<int>(), pm);
  for(vertex_descriptor v : vertices(pm))
    put(tip_of, v, 0);
  for(vertex_descriptor v : canonical_tips)
    put(tip_of, v, get(tip_of, v) + 1);
  internal::with_defect_parameters(pm, np, [&](const auto& vpm, const auto& ecm, const auto& gt)
  {
    for(vertex_descriptor v : vertices(pm))
    {
      internal::Vertex_defect_info info = internal::vertex_defect_info(v, pm, vpm, ecm, gt);
      info.defect -= get(tip_of, v);
      r.total_absolute_defect += static_cast<std::size_t>(std::abs(info.defect));
      r.number_of_singularities_by_sector += info.cut ? static_cast<std::size_t>(info.irregular_sectors)
                                                      : (info.defect != 0 ? 1 : 0);
      if(info.on_border)
      {
        ++r.boundary_valence_histogram[info.valence];
        r.boundary_defect_sum += info.defect;
        if(info.defect < 0) ++r.number_of_boundary_negative_defects;
        if(info.defect > 0) ++r.number_of_boundary_positive_defects;
      }
      else
      {
        ++r.interior_valence_histogram[info.valence];
        r.interior_defect_sum += info.defect;
        if(info.defect < 0) ++r.number_of_interior_valence_3_like;
        if(info.defect > 0) ++r.number_of_interior_valence_5_like;
      }
    }
    return 0;
  });

  r.has_singularity_lower_bound = r.is_closed() && r.is_pure_quad();
  if(r.has_singularity_lower_bound)
    r.singularity_lower_bound = static_cast<std::size_t>(4 * std::labs(r.euler_characteristic));
  return r;
}

namespace internal {

inline void write_json_histogram(std::ostream& os, const std::map<std::size_t, std::size_t>& h)
{
  os << '{';
  bool first = true;
  for(const auto& kv : h)
  {
    os << (first ? "" : ", ") << '"' << kv.first << "\": " << kv.second;
    first = false;
  }
  os << '}';
}

inline void write_text_histogram(std::ostream& os, const std::map<std::size_t, std::size_t>& h)
{
  if(h.empty())
    os << " -";
  for(const auto& kv : h)
    os << ' ' << kv.first << ':' << kv.second;
}

} // namespace internal

/*!
\ingroup PkgQzipAnalysis

writes `r` to `os` as one JSON object (histograms are objects whose keys are the degrees/valences).
*/
inline std::ostream& write_json(std::ostream& os, const Mesh_report& r)
{
  std::ostringstream s; // keep the caller's stream formatting untouched
  s << std::setprecision(17);
  s << "{\n"
    << "  \"number_of_vertices\": " << r.number_of_vertices << ",\n"
    << "  \"number_of_edges\": " << r.number_of_edges << ",\n"
    << "  \"number_of_faces\": " << r.number_of_faces << ",\n"
    << "  \"faces_by_degree\": ";
  internal::write_json_histogram(s, r.faces_by_degree);
  s << ",\n"
    << "  \"euler_characteristic\": " << r.euler_characteristic << ",\n"
    << "  \"number_of_border_edges\": " << r.number_of_border_edges << ",\n"
    << "  \"number_of_boundary_loops\": " << r.number_of_boundary_loops << ",\n"
    << "  \"number_of_connected_components\": " << r.number_of_connected_components << ",\n"
    << "  \"number_of_isolated_vertices\": " << r.number_of_isolated_vertices << ",\n"
    << "  \"genus\": " << r.genus << ",\n"
    << "  \"number_of_triangles\": " << r.number_of_triangles << ",\n"
    << "  \"number_of_canonical_triangles\": " << r.number_of_canonical_triangles << ",\n"
    << "  \"interior_valence_histogram\": ";
  internal::write_json_histogram(s, r.interior_valence_histogram);
  s << ",\n  \"boundary_valence_histogram\": ";
  internal::write_json_histogram(s, r.boundary_valence_histogram);
  s << ",\n"
    << "  \"number_of_interior_valence_3_like\": " << r.number_of_interior_valence_3_like << ",\n"
    << "  \"number_of_interior_valence_5_like\": " << r.number_of_interior_valence_5_like << ",\n"
    << "  \"number_of_boundary_negative_defects\": " << r.number_of_boundary_negative_defects << ",\n"
    << "  \"number_of_boundary_positive_defects\": " << r.number_of_boundary_positive_defects << ",\n"
    << "  \"interior_defect_sum\": " << r.interior_defect_sum << ",\n"
    << "  \"boundary_defect_sum\": " << r.boundary_defect_sum << ",\n"
    << "  \"total_absolute_defect\": " << r.total_absolute_defect << ",\n"
    << "  \"number_of_singularities_by_sector\": " << r.number_of_singularities_by_sector << ",\n"
    << "  \"singularity_lower_bound\": ";
  if(r.has_singularity_lower_bound)
    s << r.singularity_lower_bound;
  else
    s << "null";
  s << ",\n"
    << "  \"number_of_quads\": " << r.number_of_quads << ",\n"
    << "  \"min_scaled_jacobian\": ";
  if(r.number_of_quads > 0) s << r.min_scaled_jacobian; else s << "null";
  s << ",\n  \"mean_scaled_jacobian\": ";
  if(r.number_of_quads > 0) s << r.mean_scaled_jacobian; else s << "null";
  s << ",\n"
    << "  \"number_of_inverted_quads\": " << r.number_of_inverted_quads << "\n"
    << "}\n";
  return os << s.str();
}

/*!
\ingroup PkgQzipAnalysis

writes a short human-readable summary of `r` to `os` (a few lines).
*/
inline std::ostream& write_text(std::ostream& os, const Mesh_report& r)
{
  std::ostringstream s;
  s << "elements:      " << r.number_of_vertices << " vertices, " << r.number_of_edges << " edges, "
    << r.number_of_faces << " faces (by degree:";
  internal::write_text_histogram(s, r.faces_by_degree);
  s << ")\n"
    << "topology:      chi " << r.euler_characteristic << ", genus " << r.genus << ", "
    << r.number_of_connected_components << " component(s), " << r.number_of_boundary_loops
    << " boundary loop(s), " << r.number_of_border_edges << " border edge(s)";
  if(r.number_of_isolated_vertices > 0)
    s << ", " << r.number_of_isolated_vertices << " isolated vertex(es)";
  s << "\nvalences:      interior";
  internal::write_text_histogram(s, r.interior_valence_histogram);
  s << "; boundary";
  internal::write_text_histogram(s, r.boundary_valence_histogram);
  if(r.number_of_triangles > 0)
    s << "\ntriangles:     " << r.number_of_triangles << " (" << r.number_of_canonical_triangles
      << " canonical: their tips are not counted as singularities)";
  s << "\nsingularities: interior " << r.number_of_interior_valence_3_like << " v3-like, "
    << r.number_of_interior_valence_5_like << " v5-like; boundary "
    << r.number_of_boundary_negative_defects << " negative, " << r.number_of_boundary_positive_defects
    << " positive; " << r.number_of_singularities_by_sector << " counted by sector; total |defect| "
    << r.total_absolute_defect << "; lower bound ";
  if(r.has_singularity_lower_bound)
    s << r.singularity_lower_bound;
  else
    s << "n/a (not a closed pure-quad mesh)";
  s << "\nquads:         " << r.number_of_quads;
  if(r.number_of_quads > 0)
    s << ", scaled Jacobian min " << std::setprecision(4) << r.min_scaled_jacobian << " mean "
      << r.mean_scaled_jacobian << ", " << r.number_of_inverted_quads << " inverted";
  s << '\n';
  return os << s.str();
}

/// \ingroup PkgQzipAnalysis
/// same as `write_text(os, r)`.
inline std::ostream& operator<<(std::ostream& os, const Mesh_report& r)
{
  return write_text(os, r);
}

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_MESH_REPORT_H
