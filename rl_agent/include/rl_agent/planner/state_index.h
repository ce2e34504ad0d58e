/**
 * StateIndex: an open-addressing hash index from 64-bit state hashes to slot numbers, for the
 * planners' state tables (the keys live in the caller's records).
 *
 * Linear probing in a power-of-two array kept at most 70% full; deletion by backward shift
 * (Knuth, TAOCP vol. 3, §6.4, Algorithm R), so there are no tombstones and a lookup stops at
 * the first empty entry. Each entry holds the full hash, so a probe compares keys only when the
 * hashes match: a lookup touches one cache line of the index and, on a hit, the one record.
 * std::unordered_map, which this replaces in UctPlanner, chains nodes and compares the key
 * vectors of every node in the bucket through two pointers.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace rl_agent {

class StateIndex {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  /// The slot stored under `hash` for which `same(slot)` is true, or kNone.
  template <class Same>
  std::uint32_t find(std::uint64_t hash, Same same) const {
    if (entries_.empty()) return kNone;
    for (std::size_t i = hash & mask_;; i = (i + 1) & mask_) {
      const Entry& e = entries_[i];
      if (e.slot == kNone) return kNone;
      if (e.hash == hash && same(e.slot)) return e.slot;
    }
  }

  /// Adds `slot` under `hash` (the caller checked that its key is not present).
  void insert(std::uint64_t hash, std::uint32_t slot) {
    if ((size_ + 1) * 10 > entries_.size() * 7) grow();
    place(hash, slot);
    ++size_;
  }

  /// Removes `slot`, stored under `hash`. Returns false if it is not there.
  bool erase(std::uint64_t hash, std::uint32_t slot) {
    if (entries_.empty()) return false;
    std::size_t i = hash & mask_;
    for (;; i = (i + 1) & mask_) {
      if (entries_[i].slot == kNone) return false;
      if (entries_[i].slot == slot) break;
    }
    // Backward shift: move later entries of the probe run into the hole when their home
    // position does not lie cyclically in (hole, their position].
    for (std::size_t j = (i + 1) & mask_;; j = (j + 1) & mask_) {
      const Entry& e = entries_[j];
      if (e.slot == kNone) break;
      const std::size_t home = e.hash & mask_;
      const bool stays = i <= j ? (i < home && home <= j) : (i < home || home <= j);
      if (!stays) {
        entries_[i] = e;
        i = j;
      }
    }
    entries_[i].slot = kNone;
    --size_;
    return true;
  }

  std::size_t size() const { return size_; }

 private:
  struct Entry {
    std::uint64_t hash = 0;
    std::uint32_t slot = kNone;
  };

  void place(std::uint64_t hash, std::uint32_t slot) {
    std::size_t i = hash & mask_;
    while (entries_[i].slot != kNone) i = (i + 1) & mask_;
    entries_[i] = Entry{hash, slot};
  }

  void grow() {
    std::vector<Entry> old;
    old.swap(entries_);
    entries_.assign(old.empty() ? 64 : old.size() * 2, Entry{});
    mask_ = entries_.size() - 1;
    for (const Entry& e : old) {
      if (e.slot != kNone) place(e.hash, e.slot);
    }
  }

  std::vector<Entry> entries_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace rl_agent
