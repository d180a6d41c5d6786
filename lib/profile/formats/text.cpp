// Tokenising, number parsing and line reading shared by the profile readers.
#include "profile/formats/formats.hpp"

#include <algorithm>
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


std::vector<std::string> read_lines(const std::string& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open the profile file", "check the path and permissions");
  std::ostringstream ss;
  ss << in.rdbuf();
  bytes = ss.str();
  std::vector<std::string> lines;
  std::string cur;
  for (char c : bytes) {
    if (c == '\n') {
      if (!cur.empty() && cur.back() == '\r') cur.pop_back();
      lines.push_back(cur);
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

}  // namespace mh::formats
