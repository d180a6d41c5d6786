#pragma once
// The FFT library under the half-space convolutions (influence.cpp, row_fft.cpp): PocketFFT by
// default, FFTW 3 when the build sets MHCONTACT_FFTW (docs/embedding.md "FFT backends"; sources
// [P] and [LI] in influence.hpp). Internal to those files: only they see the backend
// (CMakeLists.txt gives them its define or PocketFFT's directory), and each includes this header
// before any other use of the backend, so that all of them see the same declarations below.
#include <cstddef>
#include <memory>
#include <new>
#include <vector>

#ifdef MHCONTACT_FFTW
#include <fftw3.h>

#include <mutex>
#include <type_traits>
#else
// PocketFFT's own thread pool stays out: the transforms run on the project's worker threads
// (lib/jobs), one transform per call.
#define POCKETFFT_NO_MULTITHREADING
// The header's arr<T> takes C11 aligned_alloc(64, n) under glibc without rounding n up to a
// multiple of 64, which C11 requires (AddressSanitizer rejects every plan); this macro, tested by
// the header alone, selects its portable aligned allocator (malloc + 64, aligned by hand) instead.
#define _LIBCPP_HAS_NO_ALIGNED_ALLOCATION
#include <pocketfft_hdronly.h>
#endif

namespace mh {
namespace fft {

/// Smallest n ≥ m whose only prime factors have fast butterflies in the backend: 2, 3, 5, 7 for
/// FFTW (FFTW 3 manual §2.1, "sizes of the form 2^a 3^b 5^c 7^d"); 2, 3, 5 for PocketFFT, whose
/// real transforms (rfftp) have butterflies for 2, 3, 4 and 5 only, 7 going through the generic
/// O(p²) one (radfg/radbg), the same sizes as util::good_size_real ([P]).
int smooth_size(int m);

/// Offset (in elements) represented by index i of a cyclic axis of m points carrying the offsets
/// −(n−1)…(n−1); false for the unused indices between them (DC-FFT wrap-around, [LI]). Inline:
/// the kernel's set-up calls it per padded point.
inline bool wrapped_offset(int i, int n, int m, int* offset) {
  if (i < n) {
    *offset = i;
    return true;
  }
  if (i >= m - n + 1) {
    *offset = i - m;
    return true;
  }
  return false;
}

#ifdef MHCONTACT_FFTW
/// FFTW planning (fftw_plan_* and fftw_destroy_plan) is not thread-safe, execution of an existing
/// plan is (FFTW 3 manual §5.4 "Thread safety"): every plan is made and destroyed under this mutex.
std::mutex& planner_mutex();
struct FftwFree {
  void operator()(void* ptr) const { fftw_free(ptr); }
};
struct PlanDestroy {
  void operator()(fftw_plan plan) const {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
};
using Plan = std::unique_ptr<std::remove_pointer_t<fftw_plan>, PlanDestroy>;
#else
using RealPlan = pocketfft::detail::pocketfft_r<double>;     ///< real transforms of one length
using ComplexPlan = pocketfft::detail::pocketfft_c<double>;  ///< complex transforms of one length

/// The plans of length m (factors and twiddles), made once per thread and length and kept for
/// the last kPlans lengths of each kind (a plan is read-only once made: exec() is const, its
/// scratch per call; one held by an operator stays valid after it leaves the cache and may be
/// used from any thread). A length met before allocates nothing; the same bits as a new plan.
constexpr std::size_t kPlans = 32;
std::shared_ptr<const RealPlan> real_plan(int m);
std::shared_ptr<const ComplexPlan> complex_plan(int m);
#endif

}  // namespace fft
}  // namespace mh

#ifndef MHCONTACT_FFTW
namespace mh_pocketfft {
namespace pf = pocketfft::detail;
/// PocketFFT's SIMD vector of doubles (2 lanes with SSE2, 4 with AVX, 1 without vectors): its
/// 1-D plans transform L independent sequences at once when given arrays of these ([P]).
#ifndef POCKETFFT_NO_VECTORS
using Vd = pf::vtype_t<double>;
#else
using Vd = double;
#endif
constexpr int L = static_cast<int>(sizeof(Vd) / sizeof(double));

/// Per-thread scratch for PocketFFT's 1-D calls: each rfftp/cfftp::exec makes an arr<T> of one
/// sequence (T = Vd or cmplx<Vd> here), which would be an aligned heap allocation per call.
/// The arr<> specialisations below take the buffers from this stack instead (last in, first
/// out, so nested calls each get their own) and keep them for the thread's next call: after the
/// first transform of its longest length, a thread allocates nothing in the FFT. This relies on
/// the header's exec() taking its scratch as an arr<T> (pocketfft_hdronly.h of Debian 12's
/// gemmi-dev, and PocketFFT's C++ releases since 2019); were that to change, only the
/// allocations return.
class ScratchStack {
 public:
  static ScratchStack& local() {
    static thread_local ScratchStack s;
    return s;
  }
  void* take(std::size_t bytes) {
    if (top_ == bufs_.size()) bufs_.emplace_back();
    Buffer& b = bufs_[top_++];
    if (b.bytes < bytes) {
      b.mem.reset(static_cast<char*>(::operator new(bytes, std::align_val_t{64})));
      b.bytes = bytes;
    }
    return b.mem.get();
  }
  void give_back() { --top_; }

 private:
  struct Free {
    void operator()(char* p) const { ::operator delete(p, std::align_val_t{64}); }
  };
  struct Buffer {
    std::unique_ptr<char, Free> mem;
    std::size_t bytes = 0;
  };
  std::vector<Buffer> bufs_;
  std::size_t top_ = 0;
};

/// The interface of pocketfft::detail::arr<T> as exec() uses it, on ScratchStack.
template <typename T>
class ScratchArr {
 public:
  ScratchArr() = default;
  explicit ScratchArr(std::size_t n) : sz_(n) {
    if (n > 0) p_ = static_cast<T*>(ScratchStack::local().take(n * sizeof(T)));
  }
  ScratchArr(const ScratchArr&) = delete;
  ScratchArr& operator=(const ScratchArr&) = delete;
  ~ScratchArr() {
    if (p_) ScratchStack::local().give_back();
  }
  T& operator[](std::size_t i) { return p_[i]; }
  const T& operator[](std::size_t i) const { return p_[i]; }
  T* data() { return p_; }
  const T* data() const { return p_; }
  std::size_t size() const { return sz_; }

 private:
  T* p_ = nullptr;
  std::size_t sz_ = 0;
};
}  // namespace mh_pocketfft

#ifndef POCKETFFT_NO_VECTORS  // (without vectors Vd is double, whose arr also holds the twiddles)
template <>
class pocketfft::detail::arr<mh_pocketfft::Vd> : public mh_pocketfft::ScratchArr<mh_pocketfft::Vd> {
 public:
  using ScratchArr::ScratchArr;
};
template <>
class pocketfft::detail::arr<pocketfft::detail::cmplx<mh_pocketfft::Vd>>
    : public mh_pocketfft::ScratchArr<pocketfft::detail::cmplx<mh_pocketfft::Vd>> {
 public:
  using ScratchArr::ScratchArr;
};
#endif
#endif
