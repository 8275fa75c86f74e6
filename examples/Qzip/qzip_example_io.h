// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
// Small helpers shared by the Qzip examples (not part of the library): checked mesh input,
// atomic mesh output, and a minimal command-line parser. Errors come back as a message;
// nothing here prints or exits.

#ifndef CGAL_QZIP_EXAMPLE_IO_H
#define CGAL_QZIP_EXAMPLE_IO_H

#include "qzip_example_off_check.h"
#include "qzip_example_ply_check.h"

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/number_utils.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <new>
#include <stdexcept>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace qzip_example {

/// Which face degrees `read_input_mesh()` accepts.
enum class Accepted_faces { QUADS_ONLY, TRIANGLES_AND_QUADS, ANY_POLYGON };

/// `true` if `a` and `b` both exist and are the same file (same device and inode; symbolic links followed).
inline bool same_file(const std::string& a, const std::string& b)
{
  struct stat sa, sb;
  if(::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0)
    return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/// Checks an OFF or PLY file before CGAL's readers see it. A PLY file goes through `check_ply_file()`
/// (qzip_example_ply_check.h: its header read as CGAL 5.5's reader reads it, then its data). An OFF file
/// must declare element counts that fit in the file (every element takes at least one byte): CGAL 5.5's
/// readers reserve memory for the declared counts before reading, which fails (`std::bad_alloc`, or an
/// abort under AddressSanitizer) on absurd counts. A binary OFF header (see `read_off_binary_header()`)
/// must declare non-negative counts that fit in the file too (CGAL turns a negative count into a huge one,
/// and computes an `int` from their sum: undefined behaviour when it overflows), and each face of its data
/// no more vertices than the rest of the file can hold (see `off_binary_faces_fit()`). The lines of an ASCII OFF
/// file are read as CGAL's scanner reads them (see `off_ascii_data_fits()`): each face must list the indices it
/// declares (the reader resizes the face to its count first), and with the `C` prefix every color must be one
/// the scanner reads within the line. Other formats are not checked.
inline bool check_file_header(const std::string& path, std::uintmax_t file_size, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  std::string line, token;
  auto refuse = [&](const std::string& why)
  {
    error = "cannot read '" + path + "': " + why;
    return false;
  };
  auto too_many = [&](double declared)
  {
    return declared > double(file_size) && !refuse("its header declares more elements than the file can hold");
  };
  // CGAL's PLY reader wants `ply` on the first line; its OFF reader skips blank lines before the keyword
  std::getline(in, line);
  std::istringstream first(line);
  first >> token;
  std::string why;
  if(token == "ply")
  {
    in.clear();
    in.seekg(0);
    return check_ply_file(in, file_size, why) || refuse(why);
  }
  const std::string keyword = read_off_keyword(in);
  const Off_keyword kw = parse_off_keyword(keyword);
  const std::streampos after_keyword = in.tellg();
  Off_binary_header binary;
  if(read_off_binary_header(in, kw, binary))
  {
    if(binary.vertices < 0 || binary.faces < 0) return refuse("malformed binary OFF header (a negative element count)");
    if(too_many(double(binary.vertices + binary.faces))) return false;
    if(!off_edge_count_fits(double(binary.edges))) return refuse("malformed binary OFF header (an edge count out of range)");
    return off_binary_faces_fit(in, binary, file_size, why) || refuse(why);
  }
  if(!kw.valid) return true; // CGAL's reader fails on it
  // CGAL 5.5's ASCII scanner reads texture coordinates at an index it leaves uninitialized without the C prefix,
  // and unchecked with it (a segmentation fault on a short line)
  if(kw.textures) return refuse("texture coordinates in an ASCII OFF file (" + keyword + ") are not supported");
  in.clear();
  in.seekg(after_keyword);
  Off_ascii_header ascii;
  read_off_ascii_header(in, kw, ascii);
  if(too_many(double(std::max(ascii.vertices, 0LL)) + double(std::max(ascii.faces, 0LL)))) return false;
  if(!ascii.complete) return true; // CGAL's reader fails on it
  if(ascii.vertices < 0 || ascii.faces < 0) return refuse("malformed OFF header (a negative element count)");
  if(kw.off && !off_edge_count_fits(double(ascii.edges))) return refuse("malformed OFF header (an edge count out of range)");
  return off_ascii_data_fits(in, kw, ascii, why) || refuse(why);
}

/// Checks that every face index of the file refers to an existing vertex. CGAL 5.5's OBJ and PLY readers
/// do not check the indices (OBJ even turns index 0 and `n + 1` into `n`) and then read past the end of
/// their vertex array while building the mesh; this check reads the file as a polygon soup first, which
/// only stores the indices. Returns `true` when the file cannot be read as a soup: then
/// `CGAL::IO::read_polygon_mesh()` fails on it as well and the caller reports that.
inline bool face_indices_in_range(const std::string& path, std::string& error)
{
  std::vector<CGAL::Simple_cartesian<double>::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  try
  {
    if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
      return true;
  }
  catch(const std::exception&)
  {
    return true; // e.g. std::bad_alloc on absurd element counts, reported by the caller's read as well
  }
  for(const auto& polygon : polygons)
    for(std::size_t i : polygon)
      if(i >= points.size())
      {
        error = "cannot read '" + path + "': " + missing_vertex_reason(points.size());
        return false;
      }
  return true;
}

/// Reads `path` into `mesh` (cleared first) and checks it. Returns `false` with a one-line message in `error`
/// if the file is missing or unreadable, is not a valid polygon mesh (`CGAL::IO::read_polygon_mesh` fails,
/// e.g. on an edge shared by three faces, or `CGAL::is_valid_polygon_mesh` fails), has a pinched
/// (non-manifold) vertex, has no face, has a non-finite coordinate, or has a face whose degree `accepted`
/// does not allow.
template <typename Mesh>
bool read_input_mesh(const std::string& path, Mesh& mesh, std::string& error,
                     Accepted_faces accepted = Accepted_faces::QUADS_ONLY)
{
  error.clear();
  CGAL::clear(mesh);
  struct stat st;
  if(::stat(path.c_str(), &st) != 0)
  {
    error = "cannot open input '" + path + "': no such file";
    return false;
  }
  if(!S_ISREG(st.st_mode))
  {
    error = "cannot open input '" + path + "': not a regular file";
    return false;
  }
  if(!std::ifstream(path).good())
  {
    error = "cannot open input '" + path + "': permission denied or unreadable";
    return false;
  }
  if(!check_file_header(path, std::uintmax_t(st.st_size), error) || !face_indices_in_range(path, error))
    return false;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_mesh(path, mesh);
  }
  catch(const std::bad_alloc&)
  {
    CGAL::clear(mesh);
    error = "cannot read '" + path + "': it declares more elements than can be allocated";
    return false;
  }
  catch(const std::exception& e)
  {
    CGAL::clear(mesh);
    error = "cannot read '" + path + "': " + e.what();
    return false;
  }
  if(!read)
  {
    CGAL::clear(mesh);
    error = "cannot read '" + path + "' as a polygon mesh (unsupported extension, malformed file, "
            "or a non-manifold / non-orientable surface)";
    return false;
  }
  if(!CGAL::is_valid_polygon_mesh(mesh))
  {
    CGAL::clear(mesh);
    error = "'" + path + "' is not a valid polygon mesh";
    return false;
  }
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> pinched;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(mesh, std::back_inserter(pinched));
  if(!pinched.empty())
  {
    CGAL::clear(mesh);
    error = "'" + path + "' is not manifold: it has " + std::to_string(pinched.size())
            + " pinched (non-manifold) vertex fan(s)";
    return false;
  }
  if(faces(mesh).empty())
  {
    error = "'" + path + "' contains no face";
    return false;
  }
  const auto vpm = get(CGAL::vertex_point, mesh);
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y()))
       || !std::isfinite(CGAL::to_double(p.z())))
    {
      error = "'" + path + "' has a vertex with a NaN or infinite coordinate";
      return false;
    }
  }
  if(accepted != Accepted_faces::ANY_POLYGON)
  {
    for(auto f : faces(mesh))
    {
      std::size_t d = 0;
      for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      {
        (void)h;
        ++d;
      }
      const bool ok = (d == 4) || (d == 3 && accepted == Accepted_faces::TRIANGLES_AND_QUADS);
      if(!ok)
      {
        error = "'" + path + "' has a face of degree " + std::to_string(d) + "; only "
                + (accepted == Accepted_faces::QUADS_ONLY ? "quads are" : "triangles and quads are")
                + " accepted";
        return false;
      }
    }
  }
  return true;
}

