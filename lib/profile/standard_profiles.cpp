// Standard profiles from their definitions (profiles.md; header standard_profiles.hpp).
//
// The definitions are written in millimetres, as published; the sections below hold and evaluate
// them in mm, and only the public functions convert to and from metres (units.hpp).
#include "profile/standard_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/numfmt.hpp"
#include "core/units.hpp"

namespace mh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Limits of the node spacing `step` [m] (make_standard_profile): below 1 µm the files get huge
/// (S1002: 2e5 points) for nothing; above 5 mm the R13 gauge corner gets fewer than 3 nodes.
constexpr double kMinStep = 1e-6;
constexpr double kMaxStep = 5e-3;
/// Number of intervals of the arc-length table of a polynomial section (S1002 B, C): the nodes'
/// y come from it by linear interpolation, so their spacing along the curve is equal to about
/// 1e-7 relative.
constexpr int kArcLengthIntervals = 4096;
/// Nodes per section: ceil(length / step × (1 + kNodeSafety)), so that the spacing stays below
/// `step` despite the interpolation above.
constexpr double kNodeSafety = 1e-6;
/// A rail flank whose angle to the horizontal after inclination reaches 90° − this [rad] is not a
/// function z(y) and is left out (only the gauge flank at 1:20, which becomes exactly vertical).
constexpr double kVerticalFlankMargin = 1e-6;

/// One section of a definition, on y0 ≤ y ≤ y1 [mm], in the canonical frame (z up) [mm].
struct Section {
  enum class Type { Poly, Arc, Line };
  Type type = Type::Line;
  char label = '?';        ///< S1002 section letter (A–H); rails: '1','2','3' arcs, 'f' flank
  double y0 = 0, y1 = 0;   ///< [mm]
  std::vector<double> c;   ///< Poly: z = Σ c[i] y^i
  double yc = 0, zc = 0, R = 0;  ///< Arc: z = zc + sgn √(R² − (y − yc)²)
  int sgn = +1;
  double ya = 0, za = 0, k = 0;  ///< Line: z = za + k (y − ya)
  /// The same curve as the previous section, split only to make a landmark a node (S1002 flange
  /// tip S = −55, taping line S = 0, rail crown top y = 0): its start is not a breakpoint.
  bool split = false;

  /// z [mm], dz/dy and d²z/dy² [1/mm] at y [mm].
  double eval(double y, double* dz = nullptr, double* d2z = nullptr) const {
    switch (type) {
      case Type::Poly: {
        double v = 0, d1 = 0, d2 = 0;  // Horner for the value and both derivatives
        for (std::size_t i = c.size(); i-- > 0;) {
          d2 = d2 * y + 2 * d1;
          d1 = d1 * y + v;
          v = v * y + c[i];
        }
        if (dz) *dz = d1;
        if (d2z) *d2z = d2;
        return v;
      }
      case Type::Arc: {
        const double u = y - yc;
        const double q = std::sqrt(std::max(0.0, R * R - u * u));  // 0 at a vertical tangent (S1002 at S = −70)
        if (dz) *dz = q > 0 ? -sgn * u / q : (u > 0 ? -sgn : sgn) * kInf;
        if (d2z) *d2z = q > 0 ? -sgn * R * R / (q * q * q) : -sgn * kInf;
        return zc + sgn * q;
      }
      case Type::Line:
        if (dz) *dz = k;
        if (d2z) *d2z = 0;
        return za + k * (y - ya);
    }
    return 0;
  }

  /// Length along the section [mm].
  double length() const {
    switch (type) {
      case Type::Line: return (y1 - y0) * std::sqrt(1 + k * k);
      case Type::Arc: return R * std::abs(std::acos(clamp_u(y1)) - std::acos(clamp_u(y0)));
      case Type::Poly: return arc_length_table().back();
    }
    return 0;
  }

