// The force of one contact on the wheel in the track frame: shared by the wheelset's answer
// (wheelset_contact.cpp) and its derivatives (wheelset_derivatives.cpp). Internal to the layer.
#pragma once

#include <array>

namespace mh {

/// The force on the wheel, track frame (x and z as the pair's, y = σ y_pair), of a contact's normal
/// force N along n = (0, −sin γ, cos γ) out of the rail (pair's frame: y towards the field side, z
/// up) and creep forces Fx along x and Fs along s = (0, cos γ, sin γ) (tangential_types.hpp:
/// forces on the wheel); sg, cg = sin γ, cos γ. Linear in (N, Fx, Fs): the derivatives' map too.
inline std::array<double, 3> contact_force(int sigma, double sg, double cg, double N, double Fx, double Fs) {
  const double fy_pair = -N * sg + Fs * cg;
  return {Fx, sigma * fy_pair, N * cg + Fs * sg};
}

}  // namespace mh
