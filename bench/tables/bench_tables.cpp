// mhcontact_bench_tables: a contact table stepped through t_Y = A sin(ωt) (docs/tables.md,
// docs/performance.md "Contact tables"). Figures printed, never asserted (the machines are shared).
// Usage: mhcontact_bench_tables CASE.json [STEPS] [Q_kN] [AMPLITUDE_mm] [DIRECT_EVERY] [HISTORY.csv] [OFFSET_mm]
//        [ROLL_AMPLITUDE_mrad]
//  1. the table of CASE.json (its method and sweep: `mhcontact table`) made, written and read back
//     through the C interface (mhc_table_read);
//  2. STEPS lookups (default 10,000) at t_Y = OFFSET + A sin(2π·5·k/STEPS) (five periods), Q fixed
//     (default 60 kN, A default 6 mm, OFFSET default 0), the wheel rolled by δ = B sin(2π·5·k/STEPS)
//     in phase (B = ROLL_AMPLITUDE, default 0: upright; a table with a roll axis), through
//     mhc_table_lookup_rolled: CPU time of the thread per lookup and per contact, median of 15 repeats;
//     then the same pair on both wheels of a wheelset table (mhc_wheelset_table_lookup at y = t_Y,
//     roll φ = δ, both loads Q), alternated with the pair lookups in the same repeats, and every
//     DIRECT_EVERY-th step against the wheelset call solving both rolled wheels directly;
//  3. every DIRECT_EVERY-th step (default 10; 1: every step) solved directly by the case's
//     method at that step's roll: statuses (direct ok, table ok, direct ok and table not) and the errors of N
//     (fraction of Q), pmax, area and Fy;
//  4. HISTORY.csv (optional): per step t_Y, the table's N per track, Fy and dFy/dt_Y, and the
//     direct Fy where solved (scripts/plot_table_history.py draws it).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <time.h>
#include <unistd.h>
#include <vector>

#include <mhcontact.h>

#include "contact/solve.hpp"
#include "input/case_file.hpp"
#include "jobs/contact_table_make.hpp"
#include "jobs/run.hpp"
#include "jobs/wheelset_table_make.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

