#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so a
// killed run never leaves a truncated file that looks complete.
#include <functional>
#include <ostream>
#include <string>

namespace touchdown::drop {

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace touchdown::drop
