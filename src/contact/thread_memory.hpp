#pragma once
// Values a thread remembers because they are costly to make and recur from impact to impact (a
// mode's response to a step, its free rotations, an interpolant's basis): kept by key until the
// memory holds more than its capacity, then forgotten at once (bounded, without eviction
// bookkeeping). Each thread has its own, so results never depend on another thread's work.
// Capacities are a few MB: what recurs is mostly one bat's (its ~100 modes at ~10 step lengths,
// while a study's points on it run), and a memory that outgrows the core's caches costs a cache
// miss at every lookup (the wood study ran 7 % slower with memories ten times larger).
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweetspot::detail {

// A hash of doubles' bits, a multiplication each (std::hash<double> hashes a double's bytes).
template <class... Doubles>
std::size_t bits_hash(Doubles... x) {
  std::size_t h = 0;
  ((h = h * 31 + (std::bit_cast<std::uint64_t>(static_cast<double>(x)) * 0x9E3779B97F4A7C15ull >> 7)), ...);
  return h;
}

// The hash of h followed by a range of doubles (a set of modes' frequencies, their damping).
template <class Range>
std::size_t hash_range(std::size_t h, const Range& values) {
  for (const double x : values) h = h * 31 + bits_hash(x);
  return h;
}

// An open-addressing table, each value beside its key: a lookup is one probe into one array
// (a node-based map's bucket, node and value are apart, a cache miss each, and every insert an
// allocation). At most half full, so probes stay short; forgetting everything is one increment.
template <class Key, class Value, class Hash>
class ThreadMemory {
 public:
  explicit ThreadMemory(std::size_t capacity) : capacity_(capacity), mask_(std::bit_ceil(2 * capacity) - 1) {}

  // The value kept for `key`, made by make() the first time.
  template <class Make>
  const Value& get(const Key& key, Make make) {
    Slot& s = place(key);
    if (!holds(s)) {
      s.value = make();
      s.generation = generation_;
    }
    return s.value;
  }
  // The value kept for `key`, or none; and a place to keep one (made apart, several at once).
  const Value* find(const Key& key) const {
    if (slots_.empty()) return nullptr;
    for (std::size_t i = Hash()(key) & mask_;; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (!holds(s)) return nullptr;
      if (s.key == key) return &s.value;
    }
  }
  Value& keep(const Key& key) {
    Slot& s = place(key);
    s.generation = generation_;
    return s.value;
  }

 private:
  struct Slot {
    Key key{};
    std::uint64_t generation = 0;  // the memory's generation when kept; older ones are forgotten
    Value value{};
  };
  bool holds(const Slot& s) const { return s.generation == generation_; }
  // The slot holding `key`, or the free one it goes in (its key set, counted as kept); a new key
  // finding the memory full is the first of a new generation.
  Slot& place(const Key& key) {
    if (slots_.empty()) slots_.resize(mask_ + 1);
    for (std::size_t i = Hash()(key) & mask_;; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (holds(s) && s.key == key) return s;
      if (holds(s)) continue;
      if (size_ >= capacity_) {
        ++generation_, size_ = 0;
        return place(key);
      }
      s.key = key;
      ++size_;
      return s;
    }
  }

  std::size_t capacity_, mask_, size_ = 0;
  std::uint64_t generation_ = 1;
  std::vector<Slot> slots_;
};

}  // namespace sweetspot::detail
