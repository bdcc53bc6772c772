#pragma once
// Output files written whole or not at all (writeFileAtomically) and the IoError it throws.
#include <stdexcept>
#include <string>

namespace chaplygin {

/// An output file could not be written. The message names the file and the reason.
class IoError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Writes content to path so that a failure never leaves a half-written file: the bytes go to
/// a temporary file beside it, every write() and the fsync() are checked, and only then is it
/// renamed over the target. On any failure the temporary is removed, the old file stays, and
/// IoError is thrown. path "-" writes to standard output.
void writeFileAtomically(const std::string& path, const std::string& content);

} // namespace chaplygin
