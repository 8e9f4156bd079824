// burn3d_methods.cpp -- the table of burn3d's methods (see burn3d_methods.h).
#include "pipeline/burn3d_methods.h"

#include <stdexcept>

namespace grassfire {

namespace {

struct MethodRow {
  const char* name;
  BurnMethod run;
};
const MethodRow kMethods[] = {{"discrete", burn_by_discrete}, {"exact", burn_by_exact}};

}  // namespace

BurnMethod burn_method(const std::string& name) {
  for (const MethodRow& m : kMethods)
    if (name == m.name) return m.run;
  throw std::invalid_argument("unknown method '" + name + "' (discrete or exact)");
}

}  // namespace grassfire
