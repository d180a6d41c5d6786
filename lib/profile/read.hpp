#pragma once
// Reading and writing profile files (profiles.md "File formats seen in the field").
// Every reader ends in the canonical frame of profile.hpp (y to the field side, z up, SI),
// applies the format's own transformations first, then the user's mirror/scale options, then
// checks for the obvious mistakes (metres read as mm, flange on the wrong side, rail upside
// down, loops or backward steps where contact can happen) and throws InputError naming the
// file, the value, the rule and the fix.
#include <string>

#include "profile/profile.hpp"

namespace mh {

enum class ProfileFormat { Auto, Simpack, MiniProf, Table, Vampire };

/// "auto", "simpack", "miniprof", "table", "vampire"; throws std::invalid_argument otherwise.
ProfileFormat parse_profile_format(const std::string& s);
const char* to_string(ProfileFormat f);

/// Clean-up of measured profiles where the other body can touch (docs/profiles.md §6):
///  Envelope (default): exact duplicates and ≤ 0.05 mm jitter dropped, then folds and loops
///    (y stepping back) replaced by the outer envelope of the surface the other body can touch
///    (rail: the upper envelope, wheel: the lower one), with a warning saying how many points
///    went and where; still rejected: a fold deeper than kMaxFold_mm, folds over more than
///    kMaxFoldFraction of the width, a gap wider than kMaxBridge_mm left by the clean-up.
///  Strict: duplicates and jitter dropped, any larger backward step rejected.
///  Off: nothing dropped where contact can happen; any step that does not advance y is rejected.
enum class ProfileCleanup { Envelope, Strict, Off };
/// "envelope", "strict", "off"; std::invalid_argument otherwise.
ProfileCleanup parse_profile_cleanup(const std::string& s);
const char* to_string(ProfileCleanup c);

struct ProfileReadOptions {
  ProfileFormat format = ProfileFormat::Auto;  ///< Auto: by extension, else by content
  ProfileKind kind = ProfileKind::Unknown;     ///< expected kind; Unknown: from the file (header, extension)
  bool mirror_y = false;   ///< mirror y after the format's own transformations (default: no)
  bool mirror_z = false;   ///< mirror z after the format's own transformations (default: no)
  double scale = 1.0;      ///< multiply file lengths by this before interpreting them as mm (default 1)
  bool check = true;       ///< run the plausibility checks (default: yes)
  ProfileCleanup cleanup = ProfileCleanup::Envelope;  ///< clean-up where contact can happen (default envelope)
  /// VAMPIRE files hold both sides; which one to read: "right" (default) or "left".
  std::string vampire_side = "right";
  /// Multi-profile MiniProf files (.mpt, [Profile<K>Info] sections): which profile to read
  /// (K, 1-based). 0 (default): the only one that can be a wheel or a rail (the expected kind
  /// when known); several: refused with the list of profiles. Any other file: must be 0.
  int section = 0;
};

/// Read a profile file. Throws InputError (file, line, value, rule, fix) on anything malformed.
Profile read_profile(const std::string& path, const ProfileReadOptions& opt = {});

/// Thresholds of the plausibility checks (read_profile), in mm. Defaults as documented.
struct ProfileCheckLimits {
  static constexpr double kMinWidth_mm = 5.0;      ///< total width below this: metres read as mm?
  static constexpr double kMaxWidth_mm = 500.0;    ///< total width above this: µm or 0.1 mm units?
  static constexpr std::size_t kMinPoints = 10;    ///< fewer points cannot describe a profile
  static constexpr double kRailContactDepth_mm = 25.0;  ///< rail region that can touch: z > top − 25 mm
  /// Inside that region a point that steps back in y by at most this much is measurement jitter
  /// (MiniProf resolution is 0.01 mm) and is dropped with a warning; a larger step is an error.
  static constexpr double kJitter_mm = 0.05;
  /// Rails: points at the gauge-side start with exactly one y over at least this height are a
  /// vertical gauge face (Profile::face_y, face_z; profiles.md §4), not jitter.
  static constexpr double kMinGaugeFace_mm = 2.0;
  /// Clean-up (ProfileCleanup::Envelope): a fold whose y steps back by more than this is not a
  /// measurement artefact that an envelope can honestly remove; rejected.
  static constexpr double kMaxFold_mm = 1.0;
  /// ... nor folds that together cover more than this fraction of the width that can touch.
  static constexpr double kMaxFoldFraction = 0.5;
  /// ... nor a clean-up that leaves two neighbouring points farther apart than this.
  static constexpr double kMaxBridge_mm = 2.0;
  /// MiniProf drawing elements (MPD<k>=): largest spacing of the sampled points along an element
  /// (arcs: equal angles, points exactly on the arc) ...
  static constexpr double kElementStep_mm = 0.1;
  /// ... and consecutive elements "join" when the end of one is this close to the start of the next.
  static constexpr double kElementJoin_mm = 0.001;
  static constexpr double kTapingLineFromFlangeBack_mm = 70.0;  ///< EN 13715: taping line 70 mm from the flange back
  static constexpr double kFlangeHeight_mm = 10.0; ///< a flange: lowest point this far below the field-side end
};

/// The extension's format ("prr" -> Simpack, ...), Auto if unknown.
ProfileFormat format_from_extension(const std::string& path);

}  // namespace mh
