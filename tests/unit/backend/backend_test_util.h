// Helpers for the back-end tests: build ir::Shader/ir::Program by hand from a
// small .shader text, as sema would, without the parser.
#pragma once

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "facet/backend.h"

namespace facet::backend::testing {

// A .shader with one program block, loaded into a SourceMap.
struct TestShader {
  SourceMap sources;
  ir::Shader shader;
  ir::Program program;
};

inline std::string read_test_file(const std::string& name) {
  std::ifstream in(std::string(FACET_TESTDATA_DIR) + "/backend/" + name, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

inline uint32_t line_of(const std::string& text, size_t offset) {
  return 1 + uint32_t(std::count(text.begin(), text.begin() + std::min(offset, text.size()), '\n'));
}

// The chunk between the line holding `begin_marker` and `end_marker`.
inline ir::SourceChunk chunk_between(const std::string& text, FileId file, size_t marker, const std::string& end_marker) {
  size_t begin = text.find('\n', marker) + 1;
  size_t end = text.find(end_marker, begin);
  ir::SourceChunk chunk;
  chunk.text = text.substr(begin, end - begin);
  chunk.span = {file, uint32_t(begin), uint32_t(end)};
  chunk.first_line = line_of(text, begin);
  return chunk;
}

// Reads "#pragma name args" lines of a chunk (what sema records).
inline void read_pragmas(const ir::SourceChunk& chunk, ir::Program& program) {
  std::istringstream lines(chunk.text);
  std::string line;
  uint32_t offset = chunk.span.begin;
  while (std::getline(lines, line)) {
    size_t at = line.find("#pragma");
    if (at != std::string::npos) {
      std::istringstream words(line.substr(at + 7));
      ir::Pragma pragma;
      words >> pragma.name;
      for (std::string arg; words >> arg;) pragma.args.push_back(arg);
      pragma.span = {chunk.span.file, offset + uint32_t(at), offset + uint32_t(line.size())};
      if (auto stage = parse_stage(pragma.name); stage && !pragma.args.empty()) {
        program.entry_points[size_t(*stage)] = pragma.args[0];
      }
      if (pragma.name == "target" && !pragma.args.empty()) {
        program.shader_target = int(std::stod(pragma.args[0]) * 10 + 0.5);
      }
      program.pragmas.push_back(std::move(pragma));
    }
    offset += uint32_t(line.size()) + 1;
  }
}

// `path` names the shader (its folder is searched for includes); `text` is a
// whole .shader with CGINCLUDE/HLSLINCLUDE blocks and one
// CGPROGRAM/HLSLPROGRAM/GLSLPROGRAM block.
inline TestShader make_shader(const std::string& path, const std::string& text) {
  TestShader t;
  FileId file = t.sources.add_file(path, text);
  t.shader.file = file;
  t.shader.name = "Test/" + path;
  for (size_t at = text.find("CGINCLUDE"); at != std::string::npos; at = text.find("CGINCLUDE", at + 1)) {
    t.program.includes.push_back(chunk_between(text, file, at, "ENDCG"));
  }
  struct Block { const char* begin; const char* end; ir::ProgramLanguage language; };
  for (Block b : {Block{"CGPROGRAM", "ENDCG", ir::ProgramLanguage::cg},
                  Block{"HLSLPROGRAM", "ENDHLSL", ir::ProgramLanguage::hlsl},
                  Block{"GLSLPROGRAM", "ENDGLSL", ir::ProgramLanguage::glsl}}) {
    size_t at = text.find(b.begin);
    if (at == std::string::npos) continue;
    t.program.language = b.language;
    t.program.body = chunk_between(text, file, at, b.end);
  }
  for (const ir::SourceChunk& c : t.program.includes) read_pragmas(c, t.program);
  read_pragmas(t.program.body, t.program);
  if (t.program.language == ir::ProgramLanguage::glsl) {
    if (text.find("#ifdef VERTEX") != std::string::npos) t.program.entry_points[size_t(Stage::vertex)] = "main";
    if (text.find("#ifdef FRAGMENT") != std::string::npos) t.program.entry_points[size_t(Stage::fragment)] = "main";
  }
  return t;
}

// A data file of tests/data/backend, with its real path (so that includes
// next to it resolve).
inline TestShader load_shader(const std::string& name) {
  return make_shader(std::string(FACET_TESTDATA_DIR) + "/backend/" + name, read_test_file(name));
}

inline ir::Property property(const std::string& name, ir::PropertyType type) {
  ir::Property p;
  p.name = name;
  p.type = type;
  return p;
}

// "file:line:col: error: message" lines, without the source excerpts.
inline std::string headlines(const Diagnostics& diags, const SourceMap& sources) {
  RenderOptions options;
  options.show_source_line = false;
  return render_text(diags, sources, options);
}

}  // namespace facet::backend::testing
