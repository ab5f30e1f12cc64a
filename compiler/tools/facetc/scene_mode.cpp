#include "scene_mode.h"

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "facet/support/atomic_file.h"
#include "output_safety.h"
#include "variant_collection.h"

extern char** environ;

namespace facet::tools {
namespace fs = std::filesystem;

namespace {

// A folder of its own under the system's temporary folder, removed with it.
struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "facetc-scene-XXXXXX").string();
    if (mkdtemp(pattern.data())) path = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
  }
};

// $FACET_RENDER_TOOL; else `facet` beside this facetc (an installed bin/);
// else the build tree's; else `facet` on the PATH.
std::string renderer_tool(const FacetcArgs& args) {
  if (const char* tool = std::getenv("FACET_RENDER_TOOL"); tool && *tool) return tool;
  std::error_code ec;
  fs::path sibling = fs::path(args.facetc_path).parent_path() / "facet";
  if (fs::is_regular_file(sibling, ec)) return sibling.string();
#ifdef FACET_BUILD_TREE_RENDERER
  if (fs::is_regular_file(FACET_BUILD_TREE_RENDERER, ec)) return FACET_BUILD_TREE_RENDERER;
#endif
  return "facet";
}

// Runs argv[0] (searched on the PATH) with facetc's environment, the stdlib
// folder passed on; its output goes where facetc's goes. The exit status, or
// an error.
Result<int, std::string> run_program(const std::vector<std::string>& argv, const std::string& stdlib_dir) {
  std::vector<std::string> env_text;
  for (char** e = environ; *e; ++e) {
    if (!stdlib_dir.empty() && std::strncmp(*e, "FACET_STDLIB_DIR=", 17) == 0) continue;
    env_text.emplace_back(*e);
  }
  if (!stdlib_dir.empty()) env_text.push_back("FACET_STDLIB_DIR=" + stdlib_dir);
  std::vector<char*> env, args;
  for (std::string& e : env_text) env.push_back(e.data());
  env.push_back(nullptr);
  std::vector<std::string> argv_text = argv;
  for (std::string& a : argv_text) args.push_back(a.data());
  args.push_back(nullptr);
  pid_t pid = 0;
  if (int e = posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), env.data()); e != 0) {
    return unexpected(fmt::format("cannot run '{}': {}", argv[0], std::strerror(e)));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return unexpected(fmt::format("waiting for '{}': {}", argv[0], std::strerror(errno)));
  }
  if (WIFSIGNALED(status)) return unexpected(fmt::format("'{}' was killed by signal {}", argv[0], WTERMSIG(status)));
  return WEXITSTATUS(status);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

int run_scene(const FacetcArgs& args, Console& console) {
  ScratchDir scratch;
  if (scratch.path.empty()) {
    console.err << fmt::format("facetc: error: cannot create a temporary folder: {}\n", std::strerror(errno));
    return 1;
  }
  const std::string collection_file = (scratch.path / "variants.json").string();
  std::vector<std::string> render = {renderer_tool(args), "render", args.scene, "-o", (scratch.path / "frame.png").string(),
                                     "--emit-variants", collection_file};
  for (const std::string& dir : args.backend.include_dirs) render.insert(render.end(), {"-I", dir});
  if (!args.cache_dir.empty()) render.insert(render.end(), {"--cache", args.cache_dir});
  Result<int, std::string> rendered = run_program(render, args.backend.stdlib_dir);
  if (!rendered) {
    console.err << fmt::format("facetc: error: {}: {} (set FACET_RENDER_TOOL to facet's path)\n", args.scene,
                               rendered.error());
    return 1;
  }
  if (*rendered != 0) {
    console.err << fmt::format("facetc: error: {}: rendering the scene to find its variants failed (facet render "
                               "exited with {}); nothing was built\n", args.scene, *rendered);
    return 1;
  }
  SourceMap sources;
  Diagnostics diags;
  Result<VariantCollection> collection = read_variant_collection(collection_file, sources, diags);
  if (!collection || collection->sources.empty()) {
    console.err << fmt::format("facetc: error: {}: the scene draws no shader of its own; nothing was built\n",
                               args.scene);
    return 1;
  }
  FacetcArgs build = args;
  build.scene.clear();
  build.variant_files = {collection_file};
  build.inputs.clear();
  for (const auto& [name, source] : collection->sources) build.inputs.push_back(source);
  const fs::path out_dir = args.out_dir.empty() ? "." : args.out_dir;
  fs::path kept = out_dir / fs::path(args.scene).stem();
  kept += ".variants.json";
  // The scene itself is no input of the package builds: check it here.
  std::vector<std::string> outputs = {kept.string()};
  for (const std::string& source : build.inputs) {
    outputs.push_back((out_dir / fs::path(source).stem()).string() + ".facetpkg");
  }
  std::vector<RunInput> inputs = {{args.scene, "the scene"}};
  add_inputs(inputs, build.inputs, "a shader of the scene");
  if (std::optional<std::string> clash = output_input_clash(outputs, inputs)) {
    console.err << "facetc: error: " << *clash << "\n";
    return 1;
  }
  if (int code = run_facetc(build, console); code != 0) return code;
  if (auto w = support::write_file_atomically(kept.string(), read_text(collection_file)); !w) {
    console.err << fmt::format("facetc: error: cannot write '{}': {}\n", kept.string(), w.error());
    return 1;
  }
  return 0;
}

}  // namespace facet::tools
