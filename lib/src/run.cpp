#include "mhcontact/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <memory>
#include <ostream>
#include <thread>
#include <vector>

#include "mhcontact/errors.hpp"
#include "mhcontact/manifest.hpp"
#include "mhcontact/numfmt.hpp"
#include "mhcontact/output_file.hpp"
#include "mhcontact/solver.hpp"
#include "mhcontact/units.hpp"

namespace mh {

namespace {

constexpr const char* kSchema = "mhcontact.results/1";
constexpr const char* kGeometrySchema = "mhcontact.geometry/1";

// Numbers: shortest round-trip; radii of straight profiles are "inf" in CSV, null in JSON.
inline void num(std::string& s, double v) { append_number(s, v); }
inline void jnum(std::string& s, double v) {
  if (std::isfinite(v)) append_number(s, v); else s += "null";
}
inline double radius_mm(double k) { return k == 0 ? INFINITY : 1e3 / k; }
// Grid t_Y values in mm, rounded to 1e-9 mm so that 6.6e-3 m prints 6.6 and not 6.6000000000000005.
inline double grid_mm(double m) { return std::round(m * 1e12) / 1e9; }

// RFC 4180 quoting for text cells.
void csv_text(std::string& s, const std::string& t) {
  if (t.find_first_of(",\"\n") == std::string::npos) { s += t; return; }
  s += '"';
  for (char c : t) { if (c == '"') s += '"'; s += c; }
  s += '"';
}

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) { if (!s.empty()) s += sep; s += x; }
  return s;
}

// Per-ellipse values in output units, in column order (shared by CSV and JSON).
struct Col { const char* name; double (*get)(const LoadedEllipse&); };
const Col kEllipseCols[] = {
    {"y_rail_mm", [](const LoadedEllipse& e) { return e.g.y_r * 1e3; }},
    {"y_wheel_mm", [](const LoadedEllipse& e) { return e.g.y_w * 1e3; }},
    {"gamma_deg", [](const LoadedEllipse& e) { return e.g.gamma / units::deg; }},
    {"R_rxx_mm", [](const LoadedEllipse& e) { return radius_mm(e.g.k_rxx); }},
    {"R_wxx_mm", [](const LoadedEllipse& e) { return radius_mm(e.g.k_wxx); }},
    {"R_wyy_mm", [](const LoadedEllipse& e) { return e.g.R_wyy() * 1e3; }},
    {"A_1pm", [](const LoadedEllipse& e) { return e.A; }},
    {"B_1pm", [](const LoadedEllipse& e) { return e.B; }},
    {"lambda", [](const LoadedEllipse& e) { return e.c.lambda; }},
    {"m", [](const LoadedEllipse& e) { return e.c.m; }},
    {"n", [](const LoadedEllipse& e) { return e.c.n; }},
    {"gap_mm", [](const LoadedEllipse& e) { return e.g.gap * 1e3; }},
    {"h0_mm", [](const LoadedEllipse& e) { return e.s.h0 * 1e3; }},
    {"N_kN", [](const LoadedEllipse& e) { return e.s.N / units::kN; }},
    {"a_mm", [](const LoadedEllipse& e) { return e.s.a * 1e3; }},
    {"b_mm", [](const LoadedEllipse& e) { return e.s.b * 1e3; }},
    {"p0_MPa", [](const LoadedEllipse& e) { return e.s.p0 / units::MPa; }},
    {"pmean_MPa", [](const LoadedEllipse& e) { return e.s.p_mean / units::MPa; }},
    {"approach_mm", [](const LoadedEllipse& e) { return e.s.approach * 1e3; }},
};
const Col kPlasticCols[] = {
    {"h_y_mm", nullptr},  // filled from the law, see below
    {"p_max_MPa", [](const LoadedEllipse& e) { return e.s.p_max / units::MPa; }},
    {"plateau_a_mm", [](const LoadedEllipse& e) { return e.s.plateau_a * 1e3; }},
    {"plateau_b_mm", [](const LoadedEllipse& e) { return e.s.plateau_b * 1e3; }},
    {"a_el_mm", [](const LoadedEllipse& e) { return e.s.a_el * 1e3; }},
    {"b_el_mm", [](const LoadedEllipse& e) { return e.s.b_el * 1e3; }},
    {"area_ratio", [](const LoadedEllipse& e) { return e.s.area_ratio; }},
};

struct Formatted {
  std::string cases, ellipses, json, pressure;
};

