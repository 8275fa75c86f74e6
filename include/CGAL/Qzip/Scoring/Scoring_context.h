// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_SCORING_SCORING_CONTEXT_H
#define CGAL_QZIP_SCORING_SCORING_CONTEXT_H

#include <CGAL/license/Qzip.h>

#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/surgery_plan.h>
#include <CGAL/Qzip/internal/vertex_defect.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/property_map.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Qzip {

/*!
\ingroup PkgQzipOptimizer
A singularity found near a vertex by `Scoring_context::nearest_singularities()`.
*/
template <typename PolygonMesh>
struct Nearby_singularity
{
  typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex; ///< the singular vertex
  int defect;    ///< its defect (negative: v3-like, positive: v5-like)
  int distance;  ///< graph distance in edges
};

/*!
\ingroup PkgQzipOptimizer

What a scoring functor may ask about the mesh while candidates are scored. The optimizer owns it and
refreshes it before each batch; all answers describe the mesh as it was at the start of the batch
(scoring never edits the mesh). Distances are graph distances in edges.

At the start of each batch the context updates the neighbors, defects and flags of the vertices the
previous batch edited (and of their neighbors), the distance of every vertex to the border and the
features (in time linear in the size of the mesh, unless it has neither) and the separatrices. The
closest singularities of a vertex (`nearest_singularities()`, at most `max_nearest_singularities`, ties
broken by the position of the singularities) are found when first asked for in the batch, by a
breadth-first search around the vertex that stops once they are known; the variant that skips two
singularities and asks for only a few of them stops earlier, and a later question about the same vertex
in the batch that needs more of them continues that search where it stopped. Both are kept for the
batch, and across batches for the vertices whose search ball no surgery touched (for the others, those
closer than the closest edited vertex).
`distance_to_separatrix()` is a search within three edges done once per vertex and batch. `distance()`
runs bounded breadth-first searches, a few of which are kept.

\tparam PolygonMesh a model of `MutableFaceGraph`
\tparam VertexPointMap, EdgeIsConstrainedMap, FaceIsConstrainedMap the property maps of the optimizer
*/
template <typename PolygonMesh, typename VertexPointMap, typename EdgeIsConstrainedMap, typename FaceIsConstrainedMap>
class Scoring_context
{
public:
  typedef boost::graph_traits<PolygonMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef typename Kernel_traits<Point>::Kernel Kernel;
  typedef Nearby_singularity<PolygonMesh> Nearby;

  /// the number of closest singularities known at each vertex
  static constexpr std::size_t max_nearest_singularities = 6;

  /// what `nearest_singularities()` returns: a range of `Nearby_singularity` by increasing distance
  struct Neighborhood
  {
    Nearby items[max_nearest_singularities];
    std::size_t size = 0;
    int feature_distance = (std::numeric_limits<int>::max)(); ///< distance to the closest border or feature vertex (`INT_MAX` if none)
    const Nearby* begin() const { return items; }
    const Nearby* end() const { return items + size; }
  };

private:
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<int> >::type Int_map;
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<unsigned int> >::type Stamp_map;

  // K labels (vertex indices) per vertex, with their distances
  struct Labels { std::vector<int> source, distance; std::vector<unsigned char> count; };

  PolygonMesh& pm;
  VertexPointMap vpm;
  EdgeIsConstrainedMap ecm;
  FaceIsConstrainedMap fcm;

  // index of each vertex (valid if stamped with `numbering`), its defect, whether it is a border/feature
  // vertex, whether a surgery path may pass through it, and the neighbors of each vertex by index (rows of
  // `adjacency`, in rotation order from halfedge(v); both ends of a row side by side, as the searches read
  // them together). A batch that edited few vertices rebuilds their rows only (see refresh_rows()): the
  // indices of the removed vertices are free (null in by_index, empty rows) until created vertices take
  // them, and a rebuilt row that changed size is appended to `adjacency`, leaving `adjacency_garbage`
  // entries unused.
  Stamp_map stamp;
  Int_map index_map;
  unsigned int epoch = 0, numbering = 0;
  std::vector<vertex_descriptor> by_index;
  std::vector<int> free_indices;
  std::vector<int> defects;
  std::vector<unsigned char> cut, passable;
  struct Row { int begin, end; };
  std::vector<Row> adjacency_rows;
  std::vector<int> adjacency;
  std::size_t adjacency_garbage = 0;
  std::vector<int> row_buffer; // a row being rebuilt
  std::vector<int> singular_indices; // the singular vertices, by rank
  std::size_t m_number_of_faces = 0; // at the start of the batch
  std::size_t cut_count = 0; // the border and feature vertices
  std::vector<int> feature_dist;
  bool feature_dist_all_max = false; // INT_MAX everywhere (computed without border and feature vertices)
  // what the next begin_batch(edited) must rebuild (see refresh_rows()), unless rows_known is false (all
  // rows): the vertices told of by rows_edited() (stamped with the next epoch in `reported`), and the
  // indices of those told of by may_remove(). The edits are numbered (`edit`): a vertex is alive if it was
  // named alive (`alive_after`) after an edit at least as late as the last one that may have removed it
  // (`doubted_in`).
  std::vector<vertex_descriptor> reported_vertices;
  std::vector<int> removal_candidates;
  bool rows_known = false;
  Stamp_map reported, doubted_in, alive_after;
  unsigned int edit = 0;
  std::vector<unsigned int> rebuilt_in; // by index, stamped with the epoch (see refresh_rows())
  // closest singularities: the rank of each singular vertex in the order of begin_batch() (-1 if regular),
  // and the labels of the vertices asked about in this batch (near_known: stamped with the epoch)
  std::vector<int> ranks;
  mutable Labels near_labels;
  mutable std::vector<unsigned int> near_known;
  mutable std::vector<unsigned char> near_complete;
  // by vertex, whether it is singular (`singular_mark`, where ranks is not -1), whether the search under
  // way visited it (`visited_mark`, cleared at its end by going through its queue), and whether it owns a
  // kept entry (`owner_mark`, during begin_batch(edited) only). One byte per vertex, which a search reads
  // anyway when it meets the vertex: on a large mesh they stay in the cache (unlike `ranks` or stamps of
  // four bytes), and they tell which vertices to look up in `ranks` or `kept`.
  static constexpr unsigned char visited_mark = 1, singular_mark = 2, owner_mark = 4;
  mutable std::vector<unsigned char> near_mark;
  mutable std::vector<int> near_queue;
  mutable std::vector<std::pair<int, int> > near_found;
  // a search for the closest singularities of a vertex, level by level (see search_nearest()): the last
  // two levels it went through, by their places in its queue, and how far it expanded the last one
  struct Near_levels
  {
    std::size_t previous = 0, begin = 0, end = 0; // the last two levels: [previous, begin) and [begin, end)
    std::size_t expanded = 0; // the vertices of the last level from there on were not expanded
    int level = 0; // the distance of the vertices of the last level
  };
  // the search under way: its levels and its queue, the first near_work_size vertices of near_work (which
  // has room for every vertex and one more, see expand_nearest())
  mutable Near_levels near_levels;
  mutable std::vector<int> near_work;
  mutable std::size_t near_work_size = 0;
  // the searches of the batch that stopped early, to be continued by a later query at the same vertex
  // (see resume_nearest()), with only the vertices that continuing needs, and for each vertex 1 + the
  // index of its search there (0 if none). They hold at most about `near_stopped_budget()` vertices.
  struct Near_stopped { int vertex; std::vector<int> queue; Near_levels levels; };
  mutable std::vector<Near_stopped> near_stopped;
  mutable std::size_t near_stopped_count = 0, near_stopped_size = 0;
  mutable std::vector<int> near_stopped_at;
  // the closest singularities kept across batches: a search around a vertex only read the ball of
  // `radius` edges around it, so its answer holds while no vertex of that ball is edited. The vertices
  // and positions of the labels are checked when used: a descriptor may have been recycled, and an undone
  // surgery gives back the same mesh with new descriptors.
  struct Kept
  {
    vertex_descriptor owner;
    Point position;
    int radius;
    bool complete;
    std::size_t count;
    vertex_descriptor label[max_nearest_singularities];
    Point label_position[max_nearest_singularities];
    int distance[max_nearest_singularities];
  };
  typedef typename boost::property_map<PolygonMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type Kept_map;
  Kept_map kept_index; // 1 + the index in `kept`, 0 for none
  mutable std::vector<Kept> kept;
  mutable std::vector<std::size_t> kept_free;
  mutable int kept_radius = 0; // the largest radius of a kept search
  // separatrices: the singularities whose separatrices pass through each vertex (rows of sep_owner, from
  // sep_begin to sep_end, in the order of the seeds; both 0 at the other vertices), and, computed when
  // first asked for in a batch, the three closest of them within m_separatrix_radius edges
  std::vector<int> sep_begin, sep_end, sep_owner;
  std::vector<int> sep_vertices; // the vertices whose rows are not empty
  mutable Labels sep_near;
  mutable std::vector<unsigned int> sep_near_known; // stamped with the epoch
  mutable std::vector<unsigned int> visit;
  mutable unsigned int visit_round = 0;
  mutable std::vector<int> local_queue, local_level;

