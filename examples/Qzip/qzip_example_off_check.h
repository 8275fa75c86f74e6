// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
// The examples' reading of an OFF file as CGAL 5.5's reader reads it (not part of the library): the keyword and
// its prefixes, the binary and ASCII counts, a walk through binary faces, whose counts the reader trusts (it
// resizes each face before reading it), and a walk through ASCII lines, whose color entries the reader indexes
// without checking them. Used by `check_file_header()`. Both `CGAL::IO::read_polygon_soup()` and
// `CGAL::IO::read_polygon_mesh()` (`Surface_mesh` and `Polyhedron_3`, through `Generic_facegraph_builder`) read
// an OFF file with `CGAL::IO::internal::read_OFF()` (CGAL/IO/OFF.h) and its `File_scanner_OFF`.

#ifndef CGAL_QZIP_EXAMPLE_OFF_CHECK_H
#define CGAL_QZIP_EXAMPLE_OFF_CHECK_H

#include <CGAL/IO/io.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace qzip_example {

/// The prefixes of an OFF keyword, `[ST][C][N][4][n]` before `OFF` or `SKEL`, as CGAL 5.5's `File_header_OFF`
/// reads them; `valid` is false for any other keyword.
struct Off_keyword
{
  bool valid = false, off = false, textures = false, colors = false, normals = false, homogeneous = false,
       dimension = false;
};

inline Off_keyword parse_off_keyword(const std::string& keyword)
{
  Off_keyword k;
  std::size_t j = 0;
  auto prefix = [&](const char* p)
  {
    const std::size_t n = std::strlen(p);
    if(keyword.compare(j, n, p) != 0) return false;
    j += n;
    return true;
  };
  k.textures = prefix("ST");
  k.colors = prefix("C"); // not read in binary OFF
  k.normals = prefix("N");
  k.homogeneous = prefix("4");
  k.dimension = prefix("n");
  k.off = keyword.compare(j, std::string::npos, "OFF") == 0;
  k.valid = k.off || keyword.compare(j, std::string::npos, "SKEL") == 0;
  return k;
}

/// Reads a big-endian 32-bit integer, as CGAL's binary OFF reader does.
inline bool read_big_endian_int32(std::istream& in, std::int32_t& x)
{
  unsigned char b[4];
  if(!in.read(reinterpret_cast<char*>(b), 4)) return false;
  x = std::int32_t(std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | std::uint32_t(b[3]));
  return true;
}

/// What `read_off_binary_header()` reads of a binary OFF header.
struct Off_binary_header
{
  long long vertices = 0, faces = 0, edges = 0; // 0 if the file ends before them (CGAL reports it)
  bool complete = false;             // all its counts were read: the data follows
  int floats_per_vertex = 3;         // what CGAL's scanner reads of each vertex (see `off_binary_faces_fit()`)
};

/// Whether CGAL 5.5's `File_header_OFF` can take the edge count `edges` of an OFF header: it computes `2 * edges` in
/// an `int` (undefined behaviour beyond).
inline bool off_edge_count_fits(double edges)
{
  return edges >= -1073741824. && edges <= 1073741823.;
}

/// Skips blanks and comment lines (`#` to the end of the line), as CGAL 5.5's `skip_comment_OFF` does.
inline void skip_off_blanks_and_comments(std::istream& in)
{
  for(int c = in.peek(); c != EOF; c = in.peek())
  {
    if(c == '#') { std::string comment; std::getline(in, comment); }
    else if(std::isspace(c)) in.get();
    else break;
  }
}

/// Appends to `word` the run of letters and digits that follows, and consumes the character after it (`after`),
/// as CGAL 5.5's `File_header_OFF` reads its keywords.
inline void read_off_word(std::istream& in, std::string& word, char& after)
{
  after = '\0';
  char c;
  while(in.get(c))
  {
    if(!std::isalnum(static_cast<unsigned char>(c))) { after = c; return; }
    word += c;
  }
}

