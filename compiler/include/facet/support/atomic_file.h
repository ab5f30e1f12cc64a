// Files replaced whole: every output facet writes (packages, cache entries,
// reports, images, figures) goes to a temporary file beside its target and
// is renamed over it, so a reader sees the old file or the new one and a
// failed or killed run leaves no half-written file behind.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "facet/result.h"

namespace facet::support {

// Calls `write_temporary` with the path of a new, empty file beside the
// target, "<target>.tmp.<pid>.<random><extension>", then renames that file
// over `target`. The name ends in the target's extension (image writers pick
// the format by it) and is created exclusively, so concurrent writers of one
// target never share a temporary.
// On any failure the temporary is removed and the error is a reason without
// the target's name, for the caller to place.
// What becomes of a target that exists and is no regular file.
enum class SpecialTarget {
  // A user's output: never replaced. A character device (`-o /dev/null`) or
  // a FIFO that a process reads is given to `write_temporary` itself and
  // written in place; a FIFO nobody reads, a folder, a socket or a block
  // device is an error.
  write_in_place,
  // A file of facet's own (a cache entry): whatever stands in its place is
  // replaced, as a regular file would be (a folder still fails).
  replace,
};
Result<void, std::string> replace_file_atomically(
    const std::string& target,
    const std::function<Result<void, std::string>(const std::string& temporary)>& write_temporary,
    SpecialTarget special = SpecialTarget::write_in_place);

// `bytes` as the whole content of `target`, through replace_file_atomically.
Result<void, std::string> write_file_atomically(const std::string& target, std::string_view bytes,
                                                SpecialTarget special = SpecialTarget::write_in_place);

}  // namespace facet::support
