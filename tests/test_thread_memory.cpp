// The per-thread memory that keeps the exact stepper's responses (src/contact/thread_memory.hpp):
// what is kept is found again, what was never kept is not, and past its capacity it forgets
// everything at once, whatever the keys' hashes.
#include <catch2/catch.hpp>
#include <cstddef>

#include "contact/thread_memory.hpp"

using sweetspot::detail::ThreadMemory;

namespace {

// Every key in the same probe chain, so that lookups must walk past other keys.
struct Colliding {
  std::size_t operator()(int) const { return 7; }
};
struct Spread {
  std::size_t operator()(int key) const { return sweetspot::detail::bits_hash(key); }
};

}  // namespace

TEST_CASE("A thread's memory finds what it kept, only that, and forgets all past its capacity", "[exact]") {
  ThreadMemory<int, double, Colliding> memory(8);
  CHECK(memory.find(1) == nullptr);  // nothing kept yet
  for (int key = 0; key < 8; ++key) memory.keep(key) = 10.0 * key;
  for (int key = 0; key < 8; ++key) {
    const double* kept = memory.find(key);
    REQUIRE(kept != nullptr);
    CHECK(*kept == 10.0 * key);
  }
  CHECK(memory.find(8) == nullptr);
  int made = 0;
  CHECK(memory.get(3, [&] { return ++made, -1.0; }) == 30);  // kept: not made again
  CHECK(made == 0);
  // The ninth key finds the memory full: it is kept, and every earlier one forgotten.
  CHECK(memory.get(8, [&] { return ++made, 80.0; }) == 80);
  CHECK(made == 1);
  CHECK(*memory.find(8) == 80);
  for (int key = 0; key < 8; ++key) CHECK(memory.find(key) == nullptr);
  CHECK(memory.get(3, [&] { return ++made, 33.0; }) == 33);  // made anew
  CHECK(made == 2);

  ThreadMemory<int, double, Spread> large(1000);
  for (int key = 0; key < 1000; ++key) large.keep(key) = key + 0.5;
  for (int key = 0; key < 1000; ++key) CHECK(*large.find(key) == key + 0.5);
  CHECK(large.find(1000) == nullptr);
}
