// Contact tables through the C interface (include/mhcontact.h, "contact tables"; docs/tables.md):
// a table written by `mhcontact table` read by mhc_table_read, its lookups equal to the C++
// lookup field by field (values and derivatives), its ranges and header, and its errors.
#include <catch2/catch.hpp>

#include <mhcontact.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "cli.hpp"
#include "input/contact_table.hpp"

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
  CHECK(std::string(mhc_table_header(t)).find("\"schema\":\"mhcontact.table/1\"") != std::string::npos);
  mhc_table_result r;
  r.struct_size = sizeof r;
  mh::TableAnswer a;
  int multi = 0;
  for (double ty = -4e-3; ty <= 10e-3; ty += 0.137e-3)
    for (double Q : {20e3, 47e3, 99e3, 140e3}) {
      REQUIRE(mhc_table_lookup(t, ty, Q, &r) == MHC_OK);
      look.lookup(ty, Q, a);
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
