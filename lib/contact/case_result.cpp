#include "contact/case_result.hpp"

#include <stdexcept>

namespace mh {


const char* to_string(CaseStatus s) {
  switch (s) {
    case CaseStatus::Ok: return "ok";
    case CaseStatus::NoContact: return "no_contact";
    case CaseStatus::OutOfRange: return "out_of_range";
    case CaseStatus::NotConverged: return "not_converged";
  }
  return "?";
}

}  // namespace mh