  /// Nodes of the section, its start included, its end excluded, no farther apart than step_mm
  /// along the profile: equal lengths along the curve (arcs: equal angles; lines: equal y steps;
  /// polynomials: y from the arc-length table, linearly interpolated).
  void append_nodes(double step_mm, std::vector<double>& ys, std::vector<double>& zs) const {
    const int n = std::max(1, static_cast<int>(std::ceil(length() / step_mm * (1 + kNodeSafety))));
    if (type == Type::Arc) {
      const double p0 = std::acos(clamp_u(y0)), p1 = std::acos(clamp_u(y1));
      ys.push_back(y0);
      zs.push_back(eval(y0));
      for (int i = 1; i < n; ++i) {
        const double p = p0 + (p1 - p0) * i / n;
        ys.push_back(yc + R * std::cos(p));
        zs.push_back(zc + sgn * R * std::sin(p));  // accurate near a vertical tangent too
      }
    } else if (type == Type::Line) {
      for (int i = 0; i < n; ++i) {
        const double y = y0 + (y1 - y0) * i / n;
        ys.push_back(y);
        zs.push_back(eval(y));
      }
    } else {
      const std::vector<double> s = arc_length_table();
      const double h = (y1 - y0) / kArcLengthIntervals;
      ys.push_back(y0);
      zs.push_back(eval(y0));
      std::size_t j = 0;
      for (int i = 1; i < n; ++i) {
        const double target = s.back() * i / n;
        while (j + 1 < s.size() - 1 && s[j + 1] < target) ++j;
        const double y = y0 + h * (static_cast<double>(j) + (target - s[j]) / (s[j + 1] - s[j]));
        ys.push_back(y);
        zs.push_back(eval(y));
      }
    }
  }

  /// Radius [mm] with the paper's sign (method.md §1) for a wheel (material above: R = 1/kappa)
  /// or a rail (material below: R = −1/kappa); kappa = z''/(1 + z'²)^(3/2) (profile/curve.hpp).
  double radius(double y, bool wheel) const {
    if (type == Type::Line) return kInf;
    if (type == Type::Arc) return wheel ? -sgn * R : sgn * R;  // kappa = −sgn/R exactly
    double d1 = 0, d2 = 0;
    eval(y, &d1, &d2);
    if (d2 == 0) return kInf;
    const double kappa = d2 / std::pow(1 + d1 * d1, 1.5);
    return wheel ? 1 / kappa : -1 / kappa;
  }

 private:
  double clamp_u(double y) const { return std::clamp((y - yc) / R, -1.0, 1.0); }
  /// Polynomials: length along the curve [mm] from y0 to y0 + k (y1 − y0)/N, k = 0 … N
  /// (N = kArcLengthIntervals; Simpson's rule on √(1 + z'²) in each interval).
  std::vector<double> arc_length_table() const {
    const int N = kArcLengthIntervals;
    const double h = (y1 - y0) / N;
    auto ds = [this](double y) {
      double d = 0;
      eval(y, &d);
      return std::sqrt(1 + d * d);
    };
    std::vector<double> s(N + 1, 0.0);
    for (int k = 0; k < N; ++k) {
      const double a = y0 + h * k;
      s[k + 1] = s[k] + h / 6 * (ds(a) + 4 * ds(a + h / 2) + ds(a + h));
    }
    return s;
  }
};

struct Definition {
  std::string name;
  ProfileKind kind = ProfileKind::Unknown;
  std::vector<Section> sections;  ///< ascending in y, contiguous
  double gauge_flank_end = -kInf; ///< rails: y [mm] where the gauge flank meets the last arc (−yt)
  double flank_n = 0;             ///< rails: flank 1 : n to the vertical (0: no flank)
  /// Defined already canted (EN 15302 rail A): no further inclination may be applied.
  bool canted = false;
};

