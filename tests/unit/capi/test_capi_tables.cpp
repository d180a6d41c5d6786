// Contact tables through the C interface (include/mhcontact.h, "contact tables"; docs/tables.md):
// a table written by `mhcontact table` read by mhc_table_read, its lookups equal to the C++
// lookup field by field (values and derivatives), its ranges and header, and its errors.
#include <catch2/catch.hpp>

#include <mhcontact.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "cli.hpp"
#include "input/contact_table.hpp"
#include "input/wheelset_table.hpp"

TEST_CASE("C interface: a contact table read and looked up as the C++ lookup", "[tables][capi]") {
  const std::string path = "/tmp/mhcontact_capi_table_" + std::to_string(::getpid()) + ".csv";
  std::ostringstream out, err;
  // The shipped example: three tracks (two-point contact near flange onset), a coarse cell and
  // nodes without an answer (exit 1).
  const int rc = mh::run_cli({"table", std::string(MHCONTACT_SOURCE_DIR) + "/cases/s1002-60e1-table.json", "-o", path,
                              "--threads", "2", "-q"},
                             out, err);
  INFO(err.str());
  REQUIRE((rc == 0 || rc == 1));
  mhc_table* t = nullptr;
  REQUIRE(mhc_table_read(path.c_str(), &t) == MHC_OK);
  const mh::ContactTableLookup look(mh::read_contact_table(path));
  double t0, t1, q0, q1;
  REQUIRE(mhc_table_range(t, &t0, &t1, &q0, &q1) == MHC_OK);
  CHECK(t0 == Approx(-4e-3));
  CHECK(t1 == Approx(10e-3));
  CHECK(q0 == Approx(20e3));
  CHECK(q1 == Approx(140e3));
  CHECK(std::string(mhc_table_header(t)).find("\"schema\":\"mhcontact.table/2\"") != std::string::npos);
  mhc_table_result r;
  r.struct_size = sizeof r;
  mh::TableAnswer a;
  int multi = 0;
  for (double ty = -4e-3; ty <= 10e-3; ty += 0.137e-3)
    for (double Q : {20e3, 47e3, 99e3, 140e3}) {
      REQUIRE(mhc_table_lookup(t, ty, Q, &r) == MHC_OK);
      look.lookup(ty, Q, 0.0, a);
      REQUIRE(r.n_contacts == a.n_contacts);
      CHECK(r.coarse == (a.coarse ? 1 : 0));
      CHECK(std::string(mhc_status_name(r.status)) == mh::to_string(a.status));
      CHECK(r.Fy_N == a.Fy);
      multi += r.n_contacts > 1;
      for (int k = 0; k < std::min(r.n_contacts, MHC_MAX_CONTACTS); ++k) {
        const auto& c = a.c[static_cast<std::size_t>(k)];
        CHECK(r.contact[k].track == c.track);
        CHECK(r.contact[k].N_N == c.v[mh::kTabN]);
        CHECK(r.contact[k].y_rail_m == c.v[mh::kTabYRail]);
        CHECK(r.contact[k].C23 == c.v[mh::kTabC23]);
        CHECK(r.d_dtY[k].N_N == c.d_dtY[mh::kTabN]);
        CHECK(r.d_dQ[k].p_max_Pa == c.d_dQ[mh::kTabPmax]);
      }
    }
  CHECK(multi > 0);  // two-point contact is in the table
  // Outside the ranges: out_of_range, not an error.
  REQUIRE(mhc_table_lookup(t, 11e-3, 60e3, &r) == MHC_OK);
  CHECK(r.status == MHC_STATUS_OUT_OF_RANGE);
  CHECK(r.n_contacts == 0);
  // Errors.
  r.struct_size = sizeof r - 8;
  CHECK(mhc_table_lookup(t, 0, 60e3, &r) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("sizeof(mhc_table_result)") != std::string::npos);
  CHECK(mhc_table_lookup(nullptr, 0, 60e3, &r) == MHC_ERR_ARGUMENT);
  mhc_table_free(t);
  std::ofstream(path) << "tY_mm,Q_kN\n1,2\n";
  mhc_table* bad = nullptr;
  CHECK(mhc_table_read(path.c_str(), &bad) == MHC_ERR_INPUT);
  CHECK(bad == nullptr);
  CHECK(std::string(mhc_last_message()).find(path + ":1") != std::string::npos);
  CHECK(mhc_table_read("/nonexistent/table.csv", &bad) == MHC_ERR_INPUT);
  std::remove(path.c_str());
}

