// Wheelset tables (docs/tables.md "A wheelset table"): two pairs' tables with a roll axis joined
// into one file, its lookup placing both wheels from the wheelset's y and roll, against the
// wheelset call solving both wheels directly by the strip method (an independent answer: direct
// solves of the rolled wheels, not the tables); the derivatives by the chain rule through the
// placement; the file's errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/errors.hpp"
#include "input/wheelset_table.hpp"
#include "jobs/wheelset_table_make.hpp"
#include "support/table_fixture.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

namespace {

using namespace mh;

std::string tmp_path(const std::string& name) { return "/tmp/mhcontact_wstab_" + std::to_string(::getpid()) + "_" + name; }

std::string write_table(const ContactTableData& d, const std::string& name) {
  const std::string p = tmp_path(name);
  std::ofstream f(p, std::ios::binary);
  write_contact_table(d, f);
  return p;
}

// The worn measured pair (roll −3 … 3 mrad) on the left, S1002 on 60E1 1:40 (roll −4 … 4 mrad)
// on the right: two different pairs, each table made once for the file.
struct TwoPairs {
  const test::TestTable left{"worn-table-roll.json"};
  const test::TestTable right{"cases/s1002-60e1-roll-table.json"};
  std::string lp = write_table(left.made.data, "left.csv"), rp = write_table(right.made.data, "right.csv");
  std::string wp = tmp_path("wheelset.csv");
  TwoPairs() {
    std::ostringstream out, err;
    REQUIRE(wheelset_table_job(lp, rp, wp, out, err, true) == 0);
  }
  ~TwoPairs() {
    for (const auto& p : {lp, rp, wp}) std::remove(p.c_str());
  }
};

}  // namespace

TEST_CASE("a wheelset table places both wheels as the wheelset call does: forces within 1 % of the loads of its direct strip solves",
          "[tables]") {
  // Loads given (60 and 95 kN), the roll given (−2.5 and +1.5 mrad), y where both wheels are
  // inside their tables (the right one's t_Y −2 … 4 mm is about −y); none of the poses is a node
  // or a cell centre of either table. Tolerances: issue 39's for the normal force (1 % of Q) on
  // each wheel's lateral and vertical force; the roll moment within 1 % of Q times the 0.75 m
  // lever of the taping line.
  const TwoPairs t;
  const WheelsetTableLookup look(read_wheelset_table(t.wp));
  const WheelsetContact ws(t.left.pg.geo, t.right.pg.geo, t.left.cf.track, t.left.cf.material,
                           t.left.cf.method_options(), {});
  WheelsetWorkspace work;
  WheelsetResult r;
  WheelsetTableAnswer a;
  WheelsetPose pose;
  pose.Q_left = 60e3;
  pose.Q_right = 95e3;
  pose.solve_roll = false;
  WheelsetStepOptions so;
  so.derivatives = true;
  int compared = 0;
  double worst_F = 0, worst_M = 0, worst_dy = 0;
  // The roll shifts each wheel by about ±(z0 + R0) δ = 0.46 mm/mrad: y −2.3 … 2.7 mm at −2.5 mrad
  // (the right wheel's t_Y = −y + 1.15 mm), −4.3 … 0.7 mm at +1.5 mrad.
  for (double roll_mrad : {-2.5, 1.5})
    for (double y_mm = roll_mrad < 0 ? -2.3 : -4.3, y_end = y_mm + 5.5; y_mm < y_end; y_mm += 1.0) {
      pose.y = y_mm * 1e-3;
      pose.roll = roll_mrad * 1e-3;
      ws.step(pose, so, r, work);
      look.lookup({pose.y, pose.roll, pose.Q_left, pose.Q_right}, a);
      INFO("y = " << y_mm << " mm, roll " << roll_mrad << " mrad");
      REQUIRE(r.status == CaseStatus::Ok);
      REQUIRE(a.status == CaseStatus::Ok);
      for (int s = 0; s < 2; ++s) {
        const WheelResult& w = s == 0 ? r.left : r.right;
        const WheelsetTableWheel& tw = a.wheel[static_cast<std::size_t>(s)];
        const double Q = s == 0 ? pose.Q_left : pose.Q_right;
        INFO((s == 0 ? "left" : "right") << " wheel: t_Y = " << w.tY * 1e3 << " mm, δ = " << w.delta * 1e3 << " mrad");
        CHECK(tw.tY == Approx(w.tY).margin(1e-12));
        CHECK(tw.delta == Approx(w.delta).margin(1e-15));
        CHECK(std::fabs(tw.Fy - w.on_wheelset.F[1]) / Q < 0.01);
        CHECK(std::fabs(tw.Fz - w.on_wheelset.F[2]) / Q < 0.01);
        CHECK(std::fabs(tw.Mx - w.on_wheelset.M[0]) / (0.75 * Q) < 0.01);
        worst_F = std::max({worst_F, std::fabs(tw.Fy - w.on_wheelset.F[1]) / Q, std::fabs(tw.Fz - w.on_wheelset.F[2]) / Q});
        worst_M = std::max(worst_M, std::fabs(tw.Mx - w.on_wheelset.M[0]) / (0.75 * Q));
        ++compared;
      }
      CHECK(std::fabs(a.Fy - r.total.F[1]) / (pose.Q_left + pose.Q_right) < 0.01);
      CHECK(std::fabs(a.Mx - r.total.M[0]) / (0.75 * (pose.Q_left + pose.Q_right)) < 0.01);
      // The derivatives: the chain rule through both placements against central differences of
      // the table's own forces (steps 1 µm, 1 µrad, 1 N: the interpolant is C1, the difference
      // error far below the 1 % allowed).
      WheelsetTableAnswer p, m;
      auto fd = [&](double dy, double dr, double dql, double dqr) {
        look.lookup({pose.y + dy, pose.roll + dr, pose.Q_left + dql, pose.Q_right + dqr}, p);
        look.lookup({pose.y - dy, pose.roll - dr, pose.Q_left - dql, pose.Q_right - dqr}, m);
        return (p.Fy - m.Fy) / 2;
      };
      CHECK(a.dFy_dy == Approx(fd(1e-6, 0, 0, 0) / 1e-6).epsilon(0.01));
      CHECK(a.dFy_droll == Approx(fd(0, 1e-6, 0, 0) / 1e-6).epsilon(0.01));
      CHECK(a.wheel[0].dFy_dQ == Approx(fd(0, 0, 1, 0)).epsilon(0.01));
      CHECK(a.wheel[1].dFy_dQ == Approx(fd(0, 0, 0, 1)).epsilon(0.01));
      worst_dy = std::max(worst_dy, std::fabs(a.dFy_dy - r.dF_dy[1]) / std::fabs(r.dF_dy[1]));
    }
  CHECK(compared == 24);
  WARN("wheelset table vs the wheelset call (strips): forces within " << 100 * worst_F << " % of Q, Mx within "
       << 100 * worst_M << " % of 0.75 m Q; dFy/dy off the wheelset call's (central differences of direct solves, "
       << "0.01 mm steps) by up to " << 100 * worst_dy << " %");
}

