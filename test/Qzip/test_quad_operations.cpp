// Tests of the two atomic operations (quad collapse, vertex split into a quad) and of preprocessing.
#include "qzip_test_utils.h"

#include <CGAL/Qzip/quad_operations.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/singularities.h>
#include <CGAL/Qzip/quad_quality.h>

#include <CGAL/Random.h>

using namespace qzip_test;
namespace Q = CGAL::Qzip;

template <typename Mesh>
struct Collapse_prediction
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  vertex_descriptor a, b, d;
  int deg_a, deg_b, deg_d;
};

template <typename Mesh>
Collapse_prediction<Mesh> predict_collapse(typename boost::graph_traits<Mesh>::halfedge_descriptor h, const Mesh& m)
{
  Collapse_prediction<Mesh> p;
  p.a = target(h, m);
  p.b = target(next(h, m), m);
  p.d = source(h, m);
  const auto c = target(next(next(h, m), m), m);
  p.deg_a = valence(p.a, m) + valence(c, m) - 2;
  p.deg_b = valence(p.b, m) - 1;
  p.deg_d = valence(p.d, m) - 1;
  return p;
}

/// collapses every collapsible quad of `m` (each on a fresh copy), checks the result and that
/// the split given by the returned delimiters restores an isomorphic mesh with the same positions;
/// then splits back and collapses the new quad again (collapse o split).
template <typename Mesh>
std::size_t exhaustive_collapse_split(const Mesh& m, std::size_t& refused)
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  std::size_t done = 0;
  const long chi = euler_characteristic(m);
  std::vector<halfedge_descriptor> hs(halfedges(m).begin(), halfedges(m).end());
  for(std::size_t i = 0; i < hs.size(); ++i)
  {
    Mesh work;
    copy_mesh(m, work);
    halfedge_descriptor h = *std::next(halfedges(work).begin(), long(i));
    if(is_border(h, work)) continue;
    if(!Q::can_collapse_quad(h, work)) { ++refused; continue; }
    const std::size_t nv = vertices(work).size(), nf = faces(work).size(), ne = edges(work).size();
    const Collapse_prediction<Mesh> p = predict_collapse(h, work);
    std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, Point> pos;
    for(auto v : vertices(work)) pos[v] = get(CGAL::vertex_point, work, v);

    auto delim = Q::quad_collapse(h, work);
    assert(CGAL::is_valid_polygon_mesh(work));
    assert(all_faces_have_degree(work, 4));
    assert(euler_characteristic(work) == chi);
    assert(vertices(work).size() == nv - 1 && faces(work).size() == nf - 1 && edges(work).size() == ne - 2);
    assert(valence(p.a, work) == p.deg_a);
    assert(valence(p.b, work) == p.deg_b);
    assert(valence(p.d, work) == p.deg_d);
    assert(target(delim.first, work) == p.a && target(delim.second, work) == p.a);
    assert(source(delim.first, work) == p.b && source(delim.second, work) == p.d);

    // split o collapse == identity
    assert(Q::can_split_vertex_into_quad(delim.first, delim.second, work));
    halfedge_descriptor back = Q::split_vertex_into_quad(delim, work);
    const auto c_new = target(next(next(back, work), work), work);
    for(auto v : vertices(work))
      if(v != c_new) assert(get(CGAL::vertex_point, work, v) == pos[v]);
    assert(CGAL::is_valid_polygon_mesh(work));
    assert(are_isomorphic(work, m));

    // collapse o split == identity
    Mesh before_collapse;
    copy_mesh(work, before_collapse);
    assert(Q::can_collapse_quad(back, work));
    Q::quad_collapse(back, work);
    assert(CGAL::is_valid_polygon_mesh(work));
    Mesh ref;
    copy_mesh(m, ref);
    Q::quad_collapse(*std::next(halfedges(ref).begin(), long(i)), ref);
    assert(are_isomorphic(work, ref));
    ++done;
  }
  return done;
}

