#pragma once
// `mhcontact wheelset CASE.json -o DIR` (docs/wheelset.md): one wheelset → DIR/wheelset.csv,
// DIR/conicity.csv, DIR/summary.json; a fleet (the case file's "wheels") → DIR/fleet.csv, one row
// per wheel against the one rail pair. A wheel that cannot be read or placed, or whose contact
// leaves a profile inside the oscillation of an amplitude asked, gets a status and no conicity:
// never a figure computed on a wrong placement. The run goes on.
#include <iosfwd>
#include <string>

#include "input/wheelset_case.hpp"

namespace mh {

struct WheelsetRunOptions {
  std::string out_dir;
  unsigned threads = 0;   ///< fleets (and the rows of one wheelset): 0 = all cores (default); same bytes whatever the count
  int digits = 10;        ///< significant digits of the tables (default 10; 0: shortest round trip)
  bool quiet = false;     ///< no summary on standard error
};

/// Returns the exit code: 0 when every row, amplitude (and wheel) is ok, 1 otherwise.
int wheelset_job(const WheelsetCase& wc, const WheelsetRunOptions& opt, std::ostream& out, std::ostream& err);

/// Fleet status of a wheel: "ok", "invalid_wheel" (read or placement refused), "off_profile".
constexpr const char* kInvalidWheel = "invalid_wheel";

}  // namespace mh
