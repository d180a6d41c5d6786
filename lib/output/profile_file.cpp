#include "output/profile_file.hpp"

#include <string>

#include "output/output_file.hpp"
#include "profile/write.hpp"

namespace mh {

void write_profile(const Profile& p, const std::string& path) {
  const std::string s = profile_file_text(p, path);  // InputError before any file is created
  OutputFile out(path);
  out.stream() << s;
  out.commit();
}

}  // namespace mh
