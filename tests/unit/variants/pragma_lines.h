// Keyword spaces from pragma lines ("multi_compile _ A"), shared by the
// variants tests. Each pragma's span is its line's byte range in file 0.
#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "facet/variants.h"

namespace facet::variants::pragma_lines {

using Lines = std::vector<std::string>;

inline ir::Program program_of(const Lines& lines) {
  ir::Program program;
  uint32_t offset = 0;
  for (const std::string& line : lines) {
    std::istringstream words{line};
    ir::Pragma pragma;
    words >> pragma.name;
    for (std::string arg; words >> arg;) pragma.args.push_back(arg);
    pragma.span = SourceSpan{0, offset, offset + uint32_t(line.size())};
    offset += uint32_t(line.size()) + 1;
    program.pragmas.push_back(std::move(pragma));
  }
  return program;
}

// The space of `lines`, which must build without errors.
inline KeywordSpace space_of(const Lines& lines) {
  Diagnostics diags;
  auto space = build_keyword_space(program_of(lines), diags);
  EXPECT_TRUE(space.has_value()) << (diags.size() ? diags.all()[0].message : "");
  return space ? *space : KeywordSpace{};
}

}  // namespace facet::variants::pragma_lines
