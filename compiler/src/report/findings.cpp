// Which keywords are dead, misspelt or free to drop from a stage, and what
// changing a keyword set would save.
#include "findings.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>

#include "facet/support/suggest.h"

namespace facet::report {
namespace {

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

// Identifiers of `#if/#ifdef/#ifndef/#elif` lines, and names `#define`d.
struct Directives {
  std::set<std::string> tested, defined;
};

void scan_directives(std::string_view text, Directives& out) {
  size_t pos = 0;
  while (pos < text.size()) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    size_t hash = line.find_first_not_of(" \t");
    if (hash == std::string_view::npos || line[hash] != '#') continue;
    line.remove_prefix(hash + 1);
    line.remove_prefix(std::min(line.size(), line.find_first_not_of(" \t")));
    bool conditional = line.starts_with("if") || line.starts_with("elif");
    bool define = line.starts_with("define");
    if (!conditional && !define) continue;
    size_t i = conditional ? (line.starts_with("ifndef") ? 6 : line.starts_with("ifdef") ? 5 : 2) : 6;
    for (; i < line.size(); ++i) {
      if (line.substr(i).starts_with("//")) break;
      if (!ident_start(line[i]) || (i > 0 && ident_char(line[i - 1]))) continue;
      size_t j = i;
      while (j < line.size() && ident_char(line[j])) ++j;
      std::string word(line.substr(i, j - i));
      if (define) {
        out.defined.insert(word);
        break;  // only the macro's name
      }
      if (word != "defined") out.tested.insert(word);
      i = j;
    }
  }
}

// Names the compiler, the stdlib or the stage defines, which a shader tests
// without declaring.
bool builtin_name(const std::string& name) {
  for (std::string_view prefix : {"UNITY_", "SHADER_", "FACET_", "__"}) {
    if (name.starts_with(prefix)) return true;
  }
  return name == "VERTEX" || name == "FRAGMENT";
}

bool keyword_like(const std::string& name) {
  bool letter = false;
  for (char c : name) {
    if (c >= 'a' && c <= 'z') return false;
    letter |= c >= 'A' && c <= 'Z';
  }
  return letter;
}

std::vector<std::string> declared_keywords(const variants::KeywordSpace& space) {
  std::vector<std::string> out;
  for (const variants::KeywordSet& set : space.sets) {
    for (const std::string& k : set.keywords) {
      if (!k.empty()) out.push_back(k);
    }
  }
  return out;
}

// The state a set falls back to when `keyword` is off: "" when it has one,
// else its first other entry.
std::string off_state(const variants::KeywordSet& set, const std::string& keyword) {
  for (const std::string& k : set.keywords) {
    if (k.empty()) return k;
  }
  for (const std::string& k : set.keywords) {
    if (k != keyword) return k;
  }
  return keyword;
}

std::vector<std::string> replaced(std::vector<std::string> keywords, const std::string& from, const std::string& to) {
  std::vector<std::string> out;
  for (std::string& k : keywords) {
    if (k != from) out.push_back(std::move(k));
    else if (!to.empty()) out.push_back(to);
  }
  return out;
}

// The token hash of each program of one pass and stage, by its keywords
// sorted, so that a program's counterpart is found without a scan.
using ProgramHashes = std::map<std::vector<std::string>, uint64_t>;

ProgramHashes program_hashes(const std::vector<ProgramRecord>& records, uint32_t pass, Stage stage) {
  ProgramHashes out;
  for (const ProgramRecord& r : records) {
    if (r.pass != pass || r.stage != stage) continue;
    std::vector<std::string> sorted = r.keywords;
    std::sort(sorted.begin(), sorted.end());
    out.emplace(std::move(sorted), r.token_hash);
  }
  return out;
}

// Free in a stage: every program with the keyword has the same tokens as the
// same program with the keyword's set in its off state. nullopt: no pair seen.
std::optional<bool> free_in_stage(const variants::KeywordSet& set, const std::string& keyword,
                                  const ProgramHashes& programs) {
  std::string off = off_state(set, keyword);
  std::optional<bool> all_equal;
  for (const auto& [keywords, hash] : programs) {
    if (!std::binary_search(keywords.begin(), keywords.end(), keyword)) continue;
    std::vector<std::string> other = replaced(keywords, keyword, off);
    std::sort(other.begin(), other.end());
    auto counterpart = programs.find(other);
    if (counterpart == programs.end()) continue;
    if (hash == 0 || counterpart->second == 0 || hash != counterpart->second) return false;
    all_equal = true;
  }
  return all_equal;
}

}  // namespace

