#include "jobs/run.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <ostream>

#include "contact/solve.hpp"
#include "core/errors.hpp"
#include "core/units.hpp"
#include "input/manifest.hpp"
#include "core/numfmt.hpp"
#include "jobs/shard_text.hpp"
#include "output/case_tables.hpp"
#include "output/cells.hpp"
#include "output/json_stream.hpp"
#include "output/output_file.hpp"
#include "output/pair_tables.hpp"
#include "output/run_dir.hpp"
#include "profile/standard_profiles.hpp"

#ifndef MHCONTACT_GIT_COMMIT
#define MHCONTACT_GIT_COMMIT "unknown"
#endif

namespace mh {

nlohmann::json program_json() {
  return {{"name", "mhcontact"}, {"version", MHCONTACT_VERSION}, {"commit", MHCONTACT_GIT_COMMIT}};
}

nlohmann::json pair_summary_json(const PairGeometry& pg) {
  nlohmann::json j;
  if (pg.geo.wheel_curve && pg.geo.rail_curve)
    j["profiles"] = {{"wheel", pg.geo.wheel_curve->noise().class_name()}, {"rail", pg.geo.rail_curve->noise().class_name()}};
  // Smoothing for contact (profiles.md §7): per profile, the spline's length L, 0 when not smoothed.
  if (pg.geo.wheel_gap_curve && pg.geo.rail_gap_curve)
    j["contact_smoothing_mm"] = {{"wheel", std::round(pg.geo.wheel_gap_curve->smoothing_length() * 1e6) / 1e3},
                                 {"rail", std::round(pg.geo.rail_gap_curve->smoothing_length() * 1e6) / 1e3}};
  // ... and the shortest local length where geometry above the noise was kept (auto only).
  if (pg.geo.wheel_gap_curve && pg.geo.rail_gap_curve)
    j["contact_smoothing_local_min_mm"] = {{"wheel", std::round(pg.geo.wheel_gap_curve->smoothing_local_min() * 1e6) / 1e3},
                                           {"rail", std::round(pg.geo.rail_gap_curve->smoothing_local_min() * 1e6) / 1e3}};
  // Whether the cases carry the smoothing's uncertainty band (profiles.md §7).
  j["smoothing_band"] = pg.band.any();
  j["rail_cant_deg"] = pg.cant.used.found ? nlohmann::json(pg.cant.used.angle / units::deg) : nlohmann::json(nullptr);
  j["pair_warnings"] = pg.cant.warnings;
  return j;
}

std::string pair_summary_line(const PairGeometry& pg) {
  std::string s = "mhcontact run: profiles:";
  for (const auto& [name, c] : {std::pair<const char*, const ProfileCurve*>{"wheel", pg.geo.wheel_curve.get()},
                                {"rail", pg.geo.rail_curve.get()}})
    if (c) s += std::string(" ") + name + " " + c->noise().reason + ";";
  for (const auto& [name, c] : {std::pair<const char*, const ProfileCurve*>{"wheel", pg.geo.wheel_gap_curve.get()},
                                {"rail", pg.geo.rail_gap_curve.get()}})
    if (c && c->smoothing_length() > 0)
      s += std::string(" ") + name + " smoothed for contact (grid methods): spline L = " +
           format_number(std::round(c->smoothing_length() * 1e5) / 100) + " mm" +
           (c->smoothing_sigma() > 0 ? std::string(c->smoothing_at_bound() ? " (auto, at its bound: noise " : " (auto: noise ") +
                                           format_number(std::round(c->smoothing_sigma() * 1e8) / 100) + " µm" +
                                           (c->smoothing_local_min() < c->smoothing_length()
                                                ? "; shortened where it would remove geometry above the noise, to as little as " +
                                                      format_number(std::round(c->smoothing_local_min() * 1e5) / 100) +
                                                      " mm, between y " + format_number(std::round(c->smoothing_local_from() * 1e4) / 10) +
                                                      " and " + format_number(std::round(c->smoothing_local_to() * 1e4) / 10) + " mm"
                                                : std::string()) +
                                           ")"
                                     : std::string()) +
           ", moved the points by " +
           format_number(std::round(c->smoothing_rms_change() * 1e8) / 100) + " µm RMS (max " +
           format_number(std::round(c->smoothing_max_change() * 1e8) / 100) + " µm);";
  if (pg.cant.used.found)
    s += " rail cant " + format_number(std::round(pg.cant.used.angle / units::deg * 1e3) / 1e3 + 0.0) + " deg (" +
         cant_ratio(pg.cant.used.angle) + (pg.cant.used.confident ? "" : ", not confident") + ")";
  else
    s += " rail cant not estimated";
  if (!pg.cant.warnings.empty()) s += "; " + std::to_string(pg.cant.warnings.size()) + " cant warning(s)";
  return s + "\n";
}

void warn_profiles(const PairGeometry& pg, std::ostream& err) {
  for (const Profile* p : {&pg.wheel, &pg.rail})
    for (const auto& w : p->warnings) err << "mhcontact: warning: " << p->source << ": " << w << "\n";
}

PairGeometry build_pair_geometry(const CaseFile& cf) {
  PairGeometry pg;
  pg.wheel = load_profile(cf.wheel, ProfileKind::Wheel);
  pg.rail = load_profile(cf.rail, ProfileKind::Rail, cf.inclination);
  // Conventions that can be checked are checked: a cant applied twice, a
  // mirrored canted rail (profiles.md "Cant checks").
  pg.cant = check_rail_cant(pg.rail, cf.inclination);
  for (const auto& w : pg.cant.warnings) pg.rail.warnings.push_back(w);
  pg.geo = build_geometry(pg.wheel, pg.rail, cf.track, cf.geometry);
  // The smoothing's uncertainty band (profiles.md §7): the pair at L/2 and 2L, once per pair.
  set_pair_band(pg, cf.track, cf.geometry, cf.geometry.smoothing_band, cf.method);
  for (const auto& w : pg.geo.warnings) pg.wheel.warnings.push_back(w);  // placement (a wheel without a flange)
  return pg;
}

void write_pair_geometry(const CaseFile& cf, const PairGeometry& pg, RunDirectory& rd, const std::string& prefix,
                         const std::string& out_dir) {
  const ContactGeometry& G = pg.geo;
  write_caf_csv(G, rd.path(prefix + "caf.csv"));
  write_profiles_csv(pg, rd.path(prefix + "profiles.csv"));
  nlohmann::json j;
  j["schema"] = kGeometrySchema;
  j["program"] = program_json();
  j["inputs"] = inputs_json(cf, out_dir);
  j["profiles"] = profiles_json(pg);
  j["y_offset_mm"] = G.y_offset * units::per_mm;
  j["rail_gauge_point_y_mm"] = G.rail_gauge_y * units::per_mm;
  // The wheel's steepest flange section, against which flange climb is flagged (method.md §3.7).
  j["wheel_flange"] = G.has_flange ? nlohmann::json{{"gamma_max_deg", G.flange_gamma_max / units::deg},
                                                    {"y_steepest_mm", G.flange_y_steepest * units::per_mm}}
                                   : nlohmann::json(nullptr);
  j["strips"] = G.strip_y.size();
  j["grid_points"] = G.tY.size();
  j["potential_ellipses"] = ellipses_json(G);
  OutputFile f(rd.path(prefix + "geometry.json"));
  f.stream() << j.dump(2) << "\n";
  f.commit();
}

int geometry_batch_job(const nlohmann::json& mj, const std::string& manifest_path, const std::string& out_dir,
                       std::ostream& err, bool quiet, int digits) {
  const cells::DigitsScope digits_scope(digits);
  const Manifest m = parse_manifest(mj, manifest_path);
  RunDirectory rd(out_dir);
  OutputFile fp(rd.path("pairs.csv"));
  fp.stream() << "pair,name,status,n_ellipses,message\n";
  std::uint64_t invalid = 0;
  for (std::size_t k = 0; k < m.pairs.size(); ++k) {
    std::string row = std::to_string(k) + ",";
    cells::csv_text(row, m.pairs[k].name);
    try {
      const CaseFile cf = pair_case(m, k);
      const PairGeometry pg = build_pair_geometry(cf);
      if (!quiet) warn_profiles(pg, err);
      write_pair_geometry(cf, pg, rd, "pairs/" + std::to_string(k) + "/", out_dir);
      row += ",ok," + std::to_string(pg.geo.n_ellipses()) + ",";
    } catch (const InputError& e) {
      ++invalid;
      row += ",invalid_pair,,";
      cells::csv_text(row, e.what());
    }
    fp.stream() << row << "\n";
  }
  fp.commit();
  rd.finish("geometry", program_json(), {{"digits", digits ? nlohmann::json(digits) : nlohmann::json("max")},
                                         {"pairs", m.pairs.size()}, {"invalid_pairs", invalid}});
  if (!quiet)
    err << "mhcontact geometry: " << m.pairs.size() << " pairs (" << invalid << " invalid); wrote " << out_dir
        << "/pairs.csv and pairs/<k>/caf.csv, geometry.json, profiles.csv\n";
  return invalid ? kExitCasesFailed : kExitOk;
}

int geometry_job(const CaseFile& cf, const std::string& out_dir, std::ostream& out, std::ostream& err, bool quiet,
                 int digits) {
  const auto t0 = std::chrono::steady_clock::now();
  const cells::DigitsScope digits_scope(digits);
  const PairGeometry pg = build_pair_geometry(cf);
  const ContactGeometry& G = pg.geo;
  if (!quiet) warn_profiles(pg, err);
  RunDirectory rd(out_dir);
  write_pair_geometry(cf, pg, rd, "", out_dir);
  rd.finish("geometry", program_json(), {{"digits", digits ? nlohmann::json(digits) : nlohmann::json("max")}});
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!quiet)
    err << "mhcontact geometry: " << G.n_ellipses() << " potential ellipses over t_Y " << format_number(G.tY.front() * units::per_mm)
        << " .. " << format_number(G.tY.back() * units::per_mm) << " mm (" << G.tY.size() << " grid points, "
        << G.strip_y.size() << " strips) in " << format_number(std::round(secs * 1e3) / 1e3) << " s; wrote "
        << out_dir << "/caf.csv, geometry.json, profiles.csv\n";
  (void)out;
  return kExitOk;
}