// Pressure of each loaded ellipse on an N × N grid over its patch (method.md §5): the capped
// Hertz pressure min(p0 √(1 − x²/a² − y²/b²), p_lim) and, in plastic mode, the elastic Hertz
// pressure at the same load on the elastic patch (a_el, b_el).
void format_pressure(std::uint64_t idx, const CaseResult& r, const Material& mat, bool plastic, int N,
                     std::string& s) {
  s.clear();
  for (const LoadedEllipse& L : r.loaded) {
    const double a = L.s.a, b = L.s.b;
    const double p0_el = 1.5 * L.s.N / (units::pi * L.s.a_el * L.s.b_el);
    for (int i = 0; i < N; ++i) {
      const double x = -a + 2 * a * i / (N - 1);
      for (int j = 0; j < N; ++j) {
        const double y = -b + 2 * b * j / (N - 1);
        const double q = 1 - (x * x) / (a * a) - (y * y) / (b * b);
        double p = q > 0 ? L.s.p0 * std::sqrt(q) : 0.0;
        if (plastic) p = std::min(p, mat.p_lim);
        append_number(s, static_cast<long long>(idx));
        s += ','; append_number(s, static_cast<long long>(L.ellipse));
        s += ','; num(s, x * 1e3);
        s += ','; num(s, y * 1e3);
        s += ','; num(s, p / units::MPa);
        if (plastic) {
          const double qe = 1 - (x * x) / (L.s.a_el * L.s.a_el) - (y * y) / (L.s.b_el * L.s.b_el);
          s += ','; num(s, (qe > 0 ? p0_el * std::sqrt(qe) : 0.0) / units::MPa);
        }
        s += '\n';
      }
    }
  }
}

void format_case(std::uint64_t idx, const CasePoint& cp, const CaseResult& r,
                 bool plastic, bool want_csv, bool want_json, Formatted& f) {
  const std::string warn = join(r.warnings, ";");
  auto h_y_mm = [](const LoadedEllipse& e) { return e.h_y * 1e3; };  // from the ellipse law (method.md §5)
  if (want_csv) {
    std::string& s = f.cases;
    s.clear();
    append_number(s, static_cast<long long>(idx));
    s += ','; num(s, cp.tY_mm);
    s += ','; num(s, cp.Q_kN);
    s += ','; s += to_string(r.status);
    s += ','; num(s, r.dz * 1e3);
    s += ','; append_number(s, static_cast<long long>(r.iterations));
    s += ','; num(s, r.residual);
    s += ','; append_number(s, static_cast<long long>(r.loaded.size()));
    s += ','; num(s, r.Fz / units::kN);
    s += ','; num(s, r.Fy / units::kN);
    s += ','; csv_text(s, warn);
    s += ','; csv_text(s, r.message);
    s += '\n';
    std::string& e = f.ellipses;
    e.clear();
    for (const LoadedEllipse& L : r.loaded) {
      append_number(e, static_cast<long long>(idx));
      e += ','; num(e, cp.tY_mm);
      e += ','; num(e, cp.Q_kN);
      e += ','; append_number(e, static_cast<long long>(L.ellipse));
      for (const Col& c : kEllipseCols) { e += ','; num(e, c.get(L)); }
      if (plastic) {
        e += ','; e += L.s.plastic ? "1" : "0";
        e += ','; num(e, h_y_mm(L));
        for (std::size_t k = 1; k < std::size(kPlasticCols); ++k) { e += ','; num(e, kPlasticCols[k].get(L)); }
      }
      e += '\n';
    }
  }
  if (want_json) {
    std::string& s = f.json;
    s.clear();
    s += "    {\"case\": "; append_number(s, static_cast<long long>(idx));
    s += ", \"tY_mm\": "; jnum(s, cp.tY_mm);
    s += ", \"Q_kN\": "; jnum(s, cp.Q_kN);
    s += ", \"status\": \""; s += to_string(r.status);
    s += "\", \"dz_mm\": "; jnum(s, r.dz * 1e3);
    s += ", \"iterations\": "; append_number(s, static_cast<long long>(r.iterations));
    s += ", \"residual\": "; jnum(s, r.residual);
    s += ", \"n_contacts\": "; append_number(s, static_cast<long long>(r.loaded.size()));
    s += ", \"Fz_kN\": "; jnum(s, r.Fz / units::kN);
    s += ", \"Fy_kN\": "; jnum(s, r.Fy / units::kN);
    s += ", \"warnings\": "; s += nlohmann::json(r.warnings).dump();
    s += ", \"message\": "; s += nlohmann::json(r.message).dump();
    s += ", \"ellipses\": [";
    bool first = true;
    for (const LoadedEllipse& L : r.loaded) {
      s += first ? "\n      {" : ",\n      {";
      first = false;
      s += "\"ellipse\": "; append_number(s, static_cast<long long>(L.ellipse));
      for (const Col& c : kEllipseCols) { s += ", \""; s += c.name; s += "\": "; jnum(s, c.get(L)); }
      if (plastic) {
        s += ", \"plastic\": "; s += L.s.plastic ? "true" : "false";
        s += ", \"h_y_mm\": "; jnum(s, h_y_mm(L));
        for (std::size_t k = 1; k < std::size(kPlasticCols); ++k) {
          s += ", \""; s += kPlasticCols[k].name; s += "\": "; jnum(s, kPlasticCols[k].get(L));
        }
      }
      s += "}";
    }
    s += first ? "]}" : "\n    ]}";
  }
}