std::vector<Finding> keyword_findings(const ir::Shader& shader, const SelectedPass& pass,
                                      const CompiledShader& compiled, const SourceMap& sources, uint32_t pass_index) {
  (void)shader;
  const ir::Program& program = *pass.ir.program;
  Directives user, all;
  for (const ir::SourceChunk& chunk : program.includes) scan_directives(chunk.text, user);
  scan_directives(program.body.text, user);
  all = user;
  for (const std::string& dep : compiled.dependencies) {
    if (auto id = sources.find(dep)) scan_directives(sources.text(*id), all);
  }
  std::vector<std::string> declared = declared_keywords(pass.keywords);
  std::vector<Finding> out;
  for (const variants::KeywordSet& set : pass.keywords.sets) {
    if (set.keywords.size() < 2) continue;  // always on: it multiplies nothing
    bool has_off = std::find(set.keywords.begin(), set.keywords.end(), "") != set.keywords.end();
    for (size_t i = 0; i < set.keywords.size(); ++i) {
      const std::string& k = set.keywords[i];
      // The first entry of a set without "_" is its default state; testing
      // only the others (as with KeywordEnum's "None") is the normal way.
      if (k.empty() || (!has_off && i == 0) || all.tested.count(k)) continue;
      out.push_back({FindingKind::dead, k, "",
                     "no #if of the program or its includes tests it, so its variants compile the same programs "
                     "as the set's default state"});
    }
  }
  std::vector<std::string_view> candidates(declared.begin(), declared.end());
  for (const std::string& name : user.tested) {
    if (std::find(declared.begin(), declared.end(), name) != declared.end()) continue;
    if (all.defined.count(name) || builtin_name(name) || !keyword_like(name)) continue;
    std::string detail = "tested by an #if but declared by no keyword pragma (unless it comes from -D)";
    if (auto best = closest_name(name, candidates)) detail += fmt::format("; did you mean '{}'?", *best);
    out.push_back({FindingKind::undeclared, name, "", detail});
  }
  std::vector<ProgramHashes> programs(kStageCount);
  for (int s = 0; s < kStageCount; ++s) {
    if (program.has_stage(Stage(s))) programs[s] = program_hashes(compiled.programs, pass_index, Stage(s));
  }
  for (const variants::KeywordSet& set : pass.keywords.sets) {
    for (int s = 0; s < kStageCount; ++s) {
      Stage stage = Stage(s);
      if (!program.has_stage(stage) || !set.applies_to(stage)) continue;
      for (const std::string& k : set.keywords) {
        if (k.empty() || !all.tested.count(k)) continue;
        if (free_in_stage(set, k, programs[s]) == true) {
          out.push_back({FindingKind::free_in_stage, k, std::string(stage_name(stage)),
                         fmt::format("changes no token the {} entry point reaches, so its {} programs are "
                                     "shared (stage relevance); a stage suffix would only make that explicit",
                                     stage_name(stage), stage_name(stage))});
        }
      }
    }
  }
  return out;
}

