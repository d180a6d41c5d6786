#pragma once
// The objects behind the C interface (include/mhcontact.h) and the conversion of one case's
// CaseResult into an mhc_result, shared by the C functions (mhcontact_c.cpp) and the Python
// module (python/mhcontact_module.cpp). Layer capi: above core, profile, geometry, contact and
// input (profiles and case files are read as the command reads them), never output or jobs.
#include <cstddef>
#include <functional>
#include <limits>
#include <mutex>
#include <type_traits>
#include <string>
#include <vector>

#include <mhcontact.h>

#include "contact/case_result.hpp"
#include "contact/multi_hertz/approach_given.hpp"
#include "contact/options.hpp"
#include "contact/solve.hpp"
#include "core/parallel.hpp"
#include "geometry/contact_geometry.hpp"
#include "profile/profile.hpp"

/// A profile as read, or a standard profile's name (generated again with the pair's cant).
struct mhc_profile {
  mh::Profile profile;
  std::string standard;  ///< "S1002", "60E1", "54E1", or empty
};

/// A pair: geometry tables, material, model and method options. Immutable once built.
struct mhc_pair {
  mh::PairGeometry pg;
  mh::Material material;
  mh::MethodOptions options;
  bool plastic = false;  ///< the plastic model (material.p_lim finite: given, or from the yield stress)
  mh::TrackSetup track;  ///< the track and wheelset data it was placed with (the wheelset call reads them)
  mh::GeometryOptions geometry;  ///< the geometry options it was built with (the band's tables: mhc_pair_set_smoothing_band)
  /// The pair's warnings in the command's words, "<profile>: <warning>" (mhc_pair_warning).
  std::vector<std::string> warnings;
};

/// One thread's scratch memory for calls on one pair: the multi-Hertzian approach solver's, the
/// grid methods' (patches, influence operators, solver vectors: made on the first grid call) and
/// the result, filled in place.
struct mhc_workspace {
  const mhc_pair* pair = nullptr;
  mh::ApproachWorkspace approach;
  mh::GridWorkspace grid;
  mh::CaseResult r;
  /// mhc_workspace_keep_grids: solve keeping what mhc_result_grid needs (lib/capi/grids.cpp).
  bool keep_grids = false;
  /// Whether the solve that filled r kept it.
  bool grids_kept = false;
};

namespace mh::capi {

/// The thread's last message (mhc_last_message).
std::string& last_message();
/// Set the thread's message and return e.
mhc_error fail(mhc_error e, const std::string& msg);
/// MHC_OK when p is set, else MHC_ERR_ARGUMENT with "<what>: null pointer".
mhc_error need(const void* p, const char* what);

/// A callable returning mhc_error, passed to guarded() by reference: a std::function would copy a
/// lambda capturing more than two references to the heap, once per C call.
class GuardedBody {
 public:
  template <class F, class = std::enable_if_t<!std::is_same_v<std::decay_t<F>, GuardedBody>>>
  GuardedBody(F&& f)  // NOLINT: implicit, as std::function's
      : obj_(&f), call_([](const void* o) { return (*static_cast<std::remove_reference_t<F>*>(const_cast<void*>(o)))(); }) {}
  mhc_error operator()() const { return call_(obj_); }

 private:
  const void* obj_;
  mhc_error (*call_)(const void*);
};

/// Run f, turning every exception into an error code and the thread's message (the command's
/// wording: InputError::what()). f must outlive the call (a lambda written in the call does).
mhc_error guarded(GuardedBody f) noexcept;

/// Check an mhc_result pointer and its struct_size; false with the message set otherwise.
bool result_ok(const mhc_result* out, std::size_t result_size);
/// Check the struct_size of a caller's mhc_warning (field names the argument as the caller
/// wrote it, e.g. "out->struct_size"); false with the message set otherwise.
bool warning_size_ok(std::size_t size, const char* field);

/// Solve one case: Q prescribed (approach = false) or the approach dz prescribed (approach =
/// true), at tY [m] and roll [rad]. Fills *out; sets the message for a case that is not ok.
/// Does not catch (callers wrap it in guarded()).
mhc_error solve_case(const mhc_pair& pair, mhc_workspace& ws, bool approach, double tY, double roll, double value,
                     mhc_result* out);

/// Convert a case's result. Q: the load prescribed (NaN: the load carried, Fz).
void fill_result(const CaseResult& r, double tY, double Q, bool plastic, mhc_result* out);

/// Convert a case's creep forces (capi/tangential.cpp; out->struct_size kept). mu: the pair's.
void fill_tangential(const CaseResult& r, double mu, mhc_tangential* out);
/// Whether the pair solves the tangential problem (a friction coefficient set).
inline bool pair_has_friction(const mhc_pair& p) { return p.options.tangential.enabled(); }

/// One warning as data into *out (its struct_size kept; the caller checked it).
void fill_warning(const Warning& w, mhc_warning* out);

/// The C int status of a case (mhc_status).
int32_t status_code(CaseStatus s);

/// Run body(i, state) for i in [0, n) on n_threads threads (0: all cores) by the library's one
/// parallel_for (core/parallel.hpp), each thread with its own make_state(); blocks of 256 items.
/// Returns the code of the lowest i whose body failed (the others still run), with its message;
/// an exception propagates (callers run inside guarded()).
template <class MakeState, class Body>
mhc_error for_each_index(std::size_t n, int n_threads, MakeState&& make_state, Body&& body) {
  std::mutex m;
  std::size_t first_i = std::numeric_limits<std::size_t>::max();
  mhc_error first = MHC_OK;
  std::string message;
  parallel_for(n, n_threads > 0 ? static_cast<unsigned>(n_threads) : 0u, 256, make_state, [&](std::size_t i, auto& state) {
    const mhc_error c = body(i, state);
    if (c == MHC_OK) return;
    std::lock_guard<std::mutex> lock(m);
    if (i < first_i) first_i = i, first = c, message = last_message();
  });
  if (first != MHC_OK) return fail(first, message);
  return MHC_OK;
}

/// for_each_index with a workspace on `pair` per thread, inside guarded() (never throws).
mhc_error for_each_case(const mhc_pair& pair, std::size_t n, int n_threads,
                        const std::function<mhc_error(std::size_t, mhc_workspace&)>& body);

}  // namespace mh::capi
