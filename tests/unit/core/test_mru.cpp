// MruCache (lib/core/mru.hpp): a key met again returns its value without making one, the least
// recently used goes when the cache is full, and a make() that throws leaves the cache as it was.
#include <catch2/catch.hpp>

#include <memory>
#include <stdexcept>
#include <string>

#include "core/mru.hpp"

TEST_CASE("MruCache keeps the last values by key and drops the least recently used", "[core]") {
  mh::MruCache<int, std::unique_ptr<std::string>> c(3);
  int made = 0;
  auto get = [&](int k) -> const std::string& {
    return *c.get(k, [&] {
      ++made;
      return std::make_unique<std::string>("v" + std::to_string(k));
    });
  };
  CHECK(get(1) == "v1");
  CHECK(get(2) == "v2");
  CHECK(get(3) == "v3");
  CHECK(made == 3);
  const std::string* one = &get(1);  // a hit: now the most recently used, nothing made
  CHECK(made == 3);
  CHECK(get(4) == "v4");  // full: 2, the least recently used, goes
  CHECK(made == 4);
  CHECK(c.size() == 3);
  CHECK(&get(1) == one);  // 1 stayed, the same object
  get(3);
  CHECK(made == 4);
  get(2);  // made again; 4 is now the least recently used and went
  CHECK(made == 5);
  get(4);
  CHECK(made == 6);
  // A make() that throws: nothing dropped, nothing added.
  CHECK_THROWS_AS(c.get(9, []() -> std::unique_ptr<std::string> { throw std::runtime_error("no"); }), std::runtime_error);
  CHECK(c.size() == 3);
  get(4);
  get(2);
  CHECK(made == 6);
}