/// The keyword of an OFF file as CGAL 5.5's `File_header_OFF` reads it (the first run of letters and digits after
/// blanks and comments; the character after it is consumed). Reads from the start of `in`.
inline std::string read_off_keyword(std::istream& in)
{
  in.clear();
  in.seekg(0);
  skip_off_blanks_and_comments(in);
  std::string keyword;
  char after;
  read_off_word(in, keyword, after);
  return keyword;
}

/// Reads the rest of an OFF header as CGAL 5.5's `File_header_OFF` does, `in` just after its keyword (see
/// `read_off_keyword()`) and `keyword` its prefixes: returns whether it is a binary header, the word `BINARY` and
/// the end of its line, then big-endian 32-bit counts: a dimension for `n`, the vertices, the faces, and the edges
/// for `OFF`. Leaves `in` after them.
inline bool read_off_binary_header(std::istream& in, const Off_keyword& keyword, Off_binary_header& header)
{
  if(!keyword.valid) return false;
  std::string word;
  char after = '\0', first = '\0';
  skip_off_blanks_and_comments(in);
  if(!in.get(first) || std::isdigit(static_cast<unsigned char>(first))) return false;
  word += first;
  read_off_word(in, word, after);
  if(word != "BINARY") return false;
  if(after != '\n') { std::string end_of_line; std::getline(in, end_of_line); }
  const int h = keyword.homogeneous ? 1 : 0; // binary colors are not read by CGAL's reader
  header.floats_per_vertex = 3 + h + (keyword.normals ? 3 + h : 0) + (keyword.textures ? 2 + h : 0);
  long long count[3] = { 0, 0, 0 };
  for(int k = keyword.dimension ? -1 : 0; k < (keyword.off ? 3 : 2); ++k)
  {
    std::int32_t x = 0;
    if(!read_big_endian_int32(in, x)) return true;
    if(k >= 0) count[k] = x;
  }
  header.vertices = count[0];
  header.faces = count[1];
  header.edges = count[2];
  header.complete = true;
  return true;
}

/// Walks the data of a binary OFF file (`in` just after its header) as CGAL 5.5's reader reads it: each vertex is
/// `header.floats_per_vertex` floats, each face a 32-bit count then that many indices (colors are not read).
/// The reader resizes each face to its count before reading its indices: a face that declares more indices than
/// the rest of the file can hold, a negative count, or data that ends before the last count (the reader then
/// takes an uninitialized one) is refused (`false`, the reason in `why`).
inline bool off_binary_faces_fit(std::istream& in, const Off_binary_header& header, std::uintmax_t file_size,
                                 std::string& why)
{
  if(!header.complete) return true;
  const std::streamoff data = in.tellg();
  if(data < 0) return true;
  std::uintmax_t at = std::uintmax_t(data) + std::uintmax_t(header.vertices) * 4 * std::uintmax_t(header.floats_per_vertex);
  for(long long f = 0; f < header.faces; ++f)
  {
    // at the end of the file, the reader takes the count it could not read from an uninitialized integer
    if(at + 4 > file_size)
    {
      why = "the binary OFF data ends before the faces its header declares";
      return false;
    }
    in.seekg(std::streamoff(at));
    std::int32_t n = 0;
    if(!read_big_endian_int32(in, n)) return true;
    at += 4;
    if(n < 0 || std::uintmax_t(n) * 4 > file_size - at)
    {
      why = n < 0 ? "a face of the binary OFF data has a negative number of vertices"
                  : "a face of the binary OFF data declares more vertices than the file can hold";
      return false;
    }
    at += std::uintmax_t(n) * 4;
  }
  return true;
}

/// The reason given for a face index that is not that of one of the `vertices` vertices of the file.
inline std::string missing_vertex_reason(std::uintmax_t vertices)
{
  return "a face refers to a vertex that does not exist (the file has " + std::to_string(vertices) + " vertices)";
}