nlohmann::json profile_json(const Profile& p, double window) {
  return {{"source", p.source}, {"format", p.format}, {"kind", to_string(p.kind)},
          {"sha256", p.checksum}, {"points", p.size()}, {"y_min_mm", p.y.front() * 1e3},
          {"y_max_mm", p.y.back() * 1e3}, {"fit_window_mm", window * 1e3}, {"warnings", p.warnings}};
}

nlohmann::json ellipses_json(const ContactGeometry& G) {
  nlohmann::json a = nlohmann::json::array();
  for (const PotentialEllipse& P : G.ellipses)
    a.push_back({{"ellipse", P.index}, {"tY_min_mm", grid_mm(P.tY_min)}, {"tY_max_mm", grid_mm(P.tY_max)},
                 {"y_rail_min_mm", P.y_r_min * 1e3}, {"y_rail_max_mm", P.y_r_max * 1e3},
                 {"y_wheel_min_mm", P.y_w_min * 1e3}, {"y_wheel_max_mm", P.y_w_max * 1e3}});
  return a;
}

nlohmann::json inputs_json(const CaseFile& cf, const PairGeometry& pg) {
  nlohmann::json j = cf.resolved_json();
  j["wheel"]["read"] = profile_json(pg.wheel, pg.geo.wheel_window);
  j["rail"]["read"] = profile_json(pg.rail, pg.geo.rail_window);
  return j;
}

// The profiles as used (rail with its inclination), canonical frame, mm: for plots.
void write_profiles_csv(const PairGeometry& pg, const std::string& path) {
  OutputFile f(path);
  std::string s = "kind,y_mm,z_mm\n";
  for (const Profile* p : {&pg.wheel, &pg.rail}) {
    for (std::size_t i = 0; i < p->size(); ++i) {
      s += to_string(p->kind);
      s += ','; num(s, p->y[i] * 1e3);
      s += ','; num(s, p->z[i] * 1e3);
      s += '\n';
    }
  }
  f.stream() << s;
  f.commit();
}

void warn_profiles(const PairGeometry& pg, std::ostream& err) {
  for (const Profile* p : {&pg.wheel, &pg.rail})
    for (const auto& w : p->warnings) err << "mhcontact: warning: " << p->source << ": " << w << "\n";
}

// Where the formatted rows go; `prefix` is put in front of every CSV line (the batch's "pair,").
struct Sinks {
  std::ostream* cases = nullptr;
  std::ostream* ellipses = nullptr;
  std::ostream* pressure = nullptr;
  std::ostream* json = nullptr;
  std::string prefix;
};

void put_prefixed(std::ostream& o, const std::string& prefix, const std::string& lines) {
  if (prefix.empty()) { o << lines; return; }
  std::size_t a = 0;
  while (a < lines.size()) {
    const std::size_t b = lines.find('\n', a);
    o << prefix;
    o.write(lines.data() + a, static_cast<std::streamsize>((b == std::string::npos ? lines.size() : b + 1) - a));
    a = b == std::string::npos ? lines.size() : b + 1;
  }
}

// Solve cases [first, end) of `cf` on `G` in parallel chunks and write them in order.
void solve_cases(const CaseFile& cf, const ContactGeometry& G, std::uint64_t first, std::uint64_t end,
                 const RunOptions& opt, const Sinks& out, std::map<std::string, std::uint64_t>* by_status,
                 std::uint64_t* failed, std::ostream& err) {
  const bool plastic = cf.model == Model::Plastic;
  const bool want_csv = out.cases != nullptr, want_json = out.json != nullptr;
  const int np = out.pressure ? opt.pressure_grid : 0;
  const std::uint64_t n = end - first;
  const unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t chunk = std::max<std::size_t>(opt.chunk, 1);
  std::vector<Formatted> fmt(std::max<std::uint64_t>(1, std::min<std::uint64_t>(chunk, n)));
  std::vector<CaseStatus> status(fmt.size());
  int last_pct = -1;
  for (std::uint64_t c0 = first; c0 < end; c0 += chunk) {
    const std::size_t m = static_cast<std::size_t>(std::min<std::uint64_t>(chunk, end - c0));
    auto work = [&](unsigned t, unsigned nt) {
      for (std::size_t i = t; i < m; i += nt) {
        const CasePoint cp = cf.case_at(c0 + i);
        CaseResult r;
        try {
          r = solve_case(G, cf.material, cp.tY, cp.Q, cf.solver);
        } catch (const std::exception& ex) {
          // Never let one case end the sweep (or a worker thread): report it in its row.
          r = CaseResult{};
          r.status = CaseStatus::NotConverged;
          r.message = std::string("internal error: ") + ex.what();
        }
        status[i] = r.status;
        format_case(c0 + i, cp, r, plastic, want_csv, want_json, fmt[i]);
        if (np) format_pressure(c0 + i, r, cf.material, plastic, np, fmt[i].pressure);
      }
    };
    const unsigned nt = static_cast<unsigned>(std::min<std::size_t>(threads, m));
    if (nt <= 1) {
      work(0, 1);
    } else {
      std::vector<std::thread> pool;
      for (unsigned t = 1; t < nt; ++t) pool.emplace_back(work, t, nt);
      work(0, nt);
      for (auto& th : pool) th.join();
    }
    for (std::size_t i = 0; i < m; ++i) {
      ++(*by_status)[to_string(status[i])];
      if (status[i] != CaseStatus::Ok) ++*failed;
      if (want_csv) {
        put_prefixed(*out.cases, out.prefix, fmt[i].cases);
        put_prefixed(*out.ellipses, out.prefix, fmt[i].ellipses);
      }
      if (want_json) *out.json << fmt[i].json << (c0 + i + 1 < end ? ",\n" : "\n");
      if (np) put_prefixed(*out.pressure, out.prefix, fmt[i].pressure);
    }
    if (opt.progress && !opt.quiet) {
      const int pct = static_cast<int>(100.0 * static_cast<double>(c0 + m - first) / static_cast<double>(n));
      if (pct != last_pct) {
        err << "\rmhcontact run: " << (c0 + m - first) << "/" << n << " cases (" << pct << " %)" << std::flush;
        last_pct = pct;
      }
    }
  }
}

}  // namespace

