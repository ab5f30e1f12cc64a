// analyze_program: glslang's AST of a parsed (not compiled) program, walked
// once for function signatures and struct-member reads and writes.
#include "facet/backend.h"
#include "crash_isolation.h"
#include "facet/support/text.h"

#include <glslang/Include/intermediate.h>
#include <memory>
#include <glslang/MachineIndependent/localintermediate.h>

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <cctype>
#include <set>

#include "argument_casts.h"
#include "glslang_frontend.h"
#include "includer.h"
#include "info_log.h"
#include "source_assembly.h"
#include "worker.h"

namespace facet::backend {
namespace {

std::string type_name(const glslang::TType& type) {
  if (type.isStruct()) return std::string(type.getTypeName().c_str());
  std::string base = glslang::TType::getBasicString(type.getBasicType());
  if (type.isMatrix()) return base + std::to_string(type.getMatrixRows()) + "x" + std::to_string(type.getMatrixCols());
  if (type.isVector()) return base + std::to_string(type.getVectorSize());
  return base;
}

std::string semantic_of(const glslang::TType& type) {
  const glslang::TQualifier& q = type.getQualifier();
  if (q.semanticName) return upper(q.semanticName);
  if (q.builtIn == glslang::EbvFace) return "VFACE";
  return "";
}

// Which members of the parameters of the function being walked are read and
// written. Writes are what the left side of an assignment, or an out
// argument of a call, reaches.
class Walker : public glslang::TIntermTraverser {
 public:
  explicit Walker(ProgramAnalysis& out) : out_(out) {}

  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunction) return begin_function(node);
    if (node->getOp() == glslang::EOpFunctionCall) return visit_call(node);
    return true;
  }

  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
    if (node->getOp() == glslang::EOpIndexDirectStruct) return visit_member(node);
    if (is_assignment(node->getOp())) {
      walk(node->getLeft(), true, node->getOp() != glslang::EOpAssign);
      walk(node->getRight(), false, true);
      return false;
    }
    return true;
  }

  bool visitUnary(glslang::TVisit, glslang::TIntermUnary* node) override {
    switch (node->getOp()) {
      case glslang::EOpPostIncrement: case glslang::EOpPostDecrement:
      case glslang::EOpPreIncrement: case glslang::EOpPreDecrement:
        walk(node->getOperand(), true, true);
        return false;
      default: return true;
    }
  }

  void visitSymbol(glslang::TIntermSymbol* symbol) override {
    AnalyzedParam* param = param_of(symbol);
    if (!param) return;
    if (writing_) param->whole_written = true;
    if (reading_) param->whole_read = true;
  }

 private:
  static bool is_assignment(glslang::TOperator op) {
    return op == glslang::EOpAssign || (op >= glslang::EOpAddAssign && op <= glslang::EOpRightShiftAssign);
  }

  void walk(TIntermNode* node, bool writing, bool reading) {
    bool w = writing_, r = reading_;
    writing_ = writing;
    reading_ = reading;
    node->traverse(this);
    writing_ = w;
    reading_ = r;
  }

  bool begin_function(glslang::TIntermAggregate* node) {
    std::string mangled = node->getName().c_str();
    AnalyzedFunction f;
    f.name = mangled.substr(0, mangled.find('('));
    f.return_type = type_name(node->getType());
    params_.clear();
    const glslang::TIntermSequence& seq = node->getSequence();
    if (!seq.empty() && seq[0]->getAsAggregate()) {
      for (TIntermNode* p : seq[0]->getAsAggregate()->getSequence()) {
        const glslang::TIntermSymbol* symbol = p->getAsSymbolNode();
        if (!symbol) continue;
        const glslang::TType& type = symbol->getType();
        AnalyzedParam param{.name = symbol->getName().c_str(), .type = type_name(type), .is_struct = type.isStruct()};
        glslang::TStorageQualifier storage = type.getQualifier().storage;
        param.is_out = storage == glslang::EvqOut || storage == glslang::EvqInOut;
        if (type.isStruct()) record_struct(type);
        f.params.push_back(std::move(param));
        params_.push_back(symbol->getId());
      }
    }
    out_.functions.push_back(std::move(f));
    current_ = &out_.functions.back();
    for (size_t i = 1; i < seq.size(); ++i) walk(seq[i], false, true);
    finish(*current_);
    current_ = nullptr;
    return false;
  }

  // Arguments to out/inout parameters of the callee are written (and, for
  // inout, read); a struct argument passed whole counts as every member.
  bool visit_call(glslang::TIntermAggregate* node) {
    const glslang::TQualifierList& qualifiers = node->getQualifierList();
    const glslang::TIntermSequence& args = node->getSequence();
    for (size_t i = 0; i < args.size(); ++i) {
      glslang::TStorageQualifier q = i < qualifiers.size() ? qualifiers[i] : glslang::EvqIn;
      bool out = q == glslang::EvqOut || q == glslang::EvqInOut;
      walk(args[i], out || writing_, q != glslang::EvqOut || reading_);
    }
    return false;
  }

  bool visit_member(glslang::TIntermBinary* node) {
    const glslang::TIntermSymbol* symbol = node->getLeft()->getAsSymbolNode();
    AnalyzedParam* param = symbol ? param_of(symbol) : nullptr;
    if (!param) return true;
    const glslang::TTypeList* fields = node->getLeft()->getType().getStruct();
    const glslang::TIntermConstantUnion* index = node->getRight()->getAsConstantUnion();
    if (!fields || !index) return true;
    int i = index->getConstArray()[0].getIConst();
    if (i < 0 || size_t(i) >= fields->size()) return false;
    std::string member = (*fields)[size_t(i)].type->getFieldName().c_str();
    if (writing_) param->members_written.push_back(member);
    if (reading_) param->members_read.push_back(member);
    return false;
  }

  AnalyzedParam* param_of(const glslang::TIntermSymbol* symbol) {
    if (!current_) return nullptr;
    for (size_t i = 0; i < params_.size(); ++i) {
      if (params_[i] == symbol->getId()) return &current_->params[i];
    }
    return nullptr;
  }

  void record_struct(const glslang::TType& type) {
    std::string name = type.getTypeName().c_str();
    if (out_.structs.count(name)) return;
    std::vector<AnalyzedField>& fields = out_.structs[name];
    for (const glslang::TTypeLoc& loc : *type.getStruct()) {
      fields.push_back({loc.type->getFieldName().c_str(), type_name(*loc.type), semantic_of(*loc.type)});
      if (loc.type->isStruct()) record_struct(*loc.type);
    }
  }

  static void finish(AnalyzedFunction& f) {
    for (AnalyzedParam& p : f.params) {
      for (auto* list : {&p.members_read, &p.members_written}) {
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
      }
    }
  }

  ProgramAnalysis& out_;
  AnalyzedFunction* current_ = nullptr;
  std::vector<long long> params_;  // symbol ids of the current function's parameters
  bool writing_ = false, reading_ = true;
};

}  // namespace

