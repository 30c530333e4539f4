#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so a
// killed run never leaves a truncated file that looks complete.
#include <functional>
#include <ostream>
#include <string>

namespace touchdown::drop {

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// An output directory the same way: `fill` writes into a staging directory beside `directory`,
// which replaces `directory` only when `fill` returns; on an exception it is removed.
void WriteStagedDirectory(const std::string& directory, const std::function<void(const std::string& staging)>& fill);

}  // namespace touchdown::drop