std::string cases_csv_header() {
  return "case,tY_mm,Q_kN,status,dz_mm,iterations,residual,n_contacts,Fz_kN,Fy_kN,warnings,message\n";
}

std::string pressure_csv_header(bool plastic) {
  return plastic ? "case,ellipse,x_mm,y_mm,p_MPa,p_elastic_MPa\n" : "case,ellipse,x_mm,y_mm,p_MPa\n";
}

std::string ellipses_csv_header(bool plastic) {
  std::string s = "case,tY_mm,Q_kN,ellipse";
  for (const Col& c : kEllipseCols) { s += ','; s += c.name; }
  if (plastic) {
    s += ",plastic";
    for (const Col& c : kPlasticCols) { s += ','; s += c.name; }
  }
  return s + "\n";
}

PairGeometry build_pair_geometry(const CaseFile& cf) {
  PairGeometry pg;
  pg.wheel = load_profile(cf.wheel, ProfileKind::Wheel);
  pg.rail = load_profile(cf.rail, ProfileKind::Rail, cf.inclination);
  pg.geo = build_geometry(pg.wheel, pg.rail, cf.track, cf.geometry);
  return pg;
}

int geometry_job(const CaseFile& cf, const std::string& out_dir, std::ostream& out, std::ostream& err, bool quiet) {
  const auto t0 = std::chrono::steady_clock::now();
  const PairGeometry pg = build_pair_geometry(cf);
  const ContactGeometry& G = pg.geo;
  if (!quiet) warn_profiles(pg, err);
  ensure_directory(out_dir);
  {
    OutputFile f(out_dir + "/caf.csv");
    std::string s = "tY_mm,y_rail_mm,y_wheel_mm,gamma_deg,R_rxx_mm,R_wxx_mm,R_wyy_mm,r_roll_mm,wheel_dz_mm,strip,ellipse\n";
    for (std::size_t k = 0; k < G.tY.size(); ++k) {
      const CandidateGeom& c = G.main_at(k);
      num(s, grid_mm(G.tY[k]));
      s += ','; num(s, c.y_r * 1e3);
      s += ','; num(s, c.y_w * 1e3);
      s += ','; num(s, c.gamma / units::deg);
      s += ','; num(s, radius_mm(c.k_rxx));
      s += ','; num(s, radius_mm(c.k_wxx));
      s += ','; num(s, c.R_wyy() * 1e3);
      s += ','; num(s, c.r_roll * 1e3);
      s += ','; num(s, -G.z_contact[k] * 1e3);
      s += ','; append_number(s, static_cast<long long>(G.main_strip[k]));
      s += ','; append_number(s, static_cast<long long>(G.main_ellipse[k] + 1));
      s += '\n';
    }
    f.stream() << s;
    f.commit();
  }
  write_profiles_csv(pg, out_dir + "/profiles.csv");
  {
    nlohmann::json j;
    j["schema"] = kGeometrySchema;
    j["program"] = {{"name", "mhcontact"}, {"version", MHCONTACT_VERSION}};
    j["inputs"] = inputs_json(cf, pg);
    j["y_offset_mm"] = G.y_offset * 1e3;
    j["rail_gauge_point_y_mm"] = G.rail_gauge_y * 1e3;
    j["strips"] = G.strip_y.size();
    j["grid_points"] = G.tY.size();
    j["potential_ellipses"] = ellipses_json(G);
    OutputFile f(out_dir + "/geometry.json");
    f.stream() << j.dump(2) << "\n";
    f.commit();
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!quiet)
    err << "mhcontact geometry: " << G.n_ellipses() << " potential ellipses over t_Y " << format_number(G.tY.front() * 1e3)
        << " .. " << format_number(G.tY.back() * 1e3) << " mm (" << G.tY.size() << " grid points, "
        << G.strip_y.size() << " strips) in " << format_number(std::round(secs * 1e3) / 1e3) << " s; wrote "
        << out_dir << "/caf.csv, geometry.json, profiles.csv\n";
  (void)out;
  return kExitOk;
}

