// The library on the bad-input corpus (data/bad/, see its README.md): every file is read with
// CGAL::IO::read_polygon_mesh() into a Surface_mesh and a Polyhedron_3; files listed as `accept` must load
// and files listed as `reject` must not. Every mesh that loads as a valid polygon mesh (whatever the README
// says) goes through the mesh report, preprocess_valences(), shortest_surgery_path(), plan_qzip(),
// execute_qzip() with a Qzip_history, undo_qzip() and qzip(), before and after preprocessing.
// Checked: nothing crashes; a call that refuses (a status, or a CGAL precondition exception) leaves the
// mesh exactly as it was; a call that succeeds leaves a valid polygon mesh with the same Euler
// characteristic, face degrees and border; an undo restores the mesh exactly.
// Usage: test_bad_input [DIR] (default data/bad).
#include "qzip_test_utils.h"
#include "qzip_robustness_utils.h"
#include "../../examples/Qzip/qzip_example_io.h" // the examples' input checks

#include <CGAL/Qzip/mesh_report.h>
#include <CGAL/Qzip/preprocess.h>
#include <CGAL/Qzip/qzip.h>

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <stdexcept>

#include <dirent.h>
#include <unistd.h>

using namespace qzip_test;
namespace Q = CGAL::Qzip;

namespace {

struct Counters
{
  int files = 0, loaded = 0, refused_to_load = 0;
  int preprocess_runs = 0, preprocess_refused = 0;
  int plans = 0, plans_refused = 0, executed = 0, execution_refused = 0, undone = 0, noop_executions = 0;
  int preconditions = 0; // CGAL preconditions that reported a bad argument (mesh left unchanged)
};
Counters counters;

/// reads `path` into `m`; `false` if the reader refuses it (or throws, e.g. std::bad_alloc). Two checks of the
/// examples' reader come first, because CGAL 5.5's readers misbehave on such files: OBJ and PLY face indices
/// are not checked (OBJ even turns index 0 and n+1 into n) and the builder reads past its vertex array;
/// OFF and PLY header counts are reserved before reading (an abort under AddressSanitizer on absurd counts).
template <typename Mesh>
bool read_file(const std::string& path, Mesh& m)
{
  clear(m);
  struct stat st;
  std::string error;
  if(::stat(path.c_str(), &st) != 0) return false;
  if(!qzip_example::check_file_header(path, std::uintmax_t(st.st_size), error)) return false;
  if(!qzip_example::face_indices_in_range(path, error)) return false;
  try
  {
    return CGAL::IO::read_polygon_mesh(path, m);
  }
  catch(const std::bad_alloc&) { return false; }
  catch(const std::exception&) { return false; }
}

template <typename Mesh>
bool has_finite_points(const Mesh& m)
{
  for(auto v : vertices(m))
  {
    const Point& p = get(CGAL::vertex_point, m, v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return false;
  }
  return true;
}

template <typename Mesh>
bool has_pinched_vertex(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(m, std::back_inserter(pinched));
  return !pinched.empty();
}

using qzip_robustness::fingerprint;
using qzip_robustness::shape;
using qzip_robustness::singular_interior_vertices;

template <typename Mesh>
using Fingerprint = decltype(fingerprint(std::declval<const Mesh&>()));

template <typename Mesh>
bool is_sane(const Mesh& m)
{
  return CGAL::is_valid_polygon_mesh(m);
}

/// runs `f()`; a CGAL precondition exception counts as a refusal and must leave `m` unchanged.
template <typename Mesh, typename F>
bool guarded(const Mesh& m, const Fingerprint<Mesh>& before, const char* what, const std::string& name, F f)
{
  try
  {
    f();
    return true;
  }
  catch(const CGAL::Precondition_exception& e)
  {
    ++counters.preconditions;
    std::cout << "  " << name << ": " << what << " reported a precondition: " << e.expression() << std::endl;
    assert(is_sane(m));
    assert(fingerprint(m) == before);
    return false;
  }
}

/// every pair of singularities (at most 10 of them), every motion: plan, execute with a record, undo.
template <typename Mesh>
void exercise_qzips(Mesh& m, const std::string& name)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  const Fingerprint<Mesh> fp0 = fingerprint(m);
  const qzip_robustness::Shape shape0 = shape(m);

  // arguments that are not a path
  std::vector<vertex_descriptor> none;
  assert(Q::plan_qzip(m, none, Q::Strip_operation::LEFT_SPLIT).status == Q::Plan_status::INVALID_PATH);
  if(!vertices(m).empty())
  {
    const vertex_descriptor v = *vertices(m).begin();
    assert(Q::shortest_surgery_path(m, v, v).empty());
    assert(Q::plan_qzip(m, std::vector<vertex_descriptor>(1, v), Q::Strip_operation::RIGHT_SPLIT).status
           == Q::Plan_status::INVALID_PATH);
    assert(Q::plan_qzip(m, std::vector<vertex_descriptor>(2, v), Q::Strip_operation::RIGHT_SPLIT).status
           == Q::Plan_status::INVALID_PATH);
  }

  std::vector<vertex_descriptor> sing = singular_interior_vertices(m);
  if(sing.size() > 10) sing.resize(10);
  for(std::size_t i = 0; i < sing.size(); ++i)
    for(std::size_t j = 0; j < sing.size(); ++j)
    {
      if(i == j) continue;
      std::vector<vertex_descriptor> path;
      guarded(m, fp0, "shortest_surgery_path", name, [&]() { path = Q::shortest_surgery_path(m, sing[i], sing[j]); });
      if(path.empty()) path = { sing[i], sing[j] }; // not a path in general: the planner must say so
      for(int mo = 0; mo < 4; ++mo)
      {
        const Q::Strip_operation op = Q::Strip_operation(mo);
        Q::Surgery_plan<Mesh> plan;
        ++counters.plans;
        if(!guarded(m, fp0, "plan_qzip", name, [&]() { plan = Q::plan_qzip(m, path, op); })) continue;
        assert(fingerprint(m) == fp0);
        if(!plan.is_realizable()) { ++counters.plans_refused; continue; }
        // executed on a copy: an undo may re-create elements with new descriptors (Polyhedron_3), which
        // would invalidate `sing` and `path`
        Mesh w;
        auto v2v = copy_mesh_with_map(m, w);
        std::vector<vertex_descriptor> wpath;
        for(vertex_descriptor v : path) wpath.push_back(v2v[v]);
        const Q::Surgery_plan<Mesh> wplan = Q::plan_qzip(w, wpath, op);
        assert(wplan.is_realizable() && wplan.path.size() == plan.path.size());
        Q::Qzip_history<Mesh> history(w);
        Q::Qzip_result<Mesh> r;
        if(!guarded(w, fp0, "execute_qzip", name, [&]() { r = Q::execute_qzip(w, wplan, history); })) continue;
        if(!r.is_done())
        {
          ++counters.execution_refused;
          assert(history.empty());
          assert(is_sane(w));
          assert(fingerprint(w) == fp0);
          continue;
        }
        ++counters.executed;
        if(wplan.number_of_collapses() == 0 && wplan.number_of_splits() == 0) ++counters.noop_executions;
        assert(history.size() == 1);
        assert(is_sane(w));
        assert(shape(w) == shape0);
        Q::undo_qzip(history);
        ++counters.undone;
        assert(history.empty());
        assert(is_sane(w));
        assert(fingerprint(w) == fp0);
      }
      // the convenience function, one motion per pair; undone by planning nothing: compare to a copy
      Mesh w;
      auto v2v = copy_mesh_with_map(m, w);
      const Fingerprint<Mesh> fpw = fingerprint(w);
      Q::Qzip_result<Mesh> r;
      if(guarded(w, fpw, "qzip", name,
                 [&]() { r = Q::qzip(w, v2v[sing[i]], v2v[sing[j]], Q::Strip_operation(int((i + j) % 4))); }))
      {
        assert(is_sane(w));
        if(r.is_done()) assert(shape(w) == shape0);
        else assert(fingerprint(w) == fpw);
      }
    }
  assert(fingerprint(m) == fp0);
}

template <typename Mesh>
void exercise_library(Mesh& m, const std::string& name)
{
  const Fingerprint<Mesh> fp0 = fingerprint(m);
  const qzip_robustness::Shape shape0 = shape(m);

  guarded(m, fp0, "compute_mesh_report", name, [&]() { (void)Q::compute_mesh_report(m); });
  assert(fingerprint(m) == fp0);

  exercise_qzips(m, name); // meshes with non-quad faces included: the planner must refuse what it cannot do

  Mesh p;
  copy_mesh(m, p);
  ++counters.preprocess_runs;
  Q::Preprocess_result pr;
  if(guarded(p, fingerprint(p), "preprocess_valences", name, [&]() { pr = Q::preprocess_valences(p); }))
  {
    assert(is_sane(p));
    assert(shape(p) == shape0); // quad collapses and vertex splits keep the Euler characteristic and face degrees
    if(!pr.converged) ++counters.preprocess_refused;
    std::cout << "  " << name << ": preprocessing removed " << pr.removed_valence_2 << " valence-2 vertices, split "
              << pr.vertex_splits << (pr.converged ? "" : " (not converged)") << std::endl;
    exercise_qzips(p, name + " (preprocessed)");
  }
  else
    ++counters.preprocess_refused;
}

/// the expected behaviour of each file, from the table of README.md (`| \`file\` | ... | accept |`).
std::map<std::string, std::string> read_manifest(const std::string& dir)
{
  std::map<std::string, std::string> expected;
  std::ifstream in(dir + "/README.md");
  assert(in.good());
  std::string line;
  while(std::getline(in, line))
  {
    if(line.compare(0, 3, "| `") != 0) continue;
    const std::string::size_type end = line.find('`', 3);
    const std::string::size_type last = line.find_last_of('|', line.size() - 2);
    assert(end != std::string::npos && last != std::string::npos);
    std::string value = line.substr(last + 1);
    value.erase(std::remove(value.begin(), value.end(), ' '), value.end());
    value.erase(std::remove(value.begin(), value.end(), '|'), value.end());
    assert(value == "accept" || value == "reject" || value == "either");
    expected[line.substr(3, end - 3)] = value;
  }
  return expected;
}

std::vector<std::string> list_directory(const std::string& dir)
{
  std::vector<std::string> names;
  DIR* d = ::opendir(dir.c_str());
  assert(d != nullptr);
  while(dirent* e = ::readdir(d))
  {
    const std::string n = e->d_name;
    if(n != "." && n != ".." && n != "README.md") names.push_back(n);
  }
  ::closedir(d);
  std::sort(names.begin(), names.end());
  return names;
}

template <typename Mesh>
void test_file(const std::string& dir, const std::string& name, const std::string& expected, const char* type)
{
  Mesh m;
  const bool read = read_file(dir + "/" + name, m);
  const bool valid = read && CGAL::is_valid_polygon_mesh(m);
  const bool loads = valid && !faces(m).empty() && has_finite_points(m) && !has_pinched_vertex(m);
  std::cout << name << " [" << type << "]: " << (loads ? "loads" : (valid ? "reads, but is not a usable mesh" : "refused"))
            << " (expected: " << expected << ")" << std::endl;
  if(expected == "accept") assert(loads);
  if(expected == "reject") assert(!loads);
  if(loads) ++counters.loaded; else ++counters.refused_to_load;
  if(valid && !faces(m).empty())
    exercise_library(m, name);
}

} // namespace