int run_job(const CaseFile& cf, const RunOptions& opt, std::ostream& out, std::ostream& err) {
  cf.refuse_table_axes();
  const auto t0 = std::chrono::steady_clock::now();
  const cells::DigitsScope digits_scope(opt.digits);
  const PairGeometry pg = build_pair_geometry(cf);
  const ContactGeometry& G = pg.geo;
  if (!opt.quiet) warn_profiles(pg, err);
  const bool plastic = cf.model == Model::Plastic;
  const Method M = cf.method;
  const bool to_stdout = opt.out_dir == "-";
  const bool want_csv = opt.csv && !to_stdout;
  const bool want_json = opt.json || to_stdout;

  std::unique_ptr<RunDirectory> rd;
  std::unique_ptr<OutputFile> fc, fe, fg, fpa, fj, fp, fs;
  const int np = opt.pressure_grid;
  if (opt.strips && M != Method::Strips && M != Method::Auto)
    throw InputError("--strips", "", "writes the strips of the strip method; the case's method is " + std::string(to_string(M)),
                     "set \"method\": \"strips\" (or \"auto\") in the case file or drop --strips");
  if (opt.strips && to_stdout) throw InputError("--strips", "", "needs an output directory (not -o -)");
  if (np && (M == Method::Strips || M == Method::Auto))
    throw InputError("--pressure-grid", std::to_string(np),
                     std::string("the ") + (M == Method::Auto ? "\"auto\"" : "strip") + " method writes no pressure grid",
                     "use --strips for the strips, or a single method");
  if (np && to_stdout)
    throw InputError("--pressure-grid", std::to_string(np), "needs an output directory (not -o -)");
  if (to_stdout && !opt.json)
    throw InputError("--format", "csv", "-o - writes results.json to standard output; the CSV tables need an output directory",
                     "give -o DIR, or --format json");
  if (opt.shard_count < 1 || opt.shard_index < 1 || opt.shard_index > opt.shard_count)
    throw InputError("--shard", std::to_string(opt.shard_index) + "/" + std::to_string(opt.shard_count), "must be K/N with 1 <= K <= N");
  check_pressure_cases(opt, cf.case_count());
  const ShardSlice slice = shard_slice(cf.case_count(), opt.shard_index, opt.shard_count, opt.shard_sizes);
  check_pressure_grid(np, opt.pressure_cases.count_in(slice.first, slice.end),
                      plastic, opt.force, cf.tangential.enabled());
  if (!to_stdout) {
    rd = std::make_unique<RunDirectory>(opt.out_dir);
    if (np) {
      fp = std::make_unique<OutputFile>(rd->path("pressure.csv"));
      fp->stream() << pressure_table_header(M, plastic, cf.tangential.enabled());
    }
    if (want_csv) {
      fc = std::make_unique<OutputFile>(rd->path("cases.csv"));
      fc->stream() << cases_csv_header(cf.tangential.enabled(), cf.rcf.enabled());
      if (writes_ellipses(M)) {
        fe = std::make_unique<OutputFile>(rd->path("ellipses.csv"));
        fe->stream() << ellipses_csv_header(plastic, cf.rcf.enabled(), cf.tangential.enabled(), cf.rcf.subsurface);
        fg = std::make_unique<OutputFile>(rd->path("geometry.csv"));
        fg->stream() << geometry_csv_header();
      }
      if (writes_patches(M)) {
        fpa = std::make_unique<OutputFile>(rd->path("patches.csv"));
        fpa->stream() << patches_csv_header(plastic, cf.rcf.enabled(), cf.tangential.enabled(), cf.rcf.subsurface);
      }
    }
    if (want_json) fj = std::make_unique<OutputFile>(rd->path("results.json"));
  }
  std::ostream* js = to_stdout ? &out : (fj ? &fj->stream() : nullptr);
  std::unique_ptr<JsonObjectStream> jw;
  std::vector<RecordSpan> json_spans;  // a shard's record arrays in results.json, for the merge
  if (js) {
    jw = std::make_unique<JsonObjectStream>(*js);
    if (fj && opt.shard_count > 1) jw->record_spans(&json_spans);
    jw->member("schema", kResultsSchema);
    jw->member("program", program_json());
    jw->member("inputs", inputs_json(cf, to_stdout ? std::string() : opt.out_dir));
    jw->member("case_count", cf.case_count());
    jw->member("profiles", profiles_json(pg));
    jw->member("potential_ellipses", ellipses_json(G));
  }

  const std::uint64_t n_all = cf.case_count();
  const std::uint64_t first = slice.first, end = slice.end;
  // The load-independent part of the ellipses, once per (t_Y, ellipse), before the cases
  // (geometry.csv; results.json "geometry").
  if (writes_ellipses(M)) {
    if (jw) jw->begin_array("geometry");
    write_geometry(cf, G, first, end, fg ? &fg->stream() : nullptr, "", jw.get());
    if (jw) jw->end_array();
  }
  if (jw) jw->begin_array("cases");
  const std::uint64_t n = end - first;
  SweepCounts counts;
  // The damage weighted over t_Y needs every t_Y of the sweep: a whole run, not one shard of it.
  if (opt.shard_count == 1 && cf.tangential.enabled())
    counts.tY_mean_mm = cf.rcf.tY_mean * units::per_mm, counts.tY_sd_mm = cf.rcf.tY_sd * units::per_mm;
  if (opt.strips) {
    fs = std::make_unique<OutputFile>(rd->path("strips.csv"));
    fs->stream() << strips_csv_header();
  }
  Sinks sinks{fc ? &fc->stream() : nullptr, fe ? &fe->stream() : nullptr, fpa ? &fpa->stream() : nullptr,
              fp ? &fp->stream() : nullptr, fs ? &fs->stream() : nullptr, jw.get(), "",
              to_stdout ? "standard output" : "results.json", {}};
  for (OutputFile* f : {fc.get(), fe.get(), fpa.get(), fp.get(), fs.get(), fj.get()})
    if (f) sinks.files.push_back(f);
  solve_cases(cf, G, first, end, opt, sinks, &counts, err, &pg.band);
  const auto& by_status = counts.by_status;
  const std::uint64_t failed = counts.failed;
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (jw) {
    jw->end_array();
    nlohmann::json summary = counts.summary_json(n);
    summary.update(pair_summary_json(pg));
    jw->member("summary", summary);
    jw->end();
  }
  const nlohmann::json json_layout = fj ? results_layout(fj->stream(), json_spans) : nlohmann::json();
  if (fc) {
    fc->commit();
    if (fe) fe->commit();
    if (fg) fg->commit();
    if (fpa) fpa->commit();
    write_profiles_csv(pg, rd->path("profiles.csv"));
  }
  if (opt.shard_count > 1 && !to_stdout) {
    nlohmann::json sh = {{"schema", "mhcontact.shard/1"}, {"index", opt.shard_index}, {"count", opt.shard_count},
                         {"unit", "case"}, {"first", first}, {"end", end}, {"total", n_all},
                         {"summary", [&] { nlohmann::json su = counts.summary_json(n_all); su.update(pair_summary_json(pg)); return su; }()},
                         {"csv", want_csv}, {"json", want_json}, {"pressure", np > 0}, {"digits", opt.digits},
                         {"inputs", inputs_json(cf)}, {"profiles", profiles_json(pg)}};
    if (opt.shard_sizes != ShardSizes::Equal) sh["sizes"] = to_string(opt.shard_sizes);
    if (fj) sh["results_json"] = json_layout;
    OutputFile f(rd->path("shard.json"));
    f.stream() << sh.dump(2) << "\n";
    f.commit();
  }
  if (fj) fj->commit();
  if (fp) fp->commit();
  if (fs) fs->commit();
  if (rd) rd->finish("run", program_json(), {{"digits", opt.digits ? nlohmann::json(opt.digits) : nlohmann::json("max")}, {"summary", counts.summary_json(n)}, {"pair", pair_summary_json(pg)}});
  if (to_stdout) check_written(out, "standard output");
  if (!opt.quiet) {
    if (opt.progress) err << "\n";
    err << pair_summary_line(pg);
    err << "mhcontact run: " << n << " cases";
    if (opt.shard_count > 1) err << " (shard " << opt.shard_index << "/" << opt.shard_count << ": cases " << first << " .. " << end - 1 << ")";
    for (const auto& [k, v] : by_status) err << ", " << k << " " << v;
    // Warnings reach the user: cases with each kind of warning.
    for (const auto& [k, v] : counts.warnings) err << ", " << v << " with " << k;
    err << "; " << G.n_ellipses() << " potential ellipses; " << format_number(std::round(secs * 1e3) / 1e3) << " s";
    if (!to_stdout) err << "; outputs in " << opt.out_dir;
    err << "\n";
  }
  // --fail-on-warning, --fail-on: case warnings, and a rail cant that looks wrong (applied twice, mirrored).
  const std::string warned = warnings_failure(opt, counts, pg.cant.warnings.empty() ? 0 : 1);
  if (!opt.quiet) err << warned;
  return (failed || !warned.empty()) ? kExitCasesFailed : kExitOk;
}


}  // namespace mh
