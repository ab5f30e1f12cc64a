// The calls a build farm or a planning tool makes, apart from the compile
// itself (facet/compiler.h): the distinct stage programs of a build as
// jobs, one job compiled into the shared cache, and a build's cost measured
// on a sample before it runs.
//
//   auto jobs = facet::program_jobs(compiler, shader, options, sources, diags);
//   for (const facet::ProgramJob& job : *jobs)   // on any machine sharing the cache
//     facet::compile_program(compiler, shader, options, job, sources, diags);
//   auto package = compiler.compile(shader, options, sources, diags);  // all cache hits
#pragma once

#include <string>
#include <vector>

#include "facet/compiler.h"

namespace facet {

// One distinct stage program of a build: a pass (its index in the
// SubShader), a stage and the keywords that stage sees.
struct ProgramJob {
  size_t pass = 0;
  Stage stage = Stage::vertex;
  std::vector<std::string> keywords;
};

// The distinct stage programs compile(shader, options) would compile, in
// plan order: one build-farm job each (facetc --emit-jobs).
Result<std::vector<ProgramJob>> program_jobs(const Compiler& compiler, const ir::Shader& shader,
                                             const CompileOptions& options, SourceMap& sources, Diagnostics& diags);

// Compiles the one program `job` names into the cache of `options`
// (cache_dir and/or cache_url must be set), for a farm worker. Returns
// whether it was compiled (false: it was already in the cache).
Result<bool> compile_program(const Compiler& compiler, const ir::Shader& shader, const CompileOptions& options,
                             const ProgramJob& job, SourceMap& sources, Diagnostics& diags);

// The cost of compile(shader, options) without compiling it all: see
// BuildEstimate. The cache is not used, so the estimate is of a cold build.
Result<BuildEstimate> estimate_build(const Compiler& compiler, const ir::Shader& shader, const CompileOptions& options,
                                     SourceMap& sources, Diagnostics& diags, size_t sample = kEstimateSample);

}  // namespace facet
