// The fast fixed-digit number path (cells::general_digits) writes exactly what
// std::to_chars(general, d) (printf %.*g) writes, for every digit count, on random and edge values.
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "output/cells.hpp"

using namespace mh;

namespace {
std::string slow(double v, int d) {
  char b[64];
  return std::string(b, std::to_chars(b, b + sizeof b, v, std::chars_format::general, d).ptr);
}
std::string fast(double v, int d) {
  char b[64];
  return std::string(b, cells::general_digits(b, v, d));
}
}  // namespace

TEST_CASE("general_digits equals to_chars(general, d) on edge values") {
  const double edge[] = {0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 9.5, 0.95, 99.5, 999.99995, 9999999999.5,
                         1e-5, 1e-4, 9.99999999995e-5, 1e15, 1e16, 1e17, 123456789012.0, 1e-300, 5e-324,
                         1.7976931348623157e308, 2.5, 0.125, 1.0 / 3, 2.0 / 3, 6.6, 6.6000000000000005,
                         std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN()};
  for (int d = 1; d <= 17; ++d)
    for (double v : edge) {
      INFO("v = " << slow(v, 17) << ", d = " << d);
      CHECK(fast(v, d) == slow(v, d));
    }
}

TEST_CASE("general_digits equals to_chars(general, d) on random values") {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> mant(-10, 10);
  std::uniform_int_distribution<int> ex(-30, 30);
  std::uniform_int_distribution<int> dd(1, 17);
  int bad = 0;
  for (int i = 0; i < 2000000 && bad < 5; ++i) {
    double v;
    if (i % 3 == 0) {  // arbitrary bit patterns (finite)
      std::uint64_t u = rng();
      std::memcpy(&v, &u, sizeof v);
      if (!std::isfinite(v)) continue;
    } else if (i % 3 == 1) {  // short decimals, the midpoint case of the fast path
      v = std::round(mant(rng) * 1e6) / 1e6 * std::pow(10.0, ex(rng) / 3);
    } else {
      v = mant(rng) * std::pow(10.0, ex(rng));
    }
    const int d = i % 2 ? 10 : dd(rng);
    if (fast(v, d) != slow(v, d)) {
      ++bad;
      FAIL_CHECK("v = " << slow(v, 17) << ", d = " << d << ": fast " << fast(v, d) << " vs " << slow(v, d));
    }
  }
  CHECK(bad == 0);
}

TEST_CASE("num_repeated writes what num writes, across digit settings and cache collisions") {
  // The cache is keyed by the bits and the digits: a value seen at 10 digits must not come back
  // when 4 are asked, and values sharing a slot must not return each other's text.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mant(-10, 10);
  std::vector<double> vals = {0.0, -0.0, 1.0, INFINITY, -INFINITY, 6.6, 1.0 / 3};
  for (int i = 0; i < 5000; ++i) vals.push_back(mant(rng) * std::pow(10.0, static_cast<int>(rng() % 20) - 10));
  for (int d : {10, 4, 0, 17, 10}) {
    cells::DigitsScope scope(d);
    for (int pass = 0; pass < 2; ++pass)  // the second pass reads from the cache
      for (double v : vals) {
        std::string a, b;
        cells::num(a, v);
        cells::num_repeated(b, v);
        INFO("v = " << slow(v, 17) << ", digits " << d);
        REQUIRE(a == b);
      }
  }
}

// RFC 4180 (section 2, rules 6 and 7): a cell holding a comma, a double quote or a line break is
// enclosed in double quotes, its quotes doubled; any other cell as it is.
// Break seen to fail: the line break left out of the characters that need quotes.
TEST_CASE("csv_text quotes a cell as RFC 4180 asks, and only then") {
  struct Row { const char* in; const char* out; };
  const Row rows[] = {
      {"", ""},
      {"ok", "ok"},
      {"non_hertzian:ellipse=2:kink_ratio=0.31>0.1;interacting", "non_hertzian:ellipse=2:kink_ratio=0.31>0.1;interacting"},
      {"a, b", "\"a, b\""},
      {"say \"no\"", "\"say \"\"no\"\"\""},
      {"\"", "\"\"\"\""},
      {"two\nlines", "\"two\nlines\""},
      {"tab\there; semi", "tab\there; semi"},
  };
  for (const Row& r : rows) {
    std::string s = "x,";
    mh::cells::csv_text(s, r.in);
    CHECK(s == std::string("x,") + r.out);
  }
}