namespace {

// Whether a program has set `set` in its default state: no keyword of it
// when it has a "_" entry, else its first entry; a stage the set does not
// apply to is always in it.
bool at_default(const variants::KeywordSet& set, const ProgramRecord& r) {
  if (!set.applies_to(r.stage)) return true;
  std::string chosen;
  for (const std::string& k : r.keywords) {
    if (std::find(set.keywords.begin(), set.keywords.end(), k) != set.keywords.end()) chosen = k;
  }
  bool has_off = std::find(set.keywords.begin(), set.keywords.end(), "") != set.keywords.end();
  return has_off ? chosen.empty() : chosen == set.keywords.front();
}

// Programs and distinct compiles left if `set` always took its default state.
std::pair<uint64_t, uint64_t> without_set(const variants::KeywordSet& set, const std::vector<ProgramRecord>& records,
                                          uint32_t pass, const std::set<Stage>& stages) {
  std::set<std::pair<int, std::vector<std::string>>> programs;
  std::set<std::pair<int, uint64_t>> compiles;
  for (const ProgramRecord& r : records) {
    if (r.pass != pass || !stages.count(r.stage)) continue;
    std::vector<std::string> rest;
    for (const std::string& k : r.keywords) {
      if (std::find(set.keywords.begin(), set.keywords.end(), k) == set.keywords.end()) rest.push_back(k);
    }
    programs.insert({int(r.stage), rest});
    if (at_default(set, r)) compiles.insert({int(r.stage), r.token_hash});
  }
  return {programs.size(), compiles.size()};
}

// The space's programs (variants each stage needs, summed) over `stages`.
BigCount programs_in(const variants::KeywordSpace& space, const std::set<Stage>& stages,
                     const ReportOptions& options) {
  BigCount n = 0;
  for (Stage s : stages) n += variants::count_variants(space, {.stage = s, .materials = options.materials}).reachable;
  return n;
}

// Stage programs fewer if the multi_compile set `set` were a shader_feature
// (only materials' combinations built).
BigCount shader_feature_saving(const variants::KeywordSpace& space, const variants::KeywordSet& set,
                               const std::set<Stage>& stages, const ReportOptions& options) {
  variants::KeywordSpace modified = space;
  for (variants::KeywordSet& m : modified.sets) {
    if (m.span == set.span && m.keywords == set.keywords) m.directive = variants::KeywordDirective::shader_feature;
  }
  return programs_in(space, stages, options) - programs_in(modified, stages, options);
}

// `space` with `set` held in its default state, as if it were removed: its
// other keywords become skip_variants, which keeps the set's index (and the
// curated combinations that name it) intact.
variants::KeywordSpace without_set_space(variants::KeywordSpace space, const variants::KeywordSet& set) {
  bool has_off = std::find(set.keywords.begin(), set.keywords.end(), "") != set.keywords.end();
  for (size_t i = 0; i < set.keywords.size(); ++i) {
    if (set.keywords[i].empty() || (!has_off && i == 0)) continue;
    space.skip_variants.push_back(set.keywords[i]);
  }
  return space;
}

}  // namespace

std::string set_spelling(const variants::KeywordSet& set) {
  std::string words;
  for (const std::string& k : set.keywords) words += " " + (k.empty() ? std::string("_") : k);
  return set.pragma + words;
}

