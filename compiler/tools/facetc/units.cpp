// -E, -S/--emit and --reflect over the selected passes, variants and stages.
#include "units.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "facet/reflection_json.h"

namespace facet::tools {
namespace {

struct Unit {
  const SelectedPass* pass = nullptr;
  Stage stage = Stage::vertex;
  std::vector<std::string> keywords;  // the keywords the stage sees
  std::string label;                  // "pass 'FORWARD' (#0), fragment stage, keywords {FOG_LINEAR}"
};

std::string describe_pass(const SelectedPass& pass) {
  std::string name = pass.ir.name.empty() ? "" : fmt::format(" '{}'", pass.ir.name);
  std::string light_mode = pass.ir.tag("LightMode");
  return fmt::format("pass #{}{}{}", pass.pass, name, light_mode.empty() ? "" : " (" + light_mode + ")");
}

std::vector<Stage> stages_of(const ir::Program& program, std::optional<Stage> only) {
  if (only) return {*only};
  std::vector<Stage> stages;
  for (int s = 0; s < kStageCount; ++s) {
    if (program.has_stage(Stage(s))) stages.push_back(Stage(s));
  }
  return stages;
}

Result<std::vector<Unit>> collect_units(const FacetcArgs& args, const Compiler& compiler, const ir::Shader& shader,
                                        const std::vector<SelectedPass>& passes, Diagnostics& diags) {
  CompileOptions options = compile_options(args, true);
  std::vector<Unit> units;
  bool failed = false;
  for (const SelectedPass& pass : passes) {
    auto set = compiler.select_variants(pass, options, diags);
    if (!set) {
      failed = true;
      continue;
    }
    for (const variants::VariantKey& key : set->keys) {
      for (Stage stage : stages_of(*pass.ir.program, args.stage)) {
        auto keywords = variants::stage_keywords(pass.keywords, key, stage);
        std::string label = fmt::format("{}, {} stage, keywords {{{}}}", describe_pass(pass), stage_name(stage),
                                        keywords.empty() ? "none" : fmt::format("{}", fmt::join(keywords, " ")));
        units.push_back({&pass, stage, std::move(keywords), std::move(label)});
      }
    }
  }
  (void)shader;
  if (failed) return failure("variant selection failed");
  return units;
}

// The text of one unit, or nullopt with diagnostics.
std::optional<std::string> unit_text(const FacetcArgs& args, const backend::Backend& backend, const ir::Shader& shader,
                                     const Unit& unit, SourceMap& sources, Diagnostics& diags) {
  const ir::Program& program = *unit.pass->ir.program;
  const backend::BackendOptions& options = args.backend;
  if (args.mode == Mode::preprocess || (args.mode == Mode::emit && args.emit == EmitKind::source)) {
    bool preprocess = args.mode == Mode::preprocess;
    auto source = backend.source_text(shader, program,
                                      {.stage = unit.stage, .keywords = unit.keywords, .preprocess = preprocess},
                                      options, sources, diags);
    return source ? std::optional(std::move(source->text)) : std::nullopt;
  }
  auto compiled = backend.compile(shader, program, unit.stage, unit.keywords, options, sources, diags);
  if (!compiled) return std::nullopt;
  if (args.mode == Mode::reflect) return reflection_to_json_text(compiled->reflection, -1);
  switch (args.emit) {
    case EmitKind::source:  // handled above
    case EmitKind::spirv_asm:
      return backend::disassemble(compiled->spirv);
    case EmitKind::spirv:
      return std::string(reinterpret_cast<const char*>(compiled->spirv.data()), compiled->spirv.size() * 4);
    case EmitKind::glsl:
    case EmitKind::essl:
    case EmitKind::msl: {
      backend::CrossTarget target = args.emit == EmitKind::glsl   ? backend::CrossTarget::glsl450
                                    : args.emit == EmitKind::essl ? backend::CrossTarget::essl300
                                                                  : backend::CrossTarget::msl;
      auto text = backend::cross_compile(compiled->spirv, unit.stage, target, diags);
      return text ? std::optional(*text) : std::nullopt;
    }
  }
  return std::nullopt;
}

std::string reflection_document(const std::vector<Unit>& units, const std::vector<std::string>& texts) {
  nlohmann::json doc = nlohmann::json::array();
  for (size_t i = 0; i < units.size(); ++i) {
    const Unit& u = units[i];
    doc.push_back({{"pass", u.pass->ir.name}, {"pass_index", u.pass->pass}, {"stage", stage_name(u.stage)},
                   {"keywords", u.keywords}, {"reflection", nlohmann::json::parse(texts[i])}});
  }
  return doc.dump(2) + "\n";
}

std::string text_document(const FacetcArgs& args, const std::vector<Unit>& units,
                          const std::vector<std::string>& texts) {
  if (units.size() == 1) return texts[0];
  const char* comment = args.mode == Mode::emit && args.emit == EmitKind::spirv_asm ? ";" : "//";
  std::string out;
  for (size_t i = 0; i < units.size(); ++i) {
    out += fmt::format("{}{} facetc: {}\n", i == 0 ? "" : "\n", comment, units[i].label);
    out += texts[i];
    if (!out.empty() && out.back() != '\n') out += '\n';
  }
  return out;
}

}  // namespace

CompileOptions compile_options(const FacetcArgs& args, bool one_variant_by_default) {
  CompileOptions options{.backend = args.backend, .passes = args.passes, .strict_selection = args.strict_variants,
                         .max_variants_per_pass = args.max_variants, .build_unreachable = args.build_unreachable,
                         .jobs = args.jobs, .cache_dir = args.cache_dir,
                         .cache_url = args.cache_url};
  options.shard_index = args.shard_index;
  options.shard_count = args.shard_count;
  if (args.keywords) {
    options.keywords = *args.keywords;
  } else if (one_variant_by_default && !args.all_variants) {
    options.keywords = std::vector<std::string>{};
  }
  return options;
}

Result<UnitsOutput> produce_units(const FacetcArgs& args, const Compiler& compiler, const ir::Shader& shader,
                                  SourceMap& sources, Diagnostics& diags) {
  auto passes = compiler.select_passes(shader, compile_options(args, true), diags);
  FACET_TRY(passes);
  auto units = collect_units(args, compiler, shader, *passes, diags);
  FACET_TRY(units);
  UnitsOutput out;
  if (args.mode == Mode::emit && args.emit == EmitKind::spirv && units->size() != 1) {
    diags.add(DiagId::driver_bad_option, {},
              fmt::format("--emit=spirv writes one module, but {} pass/stage/variant combinations match; narrow "
                          "them with --pass, --stage and --keywords",
                          units->size()));
    out.usage_error = true;
    return out;
  }
  std::vector<Diagnostics> per_unit;
  std::vector<std::string> texts;
  bool failed = false;
  const backend::Backend backend;  // one stage of one variant at a time, outside a build
  for (const Unit& unit : *units) {
    Diagnostics unit_diags;
    std::optional<std::string> text = unit_text(args, backend, shader, unit, sources, unit_diags);
    for (Diagnostic& d : unit_diags.mutable_all()) {
      if (d.severity != Severity::note) d.note({}, "while compiling " + unit.label);
    }
    per_unit.push_back(std::move(unit_diags));
    if (!text) {
      failed = true;
      continue;
    }
    texts.push_back(std::move(*text));
  }
  diags.append(merge_variant_duplicates(per_unit));
  if (failed) return failure("compile errors");
  if (units->empty()) return out;
  out.bytes = args.mode == Mode::reflect ? reflection_document(*units, texts) : text_document(args, *units, texts);
  return out;
}

}  // namespace facet::tools