/// Writes `mesh` to `path` through a temporary file in the same directory, renamed over `path` once
/// complete, so that `path` is never left half-written. Refuses (returns `false` with a message) when
/// `path` is the same file as `input_path` (if given), or when the format (from the extension) is not
/// supported or the file cannot be written.
template <typename Mesh>
bool write_output_mesh_atomically(const std::string& path, const Mesh& mesh, std::string& error,
                                  const std::string& input_path = std::string())
{
  error.clear();
  if(!input_path.empty() && same_file(path, input_path))
  {
    error = "output '" + path + "' is the input file; refusing to overwrite it";
    return false;
  }
  const std::string::size_type slash = path.find_last_of('/');
  const std::string dir = (slash == std::string::npos) ? std::string() : path.substr(0, slash + 1);
  const std::string name = (slash == std::string::npos) ? path : path.substr(slash + 1);
  const std::string::size_type dot = name.find_last_of('.');
  if(name.empty() || dot == std::string::npos || dot == 0)
  {
    error = "output '" + path + "' has no file extension (use .off, .obj, .ply, ...)";
    return false;
  }
  // keep the extension: CGAL::IO::write_polygon_mesh chooses the format from it
  const std::string tmp = dir + "." + name.substr(0, dot) + ".tmp" + std::to_string(::getpid()) + name.substr(dot);
  if(!std::ofstream(tmp).good()) // checked here so that CGAL's writer does not print its own message
  {
    error = "cannot create a file in the directory of '" + path + "'";
    return false;
  }
  if(!CGAL::IO::write_polygon_mesh(tmp, mesh, CGAL::parameters::stream_precision(17)))
  {
    std::remove(tmp.c_str());
    error = "cannot write '" + path + "' (unsupported file extension?)";
    return false;
  }
  if(std::rename(tmp.c_str(), path.c_str()) != 0)
  {
    std::remove(tmp.c_str());
    error = "cannot rename the temporary file to '" + path + "'";
    return false;
  }
  return true;
}

