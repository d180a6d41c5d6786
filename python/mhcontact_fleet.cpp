// The fleet entry of the Python module (mhcontact.fleet, python/mhcontact/fleet.py): one shard of
// `mhcontact run` and `mhcontact merge`, called in-process through lib/jobs (the same code as
// the command, so the same tables), with the GIL released while they run. No signal handlers are
// installed (unlike the command): a Dask worker keeps its own.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <exception>
#include <sstream>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "input/case_file.hpp"
#include "input/manifest.hpp"
#include "jobs/batch.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/contact_table_shards.hpp"
#include "jobs/run.hpp"
#include "jobs/shards.hpp"

namespace py = pybind11;

namespace {

// Runs f() without the GIL and returns its result; an InputError becomes `input_error`
// (mhcontact.InputError) with the command's message, any other failure a RuntimeError.
template <class F>
auto guarded(const py::object& input_error, F&& f) -> decltype(f()) {
  decltype(f()) result{};
  std::string input_msg, other_msg;
  {
    py::gil_scoped_release release;
    try {
      result = f();
    } catch (const mh::InputError& e) {
      input_msg = e.what();
    } catch (const std::exception& e) {
      other_msg = e.what();
    }
  }
  if (!input_msg.empty()) {
    PyErr_SetString(input_error.ptr(), input_msg.c_str());
    throw py::error_already_set();
  }
  if (!other_msg.empty()) throw std::runtime_error(other_msg);
  return result;
}

// A job's (exit code, what it wrote on its error stream).
template <class F>
py::tuple call_job(const py::object& input_error, F&& f) {
  std::ostringstream err;
  const int rc = guarded(input_error, [&] { return f(err); });
  return py::make_tuple(rc, err.str());
}

// The options of `mhcontact table` from a dict (the command's long options with _ for -, e.g.
// {"refine": 3, "tol_pmax": 0.03, "check": True}); an unknown key is a TypeError naming it.
mh::TableMakeOptions table_options(const py::dict& d, unsigned threads) {
  mh::TableMakeOptions o;
  o.threads = threads;
  o.quiet = true;
  for (const auto& kv : d) {
    const std::string k = py::str(kv.first);
    const py::handle v = kv.second;
    if (k == "refine") o.refine = v.cast<int>();
    else if (k == "check") o.check = v.cast<bool>();
    else if (k == "min_step_mm") o.min_step_mm = v.cast<double>();
    else if (k == "min_Q_step_kN") o.min_Q_step_kN = v.cast<double>();
    else if (k == "min_roll_step_mrad") o.min_roll_step_mrad = v.cast<double>();
    else if (k == "tol_N") o.tol_N = v.cast<double>();
    else if (k == "tol_pmax") o.tol_pmax = v.cast<double>();
    else if (k == "check_points") o.check_points = v.cast<int>();
    else if (k == "validate") o.validate = v.cast<int>();
    else
      throw py::type_error("table options: unknown key '" + k + "' (refine, check, check_points, validate, min_step_mm, "
                           "min_Q_step_kN, min_roll_step_mrad, tol_N, tol_pmax)");
  }
  if (o.refine < 0 || o.refine > 8) throw py::value_error("table options: refine must be 0 ... 8 (as --refine)");
  if (o.check_points != 1 && o.check_points != 3) throw py::value_error("table options: check_points must be 1 or 3 (as --check-points)");
  if (o.validate < 0 || o.validate > 100000) throw py::value_error("table options: validate must be 0 ... 100000 (as --validate)");
  return o;
}

}  // namespace

