// --fail-on CLASSES and --fail-on-warning (jobs/sweep.hpp parse_fail_on, warnings_failure;
// docs/status.md): which warnings make a run exit 1, by hand-made counts.
#include <catch2/catch.hpp>

#include "contact/case_result.hpp"
#include "core/errors.hpp"
#include "jobs/sweep.hpp"

TEST_CASE("fail-on: warning classes, comma separated, an unknown class refused", "[run][fail_on]") {
  using V = std::vector<std::string>;
  CHECK(mh::parse_fail_on("off_profile") == V{"off_profile"});
  CHECK(mh::parse_fail_on("non_hertzian,off_profile,non_hertzian") == V{"non_hertzian", "off_profile"});
  CHECK(mh::parse_fail_on("cant,auto") == V{"cant", "auto"});
  for (const mh::WarningClassInfo& c : mh::warning_classes()) CHECK(mh::parse_fail_on(c.name) == V{c.name});
  // A misspelt class must not leave CI green: an input error that lists the classes.
  for (const char* bad : {"", "off-profile", "non_hertzian,", ",off_profile", "outside_validity", "ok"}) {
    CAPTURE(bad);
    try {
      mh::parse_fail_on(bad);
      FAIL("accepted");
    } catch (const mh::InputError& e) {
      CHECK(e.where() == "--fail-on");
      CHECK(e.hint().find("off_profile") != std::string::npos);
      CHECK(e.hint().find("cant") != std::string::npos);
    }
  }
}

TEST_CASE("fail-on: exit 1 only for the classes given, --fail-on-warning for any", "[run][fail_on]") {
  mh::SweepCounts counts;
  counts.with_warnings = 14;
  counts.warnings = {{"non_hertzian", 12}, {"flange_climb", 2}};
  mh::RunOptions opt;
  CHECK(mh::warnings_failure(opt, counts, 0).empty());  // neither option: warnings never fail a run
  CHECK(mh::warnings_failure(opt, counts, 1).empty());
  opt.fail_on = {"off_profile", "strip_outlier"};
  CHECK(mh::warnings_failure(opt, counts, 0).empty());
  opt.fail_on = {"off_profile", "non_hertzian", "flange_climb"};
  CHECK(mh::warnings_failure(opt, counts, 0) ==
        "mhcontact run: 12 cases with non_hertzian, 2 cases with flange_climb (--fail-on): exit 1\n");
  opt.fail_on = {"cant"};
  CHECK(mh::warnings_failure(opt, counts, 0).empty());
  CHECK(mh::warnings_failure(opt, counts, 3) == "mhcontact run: 3 cant warning(s) (--fail-on): exit 1\n");
  opt.fail_on.clear();
  opt.fail_on_warning = true;
  CHECK(mh::warnings_failure(opt, counts, 0) ==
        "mhcontact run: 14 cases with warnings, 0 cant warning(s) (--fail-on-warning): exit 1\n");
  CHECK(mh::warnings_failure(opt, mh::SweepCounts{}, 0).empty());
  CHECK_FALSE(mh::warnings_failure(opt, mh::SweepCounts{}, 1).empty());
}
