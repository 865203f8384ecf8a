#include "openturns_setup.hpp"

#include <openturns/Log.hxx>
#include <openturns/TBBImplementation.hxx>

namespace sweetspot {

void configure_openturns() {
  OT::TBBImplementation::SetThreadsNumber(1);
  OT::Log::Show(OT::Log::NONE);
}

}  // namespace sweetspot
