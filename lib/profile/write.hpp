#pragma once
// Profile file text for every format the readers read (read.hpp), chosen by the extension, so
// that a profile round-trips: read → write → read gives the same points to the printed
// precision (shortest round-trip decimal, std::to_chars). The atomic file write is
// output/profile_file.hpp. Each format keeps the kind: a wheel is never written into a rail file.
//
//   .csv            canonical table, header "y_mm,z_mm" (y to the field side, z up, mm)
//   .txt, .dat      the same, whitespace-separated, header "y_mm z_mm"
//   .prr / .prw     SIMPACK rail / wheel (type 0 / 1), z down, no transformations
//   .ban / .whl     MiniProf Key=Value style (ColumnDef=X,Y): rails X = −y (to the gauge side),
//                   Y = −z (depth), stated by the key YAxis=depth (the reader otherwise guesses
//                   the sign from the values); wheels X = y (taping line at X = 0, flange at
//                   negative X), Y = −z (increase of radius)
//   .rail / .wheel  GENSYS style: two columns, y towards the track centre, z down (both mirrored)
//   .rai / .whe     VAMPIRE: both sides the same profile, datum line "EUROPEAN", line 4 the
//                   flange-back distance (1360) or gauge (1435) of the standard track
#include <string>

#include "profile/profile.hpp"

namespace mh {

/// The kind a profile file extension stores (Rail for prr/ban/rail/rai, Wheel for
/// prw/whl/wheel/whe), Unknown for csv/txt/dat and unknown extensions.
ProfileKind profile_extension_kind(const std::string& path);

/// The file text of `p` in the format of the extension of `path`. Throws InputError (path, the
/// extension, the rule, the fix naming the right extension) for an unknown extension or a wheel
/// written as a rail file and the reverse.
std::string profile_file_text(const Profile& p, const std::string& path);

}  // namespace mh