int run_job(const CaseFile& cf, const RunOptions& opt, std::ostream& out, std::ostream& err) {
  const auto t0 = std::chrono::steady_clock::now();
  const PairGeometry pg = build_pair_geometry(cf);
  const ContactGeometry& G = pg.geo;
  if (!opt.quiet) warn_profiles(pg, err);
  const bool plastic = cf.model == Model::Plastic;
  const bool to_stdout = opt.out_dir == "-";
  const bool want_csv = opt.csv && !to_stdout;
  const bool want_json = opt.json || to_stdout;

  std::unique_ptr<OutputFile> fc, fe, fj, fp;
  const int np = opt.pressure_grid;
  if (np != 0 && (np < 2 || np > 1000))
    throw InputError("--pressure-grid", std::to_string(np), "must be between 2 and 1000 points per axis");
  if (np && to_stdout)
    throw InputError("--pressure-grid", std::to_string(np), "needs an output directory (not -o -)");
  if (!to_stdout) {
    ensure_directory(opt.out_dir);
    if (np) {
      fp = std::make_unique<OutputFile>(opt.out_dir + "/pressure.csv");
      fp->stream() << pressure_csv_header(plastic);
    }
    if (want_csv) {
      fc = std::make_unique<OutputFile>(opt.out_dir + "/cases.csv");
      fe = std::make_unique<OutputFile>(opt.out_dir + "/ellipses.csv");
      fc->stream() << cases_csv_header();
      fe->stream() << ellipses_csv_header(plastic);
    }
    if (want_json) fj = std::make_unique<OutputFile>(opt.out_dir + "/results.json");
  }
  std::ostream* js = to_stdout ? &out : (fj ? &fj->stream() : nullptr);
  if (js) {
    nlohmann::json head;
    head["schema"] = kSchema;
    head["program"] = {{"name", "mhcontact"}, {"version", MHCONTACT_VERSION}};
    head["inputs"] = inputs_json(cf, pg);
    head["potential_ellipses"] = ellipses_json(G);
    std::string h = head.dump(2);
    h.pop_back();  // reopen the object: cases follow
    while (!h.empty() && (h.back() == '\n' || h.back() == ' ')) h.pop_back();
    *js << h << ",\n  \"cases\": [\n";
  }

  const std::uint64_t n_all = cf.case_count();
  if (opt.shard_count < 1 || opt.shard_index < 1 || opt.shard_index > opt.shard_count)
    throw InputError("--shard", std::to_string(opt.shard_index) + "/" + std::to_string(opt.shard_count), "must be K/N with 1 <= K <= N");
  const std::uint64_t first = n_all * (opt.shard_index - 1) / opt.shard_count;
  const std::uint64_t end = n_all * opt.shard_index / opt.shard_count;
  const std::uint64_t n = end - first;
  std::map<std::string, std::uint64_t> by_status;
  std::uint64_t failed = 0;
  Sinks sinks{fc ? &fc->stream() : nullptr, fe ? &fe->stream() : nullptr, fp ? &fp->stream() : nullptr, js, ""};
  solve_cases(cf, G, first, end, opt, sinks, &by_status, &failed, err);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (js) {
    nlohmann::json summary = {{"cases", n}, {"failed", failed}, {"by_status", by_status}};
    *js << "  ],\n  \"summary\": " << summary.dump() << "\n}\n";
  }
  if (fc) {
    fc->commit();
    fe->commit();
    write_profiles_csv(pg, opt.out_dir + "/profiles.csv");
  }
  if (opt.shard_count > 1 && !to_stdout) {
    nlohmann::json sh = {{"schema", "mhcontact.shard/1"}, {"index", opt.shard_index}, {"count", opt.shard_count},
                         {"unit", "case"}, {"first", first}, {"end", end}, {"total", n_all},
                         {"summary", {{"cases", n_all}, {"failed", failed}, {"by_status", by_status}}},
                         {"csv", want_csv}, {"json", want_json}, {"pressure", np > 0},
                         {"inputs", inputs_json(cf, pg)}};
    OutputFile f(opt.out_dir + "/shard.json");
    f.stream() << sh.dump(2) << "\n";
    f.commit();
  }
  if (fj) fj->commit();
  if (fp) fp->commit();
  if (to_stdout) out.flush();
  if (!opt.quiet) {
    if (opt.progress) err << "\n";
    err << "mhcontact run: " << n << " cases";
    if (opt.shard_count > 1) err << " (shard " << opt.shard_index << "/" << opt.shard_count << ": cases " << first << " .. " << end - 1 << ")";
    for (const auto& [k, v] : by_status) err << ", " << k << " " << v;
    err << "; " << G.n_ellipses() << " potential ellipses; " << format_number(std::round(secs * 1e3) / 1e3) << " s";
    if (!to_stdout) err << "; outputs in " << opt.out_dir;
    err << "\n";
  }
  return failed ? kExitCasesFailed : kExitOk;
}

