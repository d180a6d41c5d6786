// A wheelset table: the reader and the lookup placing both wheels (wheelset_table.hpp;
// docs/tables.md "A wheelset table").
#include "input/wheelset_table.hpp"

#include <cmath>
#include <fstream>

#include "core/errors.hpp"
#include "geometry/rolled_gap.hpp"

namespace mh {

WheelsetPlacement table_placement(const nlohmann::json& header, const std::string& where) {
  const auto it = header.find("wheelset_placement");
  if (it == header.end() || !it->is_object())
    throw InputError(where, "", "the table's header has no wheelset_placement (a table made before it was recorded)",
                     "remake the table with this mhcontact (`mhcontact table CASE.json -o FILE`)");
  WheelsetPlacement p;
  try {
    p.a = it->at("a_mm").get<double>() * 1e-3;
    p.H = it->at("axle_height_mm").get<double>() * 1e-3;
    p.rail_offset = it->at("rail_offset_mm").get<double>() * 1e-3;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where, it->dump(), std::string("wheelset_placement needs a_mm, axle_height_mm and rail_offset_mm: ") + e.what(),
                     "remake the table with this mhcontact");
  }
  if (!(std::isfinite(p.a) && p.a > 0 && std::isfinite(p.H) && p.H > 0 && std::isfinite(p.rail_offset)))
    throw InputError(where, it->dump(), "wheelset_placement: a_mm and axle_height_mm must be positive, all finite",
                     "remake the table with this mhcontact");
  return p;
}

WheelsetTableData read_wheelset_table(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the wheelset table file", "check the path");
  WheelsetTableData w;
  std::string line;
  if (!std::getline(in, line) || line.size() < 2 || line[0] != '#')
    throw InputError(at_line(path, 1), "", "a wheelset table starts with its JSON header line `# {...}`",
                     "write it with `mhcontact table-wheelset LEFT.csv RIGHT.csv -o FILE`");
  try {
    w.header = nlohmann::json::parse(line.substr(1));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(at_line(path, 1), "", std::string("the JSON header does not parse: ") + e.what());
  }
  if (!w.header.is_object() || w.header.value("schema", std::string()) != kWheelsetTableSchema)
    throw InputError(at_line(path, 1), w.header.is_object() ? w.header.value("schema", std::string("(none)")) : "",
                     std::string("the header's schema must be ") + kWheelsetTableSchema,
                     w.header.is_object() && w.header.value("schema", std::string()) == kContactTableSchema
                         ? "this is one pair's table: read it with read_contact_table / mhc_table_read, or combine "
                           "two with `mhcontact table-wheelset`"
                         : "write it with `mhcontact table-wheelset LEFT.csv RIGHT.csv -o FILE`");
  std::size_t ln = 1;
  for (int s = 0; s < 2; ++s) {
    const std::size_t hl = ln + 1;
    if (in.peek() == std::char_traits<char>::eof())
      throw InputError(at_line(path, hl), "", std::string("the ") + (s ? "right" : "left") + " pair's table is missing",
                       "the file is truncated: write it again with `mhcontact table-wheelset`");
    w.pair[static_cast<std::size_t>(s)] = read_contact_table(in, path, ln);
    w.place[static_cast<std::size_t>(s)] = table_placement(w.pair[static_cast<std::size_t>(s)].header, at_line(path, hl));
  }
  if (in.peek() != std::char_traits<char>::eof())
    throw InputError(at_line(path, ln + 1), "", "a wheelset table holds two pairs' tables (left, right), no more",
                     "write it again with `mhcontact table-wheelset`");
  return w;
}

WheelsetTableLookup::WheelsetTableLookup(WheelsetTableData d)
    : header_(std::move(d.header)),
      pair_{ContactTableLookup(std::move(d.pair[0])), ContactTableLookup(std::move(d.pair[1]))},
      place_(d.place) {}

void WheelsetTableLookup::place(int s, double y, double roll, double& tY, double& delta) const {
  const WheelsetPlacement& P = place_[static_cast<std::size_t>(s)];
  const double sigma = s == 0 ? 1.0 : -1.0;
  delta = sigma * roll;
  tY = rolled_wheel_tY(sigma * y, delta, P.a, P.H);
}

void WheelsetTableLookup::lookup(const WheelsetTablePose& p, WheelsetTableAnswer& out) const {
  out.status = CaseStatus::Ok;
  out.Fy = out.Fz = out.Mx = out.dFy_dy = out.dFy_droll = 0;
  for (int s = 0; s < 2; ++s) {
    const std::size_t si = static_cast<std::size_t>(s);
    const WheelsetPlacement& P = place_[si];
    const double sigma = s == 0 ? 1.0 : -1.0;
    WheelsetTableWheel& w = out.wheel[si];
    place(s, p.y, p.roll, w.tY, w.delta);
    pair_[si].lookup(w.tY, s == 0 ? p.Q_left : p.Q_right, w.delta, w.pair);
    const TableAnswer& a = w.pair;
    if (status_severity(a.status) > status_severity(out.status)) out.status = a.status;
    // Forces on the wheel in its pair's frame: −N sin γ along y (towards the field side), N cos γ up.
    w.Fy = -sigma * a.Fy;
    w.Fz = a.Fz;
    double m = P.a * a.Fz;
    const int n = a.n_contacts < kTableMaxContacts ? a.n_contacts : kTableMaxContacts;
    for (int k = 0; k < n; ++k) {
      const auto& v = a.c[static_cast<std::size_t>(k)].v;
      m += v[kTabN] * (v[kTabYWheel] * std::cos(v[kTabGamma]) - v[kTabRRoll] * std::sin(v[kTabGamma]));
    }
    w.Mx = sigma * m;
    // dt_Y/dy = σ, dt_Y/dφ = σ (H cos δ − a sin δ), dδ/dφ = σ; F_y = −σ Fy_pair.
    const double dtY_dphi = sigma * (P.H * std::cos(w.delta) - P.a * std::sin(w.delta));
    w.dFy_dy = -a.dFy_dtY;
    w.dFy_droll = -sigma * (a.dFy_dtY * dtY_dphi + a.dFy_droll * sigma);
    w.dFy_dQ = -sigma * a.dFy_dQ;
    out.Fy += w.Fy;
    out.Fz += w.Fz;
    out.Mx += w.Mx;
    out.dFy_dy += w.dFy_dy;
    out.dFy_droll += w.dFy_droll;
  }
}

}  // namespace mh