Section poly(char label, double y0, double y1, std::vector<double> c) {
  Section s;
  s.type = Section::Type::Poly;
  s.label = label;
  s.y0 = y0, s.y1 = y1, s.c = std::move(c);
  return s;
}
Section arc(char label, double y0, double y1, double yc, double zc, double R, int sgn) {
  Section s;
  s.type = Section::Type::Arc;
  s.label = label;
  s.y0 = y0, s.y1 = y1, s.yc = yc, s.zc = zc, s.R = R, s.sgn = sgn;
  return s;
}
Section line(char label, double y0, double y1, double ya, double za, double k) {
  Section s;
  s.type = Section::Type::Line;
  s.label = label;
  s.y0 = y0, s.y1 = y1, s.ya = ya, s.za = za, s.k = k;
  return s;
}

/// S1002, EN 13715 (profiles.md table): F(S) [mm], S [mm]; canonical y = S, z = −F(S).
Definition s1002() {
  Definition d;
  d.name = "S1002";
  d.kind = ProfileKind::Wheel;
  // Breakpoints of the table.
  const double sAB = 32.15796, sBC = -26, sCD = -35, sDE = -38.426669071, sEF = -39.764473993,
               sFG = -49.662510381, sGH = -62.764705882;
  // H: F = AH + √(BH² − (S + CH)²)  → z = −AH − √(…): centre (−CH, −AH), lower branch.
  d.sections.push_back(arc('H', -70, sGH, -49.5, -9.519259302, 20.5, -1));
  // G: AG = 16, BG = 12, CG = 55; split at the flange tip F(−55) = 28 to make it a node.
  d.sections.push_back(arc('G', sGH, -55, -55, -16, 12, -1));
  d.sections.push_back(arc('G', -55, sFG, -55, -16, 12, -1));
  d.sections.back().split = true;
  // F: AF = 8.834924130, BF = 20, CF = 58.558326413.
  d.sections.push_back(arc('F', sFG, sEF, -58.558326413, -8.834924130, 20, -1));
  // E: F = −AE − BE·S → z = AE + BE·S.
  d.sections.push_back(line('E', sEF, sDE, 0, 93.576667419, 2.747477419));
  // D: F = AD − √(BD² − (S + CD)²) → z = −AD + √(…): centre (−CD, −AD), upper branch (throat).
  d.sections.push_back(arc('D', sDE, sCD, -26.210665, -16.446, 13, +1));
  // C: F = −AC − BC·S − … − HC·S⁷ → z = AC + BC·S + … + HC·S⁷.
  d.sections.push_back(poly('C', sCD, sBC,
                            {4.320221063e+03, 1.038384026e+03, 1.065501873e+02, 6.051367875,
                             2.054332446e-01, 4.169739389e-03, 4.687195829e-05, 2.252755540e-07}));
  // B: F = AB − BB·S + CB·S² − DB·S³ + EB·S⁴ − FB·S⁵ + GB·S⁶ − HB·S⁷ + IB·S⁸ → z = −F.
  //    Split at the taping line S = 0 to make it a node.
  const std::vector<double> cB = {0.0, 3.358537058e-02, -1.565681624e-03, 2.810427944e-05,
                                  -5.844240864e-08, 1.562379023e-08, -5.309217349e-15,
                                  5.957839843e-12, -2.646656573e-13};
  d.sections.push_back(poly('B', sBC, 0, cB));
  d.sections.push_back(poly('B', 0, sAB, cB));
  d.sections.back().split = true;
  // A: F = AA − BA·S → z = −AA + BA·S.
  d.sections.push_back(line('A', sAB, 60, 0, -1.364323640, 0.066666667));
  return d;
}