int batch_job(const Manifest& m, const RunOptions& opt, std::ostream& out, std::ostream& err) {
  (void)out;
  const auto t0 = std::chrono::steady_clock::now();
  if (opt.out_dir == "-") throw InputError("-o", "-", "a batch writes several tables: give an output directory");
  if (opt.pressure_grid != 0 && (opt.pressure_grid < 2 || opt.pressure_grid > 1000))
    throw InputError("--pressure-grid", std::to_string(opt.pressure_grid), "must be between 2 and 1000 points per axis");
  const std::uint64_t n_pairs = m.pairs.size();
  const std::uint64_t first = n_pairs * (opt.shard_index - 1) / opt.shard_count;
  const std::uint64_t end = n_pairs * opt.shard_index / opt.shard_count;
  const CaseFile shared = pair_case(m, 0);  // validated already: the sweep and the model
  const bool plastic = shared.model == Model::Plastic;
  const int np = opt.pressure_grid;
  ensure_directory(opt.out_dir);
  std::unique_ptr<OutputFile> fc, fe, fp, fpp, fj;
  if (opt.csv) {
    fc = std::make_unique<OutputFile>(opt.out_dir + "/cases.csv");
    fe = std::make_unique<OutputFile>(opt.out_dir + "/ellipses.csv");
    fpp = std::make_unique<OutputFile>(opt.out_dir + "/pairs.csv");
    fc->stream() << "pair," << cases_csv_header();
    fe->stream() << "pair," << ellipses_csv_header(plastic);
    fpp->stream() << "pair,name,wheel,rail,status,n_ellipses,wheel_sha256,rail_sha256,message\n";
  }
  if (np) {
    fp = std::make_unique<OutputFile>(opt.out_dir + "/pressure.csv");
    fp->stream() << "pair," << pressure_csv_header(plastic);
  }
  if (opt.json) {
    fj = std::make_unique<OutputFile>(opt.out_dir + "/results.json");
    nlohmann::json head;
    head["schema"] = "mhcontact.batch/1";
    head["program"] = {{"name", "mhcontact"}, {"version", MHCONTACT_VERSION}};
    head["manifest"] = m.path;
    head["pair_count"] = n_pairs;
    std::string h = head.dump(2);
    h.pop_back();
    while (!h.empty() && (h.back() == '\n' || h.back() == ' ')) h.pop_back();
    fj->stream() << h << ",\n  \"pairs\": [\n";
  }
  std::map<std::string, std::uint64_t> by_status;
  std::uint64_t failed = 0, invalid = 0, cases_total = 0;
  RunOptions quiet_opt = opt;
  quiet_opt.progress = false;
  for (std::uint64_t k = first; k < end; ++k) {
    const ManifestPair& P = m.pairs[k];
    const std::string prefix = std::to_string(k) + ",";
    std::string status = "ok", message;
    std::unique_ptr<PairGeometry> pg;
    CaseFile cf;
    try {
      cf = pair_case(m, k);
      pg = std::make_unique<PairGeometry>(build_pair_geometry(cf));
    } catch (const InputError& e) {
      status = "invalid_pair";
      message = e.what();
    }
    const std::uint64_t n = shared.case_count();
    cases_total += n;
    if (fpp) {
      std::string row = prefix;
      csv_text(row, P.name);
      row += ',';
      csv_text(row, pg ? pg->wheel.source : P.wheel.dump());
      row += ',';
      csv_text(row, pg ? pg->rail.source : P.rail.dump());
      row += ',' + status + ',' + (pg ? std::to_string(pg->geo.n_ellipses()) : std::string()) + ',';
      row += (pg ? pg->wheel.checksum : std::string()) + ',' + (pg ? pg->rail.checksum : std::string()) + ',';
      csv_text(row, message);
      fpp->stream() << row << '\n';
    }
    std::ostringstream pair_json;
    if (fj) {
      nlohmann::json pj = {{"pair", k}, {"name", P.name}, {"status", status}, {"message", message}};
      if (pg) {
        pj["inputs"] = inputs_json(cf, *pg);
        pj["potential_ellipses"] = ellipses_json(pg->geo);
      }
      std::string h = pj.dump();
      h.pop_back();
      fj->stream() << "    " << h << ", \"cases\": [\n";
    }
    if (pg) {
      if (!opt.quiet) warn_profiles(*pg, err);
      Sinks sinks{fc ? &fc->stream() : nullptr, fe ? &fe->stream() : nullptr, fp ? &fp->stream() : nullptr,
                  fj ? &fj->stream() : nullptr, prefix};
      solve_cases(cf, pg->geo, 0, n, quiet_opt, sinks, &by_status, &failed, err);
    } else {
      ++invalid;
      by_status["invalid_pair"] += n;
      for (std::uint64_t i = 0; i < n; ++i) {
        CaseResult r;
        r.status = CaseStatus::InvalidPair;
        r.message = message;
        r.dz = r.residual = r.Fz = r.Fy = NAN;
        Formatted f;
        format_case(i, shared.case_at(i), r, plastic, fc != nullptr, fj != nullptr, f);
        if (fc) put_prefixed(fc->stream(), prefix, f.cases);
        if (fj) fj->stream() << f.json << (i + 1 < n ? ",\n" : "\n");
      }
    }
    if (fj) fj->stream() << "    ]}" << (k + 1 < end ? ",\n" : "\n");
    if (opt.progress && !opt.quiet) err << "\rmhcontact run: pair " << (k + 1 - first) << "/" << (end - first) << std::flush;
  }
  const nlohmann::json summary = {{"pairs", end - first}, {"invalid_pairs", invalid}, {"cases", cases_total},
                                  {"failed", failed}, {"by_status", by_status}};
  if (fj) fj->stream() << "  ],\n  \"summary\": " << summary.dump() << "\n}\n";
  if (fc) { fc->commit(); fe->commit(); fpp->commit(); }
  if (fp) fp->commit();
  if (fj) fj->commit();
  if (opt.shard_count > 1) {
    nlohmann::json sh = {{"schema", "mhcontact.shard/1"}, {"index", opt.shard_index}, {"count", opt.shard_count},
                         {"unit", "pair"}, {"first", first}, {"end", end}, {"total", n_pairs}, {"summary", summary},
                         {"csv", opt.csv}, {"json", opt.json}, {"pressure", np > 0},
                         {"inputs", {{"manifest", m.path}, {"common", m.common}, {"pairs", n_pairs}}}};
    OutputFile f(opt.out_dir + "/shard.json");
    f.stream() << sh.dump(2) << "\n";
    f.commit();
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!opt.quiet) {
    if (opt.progress) err << "\n";
    err << "mhcontact run: " << (end - first) << " pairs (" << invalid << " invalid), " << cases_total << " cases";
    for (const auto& [s, v] : by_status) err << ", " << s << " " << v;
    err << "; " << format_number(std::round(secs * 1e3) / 1e3) << " s; outputs in " << opt.out_dir << "\n";
  }
  return (failed || invalid) ? kExitCasesFailed : kExitOk;
}

