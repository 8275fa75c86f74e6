// Stress run of the Q-zip primitive: on each mesh, COUNT random Q-zips (random pair of singularities, random
// motion; one in four targets a border defect +1 when the mesh has one, and one in four follows a path that
// runs along the border when the mesh has one, see qzip_test::path_along_border()), with random undos and a
// full unwind whenever DEPTH Q-zips are stacked, all checked:
//  * a refused Q-zip leaves the mesh exactly as it was (geometry hash over faces and points);
//  * a done Q-zip leaves a valid polygon mesh with the same Euler characteristic, non-quad faces and border
//    (a Q-zip to a border defect may lengthen its border cycle by one edge, never change the cycles);
//  * every undo gives back exactly the mesh before the Q-zip, and the full unwind the preprocessed mesh;
//  * every Q-zip to a border defect has a reverse Q-zip unless it cancelled singularities (or, rarely, its
//    clean-up cannot be undone first); the reverse gives back a mesh isomorphic to the one before the
//    Q-zip, and is recorded in the history and undone at once, which gives back exactly the mesh after it;
//  * no exception escapes.
// Reports per mesh: Q-zips tried, done, refused (by the planner / at execution), border defects moved and
// reversed, undone, invariant
// violations, time, resident memory after the mesh and the peak resident memory of the process.
//
// With --homotopy P, instead: homotopy invariance (qzip_test::compare_homotopic_paths(), as in test_qzip) on
// P random pairs of singularities per mesh, each with a shortest path and a copy swept over one to six
// regular quads, every motion on both, once with the sweeps kept away from the other singularities (the
// faces around the swept quads hold none) and once without; reports the pairs of done Q-zips that are
// isomorphic and those that are not (those arriving at a v5 by a U-turn around one quad apart).
//
// Usage: stress_qzip [--count N] [--seed S] [--depth D] [--check-every K] [--homotopy P] [PATH...]
//   PATH: mesh files or directories (default: test/Qzip/data/bad/ and test/Qzip/data/); N defaults to 100000
//   per mesh; full validity checks (CGAL::is_valid_polygon_mesh) run every K done Q-zips (default 1).
// Exit code 1 if any violation was found (with --homotopy: if a pair kept away from other singularities
// gave different meshes).
#include "../../examples/Qzip/qzip_example_io.h"
#include "qzip_robustness_utils.h"
#include "qzip_test_utils.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/singularities.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
namespace Q = CGAL::Qzip;
namespace R = qzip_robustness;