/// What `read_off_ascii_header()` reads of an ASCII OFF header.
struct Off_ascii_header
{
  long long vertices = 0, faces = 0, edges = 0;
  bool complete = false; // all its counts were read as CGAL reads them: the data follows
};

/// Reads the counts of an ASCII OFF header as CGAL 5.5's `File_header_OFF` does, `in` just after its keyword (see
/// `read_off_keyword()`) and `keyword` its prefixes: blanks and comments, then a digit (anything else and the
/// reader fails, or reads a binary header: see `read_off_binary_header()`), then integers read with `operator>>`
/// with only blanks between them: a dimension for `n`, the vertices, the faces, and the edges for `OFF` (none for
/// `SKEL`). Leaves `in` after the last count, where the reader starts reading vertex lines (the rest of the count
/// line is the first one if it holds anything). `complete` stays false where the reader fails: a missing count, one
/// that is not an integer, or one that does not fit in a `long long` (the reader reads `int`s: beyond, it fails
/// too; counts between the two are left to the caller's checks of the counts); the counts read until then are kept.
inline void read_off_ascii_header(std::istream& in, const Off_keyword& keyword, Off_ascii_header& header)
{
  skip_off_blanks_and_comments(in);
  if(!std::isdigit(in.peek())) return;
  long long dimension = 0;
  long long* count[4] = { &dimension, &header.vertices, &header.faces, &header.edges };
  for(int k = keyword.dimension ? 0 : 1; k < (keyword.off ? 4 : 3); ++k)
    if(!(in >> *count[k])) return;
  header.complete = true;
}

/// The numbers of an ASCII OFF vertex or face line as CGAL 5.5's `File_scanner_OFF` reads them: blanks and comment
/// lines skipped, the line up to its first `#`, and as many numbers as `CGAL::IO::iformat()` reads from it (the
/// reader's own number parsing, `operator>>` on a `double` with GCC and clang: the numbers end at the first word
/// that is not one, or at a value out of range such as `1e999`).
inline std::vector<double> read_off_ascii_line(std::istream& in)
{
  skip_off_blanks_and_comments(in);
  std::string line;
  std::getline(in, line);
  std::istringstream numbers(line.substr(0, line.find('#')));
  std::vector<double> entries;
  double d = 0;
  while(numbers >> CGAL::IO::iformat(d))
    entries.push_back(d);
  return entries;
}

/// Whether CGAL 5.5's `File_scanner_OFF::scan_color()` reads the color of a line safely, the line's numbers in
/// `entries`, its color starting at `first` with `count` numbers (negative when the line is shorter than what comes
/// before its color). One number is an index in a table of 149 colors, converted to an `int` and only bounded from
/// above: it must lie in [0, 2^31). Otherwise the scanner reads three numbers whatever `count` is (past the end of
/// the line's numbers for 0, 2 or fewer), converts integer components to `unsigned char`, and others times 255:
/// each must lie in (-1, 256), the range of the conversion.
inline bool off_ascii_color_readable(const std::vector<double>& entries, std::size_t first, long long count,
                                     std::string& problem)
{
  if(count == 1)
  {
    const double index = entries[first];
    if(index > -1 && index < 2147483648.) return true;
    problem = "a colormap index out of range";
    return false;
  }
  if(count < 3)
  {
    problem = count < 0 ? "fewer numbers than the prefixes of the OFF keyword require"
                        : count == 0 ? "no color, unlike an earlier one" : "a color of 2 components";
    return false;
  }
  const double* rgb = &entries[first];
  const bool integers = std::floor(rgb[0]) == rgb[0] && std::floor(rgb[1]) == rgb[1] && std::floor(rgb[2]) == rgb[2];
  for(int c = 0; c < 3; ++c)
  {
    const double v = integers ? rgb[c] : rgb[c] * 255;
    if(!(v > -1 && v < 256))
    {
      problem = "a color component out of range";
      return false;
    }
  }
  return true;
}