void parse_shard(const std::string& text, unsigned* index, unsigned* count) {
  const auto slash = text.find('/');
  auto bad = [&]() { return InputError("--shard", text, "must be K/N with 1 <= K <= N <= 100000, e.g. 3/8"); };
  if (slash == std::string::npos) throw bad();
  try {
    std::size_t p1 = 0, p2 = 0;
    const long k = std::stol(text.substr(0, slash), &p1), n = std::stol(text.substr(slash + 1), &p2);
    if (p1 != slash || p2 != text.size() - slash - 1 || k < 1 || n < 1 || k > n || n > 100000) throw bad();
    *index = static_cast<unsigned>(k);
    *count = static_cast<unsigned>(n);
  } catch (const std::logic_error&) {
    throw bad();
  }
}

namespace {

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot read (is this the output directory of a `run --shard`?)");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Copy a CSV file to `out`, skipping its header unless `with_header`; the header must equal `header`.
void append_csv(const std::string& path, std::ostream& out, std::string* header, bool with_header) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "missing in a shard directory");
  std::string line;
  std::getline(in, line);
  if (header->empty()) *header = line;
  else if (line != *header) throw InputError(path, "", "its header differs from the first shard's");
  if (with_header) out << line << '\n';
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) out.write(buf, in.gcount());
}

}  // namespace