/// every pair of distinct incoming halfedges of every vertex: split, check, collapse back.
template <typename Mesh>
std::size_t exhaustive_split_collapse(const Mesh& m)
{
  std::size_t done = 0;
  const long chi = euler_characteristic(m);
  const std::size_t nh = halfedges(m).size();
  for(std::size_t i = 0; i < nh; ++i)
  {
    Mesh probe;
    copy_mesh(m, probe);
    auto hi = *std::next(halfedges(probe).begin(), long(i));
    std::vector<std::size_t> partners;
    std::size_t k = 0;
    std::map<decltype(hi), std::size_t> index;
    for(auto h : halfedges(probe)) index[h] = k++;
    for(auto h2 : CGAL::halfedges_around_target(hi, probe))
      if(h2 != hi) partners.push_back(index[h2]);
    for(std::size_t j : partners)
    {
      Mesh work;
      copy_mesh(m, work);
      auto h1 = *std::next(halfedges(work).begin(), long(i));
      auto h2 = *std::next(halfedges(work).begin(), long(j));
      if(!Q::can_split_vertex_into_quad(h1, h2, work)) continue;
      const auto v = target(h1, work), b = source(h1, work), d = source(h2, work);
      int between = 0;
      for(auto o = opposite(prev(opposite(h1, work), work), work); o != opposite(h2, work);
          o = opposite(prev(o, work), work))
        ++between;
      const int deg_v = valence(v, work), deg_b = valence(b, work), deg_d = valence(d, work);
      auto q = Q::split_vertex_into_quad(h1, h2, work);
      const auto c = target(next(next(q, work), work), work);
      put(get(CGAL::vertex_point, work), c, get(CGAL::vertex_point, work, v));
      assert(CGAL::is_valid_polygon_mesh(work));
      assert(all_faces_have_degree(work, 4));
      assert(euler_characteristic(work) == chi);
      assert(valence(c, work) == between + 2);
      assert(valence(v, work) == deg_v - between);
      assert(valence(b, work) == deg_b + 1 && valence(d, work) == deg_d + 1);
      assert(Q::can_collapse_quad(q, work));
      Q::quad_collapse(q, work);
      assert(CGAL::is_valid_polygon_mesh(work));
      assert(are_isomorphic(work, m));
      ++done;
    }
  }
  return done;
}

template <typename Mesh>
void test_refusals()
{
  // corner quad: the corner vertex has valence 2, collapsing towards the corner leaves a dangling vertex;
  // in a one-quad-wide strip, opposite corners are both on the border: merging them pinches the mesh.
  std::size_t refused_corner = 0, refused_border_pair = 0;
  Mesh g;
  for(int rows : { 3, 1 })
  {
    make_quad_grid(g, 4, rows);
    for(auto h : halfedges(g))
    {
      if(is_border(h, g)) continue;
      auto b = target(next(h, g), g), d = source(h, g), a = target(h, g);
      auto c = target(next(next(h, g), g), g);
      const bool corner = valence(b, g) == 2 || valence(d, g) == 2;
      const bool both_border = on_border(a, g) && on_border(c, g);
      if(corner) { assert(!Q::can_collapse_quad(h, g)); ++refused_corner; }
      else if(both_border) { assert(!Q::can_collapse_quad(h, g)); ++refused_border_pair; }
      else assert(Q::can_collapse_quad(h, g));
    }
  }
  assert(refused_corner > 0 && refused_border_pair > 0);

  // shared neighbours: on a 4x4 torus after one collapse, the merged vertex sees vertices at distance 2
  // through both sides; collapses that would double an edge or pinch a face must be refused.
  Mesh t;
  make_quad_torus(t, 4, 4);
  Q::quad_collapse(*halfedges(t).begin(), t);
  std::size_t link_refused = 0;
  for(auto h : halfedges(t))
    if(!Q::can_collapse_quad(h, t) && valence(target(next(h, t), t), t) >= 3 && valence(source(h, t), t) >= 3)
      ++link_refused;
  std::cout << "  link-condition refusals on a 4x4 torus: " << link_refused << std::endl;
  assert(link_refused > 0);

  // split preconditions
  auto h = *halfedges(g).begin();
  assert(!Q::can_split_vertex_into_quad(h, h, g));
  assert(!Q::can_split_vertex_into_quad(h, next(h, g), g));
}

