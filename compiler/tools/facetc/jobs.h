// Scale-out: facetc --emit-jobs writes one build-farm job per distinct stage
// program (facetc --program ... into a shared cache, with an exact depfile)
// and a last job that assembles the package from the cache; facetc
// --program runs one such job.
#pragma once

#include <string>

#include "args.h"
#include "facet/build_farm.h"
#include "facet/compiler.h"

namespace facet::tools {

// The ninja file or JSON for `shader` (read from `input`).
Result<std::string> emit_jobs(const FacetcArgs& args, const Compiler& compiler, const ir::Shader& shader,
                              const std::string& input, const std::string& facetc_path, SourceMap& sources,
                              Diagnostics& diags);

// "PASS:STAGE:KW1,KW2" -> a job; nullopt when malformed.
std::optional<ProgramJob> parse_program_job(const std::string& spec);
std::string program_job_spec(const ProgramJob& job);

}  // namespace facet::tools