TEST_CASE("wheelset table files: what is refused, with the file, line and rule", "[tables]") {
  const test::TestTable tab("worn-table-roll.json");
  const std::string lp = write_table(tab.made.data, "pair.csv"), wp = tmp_path("ws.csv");
  std::ostringstream out, err;
  REQUIRE(wheelset_table_job(lp, lp, wp, out, err, true) == 0);
  auto text = [](const std::string& p) {
    std::stringstream s;
    s << std::ifstream(p, std::ios::binary).rdbuf();
    return s.str();
  };
  auto write = [](const std::string& p, const std::string& t) { std::ofstream(p, std::ios::binary) << t; };
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string ws = text(wp), pair = text(lp);
  // The same pair on both sides: the file is its header and the pair's text twice, byte for byte.
  CHECK(ws.substr(ws.find('\n') + 1) == pair + pair);
  const WheelsetTableData d = read_wheelset_table(wp);
  CHECK(d.place[0].a == Approx(0.750).margin(1e-12));
  CHECK(d.place[1].H == Approx(d.place[0].H).margin(0));
  // One pair's table where a wheelset table is expected, and the other way round.
  CHECK_THAT(message([&] { read_wheelset_table(lp); }),
             Catch::Contains(lp + ":1") && Catch::Contains("this is one pair's table"));
  CHECK_THAT(message([&] { read_contact_table(wp); }), Catch::Contains("a wheelset table (two pairs' tables)"));
  // Truncated after the left pair: the line where the right one should start.
  const std::string cut = tmp_path("cut.csv");
  write(cut, ws.substr(0, ws.size() - pair.size()));
  const std::size_t lines = static_cast<std::size_t>(std::count(pair.begin(), pair.end(), '\n'));
  CHECK_THAT(message([&] { read_wheelset_table(cut); }),
             Catch::Contains(cut + ":" + std::to_string(lines + 2)) && Catch::Contains("right pair's table is missing"));
  // A pair table made before the placement was recorded.
  std::string old = pair;
  const std::size_t k = old.find(",\"wheelset_placement\"");
  REQUIRE(k != std::string::npos);
  old.erase(k, old.find('}', k) + 1 - k);
  const std::string oldp = tmp_path("old.csv");
  write(oldp, old);
  CHECK(read_contact_table(oldp).nT() == tab.made.data.nT());
  CHECK_THAT(message([&] { wheelset_table_job(oldp, lp, wp, out, err, true); }),
             Catch::Contains(oldp + ":1") && Catch::Contains("no wheelset_placement") && Catch::Contains("remake"));
  // Two methods on one wheelset.
  std::string other = pair;
  const std::size_t mk = other.rfind("\"method\":\"strips\"", other.find('\n'));  // the header's own, after its inputs
  REQUIRE(mk != std::string::npos);
  other.replace(mk, 17, "\"method\":\"auto\"");
  const std::string otherp = tmp_path("other.csv");
  write(otherp, other);
  CHECK_THAT(message([&] { wheelset_table_job(lp, otherp, wp, out, err, true); }),
             Catch::Contains("method must agree (left: strips)"));
  for (const auto& p : {lp, wp, cut, oldp, otherp}) std::remove(p.c_str());
}