/// random collapses and splits on a real mesh with the bookkeeping checked at each step.
template <typename Mesh>
void random_sequence(Mesh& m, std::size_t steps, unsigned seed)
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  CGAL::Random rng(seed);
  const long chi = euler_characteristic(m);
  std::size_t collapses = 0, splits = 0;
  std::vector<halfedge_descriptor> hs;
  for(std::size_t s = 0; s < steps; ++s)
  {
    if(hs.empty() || s % 64 == 0) hs.assign(halfedges(m).begin(), halfedges(m).end());
    const halfedge_descriptor h = hs[rng.get_int(0, int(hs.size()))];
    if(rng.get_bool())
    {
      if(is_border(h, m) || !Q::can_collapse_quad(h, m)) continue;
      const std::size_t nf = faces(m).size();
      const Collapse_prediction<Mesh> p = predict_collapse(h, m);
      Q::quad_collapse(h, m);
      hs.clear();
      assert(faces(m).size() == nf - 1);
      assert(valence(p.a, m) == p.deg_a && valence(p.b, m) == p.deg_b && valence(p.d, m) == p.deg_d);
      ++collapses;
    }
    else
    {
      const halfedge_descriptor h2 = opposite(next(h, m), m);
      halfedge_descriptor h2b = h2;
      const int skip = rng.get_int(0, 3);
      for(int i = 0; i < skip; ++i) h2b = opposite(next(h2b, m), m);
      if(!Q::can_split_vertex_into_quad(h, h2b, m)) continue;
      const std::size_t nf = faces(m).size();
      const auto v = target(h, m);
      auto q = Q::split_vertex_into_quad(h, h2b, m);
      const auto c = target(next(next(q, m), m), m);
      put(get(CGAL::vertex_point, m), c, get(CGAL::vertex_point, m, v));
      hs.clear();
      assert(faces(m).size() == nf + 1);
      ++splits;
    }
    assert(euler_characteristic(m) == chi);
    if(s % 97 == 0) assert(CGAL::is_valid_polygon_mesh(m));
  }
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(collapses > 0 && splits > 0);
}

template <typename Mesh>
void test_atomic_operations()
{
  std::size_t refused = 0, done = 0;
  Mesh g; make_quad_grid(g, 4, 4);
  done += exhaustive_collapse_split(g, refused);
  Mesh t; make_quad_torus(t, 5, 6);
  done += exhaustive_collapse_split(t, refused);
  // next to singularities: plant a v3/v5 pair by one collapse in a torus, then test everything around it
  Mesh s; make_quad_torus(s, 6, 6);
  Q::quad_collapse(*halfedges(s).begin(), s);
  done += exhaustive_collapse_split(s, refused);
  std::size_t splits = exhaustive_split_collapse(g) + exhaustive_split_collapse(s);
  std::cout << "  exhaustive: " << done << " collapses, " << refused << " refused, " << splits << " splits" << std::endl;
  assert(done > 0 && refused > 0 && splits > 0);
  test_refusals<Mesh>();
}

/// interior vertices of valence 2 or >= 6 left in `m`
template <typename Mesh>
std::size_t count_bad_interior_valences(const Mesh& m)
{
  std::size_t n = 0;
  for(auto v : vertices(m))
    if(!on_border(v, m) && (valence(v, m) == 2 || valence(v, m) >= 6)) ++n;
  return n;
}

template <typename Mesh>
void check_preprocess(Mesh& m, const char* what)
{
  const long chi = euler_characteristic(m);
  std::map<std::size_t, std::size_t> degrees;
  for(auto f : faces(m)) ++degrees[CGAL::halfedges_around_face(halfedge(f, m), m).size()];
  const std::size_t nf = faces(m).size(), bad = count_bad_interior_valences(m);
  auto inverted = [&m]()
  {
    std::size_t n = 0;
    for(auto f : faces(m))
      if(CGAL::halfedges_around_face(halfedge(f, m), m).size() == 4 && Q::quad_scaled_jacobian(f, m) <= 0) ++n;
    return n;
  };
  const std::size_t inverted_before = inverted();
  const Q::Preprocess_result r = Q::preprocess_valences(m);
  const std::size_t inverted_after = inverted();
  if(inverted_after > inverted_before)
    std::cout << "  (preprocessing inverted " << inverted_after - inverted_before << " quads)" << std::endl;
  assert(r.converged);
  assert(CGAL::is_valid_polygon_mesh(m));
  assert(euler_characteristic(m) == chi);
  assert(count_bad_interior_valences(m) == 0);
  for(auto v : vertices(m))
    if(on_border(v, m)) assert(Q::vertex_defect(v, m) < 2);
  std::map<std::size_t, std::size_t> after;
  for(auto f : faces(m)) ++after[CGAL::halfedges_around_face(halfedge(f, m), m).size()];
  assert(after[4] == degrees[4] + r.vertex_splits - r.removed_valence_2);
  for(const auto& kv : degrees) if(kv.first != 4) assert(after[kv.first] == kv.second);
  assert(faces(m).size() == nf + r.vertex_splits - r.removed_valence_2);
  std::cout << "  preprocess " << what << ": " << bad << " bad valences, " << r.removed_valence_2
            << " v2 removed, " << r.vertex_splits << " splits" << std::endl;
}

