#include "rft/forwarding_law_3d.h"

#include <stdexcept>
#include <utility>

namespace touchdown::rft {

ForwardingLaw3D::ForwardingLaw3D(std::unique_ptr<StressLaw3D> inner, std::string_view suffix)
    : inner_(std::move(inner)) {
  if (!inner_) throw std::invalid_argument("ForwardingLaw3D: no law to wrap");
  name_ = std::string(inner_->name()) + "+" + std::string(suffix);
}

}  // namespace touchdown::rft
