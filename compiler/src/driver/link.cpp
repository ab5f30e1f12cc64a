#include "link.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "facet/support/text.h"

namespace facet {
namespace {

// Shaders a Fallback chain may pass through before facet stops following it.
constexpr size_t kMaxChain = 16;

bool is_shadow_caster(const ir::Pass& pass) {
  return pass.kind == ir::PassKind::normal && iequals(pass.tag("LightMode"), "ShadowCaster");
}

// A pass of `from` made part of another shader: its programs keep reading
// includes from, and pointing messages into, the file they were written in.
ir::Pass adopted(const ir::Shader& from, const ir::Pass& pass, std::string origin) {
  ir::Pass out = pass;
  if (out.program) out.program->home_file = ir::program_file(from, *out.program);
  out.origin = std::move(origin);  // how it came into this shader; its file says where it was written
  out.fallback_stand_in = false;
  return out;
}

class Linker {
 public:
  Linker(const std::vector<ShaderDir>& search, const LoadWrittenShader& load) : search_(search), load_(load) {}

  void link(ir::Shader& shader, Diagnostics& diags) {
    chain_.push_back(shader.name);
    for (ir::SubShader& sub : shader.subshaders) {
      for (ir::Pass& pass : sub.passes) {
        if (pass.kind == ir::PassKind::use_pass) take_use_pass(shader, pass, diags);
      }
    }
    if (shader.fallback) take_fallback(shader, diags);
    chain_.pop_back();
  }

 private:
  struct Found {
    const ir::Shader* shader = nullptr;  // null: `why` says what went wrong
    std::string why;
    std::optional<Diagnostic> first_error;
  };

  const ShaderIndex& index() {
    if (!index_) index_ = index_shaders(search_);
    return *index_;
  }

  std::string where_searched() const {
    std::string dirs;
    for (const ShaderDir& d : search_) dirs += fmt::format("{}{}{}", dirs.empty() ? "" : ", ", d.path, d.recursive ? "/**" : "");
    return dirs.empty() ? "no folder" : dirs;
  }

  // The named shader, loaded and linked, once per name.
  Found shader_named(const std::string& name) {
    for (const std::string& linking : chain_) {
      if (linking == name) return {.why = fmt::format("'{}' leads back to itself", name)};
    }
    if (chain_.size() >= kMaxChain) return {.why = fmt::format("more than {} shaders deep", kMaxChain)};
    if (auto it = loaded_.find(name); it != loaded_.end()) {
      if (it->second.linking) return {.why = fmt::format("'{}' leads back to itself", name)};
      return it->second.found();
    }
    std::optional<std::string> path = find_shader(index(), name);
    if (!path) return {.why = fmt::format("no shader named '{}' in the shader search path", name)};
    Diagnostics scratch;  // the other shader's own messages are not this build's
    Loaded& entry = loaded_[name];
    entry.path = *path;
    Result<ir::Shader> other = load_(*path, scratch);
    if (!other) {
      for (const Diagnostic& d : scratch.all()) {
        if (d.severity == Severity::error) {
          entry.first_error = d;
          break;
        }
      }
      return entry.found();
    }
    entry.linking = true;
    link(*other, scratch);
    entry.linking = false;
    if (other->subshaders.empty()) {
      entry.empty = true;  // nor did its own Fallback give it one
      return entry.found();
    }
    entry.shader = std::make_unique<ir::Shader>(std::move(*other));
    return entry.found();
  }

  void take_use_pass(const ir::Shader& shader, ir::Pass& use, Diagnostics& diags) {
    const size_t slash = use.use_pass.rfind('/');
    if (slash == std::string::npos) return;  // sema reported it
    const std::string name = use.use_pass.substr(0, slash);
    const std::string pass_name = upper(use.use_pass.substr(slash + 1));
    if (name == shader.name) return;  // a pass of this same shader: selection resolves it
    Found other = shader_named(name);
    if (!other.shader) {
      warn(diags, DiagId::driver_usepass_unresolved, use.span,
           fmt::format("UsePass '{}' is not resolved: {}; the pass is skipped", use.use_pass, other.why), other);
      return;
    }
    for (const ir::SubShader& sub : other.shader->subshaders) {
      for (const ir::Pass& p : sub.passes) {
        if (p.kind == ir::PassKind::normal && upper(p.name) == pass_name) {
          SourceSpan span = use.span;
          use = adopted(*other.shader, p, fmt::format("UsePass \"{}\"", use.use_pass));
          use.span = span;
          return;
        }
      }
    }
    warn(diags, DiagId::driver_usepass_unresolved, use.span,
         fmt::format("UsePass '{}' is not resolved: shader '{}' ({}) has no pass named '{}'; the pass is skipped",
                     use.use_pass, name, path_of(name), use.use_pass.substr(slash + 1)),
         other);
  }