template <typename Mesh>
void test_preprocess_synthetic()
{
  // valence 2: split a grid vertex with an empty fan (the new vertex has valence 2)
  Mesh g; make_quad_grid(g, 6, 6);
  for(auto v : vertices(g))
    if(!on_border(v, g) && get(CGAL::vertex_point, g, v) == Point(3, 3, 0))
    {
      auto h1 = halfedge(v, g), h2 = opposite(next(h1, g), g); // consecutive: empty fan
      auto q = Q::split_vertex_into_quad(h2, h1, g);
      (void)q;
      break;
    }
  assert(count_bad_interior_valences(g) > 0);
  check_preprocess(g, "grid with a valence-2 vertex");
  // a border vertex with four quads on a straight border (defect +2): merge an interior corner into it
  {
    Mesh b; make_quad_grid(b, 6, 6);
    bool planted = false;
    for(auto h : halfedges(b))
      if(!is_border(h, b) && get(CGAL::vertex_point, b, target(h, b)) == Point(3, 0, 0) &&
         get(CGAL::vertex_point, b, target(next(next(h, b), b), b)) == Point(4, 1, 0))
      { Q::quad_collapse(h, b); planted = true; break; }
    assert(planted);
    std::size_t border_plus_2 = 0;
    for(auto v : vertices(b)) if(on_border(v, b) && Q::vertex_defect(v, b) >= 2) ++border_plus_2;
    assert(border_plus_2 == 1);
    check_preprocess(b, "grid with a border defect of +2");
  }
  // protected faces: their vertices are left alone
  {
    Mesh t; make_quad_torus(t, 10, 10);
    auto v = *vertices(t).begin();
    for(auto h : CGAL::halfedges_around_target(halfedge(v, t), t))
      if(Q::can_collapse_quad(h, t)) { Q::quad_collapse(h, t); break; }
    assert(valence(v, t) == 6);
    std::set<typename boost::graph_traits<Mesh>::face_descriptor> protect;
    protect.insert(face(halfedge(v, t), t));
    const Q::Preprocess_result r =
      Q::preprocess_valences(t, Q::parameters::face_is_constrained_map(CGAL::Boolean_property_map<decltype(protect)>(protect)));
    assert(r.vertex_splits == 0 && valence(v, t) == 6);
  }
  // valence 6 to 10: merge quads around one vertex of a torus
  for(int merges = 1; merges <= 4; ++merges)
  {
    Mesh t; make_quad_torus(t, 12, 12);
    auto v = *vertices(t).begin();
    int done = 0;
    for(int guard = 0; guard < 50 && done < merges; ++guard)
      for(auto h : CGAL::halfedges_around_target(halfedge(v, t), t))
      {
        // collapse the quad on the left of h towards v: the face of opposite(h)... take the face of h
        if(is_border(h, t)) continue;
        if(Q::can_collapse_quad(h, t)) { Q::quad_collapse(h, t); ++done; break; }
      }
    assert(valence(v, t) >= 6);
    check_preprocess(t, "torus with a high-valence vertex");
  }
}

int main()
{
  std::cout << "atomic operations, Surface_mesh" << std::endl;
  test_atomic_operations<Surface_mesh>();
  std::cout << "atomic operations, Polyhedron_3" << std::endl;
  test_atomic_operations<Polyhedron>();

  const std::vector<std::string> bundled = { "data/polylap_amo_quad.off", "data/pmp_fandisk_quads.off",
                                             "data/polylap_suzanne_half.obj", "data/trimesh_quadknot.obj" };
  for(const std::string& f : bundled)
  {
    Surface_mesh sm; Polyhedron ph;
    assert(read_mesh(f, sm) && read_mesh(f, ph));
    random_sequence(sm, 3000, 1);
    random_sequence(ph, 1000, 2);
    std::cout << "  random sequence ok: " << f << std::endl;
  }
  test_preprocess_synthetic<Surface_mesh>();
  test_preprocess_synthetic<Polyhedron>();
  for(const std::string& f : { std::string("data/polylap_suzanne_half.obj"), std::string("data/trimesh_target.obj"),
                               CGAL::data_file_path("meshes/spot_quadrangulated.obj"),
                               CGAL::data_file_path("meshes/blub_quadrangulated.obj") })
  {
    Surface_mesh sm; Polyhedron ph;
    assert(read_mesh(f, sm) && read_mesh(f, ph));
    check_preprocess(sm, f.c_str());
    check_preprocess(ph, f.c_str());
  }

  const std::string dir = shared_corpus_dir("random atomic sequences on the shared corpus");
  if(!dir.empty())
    for(const std::string& f : shared_corpus_files())
    {
      Surface_mesh sm;
      assert(read_mesh(dir + "/" + f, sm));
      Surface_mesh copy;
      copy_mesh(sm, copy);
      random_sequence(sm, 2000, 3);
      std::cout << "  random sequence ok: " << f << std::endl;
      check_preprocess(copy, f.c_str());
    }
  return EXIT_SUCCESS;
}