  int m_separatrix_length = 32;
  int m_separatrix_radius = 3;
  double m_mean_face_area = 1;

  // strip_quads() of the last plan, and the halfedges of the edges of the last path (found when first needed)
  mutable bool strip_known = false;
  mutable std::vector<vertex_descriptor> strip_path;
  mutable std::vector<Strip_operation> strip_operations;
  mutable std::vector<std::pair<halfedge_descriptor, bool> > strip_edges;
  mutable std::vector<unsigned char> strip_edge_known;

  // a few breadth-first balls kept for distance()
  struct Slot { vertex_descriptor source; int radius; unsigned int epoch; Stamp_map stamp; Int_map dist; };
  std::vector<Slot> slots;
  std::size_t next_slot = 0;
  std::vector<vertex_descriptor> queue;

public:
  /// \cond SKIP_IN_MANUAL
  Scoring_context(PolygonMesh& pm, VertexPointMap vpm, EdgeIsConstrainedMap ecm, FaceIsConstrainedMap fcm)
    : pm(pm), vpm(vpm), ecm(ecm), fcm(fcm),
      stamp(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      index_map(get(CGAL::dynamic_vertex_property_t<int>(), pm)),
      reported(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      doubted_in(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      alive_after(get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm)),
      kept_index(get(CGAL::dynamic_vertex_property_t<std::size_t>(), pm))
  {
    for(std::size_t i = 0; i < 4; ++i)
      slots.push_back(Slot{ GT::null_vertex(), -1, 0u, get(CGAL::dynamic_vertex_property_t<unsigned int>(), pm),
                            get(CGAL::dynamic_vertex_property_t<int>(), pm) });
    for(vertex_descriptor v : vertices(pm))
    {
      put(stamp, v, 0u);
      put(reported, v, 0u);
      put(doubted_in, v, 0u);
      put(alive_after, v, 0u);
      put(kept_index, v, 0);
      for(Slot& sl : slots) put(sl.stamp, v, 0u);
    }
    // geometric mean: the log-ratios of the sizing term then average to zero over the input
    double log_area = 0;
    std::size_t n = 0;
    for(face_descriptor f : faces(pm))
    {
      const double a = face_area(f);
      if(a > 0) { log_area += std::log(a); ++n; }
    }
    m_mean_face_area = n > 0 ? std::exp(log_area / double(n)) : 1.;
    if(!(m_mean_face_area > 0) || !std::isfinite(m_mean_face_area)) m_mean_face_area = 1.;
  }

  // refreshes everything; returns the singular vertices sorted by position.
  std::vector<vertex_descriptor> begin_batch()
  {
    for(const Kept& k : kept) put(kept_index, k.owner, 0);
    kept.clear();
    kept_free.clear();
    kept_radius = 0;
    return refresh(true);
  }

  // same, after a batch that edited (created, moved, or changed the neighbors of) the vertices `edited`
  // (some of which may have been removed since) and no other vertex, except by surgeries it undid. The
  // edits were told of by may_remove() and rows_edited() (else by rows_changed_elsewhere()): the rows of the
  // vertices they name are rebuilt (see refresh_rows()). The closest singularities found in earlier
  // batches are kept for the vertices farther from the edited ones than their search went, and those
  // closer than the edited vertices for the others (see keep_closer_than()).
  std::vector<vertex_descriptor> begin_batch(const std::vector<vertex_descriptor>& edited)
  {
    std::vector<vertex_descriptor> singular = rows_known ? refresh_rows() : refresh(false);
    // the vertices of the mesh that own a kept entry (marked with `owner_mark` until done), and how many
    // entries there are of each radius
    std::vector<std::size_t> of_radius(std::size_t(kept_radius) + 1, 0);
    std::vector<int> owners;
    for(std::size_t k = 1; k <= kept.size(); ++k)
    {
      const int i = index(kept[k - 1].owner);
      if(i < 0 || kept_slot(kept[k - 1].owner) != k) continue;
      near_mark[std::size_t(i)] |= owner_mark;
      owners.push_back(i);
      ++of_radius[std::size_t(kept[k - 1].radius)];
    }
    // breadth-first from the edited vertices, level by level, while an entry not reached yet may have an
    // edited vertex within its radius
    int unreached_radius = kept_radius; // the largest radius of an entry not reached yet (or less)
    auto settle = [&]() { while(unreached_radius >= 0 && of_radius[std::size_t(unreached_radius)] == 0) --unreached_radius; };
    settle();
    near_queue.clear();
    if(unreached_radius >= 0) for(vertex_descriptor v : edited)
    {
      const int i = index(v);
      if(i < 0 || (near_mark[std::size_t(i)] & visited_mark) != 0) continue;
      near_mark[std::size_t(i)] |= visited_mark;
      near_queue.push_back(i);
    }
    int level = 0;
    std::size_t level_end = near_queue.size();
    for(std::size_t q = 0; q < near_queue.size(); ++q)
    {
      if(q == level_end) { ++level; level_end = near_queue.size(); }
      const int u = queued(near_queue.data(), q, near_queue.size());
      if((near_mark[std::size_t(u)] & owner_mark) != 0)
      {
        const std::size_t k = kept_slot(by_index[std::size_t(u)]);
        --of_radius[std::size_t(kept[k - 1].radius)];
        if(kept[k - 1].radius >= level) keep_closer_than(k, level);
        settle();
      }
      if(level >= unreached_radius) continue;
      for(const int* w = neighbors_begin(u); w != neighbors_end(u); ++w)
      {
        if((near_mark[std::size_t(*w)] & visited_mark) != 0) continue;
        near_mark[std::size_t(*w)] |= visited_mark;
        near_queue.push_back(*w);
      }
    }
    for(const int i : owners) near_mark[std::size_t(i)] &= static_cast<unsigned char>(~owner_mark);
    for(const int i : near_queue) near_mark[std::size_t(i)] &= static_cast<unsigned char>(~visited_mark);
    return singular;
  }

  // tells, before an edit, that it removes no vertex but some of `vs` (alive); after it, rows_edited() and
  // survived() must name those of them still alive
  void may_remove(const std::vector<vertex_descriptor>& vs)
  {
    ++edit;
    for(vertex_descriptor v : vs)
    {
      put(doubted_in, v, edit);
      const int i = index(v);
      if(i >= 0) removal_candidates.push_back(i);
    }
  }

  // tells, after the last edit, that the vertices `vs` (alive) may have been created, moved or have other
  // neighbors (or another halfedge(v)) since the start of the batch, and that no other vertex did but
  // their neighbors and those named by may_remove(); an undo that gives back the mesh with new descriptors
  // names those it re-created or walked around. Their rows, and those of their neighbors, are rebuilt at
  // the next begin_batch(edited).
  void rows_edited(const std::vector<vertex_descriptor>& vs)
  {
    survived(vs);
    for(vertex_descriptor v : vs)
    {
      if(get(reported, v) == epoch + 1) continue;
      put(reported, v, epoch + 1);
      reported_vertices.push_back(v);
    }
  }

  // tells, after the last edit, that the vertices `vs` are alive
  void survived(const std::vector<vertex_descriptor>& vs)
  {
    for(vertex_descriptor v : vs) put(alive_after, v, edit);
  }

  // tells that the mesh was edited where neither may_remove() nor rows_edited() said: the next
  // begin_batch(edited) rebuilds every row
  void rows_changed_elsewhere() { rows_known = false; }

private:
  // 1 + the index of the entry of v in `kept`, or 0 if it has none (an entry recycled for another vertex
  // does not count)
  std::size_t kept_slot(vertex_descriptor v) const
  {
    const std::size_t k = get(kept_index, v);
    return k != 0 && k <= kept.size() && kept[k - 1].owner == v ? k : 0;
  }

  void forget(std::size_t k) const
  {
    put(kept_index, kept[k - 1].owner, 0);
    kept_free.push_back(k - 1);
  }

  // keeps, of the kept labels of entry k, those closer than `edited_distance`, the distance from their
  // vertex to the closest vertex edited by the last batch (forgets the entry if none is). They are exact:
  // a path from the vertex shorter than `edited_distance` passes through no edited vertex, so it was a path
  // before the batch and still is one, and no path through an edited vertex is shorter; thus the
  // singularities closer than `edited_distance` are the same and at the same distances, in the same order
  // (their positions are checked when the labels are restored). The search that found the labels went at
  // least that far, so it found all of them: the labels left are the start of the labels of the vertex,
  // complete up to `edited_distance - 1` edges.
  void keep_closer_than(std::size_t k, int edited_distance) const
  {
    Kept& e = kept[k - 1];
    std::size_t count = 0;
    while(count < e.count && e.distance[count] < edited_distance) ++count;
    if(count == 0) { forget(k); return; }
    e.count = count;
    e.complete = false;
    e.radius = edited_distance - 1;
  }

  // rebuilds everything; the vertices are numbered breadth-first, or (`breadth_first` false) in the order
  // of the previous batch. Returns the singular vertices sorted by position.
  std::vector<vertex_descriptor> refresh(bool breadth_first)
  {
    const std::size_t previous_size = by_index.size();
    ++epoch;
    ++numbering;
    clear_cache();
    by_index.clear(); free_indices.clear(); defects.clear(); cut.clear(); passable.clear();
    adjacency_rows.clear(); adjacency.clear();
    adjacency_garbage = 0;
    cut_count = 0;
    reported_vertices.clear();
    removal_candidates.clear();
    rows_known = true;
    // The numbering changes no answer: ties between singularities are broken by their positions, and the
    // neighbors of a vertex are listed in rotation order whatever their numbers. Numbers close to those of
    // the neighbors make the searches on the arrays indexed by vertex read entries close to each other.
    std::vector<vertex_descriptor> singular = breadth_first ? number_breadth_first() : number_as_before(previous_size);
    ranks.assign(by_index.size(), -1);
    near_mark.assign(by_index.size(), 0);
    return finish_refresh(std::move(singular));
  }

  // the same, after a batch whose edits were told of by may_remove(), rows_edited() and survived(), in
  // time proportional to the edits: it frees the indices of the vertices removed (those that may have been
  // and were not named alive since), and rebuilds the rows (and defects, cut and passable flags) of the
  // vertices named alive (created ones included), and those of their neighbors before and after. A row
  // only changes with the ring of its vertex, which changes only for the vertices the batch edited or that
  // an undo re-created or walked around, or with halfedge(v), which an operation only sets for a vertex
  // next to the vertices it edits. The rows it rebuilds are thus those a complete rebuild gives, and the
  // others are unchanged. Rebuilds everything (see refresh()) when a quarter of the vertices or more are to
  // be rebuilt.
  std::vector<vertex_descriptor> refresh_rows()
  {
    ++epoch; // the vertices named by rows_edited() are stamped with it in `reported`
    clear_cache();
    // no walk around these vertices: they may be dead
    auto is_alive = [this](vertex_descriptor v) { return get(alive_after, v) >= get(doubted_in, v); };
    for(const int i : removal_candidates)
    {
      const vertex_descriptor v = by_index[std::size_t(i)];
      if(v != GT::null_vertex() && (!is_alive(v) || index(v) != i)) free_index(i);
    }
    removal_candidates.clear();
    std::vector<int> rows;
    std::vector<vertex_descriptor> created;
    for(vertex_descriptor v : reported_vertices)
    {
      if(get(reported, v) != epoch || !is_alive(v)) continue; // named twice (recycled), or removed
      put(reported, v, 0u);
      const int i = index(v);
      if(i < 0) created.push_back(v);
      else rows.push_back(i);
    }
    reported_vertices.clear();
    if(4 * (rows.size() + created.size()) >= by_index.size() - free_indices.size()) return refresh(false);
    for(vertex_descriptor v : created) rows.push_back(take_index(v));
    // the rows of the vertices named and created, then those of their neighbors before and after
    const std::size_t reported_rows = rows.size();
    for(const int i : rows) rebuilt_in[std::size_t(i)] = epoch;
    auto add_neighbors = [&](int i)
    {
      for(const int* w = neighbors_begin(i); w != neighbors_end(i); ++w)
      {
        if(rebuilt_in[std::size_t(*w)] == epoch || by_index[std::size_t(*w)] == GT::null_vertex()) continue;
        rebuilt_in[std::size_t(*w)] = epoch;
        rows.push_back(*w);
      }
    };
    for(std::size_t k = 0; k < reported_rows; ++k) add_neighbors(rows[k]); // the rows before
    for(std::size_t k = 0; k < reported_rows; ++k) rebuild_row(rows[k]);
    for(std::size_t k = 0; k < reported_rows; ++k) add_neighbors(rows[k]); // the rows after
    for(std::size_t k = reported_rows; k < rows.size(); ++k) rebuild_row(rows[k]);
    if(2 * adjacency_garbage > adjacency.size()) compact_adjacency();
    // the singular vertices: those of the previous batch whose rows were kept, and the rebuilt ones
    std::vector<vertex_descriptor> singular;
    for(const int i : singular_indices)
    {
      ranks[std::size_t(i)] = -1;
      near_mark[std::size_t(i)] = 0;
      if(by_index[std::size_t(i)] != GT::null_vertex() && rebuilt_in[std::size_t(i)] != epoch)
        singular.push_back(by_index[std::size_t(i)]);
    }
    for(const int i : rows) if(defects[std::size_t(i)] != 0) singular.push_back(by_index[std::size_t(i)]);
    return finish_refresh(std::move(singular));
  }

  // gives the created vertex v a free index, or a new one; returns it
  int take_index(vertex_descriptor v)
  {
    int i = int(by_index.size());
    if(free_indices.empty())
    {
      by_index.push_back(v);
      defects.push_back(0);
      cut.push_back(0);
      passable.push_back(0);
      adjacency_rows.push_back(Row{ int(adjacency.size()), int(adjacency.size()) });
      ranks.push_back(-1);
      near_mark.push_back(0);
      rebuilt_in.push_back(0u);
    }
    else
    {
      i = free_indices.back();
      free_indices.pop_back();
      by_index[std::size_t(i)] = v;
    }
    put(stamp, v, numbering);
    put(index_map, v, i);
    return i;
  }

  // frees the index of a vertex removed: its descriptor (which may not be walked around) gets no index
  void free_index(int i)
  {
    put(stamp, by_index[std::size_t(i)], 0u);
    by_index[std::size_t(i)] = GT::null_vertex();
    adjacency_garbage += std::size_t(valence_at(i));
    adjacency_rows[std::size_t(i)].end = adjacency_rows[std::size_t(i)].begin;
    defects[std::size_t(i)] = 0;
    cut_count -= cut[std::size_t(i)];
    cut[std::size_t(i)] = passable[std::size_t(i)] = 0;
    free_indices.push_back(i);
  }

  // builds the row of vertex i again, in place if its size did not change, else at the end of `adjacency`
  void rebuild_row(int i)
  {
    row_buffer.clear();
    add_row(by_index[std::size_t(i)], i, row_buffer);
    const std::size_t size = std::size_t(valence_at(i));
    if(row_buffer.size() != size)
    {
      adjacency_garbage += size;
      adjacency_rows[std::size_t(i)].begin = int(adjacency.size());
      adjacency.resize(adjacency.size() + row_buffer.size());
      adjacency_rows[std::size_t(i)].end = int(adjacency.size());
    }
    std::copy(row_buffer.begin(), row_buffer.end(), adjacency.begin() + adjacency_rows[std::size_t(i)].begin);
  }

  // writes the rows again in the order of the indices, without the garbage
  void compact_adjacency()
  {
    std::vector<int> compact;
    compact.reserve(adjacency.size() - adjacency_garbage);
    for(std::size_t i = 0; i < by_index.size(); ++i)
    {
      const std::size_t begin = compact.size();
      compact.insert(compact.end(), neighbors_begin(int(i)), neighbors_end(int(i)));
      adjacency_rows[i] = Row{ int(begin), int(compact.size()) };
    }
    adjacency.swap(compact);
    adjacency_garbage = 0;
  }

  // what follows the rows: the singular vertices sorted by position (returned) and their ranks (`ranks`
  // is -1 elsewhere), the distances to the features, the separatrices, and the arrays of the searches
  // (empty for this batch)
  std::vector<vertex_descriptor> finish_refresh(std::vector<vertex_descriptor>&& singular)
  {
    const std::size_t n = by_index.size();
    // an order that does not depend on descriptors (the seeds' order breaks ties)
    std::sort(singular.begin(), singular.end(), [this](vertex_descriptor a, vertex_descriptor b)
    {
      const Point& pa = get(vpm, a);
      const Point& pb = get(vpm, b);
      if(pa.x() != pb.x()) return pa.x() < pb.x();
      if(pa.y() != pb.y()) return pa.y() < pb.y();
      return pa.z() < pb.z();
    });
    // (the range's size, not num_faces(), which on a Surface_mesh also counts the removed faces its garbage holds)
    m_number_of_faces = faces(pm).size();
    singular_indices.clear();
    for(std::size_t r = 0; r < singular.size(); ++r)
    {
      singular_indices.push_back(index(singular[r]));
      ranks[std::size_t(singular_indices.back())] = int(r);
      near_mark[std::size_t(singular_indices.back())] = singular_mark;
    }
    rebuilt_in.resize(n, 0u);
    // closest singularities: computed when first asked for in the batch (near_known is stamped,
    // near_stopped_at is 0 but at the vertices of the stopped searches)
    near_labels.source.resize(n * max_nearest_singularities);
    near_labels.distance.resize(n * max_nearest_singularities);
    near_labels.count.resize(n);
    near_known.resize(n, 0u);
    near_complete.resize(n);
    for(std::size_t k = 0; k < near_stopped_count; ++k) near_stopped_at[std::size_t(near_stopped[k].vertex)] = 0;
    near_stopped_count = near_stopped_size = 0;
    near_stopped_at.resize(n, 0);
    near_work.resize(n + 1);
    // distance to the border and the features (INT_MAX everywhere on a closed mesh without features, as
    // in the previous batch if it had none either)
    if(cut_count == 0 && feature_dist_all_max) feature_dist.resize(n, (std::numeric_limits<int>::max)());
    else
    {
      feature_dist.assign(n, (std::numeric_limits<int>::max)());
      std::vector<int> fqueue;
      for(std::size_t i = 0; i < n; ++i) if(cut[i]) { feature_dist[i] = 0; fqueue.push_back(int(i)); }
      for(std::size_t i = 0; i < fqueue.size(); ++i)
      {
        const int d = feature_dist[std::size_t(fqueue[i])];
        for(const int* w = neighbors_begin(fqueue[i]); w != neighbors_end(fqueue[i]); ++w)
        {
          const std::size_t j = std::size_t(*w);
          if(feature_dist[j] <= d + 1) continue;
          feature_dist[j] = d + 1;
          fqueue.push_back(int(j));
        }
      }
    }
    feature_dist_all_max = cut_count == 0;
    // separatrices
    std::vector<std::pair<int, int> > seeds;
    trace_separatrices(singular, seeds);
    // the seeds grouped by vertex (rows in the order of the first seeds at their vertices), in the order of
    // the seeds within a row: counted in sep_end, then written from sep_begin on (both 0 outside the rows)
    for(const int i : sep_vertices) sep_begin[std::size_t(i)] = sep_end[std::size_t(i)] = 0;
    sep_begin.resize(n, 0);
    sep_end.resize(n, 0);
    sep_vertices.clear();
    for(const std::pair<int, int>& seed : seeds)
      if(sep_end[std::size_t(seed.first)]++ == 0) sep_vertices.push_back(seed.first);
    int row_begin = 0;
    for(const int i : sep_vertices)
    {
      sep_begin[std::size_t(i)] = row_begin;
      row_begin += sep_end[std::size_t(i)];
      sep_end[std::size_t(i)] = sep_begin[std::size_t(i)];
    }
    sep_owner.resize(seeds.size());
    for(const std::pair<int, int>& seed : seeds) sep_owner[std::size_t(sep_end[std::size_t(seed.first)]++)] = seed.second;
    sep_near.source.resize(n * 3);
    sep_near.distance.resize(n * 3);
    sep_near.count.resize(n);
    sep_near_known.resize(n, 0u);
    visit.resize(n, 0u);
    return std::move(singular);
  }

  // numbers the vertices (isolated ones excepted) in breadth-first order, component by component, and
  // builds their rows; returns the singular ones
  std::vector<vertex_descriptor> number_breadth_first()
  {
    std::vector<vertex_descriptor> singular;
    for(vertex_descriptor v : vertices(pm))
    {
      if(halfedge(v, pm) == GT::null_halfedge() || get(stamp, v) == numbering) continue;
      std::size_t i = by_index.size();
      number(v);
      for(; i < by_index.size(); ++i) if(add_row(by_index[i])) singular.push_back(by_index[i]);
    }
    return singular;
  }

  // numbers the vertices (isolated ones excepted) in the order of their numbers in the previous batch of
  // `previous_size` vertices, those created since after them, and builds their rows; returns the singular
  // ones. A batch creates few vertices, so the breadth-first order of the first batch mostly holds, and the
  // mesh is read in its storage order, faster than in breadth-first order.
  std::vector<vertex_descriptor> number_as_before(std::size_t previous_size)
  {
    // the key of each vertex: its previous number, unique among the vertices numbered in the previous
    // batch (stamped with numbering - 1), or previous_size + its rank among the others
    std::vector<vertex_descriptor> stored;
    std::vector<int> key;
    int created = 0;
    for(vertex_descriptor v : vertices(pm))
    {
      if(halfedge(v, pm) == GT::null_halfedge()) continue;
      const bool numbered = get(stamp, v) == numbering - 1 && std::size_t(get(index_map, v)) < previous_size;
      stored.push_back(v);
      key.push_back(numbered ? get(index_map, v) : int(previous_size) + created++);
    }
    std::vector<int> number_of_key(previous_size + std::size_t(created), 0);
    for(int k : key) number_of_key[std::size_t(k)] = 1;
    for(std::size_t k = 0, n = 0; k < number_of_key.size(); ++k)
    {
      const int used = number_of_key[k];
      number_of_key[k] = int(n);
      n += std::size_t(used);
    }
    std::vector<int>& index_of = key; // from now on, the new number of each vertex, in storage order
    by_index.resize(stored.size());
    for(std::size_t j = 0; j < stored.size(); ++j)
    {
      index_of[j] = number_of_key[std::size_t(key[j])];
      put(stamp, stored[j], numbering);
      put(index_map, stored[j], index_of[j]);
      by_index[std::size_t(index_of[j])] = stored[j];
    }
    // the rows, built in storage order, then put in the order of the numbers
    std::vector<vertex_descriptor> singular;
    std::vector<int> row_begin, row;
    defects.resize(stored.size());
    cut.resize(stored.size());
    passable.resize(stored.size());
    for(std::size_t j = 0; j < stored.size(); ++j)
    {
      row_begin.push_back(int(row.size()));
      if(add_row(stored[j], index_of[j], row)) singular.push_back(stored[j]);
    }
    row_begin.push_back(int(row.size()));
    adjacency_rows.assign(stored.size(), Row{ 0, 0 });
    for(std::size_t j = 0; j < stored.size(); ++j)
      adjacency_rows[std::size_t(index_of[j])].end = row_begin[j + 1] - row_begin[j];
    for(std::size_t i = 0, begin = 0; i < stored.size(); ++i)
    {
      adjacency_rows[i].begin = int(begin);
      begin += std::size_t(adjacency_rows[i].end);
      adjacency_rows[i].end = int(begin);
    }
    adjacency.resize(row.size());
    for(std::size_t j = 0; j < stored.size(); ++j)
      std::copy(row.begin() + row_begin[j], row.begin() + row_begin[j + 1],
                adjacency.begin() + adjacency_rows[std::size_t(index_of[j])].begin);
    return singular;
  }

  // gives v the next index
  void number(vertex_descriptor v)
  {
    put(stamp, v, numbering);
    put(index_map, v, int(by_index.size()));
    by_index.push_back(v);
  }

  // appends the row of v (numbered) to the adjacency, numbering its neighbors that are not yet, and its
  // defect, whether it is a border/feature vertex and whether it is passable; returns whether it is singular
  bool add_row(vertex_descriptor v)
  {
    adjacency_rows.push_back(Row{ int(adjacency.size()), 0 });
    defects.emplace_back();
    cut.emplace_back();
    passable.emplace_back();
    const bool singular = add_row(v, int(defects.size()) - 1, adjacency, true);
    adjacency_rows.back().end = int(adjacency.size());
    return singular;
  }

  // the same, v numbered i, its row appended to `row`, its neighbors numbered already unless `number_them`
  bool add_row(vertex_descriptor v, int i, std::vector<int>& row, bool number_them = false)
  {
    bool c = false, p = false;
    int valence = 0;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
    {
      const vertex_descriptor w = source(h, pm);
      if(number_them && get(stamp, w) != numbering) number(w);
      row.push_back(get(index_map, w));
      ++valence;
      if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) c = true;
      if(!is_border(h, pm) && get(fcm, face(h, pm))) p = true;
    }
    const int d = c ? internal::vertex_defect_info(v, pm, vpm, ecm, Kernel()).defect : valence - 4;
    defects[std::size_t(i)] = d;
    cut_count = cut_count + (c ? 1 : 0) - cut[std::size_t(i)];
    cut[std::size_t(i)] = c ? 1 : 0;
    passable[std::size_t(i)] = c || p ? 0 : 1;
    return d != 0;
  }

public:
  void clear_cache()
  {
    for(Slot& sl : slots) sl.source = GT::null_vertex();
    strip_known = false;
  }
  /// \endcond

  /// the mesh.
  const PolygonMesh& mesh() const { return pm; }
  /// the vertex point map.
  VertexPointMap vertex_point_map() const { return vpm; }
  /// the position of `v`.
  Point point(vertex_descriptor v) const { return get(vpm, v); }
  /// the defect of `v` at the start of the batch (see `vertex_defect()`).
  int defect(vertex_descriptor v) const { const int i = index(v); return i < 0 ? 0 : defects[std::size_t(i)]; }
  /// `true` if `v` lies on the border or on a constrained (feature) edge.
  bool is_border_or_feature(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(is_border_edge(h, pm) || get(ecm, edge(h, pm))) return true;
    return false;
  }
  /// `true` if `v` is a vertex of a protected face.
  bool is_protected(vertex_descriptor v) const
  {
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
      if(!is_border(h, pm) && get(fcm, face(h, pm))) return true;
    return false;
  }
  /// the geometric mean of the areas of the faces of the mesh given to the optimizer (the uniform target size).
  double mean_face_area() const { return m_mean_face_area; }

  /// the number of singular vertices at the start of the batch (those `nearest_singularities()` finds).
  std::size_t number_of_singularities() const { return singular_indices.size(); }

  /// the number of faces of the mesh at the start of the batch.
  std::size_t number_of_faces() const { return m_number_of_faces; }

  /// the area of face `f` (half the norm of the sum of the cross products of a fan).
  double face_area(face_descriptor f) const
  {
    Point p[3];
    int k = 0;
    double x = 0, y = 0, z = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pm), pm))
    {
      const Point q = get(vpm, target(h, pm));
      if(k < 2) { p[k++] = q; continue; }
      const auto n = CGAL::cross_product(p[1] - p[0], q - p[0]);
      x += n.x(); y += n.y(); z += n.z();
      p[1] = q;
    }
    return 0.5 * std::sqrt(x * x + y * y + z * z);
  }

  /// the length of the edge (or the distance) from `a` to `b`.
  double length(vertex_descriptor a, vertex_descriptor b) const
  { return std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, a), get(vpm, b)))); }

  /// the (at most `max_nearest_singularities`) singularities closest to `v`, `v` excluded, by distance, and
  /// the distance from `v` to the closest border or feature vertex.
  Neighborhood nearest_singularities(vertex_descriptor v) const
  {
    return nearest_singularities(v, GT::null_vertex(), GT::null_vertex(), max_nearest_singularities);
  }

  /// the first `n` of the singularities of `nearest_singularities(v)` other than `x1` and `x2` (fewer if
  /// it has fewer), and the distance from `v` to the closest border or feature vertex. Cheaper than
  /// `nearest_singularities(v)` when `n` is small: the search around `v` stops once they are known.
  Neighborhood nearest_singularities(vertex_descriptor v, vertex_descriptor x1, vertex_descriptor x2, std::size_t n) const
  {
    Neighborhood nb;
    const int i = index(v);
    if(i < 0) return nb;
    nb.feature_distance = feature_dist[std::size_t(i)];
    const int i1 = index_or_none(x1), i2 = index_or_none(x2);
    n = (std::min)(n, std::size_t(max_nearest_singularities)); // by value: std::min binds references, and the member has no definition
    compute_nearest(i, i1, i2, n);
    const std::size_t K = max_nearest_singularities;
    for(std::size_t k = std::size_t(i) * K; k < std::size_t(i) * K + near_labels.count[std::size_t(i)] && nb.size < n; ++k)
    {
      const int j = near_labels.source[k];
      if(j == i || j == i1 || j == i2) continue;
      nb.items[nb.size++] = Nearby{ by_index[std::size_t(j)], defects[std::size_t(j)], near_labels.distance[k] };
    }
    return nb;
  }

  /// the distance from `v` to the closest singularity whose defect has the sign opposite to `sign`, among
  /// the singularities of `nearest_singularities(v)` other than `x1` and `x2`; -1 if there is none among
  /// them. Cheaper than `nearest_singularities(v)`: the search around `v` stops once it is known.
  int opposite_singularity_distance(vertex_descriptor v, int sign, vertex_descriptor x1, vertex_descriptor x2) const
  {
    return closest_opposite_singularity(v, sign, x1, x2).distance;
  }

  /// the singularity whose distance `opposite_singularity_distance()` gives (distance -1 and `null_vertex()`
  /// if there is none).
  Nearby closest_opposite_singularity(vertex_descriptor v, int sign, vertex_descriptor x1, vertex_descriptor x2) const
  {
    const int i = index(v);
    if(i < 0) return Nearby{ GT::null_vertex(), 0, -1 };
    const int i1 = index_or_none(x1), i2 = index_or_none(x2);
    compute_nearest(i, i1, i2, max_nearest_singularities, sign);
    const std::size_t K = max_nearest_singularities;
    for(std::size_t k = std::size_t(i) * K; k < std::size_t(i) * K + near_labels.count[std::size_t(i)]; ++k)
    {
      const int j = near_labels.source[k];
      if(j != i && j != i1 && j != i2 && defects[std::size_t(j)] * sign < 0)
        return Nearby{ by_index[std::size_t(j)], defects[std::size_t(j)], near_labels.distance[k] };
    }
    return Nearby{ GT::null_vertex(), 0, -1 };
  }

  /// the graph distance from `a` to `b`, or `max_radius + 1` if it is larger than `max_radius`.
  int distance(vertex_descriptor a, vertex_descriptor b, int max_radius)
  {
    if(a == b) return 0;
    Slot* slot = nullptr;
    for(Slot& sl : slots) if(sl.source == a && sl.radius >= max_radius) { slot = &sl; break; }
    if(slot == nullptr)
    {
      slot = &slots[next_slot];
      next_slot = (next_slot + 1) % slots.size();
      slot->source = a;
      slot->radius = max_radius;
      ++slot->epoch;
      queue.clear();
      queue.push_back(a);
      put(slot->stamp, a, slot->epoch);
      put(slot->dist, a, 0);
      for(std::size_t i = 0; i < queue.size(); ++i)
      {
        const vertex_descriptor v = queue[i];
        const int d = get(slot->dist, v);
        if(d >= slot->radius) continue;
        for(halfedge_descriptor h : halfedges_around_target(halfedge(v, pm), pm))
        {
          const vertex_descriptor w = source(h, pm);
          if(get(slot->stamp, w) == slot->epoch) continue;
          put(slot->stamp, w, slot->epoch);
          put(slot->dist, w, d + 1);
          queue.push_back(w);
        }
      }
    }
    if(get(slot->stamp, b) != slot->epoch) return max_radius + 1;
    const int d = get(slot->dist, b);
    return d > max_radius ? max_radius + 1 : d;
  }

  /// the distance from `v` to the closest vertex on a separatrix (a straight edge line leaving a
  /// singularity) of a singularity other than `x1` and `x2`, or `max_radius + 1` if there is none
  /// within `min(max_radius, 3)` edges.
  int distance_to_separatrix(vertex_descriptor v, vertex_descriptor x1, vertex_descriptor x2, int max_radius) const
  {
    const int i = index(v);
    if(i < 0) return max_radius + 1;
    if(sep_near_known[std::size_t(i)] != epoch) closest_separatrices(i);
    for(std::size_t k = std::size_t(i) * 3; k < std::size_t(i) * 3 + sep_near.count[std::size_t(i)]; ++k)
    {
      const vertex_descriptor owner = by_index[std::size_t(sep_near.source[k])];
      if(owner == x1 || owner == x2) continue;
      const int d = sep_near.distance[k];
      return d <= max_radius ? d : max_radius + 1;
    }
    return max_radius + 1;
  }

  /// \cond SKIP_IN_MANUAL
  // a quad that an operation of a plan acts on: the quad on the side of the path edge that the operation
  // collapses or splits, the length `along` of the path edge and the mean length `across` of the two
  // sides of the quad that leave the path
  struct Strip_quad { Strip_operation operation; face_descriptor face; double along, across, area; };
