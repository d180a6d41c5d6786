// --pressure-cases (jobs/sweep.hpp CaseSelection): parsing, membership and counting by hand.
#include <catch2/catch.hpp>

#include "core/errors.hpp"
#include "jobs/sweep.hpp"

TEST_CASE("case selection: numbers and ranges, merged, counted over a slice", "[run][pressure_cases]") {
  const mh::CaseSelection s = mh::parse_case_selection("40-42,7,41,43,100-100");
  REQUIRE(s.ranges.size() == 3);  // 7 | 40-43 (41 inside, 43 touching) | 100
  CHECK(s.contains(7));
  CHECK(s.contains(43));
  CHECK_FALSE(s.contains(44));
  CHECK_FALSE(s.contains(0));
  CHECK(s.largest() == 100);
  CHECK(s.count_in(0, 1000) == 6);
  CHECK(s.count_in(41, 100) == 3);   // 41, 42, 43
  CHECK(s.count_in(8, 40) == 0);
  const mh::CaseSelection all;
  CHECK(all.all());
  CHECK(all.contains(123456789));
  CHECK(all.count_in(10, 25) == 15);
  for (const char* bad : {"", "7-3", "a", "1,,2", "-1", "3-", "18446744073709551616"})
    CHECK_THROWS_AS(mh::parse_case_selection(bad), mh::InputError);
}
