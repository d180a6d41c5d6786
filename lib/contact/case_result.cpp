#include "contact/case_result.hpp"

#include <stdexcept>

namespace mh {

const char* to_string(Method m) {
  switch (m) {
    case Method::MultiHertzian: return "multi-hertzian";
    case Method::HalfSpace: return "half-space";
    case Method::Strips: return "strips";
    case Method::Auto: return "auto";
  }
  return "?";
}

Method parse_method(const std::string& s) {
  if (s == "multi-hertzian") return Method::MultiHertzian;
  if (s == "half-space") return Method::HalfSpace;
  if (s == "strips") return Method::Strips;
  if (s == "auto") return Method::Auto;
  throw std::invalid_argument("unknown method '" + s + "' (expected multi-hertzian, half-space, strips or auto)");
}

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