RailHeadDefinition rail_definition_mm(const std::string& name) {
  // EN 13674-1 heads (profiles.md "Rail 60E1"; rails-en13674.md for 60E2 and 49E1: the
  // EN 13674-1:2017 profiles as transcribed in rohrbecka/EN13674, P60E2.swift, P49E1.swift).
  // Junctions are given as |y| = w/2 of the published junction widths w.
  // The head's lower corner (rails-en13674.md): flank, fillet R3 and the under-head line 1:2.75
  // through (0, −51) (54E1: −49.4); 49E1: R2 and 1:3 through (0, −51.5).
  RailHeadDefinition d;
  d.flank_n = 20, d.depth = 20, d.fillet_R = 3, d.underhead_n = 2.75, d.underhead_z0 = -51;
  if (name == "60E1") d.R = {300, 80, 13}, d.y_junction = {10.228, 26.0265};
  else if (name == "54E1") d.R = {300, 80, 13}, d.y_junction = {10.012, 24.8635}, d.underhead_z0 = -49.4;
  else if (name == "60E2") d.R = {200, 70, 16, 8}, d.y_junction = {23.778 / 2, 48.913 / 2, 70.774 / 2};
  else if (name == "49E1") {
    d.R = {300, 80, 13}, d.y_junction = {15.267 / 2, 46.835 / 2};
    d.flank_n = 17.2, d.fillet_R = 2, d.underhead_n = 3, d.underhead_z0 = -51.5;
  } else {
    throw std::logic_error("rail_definition_mm: " + name);
  }
  return d;
}

/// The construction is homogeneous in length: the same code serves metres and millimetres.
/// Arc 0 is centred on (0, −R0) through the crown top; at each junction the next centre lies on
/// the current radius through the junction, R_k − R_{k+1} from the current centre (internal
/// tangency); the last arc ends where its tangent is the flank, 1 : flank_n to the vertical.
/// (The operations are those of the former three-arc construction, in the same order, so the
/// 60E1 and 54E1 nodes are bit for bit what they were.)
RailHeadConstruction construct(const RailHeadDefinition& d) {
  if (d.R.empty() || d.y_junction.size() + 1 != d.R.size())
    throw std::logic_error("construct_rail_head: need one junction fewer than radii");
  RailHeadConstruction c;
  RailArc a;
  a.R = d.R[0], a.yc = 0, a.zc = -d.R[0], a.y0 = 0, a.z0 = 0;
  for (std::size_t k = 0; k + 1 < d.R.size(); ++k) {
    const double u = d.y_junction[k] - a.yc;
    a.y1 = d.y_junction[k];
    a.z1 = a.zc + std::sqrt(a.R * a.R - u * u);
    c.arcs.push_back(a);
    RailArc b;
    b.R = d.R[k + 1];
    b.yc = a.yc + (a.R - b.R) * u / a.R;
    b.zc = a.zc + (a.R - b.R) * (a.z1 - a.zc) / a.R;
    b.y0 = a.y1, b.z0 = a.z1;
    a = b;
  }
  // The flank (direction (1, −n) on the field side) touches the last arc where its outward
  // normal is (n, 1)/√(1 + n²).
  const double h = std::sqrt(1 + d.flank_n * d.flank_n);
  a.y1 = a.yc + a.R * d.flank_n / h;
  a.z1 = a.zc + a.R / h;
  c.arcs.push_back(a);
  c.yt = a.y1, c.zt = a.z1;
  c.z_end = -d.depth;
  c.y_end = c.yt + (c.zt - c.z_end) / d.flank_n;
  // The fillet's centre lies R_f inside both the flank and the under-head line: with the outward
  // unit normals n1 = (n, 1)/h of the flank (through the tangency point) and
  // n2 = (1, −m)/√(1 + m²) of the under-head line (through (0, z0)), n_i · centre = n_i · P_i − R_f.
  const double m = d.underhead_n, g = std::sqrt(1 + m * m), Rf = d.fillet_R;
  const double a11 = d.flank_n / h, a12 = 1 / h, b1 = a11 * c.yt + a12 * c.zt - Rf;
  const double a21 = 1 / g, a22 = -m / g, b2 = a22 * d.underhead_z0 - Rf;
  const double det = a11 * a22 - a12 * a21;
  RailArc& f = c.fillet;
  f.R = Rf;
  f.yc = (b1 * a22 - a12 * b2) / det;
  f.zc = (a11 * b2 - b1 * a21) / det;
  f.y0 = f.yc + Rf * a11, f.z0 = f.zc + Rf * a12;  // on the flank
  f.y1 = f.yc + Rf, f.z1 = f.zc;                   // the vertical tangent
  c.y_under = f.yc + Rf * a21, c.z_under = f.zc + Rf * a22;
  return c;
}

