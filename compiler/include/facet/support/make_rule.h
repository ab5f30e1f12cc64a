// Make-style dependency rules: what facetc -M / -MD and facet render
// --depfile write, and what Ninja and Make read as depfiles.
#pragma once

#include <string>
#include <vector>

namespace facet {

// "target: dep1 dep2 ...", one dependency a line, with spaces, '#' and '$'
// escaped as Make reads them.
std::string make_rule(const std::string& target, const std::vector<std::string>& deps);

}  // namespace facet
