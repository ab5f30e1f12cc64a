// PNG and EXR files through image_io, written atomically, and the --explain listing.
#include <fmt/format.h>


#include "facet/runtime/renderer.h"
#include "facet/support/atomic_file.h"
#include "image_io/image_io.h"

namespace facet::runtime {
namespace {

template <typename Pixel>
Result<void, RenderError> write_atomically(const std::string& path, const RenderedFrame& frame, const Pixel* pixels) {
  Result<void, std::string> written = support::replace_file_atomically(path, [&](const std::string& temporary) {
    return write_image_file(temporary, frame.width, frame.height, pixels);
  });
  if (!written) return unexpected(RenderError{fmt::format("{}: cannot write the image: {}", path, written.error())});
  return {};
}

std::string join(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s.empty() ? "(none)" : s;
}

}  // namespace

Result<void, RenderError> write_png(const RenderedFrame& frame, const std::string& path) {
  return write_atomically(path, frame, frame.ldr.data());
}

Result<void, RenderError> write_exr(const RenderedFrame& frame, const std::string& path) {
  return write_atomically(path, frame, frame.hdr.data());
}

std::string explain_text(const RenderedFrame& frame) {
  std::string text;
  size_t n = 0;
  for (const DrawRecord& d : frame.draws) {
    std::string mode = d.light_mode.empty() ? "no LightMode" : d.light_mode;
    if (!d.drawn) {
      text += fmt::format("   - {} '{}' pass {} ({}): not drawn: {}\n", d.object, d.shader, d.pass, mode, d.why);
      continue;
    }
    text += fmt::format("{:4} {} '{}' pass {} ({}), queue {}{}\n", ++n, d.object, d.shader, d.pass, mode, d.queue,
                        d.light.empty() ? "" : ", light " + d.light);
    text += fmt::format("       variant: {}{}\n       state: {}\n       why: {}\n", join(d.keywords),
                        d.exact ? "" : " (closest match)", d.state, d.why);
  }
  return text;
}

}  // namespace facet::runtime
