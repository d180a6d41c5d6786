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
  double gauge_flank_end = -kInf; ///< rails: y [mm] where the gauge flank meets R13 (−yt)
  double flank_n = 0;             ///< rails: flank 1 : n to the vertical
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
  RailHeadDefinition d;
  d.R1 = 300, d.R2 = 80, d.R3 = 13, d.flank_n = 20, d.depth = 20;
  if (name == "60E1") d.y12 = 10.228, d.y23 = 26.0265;      // EN 13674-1 (profiles.md)
  else if (name == "54E1") d.y12 = 10.012, d.y23 = 24.8635; // EN 13674-1 (profiles.md)
  else throw std::logic_error("rail_definition_mm: " + name);
  return d;
}

/// The construction is homogeneous in length: the same code serves metres and millimetres.
RailHeadConstruction construct(const RailHeadDefinition& d) {
  RailHeadConstruction c;
  // R1: centre (0, −R1) through the crown top (0, 0).
  c.z12 = -d.R1 + std::sqrt(d.R1 * d.R1 - d.y12 * d.y12);
  // Internal tangency at y12: the R2 centre lies on the R1 radius through the junction,
  // R1 − R2 from the R1 centre.
  c.yc2 = (d.R1 - d.R2) * d.y12 / d.R1;
  c.zc2 = -d.R1 + (d.R1 - d.R2) * (c.z12 + d.R1) / d.R1;
  const double u2 = d.y23 - c.yc2;
  c.z23 = c.zc2 + std::sqrt(d.R2 * d.R2 - u2 * u2);
  c.yc3 = c.yc2 + (d.R2 - d.R3) * u2 / d.R2;
  c.zc3 = c.zc2 + (d.R2 - d.R3) * (c.z23 - c.zc2) / d.R2;
  // The flank (direction (1, −n) on the field side) touches R3 where R3's outward normal is
  // (n, 1)/√(1 + n²).
  const double h = std::sqrt(1 + d.flank_n * d.flank_n);
  c.yt = c.yc3 + d.R3 * d.flank_n / h;
  c.zt = c.zc3 + d.R3 / h;
  c.z_end = -d.depth;
  c.y_end = c.yt + (c.zt - c.z_end) / d.flank_n;
  return c;
}

/// Rail head sections [mm], gauge flank to field flank.
Definition rail(const std::string& name) {
  const RailHeadDefinition r = rail_definition_mm(name);
  const RailHeadConstruction c = construct(r);
  Definition d;
  d.name = name;
  d.kind = ProfileKind::Rail;
  d.flank_n = r.flank_n;
  d.gauge_flank_end = -c.yt;
  d.sections.push_back(line('f', -c.y_end, -c.yt, -c.yt, c.zt, r.flank_n));
  d.sections.push_back(arc('3', -c.yt, -r.y23, -c.yc3, c.zc3, r.R3, +1));
  d.sections.push_back(arc('2', -r.y23, -r.y12, -c.yc2, c.zc2, r.R2, +1));
  d.sections.push_back(arc('1', -r.y12, 0, 0, -r.R1, r.R1, +1));  // split at the crown top
  d.sections.push_back(arc('1', 0, r.y12, 0, -r.R1, r.R1, +1));
  d.sections.back().split = true;
  d.sections.push_back(arc('2', r.y12, r.y23, c.yc2, c.zc2, r.R2, +1));
  d.sections.push_back(arc('3', r.y23, c.yt, c.yc3, c.zc3, r.R3, +1));
  d.sections.push_back(line('f', c.yt, c.y_end, c.yt, c.zt, -r.flank_n));
  return d;
}

std::string valid_names_text() {
  std::string s;
  for (const auto& n : standard_profile_names()) s += (s.empty() ? "" : ", ") + n;
  return s;
}

const Definition& definition(const std::string& name) {
  static const Definition defs[] = {s1002(), rail("60E1"), rail("54E1")};
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
  static const std::vector<std::string> names = {"S1002", "60E1", "54E1"};
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
                     "a wheel profile has no inclination", "use inclination none for S1002");
  const double angle = inclination_angle(incl);

  // A flank that the rotation makes vertical is not a function z(y): leave it out (1:20, gauge
  // side; the field flank turns away from the vertical).
  const bool drop_gauge_flank =
      !wheel && std::atan(d.flank_n) + angle >= units::pi / 2 - kVerticalFlankMargin;

  const double step_mm = step / units::mm;
  std::vector<double> ys, zs;
  for (const auto& s : d.sections) {
    if (drop_gauge_flank && s.y1 <= d.gauge_flank_end) continue;
    s.append_nodes(step_mm, ys, zs);
  }
  ys.push_back(d.sections.back().y1);  // the last section owns its end
  zs.push_back(d.sections.back().eval(ys.back()));

  Profile p;
  p.kind = d.kind;
  p.source = "standard:" + name;
  p.format = "standard";
  if (angle != 0) p.source += " inclined " + to_string(incl);
  if (drop_gauge_flank)
    p.warnings.push_back(std::string("gauge-side flank left out: it is vertical at ") + to_string(incl) +
                         "; the profile ends at the R13/flank tangency point");
  p.y.resize(ys.size());
  p.z.resize(zs.size());
  for (std::size_t i = 0; i < ys.size(); ++i) {
    p.y[i] = ys[i] * units::mm + 0.0;  // + 0.0: no −0 in the files
    p.z[i] = zs[i] * units::mm + 0.0;
  }
  rotate_towards_track_centre(p, angle);
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
  if (standard_profile_kind(name) != ProfileKind::Rail)
    throw InputError("standard profile", "\"" + name + "\"", "not a rail",
                     "rails: 60E1, 54E1");
  RailHeadDefinition d = rail_definition_mm(name);
  d.R1 *= units::mm, d.R2 *= units::mm, d.R3 *= units::mm;
  d.y12 *= units::mm, d.y23 *= units::mm, d.depth *= units::mm;
  return d;
}

RailHeadConstruction construct_rail_head(const RailHeadDefinition& d) { return construct(d); }

}  // namespace mh
