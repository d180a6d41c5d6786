#include "jobs/shards.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "jobs/shard_text.hpp"
#include "output/json_stream.hpp"
#include "output/output_file.hpp"
#include "output/run_dir.hpp"

namespace fs = std::filesystem;

namespace mh {

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

const char* to_string(ShardSizes s) { return s == ShardSizes::Tapered ? "tapered" : "equal"; }

ShardSizes parse_shard_sizes(const std::string& text) {
  if (text == "equal") return ShardSizes::Equal;
  if (text == "tapered") return ShardSizes::Tapered;
  throw InputError("--shard-sizes", text, "must be equal or tapered");
}

ShardSlice shard_slice(std::uint64_t units, unsigned K, unsigned N, ShardSizes sizes) {
  // ⌊u w(j) / w(N)⌋ exactly, w(j) = j (equal) or C(j) (tapered): u < 2^64 and w(N) < 2^34
  // (N ≤ 100000), so the product fits 128 bits.
  __extension__ typedef unsigned __int128 u128;
  auto w = [N, sizes](unsigned j) {
    return sizes == ShardSizes::Equal ? static_cast<u128>(j) : static_cast<u128>(j) * (2 * static_cast<u128>(N) - j + 1) / 2;
  };
  auto at = [&](unsigned j) { return static_cast<std::uint64_t>(static_cast<u128>(units) * w(j) / w(N)); };
  return {at(K - 1), at(K)};
}

namespace {

// Open a shard's CSV file and check its header against `header` (set from the first shard);
// the header is copied to `out` when `with_header`.
std::ifstream open_shard_csv(const std::string& path, std::ostream& out, std::string* header, bool with_header) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "missing in a shard directory");
  std::string line;
  std::getline(in, line);
  if (header->empty()) *header = line;
  else if (line != *header) throw InputError(path, "", "its header differs from the first shard's");
  if (with_header) out << line << '\n';
  return in;
}

// Copy a CSV file to `f`, skipping its header unless `with_header`; the header must equal `header`.
// The rows are copied as they stand (put_verbatim).
void append_csv(const std::string& path, OutputFile& f, std::string* header, bool with_header) {
  const ShardText csv(path, false, "missing in a shard directory");
  const std::string_view t = csv.text();
  const std::size_t nl = t.find('\n');
  const std::string_view line = t.substr(0, nl);
  if (header->empty()) *header = std::string(line);
  else if (line != *header) throw InputError(path, "", "its header differs from the first shard's");
  if (with_header) f.stream() << line << '\n';
  if (nl != std::string_view::npos) put_verbatim(f, csv, t.substr(nl + 1));
}

// geometry.csv of the shards: rows in shard order, a row whose key (its first `key_fields`
// fields: tY_mm,ellipse, in a case file's shards) an earlier shard already wrote is skipped, so the
// rows are those of one run: each (t_Y, ellipse) once, in order of first appearance in case order.
// Memory: the keys (a few per distinct t_Y).
void append_csv_dedupe(const std::string& path, std::ostream& out, std::string* header, bool with_header,
                       std::size_t key_fields, std::unordered_set<std::string>& seen) {
  std::ifstream in = open_shard_csv(path, out, header, with_header);
  std::string line;
  while (std::getline(in, line)) {
    std::size_t at = std::string::npos, from = 0;
    for (std::size_t k = 0; k < key_fields; ++k) {
      at = line.find(',', from);
      if (at == std::string::npos) break;
      from = at + 1;
    }
    if (!seen.insert(line.substr(0, at)).second) continue;
    out << line << '\n';
  }
}