void bind_fleet(py::module_& m, py::object input_error) {
  m.def("_table_shard", [input_error](const std::string& path, unsigned k, unsigned n, const std::string& points_path,
                                      unsigned threads, const py::dict& options) {
        const mh::TableMakeOptions o = table_options(options, threads);
        std::ostringstream out;
        const py::tuple r = call_job(input_error, [&](std::ostream& err) {
          const mh::CaseFile cf = mh::load_case_file(path, true);
          return mh::table_shard_job(cf, o, std::to_string(k) + "/" + std::to_string(n), "-", out, err, points_path);
        });
        return py::make_tuple(r[0], r[1], py::bytes(out.str()));
      }, py::arg("path"), py::arg("k"), py::arg("n"), py::arg("points_path"), py::arg("threads"), py::arg("options"),
      "`mhcontact table PATH --shard K/N [--points POINTS] -o -`: (exit code, standard error, the shard file's bytes).");
  m.def("_table_merge", [input_error](const std::string& path, const std::vector<std::string>& parts,
                                      const std::string& next_path, const std::string& out_path, unsigned threads,
                                      const py::dict& options) {
        const mh::TableMakeOptions o = table_options(options, threads);
        return call_job(input_error, [&](std::ostream& err) {
          std::ostringstream out;
          const mh::CaseFile cf = mh::load_case_file(path, true);
          return mh::table_job(cf, o, out_path, out, err, parts, next_path);
        });
      }, py::arg("path"), py::arg("parts"), py::arg("next_path"), py::arg("out_path"), py::arg("threads"),
      py::arg("options"),
      "`mhcontact table PATH --merge PARTS --next NEXT -o OUT`: (exit code, standard error); 5: the points of the "
      "next pass written to NEXT, no table.");
  m.def("_fleet_units", [input_error](const std::string& path) {
        const auto units = guarded(input_error, [&] {
          const nlohmann::json j = mh::read_json_file(path);
          if (mh::is_manifest(j)) return std::pair<std::string, std::uint64_t>("pair", mh::parse_manifest(j, path).pairs.size());
          return std::pair<std::string, std::uint64_t>("case", mh::parse_case_json(j, path, true).case_count());
        });
        return py::make_tuple(units.first, units.second);
      }, py::arg("path"),
      "(unit, count): a manifest's pairs (\"pair\") or a case file's cases (\"case\"), the units a shard slices.");
  m.def("_fleet_plan", [input_error](const std::string& path) {
        struct Plan { std::string unit; std::uint64_t units = 0, cases = 0; std::string method; };
        const Plan p = guarded(input_error, [&] {
          const nlohmann::json j = mh::read_json_file(path);
          if (mh::is_manifest(j)) {
            const mh::Manifest m = mh::parse_manifest(j, path);
            const mh::CaseFile shared = mh::pair_case(m, 0);
            return Plan{"pair", m.pairs.size(), m.pairs.size() * shared.case_count(), mh::to_string(shared.method)};
          }
          const mh::CaseFile cf = mh::parse_case_json(j, path, true);
          return Plan{"case", cf.case_count(), cf.case_count(), mh::to_string(cf.method)};
        });
        return py::make_tuple(p.unit, p.units, p.cases, p.method);
      }, py::arg("path"),
      "(unit, count, cases, method): a manifest's pairs (\"pair\") or a case file's cases (\"case\"), the "
      "run's cases in all, and its method (as the case file names it): what fleet() cuts into shards.");
  m.def("_run_shard", [input_error](const std::string& path, const std::string& out_dir, unsigned k, unsigned n,
                                    unsigned threads, int digits, bool by_cases, const std::string& sizes) {
        return call_job(input_error, [&](std::ostream& err) {
          mh::RunOptions ro;
          ro.out_dir = out_dir;
          ro.shard_index = k;
          ro.shard_count = n;
          ro.threads = threads;
          ro.digits = digits;
          ro.quiet = true;
          ro.shard_by_cases = by_cases;
          ro.shard_sizes = mh::parse_shard_sizes(sizes);
          std::ostringstream out;
          const nlohmann::json j = mh::read_json_file(path);
          if (mh::is_manifest(j)) return mh::batch_job(mh::parse_manifest(j, path), ro, out, err);
          return mh::run_job(mh::parse_case_json(j, path, true), ro, out, err);
        });
      }, py::arg("path"), py::arg("out_dir"), py::arg("k"), py::arg("n"), py::arg("threads"), py::arg("digits"),
      py::arg("by_cases") = false, py::arg("sizes") = "equal",
      "`mhcontact run PATH -o OUT_DIR --shard K/N --threads T --digits D -q` (by_cases: --shard-by cases; "
      "sizes: --shard-sizes): "
      "(exit code, standard error).");
  m.def("_merge", [input_error](const std::vector<std::string>& dirs, const std::string& out_dir) {
        return call_job(input_error, [&](std::ostream& err) { return mh::merge_job(dirs, out_dir, err, true); });
      }, py::arg("dirs"), py::arg("out_dir"), "`mhcontact merge DIRS -o OUT_DIR -q`: (exit code, standard error).");
}
