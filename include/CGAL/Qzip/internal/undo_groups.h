// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_UNDO_GROUPS_H
#define CGAL_QZIP_INTERNAL_UNDO_GROUPS_H

#include <CGAL/license/Qzip.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// The entries of a journal of mesh operations (Operation_log, Triangle_journal), in groups: mark()
// opens a group, rollback_to_mark() undoes the entries of the last open group, most recent first (all
// entries when no group is open), and closes it.
template <typename Entry>
class Undo_groups
{
  std::vector<Entry> entries;
  std::vector<std::size_t> marks;

public:
  void push(const Entry& e) { entries.push_back(e); }
  bool empty() const { return entries.empty(); }
  std::size_t size() const { return entries.size(); }
  std::size_t number_of_marks() const { return marks.size(); }
  void mark() { marks.push_back(entries.size()); }
  // forgets the last mark, keeping its entries in the previous group
  void drop_mark() { CGAL_precondition(!marks.empty()); marks.pop_back(); }
  // forgets every entry and mark without undoing them (keeps the buffers allocated)
  void clear() { entries.clear(); marks.clear(); }

  // `undo(entry)` undoes one entry
  template <typename Undo>
  void rollback_to_mark(const Undo& undo)
  {
    const std::size_t keep = marks.empty() ? 0 : marks.back();
    if(!marks.empty()) marks.pop_back();
    while(entries.size() > keep)
    {
      undo(entries.back());
      entries.pop_back();
    }
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_UNDO_GROUPS_H
