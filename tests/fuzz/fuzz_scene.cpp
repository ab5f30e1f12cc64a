// Arbitrary bytes as a scene JSON file through the runtime's scene reader
// (facet/runtime/scene.h). parse_scene only resolves the paths it names; it
// opens no file.
#include "facet/runtime/scene.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = facet::fuzz::TempDir::get().file("scene.json");
  facet::SourceMap sources;
  facet::Diagnostics diags;
  if (!facet::runtime::parse_scene(std::string(facet::fuzz::as_text(data, size)), path, sources, diags)) {
    (void)facet::render_text(diags, sources);  // the printer runs over every located error too
  }
  return 0;
}