/// Walks the lines of an ASCII OFF file (`in` just after its header, see `read_off_ascii_header()`) as CGAL 5.5's
/// `CGAL::IO::internal::read_OFF()` reads them with its `File_scanner_OFF` (lines split by `read_off_ascii_line()`),
/// stopping where the reader fails on its own (a vertex line with too few numbers, the end of the file...), and
/// refuses (`false`, the reason in `why`) what the reader would misread:
/// * a face whose count is negative (the reader converts it to `std::size_t`: undefined behaviour) or larger
///   than the number of indices its line lists: the reader resizes the face to its count before reading the
///   indices, and fails only then (16 GB for a count of 2e9);
/// * a face index that is negative (converted to `std::size_t`) or not that of a vertex (the reader fails on it);
/// * a vertex `w = 0` with the `4` prefix (an assertion in the reader, a division by zero without assertions);
/// * with the `C` prefix, a line whose color the scanner does not read safely (see `off_ascii_color_readable()`):
///   it takes the numbers after the coordinates (and normals, with `N`) as the color, counts them in a `std::size_t`
///   (a vertex line shorter than the prefixes require wraps around, and so does the end of the file within the
///   vertices, even without any color), and once a vertex (a face) has a color, it reads a color on every later
///   vertex (face), from past the end of the line's numbers if there is none.
inline bool off_ascii_data_fits(std::istream& in, const Off_keyword& keyword, const Off_ascii_header& header,
                                std::string& why)
{
  if(!header.complete) return true;
  const std::size_t h = keyword.homogeneous ? 1 : 0;
  const std::size_t coordinates = 3 + h, before_color = coordinates + (keyword.normals ? 3 + h : 0);
  std::string problem;
  bool colors = false; // the scanner's `has_vcolors()`, then `has_fcolors()`: once set, never reset
  auto refuse = [&](const std::string& element, long long i, const std::string& what)
  {
    why = element + " " + std::to_string(i) + " of the OFF data " + what;
    return false;
  };
  for(long long v = 0; v < header.vertices; ++v)
  {
    const std::vector<double> entries = read_off_ascii_line(in);
    if(h == 1 && entries.size() >= 4 && entries[3] == 0) return refuse("vertex", v, "has a homogeneous coordinate w = 0");
    if(keyword.colors)
    {
      const long long count = (long long)entries.size() - (long long)before_color;
      colors = colors || count != 0;
      if(colors && !off_ascii_color_readable(entries, before_color, count, problem)) return refuse("vertex", v, "has " + problem);
    }
    if(entries.size() < before_color || !in.good()) return true; // the reader fails on this vertex
  }
  colors = false;
  for(long long f = 0; f < header.faces; ++f)
  {
    const std::vector<double> entries = read_off_ascii_line(in);
    if(entries.empty()) return true; // the reader fails
    if(!(entries[0] > -1)) return refuse("face", f, "has a negative number of vertices");
    if(entries[0] >= double(entries.size()))
    {
      std::ostringstream declared;
      declared.precision(15);
      declared << entries[0];
      return refuse("face", f, "declares " + declared.str() + " vertices but lists " + std::to_string(entries.size() - 1));
    }
    const std::size_t n = std::size_t(entries[0]);
    for(std::size_t j = 1; j <= n; ++j)
      if(!(entries[j] > -1 && entries[j] < double(header.vertices)))
      {
        why = missing_vertex_reason(std::uintmax_t(header.vertices));
        return false;
      }
    if(keyword.colors)
    {
      const long long count = (long long)(entries.size() - n - 1);
      colors = colors || count != 0;
      if(colors && !off_ascii_color_readable(entries, n + 1, count, problem)) return refuse("face", f, "has " + problem);
    }
  }
  return true;
}

} // namespace qzip_example

#endif // CGAL_QZIP_EXAMPLE_OFF_CHECK_H