/// Rail head sections [mm], gauge flank to field flank; arcs labelled '1', '2', ... from the crown.
Definition rail(const std::string& name) {
  const RailHeadDefinition r = rail_definition_mm(name);
  const RailHeadConstruction c = construct(r);
  Definition d;
  d.name = name;
  d.kind = ProfileKind::Rail;
  d.flank_n = r.flank_n;
  d.gauge_flank_end = -c.yt;
  const std::size_t n = c.arcs.size();
  auto label = [](std::size_t k) { return static_cast<char>('1' + k); };
  d.sections.push_back(line('f', -c.y_end, -c.yt, -c.yt, c.zt, r.flank_n));
  for (std::size_t k = n; k-- > 0;) {
    const RailArc& a = c.arcs[k];
    d.sections.push_back(arc(label(k), -a.y1, -a.y0, -a.yc, a.zc, a.R, +1));  // the crown arc ends at the top
  }
  for (std::size_t k = 0; k < n; ++k) {
    const RailArc& a = c.arcs[k];
    d.sections.push_back(arc(label(k), a.y0, a.y1, a.yc, a.zc, a.R, +1));
    if (k == 0) d.sections.back().split = true;  // split at the crown top
  }
  d.sections.push_back(line('f', c.yt, c.y_end, c.yt, c.zt, -r.flank_n));
  return d;
}

/// EN 15302:2021 reference wheel A (appendix I, as transcribed in rohrbecka/EN15302; the table
/// in tests/data/en15302/README.md): r(y) [mm] = increase of radius over the taping line, y
/// from the taping line, flange at negative y; canonical z = −r(y). Split at the flange tip
/// (y = −55, the top of the R12 arc) and the taping line (y = 0) to make them nodes.
Definition en15302_wheel_a() {
  Definition d;
  d.name = "EN15302-wheel-A";
  d.kind = ProfileKind::Wheel;
  auto& S = d.sections;
  S.push_back(arc('a', -70, -62.7647, -49.5, -9.51926, 20.5, -1));
  S.push_back(arc('b', -62.7647, -55, -55, -16.00065, 12, -1));
  S.push_back(arc('b', -55, -49.6625, -55, -16.00065, 12, -1));
  S.back().split = true;
  S.push_back(arc('c', -49.6625, -39.7645, -58.5583, -8.83556, 20, -1));
  S.push_back(line('d', -39.7645, -38.7372, 0, 93.57685, 2.7475));
  S.push_back(arc('e', -38.7372, -29.4591, -25.5816, -17.64215, 14, +1));
  S.push_back(arc('f', -29.4591, -10.8749, -2.6594, -97.16493, 96.76055, +1));
  S.push_back(arc('g', -10.8749, 0, 18.4173, -344.50806, 345, +1));
  S.push_back(arc('g', 0, 18.4173, 18.4173, -344.50806, 345, +1));
  S.back().split = true;
  S.push_back(line('h', 18.4173, 30, 0, 0.49194, 0));
  S.push_back(line('i', 30, 60, 0, -1.50804, 0.066666));
  S.push_back(line('j', 60, 65, 0, -57.50808, 1));
  return d;
}

