// Allocations per call of the grid methods through solve_contact with a reused workspace (issue
// 35): a case solved once more, or at a neighbouring t_Y, allocates nothing once the workspace has
// seen it. An executable of its own: it replaces malloc and its relatives (glibc's, which the C++
// operator new of libstdc++ calls too, as do PocketFFT's and Eigen's allocators) by counting
// wrappers around glibc's __libc_* entries; the Catch2 tests of mhcontact_tests keep the ordinary
// allocator. MHCONTACT_ALLOC_TRACE=1 prints the stack of every counted allocation (addresses;
// `addr2line -fCe <binary>` names them).
#include <catch2/catch.hpp>

#include <execinfo.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "contact/solve.hpp"
#include "profile/standard_profiles.hpp"
#include "wheelset_contact/wheelset_contact.hpp"

#include "unit/contact/manchester_fixture.hpp"

extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void __libc_free(void*);
}

namespace {
std::atomic<long> g_count{0};
thread_local bool t_counting = false;
thread_local bool t_tracing = false;  // this region's allocations are printed (MHCONTACT_ALLOC_TRACE)
thread_local bool t_in_trace = false;

void counted() {
  if (!t_counting) return;
  ++g_count;
  if (t_tracing && !t_in_trace) {
    t_in_trace = true;
    void* frames[24];
    const int n = backtrace(frames, 24);
    const char line[] = "--- allocation\n";
    (void)!write(2, line, sizeof line - 1);
    backtrace_symbols_fd(frames, n, 2);
    t_in_trace = false;
  }
}
}  // namespace

