#pragma once
// Shared by the profile readers (one file per format in this folder): the points of a file as
// read (RawProfile, millimetres, file order, with their line numbers), tokenising and number
// parsing with located errors. Internal to lib/profile.
#include <string>
#include <vector>

#include "profile/profile.hpp"
#include "profile/read.hpp"

namespace mh::formats {

std::string lower(std::string s);
/// Lower-case extension of a path without the dot ("" if none).
std::string extension(const std::string& path);
std::string trim(const std::string& s);
/// "12.345 mm" (rounded to 1 nm), for messages.
std::string mm(double v);
/// Split on whitespace and commas.
std::vector<std::string> tokens(const std::string& line);
bool looks_numeric(const std::string& t);
/// A number that must be the whole token and finite; InputError at `where` otherwise.
double parse_number(const std::string& tok, const std::string& where);
/// The step of the last printed digit of a number token, in the token's units: 10^-d for d
/// decimals, times 10^e for an exponent ("12.345" 0.001, "1.5e-3" 1e-4, "12" 1); 0 when the token
/// is not a plain decimal number (profiles.md "Measured or exact").
double printed_step(const std::string& tok);
/// A whole number in [lo, hi] (a count, a type code); InputError at `where` naming `what` otherwise.
long parse_integer(const std::string& tok, const std::string& where, const std::string& what, long lo, long hi);

/// Points as read, in file order, mm, with their file line (for messages).
struct RawProfile {
  std::vector<double> y, z;
  std::vector<std::size_t> line;
  ProfileKind kind = ProfileKind::Unknown;
  std::string format;
  std::vector<std::string> warnings;
  CleanupReport cleanup;
  std::string taping_line;  ///< wheels: how y = 0 was put on the taping line (Profile::taping_line)
  std::vector<std::pair<std::string, std::string>> measures;  ///< from the header (MiniProf Sd/Sh/qR)
  /// Smallest printed step of the coordinates (the most decimals seen), in the file's length
  /// units until the reader scales it to mm; 0: not printed (sampled elements) or unknown.
  double print_step = 0;
  /// The printed step of each file line's point: the finer of its two coordinates' steps (the
  /// decimals a point shows; trailing zeros a writer dropped make a step coarser than the
  /// precision, which Profile::point_step's user allows for), in the same units as print_step,
  /// indexed by file line (0: no printed point on that line).
  std::vector<double> line_step;
  /// Rails: the vertical gauge face found by the clean-up (Profile::face_y, face_z), mm.
  std::vector<double> face_y, face_z;
  void add(double yy, double zz, std::size_t ln) { y.push_back(yy); z.push_back(zz); line.push_back(ln); }
  /// The same from the tokens as printed; records their printed step.
  void add(const std::string& ty, const std::string& tz, const std::string& where, std::size_t ln) {
    add(parse_number(ty, where), parse_number(tz, where), ln);
    double finest = 0;
    for (const std::string* t : {&ty, &tz}) {
      const double q = printed_step(*t);
      if (q > 0 && (print_step == 0 || q < print_step)) print_step = q;
      if (q > 0 && (finest == 0 || q < finest)) finest = q;
    }
    if (line_step.size() <= ln) line_step.resize(ln + 1, 0.0);
    line_step[ln] = finest;
  }
  /// The printed step of the point on file line `ln` (0: unknown).
  double step_of_line(std::size_t ln) const { return ln < line_step.size() ? line_step[ln] : 0.0; }
  std::size_t size() const { return y.size(); }
};

/// The file's lines (CR LF or LF) and its bytes (for the checksum).
std::vector<std::string> read_lines(const std::string& path, std::string& bytes);
ProfileKind kind_from_extension(const std::string& ext);

// The readers (one file each). They apply the format's own conventions and end in the
// canonical frame of profile.hpp, in mm.
RawProfile read_simpack(const std::string& path, const std::vector<std::string>& lines);
/// hint: Wheel or Rail from the extension or the user; Unknown: from the content (default rail).
/// section: multi-profile files (.mpt), the profile to read (1-based; 0: the only one that can be `hint`).
RawProfile read_miniprof(const std::string& path, const std::vector<std::string>& lines, ProfileKind hint, int section = 0);
RawProfile read_table(const std::string& path, const std::vector<std::string>& lines, bool gensys);
RawProfile read_vampire(const std::string& path, const std::vector<std::string>& lines, const std::string& side);
/// The format of a file whose extension says nothing, from its content.
ProfileFormat sniff(const std::vector<std::string>& lines);

// The writers (one per format, in the reader's file): the text of the canonical profile `p`.
std::string write_simpack(const Profile& p, bool wheel);
std::string write_miniprof(const Profile& p, bool wheel);
/// sep: ',' (csv, header y_mm,z_mm) or ' '; gensys: both axes mirrored, no header.
std::string write_table(const Profile& p, char sep, bool gensys);
std::string write_vampire(const Profile& p, bool wheel);
/// "! written by mhcontact from SOURCE (FORMAT)" style provenance text (without comment marker).
std::string provenance(const Profile& p);

/// A profile in the canonical frame whose shape can be a `k` (a wheel: a flange near one end; a
/// rail: a head with both ends at least 5 mm lower) (shape.cpp; used to choose among the
/// profiles of a multi-profile file).
bool shape_could_be(const RawProfile& r, ProfileKind k);

/// Shape checks and clean-up in the canonical frame (shape.cpp).
void clean_and_check(RawProfile& r, const std::string& path, const ProfileReadOptions& opt);

}  // namespace mh::formats
