// The FFT backend's shared parts (fft_backend.hpp).
#include "contact/half_space/fft_backend.hpp"

#include "core/mru.hpp"

namespace mh {
namespace fft {

int smooth_size(int m) {
#ifdef MHCONTACT_FFTW
  static const int factors[] = {2, 3, 5, 7};
#else
  static const int factors[] = {2, 3, 5};
#endif
  for (int n = m > 1 ? m : 1;; ++n) {
    int r = n;
    for (int f : factors)
      while (r % f == 0) r /= f;
    if (r == 1) return n;
  }
}

#ifdef MHCONTACT_FFTW
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}
#else
std::shared_ptr<const RealPlan> real_plan(int m) {
  thread_local MruCache<int, std::shared_ptr<const RealPlan>> plans(kPlans);
  return plans.get(m, [m] { return std::make_shared<const RealPlan>(static_cast<std::size_t>(m)); });
}
std::shared_ptr<const ComplexPlan> complex_plan(int m) {
  thread_local MruCache<int, std::shared_ptr<const ComplexPlan>> plans(kPlans);
  return plans.get(m, [m] { return std::make_shared<const ComplexPlan>(static_cast<std::size_t>(m)); });
}
#endif

}  // namespace fft
}  // namespace mh