/// EN 15302:2021 reference rail A (appendix I, as transcribed in rohrbecka/EN15302): a UIC60
/// head ALREADY CANTED 1:20 as defined (it takes no inclination), d(y) [mm] = depth below the
/// reference, local y towards the field side; canonical z = −d(y).
Definition en15302_rail_a() {
  Definition d;
  d.name = "EN15302-rail-A";
  d.kind = ProfileKind::Rail;
  d.canted = true;
  auto& S = d.sections;
  S.push_back(arc('1', -32.6340, -23.2401, -19.63949, -15.899044, 13, +1));
  S.push_back(arc('2', -23.2401, -7.8749, -1.0825, -80.277908, 80, +1));
  S.push_back(arc('3', -7.8749, 13.0989, 17.5966, -299.48349, 300, +1));
  S.push_back(arc('4', 13.0989, 28.6709, 14.29829, -79.508225, 80, +1));
  S.push_back(arc('5', 28.6709, 39.2705, 26.33535, -13.598369, 13, +1));
  return d;
}

std::string valid_names_text() {
  std::string s;
  for (const auto& n : standard_profile_names()) s += (s.empty() ? "" : ", ") + n;
  return s;
}

const Definition& definition(const std::string& name) {
  static const Definition defs[] = {s1002(),         rail("60E1"),       rail("54E1"), rail("60E2"),
                                    rail("49E1"),    en15302_wheel_a(),  en15302_rail_a()};
  for (const auto& d : defs)
    if (d.name == name) return d;
  throw InputError("standard profile", "\"" + name + "\"", "unknown standard profile name",
                   "valid names: " + valid_names_text());
}

/// The section owning y [mm]: the right one at a breakpoint (side = +1), else the left one.
const Section& section_at(const Definition& d, double y_mm, int side, double y_m) {
  const auto& S = d.sections;
  if (!(y_mm >= S.front().y0 && y_mm <= S.back().y1))
    throw InputError("standard profile " + d.name, format_number(y_m * 1e3) + " mm",
                     "y outside the definition's range " + format_number(S.front().y0) + " … " +
                         format_number(S.back().y1) + " mm");
  if (side >= 0) {
    for (const auto& s : S)
      if (y_mm < s.y1) return s;
    return S.back();
  }
  for (auto it = S.rbegin(); it != S.rend(); ++it)
    if (y_mm > it->y0) return *it;
  return S.front();
}

}  // namespace

const std::vector<std::string>& standard_profile_names() {
  static const std::vector<std::string> names = {"S1002", "60E1", "54E1", "60E2", "49E1", "EN15302-wheel-A",
                                                 "EN15302-rail-A"};
  return names;
}

ProfileKind standard_profile_kind(const std::string& name) { return definition(name).kind; }

