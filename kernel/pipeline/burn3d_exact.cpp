// burn3d_exact.cpp -- `burn3d --method exact`: the exact engine's entry (issue 8).
#include <stdexcept>

#include "pipeline/burn3d_methods.h"

namespace grassfire {

BurnOutcome burn_by_exact(const BurnRequest& /*request*/) {
  throw std::runtime_error("method 'exact' is not available yet: the exact window-propagation engine (issue 8) "
                           "has not landed; use --method discrete");
}

}  // namespace grassfire