namespace {

struct Stats
{
  std::string name;
  std::size_t vertices = 0, faces = 0, singular = 0;
  long tried = 0, done = 0, done_to_border = 0, done_along_border = 0, refused_plan = 0, refused_execution = 0, undone = 0, violations = 0;
  long border_moves_reversed = 0;
  double seconds = 0;
  long rss_kb = 0;
  std::string status;
};

long peak_rss_kb()
{
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

long current_rss_kb()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

std::vector<std::string> expand(const std::string& path)
{
  std::vector<std::string> out;
  struct stat st;
  if(::stat(path.c_str(), &st) != 0) return out;
  if(!S_ISDIR(st.st_mode)) { out.push_back(path); return out; }
  if(DIR* d = ::opendir(path.c_str()))
  {
    while(dirent* e = ::readdir(d))
    {
      const std::string n = e->d_name;
      const std::string::size_type dot = n.find_last_of('.');
      const std::string ext = dot == std::string::npos ? "" : n.substr(dot);
      if(n[0] == '.' || ext == ".md") continue;
      const std::string full = path + "/" + n;
      if(::stat(full.c_str(), &st) == 0 && S_ISREG(st.st_mode)) out.push_back(full);
    }
    ::closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string base_name(const std::string& p)
{
  const std::string::size_type s = p.find_last_of('/');
  return s == std::string::npos ? p : p.substr(s + 1);
}

Stats stress(const std::string& file, long count, unsigned seed, std::size_t depth, long check_every)
{
  Stats st;
  st.name = base_name(file);
  Mesh mesh;
  std::string error;
  if(!qzip_example::read_input_mesh(file, mesh, error, qzip_example::Accepted_faces::ANY_POLYGON))
  {
    st.status = "refused: " + error.substr(0, 60);
    st.rss_kb = current_rss_kb();
    return st;
  }
  CGAL::Real_timer timer;
  timer.start();
  Q::preprocess_valences(mesh);
  mesh.collect_garbage();
  const R::Shape shape0 = R::shape(mesh);
  const std::uint64_t baseline = R::geometry_hash(mesh);
  st.vertices = vertices(mesh).size();
  st.faces = faces(mesh).size();
  st.singular = R::singular_interior_vertices(mesh).size();
  std::mt19937 rng(seed);
  Q::Qzip_history<Mesh> history(mesh);
  std::vector<std::uint64_t> stacked; // hash of the mesh before each recorded Q-zip
  auto violation = [&](const char* what)
  {
    if(st.violations < 5) std::cerr << st.name << ": violation after " << st.tried << " Q-zips: " << what << std::endl;
    ++st.violations;
  };
  // the number of border halfedges before the first stacked Q-zip and after each: a Q-zip to a border
  // defect adds one, the others none
  std::vector<std::size_t> border_lengths(1, shape0.border_halfedges);
  auto undo_last = [&]()
  {
    Q::undo_qzip(history);
    border_lengths.pop_back();
    ++st.undone;
    if(R::geometry_hash(mesh) != stacked.back()) violation("an undo did not restore the mesh");
    stacked.pop_back();
  };
  long done_since_check = 0;
  try
  {
    for(long i = 0; i < count; ++i)
    {
      const std::vector<vertex_descriptor> sing = R::singular_interior_vertices(mesh);
      if(sing.size() < 2) { st.status = "fewer than 2 singularities"; break; }
      ++st.tried;
      const vertex_descriptor s = sing[rng() % sing.size()];
      vertex_descriptor t = sing[rng() % sing.size()];
      const unsigned kind = unsigned(rng() % 4); // 0: to a border defect, 1: along the border, else inside
      if(kind == 0)
      {
        std::vector<vertex_descriptor> border_defects;
        for(vertex_descriptor v : vertices(mesh))
          if(CGAL::is_border(v, mesh) && Q::vertex_defect(v, mesh) == 1) border_defects.push_back(v);
        if(!border_defects.empty()) t = border_defects[rng() % border_defects.size()];
      }
      const Q::Strip_operation op = Q::Strip_operation(rng() % 4);
      std::vector<vertex_descriptor> path;
      if(kind == 1 && shape0.border_halfedges > 0)
      {
        const int steps = 1 + int(rng() % 6);
        path = qzip_test::path_along_border(mesh, s, steps, rng() % 2 == 0, 8);
      }
      const bool along_border = !path.empty();
      if(along_border) t = path.back();
      else if(s == t) { ++st.refused_plan; continue; }
      else path = Q::shortest_surgery_path(mesh, s, t);
      if(path.empty()) { ++st.refused_plan; continue; }
      const Q::Surgery_plan<Mesh> plan = Q::plan_qzip(mesh, path, op);
      if(!plan.is_realizable()) { ++st.refused_plan; continue; }
      const std::uint64_t before = R::geometry_hash(mesh);
      const std::size_t recorded = history.size();
      const bool border_target = static_cast<bool>(CGAL::is_border(t, mesh));
      Mesh copy_before; // to check the reverse of a Q-zip to a border defect
      if(border_target) qzip_test::copy_mesh(mesh, copy_before);
      const Q::Qzip_result<Mesh> r = Q::execute_qzip(mesh, plan, history);
      if(!r.is_done())
      {
        ++st.refused_execution;
        if(history.size() != recorded) violation("a refused Q-zip was recorded");
        if(R::geometry_hash(mesh) != before) violation("a refused Q-zip changed the mesh");
        continue;
      }
      ++st.done;
      if(history.size() != recorded + 1) violation("a Q-zip was not recorded");
      stacked.push_back(before);
      if(++done_since_check >= check_every)
      {
        done_since_check = 0;
        if(!CGAL::is_valid_polygon_mesh(mesh)) violation("a Q-zip left an invalid mesh");
      }
      const R::Shape now = R::shape(mesh);
      const std::size_t added = now.border_halfedges - border_lengths.back();
      if(!now.same_up_to_border_length(shape0) || now.border_halfedges < border_lengths.back() ||
         added > (border_target ? 1u : 0u))
        violation("a Q-zip changed the Euler characteristic, a non-quad face or the border");
      if(border_target)
      {
        ++st.done_to_border;
        if(r.reverse_status == Q::Reverse_qzip_status::AVAILABLE)
        {
          // the reverse Q-zip, recorded and undone at once
          const std::uint64_t after = R::geometry_hash(mesh);
          const Q::Qzip_result<Mesh> back = Q::execute_qzip(mesh, r.reverse_plan, history);
          if(!back.is_done())
            violation(("a reverse Q-zip rolled back: " + std::string(Q::describe(back.failure))).c_str());
          else if(!qzip_test::are_isomorphic(mesh, copy_before)) violation("a reverse Q-zip did not restore the mesh");
          if(back.is_done())
          {
            ++st.border_moves_reversed;
            Q::undo_qzip(history);
            if(R::geometry_hash(mesh) != after) violation("the undo of a reverse Q-zip did not restore the mesh");
          }
        }
        else if(r.reverse_status != Q::Reverse_qzip_status::SINGULARITIES_CANCELLED &&
                r.reverse_status != Q::Reverse_qzip_status::CLEANED_UP)
          violation("a Q-zip to a border defect has no reverse Q-zip");
      }
      if(along_border) ++st.done_along_border;
      border_lengths.push_back(now.border_halfedges);
      if(rng() % 3 == 0) undo_last();
      if(stacked.size() >= depth)
      {
        while(!stacked.empty()) undo_last();
        if(R::geometry_hash(mesh) != baseline) violation("the full unwind did not restore the preprocessed mesh");
      }
    }
    while(!stacked.empty()) undo_last();
    if(!CGAL::is_valid_polygon_mesh(mesh)) violation("the final mesh is invalid");
    if(R::geometry_hash(mesh) != baseline) violation("the final unwind did not restore the preprocessed mesh");
  }
  catch(const std::exception& e)
  {
    violation("an exception escaped");
    std::cerr << st.name << ": " << e.what() << std::endl;
  }
  st.seconds = timer.time();
  st.rss_kb = current_rss_kb();
  if(st.status.empty()) st.status = "ok";
  return st;
}

// the --homotopy run on one mesh: returns false when the mesh cannot be read
bool homotopy(const std::string& file, std::size_t pairs, unsigned seed, qzip_test::Homotopy_counts& kept_away,
              qzip_test::Homotopy_counts& anywhere)
{
  Mesh mesh;
  std::string error;
  if(!qzip_example::read_input_mesh(file, mesh, error, qzip_example::Accepted_faces::ANY_POLYGON)) return false;
  Q::preprocess_valences(mesh);
  mesh.collect_garbage();
  auto nothing = [](Mesh&, const Q::Surgery_plan<Mesh>&) {};
  qzip_test::compare_homotopic_paths(mesh, base_name(file), pairs, seed, true, kept_away, nothing);
  qzip_test::compare_homotopic_paths(mesh, base_name(file), pairs, seed, false, anywhere, nothing);
  return true;
}

int homotopy_run(const std::vector<std::string>& files, std::size_t pairs, unsigned seed)
{
  std::cout << "stress_qzip --homotopy: " << files.size() << " files, " << pairs << " pairs of singularities per mesh, seed "
            << seed << "\n\n| mesh | sweeps | done | isomorphic | of which U-turn arrivals | different | of which U-turn arrivals |\n"
            << "|---|---|---|---|---|---|---|" << std::endl;
  qzip_test::Homotopy_counts total[2];
  CGAL::Real_timer timer;
  timer.start();
  for(const std::string& f : files)
  {
    qzip_test::Homotopy_counts h[2];
    if(!homotopy(f, pairs, seed++, h[0], h[1])) continue;
    for(int k = 0; k < 2; ++k)
    {
      std::cout << "| " << base_name(f) << " | " << (k == 0 ? "kept away" : "anywhere") << " | " << h[k].done << " | "
                << h[k].isomorphic << " | " << h[k].u_turn_isomorphic << " | " << h[k].differing << " | "
                << h[k].u_turn_differing << " |" << std::endl;
      total[k] += h[k];
    }
  }
  for(int k = 0; k < 2; ++k)
    std::cout << "\n" << (k == 0 ? "kept away from other singularities" : "anywhere") << ": " << total[k].isomorphic
              << " pairs isomorphic (" << total[k].u_turn_isomorphic << " U-turn arrivals), " << total[k].differing
              << " different (" << total[k].u_turn_differing << " U-turn arrivals)";
  std::cout << "; " << std::setprecision(1) << std::fixed << timer.time() << " s" << std::endl;
  return total[0].differing == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace

int main(int argc, char** argv)
{
  const std::set<std::string> with_value = { "--count", "--seed", "--depth", "--check-every", "--homotopy" };
  const std::string bad = qzip_example::unknown_option(argc, argv, { "--help", "-h" }, with_value);
  if(!bad.empty() || qzip_example::has_flag(argc, argv, "--help") || qzip_example::has_flag(argc, argv, "-h"))
  {
    std::cerr << (bad.empty() ? "" : "error: unknown option '" + bad + "'; ")
              << "usage: stress_qzip [--count N] [--seed S] [--depth D] [--check-every K] [--homotopy P] [PATH...]" << std::endl;
    return bad.empty() ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  long count = 100000, check_every = 1, homotopy_pairs = 0;
  unsigned long seed = 1, depth = 16;
  try
  {
    count = std::stol(qzip_example::option_value(argc, argv, "--count", "100000"));
    seed = std::stoul(qzip_example::option_value(argc, argv, "--seed", "1"));
    depth = std::stoul(qzip_example::option_value(argc, argv, "--depth", "16"));
    check_every = std::stol(qzip_example::option_value(argc, argv, "--check-every", "1"));
    homotopy_pairs = std::stol(qzip_example::option_value(argc, argv, "--homotopy", "0"));
  }
  catch(const std::exception&)
  {
    std::cerr << "error: option values must be integers" << std::endl;
    return EXIT_FAILURE;
  }
  if(count < 0 || depth < 1 || check_every < 1 || homotopy_pairs < 0)
  {
    std::cerr << "error: --count and --homotopy must be >= 0, --depth and --check-every >= 1" << std::endl;
    return EXIT_FAILURE;
  }

  std::vector<std::string> paths = qzip_example::positional_arguments(argc, argv, with_value);
  if(paths.empty())
  {
    // the repository root, from this file's location: benchmark/Qzip/stress_qzip.cpp
    std::string root = __FILE__;
    for(int up = 0; up < 3; ++up) root = root.substr(0, root.find_last_of('/') == std::string::npos ? 0 : root.find_last_of('/'));
    if(root.empty()) root = ".";
    paths = { root + "/test/Qzip/data/bad", root + "/test/Qzip/data" };
  }
  std::vector<std::string> files;
  for(const std::string& p : paths)
  {
    const std::vector<std::string> f = expand(p);
    if(f.empty()) { std::cerr << "error: no mesh file at '" << p << "'" << std::endl; return EXIT_FAILURE; }
    files.insert(files.end(), f.begin(), f.end());
  }

  if(homotopy_pairs > 0) return homotopy_run(files, std::size_t(homotopy_pairs), unsigned(seed));

  std::cout << "stress_qzip: " << files.size() << " files, " << count << " random Q-zips per mesh, seed " << seed << ", unwind depth " << depth
            << ", validity check every " << check_every << " done Q-zip(s)\n\n"
            << "| mesh | V | F | singular | tried | done | done to a border defect | of which reversed | done along the border | refused (plan) | refused (execution) | undone | violations | time (s) | RSS after (MiB) | status |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|" << std::endl;
  long files_tried = 0, loaded = 0, tried = 0, done = 0, done_to_border = 0, reversed = 0, done_along_border = 0, refused = 0, undone = 0, violations = 0;
  std::vector<std::string> refused_names;
  double seconds = 0;
  for(const std::string& f : files)
  {
    ++files_tried;
    const Stats s = stress(f, count, unsigned(seed), std::size_t(depth), check_every);
    if(s.vertices == 0) { refused_names.push_back(s.name); continue; }
    ++loaded;
    tried += s.tried; done += s.done; done_to_border += s.done_to_border; reversed += s.border_moves_reversed; done_along_border += s.done_along_border; refused += s.refused_plan + s.refused_execution; undone += s.undone;
    violations += s.violations;
    seconds += s.seconds;
    std::cout << "| " << s.name << " | " << s.vertices << " | " << s.faces << " | " << s.singular << " | " << s.tried
              << " | " << s.done << " | " << s.done_to_border << " | " << s.border_moves_reversed << " | " << s.done_along_border << " | " << s.refused_plan << " | " << s.refused_execution << " | " << s.undone << " | "
              << s.violations << " | " << std::fixed << std::setprecision(1) << s.seconds << " | "
              << std::setprecision(1) << double(s.rss_kb) / 1024. << " | " << s.status << " |" << std::endl;
  }
  if(!refused_names.empty())
  {
    std::cout << "\nrefused by the reader (" << refused_names.size() << "):";
    for(const std::string& n : refused_names) std::cout << " " << n;
    std::cout << std::endl;
  }
  std::cout << "\nfiles tried " << files_tried << ", meshes stressed " << loaded << ", Q-zips tried " << tried
            << ", done " << done << " (" << done_to_border << " to a border defect, " << reversed
            << " of them reversed by their reverse Q-zip, " << done_along_border
            << " along the border), refused " << refused << ", undone " << undone << ", invariant violations "
            << violations << ", crashes 0; " << std::setprecision(1) << seconds << " s; peak RSS "
            << double(peak_rss_kb()) / 1024. << " MiB" << std::endl;
  return violations == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
