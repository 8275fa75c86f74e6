// Moves pairs of singularities of a quad mesh by Q-zips.
//
// usage: move_singularity_pair IN OUT [--source V --target W] [--motion 0-3] [--random N] [--seed S] [--json]
//
// The input is preprocessed first (interior valences brought to 3..5). V and W are 0-based vertex indices
// of the preprocessed mesh (the input's own indices when it needed no preprocessing); one of them is an
// interior singularity, the other one too or a border vertex with one quad too many or too few (a border
// defect: the Q-zip then runs from the interior singularity and moves the defect along the border, or
// cancels it). Without them, the closest pair of interior singularities is moved; with --random N, N random
// realizable Q-zips between nearby singularities (border defects included) are performed. --motion picks the initial compass operation (0 LS, 1 RC, 2 LC,
// 3 RS); by default the first realizable one. OUT is written atomically; the input is never overwritten.

#include "qzip_example_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/singularities.h>

#include <cstdlib>
#include <deque>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Vertex_index                                  Vertex;
namespace Q = CGAL::Qzip;

static const char* usage =
  "usage: move_singularity_pair IN OUT [--source V --target W] [--motion 0-3] [--random N] [--seed S] [--json]";

// interior v3 and v5, and border vertices with one quad too few (b-) or too many (b+)
struct Singularity_count { std::size_t v3 = 0, v5 = 0, border_minus = 0, border_plus = 0; };

Singularity_count count_singularities(const Mesh& m)
{
  Singularity_count c;
  for(Vertex v : vertices(m))
  {
    if(CGAL::is_border(v, m))
    {
      const int d = Q::vertex_defect(v, m);
      if(d < 0) c.border_minus += std::size_t(-d);
      else c.border_plus += std::size_t(d);
      continue;
    }
    const std::size_t d = Q::vertex_valence(v, m);
    if(d == 3) ++c.v3;
    else if(d == 5) ++c.v5;
  }
  return c;
}

// an interior singularity: a Q-zip may start or end there
bool is_singular(Vertex v, const Mesh& m)
{
  const std::size_t d = Q::vertex_valence(v, m);
  return !CGAL::is_border(v, m) && (d == 3 || d == 5);
}

// a border vertex with one quad too many or too few: a Q-zip may end there (plan_qzip() refuses it when
// the border is not straight there, or when a -1 is not reached along the border)
bool is_border_end(Vertex v, const Mesh& m)
{
  return CGAL::is_border(v, m) && std::abs(Q::vertex_defect(v, m)) == 1;
}

// the interior singularities (and, with `border`, the border targets) within `radius` edges of `s`,
// closest first
std::vector<Vertex> nearby_singularities(const Mesh& m, Vertex s, int radius, bool border = false)
{
  std::map<Vertex, int> dist;
  std::deque<Vertex> queue(1, s);
  dist[s] = 0;
  std::vector<Vertex> out;
  while(!queue.empty())
  {
    const Vertex v = queue.front(); queue.pop_front();
    if(v != s && (is_singular(v, m) || (border && is_border_end(v, m)))) out.push_back(v);
    if(dist[v] == radius) continue;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
      if(dist.emplace(source(h, m), dist[v] + 1).second) queue.push_back(source(h, m));
  }
  return out;
}

struct Operation_report
{
  std::size_t source, target, path_length = 0, collapses = 0, splits = 0;
  int motion = -1;
  Singularity_count before, after;
  std::string status;
};

// tries the given motion, or all four in order; returns the report of the first done (or the last refusal)
Operation_report move_pair(Mesh& m, Vertex s, Vertex t, int motion)
{
  Operation_report rep;
  rep.source = std::size_t(s);
  rep.target = std::size_t(t);
  rep.before = count_singularities(m);
  const std::vector<Vertex> path = Q::shortest_surgery_path(m, s, t);
  rep.path_length = path.empty() ? 0 : path.size() - 1;
  rep.status = "no surgery path";
  for(int mo = (motion < 0 ? 0 : motion); !path.empty() && mo < (motion < 0 ? 4 : motion + 1); ++mo)
  {
    rep.motion = mo;
    const Q::Surgery_plan<Mesh> plan = Q::plan_qzip(m, path, Q::Strip_operation(mo));
    if(!plan.is_realizable()) { rep.status = Q::describe(plan.status); continue; }
    const Q::Qzip_result<Mesh> r = Q::execute_qzip(m, plan);
    if(!r.is_done()) { rep.status = Q::describe(r.status); continue; }
    rep.status = "done";
    rep.collapses = r.number_of_collapses;
    rep.splits = r.number_of_splits;
    break;
  }
  rep.after = count_singularities(m);
  return rep;
}