static double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: mhcontact_bench_tables CASE.json [STEPS] [Q_kN] [AMPLITUDE_mm] [DIRECT_EVERY] [HISTORY.csv] [OFFSET_mm] "
                         "[ROLL_AMPLITUDE_mrad]\n");
    return 2;
  }
  const std::string case_path = argv[1];
  const int steps = argc > 2 ? std::atoi(argv[2]) : 10000;
  const double Q = (argc > 3 ? std::atof(argv[3]) : 60.0) * 1e3;
  const double A = (argc > 4 ? std::atof(argv[4]) : 6.0) * 1e-3;
  const int every = argc > 5 ? std::max(1, std::atoi(argv[5])) : 10;
  const std::string history = argc > 6 ? argv[6] : "";
  const double offset = (argc > 7 ? std::atof(argv[7]) : 0.0) * 1e-3;
  const double B = (argc > 8 ? std::atof(argv[8]) : 0.0) * 1e-3;

  // 1. Make the table and read it back through the C interface.
  const mh::CaseFile cf = mh::load_case_file(case_path, true);
  const mh::PairGeometry pg = mh::build_pair_geometry(cf);
  mh::TableMakeOptions mo;
  mo.quiet = true;
  std::ostringstream err;
  const mh::TableMade made = mh::make_contact_table(cf, pg, mo, err);
  const std::string path = "/tmp/mhcontact_bench_table_" + std::to_string(::getpid()) + ".csv";
  {
    std::ofstream o(path);
    mh::write_contact_table(made.data, o);
  }
  mhc_table* table = nullptr;
  if (mhc_table_read(path.c_str(), &table) != MHC_OK) {
    std::fprintf(stderr, "%s\n", mhc_last_message());
    return 1;
  }
  std::remove(path.c_str());
  std::printf("mhcontact %s: table of %s: %zu x %zu x %zu nodes (t_Y, Q, roll), %d tracks, %zu solves, %zu coarse cells\n",
              mhc_version(), case_path.c_str(), made.data.nT(), made.data.nQ(), made.data.nR(), made.data.n_tracks,
              made.solves, made.data.header["coarse_cells"].size());

  // 2. The lookups.
  std::vector<double> tY(static_cast<std::size_t>(steps)), roll(static_cast<std::size_t>(steps));
  for (int k = 0; k < steps; ++k) {
    tY[static_cast<std::size_t>(k)] = offset + A * std::sin(2 * M_PI * 5.0 * k / steps);
    roll[static_cast<std::size_t>(k)] = B * std::sin(2 * M_PI * 5.0 * k / steps);
  }
  std::vector<mhc_table_result> res(static_cast<std::size_t>(steps));
  for (auto& r : res) r.struct_size = sizeof(mhc_table_result);
  std::vector<double> per;
  double contacts = 0;
  for (int rep = 0; rep < 15; ++rep) {
    const double t0 = cpu_now();
    for (int k = 0; k < steps; ++k)
      mhc_table_lookup_rolled(table, tY[static_cast<std::size_t>(k)], Q, roll[static_cast<std::size_t>(k)],
                              &res[static_cast<std::size_t>(k)]);
    per.push_back((cpu_now() - t0) / steps);
  }
  for (const auto& r : res) contacts += r.n_contacts;
  std::sort(per.begin(), per.end());
  const double mean_contacts = contacts / steps;
  std::printf("lookups: %d steps, t_Y = %g + %g mm sin(wt), roll %g mrad sin(wt), Q = %g kN: %.3f us a lookup (median of 15), "
              "%.2f contacts a step, %.3f us a contact\n",
              steps, offset * 1e3, A * 1e3, B * 1e3, Q * 1e-3, per[per.size() / 2] * 1e6, mean_contacts,
              per[per.size() / 2] * 1e6 / mean_contacts);

  // 2b. The same pair on both wheels of a wheelset table (`mhcontact table-wheelset`): the wheelset
  // at y = the history's t_Y and roll φ = the history's δ, both loads Q, through
  // mhc_wheelset_table_lookup (two placements, two lookups, the track-frame sums); against the
  // pair lookups above, alternated in the same repeats.
  {
    const std::string pair_path = path + ".pair.csv", ws_path = path + ".wheelset.csv";
    {
      std::ofstream o(pair_path);
      mh::write_contact_table(made.data, o);
    }
    std::ostringstream wout, werr;
    mh::wheelset_table_job(pair_path, pair_path, ws_path, wout, werr, true);
    mhc_wheelset_table* wt = nullptr;
    if (mhc_wheelset_table_read(ws_path.c_str(), &wt) != MHC_OK) {
      std::fprintf(stderr, "%s\n", mhc_last_message());
      return 1;
    }
    std::remove(pair_path.c_str());
    std::remove(ws_path.c_str());
    mhc_wheelset_table_result wr;
    wr.struct_size = sizeof wr;
    std::vector<double> pw, pp;
    double wc = 0;
    int wok = 0;
    for (int rep = 0; rep < 15; ++rep) {
      double t0 = cpu_now();
      for (int k = 0; k < steps; ++k)
        mhc_table_lookup_rolled(table, tY[static_cast<std::size_t>(k)], Q, roll[static_cast<std::size_t>(k)],
                                &res[static_cast<std::size_t>(k)]);
      pp.push_back((cpu_now() - t0) / steps);
      t0 = cpu_now();
      wc = 0, wok = 0;
      for (int k = 0; k < steps; ++k) {
        mhc_wheelset_table_lookup(wt, tY[static_cast<std::size_t>(k)], roll[static_cast<std::size_t>(k)], Q, Q, &wr);
        wc += wr.wheel[0].n_contacts + wr.wheel[1].n_contacts;
        wok += wr.status == MHC_STATUS_OK;
      }
      pw.push_back((cpu_now() - t0) / steps);
    }
    std::sort(pw.begin(), pw.end());
    std::sort(pp.begin(), pp.end());
    const double mw = pw[pw.size() / 2], mp = pp[pp.size() / 2];
    std::printf("wheelset table (this pair on both wheels), y and roll as above: %.3f us a wheelset lookup (median of 15), "
                "%.2f contacts a step, %.3f us a contact, %d of %d steps ok; x %.2f the pair lookup's time in the same "
                "repeats (%.3f us)\n",
                mw * 1e6, wc / steps, mw * 1e6 / std::max(wc / steps, 1e-9), wok, steps, mw / mp, mp * 1e6);
    // Every DIRECT_EVERY-th step the wheelset call (the case's method, each wheel rolled) solves
    // both wheels directly: statuses, and the table's forces against its, per wheel.
    const mh::WheelsetContact wsc(pg.geo, pg.geo, cf.track, cf.material, cf.method_options(), {});
    mh::WheelsetWorkspace wwork;
    mh::WheelsetResult wres;
    mh::WheelsetPose pose;
    pose.Q_left = pose.Q_right = Q;
    pose.solve_roll = false;
    int nd = 0, dok = 0, tok = 0, dok_tnot = 0;
    double eF = 0, eM = 0;
    const double tw = cpu_now();
    for (int k = 0; k < steps; k += every) {
      const auto K = static_cast<std::size_t>(k);
      pose.y = tY[K];
      pose.roll = roll[K];
      wsc.step(pose, mh::WheelsetStepOptions(), wres, wwork);
      mhc_wheelset_table_lookup(wt, tY[K], roll[K], Q, Q, &wr);
      ++nd;
      const bool d_ok = wres.status == mh::CaseStatus::Ok, t_ok = wr.status == MHC_STATUS_OK;
      dok += d_ok, tok += t_ok, dok_tnot += d_ok && !t_ok;
      if (!d_ok || !t_ok) continue;
      for (int s = 0; s < 2; ++s) {
        const mh::WheelResult& w = s == 0 ? wres.left : wres.right;
        eF = std::max({eF, std::fabs(wr.wheel_Fy_N[s] - w.on_wheelset.F[1]) / Q, std::fabs(wr.wheel_Fz_N[s] - w.on_wheelset.F[2]) / Q});
        eM = std::max(eM, std::fabs(wr.wheel_Mx_Nm[s] - w.on_wheelset.M[0]) / (0.75 * Q));
      }
    }
    std::printf("wheelset call (%s, both wheels rolled) at every %d-th step: %d (%.1f ms each); ok: direct %d, table %d, "
                "direct ok and table not %d; where both ok: wheel Fy, Fz within %.3g %% of Q, Mx within %.3g %% of 0.75 m Q\n",
                mh::to_string(cf.method), every, nd, (cpu_now() - tw) / nd * 1e3, dok, tok, dok_tnot, 100 * eF, 100 * eM);
    mhc_wheelset_table_free(wt);
  }

  // 3. Direct solves.
  int n_direct = 0, direct_ok = 0, table_ok = 0, direct_ok_table_not = 0, both = 0;
  // Errors where the table says ok ([0]) and over every answer ([1]).
  double eN[2] = {0, 0}, eP[2] = {0, 0}, eA[2] = {0, 0}, eFy[2] = {0, 0};
  int both_ok = 0;
  std::vector<double> fy_direct(static_cast<std::size_t>(steps), NAN);
  mh::GridWorkspace ws;
  mh::CaseResult r;
  mh::MethodOptions mopt = cf.method_options();
  const double tc = cpu_now();
  for (int k = 0; k < steps; k += every) {
    const auto K = static_cast<std::size_t>(k);
    mopt.multi_hertzian.roll = roll[K];
    mh::solve_contact(pg.geo, cf.material, tY[K], Q, mopt, r, &ws);
    ++n_direct;
    const mhc_table_result& t = res[K];
    const bool dok = r.status == mh::CaseStatus::Ok, tok = t.status == MHC_STATUS_OK;
    direct_ok += dok;
    table_ok += tok;
    direct_ok_table_not += dok && !tok;
    if (mh::is_failure(r.status) || t.status == MHC_STATUS_OUT_OF_RANGE || t.status == MHC_STATUS_NO_CONTACT ||
        t.status == MHC_STATUS_NOT_CONVERGED)
      continue;
    ++both;
    fy_direct[K] = r.Fy;
    double pt = 0, at = 0;
    for (int c = 0; c < std::min(t.n_contacts, MHC_MAX_CONTACTS); ++c) {
      pt = std::max(pt, t.contact[c].p_max_Pa);
      at += t.contact[c].area_m2;
    }
    // N: each direct patch against the table contact nearest in rail y.
    double eNk = 0;
    for (const mh::PatchResult& P : r.patches) {
      double best = INFINITY, Nt = 0;
      for (int c = 0; c < std::min(t.n_contacts, MHC_MAX_CONTACTS); ++c)
        if (std::fabs(t.contact[c].y_rail_m - P.y_r) < best) best = std::fabs(t.contact[c].y_rail_m - P.y_r), Nt = t.contact[c].N_N;
      eNk = std::max(eNk, std::fabs(Nt - P.N) / Q);
    }
    both_ok += tok;
    for (int w = tok ? 0 : 1; w < 2; ++w) {
      eN[w] = std::max(eN[w], eNk);
      eP[w] = std::max(eP[w], std::fabs(pt - r.pmax) / r.pmax);
      eA[w] = std::max(eA[w], std::fabs(at - r.area) / r.area);
      eFy[w] = std::max(eFy[w], std::fabs(t.Fy_N - r.Fy) / Q);
    }
  }
  std::printf("direct %s solves at every %d-th step: %d (%.1f ms each); ok: direct %d, table %d, direct ok and table not %d\n",
              mh::to_string(cf.method), every, n_direct, (cpu_now() - tc) / n_direct * 1e3, direct_ok, table_ok,
              direct_ok_table_not);
  std::printf("table against direct where the table is ok (%d steps): max |dN|/Q %.3g %%, pmax %.3g %%, area %.3g %%, "
              "|dFy|/Q %.3g %%\n",
              both_ok, 100 * eN[0], 100 * eP[0], 100 * eA[0], 100 * eFy[0]);
  std::printf("... at every step both answer (%d): max |dN|/Q %.3g %%, pmax %.3g %%, area %.3g %%, |dFy|/Q %.3g %%\n", both,
              100 * eN[1], 100 * eP[1], 100 * eA[1], 100 * eFy[1]);

  // 4. The force history.
  if (!history.empty()) {
    std::ofstream h(history);
    h << "step,tY_mm";
    for (int k = 1; k <= made.data.n_tracks; ++k) h << ",N" << k << "_kN";
    h << ",Fy_table_kN,dFy_dtY_kN_per_mm,Fy_direct_kN,status_table\n";
    for (int k = 0; k < steps; ++k) {
      const auto K = static_cast<std::size_t>(k);
      const mhc_table_result& t = res[K];
      h << k << ',' << tY[K] * 1e3;
      for (int tr = 1; tr <= made.data.n_tracks; ++tr) {
        double N = 0;
        for (int c = 0; c < std::min(t.n_contacts, MHC_MAX_CONTACTS); ++c)
          if (t.contact[c].track == tr) N = t.contact[c].N_N;
        h << ',' << N * 1e-3;
      }
      h << ',' << t.Fy_N * 1e-3 << ',' << t.dFy_dtY_N_per_m * 1e-6 << ',';
      if (!std::isnan(fy_direct[K])) h << fy_direct[K] * 1e-3;
      h << ',' << mhc_status_name(t.status) << '\n';
    }
  }
  mhc_table_free(table);
  return 0;
}
