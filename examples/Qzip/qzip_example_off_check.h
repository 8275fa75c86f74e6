// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
// The examples' reading of an OFF header and of binary OFF data as CGAL 5.5's reader reads them (not part of
// the library): the keyword and its prefixes, the binary counts, and a walk through binary faces, whose counts
// the reader trusts (it resizes each face before reading it). Used by `check_file_header()`.

#ifndef CGAL_QZIP_EXAMPLE_OFF_CHECK_H
#define CGAL_QZIP_EXAMPLE_OFF_CHECK_H

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <istream>
#include <string>

namespace qzip_example {

/// The prefixes of an OFF keyword, `[ST][C][N][4][n]` before `OFF` or `SKEL`, as CGAL 5.5's `File_header_OFF`
/// reads them; `valid` is false for any other keyword.
struct Off_keyword
{
  bool valid = false, off = false, textures = false, normals = false, homogeneous = false, dimension = false;
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
  prefix("C"); // colors: not read in binary OFF, and not checked in ASCII OFF
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

} // namespace qzip_example

#endif // CGAL_QZIP_EXAMPLE_OFF_CHECK_H
