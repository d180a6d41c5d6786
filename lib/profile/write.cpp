// Profile file text by extension (write.hpp); one writer per format in formats/.
#include "profile/write.hpp"

#include <string>

#include "core/errors.hpp"
#include "profile/formats/formats.hpp"

namespace mh {

using namespace formats;

ProfileKind profile_extension_kind(const std::string& path) { return kind_from_extension(extension(path)); }

std::string profile_file_text(const Profile& p, const std::string& path) {
  const std::string e = extension(path);
  const bool known = e == "csv" || e == "txt" || e == "dat" || e == "prr" || e == "prw" || e == "ban" || e == "whl" ||
                     e == "rail" || e == "wheel" || e == "rai" || e == "whe";
  if (!known)
    throw InputError(path, "." + e, "unknown output profile format",
                     "use .csv, .txt, .dat, .prr/.prw (SIMPACK), .ban/.whl (MiniProf), .rail/.wheel (GENSYS) or "
                     ".rai/.whe (VAMPIRE)");
  const ProfileKind fk = kind_from_extension(e);
  if (fk != ProfileKind::Unknown && p.kind != ProfileKind::Unknown && fk != p.kind) {
    const bool wheel = p.kind == ProfileKind::Wheel;
    const char* right = e == "prr" || e == "prw" ? (wheel ? ".prw" : ".prr")
                        : e == "ban" || e == "whl" ? (wheel ? ".whl" : ".ban")
                        : e == "rail" || e == "wheel" ? (wheel ? ".wheel" : ".rail")
                                                      : (wheel ? ".whe" : ".rai");
    throw InputError(path, "." + e,
                     std::string("a ") + to_string(p.kind) + " profile cannot be written into a " + to_string(fk) +
                         " file (the format stores the kind; reading it back would fail)",
                     std::string("use ") + right + " (or .csv)");
  }
  const bool wheel = (fk != ProfileKind::Unknown ? fk : p.kind) == ProfileKind::Wheel;
  if (!p.face_y.empty()) {
    // A vertical gauge face is written before the first point, from its foot upwards, so that
    // the points run along the profile (the readers take it back as the face, profiles.md §4).
    Profile all = p;
    all.face_y.clear();
    all.face_z.clear();
    all.y.assign(p.face_y.rbegin(), p.face_y.rend());
    all.z.assign(p.face_z.rbegin(), p.face_z.rend());
    all.y.insert(all.y.end(), p.y.begin(), p.y.end());
    all.z.insert(all.z.end(), p.z.begin(), p.z.end());
    return profile_file_text(all, path);
  }
  if (e == "csv") return write_table(p, ',', false);
  if (e == "txt" || e == "dat") return write_table(p, ' ', false);
  if (e == "prr" || e == "prw") return write_simpack(p, wheel);
  if (e == "ban" || e == "whl") return write_miniprof(p, wheel);
  if (e == "rail" || e == "wheel") return write_table(p, ' ', true);
  return write_vampire(p, wheel);
}

}  // namespace mh
