#pragma once
// SHA-256 (FIPS 180-4) of bytes and of a file's bytes, as lower-case hex. Used to record the
// checksum of every input file in result files (Profile::checksum).
#include <string>

namespace mh {

/// SHA-256 of `bytes`, 64 lower-case hex digits.
std::string sha256_hex(const std::string& bytes);
/// SHA-256 of the file's bytes. Throws InputError naming the file if it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace mh
