// JsonRecord (lib/output/json_record.hpp) writes what nlohmann::ordered_json's compact dump()
// writes for the same values, byte for byte: the reference is nlohmann's serializer itself, on
// numbers at the edges of its shortest form (0, −0, integers, 1e-5, 1e21, subnormals, not
// finite), integers at their limits, text needing escapes (quotes, backslashes, control
// characters, UTF-8), and objects and arrays nested and empty.
// Break seen to fail: the backslash left unescaped in string_body.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "output/json_record.hpp"

namespace {

using ojson = nlohmann::ordered_json;

const std::vector<double> kDoubles = {0.0,
                                      -0.0,
                                      1.0,
                                      -3.0,
                                      0.1,
                                      0.102,
                                      123.456,
                                      1e-5,
                                      -2.5e-7,
                                      1e21,
                                      1e22,
                                      123456789012345680.0,
                                      6.02214076e23,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::min(),
                                      std::numeric_limits<double>::max(),
                                      std::nextafter(1.0, 2.0),
                                      1.0 / 3.0};

const std::vector<std::string> kTexts = {"",
                                         "ok",
                                         "outside the validity of the method: non_hertzian (see warnings)",
                                         "say \"no\"",
                                         "C:\\path\\file",
                                         "two\nlines\tand\r\b\f",
                                         std::string("nul\0byte", 8),
                                         "\x01\x1f",
                                         "del \x7f",
                                         "p0 \xc2\xb5m and \xe2\x89\xa5 3.9 \xcf\x83_y"};

}  // namespace

TEST_CASE("JsonRecord writes what nlohmann's dump() writes", "[output][json]") {
  SECTION("numbers") {
    for (double v : kDoubles)
      for (double sgn : {1.0, -1.0}) {
        const double x = sgn * v;
        std::string s;
        mh::JsonRecord j{s};
        j.number(x);
        CHECK(s == ojson(x).dump());
      }
    for (double x : {std::nan(""), double(INFINITY), -double(INFINITY)}) {
      std::string s;
      mh::JsonRecord j{s};
      j.number(x);
      CHECK(s == ojson(nullptr).dump());
    }
  }
  SECTION("integers, booleans, null") {
    for (long long i : {0LL, 7LL, -7LL, 1234567890123LL, std::numeric_limits<long long>::max(),
                        std::numeric_limits<long long>::min()}) {
      std::string s;
      mh::JsonRecord j{s};
      j.integer(i);
      CHECK(s == ojson(i).dump());
    }
    // Case numbers and counts are unsigned in the tree dump() wrote; written as integers.
    for (std::uint64_t u : {std::uint64_t{0}, std::uint64_t{9}, std::uint64_t{10}, std::uint64_t{1000000},
                            std::uint64_t{std::numeric_limits<long long>::max()}}) {
      std::string s;
      mh::JsonRecord j{s};
      j.integer(static_cast<long long>(u));
      CHECK(s == ojson(u).dump());
    }
    std::string s;
    mh::JsonRecord j{s};
    j.begin_array();
    j.boolean(true);
    j.boolean(false);
    j.null();
    j.end_array();
    CHECK(s == ojson::array({true, false, nullptr}).dump());
  }
  SECTION("text") {
    for (const std::string& t : kTexts) {
      INFO(t);
      std::string s;
      mh::JsonRecord j{s};
      j.string(t);
      CHECK(s == ojson(t).dump());
    }
  }
  SECTION("a record: members in order, nested and empty containers") {
    ojson ref;
    std::string s;
    mh::JsonRecord j{s};
    j.begin_object();
    j.key("case"); j.integer(42); ref["case"] = std::uint64_t{42};
    j.key("tY_mm"); j.number(-6.0); ref["tY_mm"] = -6.0;
    j.key("status"); j.string("ok"); ref["status"] = "ok";
    j.key("iterations"); j.null(); ref["iterations"] = nullptr;
    j.key("warnings"); j.begin_array(); ref["warnings"] = ojson::array();
    for (const std::string& t : kTexts) { j.string(t); ref["warnings"].push_back(t); }
    j.end_array();
    j.key("empty"); j.begin_array(); j.end_array(); ref["empty"] = ojson::array();
    j.key("ellipses"); j.begin_array(); ref["ellipses"] = ojson::array();
    for (int e = 0; e < 3; ++e) {
      ojson o;
      j.begin_object();
      j.key("ellipse"); j.integer(e); o["ellipse"] = e;
      j.key("p0_MPa"); j.number(kDoubles[static_cast<std::size_t>(e) + 5]); o["p0_MPa"] = kDoubles[static_cast<std::size_t>(e) + 5];
      j.key("inner"); j.begin_object(); j.end_object(); o["inner"] = ojson::object();
      j.key("valid"); j.boolean(e != 1); o["valid"] = e != 1;
      j.end_object();
      ref["ellipses"].push_back(o);
    }
    j.end_array();
    const std::string long_key(100, 'k');  // longer than key()'s buffer
    j.key(long_key.c_str()); j.number(1.5); ref[long_key] = 1.5;
    j.key("patches"); j.begin_array(); j.end_array(); ref["patches"] = ojson::array();
    j.end_object();
    CHECK(s == ref.dump());
  }
}