  // A Fallback supplies a shader with a SubShader only its ShadowCaster, in
  // place of surface lowering's stand-in when there is one.
  void take_fallback(ir::Shader& shader, Diagnostics& diags) {
    const bool whole = shader.subshaders.empty();
    ir::Pass* stand_in = nullptr;
    if (!whole) {
      for (ir::Pass& p : shader.subshaders[0].passes) {
        if (!is_shadow_caster(p)) continue;
        if (!p.fallback_stand_in) return;  // its own caster
        stand_in = &p;
      }
    }
    const std::string& name = *shader.fallback;
    Found other = shader_named(name);
    if (!other.shader) {
      if (stand_in) return;  // the stand-in casts the shadow
      warn(diags, DiagId::driver_fallback_unresolved, shader.fallback_span,
           fmt::format("Fallback '{}' is not used: {}; the shader {}", name, other.why,
                       whole ? "has nothing to draw" : "casts no shadow"),
           other);
      return;
    }
    const ir::SubShader& theirs = other.shader->subshaders[0];
    const std::string origin = fmt::format("Fallback \"{}\"", name);
    if (whole) {
      ir::SubShader sub = theirs;
      for (ir::Pass& p : sub.passes) p = adopted(*other.shader, p, origin);
      shader.subshaders.push_back(std::move(sub));
      diags.add(DiagId::driver_fallback_only, shader.fallback_span,
                fmt::format("shader '{}' has no SubShader; it is drawn with its Fallback '{}' ({})", shader.name, name,
                            path_of(name)));
      return;
    }
    for (const ir::Pass& p : theirs.passes) {
      if (!is_shadow_caster(p)) continue;
      if (stand_in) {
        SourceSpan span = stand_in->span;
        *stand_in = adopted(*other.shader, p, origin);
        stand_in->span = span;
      } else {
        shader.subshaders[0].passes.push_back(adopted(*other.shader, p, origin));
      }
      return;
    }
  }

  void warn(Diagnostics& diags, DiagId id, SourceSpan span, std::string message, const Found& found) {
    Diagnostic& d = diags.add(id, span, std::move(message));
    if (found.first_error) d.note(found.first_error->span, found.first_error->message);
    if (found.why.rfind("no shader named", 0) == 0) d.note({}, "searched: " + where_searched());
  }

  std::string path_of(const std::string& name) const {
    auto it = loaded_.find(name);
    return it == loaded_.end() ? std::string() : it->second.path;
  }

  struct Loaded {
    std::string path;
    std::unique_ptr<ir::Shader> shader;  // null when it did not load
    std::optional<Diagnostic> first_error;
    bool linking = false;  // its own UsePass and Fallback are being followed
    bool empty = false;    // it loaded, with no SubShader to take from
    Found found() const {
      if (shader) return {.shader = shader.get()};
      if (empty) return {.why = fmt::format("'{}' has no SubShader, of its own or from its Fallback", path)};
      return {.why = fmt::format("'{}' does not compile", path), .first_error = first_error};
    }
  };

  const std::vector<ShaderDir>& search_;
  const LoadWrittenShader& load_;
  std::optional<ShaderIndex> index_;
  std::map<std::string, Loaded> loaded_;
  std::vector<std::string> chain_;  // the shaders being linked, outermost first
};

}  // namespace

std::vector<ShaderDir> shader_search_dirs(const std::string& shader_path, const std::vector<std::string>& include_dirs,
                                          const std::string& stdlib_dir) {
  std::vector<ShaderDir> dirs;
  std::string folder = std::filesystem::path(shader_path).parent_path().string();
  dirs.push_back({folder.empty() ? "." : folder, false});
  for (const std::string& dir : include_dirs) dirs.push_back({dir, false});
  if (!stdlib_dir.empty()) dirs.push_back({stdlib_dir + "/Shaders", true});
  return dirs;
}

void link_shader(ir::Shader& shader, const std::vector<ShaderDir>& search, const LoadWrittenShader& load,
                 Diagnostics& diags) {
  Linker(search, load).link(shader, diags);
}

}  // namespace facet
