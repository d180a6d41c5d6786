// Tokenising, number parsing and line reading shared by the profile readers.
#include "profile/formats/formats.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "core/numfmt.hpp"

namespace mh::formats {


std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lower(path.substr(dot + 1));
}

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string mm(double v) { return format_number(std::round(v * 1e6) / 1e6) + " mm"; }  // to 1 nm

/// Split on whitespace and commas.
std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
      if (!cur.empty()) out.push_back(cur), cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool looks_numeric(const std::string& t) {
  if (t.empty()) return false;
  const char c = t[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
}

/// A number that must be the whole token and finite.
double parse_number(const std::string& tok, const std::string& where) {
  // A plain decimal number (what the profile files hold) by std::from_chars, correctly rounded
  // like strtod and several times faster; anything else (a sign '+', hex, junk, out of range)
  // through strtod as it always was, with its messages.
  {
    double v = 0;
    const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (r.ec == std::errc() && r.ptr == tok.data() + tok.size() && !tok.empty() && std::isfinite(v)) return v;
  }
  const char* b = tok.c_str();
  char* e = nullptr;
  const double v = std::strtod(b, &e);
  if (e == b) throw InputError(where, "'" + tok + "'", "not a number", "each row must hold numbers only");
  if (*e != '\0')
    throw InputError(where, "'" + tok + "'", "number with trailing junk '" + std::string(e) + "'",
                     "remove the extra characters; use '.' as the decimal separator");
  if (!std::isfinite(v))
    throw InputError(where, "'" + tok + "'", "NaN or infinite coordinate", "every point needs finite y and z");
  return v;
}

double printed_step(const std::string& tok) {
  std::size_t i = 0;
  if (i < tok.size() && (tok[i] == '+' || tok[i] == '-')) ++i;
  int decimals = 0;
  bool digits = false, point = false;
  for (; i < tok.size(); ++i) {
    const char c = tok[i];
    if (std::isdigit(static_cast<unsigned char>(c))) { digits = true; if (point) ++decimals; }
    else if (c == '.' && !point) point = true;
    else break;
  }
  if (!digits) return 0;
  long exponent = 0;
  if (i < tok.size()) {
    if (tok[i] != 'e' && tok[i] != 'E') return 0;
    char* e = nullptr;
    exponent = std::strtol(tok.c_str() + i + 1, &e, 10);
    if (*e != '\0' || e == tok.c_str() + i + 1 || std::labs(exponent) > 300) return 0;
  }
  return std::pow(10.0, static_cast<double>(exponent - decimals));
}

long parse_integer(const std::string& tok, const std::string& where, const std::string& what, long lo, long hi) {
  const double v = parse_number(tok, where);
  if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi))
    throw InputError(where, "'" + tok + "'",
                     what + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi),
                     "correct the number, or drop the key to let the reader count");
  return static_cast<long>(v);
}


namespace {
/// Refuse what is not a text file of 8-bit characters, naming what it is and how to fix it.
void check_encoding(const std::string& path, const std::string& b) {
  auto starts = [&b](const char* sig, std::size_t n) { return b.size() >= n && b.compare(0, n, sig, n) == 0; };
  if (starts("\xFF\xFE", 2) || starts("\xFE\xFF", 2))
    throw InputError(path, std::string("byte-order mark ") + (b[0] == '\xFF' ? "FF FE" : "FE FF"),
                     std::string("the file is UTF-16 (") + (b[0] == '\xFF' ? "little" : "big") +
                         "-endian) text; profile files must be UTF-8 or ASCII",
                     "save it as UTF-8 (Excel: \"CSV UTF-8\"; iconv -f UTF-16 -t UTF-8 IN > OUT)");
  if (starts("\x1F\x8B", 2))
    throw InputError(path, "bytes 1F 8B", "the file is gzip-compressed", "decompress it first: gunzip -k FILE");
  if (starts("PK\x03\x04", 4))
    throw InputError(path, "bytes 50 4B 03 04", "the file is a ZIP archive (an .xlsx workbook?)",
                     "unpack it, or export the sheet as CSV (two columns y, z in mm)");
  const auto nul = b.find('\0');
  if (nul != std::string::npos) {
    // UTF-16 without a byte-order mark: every other byte of ASCII text is NUL.
    std::size_t even = 0, odd = 0, n = std::min<std::size_t>(b.size(), 4096);
    for (std::size_t i = 0; i < n; ++i)
      if (b[i] == '\0') (i % 2 ? odd : even)++;
    if (n >= 8 && (odd > n * 4 / 10 || even > n * 4 / 10))
      throw InputError(path, "NUL bytes at every other position",
                       "the file looks like UTF-16 text without a byte-order mark; profile files must be UTF-8 or ASCII",
                       "save it as UTF-8 (iconv -f UTF-16LE -t UTF-8 IN > OUT)");
    throw InputError(path, "NUL byte at offset " + std::to_string(nul),
                     "the file is binary, not a text profile",
                     "export the profile as text (CSV, SIMPACK .prr/.prw, MiniProf .ban/.whl)");
  }
}
}  // namespace

std::vector<std::string> read_lines(const std::string& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the profile file", "check the path and permissions");
  std::ostringstream ss;
  ss << in.rdbuf();
  bytes = ss.str();
  check_encoding(path, bytes);
  std::vector<std::string> lines;
  std::string cur;
  // A UTF-8 byte-order mark (Excel's "CSV UTF-8") is not part of the first line.
  const std::size_t start = bytes.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  for (std::size_t i = start; i < bytes.size(); ++i) {
    const char c = bytes[i];
    if (c == '\n') {
      if (!cur.empty() && cur.back() == '\r') cur.pop_back();
      lines.push_back(cur);
      cur.clear();
    } else if (c == '\r' && i + 1 < bytes.size() && bytes[i + 1] != '\n') {
      lines.push_back(cur);  // old Mac line ends (CR only)
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) {
    if (cur.back() == '\r') cur.pop_back();
    lines.push_back(cur);
  }
  return lines;
}

ProfileKind kind_from_extension(const std::string& ext) {
  if (ext == "prr" || ext == "ban" || ext == "rail" || ext == "rai") return ProfileKind::Rail;
  if (ext == "prw" || ext == "whl" || ext == "wheel" || ext == "whe") return ProfileKind::Wheel;
  return ProfileKind::Unknown;
}

std::string provenance(const Profile& p) {
  return "written by mhcontact from " + (p.source.empty() ? std::string("(generated)") : p.source) + " (" +
         (p.format.empty() ? std::string("?") : p.format) + ")";
}

}  // namespace mh::formats
