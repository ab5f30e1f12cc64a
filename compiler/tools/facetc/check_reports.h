// The reports of facetc --check for CI systems: JUnit XML (one test case per
// shader) and SARIF 2.1.0 (one result per diagnostic, for code scanning).
#pragma once

#include <string>
#include <vector>

#include "check_mode.h"

namespace facet::tools {

// One <testsuite name="facetc --check"> inside <testsuites>; a <testcase> per
// shader (classname: its folder, name: its file name, time in seconds) with a
// <failure> (the first error as message, every diagnostic as text) when it
// fails, and its warnings as <system-out> when it compiles with some.
// `timestamp` is ISO 8601 without a zone, as the Jenkins schema has it.
std::string junit_xml(const std::vector<ShaderCheck>& checks, double seconds, const std::string& timestamp);

// One run of tool "facetc" with a rule per diagnostic id that occurs and a
// result per diagnostic, errors, warnings and notes alike. Files under
// `base_dir` (absolute) are URIs relative to uriBaseId SRCROOT, which
// originalUriBaseIds sets to `base_dir`; others are file:// URIs.
std::string sarif_json(const std::vector<ShaderCheck>& checks, const std::string& base_dir);

}  // namespace facet::tools
