// libFuzzer harness: reading a mesh + preprocessing + a few random Q-zips + undo.
//
// Input layout: byte 0 chooses the file format (0: OFF, 1: OBJ, 2: PLY, modulo 3), byte 1 seeds the random
// choices, the rest is the file. The file goes through the examples' reader (qzip_example::read_input_mesh,
// any polygon accepted), then preprocess_valences(), then up to 8 random Q-zips recorded in a Qzip_history,
// then undo_qzip() of all of them. One Q-zip in four goes to a border defect +1 when there is one; some
// done Q-zips are undone at once, others by their reverse Q-zip (reverse_qzip(), recorded too). Checked
// (abort on violation): every accepted mesh is a valid polygon mesh; the preprocessing and each Q-zip keep
// a valid polygon mesh with the same Euler characteristic, non-quad faces and border cycles; a refused
// Q-zip leaves the mesh exactly as it was; an undo restores it exactly; a reverse Q-zip gives back the
// Euler characteristic, faces, border and vertex degrees (an isomorphism invariant); undoing everything
// gives back exactly the preprocessed mesh.
//
// Build: cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DBUILD_TESTING=ON -DQZIP_BUILD_FUZZER=ON
//        cmake --build build-fuzz --target fuzz_qzip
// Run:   see .ci/fuzz.sh (short CI run) and test/Qzip/fuzz/README.md (longer runs, regressions).
#include "../../../examples/Qzip/qzip_example_io.h"
#include "qzip_robustness_utils.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/qzip.h>
#include <CGAL/Qzip/singularities.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
namespace Q = CGAL::Qzip;
namespace R = qzip_robustness;

namespace {

// the largest mesh worth fuzzing: keeps each input well under a millisecond
const std::size_t max_vertices = 3000;

void check(bool ok, const char* what)
{
  if(ok) return;
  std::cerr << "fuzz_qzip: violation: " << what << std::endl;
  std::abort();
}

std::string temp_path(int format)
{
  static const char* ext[] = { ".off", ".obj", ".ply" };
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir ? dir : "/tmp") + "/qzip_fuzz_" + std::to_string(::getpid()) + ext[format];
}

// the sorted vertex degrees: equal for isomorphic meshes
std::vector<std::size_t> degree_sequence(const Mesh& m)
{
  std::vector<std::size_t> degrees;
  for(vertex_descriptor v : vertices(m)) degrees.push_back(degree(v, m));
  std::sort(degrees.begin(), degrees.end());
  return degrees;
}

std::vector<vertex_descriptor> border_defects(const Mesh& m)
{
  std::vector<vertex_descriptor> out;
  for(vertex_descriptor v : vertices(m))
    if(CGAL::is_border(v, m) && Q::vertex_defect(v, m) == 1) out.push_back(v);
  return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 2) return 0;
  const int format = data[0] % 3;
  // No input is skipped for its counts: CGAL's OFF and PLY readers allocate for the counts a file declares (element
  // counts, each face or PLY list resized to its count before it is read), an allocation that libFuzzer reports
  // beyond -rss_limit_mb, but the examples' reader refuses every count beyond what the file holds before CGAL
  // sees it (check_file_header(): OFF header counts, binary and ASCII OFF faces, PLY element and list counts).
  std::mt19937 rng(data[1]);
  const std::string path = temp_path(format);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 2), std::streamsize(size - 2));
  }

  Mesh mesh;
  std::string error;
  const bool read = qzip_example::read_input_mesh(path, mesh, error, qzip_example::Accepted_faces::ANY_POLYGON);
  std::remove(path.c_str());
  if(!read)
  {
    check(!error.empty() && error.find('\n') == std::string::npos, "a refusal without a one-line message");
    return 0;
  }
  check(CGAL::is_valid_polygon_mesh(mesh), "the reader accepted an invalid mesh");
  if(vertices(mesh).size() > max_vertices) return 0;

  const R::Shape shape0 = R::shape(mesh);
  Q::preprocess_valences(mesh);
  check(CGAL::is_valid_polygon_mesh(mesh), "preprocess_valences left an invalid mesh");
  check(R::shape(mesh) == shape0, "preprocess_valences changed the Euler characteristic, a non-quad face or the border");

  const auto preprocessed = R::fingerprint(mesh);
  Q::Qzip_history<Mesh> history(mesh);
  for(int attempt = 0; attempt < 8; ++attempt)
  {
    const std::vector<vertex_descriptor> sing = R::singular_interior_vertices(mesh);
    if(sing.size() < 2) break;
    const vertex_descriptor s = sing[rng() % sing.size()];
    vertex_descriptor t = sing[rng() % sing.size()];
    if(rng() % 4 == 0)
    {
      const std::vector<vertex_descriptor> border = border_defects(mesh);
      if(!border.empty()) t = border[rng() % border.size()];
    }
    if(s == t) continue;
    const auto path_st = Q::shortest_surgery_path(mesh, s, t);
    const Q::Surgery_plan<Mesh> plan = Q::plan_qzip(mesh, path_st.empty() ? std::vector<vertex_descriptor>{ s, t } : path_st,
                                                    Q::Strip_operation(rng() % 4));
    if(!plan.is_realizable()) continue;
    const auto before = R::fingerprint(mesh);
    const R::Shape shape_before = R::shape(mesh);
    const std::vector<std::size_t> degrees_before = degree_sequence(mesh);
    const std::size_t recorded = history.size();
    const Q::Qzip_result<Mesh> r = Q::execute_qzip(mesh, plan, history);
    check(CGAL::is_valid_polygon_mesh(mesh), "execute_qzip left an invalid mesh");
    if(!r.is_done())
    {
      check(history.size() == recorded, "a refused Q-zip was recorded");
      check(R::fingerprint(mesh) == before, "a refused Q-zip changed the mesh");
      continue;
    }
    check(history.size() == recorded + 1, "a Q-zip was not recorded");
    check(R::shape(mesh).same_up_to_border_length(shape0),
          "a Q-zip changed the Euler characteristic, a non-quad face or the border");
    const unsigned int choice = rng() % 4;
    if(choice == 0)
    {
      Q::undo_qzip(history);
      check(CGAL::is_valid_polygon_mesh(mesh), "undo_qzip left an invalid mesh");
      check(R::fingerprint(mesh) == before, "undo_qzip did not restore the mesh");
    }
    else if(choice == 1 && r.reverse_status == Q::Reverse_qzip_status::AVAILABLE)
    {
      const Q::Qzip_result<Mesh> back = Q::execute_qzip(mesh, r.reverse_plan, history);
      check(back.is_done(), "an available reverse Q-zip was refused");
      check(CGAL::is_valid_polygon_mesh(mesh), "the reverse Q-zip left an invalid mesh");
      check(R::shape(mesh) == shape_before && degree_sequence(mesh) == degrees_before,
            "the reverse Q-zip did not give back an isomorphic mesh");
    }
  }
  history.undo_all();
  check(CGAL::is_valid_polygon_mesh(mesh), "undoing every Q-zip left an invalid mesh");
  check(R::fingerprint(mesh) == preprocessed, "undoing every Q-zip did not restore the preprocessed mesh");
  return 0;
}
