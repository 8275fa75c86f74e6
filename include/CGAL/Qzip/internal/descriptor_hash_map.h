// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
#ifndef CGAL_QZIP_INTERNAL_DESCRIPTOR_HASH_MAP_H
#define CGAL_QZIP_INTERNAL_DESCRIPTOR_HASH_MAP_H

#include <CGAL/license/Qzip.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Qzip {
namespace internal {

// A hash map from mesh descriptors to small values for a few hundred entries, cleared and filled again
// many times: open addressing with linear probing in one array, which `clear()` empties in constant time
// (an entry belongs to the map when its stamp is the current one) and keeps allocated, so that a map
// reused from call to call allocates nothing.
template <typename Key, typename Value>
class Descriptor_hash_map
{
  struct Slot { Key key; Value value; unsigned stamp = 0; };
  std::vector<Slot> slots;  // 2^bits of them, at most half full
  int bits = 0;
  unsigned current = 1;
  std::size_t entries = 0;

  // boost::hash of an index is the index itself, and the descriptors of a neighbourhood are close to
  // each other: Fibonacci hashing spreads them (the high bits of the product)
  std::size_t home(const Key& k) const
  {
    const std::uint64_t h = std::uint64_t(boost::hash<Key>()(k)) * 0x9E3779B97F4A7C15ull;
    return std::size_t(h >> (64 - bits));
  }

  void grow()
  {
    std::vector<Slot> old;
    old.swap(slots);
    bits = (std::max)(6, bits + 1);
    slots.assign(std::size_t(1) << bits, Slot());
    const unsigned live = current;
    current = 1;
    entries = 0;
    for(const Slot& s : old)
      if(s.stamp == live) insert(s.key, s.value);
  }

public:
  // forgets every entry
  void clear()
  {
    entries = 0;
    if(++current == 0) // the stamps wrapped around: no slot may look current
    {
      for(Slot& s : slots) s.stamp = 0;
      current = 1;
    }
  }

  std::size_t size() const { return entries; }

  // the value of `k`, and whether it was absent (then inserted with `v`)
  std::pair<Value*, bool> insert(const Key& k, const Value& v)
  {
    if(2 * (entries + 1) > slots.size()) grow();
    for(std::size_t i = home(k);; i = (i + 1) & (slots.size() - 1))
    {
      Slot& s = slots[i];
      if(s.stamp != current) { s.key = k; s.value = v; s.stamp = current; ++entries; return { &s.value, true }; }
      if(s.key == k) return { &s.value, false };
    }
  }

  // the value of `k`, or nullptr
  const Value* find(const Key& k) const
  {
    if(slots.empty()) return nullptr;
    for(std::size_t i = home(k);; i = (i + 1) & (slots.size() - 1))
    {
      const Slot& s = slots[i];
      if(s.stamp != current) return nullptr;
      if(s.key == k) return &s.value;
    }
  }
};

} // namespace internal
} // namespace Qzip
} // namespace CGAL

#endif // CGAL_QZIP_INTERNAL_DESCRIPTOR_HASH_MAP_H