private:
  mutable std::vector<Strip_quad> strip;
public:

  // the strip quads of `plan`, in path order (path edges without an operation, without a quad on that
  // side, or of zero length are left out). The terms of a candidate ask for the same plan in turn, and
  // the candidates of a source follow the same path: the quads of the last plan and the path edges of
  // the last path are kept until `clear_cache()`.
  const std::vector<Strip_quad>& strip_quads(const Surgery_plan<PolygonMesh>& plan) const
  {
    if(strip_known && plan.path == strip_path && plan.operations == strip_operations) return strip;
    if(!strip_known || plan.path != strip_path)
    {
      strip_path = plan.path;
      strip_edges.assign(plan.path.size(), std::make_pair(GT::null_halfedge(), false));
      strip_edge_known.assign(plan.path.size(), 0);
    }
    strip_operations = plan.operations;
    strip_known = true;
    strip.clear();
    for(std::size_t j = 0; j + 1 < plan.path.size(); ++j)
    {
      const Strip_operation op = plan.operations[j];
      if(op == Strip_operation::NO_OPERATION) continue;
      if(!strip_edge_known[j])
      {
        strip_edges[j] = halfedge(plan.path[j], plan.path[j + 1], pm);
        strip_edge_known[j] = 1;
      }
      if(!strip_edges[j].second) continue;
      const bool left = op == Strip_operation::RIGHT_COLLAPSE || op == Strip_operation::LEFT_SPLIT;
      const halfedge_descriptor h = left ? strip_edges[j].first : opposite(strip_edges[j].first, pm);
      if(is_border(h, pm) || !is_quad(h, pm)) continue;
      const halfedge_descriptor n = next(h, pm), p = prev(h, pm);
      const double along = length(source(h, pm), target(h, pm));
      const double across = 0.5 * (length(source(n, pm), target(n, pm)) + length(source(p, pm), target(p, pm)));
      if(!(along > 0) || !(across > 0)) continue;
      strip.push_back(Strip_quad{ op, face(h, pm), along, across, face_area(face(h, pm)) });
    }
    return strip;
  }

  // the mesh as it was at the start of the batch, by vertex index (-1: a vertex created since)
  int index(vertex_descriptor v) const { return get(stamp, v) == numbering ? get(index_map, v) : -1; }
  // the same, with -1 for null_vertex() too
  int index_or_none(vertex_descriptor v) const { return v == GT::null_vertex() ? -1 : index(v); }
  vertex_descriptor vertex(int i) const { return by_index[std::size_t(i)]; }
  int defect_at(int i) const { return defects[std::size_t(i)]; }
  // interior, on no constrained edge and no protected face
  bool is_passable_at(int i) const { return passable[std::size_t(i)] != 0; }
  int valence_at(int i) const { return adjacency_rows[std::size_t(i)].end - adjacency_rows[std::size_t(i)].begin; }
  const int* neighbors_begin(int i) const { return adjacency.data() + adjacency_rows[std::size_t(i)].begin; }
  const int* neighbors_end(int i) const { return adjacency.data() + adjacency_rows[std::size_t(i)].end; }
  std::size_t number_of_vertices() const { return by_index.size(); }
  /// \endcond

