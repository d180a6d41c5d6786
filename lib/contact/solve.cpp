#include "contact/solve.hpp"

namespace mh {

CaseResult solve_method(const ContactGeometry& G, const Material& mat, double tY, double Q, const MethodOptions& opt) {
  switch (opt.method) {
    case Method::HalfSpace: return solve_half_space(G, mat, tY, Q, opt.half_space);
    case Method::Strips: return solve_strip_method(G, mat, tY, Q, opt.strips);
    case Method::MultiHertzian:
    default: return solve_case(G, mat, tY, Q, opt.multi_hertzian);
  }
}

}  // namespace mh
