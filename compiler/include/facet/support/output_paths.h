// Whether two paths of a run name one file: an output that is an input, or
// two outputs of one run (`-o x -MF x`, `-o x.png --depfile x.png`), would
// have one write replace the other's bytes.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace facet::support {

// By identity (device and inode) when both exist, so that another spelling
// or a hard link counts; by the absolute, normalised path with symbolic
// links resolved otherwise (an output not written yet). A file that exists
// and is not a regular file (`/dev/null`) is written in place, so naming it
// twice is no clash.
bool same_file(const std::string& a, const std::string& b);

// The first two of `outputs` that name one file; empty names and "-"
// (standard output) are no file.
std::optional<std::pair<std::string, std::string>> repeated_output(const std::vector<std::string>& outputs);

}  // namespace facet::support