private:

  // whether the labels of vertex i (a beginning of the list of its closest singularities) answer a query:
  // they hold n singularities other than i, x1 and x2, or (`sign` not 0) one of them has a defect of the
  // sign opposite to `sign`
  bool labels_answer(int i, int x1, int x2, std::size_t n, int sign) const
  {
    const std::size_t K = max_nearest_singularities;
    std::size_t others = 0;
    for(std::size_t k = std::size_t(i) * K; k < std::size_t(i) * K + near_labels.count[std::size_t(i)]; ++k)
    {
      const int j = near_labels.source[k];
      if(j == i || j == x1 || j == x2) continue;
      if(defects[std::size_t(j)] * sign < 0) return true;
      ++others;
    }
    return others >= n;
  }

  // makes the labels of vertex i hold at least n singularities other than i, x1 and x2 (or, `sign` not 0,
  // up to the first of them whose defect has the sign opposite to `sign`), or all of its
  // max_nearest_singularities closest ones: ties broken by their rank (the order of begin_batch()), by
  // increasing distance. A breadth-first search from i, level by level, that stops at the first level
  // where enough are known. It gives the same labels as a breadth-first search from all singularities at
  // once, in rank order, in which each vertex keeps the first labels that reach it (a label among the
  // closest of a vertex is among the closest of its predecessor on a shortest path), but it only costs
  // the ball around i that holds them. A search that stopped early is set aside (see stop_nearest()), and
  // continued by a later query at i in the batch that its labels do not answer (see resume_nearest()): the
  // scoring asks about the same vertices with other exclusions and signs.
  void compute_nearest(int i, int x1, int x2, std::size_t n, int sign = 0) const
  {
    if(near_known[std::size_t(i)] == epoch && (near_complete[std::size_t(i)] || labels_answer(i, x1, x2, n, sign))) return;
    if(near_known[std::size_t(i)] != epoch && restore_nearest(i, x1, x2, n, sign)) return;
    std::size_t others = 0;
    if(near_stopped_at[std::size_t(i)] != 0) others = resume_nearest(i, x1, x2);
    else
    {
      near_known[std::size_t(i)] = epoch;
      near_labels.count[std::size_t(i)] = 0;
      near_work[0] = i;
      near_work_size = 1;
      near_mark[std::size_t(i)] |= visited_mark;
      near_levels = Near_levels();
    }
    search_nearest(i, x1, x2, n, sign, others);
  }

  // the levels of the search from vertex i under way, from near_levels.level on (the vertices of that
  // level, from near_levels.begin on, are all in the queue and marked), given the number of the labels of
  // i other than i, x1 and x2; then records the labels (see compute_nearest())
  void search_nearest(int i, int x1, int x2, std::size_t n, int sign, std::size_t others) const
  {
    const std::size_t K = max_nearest_singularities;
    Near_levels& s = near_levels;
    unsigned char& count = near_labels.count[std::size_t(i)];
    bool opposite_found = false;
    int radius = (std::max)(0, s.level - 1); // the last level searched
    bool stopped = false; // at the end of level `radius`, once the labels answered the query
    while(s.begin < near_work_size && count < K && others < n && !opposite_found)
    {
      radius = s.level;
      s.end = near_work_size;
      s.expanded = s.end;
      near_found.clear();
      std::size_t found_others = 0;
      bool last_level = false; // the labels are known at the end of this level: no need for the next one
      for(std::size_t q = s.begin; q < s.end; ++q)
      {
        const int u = queued(near_work.data(), q, near_work_size);
        if((near_mark[std::size_t(u)] & singular_mark) != 0)
        {
          near_found.emplace_back(ranks[std::size_t(u)], u);
          if(u != i && u != x1 && u != x2)
          {
            ++found_others;
            opposite_found = opposite_found || defects[std::size_t(u)] * sign < 0;
          }
          if(!last_level && (count + near_found.size() >= K || others + found_others >= n || opposite_found))
          {
            last_level = true;
            s.expanded = q;
          }
        }
        if(!last_level) expand_nearest(u);
      }
      std::sort(near_found.begin(), near_found.end());
      for(std::size_t k = 0; k < near_found.size() && count < K; ++k, ++count)
      {
        const int j = near_found[k].second;
        near_labels.source[std::size_t(i) * K + count] = j;
        near_labels.distance[std::size_t(i) * K + count] = s.level;
        if(j != i && j != x1 && j != x2) ++others;
      }
      if(last_level) { stopped = true; break; }
      s.previous = s.begin;
      s.begin = s.end;
      ++s.level;
    }
    // else the search stopped with enough, or the ball around i has fewer
    near_complete[std::size_t(i)] = count == K || (others < n && !opposite_found);
    keep_nearest(i, radius);
    stop_nearest(i, stopped);
    unsigned char* mark = near_mark.data();
    for(const int *u = near_work.data(), *end = u + near_work_size; u != end; ++u)
      mark[std::size_t(*u)] &= static_cast<unsigned char>(~visited_mark);
  }

  // the vertex at place q of the queue of a breadth-first search, whose first `size` places are known. It
  // asks the processor for the rows of the vertices a few places further, and for their neighbors a little
  // later: on a large mesh they are seldom in the cache, and waiting for each of them in turn took most of
  // the time of the searches. (The vertex is returned, not only the requests made: GCC 12 drops the calls
  // of a function that only asks for memory.)
  int queued(const int* queue, std::size_t q, std::size_t size) const
  {
#if defined(__GNUC__) || defined(__clang__)
    if(q + 16 < size) __builtin_prefetch(&adjacency_rows[std::size_t(queue[q + 16])]);
    if(q + 8 < size) __builtin_prefetch(neighbors_begin(queue[q + 8]));
#else
    (void)size;
#endif
    return queue[q];
  }

  // appends the neighbors of u not visited yet by the search under way to its queue. Each neighbor is
  // written after the queue, which only grows if it was not visited: no branch to mispredict.
  void expand_nearest(int u) const
  {
    int* queue = near_work.data();
    unsigned char* mark = near_mark.data();
    std::size_t size = near_work_size;
    for(const int *w = neighbors_begin(u), *end = neighbors_end(u); w != end; ++w)
    {
      const unsigned char m = mark[std::size_t(*w)];
      queue[size] = *w;
      size += (m & visited_mark) ^ visited_mark;
      mark[std::size_t(*w)] = m | visited_mark;
    }
    near_work_size = size;
  }

  // keeps the search from vertex i that just ended, if it stopped early with fewer than
  // max_nearest_singularities labels (else its labels answer any query; a search for no singularity at
  // all did not start) and the budget allows: the vertices of its last two levels and those of the next
  // level found so far, all that resume_nearest() needs
  void stop_nearest(int i, bool stopped) const
  {
    const Near_levels& s = near_levels;
    std::size_t k = std::size_t(near_stopped_at[std::size_t(i)]);
    if(k != 0) near_stopped_size -= near_stopped[k - 1].queue.size(); // out of date: replaced or dropped
    near_stopped_at[std::size_t(i)] = 0;
    const std::size_t size = near_work_size - s.previous;
    if(!stopped || near_complete[std::size_t(i)] || near_stopped_size + size > near_stopped_budget()) return;
    if(k == 0)
    {
      if(near_stopped_count == near_stopped.size()) near_stopped.emplace_back();
      k = ++near_stopped_count;
    }
    Near_stopped& e = near_stopped[k - 1];
    e.vertex = i;
    e.queue.assign(near_work.begin() + std::ptrdiff_t(s.previous), near_work.begin() + std::ptrdiff_t(near_work_size));
    e.levels.previous = 0;
    e.levels.begin = s.begin - s.previous;
    e.levels.end = s.end - s.previous;
    e.levels.expanded = s.expanded - s.previous;
    e.levels.level = s.level;
    near_stopped_size += size;
    near_stopped_at[std::size_t(i)] = int(k);
  }

  // the number of vertices the stopped searches of a batch may hold together
  std::size_t near_stopped_budget() const { return 4 * by_index.size() + 1024; }

  // makes the search from vertex i set aside by stop_nearest(), which stopped at the end of level L, the
  // search under way, ready to go on with level L + 1; returns the number of the labels of i other than i, x1 and x2. Going on
  // gives the labels a new search would give:
  // - the labels found so far are the same. They are all the singularities within L edges (fewer than
  //   max_nearest_singularities, else the search would be complete), by distance and rank, whatever the
  //   query: the search stopped at the end of level L, after collecting all of its singularities. And a
  //   new search for this query would not stop before the end of level L: it would stop at the first level
  //   whose singularities answer the query, and labels_answer() found that those within L edges do not.
  // - the vertices of level L + 1 are in the same order: a new search finds them by expanding the vertices
  //   of level L in order; the stopped search expanded those before `expanded`, and this expands the
  //   others, in order.
  // - the vertices marked as visited are those a new search would have marked, as far as the next levels
  //   can see: a neighbor of a vertex at distance d is at distance d - 1, d or d + 1, so the vertices of
  //   level L only meet those of levels L - 1 and on, and those of levels L + 1 and on only those of
  //   levels L and on, all of which were set aside and are marked again.
  // From level L + 1 on, the search then does what a new one does.
  std::size_t resume_nearest(int i, int x1, int x2) const
  {
    const Near_stopped& e = near_stopped[std::size_t(near_stopped_at[std::size_t(i)]) - 1];
    std::copy(e.queue.begin(), e.queue.end(), near_work.begin());
    near_work_size = e.queue.size();
    for(const int u : e.queue) near_mark[std::size_t(u)] |= visited_mark;
    Near_levels& s = near_levels;
    s = e.levels;
    for(std::size_t q = s.expanded; q < s.end; ++q) expand_nearest(near_work[q]);
    s.previous = s.begin;
    s.begin = s.end;
    ++s.level;
    const std::size_t K = max_nearest_singularities;
    std::size_t others = 0;
    for(std::size_t k = std::size_t(i) * K; k < std::size_t(i) * K + near_labels.count[std::size_t(i)]; ++k)
    {
      const int j = near_labels.source[k];
      if(j != i && j != x1 && j != x2) ++others;
    }
    return others;
  }

  // records the labels of vertex i, found by a search of `radius` edges, in `kept`
  void keep_nearest(int i, int radius) const
  {
    const std::size_t K = max_nearest_singularities;
    const vertex_descriptor v = by_index[std::size_t(i)];
    std::size_t k = kept_slot(v);
    if(k == 0)
    {
      if(kept_free.empty()) { kept.emplace_back(); k = kept.size(); }
      else { k = kept_free.back() + 1; kept_free.pop_back(); }
      put(kept_index, v, k);
    }
    Kept& e = kept[k - 1];
    e.owner = v;
    e.position = get(vpm, v);
    e.radius = radius;
    e.complete = near_complete[std::size_t(i)] != 0;
    e.count = near_labels.count[std::size_t(i)];
    for(std::size_t j = 0; j < e.count; ++j)
    {
      e.label[j] = by_index[std::size_t(near_labels.source[std::size_t(i) * K + j])];
      e.label_position[j] = get(vpm, e.label[j]);
      e.distance[j] = near_labels.distance[std::size_t(i) * K + j];
    }
    kept_radius = (std::max)(kept_radius, radius);
  }

  // the labels of vertex i from `kept`, if they are known there, still hold (same vertex and labels at
  // the same places, still singular) and suffice for the query
  bool restore_nearest(int i, int x1, int x2, std::size_t n, int sign) const
  {
    const std::size_t K = max_nearest_singularities;
    const vertex_descriptor v = by_index[std::size_t(i)];
    const std::size_t k = kept_slot(v);
    if(k == 0) return false;
    const Kept& e = kept[k - 1];
    if(!(e.position == get(vpm, v))) return false;
    for(std::size_t j = 0; j < e.count; ++j)
    {
      const int l = index(e.label[j]);
      if(l < 0 || ranks[std::size_t(l)] < 0 || !(e.label_position[j] == get(vpm, e.label[j]))) return false;
    }
    // the labels still hold: they answer the query if the search was complete or if labels_answer() says so
    // (until near_known is stamped, the labels copied here are not read by anything else)
    near_labels.count[std::size_t(i)] = static_cast<unsigned char>(e.count);
    for(std::size_t j = 0; j < e.count; ++j)
    {
      near_labels.source[std::size_t(i) * K + j] = index(e.label[j]);
      near_labels.distance[std::size_t(i) * K + j] = e.distance[j];
    }
    if(!e.complete && !labels_answer(i, x1, x2, n, sign)) return false;
    near_known[std::size_t(i)] = epoch;
    near_complete[std::size_t(i)] = e.complete ? 1 : 0;
    return true;
  }

  // the three closest distinct singularities whose separatrices pass within m_separatrix_radius edges of
  // vertex i (breadth-first, so by increasing distance)
  void closest_separatrices(int i) const
  {
    if(++visit_round == 0) { std::fill(visit.begin(), visit.end(), 0u); visit_round = 1; }
    const std::size_t row = std::size_t(i) * 3;
    unsigned char& count = sep_near.count[std::size_t(i)];
    count = 0;
    sep_near_known[std::size_t(i)] = epoch;
    local_queue.assign(1, i);
    local_level.assign(1, 0);
    visit[std::size_t(i)] = visit_round;
    for(std::size_t q = 0; q < local_queue.size() && count < 3; ++q)
    {
      const int u = local_queue[q];
      for(int k = sep_begin[std::size_t(u)]; k < sep_end[std::size_t(u)] && count < 3; ++k)
      {
        const int o = sep_owner[std::size_t(k)];
        bool known = false;
        for(std::size_t j = 0; j < count; ++j) known = known || sep_near.source[row + j] == o;
        if(known) continue;
        sep_near.source[row + count] = o;
        sep_near.distance[row + count] = local_level[q];
        ++count;
      }
      if(local_level[q] >= m_separatrix_radius) continue;
      for(const int* w = neighbors_begin(u); w != neighbors_end(u); ++w)
      {
        if(visit[std::size_t(*w)] == visit_round) continue;
        visit[std::size_t(*w)] = visit_round;
        local_queue.push_back(*w);
        local_level.push_back(local_level[q] + 1);
      }
    }
  }

  // straight edge lines from every interior singularity, through regular interior vertices, until a
  // singular, border or feature vertex or `m_separatrix_length` edges; (vertex, owner) pairs. At a regular
  // vertex the line leaves by the neighbor opposite to the one it came from (two places further in the
  // neighbors, which are in rotation order).
  void trace_separatrices(const std::vector<vertex_descriptor>& singular,
                          std::vector<std::pair<int, int> >& out) const
  {
    for(vertex_descriptor sv : singular)
    {
      const int s = index(sv);
      if(cut[std::size_t(s)]) continue;
      for(const int* first = neighbors_begin(s); first != neighbors_end(s); ++first)
      {
        int from = s, w = *first;
        for(int len = 0; len < m_separatrix_length; ++len)
        {
          if(w == s) break;
          out.emplace_back(w, s);
          if(defects[std::size_t(w)] != 0 || cut[std::size_t(w)] || valence_at(w) != 4) break;
          const int* nb = neighbors_begin(w);
          const int k = int(std::find(nb, nb + 4, from) - nb);
          from = w;
          w = nb[(k + 2) % 4];
        }
      }
    }
  }
};

} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_SCORING_SCORING_CONTEXT_H
