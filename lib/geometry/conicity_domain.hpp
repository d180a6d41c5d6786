#pragma once
// The domain in which an equivalent conicity (conicity.hpp) is `ok` (docs/wheelset.md "Where the
// conicity is ok"): what the project's EN 15302 reference tests cover, written once here as a
// table (conicity_evidence(), rendered in the docs), and the checks that hold a wheelset against
// it.
//
//  - profile_incomplete: EN 15302's tan γe is the linearised wheelset's between the flanges; its
//    amplitude is judged against the flangeway clearance (below), which needs each wheel's flange
//    face at the Sd level (10 mm above the running circle, EN 15313) and each rail's gauge point
//    (gauge_height below its top, EN 13848-1). A wheel without them (no flange: a fragment, a
//    roller's tread) or a rail without a gauge point leaves that domain unknown.
//  - flange_contact: the oscillation's contact angle exceeds what the reference covers inside its
//    clearance (kTreadContactAngleMax), or its turning points reach beyond the flangeway clearance
//    of their side, c_s = |Y| of rail s's gauge point − |Y| of wheel s's flange face at the Sd level,
//    the wheelset centred (c_left + c_right = TG − SR: the gauge TG less the distance SR between
//    the wheels' active faces). The linearised conicity describes the tread's rolling-radius
//    difference; the TSI (Regulation (EU) 1302/2014 LOC&PAS §4.2.3.4.3 and 321/2013 WAG,
//    after EN 15302) asks it at an amplitude inside that clearance: ŷ = 3 mm when TG − SR ≥ 7 mm,
//    ((TG − SR) − 1)/2 when 5 ≤ TG − SR < 7 mm. Beyond the clearance the flange root and flank
//    carry the contact (EN 15302 wheel A on rail A: γ 11.8° at y = 5 mm, 70° from 7 mm).
//    tan γe is still written (it is EN 15302's integral, which the standard's tables also give
//    there), with this status.
//  - the wheel measures Sd, Sh, qR against EN 15313's in-service limits (wheel_measure_limits).
#include <string>
#include <vector>

#include "geometry/conicity.hpp"
#include "geometry/wheelset.hpp"
#include "profile/profile.hpp"

namespace mh {

/// One row of the conicity's evidence: what a reference test of the project covers.
struct ConicityEvidenceRow {
  const char* quantity;  ///< what is covered
  const char* covered;   ///< the range or the cases covered
  const char* test;      ///< the test that establishes it (and its reference)
};
/// The evidence table (docs/wheelset.md "Where the conicity is ok" renders it).
const std::vector<ConicityEvidenceRow>& conicity_evidence();
/// The table as the Markdown the docs hold (a test compares them).
std::string conicity_evidence_markdown();

/// [m] Flangeway clearance of the centred wheelset on each side (see above); valid false, with
/// the reason in `why`, when a wheel has no flange face at the Sd level or a rail no gauge point.
struct FlangewayClearance {
  double left = 0, right = 0;
  bool valid = false;
  std::string why;
};
/// From the placed wheelset and its wheels' measures (computed from the profiles, in the frame
/// the wheelset places: the flange face at the Sd level lies at wheel y = Sd − 70 mm).
FlangewayClearance flangeway_clearance(const Wheelset& ws, const WheelMeasures& left, const WheelMeasures& right);

/// [rad] The largest contact angle of an `ok` amplitude of the evidence: EN 15302 wheel A on rail
/// A at ŷ = 4.8 mm, the largest amplitude of the standard's table inside the pair's clearance
/// (4.89 mm), reaches 11.09° (right wheel at y = 4.8 mm). Beyond 11.1° an oscillation runs on
/// the flange root whatever the clearance says (a worn gauge corner, a hollow tread):
/// flange_contact.
constexpr double kTreadContactAngleMax = 11.1 * 3.14159265358979323846 / 180.0;

/// An amplitude's status by the domain, and why when it is not ok.
struct ConicityDomainVerdict {
  std::string status = "ok";
  std::string why;  ///< the bound crossed, with the value and the limit (empty when ok)
};
/// The verdict on an amplitude whose EN 15302 integral is `c` (its own status first: anything but
/// "ok" is kept), given the largest |contact angle| of either wheel over the rows between its
/// turning points, gamma_max [rad]: "profile_incomplete" when the clearance is unknown;
/// "flange_contact" when a turning point lies beyond its side's clearance or gamma_max exceeds
/// kTreadContactAngleMax; else "ok".
ConicityDomainVerdict conicity_domain(const ConicityResult& c, const FlangewayClearance& fc, double gamma_max);

/// EN 15313 in-service limits of the wheel measures in one band of wheel diameter [m].
struct WheelMeasureLimits {
  double D_min, D_max;            ///< [m] the band D_min ≤ D < D_max
  double Sd_min, Sd_max;          ///< [m] flange thickness
  double Sh_min, Sh_max;          ///< [m] flange height
  double qR_min;                  ///< [m] flange slope (qR)
};
/// The band of diameter D [m] (nullptr below 330 mm: no limits given).
const WheelMeasureLimits* wheel_measure_limits(double D);

/// One measure outside its limit.
struct MeasureViolation {
  const char* measure;  ///< "Sd", "Sh", "qR"
  double value = 0;     ///< [m]
  double limit = 0;     ///< [m]
  bool above = false;   ///< above a maximum (else below a minimum)
};
/// A wheel's measures against the limits of its diameter.
struct WheelMeasureCheck {
  /// "ok"; "outside_en15313" (violations listed); "unknown" (a measure missing, or no band).
  std::string status = "unknown";
  std::vector<MeasureViolation> violations;
  /// "Sd 36.4 mm > 33 mm (EN 15313, D 920 mm); ..." (empty when none).
  std::string text(double D) const;
};
/// Sd, Sh, qR [m] (NaN: unknown), D [m] the wheel diameter.
WheelMeasureCheck check_wheel_measures(double Sd, double Sh, double qR, double D);

}  // namespace mh