int merge_job(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& err, bool quiet) {
  if (dirs.empty()) throw InputError("merge", "", "give the shard directories");
  struct Shard { std::string dir; nlohmann::json meta; };
  std::vector<Shard> shards;
  for (const auto& d : dirs) {
    const std::string p = d + "/shard.json";
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(read_all(p));
    } catch (const nlohmann::json::exception& e) {
      throw InputError(p, "", std::string("not a shard description: ") + e.what());
    }
    if (j.value("schema", "") != "mhcontact.shard/1") throw InputError(p, "", "not a shard description (schema mhcontact.shard/1)");
    shards.push_back({d, j});
  }
  std::sort(shards.begin(), shards.end(), [](const Shard& a, const Shard& b) { return a.meta["index"] < b.meta["index"]; });
  const auto N = shards[0].meta["count"].get<unsigned>();
  if (shards.size() != N)
    throw InputError("merge", std::to_string(shards.size()) + " directories", "the run was split into " + std::to_string(N) + " shards: give all of them, once each");
  std::uint64_t expect = 0;
  for (unsigned k = 0; k < N; ++k) {
    const nlohmann::json& m = shards[k].meta;
    const std::string where = shards[k].dir + "/shard.json";
    if (m["index"].get<unsigned>() != k + 1) throw InputError(where, m["index"].dump(), "shard " + std::to_string(k + 1) + " is missing or given twice");
    if (m["count"] != shards[0].meta["count"] || m["total"] != shards[0].meta["total"] || m["unit"] != shards[0].meta["unit"])
      throw InputError(where, "", "shards of different runs (case or shard counts differ)");
    if (m["inputs"] != shards[0].meta["inputs"]) throw InputError(where, "", "shards of different runs (inputs differ: case file, profiles or options)");
    if (m["csv"] != shards[0].meta["csv"] || m["json"] != shards[0].meta["json"] || m["pressure"] != shards[0].meta["pressure"])
      throw InputError(where, "", "shards written with different output options");
    if (m["first"].get<std::uint64_t>() != expect) throw InputError(where, m["first"].dump(), "the shards' ranges do not tile the case (or pair) list");
    expect = m["end"].get<std::uint64_t>();
  }
  if (expect != shards[0].meta["total"].get<std::uint64_t>()) throw InputError("merge", "", "the shards do not cover every case (or pair)");
  const bool batch = shards[0].meta["unit"] == "pair";
  ensure_directory(out_dir);
  // Summary of all shards: counts added up, by_status merged; `cases` and `pairs` are totals
  // of the whole run for unsharded-equal output (run: cases = total).
  nlohmann::json summary = nlohmann::json::object();
  std::map<std::string, std::uint64_t> by_status;
  for (const auto& sh : shards) {
    const nlohmann::json& su = sh.meta["summary"];
    for (auto it = su.begin(); it != su.end(); ++it) {
      if (it.key() == "by_status") {
        for (auto b = it.value().begin(); b != it.value().end(); ++b) by_status[b.key()] += b.value().get<std::uint64_t>();
      } else if (!batch && it.key() == "cases") {
        summary["cases"] = it.value();
      } else {
        summary[it.key()] = summary.value(it.key(), std::uint64_t{0}) + it.value().get<std::uint64_t>();
      }
    }
  }
  summary["by_status"] = by_status;
  const std::uint64_t failed = summary.value("failed", std::uint64_t{0}) + summary.value("invalid_pairs", std::uint64_t{0});
  const bool csv = shards[0].meta["csv"], json = shards[0].meta["json"], pressure = shards[0].meta["pressure"];
  std::vector<std::string> tables;
  if (csv) tables = {"cases.csv", "ellipses.csv"};
  if (csv && batch) tables.push_back("pairs.csv");
  if (pressure) tables.push_back("pressure.csv");
  for (const auto& t : tables) {
    OutputFile f(out_dir + "/" + t);
    std::string header;
    for (unsigned k = 0; k < N; ++k) append_csv(shards[k].dir + "/" + t, f.stream(), &header, k == 0);
    f.commit();
  }
  if (csv && !batch) {
    OutputFile f(out_dir + "/profiles.csv");
    f.stream() << read_all(shards[0].dir + "/profiles.csv");
    f.commit();
  }
  if (json) {
    // Each shard's results.json: the same head, its cases, its summary. Keep the first head,
    // concatenate the case lines, write the summary of all cases.
    OutputFile f(out_dir + "/results.json");
    const std::string open = batch ? "  \"pairs\": [\n" : "  \"cases\": [\n", close = "  ],\n  \"summary\": ";
    bool any = false;
    for (unsigned k = 0; k < N; ++k) {
      const std::string path = shards[k].dir + "/results.json";
      const std::string t = read_all(path);
      const auto a = t.find(open), b = t.rfind(close);
      if (a == std::string::npos || b == std::string::npos || b < a + open.size()) throw InputError(path, "", "not a results.json of mhcontact run");
      if (k == 0) f.stream() << t.substr(0, a + open.size());
      std::string body = t.substr(a + open.size(), b - a - open.size());
      if (body.empty()) continue;  // a shard without cases (more shards than cases)
      body.pop_back();             // the newline after the shard's last case
      f.stream() << (any ? ",\n" : "") << body;
      any = true;
    }
    if (any) f.stream() << "\n";
    f.stream() << close << summary.dump() << "\n}\n";
    f.commit();
  }
  if (!quiet) {
    err << "mhcontact merge: " << N << " shards, " << shards[0].meta["total"].get<std::uint64_t>() << (batch ? " pairs" : " cases");
    for (const auto& [k, v] : by_status) err << ", " << k << " " << v;
    err << "; outputs in " << out_dir << "\n";
  }
  return failed ? kExitCasesFailed : kExitOk;
}

}  // namespace mh
