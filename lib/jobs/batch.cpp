#include "jobs/batch.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <utility>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "core/numfmt.hpp"
#include "jobs/run.hpp"
#include "jobs/shard_text.hpp"
#include "output/case_tables.hpp"
#include "output/cells.hpp"
#include "output/json_stream.hpp"
#include "output/output_file.hpp"
#include "output/pair_tables.hpp"
#include "output/run_dir.hpp"

namespace mh {

using cells::csv_text;

namespace {
// A pair's profile as pairs.csv names it when the pair could not be read: the file name (or the
// standard profile's name) as given, in the same form as a read profile's source, not JSON.
std::string source_text(const nlohmann::json& side) {
  const nlohmann::json* p = &side;
  if (side.is_object() && side.contains("profile")) p = &side["profile"];
  if (p->is_string()) return p->get<std::string>();
  if (p->is_object()) {
    if (p->contains("file") && (*p)["file"].is_string()) return (*p)["file"].get<std::string>();
    if (p->contains("standard") && (*p)["standard"].is_string()) return "standard:" + (*p)["standard"].get<std::string>();
  }
  return p->dump();
}
}  // namespace

int batch_job(const Manifest& m, const RunOptions& opt, std::ostream& out, std::ostream& err) {
  (void)out;
  const auto t0 = std::chrono::steady_clock::now();
  const cells::DigitsScope digits_scope(opt.digits);
  if (opt.out_dir == "-") throw InputError("-o", "-", "a batch writes several tables: give an output directory");
  if (opt.strips) throw InputError("--strips", "", "is not available for batch manifests", "run the pair's case file alone");
  const std::uint64_t n_pairs = m.pairs.size();
  const CaseFile shared = pair_case(m, 0);  // validated already: the sweep and the model
  const std::uint64_t n = shared.case_count();  // cases of every pair (the shared sweep)
  // The shard's slice: of the pairs (unit "pair"), or with shard_by_cases of the list of every
  // pair's cases, pair after pair (unit "pair_case": global case g = pair · n + case), so that a
  // pair's cases can be spread over shards. [pair_first, pair_end): the pairs the slice touches.
  const bool by_cases = opt.shard_by_cases && opt.shard_count > 1;
  const std::uint64_t units = by_cases ? n_pairs * n : n_pairs;
  const ShardSlice slice = shard_slice(units, opt.shard_index, opt.shard_count, opt.shard_sizes);
  const std::uint64_t first = slice.first, end = slice.end;
  const std::uint64_t pair_first = by_cases ? (n ? first / n : 0) : first;
  const std::uint64_t pair_end = by_cases ? (first == end || !n ? pair_first : (end + n - 1) / n) : end;
  // The pair's cases [lo, hi) in this shard.
  auto case_range = [&](std::uint64_t k) {
    if (!by_cases) return std::pair<std::uint64_t, std::uint64_t>(0, n);
    return std::pair<std::uint64_t, std::uint64_t>(std::max(first, k * n) - k * n, std::min(end, (k + 1) * n) - k * n);
  };
  const bool plastic = shared.model == Model::Plastic;
  const Method M = shared.method;
  if (opt.pressure_grid && (M == Method::Strips || M == Method::Auto))
    throw InputError("--pressure-grid", std::to_string(opt.pressure_grid), "the strip and \"auto\" methods write no pressure grid",
                     "use a single grid method or the multi-Hertzian method");
  const int np = opt.pressure_grid;
  check_pressure_cases(opt, shared.case_count());
  std::uint64_t pressure_count = 0;
  for (std::uint64_t k = pair_first; k < pair_end; ++k)
    pressure_count += opt.pressure_cases.count_in(case_range(k).first, case_range(k).second);
  check_pressure_grid(np, pressure_count, plastic, opt.force, shared.tangential.enabled());
  RunDirectory rd(opt.out_dir);
  std::unique_ptr<OutputFile> fc, fe, fg, fpa, fp, fpp, fj;
  std::unique_ptr<JsonObjectStream> jw;
  std::vector<RecordSpan> json_spans;  // a shard's record arrays in results.json, for the merge
  if (opt.csv) {
    fc = std::make_unique<OutputFile>(rd.path("cases.csv"));
    if (writes_ellipses(M)) {
      fe = std::make_unique<OutputFile>(rd.path("ellipses.csv"));
      fg = std::make_unique<OutputFile>(rd.path("geometry.csv"));
    }
    if (writes_patches(M)) fpa = std::make_unique<OutputFile>(rd.path("patches.csv"));
    fpp = std::make_unique<OutputFile>(rd.path("pairs.csv"));
    fc->stream() << "pair," << cases_csv_header(shared.tangential.enabled(), shared.rcf.enabled());
    if (fe) fe->stream() << "pair," << ellipses_csv_header(plastic, shared.rcf.enabled(), shared.tangential.enabled(), shared.rcf.subsurface);
    if (fg) fg->stream() << "pair," << geometry_csv_header();
    if (fpa) fpa->stream() << "pair," << patches_csv_header(plastic, shared.rcf.enabled(), shared.tangential.enabled(), shared.rcf.subsurface);
    fpp->stream() << "pair,name,wheel,rail,status,n_ellipses,wheel_sha256,rail_sha256,message\n";
  }
  if (np) {
    fp = std::make_unique<OutputFile>(rd.path("pressure.csv"));
    fp->stream() << "pair," << pressure_table_header(M, plastic, shared.tangential.enabled());
  }
  if (opt.json) {
    fj = std::make_unique<OutputFile>(rd.path("results.json"));
    jw = std::make_unique<JsonObjectStream>(fj->stream());
    if (opt.shard_count > 1) jw->record_spans(&json_spans);
    jw->member("schema", kBatchSchema);
    jw->member("program", program_json());
    jw->member("manifest", m.path);
    jw->member("pair_count", n_pairs);
    jw->begin_array("pairs");
  }
  SweepCounts counts;
  auto& by_status = counts.by_status;
  std::uint64_t invalid = 0, cases_total = 0, cant_warned = 0;
  std::set<std::string> printed;  // (profile source, warning) already printed
  RunOptions quiet_opt = opt;
  quiet_opt.progress = false;
  std::uint64_t pairs_here = 0, cases_done = 0;
  for (std::uint64_t k = pair_first; k < pair_end; ++k) {
    const ManifestPair& P = m.pairs[k];
    const auto [lo, hi] = case_range(k);
    // The shard that holds the pair's first case writes the pair's own facts (its pairs.csv row,
    // geometry, pairs/<k>/, its record's head, the pair counts); a shard that continues the pair
    // writes its cases only (its record: "pair" and "cases", joined to the head by the merge).
    const bool head = lo == 0;
    const std::string prefix = std::to_string(k) + ",";
    std::string status = "ok", message;
    std::unique_ptr<PairGeometry> pg;
    CaseFile cf;
    try {
      cf = pair_case(m, k);
      pg = std::make_unique<PairGeometry>(build_pair_geometry(cf));
    } catch (const InputError& e) {
      status = kInvalidPair;
      message = e.what();
    }
    cases_total += hi - lo;
    if (head) ++pairs_here;
    if (fpp && head) {
      std::string row = prefix;
      csv_text(row, P.name);
      row += ',';
      csv_text(row, pg ? pg->wheel.source : source_text(P.wheel));
      row += ',';
      csv_text(row, pg ? pg->rail.source : source_text(P.rail));
      row += ',' + status + ',' + (pg ? std::to_string(pg->geo.n_ellipses()) : std::string()) + ',';
      row += (pg ? pg->wheel.checksum : std::string()) + ',' + (pg ? pg->rail.checksum : std::string()) + ',';
      csv_text(row, message);
      fpp->stream() << row << '\n';
    }
    // The pair's record in results.json: an object of its own, with its cases streamed.
    std::unique_ptr<JsonObjectStream> pw;
    if (jw) {
      jw->element_open();
      pw = std::make_unique<JsonObjectStream>(fj->stream(), 6);
      if (opt.shard_count > 1) pw->record_spans(&json_spans);
      pw->member("pair", k);
    }
    if (pw && head) {
      pw->member("name", P.name);
      pw->member("status", status);
      pw->member("message", message);
      if (pg) {
        pw->member("inputs", inputs_json(cf, opt.out_dir));
        pw->member("profiles", profiles_json(*pg));
        pw->member("potential_ellipses", ellipses_json(pg->geo));
      }
    }
    // The load-independent part of the pair's ellipses, once per (t_Y, ellipse), before its cases
    // (geometry.csv; the pair record's "geometry").
    if (pg && head && writes_ellipses(M)) {
      if (pw) pw->begin_array("geometry");
      write_geometry(cf, pg->geo, 0, n, fg ? &fg->stream() : nullptr, prefix, pw.get());
      if (pw) pw->end_array();
    }
    if (pw) pw->begin_array("cases");
    if (pg) {
      // A profile's warnings once per batch, not once per pair it is in (the same five
      // lines appeared eight times): the reader's warnings of a file, and any pair-level warning
      // with the same text, are printed the first time they occur.
      if (!opt.quiet && head)
        for (const Profile* p : {&pg->wheel, &pg->rail})
          for (const auto& w : p->warnings)
            if (printed.insert(p->source + '\n' + w).second) err << "mhcontact: warning: " << p->source << ": " << w << "\n";
      if (head && !pg->cant.warnings.empty()) ++cant_warned;
      // Each pair can be inspected on its own: its profiles, CAF and potential
      // ellipses, as `mhcontact geometry` writes them for one pair.
      if (head) write_pair_geometry(cf, *pg, rd, "pairs/" + std::to_string(k) + "/", opt.out_dir);
      Sinks sinks{fc ? &fc->stream() : nullptr, fe ? &fe->stream() : nullptr, fpa ? &fpa->stream() : nullptr,
                  fp ? &fp->stream() : nullptr, nullptr, pw.get(), prefix, "results.json", {}};
      for (OutputFile* f : {fc.get(), fe.get(), fpa.get(), fp.get(), fj.get()})
        if (f) sinks.files.push_back(f);
      solve_cases(cf, pg->geo, lo, hi, quiet_opt, sinks, &counts, err, &pg->band);
    } else {
      if (head) ++invalid;
      by_status[kInvalidPair] += hi - lo;
      counts.failed += hi - lo;  // counted as a single run counts its cases that are not ok
      for (std::uint64_t i = lo; i < hi; ++i) {
        CaseResult r;
        r.message = message;
        r.dz = r.approach = r.residual = r.Fz = r.Fy = r.pmax = r.area = NAN;
        Formatted f;
        format_case(i, shared.case_at(i), r, plastic, fc != nullptr, pw != nullptr, f, kInvalidPair, {},
                    shared.tangential.enabled());
        if (fc) put_prefixed(fc->stream(), prefix, f.cases);
        if (pw) pw->element(f.json);
      }
    }
    if (pw) {
      pw->end_array();
      pw->end();
    }
    if (opt.progress && !opt.quiet) {
      cases_done += hi - lo;
      err << "\r" << progress_line(cases_done, by_cases ? end - first : (end - first) * n,
                                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count())
          << std::flush;
    }
  }
  const std::uint64_t failed = counts.failed;  // cases not ok, invalid pairs' cases included
  const nlohmann::json summary = {{"pairs", pairs_here}, {"invalid_pairs", invalid}, {"cases", cases_total},
                                  {"failed", failed}, {"by_status", by_status},
                                  {"cases_with_warnings", counts.with_warnings}, {"warnings", counts.warnings},
                                  {"pairs_with_cant_warnings", cant_warned}};
  if (jw) {
    jw->end_array();
    jw->member("summary", summary);
    jw->end();
  }
  const nlohmann::json json_layout = fj ? results_layout(fj->stream(), json_spans) : nlohmann::json();
  if (fc) {
    fc->commit();
    if (fe) fe->commit();
    if (fg) fg->commit();
    if (fpa) fpa->commit();
    fpp->commit();
  }
  if (fp) fp->commit();
  if (fj) fj->commit();
  if (opt.shard_count > 1) {
    nlohmann::json sh = {{"schema", "mhcontact.shard/1"}, {"index", opt.shard_index}, {"count", opt.shard_count},
                         {"unit", by_cases ? "pair_case" : "pair"}, {"first", first}, {"end", end}, {"total", units},
                         {"cases_per_pair", n}, {"summary", summary},
                         {"csv", opt.csv}, {"json", opt.json}, {"pressure", np > 0}, {"digits", opt.digits},
                         {"inputs", {{"manifest", m.path}, {"common", m.common}, {"pairs", n_pairs}}}};
    if (opt.shard_sizes != ShardSizes::Equal) sh["sizes"] = to_string(opt.shard_sizes);
    if (fj) sh["results_json"] = json_layout;
    OutputFile f(rd.path("shard.json"));
    f.stream() << sh.dump(2) << "\n";
    f.commit();
  }
  rd.finish("run", program_json(), {{"digits", opt.digits ? nlohmann::json(opt.digits) : nlohmann::json("max")}, {"summary", summary}});
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!opt.quiet) {
    if (opt.progress) err << "\n";
    err << "mhcontact run: " << pairs_here << " pairs (" << invalid << " invalid), " << cases_total << " cases";
    for (const auto& [s, v] : by_status) err << ", " << s << " " << v;
    for (const auto& [k, v] : counts.warnings) err << ", " << v << " with " << k;
    if (cant_warned) err << ", " << cant_warned << " pairs with cant warnings";
    err << "; " << format_number(std::round(secs * 1e3) / 1e3) << " s; outputs in " << opt.out_dir << "\n";
  }
  // --fail-on-warning, --fail-on: case warnings, and rail cants that look wrong (applied twice, mirrored).
  const std::string warned = warnings_failure(opt, counts, cant_warned);
  if (!opt.quiet) err << warned;
  return (failed || invalid || !warned.empty()) ? kExitCasesFailed : kExitOk;
}


}  // namespace mh