Profile make_standard_profile(const std::string& name, Inclination incl, double step) {
  const Definition& d = definition(name);
  if (!(step >= kMinStep && step <= kMaxStep))
    throw InputError("standard profile " + name, format_number(step * 1e3) + " mm",
                     "step must lie in " + format_number(kMinStep * 1e3) + " … " +
                         format_number(kMaxStep * 1e3) + " mm");
  const bool wheel = d.kind == ProfileKind::Wheel;
  if (wheel && inclination_angle(incl) != 0.0)
    throw InputError("standard profile " + name, to_string(incl),
                     "a wheel profile has no inclination", "use inclination none for " + name);
  if (d.canted && inclination_angle(incl) != 0.0)
    throw InputError("standard profile " + name, to_string(incl), "this rail is defined already canted (1:20)",
                     "use inclination none (or as-is): it is never applied twice");
  const double angle = inclination_angle(incl);

  // A flank that the rotation makes vertical is not a function z(y): it becomes the profile's
  // gauge face (Profile::face_y, face_z) and z(y) ends at the tangency point (1:20, gauge side;
  // the field flank turns away from the vertical).
  const bool vertical_gauge_flank =
      !wheel && d.flank_n > 0 && std::atan(d.flank_n) + angle >= units::pi / 2 - kVerticalFlankMargin;

  const double step_mm = step / units::mm;
  std::vector<double> ys, zs, face_ys, face_zs;
  for (const auto& s : d.sections) {
    if (vertical_gauge_flank && s.y1 <= d.gauge_flank_end) {
      s.append_nodes(step_mm, face_ys, face_zs);  // foot first, the tangency point excluded
      continue;
    }
    s.append_nodes(step_mm, ys, zs);
  }
  ys.push_back(d.sections.back().y1);  // the last section owns its end
  zs.push_back(d.sections.back().eval(ys.back()));

  Profile p;
  p.kind = d.kind;
  p.source = "standard:" + name;
  p.format = "standard";
  if (angle != 0) p.source += " inclined " + to_string(incl);
  if (vertical_gauge_flank)
    p.warnings.push_back(std::string("gauge-side flank vertical at ") + to_string(incl) +
                         ": kept as the gauge face below the R" + format_number(d.sections[1].R) +
                         "/flank tangency point, where z(y) ends");
  p.y.resize(ys.size());
  p.z.resize(zs.size());
  for (std::size_t i = 0; i < ys.size(); ++i) {
    p.y[i] = ys[i] * units::mm + 0.0;  // + 0.0: no −0 in the files
    p.z[i] = zs[i] * units::mm + 0.0;
  }
  rotate_towards_track_centre(p, angle);
  if (vertical_gauge_flank) {
    // The flank nodes turned like the points (profile.cpp rotate_towards_track_centre), from the
    // tangency point down to the foot. The turned flank is vertical: each face y is the
    // tangency point's, p.y[0] (the rotation's rounding, ~1e-16 m, is not kept).
    const double c = std::cos(angle), sn = std::sin(angle);
    for (std::size_t i = face_ys.size(); i-- > 0;) {
      const double y = face_ys[i] * units::mm, z = face_zs[i] * units::mm;
      p.face_y.push_back(p.y[0]);
      p.face_z.push_back(sn * y + c * z);
    }
  }
  for (std::size_t i = 1; i < p.size(); ++i)
    if (!(p.y[i] > p.y[i - 1]))
      throw std::logic_error("make_standard_profile: y not strictly increasing in " + p.source);
  return p;
}

std::vector<double> standard_profile_breakpoints(const std::string& name) {
  const Definition& d = definition(name);
  std::vector<double> b;
  for (std::size_t i = 1; i < d.sections.size(); ++i)
    if (!d.sections[i].split) b.push_back(d.sections[i].y0 * units::mm);
  return b;
}

std::pair<double, double> standard_profile_range(const std::string& name) {
  const Definition& d = definition(name);
  return {d.sections.front().y0 * units::mm, d.sections.back().y1 * units::mm};
}

double standard_profile_z(const std::string& name, double y, double* dz, int side) {
  const Definition& d = definition(name);
  const double y_mm = y / units::mm;
  const Section& s = section_at(d, y_mm, side, y);
  return s.eval(y_mm, dz) * units::mm;  // dz/dy is dimensionless
}

double standard_profile_radius(const std::string& name, double y, int side) {
  const Definition& d = definition(name);
  const double y_mm = y / units::mm;
  const Section& s = section_at(d, y_mm, side, y);
  return s.radius(y_mm, d.kind == ProfileKind::Wheel) * units::mm;
}

RailHeadDefinition rail_head_definition(const std::string& name) {
  if (standard_profile_kind(name) != ProfileKind::Rail || definition(name).canted)
    throw InputError("standard profile", "\"" + name + "\"", "not a rail head built from tangent arcs",
                     "rail heads: 60E1, 54E1, 60E2, 49E1");
  RailHeadDefinition d = rail_definition_mm(name);
  for (double& R : d.R) R *= units::mm;
  for (double& y : d.y_junction) y *= units::mm;
  d.depth *= units::mm;
  d.fillet_R *= units::mm;
  d.underhead_z0 *= units::mm;
  return d;
}

RailHeadConstruction construct_rail_head(const RailHeadDefinition& d) { return construct(d); }

}  // namespace mh
