// --shard K/N --shard-sizes (jobs/shards.hpp, shard_slice): the slices by hand, their tiling and
// their shares on lists up to 2^64 − 1 units and 100,000 shards.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/errors.hpp"
#include "jobs/shards.hpp"

using mh::ShardSizes;
using mh::shard_slice;

TEST_CASE("shard slices: tapered by hand on cases/fleet.json's 396 cases in 10 shards", "[run][shards]") {
  // C(j) = j (21 − j) / 2: 0, 10, 19, 27, 34, 40, 45, 49, 52, 54, 55; first = ⌊396 C(K−1) / 55⌋.
  const std::uint64_t first[] = {0, 72, 136, 194, 244, 288, 324, 352, 374, 388, 396};
  for (unsigned K = 1; K <= 10; ++K) {
    const mh::ShardSlice s = shard_slice(396, K, 10, ShardSizes::Tapered);
    CHECK(s.first == first[K - 1]);
    CHECK(s.end == first[K]);
  }
  // Equal slices as before: ⌊(K − 1) 396 / 10⌋.
  CHECK(shard_slice(396, 3, 10).first == 79);
  CHECK(shard_slice(396, 3, 10).end == 118);
  CHECK(shard_slice(396, 1, 1, ShardSizes::Tapered).end == 396);
  CHECK(std::string(mh::to_string(mh::parse_shard_sizes("tapered"))) == "tapered");
  CHECK(mh::parse_shard_sizes("equal") == ShardSizes::Equal);
  CHECK_THROWS_AS(mh::parse_shard_sizes("geometric"), mh::InputError);
}

TEST_CASE("shard slices tile the list, each within one unit of its share", "[run][shards]") {
  const std::uint64_t big = std::numeric_limits<std::uint64_t>::max();
  for (const std::uint64_t units : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{7}, std::uint64_t{19212},
                                    std::uint64_t{1} << 40, big})
    for (const unsigned N : {1u, 2u, 3u, 16u, 1000u, 100000u})
      for (const ShardSizes sizes : {ShardSizes::Equal, ShardSizes::Tapered}) {
        std::uint64_t expect = 0;
        const long double CN = static_cast<long double>(N) * (N + 1) / 2;
        int off = 0;
        for (unsigned K = 1; K <= N; ++K) {
          const mh::ShardSlice s = shard_slice(units, K, N, sizes);
          if (s.first != expect || s.end < s.first) ++off;
          expect = s.end;
          if (sizes == ShardSizes::Tapered && units < (std::uint64_t{1} << 50)) {
            const long double share = static_cast<long double>(units) * (N - K + 1) / CN;
            if (std::fabs(static_cast<long double>(s.end - s.first) - share) >= 1) ++off;
          }
        }
        INFO("units " << units << ", N " << N << ", " << mh::to_string(sizes));
        CHECK(off == 0);
        CHECK(expect == units);
      }
}