std::vector<WhatIf> what_ifs(const SelectedPass& pass, const std::vector<ProgramRecord>& records, uint32_t pass_index,
                             double compile_seconds, const ReportOptions& options) {
  std::set<Stage> all_stages, other_than_fragment;
  uint64_t compiled = 0;
  std::set<std::pair<int, uint64_t>> compiles;
  for (const ProgramRecord& r : records) {
    if (r.pass != pass_index) continue;
    all_stages.insert(r.stage);
    if (r.stage != Stage::fragment) other_than_fragment.insert(r.stage);
    compiled += r.compiled;
    compiles.insert({int(r.stage), r.token_hash});
  }
  const double mean = compiled ? compile_seconds / double(compiled) : 0;
  auto count_in = [&](const std::set<Stage>& stages) {
    std::pair<uint64_t, uint64_t> n{0, 0};
    std::set<std::pair<int, uint64_t>> c;
    for (const ProgramRecord& r : records) {
      if (r.pass != pass_index || !stages.count(r.stage)) continue;
      ++n.first;
      c.insert({int(r.stage), r.token_hash});
    }
    n.second = c.size();
    return n;
  };
  std::vector<WhatIf> out;
  for (const variants::KeywordSet& set : pass.keywords.sets) {
    if (set.keywords.size() < 2) continue;  // one state: it multiplies nothing
    auto [programs, unique] = count_in(all_stages);
    auto [left, left_compiles] = without_set(set, records, pass_index, all_stages);
    out.push_back({fmt::format("remove '{}'", set_spelling(set)), BigCount(programs - left),
                   double(unique - std::min(unique, left_compiles)) * mean});
    bool beyond_fragment = std::any_of(other_than_fragment.begin(), other_than_fragment.end(),
                                       [&](Stage s) { return set.applies_to(s); });
    if (beyond_fragment && set.applies_to(Stage::fragment)) {
      auto [p_other, u_other] = count_in(other_than_fragment);
      auto [l_other, lc_other] = without_set(set, records, pass_index, other_than_fragment);
      WhatIf w{fmt::format("make '{}' fragment-only (_fragment)", set_spelling(set)), BigCount(p_other - l_other),
               double(u_other - std::min(u_other, lc_other)) * mean};
      if (w.seconds_saved == 0 && !w.programs_saved.is_zero()) w.change += " [stage relevance already shares these programs]";
      out.push_back(std::move(w));
    }
    if (set.directive == variants::KeywordDirective::multi_compile && options.materials) {
      BigCount saved = shader_feature_saving(pass.keywords, set, all_stages, options);
      double ratio = programs ? double(compiles.size()) / double(programs) : 0;
      out.push_back({fmt::format("make '{}' shader_feature", set_spelling(set)), saved,
                     saved.to_double() * ratio * mean});
    }
  }
  return out;
}

std::vector<WhatIf> counted_what_ifs(const SelectedPass& pass, const ReportOptions& options,
                                     double seconds_per_program) {
  std::set<Stage> all_stages, other_than_fragment;
  for (int s = 0; s < kStageCount; ++s) {
    if (!pass.ir.program->has_stage(Stage(s))) continue;
    all_stages.insert(Stage(s));
    if (Stage(s) != Stage::fragment) other_than_fragment.insert(Stage(s));
  }
  auto what_if = [&](std::string change, BigCount saved) {
    double seconds = saved.to_double() * seconds_per_program;
    return WhatIf{std::move(change), std::move(saved), seconds};
  };
  const variants::KeywordSpace& space = pass.keywords;
  BigCount programs = programs_in(space, all_stages, options);
  std::vector<WhatIf> out;
  for (const variants::KeywordSet& set : space.sets) {
    if (set.keywords.size() < 2) continue;  // one state: it multiplies nothing
    out.push_back(what_if(fmt::format("remove '{}'", set_spelling(set)),
                          programs - programs_in(without_set_space(space, set), all_stages, options)));
    bool beyond_fragment = std::any_of(other_than_fragment.begin(), other_than_fragment.end(),
                                       [&](Stage s) { return set.applies_to(s); });
    if (beyond_fragment && set.applies_to(Stage::fragment)) {
      variants::KeywordSpace fragment_only = space;
      for (variants::KeywordSet& m : fragment_only.sets) {
        if (m.span == set.span && m.keywords == set.keywords) m.stages = stage_bit(Stage::fragment);
      }
      out.push_back(what_if(fmt::format("make '{}' fragment-only (_fragment)", set_spelling(set)),
                            programs_in(space, other_than_fragment, options) -
                                programs_in(fragment_only, other_than_fragment, options)));
    }
    if (set.directive == variants::KeywordDirective::multi_compile && options.materials) {
      out.push_back(what_if(fmt::format("make '{}' shader_feature", set_spelling(set)),
                            shader_feature_saving(space, set, all_stages, options)));
    }
  }
  return out;
}

}  // namespace facet::report
