#pragma once
// The library's one "keep the last few, by key" cache: values that are costly to make and are
// asked for again by the same key (FFT plans by length, least-squares factorisations by shape).
// Small (a linear search over a handful of entries beats hashing at these sizes), most recently
// used last; once full it allocates only what a new value itself needs.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace mh {

/// The last `capacity` values made by get(), by key (Key with ==; Value movable). Not
/// thread-safe: one per thread or per object.
template <class Key, class Value>
class MruCache {
 public:
  explicit MruCache(std::size_t capacity) : capacity_(capacity > 0 ? capacity : 1) {}  ///< allocates nothing

  /// The value kept for `key`, now the most recently used; else `make()`'s (called with no
  /// argument), which takes the place of the least recently used one when the cache is full.
  template <class Make>
  Value& get(const Key& key, Make&& make) {
    auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.first == key; });
    if (it != entries_.end()) {
      std::rotate(it, it + 1, entries_.end());
      return entries_.back().second;
    }
    Value v = make();  // before anything is dropped: a throw leaves the cache as it was
    entries_.reserve(capacity_);  // once: a full cache then allocates nothing of its own
    if (entries_.size() >= capacity_) entries_.erase(entries_.begin());
    entries_.emplace_back(key, std::move(v));
    return entries_.back().second;
  }

  std::size_t size() const { return entries_.size(); }
  std::size_t capacity() const { return capacity_; }

 private:
  using Entry = std::pair<Key, Value>;
  std::size_t capacity_;
  std::vector<Entry> entries_;  ///< most recently used last
};

}  // namespace mh
