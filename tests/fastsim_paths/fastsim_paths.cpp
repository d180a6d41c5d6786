// FASTSIM's march has two paths (lib/contact/tangential/fastsim.cpp): SSE2 registers, two strips
// to a register, on x86-64, and plain C++ elsewhere (an ARM host, or any build defining
// MHC_FASTSIM_SCALAR). Both claim the same bits: IEEE operations lane by lane, in the same order.
// This program prints FASTSIM's results in hexadecimal over inputs that visit every branch
// (adhesion, partial and full slip, pure spin, no creep; ny a multiple of the 8 lanes and not;
// the load slope; the blended flexibilities; the traction grid). CMake links it twice, once with
// each path (tests/CMakeLists.txt), and the test fastsim.paths (compare.sh) compares the two
// outputs byte for byte.
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "contact/tangential/fastsim.hpp"

namespace {

// A deterministic generator (the same inputs on every host), uniform in [0, 1).
struct Lcg {
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0);
  }
};

// The bits of a double, so that -0 and NaN payloads count too.
std::uint64_t bits(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

}  // namespace

int main() {
  Lcg rng;
  mh::FastsimGrid grid;
  const int sizes[][2] = {{16, 16}, {32, 32}, {7, 13}, {24, 9}, {5, 1}};
  int cases = 0;
  for (const auto& nxy : sizes)
    for (int k = 0; k < 40; ++k) {
      const double a = 2e-3 + 6e-3 * rng.next(), b = 2e-3 + 6e-3 * rng.next();
      const double N = 5e3 + 120e3 * rng.next(), mu = 0.1 + 0.5 * rng.next();
      // Creepages from none to full slip, signs mixed; every fifth pure spin, every seventh none.
      mh::Creepages cr;
      const double scale = std::pow(10.0, -5 + 3.5 * rng.next());
      cr.xi = scale * (2 * rng.next() - 1);
      cr.eta = scale * (2 * rng.next() - 1);
      cr.phi = (scale / 5e-3) * (2 * rng.next() - 1);
      if (k % 5 == 0) cr.xi = cr.eta = 0;
      if (k % 7 == 0) cr = mh::Creepages{};
      mh::FastsimOptions o;
      o.nx = nxy[0];
      o.ny = nxy[1];
      o.load_slope = k % 2 == 1;
      o.blend = k % 3 == 2;
      const bool with_grid = k % 4 == 3;
      const mh::TangentialResult r = mh::fastsim(cr, a, b, N, mu, 81e9, 0.28, o, with_grid ? &grid : nullptr);
      std::printf("%d %d %d: %a %a %a %a %a %a %a %a %d %d\n", o.nx, o.ny, k, r.Fx, r.Fy, r.Mz, r.adhesion_fraction,
                  r.Tgamma, r.Tgamma_spin, r.dFx_dN, r.dFy_dN, r.iterations, r.solved ? 1 : 0);
      if (with_grid) {
        std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the grid's tractions and slip flags
        auto mix = [&h](std::uint64_t v) {
          for (int i = 0; i < 8; ++i) h = (h ^ ((v >> (8 * i)) & 0xff)) * 1099511628211ull;
        };
        for (std::size_t i = 0; i < grid.px.size(); ++i) {
          mix(bits(grid.px[i]));
          mix(bits(grid.py[i]));
          mix(bits(grid.pn[i]));
          mix(grid.slip[i]);
        }
        std::printf("  grid %zu cells %016" PRIx64 "\n", grid.px.size(), h);
      }
      ++cases;
    }
  std::printf("%d cases\n", cases);
  return 0;
}