// An integer field of shard.json, range-checked as an integer before any conversion
// (a count of 4294967297 must not wrap to 1; a string or 2.5 is an input error, not a crash).
std::uint64_t uint_field(const nlohmann::json& m, const char* key, const std::string& where, std::uint64_t lo, std::uint64_t hi) {
  const auto it = m.find(key);
  if (it == m.end()) throw InputError(where + ": /" + key, "", "missing: not a shard description");
  if (!it->is_number_unsigned() || it->get<std::uint64_t>() < lo || it->get<std::uint64_t>() > hi)
    throw InputError(where + ": /" + key, it->dump(), "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return it->get<std::uint64_t>();
}

// A run names its profile files relative to its output directory (inputs_json); a shard's are
// relative to the shard's directory. Rewrite them relative to the merged directory, as the
// single run writes them: `inputs` is an "inputs" object (wheel/rail → profile → file).
template <class Json>
void rebase_profile_files(Json& inputs, const fs::path& shard_dir, const fs::path& out_dir) {
  if (!inputs.is_object()) return;
  for (const char* side : {"wheel", "rail"}) {
    if (!inputs.contains(side) || !inputs[side].is_object() || !inputs[side].contains("profile")) continue;
    Json& p = inputs[side]["profile"];
    if (!p.is_object() || !p.contains("file") || !p["file"].is_string()) continue;
    const fs::path file = p["file"].template get<std::string>();
    if (file.is_absolute()) continue;  // written absolute when no relative path existed
    std::error_code ec;
    const fs::path abs = fs::absolute(shard_dir, ec) / file;
    const fs::path rel = fs::relative(abs, fs::absolute(out_dir, ec), ec);
    p["file"] = (ec || rel.empty()) ? abs.lexically_normal().string() : rel.string();
  }
}


// A member `inputs` written as the member "inputs" of a stream at `pad`: its profile files
// rebased from the shard's directory to the merged one (parsed: a few hundred bytes).
void write_inputs_rebased(JsonObjectStream& w, std::string_view value, const std::string& shard_dir, const std::string& out_dir,
                          const std::string& path) {
  nlohmann::ordered_json in;
  try {
    in = nlohmann::ordered_json::parse(value);
  } catch (const nlohmann::json::exception& e) {
    bad_results(path, 0, std::string("its \"inputs\" do not parse: ") + e.what());
  }
  rebase_profile_files(in, shard_dir, out_dir);
  w.member("inputs", in);
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
    if (!j.is_object() || j.value("schema", "") != "mhcontact.shard/1") throw InputError(p, "", "not a shard description (schema mhcontact.shard/1)");
    const std::uint64_t count = uint_field(j, "count", p, 1, 1000000);
    uint_field(j, "index", p, 1, count);
    const std::uint64_t total = uint_field(j, "total", p, 0, UINT64_MAX);
    const std::uint64_t end = uint_field(j, "end", p, 0, total);
    uint_field(j, "first", p, 0, end);
    shards.push_back({d, j});
  }
  std::sort(shards.begin(), shards.end(), [](const Shard& a, const Shard& b) { return a.meta["index"] < b.meta["index"]; });
  const auto N = shards[0].meta["count"].get<unsigned>();
  const std::string sizes0 = shards[0].meta.value("sizes", "equal");  // shard.json writes it only when tapered
  for (const auto& sh : shards)
    if (sh.meta["count"].get<unsigned>() != N)
      throw InputError(sh.dir + "/shard.json", "count " + sh.meta["count"].dump(),
                       "shards of different runs: " + shards[0].dir + " is one of " + std::to_string(N) + " shards, this one of " +
                           sh.meta["count"].dump(),
                       "give the directories of one run");
  {
    // Name the shards that are missing or given twice, not only their count.
    std::map<unsigned, std::vector<std::string>> dirs_of;
    for (const auto& sh : shards) dirs_of[sh.meta["index"].get<unsigned>()].push_back(sh.dir);
    std::string missing, twice;
    std::size_t n_missing = 0;
    for (unsigned k = 1; k <= N; ++k) {
      const auto it = dirs_of.find(k);
      if (it == dirs_of.end()) {
        if (++n_missing <= 20) missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(N);
      } else if (it->second.size() > 1) {
        twice += (twice.empty() ? "" : "; ") + std::to_string(k) + "/" + std::to_string(N) + " in";
        for (const auto& d : it->second) twice += " " + d;
      }
    }
    if (n_missing > 20) missing += " and " + std::to_string(n_missing - 20) + " more";
    if (!missing.empty() || !twice.empty())
      throw InputError("merge", std::to_string(shards.size()) + " directories",
                       "the run was split into " + std::to_string(N) + " shards: " +
                           (missing.empty() ? std::string() : "shard " + missing + " missing") +
                           (!missing.empty() && !twice.empty() ? "; " : "") +
                           (twice.empty() ? std::string() : "shard " + twice + " given twice"),
                       missing.empty() ? "give each shard's directory once"
                                       : "run the missing shard(s) with the same inputs (mhcontact run CASE -o DIR --shard K/" +
                                             std::to_string(N) + (sizes0 == "equal" ? std::string() : " --shard-sizes " + sizes0) +
                                             ") and give all " + std::to_string(N) + " directories");
  }
  std::uint64_t expect = 0;
  for (unsigned k = 0; k < N; ++k) {
    const nlohmann::json& m = shards[k].meta;
    const std::string where = shards[k].dir + "/shard.json";
    if (m["index"].get<unsigned>() != k + 1) throw InputError(where, m["index"].dump(), "shard " + std::to_string(k + 1) + " is missing or given twice");
    if (m["count"] != shards[0].meta["count"] || m["total"] != shards[0].meta["total"] || m["unit"] != shards[0].meta["unit"])
      throw InputError(where, "", "shards of different runs (case or shard counts differ)");
    if (m["inputs"] != shards[0].meta["inputs"]) throw InputError(where, "", "shards of different runs (inputs differ: case file, profiles or options)");
    if (m["csv"] != shards[0].meta["csv"] || m["json"] != shards[0].meta["json"] || m["pressure"] != shards[0].meta["pressure"] ||
        m.value("digits", -1) != shards[0].meta.value("digits", -1))
      throw InputError(where, "", "shards written with different output options");
    if (m.value("sizes", "equal") != sizes0)
      throw InputError(where, "sizes " + m.value("sizes", "equal"),
                       "shards cut with different --shard-sizes (" + shards[0].dir + ": " + sizes0 + ")",
                       "run every shard of a run with the same --shard-sizes");
    if (m["first"].get<std::uint64_t>() != expect) throw InputError(where, m["first"].dump(), "the shards' ranges do not tile the case (or pair) list");
    expect = m["end"].get<std::uint64_t>();
  }
  if (expect != shards[0].meta["total"].get<std::uint64_t>()) throw InputError("merge", "", "the shards do not cover every case (or pair)");
  // A manifest's shards: slices of its pairs ("pair"), or of every pair's cases ("pair_case":
  // a pair's cases may be spread over consecutive shards, and its record joined back).
  const bool batch = shards[0].meta["unit"] == "pair" || shards[0].meta["unit"] == "pair_case";
  const bool pair_cases = shards[0].meta["unit"] == "pair_case";
  std::uint64_t per_pair = 0;
  if (pair_cases) {
    per_pair = uint_field(shards[0].meta, "cases_per_pair", shards[0].dir + "/shard.json", 1, UINT64_MAX);
    for (const auto& sh : shards)
      if (sh.meta.value("cases_per_pair", nlohmann::json()) != shards[0].meta["cases_per_pair"])
        throw InputError(sh.dir + "/shard.json", "", "shards of different runs (cases per pair differ)");
  }
  RunDirectory rd(out_dir);
  // Summary of all shards: counts added up, by_status merged; `cases` and `pairs` are totals
  // of the whole run for unsharded-equal output (run: cases = total).
  nlohmann::json summary = nlohmann::json::object();
  std::map<std::string, std::uint64_t> by_status, warnings;
  for (const auto& sh : shards) {
    const nlohmann::json& su = sh.meta["summary"];
    for (auto it = su.begin(); it != su.end(); ++it) {
      if (it.key() == "by_status") {
        for (auto b = it.value().begin(); b != it.value().end(); ++b) by_status[b.key()] += b.value().get<std::uint64_t>();
      } else if (it.key() == "warnings") {
        for (auto b = it.value().begin(); b != it.value().end(); ++b) warnings[b.key()] += b.value().get<std::uint64_t>();
      } else if (!batch && it.key() == "cases") {
        summary["cases"] = it.value();
      } else if (!it.value().is_number_unsigned()) {
        // Facts of the profile pair (pair_summary_json: classes, cant, pair warnings): the same in
        // every shard.
        if (!summary.contains(it.key())) summary[it.key()] = it.value();
      } else {
        summary[it.key()] = summary.value(it.key(), std::uint64_t{0}) + it.value().get<std::uint64_t>();
      }
    }
  }
  summary["by_status"] = by_status;
  if (summary.contains("cases_with_warnings")) summary["warnings"] = warnings;
  const std::uint64_t failed = summary.value("failed", std::uint64_t{0}) + summary.value("invalid_pairs", std::uint64_t{0});
  const bool csv = shards[0].meta["csv"], json = shards[0].meta["json"], pressure = shards[0].meta["pressure"];
  std::vector<std::string> tables;
  if (csv) {
    // The per-contact tables: ellipses.csv (multi-Hertzian) and/or patches.csv (grid methods).
    tables = {"cases.csv"};
    for (const char* t : {"ellipses.csv", "geometry.csv", "patches.csv"})
      if (std::ifstream(shards[0].dir + "/" + t).good()) tables.push_back(t);
  }
  if (csv && batch) tables.push_back("pairs.csv");
  if (pressure) tables.push_back("pressure.csv");
  if (std::ifstream(shards[0].dir + "/strips.csv").good()) tables.push_back("strips.csv");
  for (const auto& t : tables) {
    OutputFile f(rd.path(t));
    std::string header;
    std::unordered_set<std::string> seen;
    for (unsigned k = 0; k < N; ++k) {
      // A batch's shards hold disjoint pairs, and its geometry.csv rows start with the pair: no
      // row can repeat.
      if (t == "geometry.csv" && !batch) append_csv_dedupe(shards[k].dir + "/" + t, f.stream(), &header, k == 0, 2, seen);
      else append_csv(shards[k].dir + "/" + t, f, &header, k == 0);
      f.start_writeback();
    }
    f.commit();
  }
  if (csv && !batch) {
    OutputFile f(rd.path("profiles.csv"));
    f.stream() << read_all(shards[0].dir + "/profiles.csv");
    f.commit();
  }
  if (batch) {
    // Each pair's profiles and contact geometry (pairs/<k>/, numbered over the whole manifest)
    // come from the one shard that solved the pair: copied as they are, in pair order.
    std::vector<std::pair<std::string, std::string>> files;  // (name in the run, source path)
    for (const auto& sh : shards) {
      const fs::path root = fs::path(sh.dir) / "pairs";
      std::error_code ec;
      if (!fs::is_directory(root, ec)) continue;
      for (fs::recursive_directory_iterator it(root, ec), e; !ec && it != e; it.increment(ec))
        if (it->is_regular_file()) files.emplace_back("pairs/" + fs::relative(it->path(), root).generic_string(), it->path().string());
      if (ec) throw InputError(root.string(), "", "cannot read the shard's per-pair files: " + ec.message());
    }
    std::sort(files.begin(), files.end());
    for (std::size_t i = 1; i < files.size(); ++i)
      if (files[i].first == files[i - 1].first)
        throw InputError(files[i].second, "", "two shards hold " + files[i].first + " (shards of different runs?)");
    for (const auto& [name, src] : files) {
      OutputFile f(rd.path(name));
      const bool geometry_json = fs::path(name).filename() == "geometry.json";
      if (!geometry_json) {
        f.stream() << read_all(src);
      } else {
        // Written by write_pair_geometry as nlohmann::json::dump(2): parsed, its inputs rebased
        // and dumped again, it is byte for byte what the single run writes.
        nlohmann::json g;
        try {
          g = nlohmann::json::parse(read_all(src));
        } catch (const nlohmann::json::exception& e) {
          throw InputError(src, "", std::string("not a geometry.json of mhcontact run: ") + e.what());
        }
        if (g.is_object() && g.contains("inputs")) rebase_profile_files(g["inputs"], fs::path(src).parent_path().parent_path().parent_path(), out_dir);
        f.stream() << g.dump(2) << "\n";
      }
      f.commit();
    }
  }
  if (json) {
    // Each shard's results.json holds the same head, its own cases (or pairs) and its summary.
    // Copied as text (split_object: no parse, no re-serialisation, so the merge costs about a
    // copy of the bytes): the first shard's head, the records of all in order, then the summary
    // of the whole run. Parsed: only the "inputs" (rebased to the merged directory) and, for a
    // case file, the "geometry" records (to keep each once). Checked: the layout, the schema
    // (the same as the first shard's) and the number of records (the shard's slice).
    // Memory: one shard's results.json at a time.
    const std::string key = batch ? "pairs" : "cases";
    struct Doc {
      std::string path;
      ShardText file;
      std::string_view text;
      std::vector<JsonMember> members;
      Doc(const std::string& p, bool whole)
          : path(p), file(p, whole, "cannot read (is this the output directory of a `run --shard`?)"), text(file.text()) {}
    };
    // A run's "geometry" records (one per (t_Y, ellipse), before the cases) are spread over the
    // shards like geometry.csv: a first pass over the members before the cases keeps each record
    // once, in shard order (the second pass checks the whole document).
    std::vector<std::string> geometry;
    bool has_geometry = false;
    if (!batch) {
      std::unordered_set<std::string> seen;
      for (unsigned k = 0; k < N; ++k) {
        Doc d(shards[k].dir + "/results.json", false);
        split_object(d.text, 0, 2, &d.members, d.path, key);
        const JsonMember* g = find_member(d.members, "geometry");
        if (!g) continue;
        has_geometry = true;
        std::string_view recs = array_records(g->value, 2, d.path, "geometry");
        const std::string sep = ",\n    ";
        while (!recs.empty()) {
          if (!text_at(recs, 0, "    ")) bad_results(d.path, 0, "a \"geometry\" record not at indentation 4");
          const std::size_t e = recs.find(sep);
          const std::string_view rec = recs.substr(4, e == std::string_view::npos ? std::string_view::npos : e - 4);
          recs = e == std::string_view::npos ? std::string_view() : recs.substr(e + 2);
          nlohmann::ordered_json r;
          try {
            r = nlohmann::ordered_json::parse(rec);
          } catch (const nlohmann::json::exception& ex) {
            bad_results(d.path, 0, std::string("a \"geometry\" record does not parse: ") + ex.what());
          }
          if (!r.is_object()) bad_results(d.path, 0, "a \"geometry\" record is not an object");
          if (seen.insert(r.value("tY_mm", nlohmann::ordered_json()).dump() + "," + r.value("ellipse", nlohmann::ordered_json()).dump()).second)
            geometry.emplace_back(rec);
        }
      }
    }
    OutputFile f(rd.path("results.json"));
    JsonObjectStream w(f.stream());
    std::string schema;
    // A batch's pair record is left open after its "cases" until the next record shows whether
    // it continues the pair (pair_case shards: a record of "pair" and "cases" only, whose cases
    // are appended) or starts another.
    std::unique_ptr<JsonObjectStream> open_pair;
    std::string open_pair_number;
    auto close_pair = [&]() {
      if (!open_pair) return;
      open_pair->end_array();
      open_pair->end();
      open_pair.reset();
    };
    for (unsigned k = 0; k < N; ++k) {
      // One pass over each shard's text (mapped whole): the members before the records, the
      // records (counted as they are split), the members after them.
      // With the record arrays' spans in its shard.json (written by this version), the records are
      // not read: only the text between them, the spans' ends and the document's size are checked.
      const nlohmann::json& layout = shards[k].meta.contains("results_json") ? shards[k].meta["results_json"] : nlohmann::json();
      Doc d(shards[k].dir + "/results.json", !layout.is_object());
      SpanSkip skip = span_skip(layout, d.text, d.path);
      std::size_t p = split_object(d.text, 0, 2, &d.members, d.path, key, &skip);
      if (d.members.empty() || d.members.front().key != "schema") bad_results(d.path, 0, "its first member must be \"schema\"");
      if (k == 0) {
        schema = std::string(d.members.front().value);
        for (const auto& m : d.members) {
          if (m.key == "inputs") write_inputs_rebased(w, m.value, shards[k].dir, out_dir, d.path);
          else if (m.key == "geometry" && has_geometry) {
            w.begin_array("geometry");
            for (const auto& g : geometry) w.element(g);
            w.end_array();
          } else {
            w.member_verbatim(m.key, m.value);
          }
        }
        w.begin_array(key);
      } else if (d.members.front().value != schema) {
        bad_results(d.path, 0, "schema " + std::string(d.members.front().value) + ", the first shard's is " + schema);
      }
      const std::string head = "\n  \"" + key + "\": ";
      if (!text_at(d.text, p, head)) bad_results(d.path, p, "no \"" + key + "\" array");
      const std::size_t at = p;
      const std::uint64_t s_first = shards[k].meta["first"].get<std::uint64_t>(), s_end = shards[k].meta["end"].get<std::uint64_t>();
      // The records the shard holds: its cases, its pairs, or the pairs its cases touch.
      const std::uint64_t want = !pair_cases ? s_end - s_first
                                 : s_first == s_end ? 0
                                                    : (s_end + per_pair - 1) / per_pair - s_first / per_pair;
      std::uint64_t have = 0;
      if (!batch) {
        // A case record is one line: the records are counted by their lines and copied in one piece.
        const std::size_t n_before = d.members.size();
        p = split_members(d.text, p, 2, &d.members, d.path, {}, &skip);
        const JsonMember& cases = d.members[n_before];
        elements_copied(w, f, d.file, array_records(cases.value, 2, d.path, key));
        have = cases.lines > 0 ? cases.lines - 1 : 0;
      } else {
        // A pair's record is an object (indentation 6) with its own arrays: copied member by
        // member, its "inputs" rebased.
        p += head.size();
        if (text_at(d.text, p, "[]")) {
          p += 2;
        } else {
          if (!text_at(d.text, p, "[\n")) bad_results(d.path, p, "\"pairs\" is not an array of records");
          for (p += 2;;) {
            if (!text_at(d.text, p, "    {")) bad_results(d.path, p, "a pair record expected at indentation 4");
            std::vector<JsonMember> pm;
            const std::size_t past = split_object(d.text, p + 4, 6, &pm, d.path, {}, &skip);
            if (pm.empty() || pm.front().key != "pair" || pm.back().key != "cases")
              bad_results(d.path, p, "a pair record must start with \"pair\" and end with \"cases\"");
            const bool continued = pair_cases && open_pair && have == 0 && pm.size() == 2 && pm.front().value == open_pair_number;
            if (!continued) {
              if (pm.size() == 2)
                bad_results(d.path, p, "it continues pair " + std::string(pm.front().value) + ", which the shard before does not end with");
              close_pair();
              w.element_open();
              open_pair = std::make_unique<JsonObjectStream>(f.stream(), 6);
              open_pair_number = std::string(pm.front().value);
              for (std::size_t i = 0; i + 1 < pm.size(); ++i) {
                const JsonMember& m = pm[i];
                if (m.key == "inputs") write_inputs_rebased(*open_pair, m.value, shards[k].dir, out_dir, d.path);
                else member_copied(*open_pair, f, d.file, m.key, m.value);
              }
              open_pair->begin_array("cases");
            }
            elements_copied(*open_pair, f, d.file, array_records(pm.back().value, 6, d.path, "cases"));
            ++have;
            if (text_at(d.text, past, ",\n")) {
              p = past + 2;
            } else if (text_at(d.text, past, "\n  ]")) {
              p = past + 4;
              break;
            } else {
              bad_results(d.path, past, "pair records not separated by a comma and a newline");
            }
          }
        }
        // The members after the records: `,` then the next member's line.
        if (!text_at(d.text, p, ",\n")) bad_results(d.path, p, "its last member must be \"summary\"");
        d.members.push_back({key, {}, 0});  // the records, copied above
        p = split_members(d.text, p + 1, 2, &d.members, d.path, {}, &skip);
      }
      if (skip.next != skip.spans.size())
        bad_results(d.path, skip.spans[skip.next].begin, "its shard.json's record span lies outside the document's record arrays");
      if (d.text.substr(p) != "\n") bad_results(d.path, p, "text after the document's end");
      // The run writes "summary" alone after the records (only the members before them are copied).
      if (d.members.back().key != "summary" || d.members[d.members.size() - 2].key != key)
        bad_results(d.path, 0, "its first member must be \"schema\", and \"summary\" alone must follow the \"" + key + "\"");
      if (have != want)
        bad_results(d.path, at, "it holds " + std::to_string(have) + " " + key + ", its shard.json " + std::to_string(want));
      f.start_writeback();
    }
    close_pair();
    w.end_array();
    w.member("summary", summary);
    w.end();
    f.commit();
  }
  rd.finish("merge", shards[0].meta.value("program", nlohmann::json::object()), {{"summary", summary}, {"shards", N}});
  if (!quiet) {
    err << "mhcontact merge: " << N << " shards, " << shards[0].meta["total"].get<std::uint64_t>() << (batch ? " pairs" : " cases");
    for (const auto& [k, v] : by_status) err << ", " << k << " " << v;
    err << "; outputs in " << out_dir << "\n";
  }
  return failed ? kExitCasesFailed : kExitOk;
}

}  // namespace mh