extern "C" {
void* malloc(size_t n) { counted(); return __libc_malloc(n); }
void* calloc(size_t n, size_t m) { counted(); return __libc_calloc(n, m); }
void* realloc(void* p, size_t n) { counted(); return __libc_realloc(p, n); }
void free(void* p) { __libc_free(p); }
void* memalign(size_t a, size_t n) { counted(); return __libc_memalign(a, n); }
void* aligned_alloc(size_t a, size_t n) { counted(); return __libc_memalign(a, n); }
int posix_memalign(void** out, size_t a, size_t n) {
  counted();
  void* p = __libc_memalign(a, n);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
}

namespace {

/// Allocations made by f() on this thread. With MHCONTACT_ALLOC_TRACE=1 the stacks of those of
/// the calls after the first (`traced`) are printed.
template <class F>
long allocations(F&& f, bool traced = true) {
  static const bool trace = std::getenv("MHCONTACT_ALLOC_TRACE") != nullptr;
  g_count = 0;
  t_tracing = trace && traced;
  t_counting = true;
  f();
  t_counting = false;
  t_tracing = false;
  return g_count.load();
}

TEST_CASE("the sanity of the counter: a std::vector allocates once", "[alloc]") {
  const long n = allocations([] {
    std::vector<double> v(100);
    v[3] = 1;
    REQUIRE(v[3] == 1);
  });
  CHECK(n == 1);
}

/// Allocations of the calls on one reused workspace: the first call at tY0, the same case again,
/// a neighbouring t_Y (an MBS step, 0.01 mm), then tY0 and the neighbour once more.
struct Counts {
  long first = 0, again = 0, step = 0, back = 0, step_again = 0;
  mh::CaseResult r, fresh;  // the last call's result; the same case without a workspace
};

Counts count_calls(mh::Method method, double p_lim, double tY0, double Q = 50e3, double d_comb = NAN) {
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  mh::Material mat = mh::testing::steel();
  mat.p_lim = p_lim;
  mh::MethodOptions opt;
  opt.method = method;
  if (std::isfinite(d_comb)) opt.half_space.d_comb = opt.strips.d_comb = d_comb;
  const double tY1 = tY0 + 1e-5;
  mh::GridWorkspace ws;
  Counts c;
  auto call = [&](double tY) { return allocations([&] { mh::solve_contact(G, mat, tY, Q, opt, c.r, &ws); }); };
  c.first = allocations([&] { mh::solve_contact(G, mat, tY0, Q, opt, c.r, &ws); }, false);
  c.again = call(tY0);
  c.step = call(tY1);
  c.back = call(tY0);
  c.step_again = call(tY1);
  c.fresh = mh::solve_contact(G, mat, tY1, Q, opt);
  return c;
}

struct Run {
  const char* name;
  mh::Method method;
  double p_lim;        // [Pa] INFINITY: elastic
  double tY;           // [m]
  double Q = 50e3;     // [N]
  double d_comb = NAN; // [m] NaN: the default (8 mm)
  std::size_t patches = 1;
};

/// The calls of count_calls on `run`: nothing allocated after the first call, except for the
/// neighbouring t_Y's first visit, and the same bytes as a call without the workspace. A row may be
/// outside_validity where `outside_ok` (the capped flange beyond the plastic law's evidence).
void check_reuse(const Run& run, bool outside_ok) {
  const Counts c = count_calls(run.method, run.p_lim, run.tY, run.Q, run.d_comb);
  INFO(run.name << " at t_Y = " << run.tY * 1e3 << " mm: status " << mh::to_string(c.r.status) << " " << c.r.message
                << "; allocations: first call " << c.first << ", again " << c.again << ", t_Y + 0.01 mm "
                << c.step << ", t_Y again " << c.back << ", t_Y + 0.01 mm again " << c.step_again);
  REQUIRE((c.r.status == mh::CaseStatus::Ok || (outside_ok && c.r.status == mh::CaseStatus::OutsideValidity)));
  REQUIRE(c.r.patches.size() == run.patches);
  CHECK(c.first > 0);
  CHECK(c.again == 0);
  CHECK(c.back == 0);
  CHECK(c.step_again == 0);
  // The same bytes as a call without the workspace.
  CHECK(c.r.Fz == c.fresh.Fz);
  CHECK(c.r.pmax == c.fresh.pmax);
  CHECK(c.r.approach == c.fresh.approach);
  CHECK(c.r.area == c.fresh.area);
  CHECK(c.r.iterations == c.fresh.iterations);
}

}  // namespace

// The half-space method on the Manchester pair: one tread patch (t_Y = 0, 50 kN; load control in
// the patch), elastic and capped at 900 MPa (the capped runs solve the elastic pass, then the
// capped one), and tread and gauge corner as two patches (t_Y = 5 mm, 10 kN, d_comb 4 mm as in
// test_half_space.cpp: approach control in each patch, the shared approach balanced). A
// neighbouring t_Y may need patch grids of other sizes, whose influence operators the workspace
// then makes once (it keeps them by size): its first call may allocate, its second may not. Seen
// to fail (the two-patch runs) with the CG work vectors made per approach-control solve again
// (normal_cg.cpp, a local NormalCGWorkspace).
TEST_CASE("half-space through solve_contact with a reused workspace allocates nothing after the first call",
          "[alloc]") {
  const Run runs[] = {{"elastic, one patch", mh::Method::HalfSpace, INFINITY, 0.0},
                      {"capped, one patch", mh::Method::HalfSpace, 900e6, 0.0},
                      {"elastic, two patches", mh::Method::HalfSpace, INFINITY, 5e-3, 10e3, 4e-3, 2},
                      {"capped, two patches", mh::Method::HalfSpace, 700e6, 5e-3, 10e3, 4e-3, 2}};
  for (const Run& run : runs) check_reuse(run, false);
}

// The strip method on the Manchester pair, elastic and capped at 900 MPa: the tread patch at
// t_Y = 0 (load control, the extents refined by the end-gap condition, its Anderson steps) and the
// flange at t_Y = 6 mm (capped: outside the plastic law's evidence, still solved). The strip
// solvers, their collocations, factorisations and results keep their memory in the workspace's
// patches (strip_collocation.hpp, StripScratch; core/dense.hpp). Seen to fail with the patch's
// solver made anew for every patch (StripPatch::solver, about 60 allocations a call), with the
// scaled reflectors of Eigen's Householder sequence in the Anderson step (7 a call), and before
// (about 1,600 a call).
TEST_CASE("strips through solve_contact with a reused workspace allocate nothing after the first call", "[alloc]") {
  const Run runs[] = {{"elastic, tread", mh::Method::Strips, INFINITY, 0.0},
                      {"capped, tread", mh::Method::Strips, 900e6, 0.0},
                      {"elastic, flange", mh::Method::Strips, INFINITY, 6e-3},
                      {"capped, flange", mh::Method::Strips, 900e6, 6e-3}};
  for (const Run& run : runs) check_reuse(run, true);
}

// `auto` with a workspace hands its strip and half-space solves the workspace's memory and keeps
// its own rows there (lib/contact/solve.cpp, GridWorkspace::auto_rows): the rows must be those
// of `auto` without it, and the second pass over the same steps allocates nothing. Manchester
// pair, 50 kN, t_Y 4 … 8 mm (gauge corner and flange: rows handed to the strips among them),
// elastic and capped at 900 MPa. Seen to fail with the rows made new per call (26 and 56
// allocations over the second pass).
TEST_CASE("auto through solve_contact with a reused workspace: the same rows as without, no allocation", "[alloc]") {
  const mh::ContactGeometry& G = mh::testing::manchester_geometry();
  for (const double p_lim : {static_cast<double>(INFINITY), 900e6}) {
    mh::Material mat = mh::testing::steel();
    mat.p_lim = p_lim;
    mh::MethodOptions opt;
    opt.method = mh::Method::Auto;
    mh::GridWorkspace ws;
    mh::CaseResult r;
    int handed = 0;
    long second = 0;
    for (int pass = 0; pass < 2; ++pass)
      for (double tY = 4e-3; tY <= 8.0001e-3; tY += 0.5e-3) {
        const long n = allocations([&] { mh::solve_contact(G, mat, tY, 50e3, opt, r, &ws); }, pass == 1);
        if (pass == 0) {
          const mh::CaseResult fresh = mh::solve_contact(G, mat, tY, 50e3, opt);
          INFO("p_lim " << p_lim << ", t_Y " << tY * 1e3 << " mm: " << mh::to_string(r.method) << " / "
                        << mh::to_string(fresh.method));
          CHECK(r.method == fresh.method);
          CHECK(r.status == fresh.status);
          CHECK(r.Fz == fresh.Fz);
          CHECK(r.pmax == fresh.pmax);
          CHECK(r.area == fresh.area);
          CHECK(r.approach == fresh.approach);
          CHECK(r.warnings.size() == fresh.warnings.size());
          handed += r.method != mh::Method::MultiHertzian;
        } else {
          second += n;
        }
      }
    std::printf("auto, p_lim %g MPa: %d of 9 rows handed on; allocations over the second pass %ld\n", p_lim / 1e6,
                handed, second);
    CHECK(handed > 0);
    CHECK(second == 0);
  }
}

// The figures of docs/c-api.md ("What a call allocates"), printed, not asserted:
// build/tests/mhcontact_alloc_tests "[.report]".
TEST_CASE("allocations per call, the table of docs/c-api.md", "[.report]") {
  const Run runs[] = {{"half-space elastic", mh::Method::HalfSpace, INFINITY, 0.0},
                      {"half-space capped", mh::Method::HalfSpace, 900e6, 0.0},
                      {"half-space elastic", mh::Method::HalfSpace, INFINITY, 6e-3},
                      {"half-space capped", mh::Method::HalfSpace, 900e6, 6e-3},
                      {"half-space elastic 2", mh::Method::HalfSpace, INFINITY, 5e-3, 10e3, 4e-3, 2},
                      {"half-space capped 2", mh::Method::HalfSpace, 700e6, 5e-3, 10e3, 4e-3, 2},
                      {"strips elastic", mh::Method::Strips, INFINITY, 0.0},
                      {"strips capped", mh::Method::Strips, 900e6, 0.0},
                      {"strips elastic", mh::Method::Strips, INFINITY, 6e-3},
                      {"strips capped", mh::Method::Strips, 900e6, 6e-3}};
  std::printf("method               tY_mm  Q_kN  patches  status            first  again  tY+0.01mm  tY_again  tY+0.01mm_again\n");
  for (const Run& run : runs) {
    const Counts c = count_calls(run.method, run.p_lim, run.tY, run.Q, run.d_comb);
    std::printf("%-20s %5.1f %5.0f  %zu  pmax %6.1f  %-16s %6ld %6ld %10ld %9ld %16ld\n", run.name, run.tY * 1e3, run.Q / 1e3,
                c.r.patches.size(), c.r.pmax / 1e6, mh::to_string(c.r.status), c.first, c.again, c.step, c.back, c.step_again);
  }
}

#ifdef MHCONTACT_ALLOC_CAPI
#include <mhcontact.h>

// The same through the C interface an MBS calls (include/mhcontact.h): mhc_solve_load on a
// reused mhc_workspace, half-space pair (cases/manchester-halfspace.json), at t_Y = 0, again, a
// neighbouring t_Y and both again. Seen to fail (1 allocation per call) with guarded() taking
// its body as a const std::function& again, as it did before (lib/capi/handles.hpp).
TEST_CASE("the C interface's workspace: mhc_solve_load on a half-space pair allocates nothing after the first call",
          "[alloc]") {
  mhc_pair* pair = nullptr;
  REQUIRE(mhc_pair_from_case_file(MHCONTACT_SOURCE_DIR "/cases/manchester-halfspace.json", &pair) == MHC_OK);
  mhc_workspace* ws = nullptr;
  REQUIRE(mhc_workspace_create(pair, &ws) == MHC_OK);
  mhc_result r{};
  r.struct_size = sizeof r;
  mhc_error e = MHC_OK;
  auto call = [&](double tY) { return allocations([&] { e = mhc_solve_load(pair, ws, tY, 0.0, 50e3, &r); }); };
  const long first = allocations([&] { e = mhc_solve_load(pair, ws, 0.0, 0.0, 50e3, &r); }, false);
  const long again = call(0.0), step = call(1e-5), back = call(0.0), step_again = call(1e-5);
  INFO("allocations: first call " << first << ", again " << again << ", t_Y + 0.01 mm " << step << ", t_Y again "
                                  << back << ", t_Y + 0.01 mm again " << step_again);
  CHECK(e == MHC_OK);
  CHECK(r.status == 0);
  CHECK(first > 0);
  CHECK(again == 0);
  CHECK(back == 0);
  CHECK(step_again == 0);
  mhc_workspace_free(ws);
  mhc_pair_free(pair);
}
#endif

// A row that is not ok (here outside_validity: the capped flange case beyond the plastic law's
// evidence, docs/status.md) allocates nothing either once its result has grown: the judge lists
// the failing classes its message names on the stack (decide_status) and the message reuses the
// result's string. Seen to fail (one allocation per call) with validity_failures()'s vector in
// decide_status, as before.
TEST_CASE("half-space: a row that is not ok allocates nothing once its message has grown", "[alloc]") {
  const Counts c = count_calls(mh::Method::HalfSpace, 900e6, 6e-3);
  INFO("status " << mh::to_string(c.r.status) << "; allocations: first call " << c.first << ", again " << c.again
                 << ", t_Y + 0.01 mm " << c.step << ", t_Y again " << c.back << ", t_Y + 0.01 mm again "
                 << c.step_again);
  REQUIRE(c.r.status == mh::CaseStatus::OutsideValidity);
  CHECK(c.back == 0);
  CHECK(c.step_again == 0);
}

// The wheelset call (wheelset_contact/wheelset_contact.hpp): both wheels, multi-Hertzian normal
// contact and FASTSIM, loads given, with and without derivatives, over a lateral and yaw motion:
// the second pass over the same steps allocates nothing (the result's vectors, the warnings and
// the status messages keep their capacity). Seen to fail with WheelResult::contacts assigned a
// fresh vector at every step (solve_wheel), and before the judge's and the gap's changes (the
// failing classes' list of decide_status; the node tables of gap.cpp remade for each wheel).
TEST_CASE("the wheelset call allocates nothing once its workspace and result have seen the steps", "[alloc]") {
  mh::WheelsetSetup s;
  s.wheel_left = s.wheel_right = mh::make_standard_profile("S1002", mh::Inclination::None);
  s.rail_left = s.rail_right = mh::make_standard_profile("60E1", mh::Inclination::In40);
  s.method.tangential.mu = 0.3;
  const mh::WheelsetContact W(s);
  mh::WheelsetWorkspace ws;
  mh::WheelsetResult r;
  for (bool derivatives : {false, true}) {
    mh::WheelsetStepOptions o;
    o.derivatives = derivatives;
    auto pass = [&] {
      for (int i = 0; i <= 200; ++i) {
        mh::WheelsetPose p;
        p.y = 7e-3 * std::sin(0.0314159 * i);
        p.yaw = 2e-3 * std::cos(0.0314159 * i);
        p.Q_left = p.Q_right = 50e3;
        p.V = 30;
        W.step(p, o, r, ws);
      }
    };
    allocations(pass, false);
    INFO("derivatives " << derivatives);
    CHECK(allocations(pass) == 0);
  }
}

// The wheelset call by every method it offers, each wheel rolled against its rail in the geometry
// (the default), without and with friction (μ = 0.3), elastic and capped (900 MPa): the second
// pass over the same steps allocates nothing: the patch results' vectors come back to the workspace (GridCaseWorkspace::take_patch),
// the exact tangential solver of each patch is set up again in its own buffers, its row FFT's
// plans taken from the thread's plans by length (TangentialPatchWorkspace,
// HalfSpaceTangentialSolver::reset, RowFft::reset), the rolled wheel curves are kept per thread
// and rebuilt in place (gap.cpp, rolled_curve), and the half-space influence operators, of more
// grid sizes than the workspace keeps (the equilibrium with friction solves each wheel at other
// loads), are rebuilt in their own buffers (InfluenceGrid::reset, half_space_method.cpp). Each
// step's forces are those of a fresh workspace, bit for bit. Seen to fail without take_patch
// (strips about 14 allocations a step, their strip lists; half-space 2, the pressure grids), with
// a tangential solver made per patch and solve (about 250 a step with friction), with a rolled
// curve made per gap (about 50 a step), with a new operator in place of an evicted one
// (half-space with friction: 399 over the second pass), and at 74ec3be capped (half-space 160,
// strips 91) and by `auto` (138–268).
TEST_CASE("the wheelset call by any method allocates nothing once it has seen the steps", "[alloc]") {
  struct Run {
    mh::Method m;
    double mu, p_lim;
  };
  const Run runs[] = {{mh::Method::Strips, 0.0, INFINITY},    {mh::Method::Strips, 0.3, INFINITY},
                      {mh::Method::HalfSpace, 0.0, INFINITY}, {mh::Method::HalfSpace, 0.3, INFINITY},
                      {mh::Method::Strips, 0.3, 900e6},       {mh::Method::HalfSpace, 0.3, 900e6},
                      {mh::Method::Auto, 0.0, INFINITY},      {mh::Method::Auto, 0.3, INFINITY},
                      {mh::Method::Auto, 0.3, 900e6},         {mh::Method::MultiHertzian, 0.3, 900e6}};
  for (const auto& [m, mu, p_lim] : runs) {
    {
      mh::WheelsetSetup s;
      s.wheel_left = s.wheel_right = mh::make_standard_profile("S1002", mh::Inclination::None);
      s.rail_left = s.rail_right = mh::make_standard_profile("60E1", mh::Inclination::In40);
      s.method.tangential.mu = mu;
      s.method.method = m;
      s.material.p_lim = p_lim;
      const mh::WheelsetContact W(s);
      mh::WheelsetWorkspace ws;
      mh::WheelsetResult r;
      const mh::WheelsetStepOptions o;
      auto pose = [](int i) {
        mh::WheelsetPose p;
        p.y = 7e-3 * std::sin(1.256637 * i);
        p.yaw = 2e-3 * std::cos(1.256637 * i);
        p.Q_left = p.Q_right = 50e3;
        p.V = 30;
        return p;
      };
      std::vector<mh::Wrench> reused;
      auto pass = [&] {
        reused.clear();
        for (int i = 0; i <= 4; ++i) {
          W.step(pose(i), o, r, ws);
          reused.push_back(r.total);  // capacity reserved below: no allocation
        }
      };
      reused.reserve(5);
      const long first = allocations(pass, false);
      const long second = allocations(pass);
      std::printf("wheelset by %s, mu %g, p_lim %g MPa, 5 steps: allocations first pass %ld, second pass %ld\n",
                  mh::to_string(m), mu, p_lim / 1e6, first, second);
      INFO(mh::to_string(m) << ", mu " << mu << ", p_lim " << p_lim << ": first pass " << first << ", second " << second);
      CHECK(first > 0);
      CHECK(second == 0);
      for (int i = 0; i <= 4; ++i) {  // the same bits as a fresh workspace
        mh::WheelsetWorkspace fresh;
        mh::WheelsetResult f;
        W.step(pose(i), o, f, fresh);
        INFO("step " << i);
        for (int k = 0; k < 3; ++k) {
          CHECK(f.total.F[k] == reused[i].F[k]);
          CHECK(f.total.M[k] == reused[i].M[k]);
        }
      }
    }
  }
}