/// The PLY header is read as CGAL 5.5's reader reads it (examples/Qzip/qzip_example_ply_check.h): element
/// counts as unsigned integers (the reader takes `8ent` as 8), the format from line 2 whatever its first word,
/// unknown keywords ignored, properties of unknown types skipped; refused where the reader fails or goes astray.
void test_ply_header_as_cgal_reads_it()
{
  auto read = [](const std::string& header, std::string& format, std::vector<qzip_example::Ply_element>& elements,
                 std::string& why)
  {
    std::istringstream in(header);
    return qzip_example::read_ply_header(in, format, elements, why);
  };
  std::string format, why;
  std::vector<qzip_example::Ply_element> elements;
  const bool garbled = read("ply\nformatx binary_little_endian 1.0\nelement vertex 8ent vertex 9\nproperty float x\n"
                            "pvoperty float y\nproperty fmoa w\nend_head 1\nelement face 2\n"
                            "property list uchar int vertex_indices\nproperty list float int bad\nend_header\n",
                            format, elements, why);
  assert(garbled);
  assert(format == "binary_little_endian");
  assert(elements.size() == 2);
  assert(elements[0].name == "vertex" && elements[0].count == 8 && elements[0].properties.size() == 1);
  assert(elements[1].name == "face" && elements[1].count == 2 && elements[1].properties.size() == 1);
  assert(elements[1].properties[0] == std::make_pair(std::string("uchar"), std::string("int")));
  // what the reader fails on, or misreads
  for(const char* header : { "ply\nformat ascii\nend_header\n",                              // no version
                             "ply\nformat utf8 1.0\nend_header\n",                           // unknown format
                             "ply\nformat ascii 1.0\n\nend_header\n",                         // empty line
                             "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n",        // negative count
                             "ply\nformat ascii 1.0\nelement vertex\nend_header\n",           // no count
                             "ply\nformat ascii 1.0\nproperty float x\nend_header\n",         // no element
                             "ply\nformat ascii 1.0\nelement vertex 1\nproperty float\nend_header\n",
                             "ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar x\nend_header\n",
                             "ply\nformat ascii 1.0\nelement vertices 1\nproperty list uchar float y\nend_header\n",
                             "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n" })  // no end_header
  {
    why.clear();
    assert(!read(header, format, elements, why));
    assert(!why.empty());
  }
  // the data is read as the reader reads it: a float as a float, integers within their type's range
  auto data_fits = [&](const std::string& header, const std::string& data)
  {
    std::istringstream in(header + data);
    if(!qzip_example::read_ply_header(in, format, elements, why)) return false;
    return qzip_example::ply_data_fits(in, format, elements, std::uintmax_t(header.size() + data.size()), why);
  };
  const std::string triangle = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  assert(data_fits(triangle, "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  assert(!data_fits(triangle, "0 0 0\n1 0 0\n0 1 1e39\n3 0 1 2\n"));   // not a float
  assert(!data_fits(triangle, "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n"));    // not a uchar
  assert(!data_fits(triangle, "0 0 0\n1 0 0\n0 1 0\n3 0 1\n"));        // ends early
}

/// ASCII OFF lines are read as CGAL 5.5's scanner reads them (examples/Qzip/qzip_example_off_check.h): refused where
/// the scanner would read a color past the end of a line's numbers, resize a face to a count its line does not hold,
/// convert a value out of the range of its type or divide by a zero `w`; accepted (or left to CGAL's reader where it
/// fails on its own) otherwise.
void test_off_ascii_lines_as_cgal_reads_them()
{
  std::string why;
  auto fits = [&why](const std::string& file)
  {
    std::istringstream in(file);
    const qzip_example::Off_keyword keyword = qzip_example::parse_off_keyword(qzip_example::read_off_keyword(in));
    assert(keyword.valid);
    qzip_example::Off_ascii_header header;
    qzip_example::read_off_ascii_header(in, keyword, header);
    why.clear();
    const bool ok = qzip_example::off_ascii_data_fits(in, keyword, header, why);
    assert(ok == why.empty() && why.find('\n') == std::string::npos);
    return ok;
  };
  const std::string quad = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  const std::string colored_quad = "0 0 0 255 0 0\n1 0 0 0 255 0\n1 1 0 0 0 255\n0 1 0 1 1 1\n";
  // what CGAL's reader reads correctly
  for(const std::string& file : std::vector<std::string>{
        "OFF\n4 1 0\n" + quad + "4 0 1 2 3\n",
        "# comment\nOFF\n# comment\n4 1 0\n\n" + quad + "# comment\n\n4 0 1 2 3 # comment\n",
        "OFF\r\n4 1 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n4 0 1 2 3\r\n",          // CRLF
        "OFF 4 1 0 0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3",                            // first vertex on the count line, no final newline
        "OFF\n4 1 0\n" + quad + "4 0 1 2 3 255 0 0 255\n",                            // face color without C: ignored
        "OFF\n4 1 0\n" + quad + "3.9 0 1 2 3\n",                                      // count read as 3
        "COFF\n4 1 0\n" + quad + "4 0 1 2 3 1e999 0 0\n",                              // the numbers end at 1e999: no color
        "nOFF 3\n4 1 0\n" + quad + "4 0 1 2 3\n",                                     // dimension first
        "4OFF\n4 1 0\n0 0 0 1\n2 0 0 2\n1 1 0 1\n0 1 0 -1\n4 0 1 2 3\n",
        "COFF\n4 1 0\n" + colored_quad + "4 0 1 2 3\n",                               // colors on vertices only
        "COFF\n4 2 0\n" + quad + "3 0 1 2 255 0 0\n3 0 2 3 0.5 0.5 0.5 1\n",          // on faces only (RGB, RGBA)
        "COFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0 3\n0 1 0 0.2 0.4 0.6 1\n4 0 1 2 3\n",       // none, then colors: none read first
        "COFF\n4 1 0\n0 0 0 0\n1 0 0 148\n1 1 0 500\n0 1 0 -0.5\n4 0 1 2 3 12\n",     // colormap indices (clamped above 148)
        "CNOFF\n4 1 0\n0 0 0 0 0 1 255 0 0\n1 0 0 0 0 1 7\n1 1 0 0 0 1 0 0 1 1\n0 1 0 0 0 1 9\n4 0 1 2 3\n",
        "C4OFF\n4 1 0\n0 0 0 1 255 0 0\n1 0 0 1 7\n1 1 0 2 0 0 255\n0 1 0 1 3\n4 0 1 2 3\n" })
    assert(fits(file));
  // where CGAL's reader fails on its own, before any color: left to it
  assert(fits("OFF\n4 1 0\n0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));        // a short vertex line
  assert(fits("COFF\n4 2 0\n" + quad + "4 0 1 2 3\n"));                        // a missing face
  assert(fits("OFF\n4 1\n" + quad + "4 0 1 2 3\n"));                           // no edge count: read from the vertices
  // what it misreads
  for(const std::string& file : std::vector<std::string>{
        "OFF\n4 1 0\n" + quad + "1000000000 0 1 2 3\n",         // a face resized to 10^9 before its indices are read
        "OFF\n4 1 0\n" + quad + "5 0 1 2 3\n",                  // one index missing
        "OFF\n4 1 0\n" + quad + "1e300 0 1 2 3\n",
        "OFF\n4 1 0\n" + quad + "-1 0 1 2 3\n",                 // converted to std::size_t
        "OFF\n4 1 0\n" + quad + "4 0 1 2 -1\n",                 // an index converted to std::size_t
        "OFF\n4 1 0\n" + quad + "4 0 1 2 4\n",                  // no vertex 4
        "COFF\n4 1 0\n0 0 0 255 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n",                 // vertex colors, then none
        "COFF\n4 2 0\n" + quad + "3 0 1 2 255 0 0\n3 0 2 3\n",                         // face colors, then none
        "COFF\n4 1 0\n0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n",                          // the color count wraps around
        "COFF\n5 1 0\n" + quad,                                                       // at the end of the file too
        "CNOFF\n4 1 0\n0 0 0 0 0 1\n1 0 0 0 0\n1 1 0 0 0 1\n0 1 0 0 0 1\n4 0 1 2 3\n", // the same with normals
        "C4OFF\n4 1 0\n0 0 0\n1 0 0 1\n1 1 0 1\n0 1 0 1\n4 0 1 2 3\n",                 // and with w
        "COFF\n4 1 0\n" + quad + "4 0 1 2 3 255 0\n",                                  // two components
        "COFF\n4 1 0\n0 0 0 -1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n4 0 1 2 3\n",               // a negative colormap index
        "COFF\n4 1 0\n" + quad + "4 0 1 2 3 1e10\n",                                   // an index beyond int
        "COFF\n4 1 0\n" + quad + "4 0 1 2 3 256 0 0\n",                                // beyond unsigned char
        "COFF\n4 1 0\n" + quad + "4 0 1 2 3 1.5 0.5 0\n",                              // 1.5 * 255
        "COFF\n4 1 0\n" + quad + "4 0 1 2 3 255 255 -1\n",                            // negative
        "4OFF\n4 1 0\n0 0 0 1\n1 0 0 0\n1 1 0 1\n0 1 0 1\n4 0 1 2 3\n" })              // w = 0
    assert(!fits(file));
  // the header counts, through check_file_header() on a file
  auto check = [&why](const std::string& content)
  {
    const char* tmp = std::getenv("TMPDIR");
    const std::string path = std::string(tmp ? tmp : "/tmp") + "/test_bad_input_off_ascii_" + std::to_string(::getpid()) + ".off";
    {
      std::ofstream out(path, std::ios::binary);
      out << content;
    }
    why.clear();
    const bool ok = qzip_example::check_file_header(path, std::uintmax_t(content.size()), why);
    std::remove(path.c_str());
    return ok;
  };
  assert(check("COFF\n4 1 0\n" + colored_quad + "4 0 1 2 3\n"));
  assert(!check("nOFF 3 -4 1 0\n" + quad + "4 0 1 2 3\n") && why.find("negative") != std::string::npos);
  assert(!check("OFF\n8 6") && why.find("more elements") != std::string::npos);
  assert(!check("OFF\n4 1 0\n" + quad + "2000000000 0 1 2 3\n") && why.find("declares 2000000000 vertices") != std::string::npos);
  assert(!check("COFF\n4 1 0\n0 0 0 9\n" + quad.substr(6) + "4 0 1 2 3\n") && why.find("vertex 1") != std::string::npos);
}

int main(int argc, char** argv)
{
  test_ply_header_as_cgal_reads_it();
  test_off_ascii_lines_as_cgal_reads_them();
  const std::string dir = (argc > 1) ? argv[1] : "data/bad";
  const std::map<std::string, std::string> expected = read_manifest(dir);
  const std::vector<std::string> names = list_directory(dir);
  assert(names.size() >= 30);
  for(const auto& kv : expected)
    assert(std::find(names.begin(), names.end(), kv.first) != names.end());

  for(const std::string& name : names)
  {
    const auto it = expected.find(name);
    if(it == expected.end())
    {
      std::cerr << name << " is not listed in " << dir << "/README.md" << std::endl;
      assert(false);
      return EXIT_FAILURE;
    }
    ++counters.files;
    test_file<Surface_mesh>(dir, name, it->second, "Surface_mesh");
    test_file<Polyhedron>(dir, name, it->second, "Polyhedron_3");
  }

  std::cout << "files tried " << counters.files << "; loads (Surface_mesh and Polyhedron_3 counted apart) " << counters.loaded << ", refused "
            << counters.refused_to_load << "; preprocessing runs " << counters.preprocess_runs << " ("
            << counters.preprocess_refused << " not converged or refused); plans " << counters.plans << " ("
            << counters.plans_refused << " refused), Q-zips executed and undone " << counters.executed << ", "
            << "refused at execution " << counters.execution_refused << ", empty plans " << counters.noop_executions
            << " (no operation); preconditions reported "
            << counters.preconditions << "; crashes 0, violations 0" << std::endl;
  return EXIT_SUCCESS;
}