TEST_CASE("C interface: a table with a roll axis, looked up at a roll as the C++ lookup", "[tables][capi]") {
  // A small three-axis table of the worn measured pair (tests/data/tables/worn-table-roll.json's
  // pair, fewer nodes): mhc_table_lookup_rolled equals the C++ lookup with its d/droll; the
  // upright mhc_table_lookup is the lookup at roll 0; a caller with the layout before the roll
  // fields is served those.
  const std::string dir = std::string(MHCONTACT_SOURCE_DIR) + "/tests/data/tables/";
  std::ifstream in(dir + "worn-table-roll.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string c = text.str();
  const std::string from = "\"roll_mrad\": {";
  REQUIRE(c.find(from) != std::string::npos);
  const std::string case_path = "/tmp/mhcontact_capi_roll_case_" + std::to_string(::getpid()) + ".json";
  const std::string path = "/tmp/mhcontact_capi_table_roll_" + std::to_string(::getpid()) + ".csv";
  {
    // t_Y −2 ... 2 mm, the roll −2 ... 2 mrad.
    std::string s = c;
    s.replace(s.find("\"from\": -8"), 10, "\"from\": -2");
    s.replace(s.find("\"to\": 8"), 7, "\"to\": 2");
    s.replace(s.find("\"from\": -3"), 10, "\"from\": -2");
    s.replace(s.find("\"to\": 3"), 7, "\"to\": 2");
    for (std::size_t at; (at = s.find("\"../profiles/")) != std::string::npos;) s.replace(at + 1, 3, dir + "../");
    std::ofstream(case_path) << s;
  }
  std::ostringstream out, err;
  const int rc = mh::run_cli({"table", case_path, "-o", path, "--threads", "2", "-q", "--refine", "0"}, out, err);
  std::remove(case_path.c_str());
  INFO(err.str());
  REQUIRE(rc == 0);
  mhc_table* t = nullptr;
  REQUIRE(mhc_table_read(path.c_str(), &t) == MHC_OK);
  const mh::ContactTableLookup look(mh::read_contact_table(path));
  double r0, r1;
  int32_t nr = 0;
  REQUIRE(mhc_table_roll_range(t, &r0, &r1, &nr) == MHC_OK);
  CHECK(r0 == Approx(-2e-3));
  CHECK(r1 == Approx(2e-3));
  CHECK(nr == 5);
  mhc_table_result r;
  r.struct_size = sizeof r;
  mh::TableAnswer a;
  for (double ty : {-1.7e-3, 0.3e-3, 1.9e-3})
    for (double roll : {-1.9e-3, -0.2e-3, 0.0, 1.3e-3}) {
      REQUIRE(mhc_table_lookup_rolled(t, ty, 70e3, roll, &r) == MHC_OK);
      look.lookup(ty, 70e3, roll, a);
      REQUIRE(r.n_contacts == 1);
      REQUIRE(a.n_contacts == 1);
      CHECK(r.status == MHC_STATUS_OK);
      CHECK(r.off_roll == 0);
      CHECK(r.roll_rad == roll);
      CHECK(r.contact[0].p_max_Pa == a.c[0].v[mh::kTabPmax]);
      CHECK(r.d_droll[0].N_N == a.c[0].d_droll[mh::kTabN]);
      CHECK(r.d_droll[0].p_max_Pa == a.c[0].d_droll[mh::kTabPmax]);
      CHECK(r.d_droll[0].p_max_Pa != 0);  // the roll moves the peak pressure
      CHECK(r.dFy_droll_N_per_rad == a.dFy_droll);
    }
  // The upright lookup is the lookup at roll 0.
  mhc_table_result u;
  u.struct_size = sizeof u;
  REQUIRE(mhc_table_lookup(t, 0.3e-3, 70e3, &u) == MHC_OK);
  REQUIRE(mhc_table_lookup_rolled(t, 0.3e-3, 70e3, 0.0, &r) == MHC_OK);
  CHECK(u.contact[0].p_max_Pa == r.contact[0].p_max_Pa);
  // Outside the roll range: out_of_range.
  REQUIRE(mhc_table_lookup_rolled(t, 0.3e-3, 70e3, 2.5e-3, &r) == MHC_OK);
  CHECK(r.status == MHC_STATUS_OUT_OF_RANGE);
  // The layout before the roll fields: served up to d_dQ, nothing written after it.
  std::vector<unsigned char> old(sizeof(mhc_table_result), 0xAB);
  auto* o = reinterpret_cast<mhc_table_result*>(old.data());
  o->struct_size = offsetof(mhc_table_result, roll_rad);
  REQUIRE(mhc_table_lookup_rolled(t, 0.3e-3, 70e3, 1e-3, o) == MHC_OK);
  CHECK(o->n_contacts == 1);
  for (std::size_t b = offsetof(mhc_table_result, roll_rad); b < old.size(); ++b) REQUIRE(old[b] == 0xAB);

  // The wheelset table of this pair on both sides (`mhcontact table-wheelset`): its lookup equals
  // the C++ one, each wheel's answer that of its pair's table at its placed t_Y and roll.
  const std::string wpath = path + ".wheelset.csv";
  REQUIRE(mh::run_cli({"table-wheelset", path, path, "-o", wpath, "-q"}, out, err) == 0);
  mhc_wheelset_table* w = nullptr;
  REQUIRE(mhc_wheelset_table_read(wpath.c_str(), &w) == MHC_OK);
  CHECK(std::string(mhc_wheelset_table_header(w)).find("\"schema\":\"mhcontact.wheelset-table/1\"") != std::string::npos);
  const mh::WheelsetTableLookup wl(mh::read_wheelset_table(wpath));
  mhc_wheelset_table_result wr;
  wr.struct_size = sizeof wr;
  mh::WheelsetTableAnswer wa;
  for (double y : {-1.3e-3, 0.4e-3})
    for (double roll : {-1.1e-3, 0.7e-3}) {
      REQUIRE(mhc_wheelset_table_lookup(w, y, roll, 70e3, 85e3, &wr) == MHC_OK);
      wl.lookup({y, roll, 70e3, 85e3}, wa);
      CHECK(wr.status == MHC_STATUS_OK);
      CHECK(wr.Fy_N == wa.Fy);
      CHECK(wr.Mx_Nm == wa.Mx);
      CHECK(wr.dFy_droll_N_per_rad == wa.dFy_droll);
      CHECK(wr.wheel_dFy_dQ[1] == wa.wheel[1].dFy_dQ);
      for (int s = 0; s < 2; ++s) {
        CHECK(wr.wheel[s].tY_m == wa.wheel[static_cast<std::size_t>(s)].tY);
        CHECK(wr.wheel[s].roll_rad == (s == 0 ? roll : -roll));
        REQUIRE(mhc_table_lookup_rolled(t, wr.wheel[s].tY_m, s == 0 ? 70e3 : 85e3, wr.wheel[s].roll_rad, &r) == MHC_OK);
        CHECK(wr.wheel[s].contact[0].p_max_Pa == r.contact[0].p_max_Pa);
        CHECK(wr.wheel[s].d_droll[0].N_N == r.d_droll[0].N_N);
        CHECK(wr.wheel_Fy_N[s] == (s == 0 ? -1 : 1) * r.Fy_N);
      }
    }
  // Beyond the wheels' tables (t_Y −2 … 2 mm): out_of_range, not an error.
  REQUIRE(mhc_wheelset_table_lookup(w, 2.5e-3, 0.0, 70e3, 85e3, &wr) == MHC_OK);
  CHECK(wr.status == MHC_STATUS_OUT_OF_RANGE);
  CHECK(wr.wheel[0].status == MHC_STATUS_OUT_OF_RANGE);
  CHECK(wr.wheel[0].n_contacts == 0);
  double lo = 0, hi = 0;
  REQUIRE(mhc_wheelset_table_pair_range(w, 1, &lo, &hi, nullptr, nullptr, nullptr, nullptr) == MHC_OK);
  CHECK(hi == Approx(2e-3));
  CHECK(mhc_wheelset_table_pair_range(w, 2, &lo, &hi, nullptr, nullptr, nullptr, nullptr) == MHC_ERR_ARGUMENT);
  wr.struct_size = sizeof wr - 8;
  CHECK(mhc_wheelset_table_lookup(w, 0.0, 0.0, 70e3, 85e3, &wr) == MHC_ERR_ARGUMENT);
  CHECK(std::string(mhc_last_message()).find("sizeof(mhc_wheelset_table_result)") != std::string::npos);
  mhc_wheelset_table* bad = nullptr;
  CHECK(mhc_wheelset_table_read(path.c_str(), &bad) == MHC_ERR_INPUT);
  CHECK(bad == nullptr);
  CHECK(std::string(mhc_last_message()).find("one pair's table") != std::string::npos);
  mhc_wheelset_table_free(w);
  std::remove(wpath.c_str());
  mhc_table_free(t);
  std::remove(path.c_str());
}