void print(const Operation_report& r, bool json, bool first)
{
  if(json)
  {
    std::cout << (first ? "" : ",\n") << "    {\"source\": " << r.source << ", \"target\": " << r.target
              << ", \"motion\": " << r.motion << ", \"path_length\": " << r.path_length
              << ", \"collapses\": " << r.collapses << ", \"splits\": " << r.splits
              << ", \"v3_before\": " << r.before.v3 << ", \"v5_before\": " << r.before.v5
              << ", \"border_minus_before\": " << r.before.border_minus << ", \"border_plus_before\": " << r.before.border_plus
              << ", \"v3_after\": " << r.after.v3 << ", \"v5_after\": " << r.after.v5
              << ", \"border_minus_after\": " << r.after.border_minus << ", \"border_plus_after\": " << r.after.border_plus
              << ", \"status\": \"" << r.status << "\"}";
    return;
  }
  static const char* names[] = { "LS", "RC", "LC", "RS" };
  std::cout << "pair " << r.source << " -> " << r.target << ", motion " << (r.motion >= 0 ? names[r.motion] : "-")
            << ", path of " << r.path_length << " edges: " << r.status;
  if(r.status == "done")
    std::cout << " (" << r.collapses << " collapses, " << r.splits << " splits)";
  std::cout << "; singularities " << r.before.v3 << " v3 + " << r.before.v5 << " v5 -> "
            << r.after.v3 << " v3 + " << r.after.v5 << " v5";
  if(r.before.border_minus + r.before.border_plus + r.after.border_minus + r.after.border_plus > 0)
    std::cout << ", border defects " << r.before.border_minus << " b- + " << r.before.border_plus << " b+ -> "
              << r.after.border_minus << " b- + " << r.after.border_plus << " b+";
  std::cout << "\n";
}

bool parse_index(const std::string& text, long& value)
{
  std::istringstream in(text);
  return (in >> value) && in.eof() && value >= 0;
}