/// `true` if `flag` (e.g. `--json`) is among the arguments.
inline bool has_flag(int argc, char** argv, const std::string& flag)
{
  for(int i = 1; i < argc; ++i)
    if(flag == argv[i])
      return true;
  return false;
}

/// The value following option `name` (e.g. `--output out.off`), or `default_value` if absent.
inline std::string option_value(int argc, char** argv, const std::string& name,
                                const std::string& default_value = std::string())
{
  for(int i = 1; i + 1 < argc; ++i)
    if(name == argv[i])
      return argv[i + 1];
  return default_value;
}

/// The arguments that are neither options (starting with `-`) nor values of `options_with_value`.
inline std::vector<std::string> positional_arguments(int argc, char** argv,
                                                     const std::set<std::string>& options_with_value = {})
{
  std::vector<std::string> out;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(options_with_value.count(a) > 0) { ++i; continue; }
    if(!a.empty() && a[0] == '-') continue;
    out.push_back(a);
  }
  return out;
}

/// The first argument starting with `-` that is neither in `flags` nor in `options_with_value`, or "" if none.
inline std::string unknown_option(int argc, char** argv, const std::set<std::string>& flags,
                                  const std::set<std::string>& options_with_value = {})
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(options_with_value.count(a) > 0) { ++i; continue; }
    if(!a.empty() && a[0] == '-' && flags.count(a) == 0)
      return a;
  }
  return std::string();
}

} // namespace qzip_example

#endif // CGAL_QZIP_EXAMPLE_IO_H