namespace {

// analyze_program, on the worker thread.
Result<ProgramAnalysis> analyze(const ir::Shader& shader, const ir::Program& program,
                                const std::vector<std::string>& keywords, const BackendOptions& options,
                                SourceMap& sources, Diagnostics& diags, const CrashIsolation* isolation,
                                const std::shared_ptr<IncludeScanCache>& scan_cache) {
  const FileId home = ir::program_file(shader, program);
  std::string path = home != kNoFile && home < sources.file_count() ? sources.path(home) : "";
  std::string stdlib = options.stdlib_dir.empty() ? default_stdlib_dir() : options.stdlib_dir;
  ProgramAnalysis analysis;
  auto parse = [&](const ir::Program& p, AssembledSource& source, FileIncluder& includer) {
    source = assemble_source(p, Stage::fragment, keywords, options, path);
    analysis = {};
    // Any entry point will do: nothing is linked, and the walk covers every function.
    return parse_glslang(source, p.language, Stage::fragment, "facet_analysis_entry", options, includer,
                         [&](const glslang::TIntermediate& intermediate) {
                           Walker walker(analysis);
                           if (TIntermNode* root = intermediate.getTreeRoot()) root->traverse(&walker);
                         },
                         isolation);
  };
  AssembledSource source;
  source = assemble_source(program, Stage::fragment, keywords, options, path);
  std::unique_ptr<FileIncluder> includer = checked_includer(program, source, options, stdlib, diags, scan_cache);
  if (!includer) return failure("input limit");
  GlslangOutput out = parse(program, source, *includer);
  // Calls fxc accepts by truncating a wider vector argument: analysed with
  // the arguments cast, as Backend::compile compiles them (and warns there).
  if (!out.ok && program.language != ir::ProgramLanguage::glsl) {
    ir::Program cast = program;
    if (!cast_rejected_calls(cast, source.root_name, parse_info_log(out.parse_log), includer->returned_texts()).empty()) {
      AssembledSource cast_source;
      Diagnostics refused;  // the program's text passed these checks before its casts
      std::unique_ptr<FileIncluder> cast_includer =
          checked_includer(cast, cast_source, options, stdlib, refused, scan_cache);
      if (!cast_includer) return failure("input limit");
      GlslangOutput cast_out = parse(cast, cast_source, *cast_includer);
      if (cast_out.ok) {
        source = std::move(cast_source);
        includer = std::move(cast_includer);
        out = std::move(cast_out);
      } else {
        parse(program, source, *includer);  // the analysis of the program as written
      }
    }
  }
  add_included_files(*includer, sources);
  LogContext context{program, Stage::fragment, home, source, *includer, sources, DiagId::hlsl_error};
  report_info_log(out.parse_log, context, diags);
  if (!out.ok) return failure("the program does not parse");
  return analysis;
}

}  // namespace

Result<ProgramAnalysis> Backend::analyze_program(const ir::Shader& shader, const ir::Program& program,
                                                 const std::vector<std::string>& keywords,
                                                 const BackendOptions& options, SourceMap& sources,
                                                 Diagnostics& diags) const {
  std::optional<Result<ProgramAnalysis>> result;
  std::string timeout = fmt::format("facet: error: analysing a program took longer than {} s (--time-limit)\n",
                                    options.limits.time_limit_s);
  run_on_worker(
      [&, scan_cache = scan_cache_] {
        result = analyze(shader, program, keywords, options, sources, diags, isolation_.get(), scan_cache);
      },
      options.limits.time_limit_s, [&] { return timeout; });
  return std::move(*result);
}

}  // namespace facet::backend