int main(int argc, char** argv)
{
  const std::set<std::string> with_value = { "--source", "--target", "--motion", "--random", "--seed" };
  const std::string bad = qzip_example::unknown_option(argc, argv, { "--json", "--help", "-h" }, with_value);
  if(qzip_example::has_flag(argc, argv, "--help") || qzip_example::has_flag(argc, argv, "-h"))
  { std::cout << usage << "\n"; return EXIT_SUCCESS; }
  const std::vector<std::string> files = qzip_example::positional_arguments(argc, argv, with_value);
  if(!bad.empty()) { std::cerr << "error: unknown option '" << bad << "' (" << usage << ")" << std::endl; return EXIT_FAILURE; }
  if(files.size() != 2) { std::cerr << "error: expected IN and OUT (" << usage << ")" << std::endl; return EXIT_FAILURE; }

  long source = -1, target = -1, motion = -1, random = 0, seed = 0;
  const std::string vs = qzip_example::option_value(argc, argv, "--source");
  const std::string vt = qzip_example::option_value(argc, argv, "--target");
  const std::string vm = qzip_example::option_value(argc, argv, "--motion");
  const std::string vr = qzip_example::option_value(argc, argv, "--random");
  const std::string vseed = qzip_example::option_value(argc, argv, "--seed");
  if((!vs.empty() && !parse_index(vs, source)) || (!vt.empty() && !parse_index(vt, target)) ||
     (!vm.empty() && (!parse_index(vm, motion) || motion > 3)) || (!vr.empty() && !parse_index(vr, random)) ||
     (!vseed.empty() && !parse_index(vseed, seed)))
  { std::cerr << "error: option values must be non-negative integers, --motion 0 to 3 (" << usage << ")" << std::endl; return EXIT_FAILURE; }
  if((source < 0) != (target < 0))
  { std::cerr << "error: --source and --target go together" << std::endl; return EXIT_FAILURE; }
  if(source >= 0 && random > 0)
  { std::cerr << "error: --random cannot be combined with --source/--target" << std::endl; return EXIT_FAILURE; }

  Mesh mesh;
  std::string error;
  if(!qzip_example::read_input_mesh(files[0], mesh, error, qzip_example::Accepted_faces::TRIANGLES_AND_QUADS))
  { std::cerr << "error: " << error << std::endl; return EXIT_FAILURE; }
  if(qzip_example::same_file(files[0], files[1]))
  { std::cerr << "error: output '" << files[1] << "' is the input file; refusing to overwrite it" << std::endl; return EXIT_FAILURE; }

  const Q::Preprocess_result pre = Q::preprocess_valences(mesh);
  mesh.collect_garbage();
  const bool json = qzip_example::has_flag(argc, argv, "--json");
  if(!json && (pre.removed_valence_2 + pre.vertex_splits) > 0)
    std::cout << "preprocessing: " << pre.removed_valence_2 << " valence-2 vertices removed, "
              << pre.vertex_splits << " vertex splits\n";

  std::vector<Operation_report> reports;
  if(source >= 0)
  {
    if(std::size_t(source) >= num_vertices(mesh) || std::size_t(target) >= num_vertices(mesh) || source == target)
    { std::cerr << "error: --source/--target must be two distinct vertex indices below " << num_vertices(mesh) << std::endl; return EXIT_FAILURE; }
    const Vertex s(static_cast<Mesh::size_type>(source)), t(static_cast<Mesh::size_type>(target));
    if(!(is_singular(s, mesh) && (is_singular(t, mesh) || is_border_end(t, mesh))) &&
       !(is_border_end(s, mesh) && is_singular(t, mesh)))
    { std::cerr << "error: one of --source/--target must be an interior vertex of valence 3 or 5 (after preprocessing), the other one too or a border vertex with one quad too many or too few" << std::endl; return EXIT_FAILURE; }
    reports.push_back(move_pair(mesh, s, t, int(motion)));
  }
  else if(random > 0)
  {
    CGAL::Random rng(static_cast<unsigned int>(seed));
    std::size_t attempts = 0;
    while(long(reports.size()) < random && attempts < std::size_t(50 * random))
    {
      ++attempts;
      std::vector<Vertex> sing;
      for(Vertex v : vertices(mesh)) if(is_singular(v, mesh)) sing.push_back(v);
      if(sing.size() < 2) break;
      const Vertex s = sing[std::size_t(rng.get_int(0, int(sing.size())))];
      const std::vector<Vertex> near = nearby_singularities(mesh, s, rng.get_int(1, 12), true);
      if(near.empty()) continue;
      const Vertex t = near[std::size_t(rng.get_int(0, int(near.size())))];
      const Operation_report r = move_pair(mesh, s, t, motion >= 0 ? int(motion) : rng.get_int(0, 4));
      if(r.status == "done") reports.push_back(r);
    }
    if(long(reports.size()) < random)
      std::cerr << "warning: only " << reports.size() << " of " << random << " random Q-zips were realizable" << std::endl;
  }
  else
  {
    // the closest pair of interior singularities
    Vertex best_s, best_t;
    std::size_t best = std::size_t(-1);
    for(Vertex v : vertices(mesh))
    {
      if(!is_singular(v, mesh)) continue;
      const std::vector<Vertex> near = nearby_singularities(mesh, v, 8);
      if(near.empty()) continue;
      const std::size_t d = Q::shortest_surgery_path(mesh, v, near.front()).size();
      if(d > 1 && d < best) { best = d; best_s = v; best_t = near.front(); }
    }
    if(best == std::size_t(-1))
    { std::cerr << "error: no pair of interior singularities within 8 edges of each other" << std::endl; return EXIT_FAILURE; }
    reports.push_back(move_pair(mesh, best_s, best_t, int(motion)));
  }

  if(random == 0 && reports.back().status != "done")
  {
    std::cerr << "error: the Q-zip of " << reports.back().source << " and " << reports.back().target
              << " is not realizable: " << reports.back().status << "; nothing written" << std::endl;
    return EXIT_FAILURE;
  }
  if(!qzip_example::write_output_mesh_atomically(files[1], mesh, error, files[0]))
  { std::cerr << "error: " << error << std::endl; return EXIT_FAILURE; }

  if(json) std::cout << "{\n  \"input\": \"" << files[0] << "\",\n  \"output\": \"" << files[1] << "\",\n  \"operations\": [\n";
  for(std::size_t i = 0; i < reports.size(); ++i) print(reports[i], json, i == 0);
  if(json) std::cout << "\n  ]\n}\n";
  if(!json) std::cout << reports.size() << " Q-zip(s) done, written to " << files[1] << "\n";
  return EXIT_SUCCESS;
}
